//! A force and a torque.

use nalgebra::Vector3;

/// A force (N) and a torque (N·m, about a point the context names), world frame, `f64`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Wrench {
    pub force: Vector3<f64>,
    pub torque: Vector3<f64>,
}
