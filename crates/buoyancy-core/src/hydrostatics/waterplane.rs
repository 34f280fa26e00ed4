//! The waterplane: Green's theorem over the oriented waterline segments.

use nalgebra::{Matrix2, Point3, Unit, Vector2, Vector3};

use crate::mesh::hierarchy::Visit;
use crate::query::clip::{TriangleClass, classify, cut_at_waterline};
use crate::query::frame::Frame;
use crate::{Error, Mesh, Pose, Real, Water};

/// The waterplane of a body at a pose: the part of the still-water plane inside the mesh (the
/// section the plane cuts through it, holes left out), its area, centroid and second moments.
///
/// Exact for the polygon(s) where the plane cuts the mesh (see the [module
/// documentation](super)). Points and vectors are in the *world frame*; the in-plane
/// coordinates `(ξ, η)` of a point `r` are `ξ = (r − F)·e₁`, `η = (r − F)·e₂` about the center
/// of flotation `F`, along the basis `axes = [e₁, e₂]`, with `e₁ × e₂ = n` (the water's up
/// normal), so that counter-clockwise seen from above is the positive sense.
///
/// When nothing crosses the plane (the body is dry, or entirely under water) the area and
/// moments are zero and the center of flotation is the projection of the body's center of
/// volume on the plane.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Waterplane<T: Real> {
    /// Waterplane area `A = ∫ dA`, m².
    pub area: T,
    /// Center of flotation `F`, the centroid of the waterplane, `F = ∫ r dA / A`, world frame,
    /// m (on the water plane).
    pub center_of_flotation: Point3<T>,
    /// The in-plane basis `[e₁, e₂]` the tensor [`second_moments`](Self::second_moments) is
    /// written in, world frame, unit vectors, `e₁ × e₂ = n`. [`Mesh::waterplane`] takes for
    /// `e₁` the body's x axis (the mesh frame's x axis under the pose) projected on the plane,
    /// or its z axis when the x axis is within 30° of the vertical;
    /// [`Mesh::hydrostatics`](crate::Mesh::hydrostatics) the body's longitudinal axis.
    pub axes: [Unit<Vector3<T>>; 2],
    /// The tensor of second moments of area about `F` in the basis `axes`, m⁴:
    ///
    /// ```text
    /// ⎡  ∫η² dA   −∫ξη dA ⎤
    /// ⎣ −∫ξη dA    ∫ξ² dA ⎦
    /// ```
    ///
    /// so that the second moment about the line through `F` along the in-plane unit vector
    /// `u = u₁e₁ + u₂e₂` is `I_u = ∫ (distance to the line)² dA = uᵀ·second_moments·u`: the
    /// first diagonal entry is the moment about `e₁` (for `e₁` the body's longitudinal axis, the
    /// *transverse* moment `I_T`, which rolling feels), the second the moment about `e₂`.
    pub second_moments: Matrix2<T>,
    /// The eigenvalues of [`second_moments`](Self::second_moments), least first, m⁴: the least
    /// and greatest second moments about a line through `F`.
    pub principal_moments: [T; 2],
    /// The lines through `F` about which the second moments are
    /// [`principal_moments`](Self::principal_moments), world frame, unit vectors: the first
    /// with a non-negative component along `e₁` (along `e₁` for a circle), the second
    /// `n × principal_axes[0]`.
    pub principal_axes: [Unit<Vector3<T>>; 2],
}

/// Green's theorem sums over the waterline segments `p → q`, in plane coordinates `(u, w)`
/// along `e₁`, `e₂` about the projection `o` of the centroid on the plane, with
/// `d = u_p w_q − w_p u_q`: twice the signed area of the triangle `(o, p, q)`.
#[derive(Debug, Clone, Copy)]
struct GreenSums<T: Real> {
    /// `Σ d = 2A`.
    area2: T,
    /// `Σ |d|`: the size of the terms, for the round-off threshold.
    magnitude: T,
    /// `Σ d·(p + q) = 6·∫ r dA`.
    moment6: Vector2<T>,
    /// `Σ d·(2u_p² + 2u_q² + 2u_p u_q) = 24·∫u² dA`, the same in `w`, and
    /// `Σ d·(2u_p w_p + 2u_q w_q + u_p w_q + u_q w_p) = 24·∫uw dA`.
    moments24: [T; 3],
}

