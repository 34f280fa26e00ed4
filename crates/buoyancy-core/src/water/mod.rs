//! The water a body floats in: its still plane ([`Water`]: density, gravity, the plane) and the
//! free surfaces that move over it, the elevation `η` above the still plane as a function of
//! horizontal position and time.
//!
//! # Frames
//! A [`Water`] defines the still plane `n·p = level` of the world frame. A
//! *horizontal position* is a world point projected onto that plane, `p − (n·p − level)·n`, so
//! any up normal works. The free surface is `{ q + η(q, t)·n : q on the still plane }`, and a
//! world point `x` lies `h = n·x − level − η(q, t)` above it, `q` its projection. Units: m, s.
//!
//! # Surfaces
//! * [`CalmSurface`]: `η = 0`, the still water of [`Mesh::buoyancy`].
//! * [`AiryWaves`]: a sum of linear (Airy) wave components, finite or infinite depth, given
//!   one by one or drawn from a [`SeaState`] (Pierson–Moskowitz or JONSWAP spectrum).
//! * [`GerstnerWaves`]: trochoidal waves, the elevation at a point solved from the particle
//!   there.
//! * [`HeightGrid`]: heights on a regular grid, bilinear, optionally periodic, replaceable each
//!   step without reallocating (oceans computed elsewhere).
//! * [`SurfaceFn`]: any function or closure of the horizontal position and time.
//!
//! Every surface is evaluated in batches, once per vertex per evaluation
//! ([`WaterSurface::elevations`]); [`Mesh::buoyancy`] under a [`Sea`](crate::query::Sea)
//! integrates the pressure over the wetted surface (see the [query's guide](crate::query)).

mod airy;
mod cosine;
mod gerstner;
mod grid;
mod spectrum;
mod still_water;
mod surface;

pub(crate) use airy::pressure_ratio;
pub use airy::{AiryComponent, AiryWaves, BREAKING_STEEPNESS, WaterMotion};
pub(crate) use airy::{ResolvedWave, amplitude_sum, horizontal_direction, resolve};
pub use gerstner::GerstnerWaves;
pub use grid::HeightGrid;
pub use spectrum::{SeaState, Spectrum};
pub use still_water::Water;
pub use surface::{CalmSurface, SurfaceFn, WaterSurface};

#[cfg(doc)]
use crate::Mesh;
