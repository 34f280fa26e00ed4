#![doc = include_str!("../README.md")]
#![no_std]
pub use buoyancy_core::*;

/// The rapier3d adapter ([`buoyancy_rapier`]): bodies that float in a rapier world.
#[cfg(feature = "rapier")]
pub use buoyancy_rapier as rapier;