impl<T: Real> GreenSums<T> {
    fn zero() -> Self {
        GreenSums {
            area2: T::zero(),
            magnitude: T::zero(),
            moment6: Vector2::zeros(),
            moments24: [T::zero(); 3],
        }
    }

    /// Adds the segment `p → q` of the boundary (counter-clockwise seen from above around the
    /// region): the signed triangle `(o, p, q)`, whose area is `d/2`, first moment
    /// `(d/2)(p + q)/3` and second moments `(d/24)(2ppᵀ + 2qqᵀ + pqᵀ + qpᵀ)`.
    #[inline(always)]
    fn add(&mut self, p: Vector2<T>, q: Vector2<T>) {
        let d = p.x * q.y - p.y * q.x;
        let two = T::from_f64_lossy(2.0);
        self.area2 += d;
        self.magnitude += d.abs();
        self.moment6 += (p + q) * d;
        self.moments24[0] += (p.x * p.x + q.x * q.x + p.x * q.x) * two * d;
        self.moments24[1] += (p.y * p.y + q.y * q.y + p.y * q.y) * two * d;
        self.moments24[2] += ((p.x * p.y + q.x * q.y) * two + p.x * q.y + q.x * p.y) * d;
    }
}

/// `axis` (mesh frame) projected on the plane of up normal `normal` (mesh frame, unit) and
/// normalised, or `None` when its projection is shorter than `min_length` times its length.
pub(crate) fn in_plane<T: Real>(
    axis: &Vector3<T>,
    normal: &Vector3<T>,
    min_length: T,
) -> Option<Vector3<T>> {
    let projected = axis - normal * normal.dot(axis);
    let length = projected.norm();
    (length > min_length * axis.norm() && length > T::zero()).then(|| projected / length)
}

impl<T: Real> Mesh<T> {
    /// The waterplane of this mesh placed by `pose` (mesh → world) in `water`: its area, center
    /// of flotation and second moments, world frame; see [`Waterplane`] and the [module
    /// documentation](crate::hydrostatics) for the method and conventions.
    ///
    /// Walks the mesh's hierarchy: only the triangles near the waterline are visited. No
    /// allocation.
    ///
    /// ```
    /// use buoyancy_core::{Mesh, Pose, Water, mesh::primitives};
    ///
    /// // A unit cube centered at the surface: a unit square, F at the origin, I = 1/12.
    /// let (v, t) = primitives::cube::<f64>(2)?;
    /// let wp = Mesh::new(v, t)?.waterplane(&Pose::identity(), &Water::default())?;
    /// assert!((wp.area - 1.0).abs() < 1e-14);
    /// assert!(wp.center_of_flotation.coords.norm() < 1e-14);
    /// assert!((wp.principal_moments[0] - 1.0 / 12.0).abs() < 1e-14);
    /// # Ok::<(), buoyancy_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidPose`] if the pose has a NaN or infinite component or a zero quaternion;
    /// [`Error::OpeningSubmerged`] if the water reaches the rim of an opening closed by
    /// [`Mesh::close_openings`] (the lid is no waterplane); [`Error::NonFiniteResult`] if the
    /// pose is so large that the result overflows.
    pub fn waterplane(&self, pose: &Pose<T>, water: &Water<T>) -> Result<Waterplane<T>, Error> {
        let frame = Frame::new(self, pose, water)?;
        self.openings_dry(&frame)?;
        self.waterplane_at(&frame)
    }

    /// [`waterplane`](Self::waterplane) of the closed mesh, its lids counted as hull wherever
    /// the water is: for the equilibrium solver's iterates, which may wet a lid on the way to a
    /// rest that does not.
    pub(crate) fn closed_waterplane(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
    ) -> Result<Waterplane<T>, Error> {
        self.waterplane_at(&Frame::new(self, pose, water)?)
    }

