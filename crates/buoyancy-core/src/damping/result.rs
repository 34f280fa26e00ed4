//! What the damping model gives: [`Damping`].

use nalgebra::{Point3, Vector3};

use crate::Real;
#[cfg(doc)]
use crate::damping::angular_damping;

/// The damping force and torque on a body for one instant, world frame, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Damping<T: Real> {
    /// Total damping force, N.
    pub force: Vector3<T>,
    /// Torque about [`torque_point`](Self::torque_point), N·m: the moments of the pressure drag
    /// plus the angular damping.
    pub torque: Vector3<T>,
    /// The angular damping `τ_ω` alone (included in [`torque`](Self::torque)), N·m: a body
    /// made of several meshes takes it back from each and adds [`angular_damping`] once for the
    /// whole body.
    pub angular_torque: Vector3<T>,
    /// The body's center of mass (the mesh centroid under the pose), world frame, m.
    pub torque_point: Point3<T>,
    /// Wetted area `A_wet`, m²: the area of the surface under water.
    pub wetted_area: T,
    /// `f = A_wet / A_total`, the wetted fraction of the surface, in [0, 1].
    pub wetted_fraction: T,
}

impl<T: Real> Damping<T> {
    /// Zero force and torque about `torque_point`.
    pub fn zero(torque_point: Point3<T>) -> Self {
        Damping {
            force: Vector3::zeros(),
            torque: Vector3::zeros(),
            angular_torque: Vector3::zeros(),
            torque_point,
            wetted_area: T::zero(),
            wetted_fraction: T::zero(),
        }
    }

    /// The torque of the same force system about another world point `q`:
    /// `τ_q = τ + (torque_point − q) × F`.
    pub fn torque_about(&self, q: &Point3<T>) -> Vector3<T> {
        self.torque + (self.torque_point - q).cross(&self.force)
    }
}
