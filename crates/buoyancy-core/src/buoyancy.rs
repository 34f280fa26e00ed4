//! The result of an evaluation.

use nalgebra::{Point3, Vector3};

#[cfg(doc)]
use crate::Method;
use crate::{Error, Real};

/// The buoyancy of a body: force, its point of application and its torque, world frame, SI units.
///
/// For the volume methods ([`Fast`](Method::Fast), [`Improved`](Method::Improved),
/// [`Exact`](Method::Exact)) `submerged_volume` and `center_of_buoyancy` are the volume and
/// centroid of the part found under water, the force is `ρ·g·V·n` and it acts at the center of
/// buoyancy. For the surface methods ([`FastSurface`](Method::FastSurface),
/// [`ExactSurface`](Method::ExactSurface)) the force and torque are the integrals of the pressure
/// over the wetted triangles; `submerged_volume` is the volume implied by the force,
/// `n·F / (ρ·g)`, and `center_of_buoyancy` the centroid implied by the pressure moments,
/// `∫ h r (n·dA) − (n/2)∫ h² (n·dA)` divided by that volume. For a closed mesh under a flat plane
/// the exact methods agree on all of it.
///
/// When (almost) nothing is under water, that is when `|submerged_volume|` is below round-off
/// relative to the mesh's own volume, `center_of_buoyancy` is the projection of the center of
/// mass onto the water plane: the point where buoyancy starts to act as the body enters the
/// water. Volume, force and torque are then as computed (zero, or round-off), never NaN.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Buoyancy<T: Real> {
    /// Volume under water, m³. Never negative for [`Method::Exact`], also for a body touching
    /// the water within round-off (see `tests/contact.rs`); it may be negative for the
    /// approximate methods on non-convex meshes, whose missing contributions are not
    /// sign-definite.
    pub submerged_volume: T,
    /// Point of application of the force, world frame, m.
    pub center_of_buoyancy: Point3<T>,
    /// Buoyant force, world frame, N.
    pub force: Vector3<T>,
    /// Torque of the buoyant force about [`torque_point`](Self::torque_point), world frame, N·m.
    pub torque: Vector3<T>,
    /// The point the torque is taken about: the body's center of mass (the mesh centroid under
    /// the pose), world frame, m. Use [`torque_about`](Self::torque_about) for another point.
    pub torque_point: Point3<T>,
    /// Number of triangles entirely under water (a triangle lying in the surface counts).
    pub fully_submerged: usize,
    /// Number of triangles the surface cuts (some vertex above, some below).
    pub partially_submerged: usize,
}

impl<T: Real> Buoyancy<T> {
    /// The torque of the same force system about another world point `q`:
    /// `τ_q = τ + (torque_point − q) × F`. Exact for any force system, not only a single force.
    pub fn torque_about(&self, q: &Point3<T>) -> Vector3<T> {
        self.torque + (self.torque_point - q).cross(&self.force)
    }

    /// This result with its torque taken about the world point `q` instead.
    pub fn about(mut self, q: &Point3<T>) -> Self {
        self.torque = self.torque_about(q);
        self.torque_point = *q;
        self
    }

    /// This result, or [`Error::NonFiniteResult`] if any of its numbers overflowed.
    pub(crate) fn checked(self) -> Result<Self, Error> {
        if self.is_finite() {
            Ok(self)
        } else {
            Err(Error::NonFiniteResult)
        }
    }

    fn is_finite(&self) -> bool {
        self.submerged_volume.is_finite()
            && self.center_of_buoyancy.iter().all(|c| c.is_finite())
            && self.force.iter().all(|c| c.is_finite())
            && self.torque.iter().all(|c| c.is_finite())
    }
}

/// How many triangles an evaluation found fully and partly under water.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct TriangleCounts {
    /// Triangles entirely under water (or lying in the surface).
    pub full: usize,
    /// Triangles the waterline cuts.
    pub partial: usize,
}

impl core::ops::Add for TriangleCounts {
    type Output = TriangleCounts;
    #[inline]
    fn add(self, o: TriangleCounts) -> TriangleCounts {
        TriangleCounts {
            full: self.full + o.full,
            partial: self.partial + o.partial,
        }
    }
}