    /// The waterplane in the frame `frame`, its first axis the mesh's x axis projected on the
    /// plane (its z axis when x is within 30° of the vertical).
    fn waterplane_at(&self, frame: &Frame<T>) -> Result<Waterplane<T>, Error> {
        let half = T::from_f64_lossy(0.5);
        let normal = &frame.normal_local;
        // The x axis is within 30° of the vertical when its projection is shorter than 1/2;
        // then the z axis, perpendicular to it, lies within 30° of the plane.
        let e1 = in_plane(&Vector3::x(), normal, half)
            .or_else(|| in_plane(&Vector3::z(), normal, half))
            .unwrap_or_else(Vector3::x);
        self.waterplane_in(frame, &e1)
    }

    /// The waterplane in the frame `frame`, with `e1` (mesh frame, unit, in the plane) the first
    /// axis of its basis.
    pub(crate) fn waterplane_in(
        &self,
        frame: &Frame<T>,
        e1: &Vector3<T>,
    ) -> Result<Waterplane<T>, Error> {
        let e2 = frame.normal_local.cross(e1);
        let sums = self.green_sums(frame, e1, &e2);
        let zero = T::zero();
        let (e1_world, e2_world) = (frame.rotation * e1, frame.rotation * e2);
        let origin = frame.surface_point();
        // A region that is not there: only round-off left of edges that cancel.
        let tolerance = T::default_epsilon() * T::from_f64_lossy(64.0) * sums.magnitude;
        let wp = if sums.area2 <= tolerance {
            Waterplane {
                area: zero,
                center_of_flotation: origin,
                axes: [Unit::new_unchecked(e1_world), Unit::new_unchecked(e2_world)],
                second_moments: Matrix2::zeros(),
                principal_moments: [zero; 2],
                principal_axes: [Unit::new_unchecked(e1_world), Unit::new_unchecked(e2_world)],
            }
        } else {
            let area = sums.area2 / T::from_f64_lossy(2.0);
            let c = sums.moment6 / (T::from_f64_lossy(6.0) * area);
            let m = sums.moments24.map(|s| s / T::from_f64_lossy(24.0));
            // Parallel axes: about F.
            let uu = m[0] - area * c.x * c.x;
            let ww = m[1] - area * c.y * c.y;
            let uw = m[2] - area * c.x * c.y;
            let second_moments = Matrix2::new(ww, -uw, -uw, uu);
            let (principal_moments, [a0, a1]) = principal(&second_moments);
            let in_world = |a: Vector2<T>| Unit::new_normalize(e1_world * a.x + e2_world * a.y);
            Waterplane {
                area,
                center_of_flotation: origin + e1_world * c.x + e2_world * c.y,
                axes: [Unit::new_unchecked(e1_world), Unit::new_unchecked(e2_world)],
                second_moments,
                principal_moments,
                principal_axes: [in_world(a0), in_world(a1)],
            }
        };
        let finite = wp.area.is_finite()
            && wp.center_of_flotation.iter().all(|x| x.is_finite())
            && wp.second_moments.iter().all(|x| x.is_finite());
        if finite {
            Ok(wp)
        } else {
            Err(Error::NonFiniteResult)
        }
    }

    /// Sums Green's terms over the waterline segments of the triangles the hierarchy finds near
    /// the surface, in plane coordinates along `e1`, `e2` (mesh frame).
    ///
    /// A triangle the plane cuts contributes its segment between the waterline points `ab` and
    /// `ca`, oriented as the cap (the waterplane seen from above, counter-clockwise) runs along
    /// it, opposite to the submerged part's boundary: `ca → ab` when the odd vertex `a` is the
    /// one under water, `ab → ca` when it is the one above. A triangle under water with an edge
    /// lying in the surface (both ends at `h = 0`) contributes that edge reversed: where the
    /// neighbour across it is dry, this is the segment the neighbour would give were the
    /// surface raised by a hair (a vertex at `h = 0` counts as under water); where the
    /// neighbour is under water too, the two contributions cancel.
    fn green_sums(&self, frame: &Frame<T>, e1: &Vector3<T>, e2: &Vector3<T>) -> GreenSums<T> {
        // Vertices are relative to the centroid, whose projection `o` on the plane lies along
        // the normal from it: `(p − o)·eₖ = p·eₖ`.
        let plane = |p: &Vector3<T>| Vector2::new(p.dot(e1), p.dot(e2));
        let mut sums = GreenSums::zero();
        self.waterline_segments(frame, |p, q| sums.add(plane(p), plane(q)));
        sums
    }

