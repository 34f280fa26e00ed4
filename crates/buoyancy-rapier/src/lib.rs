//! Buoyancy for rapier3d rigid bodies (in development: the adapter is not written yet; this
//! crate only re-exports the core so that the workspace layout is in place).
pub use buoyancy_core;
