//! Buoyant force, center of buoyancy and torque on closed triangle meshes.
//!
//! This crate implements the five methods of Fábián's *Approximate and exact buoyancy
//! calculation for real-time floating simulation of meshes* against a flat water plane of any
//! orientation, with the torque of the pressure field integrated exactly: [`Method`] lists them.
//! [`Mesh::buoyancy`] is the one query, in still water and under waves (the hydrostatic or the
//! Froude–Krylov pressure of a moving [`water`] surface, [`query::Sea`]); [`Mesh::damping`] the
//! hydrodynamic damping that lets floating bodies settle; [`hydrostatics`] equilibrium and
//! stability; [`controller`] one controller for physics engines.
//!
//! # Modules
//! * [`mesh`]: the closed mesh, its validation and what is built with it; [`mesh::primitives`]
//!   builds procedural meshes. [`io`] reads OBJ, STL and PLY files.
//! * [`water`]: the still water and the surfaces that move over it (Airy, spectral, Gerstner,
//!   grids, functions).
//! * [`query`]: the buoyancy query, its methods, its options and its result, with the guide to
//!   each pressure model.
//! * [`damping`], [`hydrostatics`], [`controller`].
//!
//! # Features
//! * `std` (default): [`io::load`] (reading files), `std::error::Error` for [`Error`] (through
//!   `core::error::Error`, which it implements without `std` too) and nalgebra's `std`.
//! * `rayon`: `Query::in_parallel` ([`query::Query`]), which splits one
//!   evaluation's work across rayon's thread pool, bit-identical to the serial result.
//!
//! Without default features the crate is `no_std` (it needs `alloc`): everything but reading
//! files and parsing PLY (`io::load`, `io::parse_ply`) works, e.g. on `wasm32-unknown-unknown`.
//!
//! # Frames and units
//! A [`Mesh`] lives in its own *mesh frame* (local space). A [`Pose`] maps mesh space to world
//! space: `x_world = R·x_mesh + t`. A [`Water`] plane and every [`Buoyancy`] result are expressed
//! in the *world frame*. Units are SI: metres, kilograms per cubic metre, metres per second
//! squared, newtons, newton-metres.
//!
//! # Example
//! ```
//! use buoyancy_core::{mesh::primitives, Mesh, Method, Pose, Water};
//! use nalgebra::{Translation3, UnitQuaternion};
//!
//! // A unit cube (centered at the origin of its mesh frame) with its center 0.25 m below the surface.
//! let (vertices, triangles) = primitives::cube::<f64>(1).unwrap();
//! let cube = Mesh::new(vertices, triangles).unwrap();
//! let pose = Pose::from_parts(Translation3::new(0.0, -0.25, 0.0), UnitQuaternion::identity());
//! let b = cube.buoyancy(&pose, &Water::default(), Method::Exact).unwrap();
//!
//! assert!((b.submerged_volume - 0.75).abs() < 1e-12);
//! assert!((b.force.y - 1000.0 * 9.81 * 0.75).abs() < 1e-9);
//! assert!((b.center_of_buoyancy.y - (-0.25 - 0.125)).abs() < 1e-12);
//! assert!(b.torque.norm() < 1e-9); // upright: the force acts through the center of mass
//! ```
#![no_std]

extern crate alloc;
#[cfg(feature = "std")]
extern crate std;

pub mod controller;
pub mod damping;
mod error;
pub mod hydrostatics;
pub mod io;
pub mod mesh;
pub mod query;
mod real;
pub mod water;

pub use damping::{Damping, DampingCoefficients};
pub use error::Error;
pub use mesh::{Culprit, Defect, DefectKind, Mesh, MeshDefects};
pub use query::{Buoyancy, Method, Traversal};
pub use real::Real;
pub use water::Water;

/// A rigid transform from mesh space to world space: `x_world = rotation · x_mesh + translation`.
pub type Pose<T> = nalgebra::Isometry3<T>;

pub use nalgebra;