    /// Calls `segment(p, q)` for each segment `p → q` of the waterline at the frame's pose
    /// (mesh frame, relative to the centroid), oriented as [`green_sums`](Self::green_sums)
    /// says: visiting only the leaves the surface crosses.
    pub(super) fn waterline_segments(
        &self,
        frame: &Frame<T>,
        mut segment: impl FnMut(&Vector3<T>, &Vector3<T>),
    ) {
        let zero = T::zero();
        self.hierarchy
            .walk(&frame.normal_local, frame.height, |visit| {
                let Visit::CrossedLeaf { triangles } = visit else {
                    return;
                };
                for i in triangles {
                    let v = self.corners(i);
                    let h = frame.heights(&v);
                    match classify(&h) {
                        TriangleClass::Cut => {
                            let cut = cut_at_waterline(v, h);
                            if cut.odd_is_below {
                                segment(&cut.ca, &cut.ab);
                            } else {
                                segment(&cut.ab, &cut.ca);
                            }
                        }
                        TriangleClass::Submerged
                            if h[0] == zero || h[1] == zero || h[2] == zero =>
                        {
                            for k in 0..3 {
                                let j = (k + 1) % 3;
                                if h[k] == zero && h[j] == zero {
                                    segment(&v[j], &v[k]);
                                }
                            }
                        }
                        _ => {}
                    }
                }
            });
    }
}

/// The eigenvalues of the symmetric `m` (least first, not below zero) and their unit
/// eigenvectors `[u, rot90(u)]`, `u` with a non-negative first component.
fn principal<T: Real>(m: &Matrix2<T>) -> ([T; 2], [Vector2<T>; 2]) {
    let half = T::from_f64_lossy(0.5);
    let (a, b, c) = (m[(0, 0)], m[(0, 1)], m[(1, 1)]);
    let mean = (a + c) * half;
    let radius = ((a - c) * half).hypot(b);
    // The least eigenvalue's eigenvector is the greatest one's of −m: at the angle
    // φ = atan2(−2b, c − a)/2 ∈ [−π/2, π/2], cos φ ≥ 0.
    let angle = (-b).atan2((c - a) * half) * half;
    let (s, co) = angle.sin_cos();
    (
        [(mean - radius).max(T::zero()), mean + radius],
        [Vector2::new(co, s), Vector2::new(-s, co)],
    )
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix2, Rotation2, Vector2};

    use super::principal;

    #[test]
    fn principal_axes_diagonalise_the_tensor() {
        for angle in [0.0, 0.3, -1.2, core::f64::consts::FRAC_PI_2, 2.9] {
            let r = *Rotation2::new(angle).matrix();
            let m: Matrix2<f64> = r * Matrix2::new(0.5, 0.0, 0.0, 3.0) * r.transpose();
            let ([least, greatest], [u, v]) = principal(&m);
            assert!((least - 0.5).abs() < 1e-14 && (greatest - 3.0).abs() < 1e-14);
            assert!((m * u - u * least).norm() < 1e-14, "{angle}");
            assert!((m * v - v * greatest).norm() < 1e-14, "{angle}");
            // u along the least axis, its first component non-negative; v = rot90(u).
            assert!(u.x >= 0.0 && (u.x * v.y - u.y * v.x - 1.0).abs() < 1e-15);
            assert!((u.dot(&(r * Vector2::x())).abs() - 1.0).abs() < 1e-14);
        }
        // Isotropic: the basis itself.
        let ([a, b], [u, _]) = principal(&Matrix2::new(2.0, 0.0, 0.0, 2.0));
        assert_eq!((a, b, u), (2.0, 2.0, Vector2::x()));
    }
}
