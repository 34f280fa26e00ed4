//! Exact buoyant force, center of buoyancy and torque on triangle meshes, in real time.
//!
//! This facade re-exports [`buoyancy_core`]; see its documentation.
#![no_std]
pub use buoyancy_core::*;
