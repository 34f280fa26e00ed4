//! glam (rapier's types) ↔ nalgebra (the core's types), at the boundary only.
//!
//! rapier computes in `f32`; the adapter computes buoyancy and damping in `f64` and rounds the
//! results back to `f32`.

use buoyancy_core::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use rapier3d::math::{Pose, Vector};

/// A rapier vector as an `f64` nalgebra vector.
pub(crate) fn vector_to_nalgebra(v: Vector) -> Vector3<f64> {
    Vector3::<f32>::from(v).cast::<f64>()
}

/// A rapier point (a glam vector) as an `f64` nalgebra point.
pub(crate) fn point_to_nalgebra(v: Vector) -> Point3<f64> {
    Point3::from(vector_to_nalgebra(v))
}

/// A rapier pose as an `f64` nalgebra isometry (the quaternion renormalised in `f64`).
pub(crate) fn pose_to_nalgebra(pose: &Pose) -> Isometry3<f64> {
    let rotation = UnitQuaternion::<f32>::from(pose.rotation)
        .into_inner()
        .cast::<f64>();
    Isometry3::from_parts(
        Translation3::from(vector_to_nalgebra(pose.translation)),
        UnitQuaternion::new_normalize(rotation),
    )
}

/// An `f64` nalgebra isometry as a rapier pose (rounded to `f32`).
pub(crate) fn pose_from_nalgebra(pose: &Isometry3<f64>) -> Pose {
    let t = pose.translation.vector.cast::<f32>();
    let q = pose.rotation.into_inner().cast::<f32>();
    Pose::from_parts(
        Vector::new(t.x, t.y, t.z),
        rapier3d::math::Rotation::from_xyzw(q.i, q.j, q.k, q.w).normalize(),
    )
}
