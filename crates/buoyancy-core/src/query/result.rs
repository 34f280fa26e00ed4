//! The result of an evaluation.

use nalgebra::{Point3, Vector3};

use crate::{Error, Real};
#[cfg(doc)]
use crate::{Mesh, Method};

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
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
    /// Area of the mesh surface under water, m²: of the triangles entirely under water (a
    /// triangle lying in the surface counts, as in [`fully_submerged`](Self::fully_submerged))
    /// and of the parts under water of the triangles the surface cuts.
    ///
    /// * [`Exact`](Method::Exact), [`Improved`](Method::Improved),
    ///   [`ExactSurface`](Method::ExactSurface), and [`Mesh::buoyancy`] under waves
    ///   (either pressure): exact, the area of the wetted pieces (under waves,
    ///   of the wetted surface those two integrate over: each triangle cut where its linearly
    ///   interpolated height above the free surface is zero). For a unit cube upright at draft
    ///   `d`, `1 + 4d`. `Improved` leaves the cut triangles out of its volume, not out of its
    ///   area: it cuts them anyway.
    /// * [`Fast`](Method::Fast) and [`FastSurface`](Method::FastSurface): the area of the
    ///   triangles entirely under water only, what they integrate over. It falls short of the
    ///   exact area by the wetted parts of the `partially_submerged` triangles, at most their
    ///   total area, which shrinks with the resolution of the waterline.
    ///
    /// Never more than [`Mesh::surface_area`] beyond round-off. A cut triangle's part is its
    /// area times its share under water (the corner cut off at a vertex is the product of the
    /// fractions of the two edges leaving it); the hierarchy adds the stored area of the nodes
    /// entirely under water.
    pub wetted_area: T,
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
            && self.wetted_area.is_finite()
            && self.center_of_buoyancy.iter().all(|c| c.is_finite())
            && self.force.iter().all(|c| c.is_finite())
            && self.torque.iter().all(|c| c.is_finite())
    }
}

/// How many triangles an evaluation found fully and partly under water, and twice the area
/// under water (see [`Buoyancy::wetted_area`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TriangleCounts<T: Real> {
    /// Triangles entirely under water (or lying in the surface).
    pub full: usize,
    /// Triangles the waterline cuts.
    pub partial: usize,
    /// Twice the wetted area, m²: what the method counts of the triangles' `double_area`.
    pub wetted_area2: T,
}

impl<T: Real> Default for TriangleCounts<T> {
    #[inline]
    fn default() -> Self {
        TriangleCounts {
            full: 0,
            partial: 0,
            wetted_area2: T::zero(),
        }
    }
}

impl<T: Real> core::ops::Add for TriangleCounts<T> {
    type Output = TriangleCounts<T>;
    #[inline]
    fn add(self, o: TriangleCounts<T>) -> TriangleCounts<T> {
        TriangleCounts {
            full: self.full + o.full,
            partial: self.partial + o.partial,
            wetted_area2: self.wetted_area2 + o.wetted_area2,
        }
    }
}
