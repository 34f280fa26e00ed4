//! How one body floats: which of its colliders, how finely round shapes are meshed, and the
//! body's overrides of the world's settings.

use buoyancy_core::controller::DampingResolution;
use buoyancy_core::{DampingCoefficients, Method, Water};
use rapier3d::prelude::ColliderHandle;

/// Which colliders of a body float.
#[derive(Debug, Clone, Default, PartialEq)]
pub enum FloatingColliders {
    /// Every collider attached to the body at registration.
    #[default]
    All,
    /// Only these (each must be attached to the body; repeats count once).
    Only(Vec<ColliderHandle>),
}

/// How one body floats: which colliders, how finely round shapes are meshed, and overrides of
/// the world's method, water and damping.
#[derive(Debug, Clone, PartialEq)]
pub struct FloatOptions {
    /// The colliders that float. Default: all of them.
    pub colliders: FloatingColliders,
    /// Segments around a ball, cylinder, capsule or cone (half as many from pole to pole).
    /// Default 32. Cuboids, convex polyhedra and trimeshes are used exactly.
    pub subdivisions: u32,
    /// This body's method; `None`: the world's ([`FloatingBodies::method`](crate::FloatingBodies::method)).
    pub method: Option<Method>,
    /// This body's water; `None`: the world's ([`FloatingBodies::water`](crate::FloatingBodies::water)).
    pub water: Option<Water<f64>>,
    /// This body's damping; `None`: the world's
    /// ([`FloatingBodies::damping`](crate::FloatingBodies::damping)).
    pub damping: Option<DampingCoefficients<f64>>,
    /// How finely this body's pressure drag is integrated; `None`: the world's
    /// ([`FloatingBodies::damping_resolution`](crate::FloatingBodies::damping_resolution)).
    pub damping_resolution: Option<DampingResolution>,
}

impl Default for FloatOptions {
    fn default() -> Self {
        FloatOptions {
            colliders: FloatingColliders::All,
            subdivisions: 32,
            method: None,
            water: None,
            damping: None,
            damping_resolution: None,
        }
    }
}

impl FloatOptions {
    /// Only these colliders float.
    pub fn colliders(mut self, colliders: impl IntoIterator<Item = ColliderHandle>) -> Self {
        self.colliders = FloatingColliders::Only(colliders.into_iter().collect());
        self
    }
    /// Segments around round shapes.
    pub fn subdivisions(mut self, subdivisions: u32) -> Self {
        self.subdivisions = subdivisions;
        self
    }
    /// This body's method.
    pub fn method(mut self, method: Method) -> Self {
        self.method = Some(method);
        self
    }
    /// This body's water.
    pub fn water(mut self, water: Water<f64>) -> Self {
        self.water = Some(water);
        self
    }
    /// This body's damping ([`DampingCoefficients::off`] for none).
    pub fn damping(mut self, damping: DampingCoefficients<f64>) -> Self {
        self.damping = Some(damping);
        self
    }
    /// How finely this body's pressure drag is integrated, e.g.
    /// [`DampingResolution::Full`] for the model exactly.
    pub fn damping_resolution(mut self, resolution: DampingResolution) -> Self {
        self.damping_resolution = Some(resolution);
        self
    }
}
