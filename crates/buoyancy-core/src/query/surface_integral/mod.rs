//! The surface methods, `FastSurface` and `ExactSurface`: the hydrostatic pressure integrated
//! over the wetted triangles, in closed form per triangle.
//!
//! `FastSurface` integrates over the fully submerged triangles, `ExactSurface` over the exact
//! wetted surface (the waterline triangles clipped). With the hierarchy, the inner nodes entirely
//! under water add their stored coefficients (see `moments`), and the cost follows the
//! waterline.

pub(crate) mod moments;
mod sums;

use crate::mesh::hierarchy::Visit;
use crate::query::frame::Frame;
use crate::query::reduction::{Sums, reduce};
use crate::query::surface_integral::moments::SurfaceMoments;
pub(crate) use crate::query::surface_integral::sums::SurfaceSums;
use crate::{Buoyancy, Mesh, Method, Real, Water};

impl<T: Real> Mesh<T> {
    /// `FastSurface` or `ExactSurface`, moments about the centroid.
    pub(crate) fn surface(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        method: Method,
        hierarchy: bool,
        parallel: bool,
    ) -> Buoyancy<T> {
        let exact = method == Method::ExactSurface;
        let n = frame.normal_local;
        // Positions relative to the centroid.
        let triangle = |s: &mut SurfaceSums<T>, i: usize| {
            let v = self.corners(i);
            s.add_wetted_part(&n, v, frame.heights(&v), exact, &self.double_areas[i]);
        };
        let sums = if hierarchy {
            self.surface_walk(frame, parallel, triangle)
        } else {
            reduce(self.triangles.len(), parallel, &triangle)
        };
        self.surface_result(frame, water, sums)
    }

    /// The surface sums over the hierarchy: the triangles of the leaves the surface crosses go
    /// through `triangle`; the inner nodes entirely under water add their stored coefficients,
    /// evaluated once at the end (see [`crate::query::surface_integral::moments`]), with their area; the leaves
    /// entirely under water, which store no coefficients, integrate their few triangles whole
    /// (every vertex lies below the surface by more than its round-off: each triangle is
    /// submerged, as `triangle` would find) and add their stored area. In parallel as
    /// [`Hierarchy::reduce`](crate::mesh::hierarchy::Hierarchy::reduce) says.
    fn surface_walk(
        &self,
        frame: &Frame<T>,
        parallel: bool,
        triangle: impl Fn(&mut SurfaceSums<T>, usize) + Sync,
    ) -> SurfaceSums<T> {
        let n = &frame.normal_local;
        let WalkSums {
            mut triangles,
            nodes,
        } = self.hierarchy.reduce(
            n,
            frame.height,
            parallel,
            &|walk: &mut WalkSums<T>, visit| match visit {
                Visit::SubmergedNode {
                    node,
                    triangle_count,
                } => {
                    let sums = &mut walk.triangles;
                    sums.counts.full += triangle_count as usize;
                    match self.node_sums.surface(node) {
                        Some(moments) => walk.nodes.add(moments),
                        // A leaf: no stored coefficients.
                        None => {
                            for i in self.hierarchy.range(node) {
                                let v = self.corners(i);
                                sums.add_triangle(n, v, frame.heights(&v));
                            }
                            sums.counts.wetted_area2 += self.node_sums.volume(node).double_area;
                        }
                    }
                }
                Visit::CrossedLeaf { triangles } => {
                    for i in triangles {
                        triangle(&mut walk.triangles, i);
                    }
                }
            },
        );
        nodes.add_to(n, frame.height, &mut triangles);
        triangles
    }

    /// Builds the result of a surface method from sums about the centroid (mesh frame).
    fn surface_result(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        sums: SurfaceSums<T>,
    ) -> Buoyancy<T> {
        let weight = water.specific_weight();
        let force = sums.force6 / T::from_f64_lossy(6.0);
        let volume = frame.normal_local.dot(&force);
        let center_of_buoyancy = if volume.abs() > self.volume_tolerance() {
            frame.center_of_mass
                + frame.rotation * (sums.moment24 / (T::from_f64_lossy(24.0) * volume))
        } else {
            frame.surface_point()
        };
        self.finish(
            frame,
            sums.counts,
            volume,
            center_of_buoyancy,
            frame.rotation * force * weight,
            frame.rotation * sums.torque24 * (weight / T::from_f64_lossy(24.0)),
        )
    }
}

/// The surface walk's running sums: the triangles integrated one by one, and the coefficients
/// of the nodes taken whole, evaluated once at the end.
#[derive(Clone, Copy)]
struct WalkSums<T: Real> {
    triangles: SurfaceSums<T>,
    nodes: SurfaceMoments<T>,
}

impl<T: Real> Sums for WalkSums<T> {
    fn zero() -> Self {
        WalkSums {
            triangles: SurfaceSums::zero(),
            nodes: SurfaceMoments::zero(),
        }
    }

    fn merge(mut self, other: Self) -> Self {
        self.nodes.add(&other.nodes);
        WalkSums {
            triangles: self.triangles.merge(other.triangles),
            nodes: self.nodes,
        }
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::Vector3;

    use super::*;

    #[test]
    fn corner_kernel_is_the_triangle_kernel() {
        let n = Vector3::new(0.2, 0.9, -0.3).normalize();
        let (a, ab, ca) = (
            Vector3::new(0.3, -1.2, 0.5),
            Vector3::new(1.1, 0.2, -0.4),
            Vector3::new(-0.7, 0.3, 0.9),
        );
        for sign in [1.0, -1.0] {
            let (mut corner, mut triangle) =
                (SurfaceSums::<f64>::zero(), SurfaceSums::<f64>::zero());
            corner.add_corner(&n, [a, ab, ca], -0.8, sign);
            let (b, c) = if sign > 0.0 { (ab, ca) } else { (ca, ab) };
            triangle.add_triangle(&n, [a, b, c], [-0.8, 0.0, 0.0]);
            assert!((corner.force6 - triangle.force6).norm() < 1e-14);
            assert!((corner.torque24 - triangle.torque24).norm() < 1e-14);
            assert!((corner.moment24 - triangle.moment24).norm() < 1e-14);
        }
    }

    #[test]
    fn pressure_force_on_a_horizontal_triangle() {
        // Unit right triangle facing down at depth 2: force (in units of ρg) = 2·(1/2) up.
        let r = [
            Vector3::new(0.0, -2.0, 0.0),
            Vector3::new(1.0, -2.0, 0.0),
            Vector3::new(0.0, -2.0, 1.0),
        ];
        let mut s = SurfaceSums::<f64>::zero();
        s.add_triangle(&Vector3::y(), r, [-2.0; 3]);
        assert!((s.force6 / 6.0 - Vector3::new(0.0, 1.0, 0.0)).norm() < 1e-15);
        // Uniform pressure acts at the triangle's centroid (1/3, -2, 1/3).
        let torque = s.torque24 / 24.0;
        let expected = Vector3::new(1.0 / 3.0, -2.0, 1.0 / 3.0).cross(&(s.force6 / 6.0));
        assert!((torque - expected).norm() < 1e-15);
    }

    #[test]
    fn pressure_moment_of_a_vertical_triangle_is_exact() {
        // Vertical triangle in the plane z = 0 facing +z, heights from -1 to 0.
        // ∫ h x dA over it, computed by 2D quadrature, must match w/12·|A|.
        let r = [
            Vector3::new(0.0, -1.0, 0.0),
            Vector3::new(2.0, -1.0, 0.0),
            Vector3::new(0.0, 0.0, 0.0),
        ];
        let h = r.map(|v| v.y);
        let mut s = SurfaceSums::<f64>::zero();
        s.add_triangle(&Vector3::y(), r, h);
        // Midpoint rule on a fine grid of the triangle x ∈ [0, 2(−y)], y ∈ [−1, 0].
        let n = 2000;
        let (mut fz, mut mx, mut my) = (0.0, 0.0, 0.0);
        for i in 0..n {
            let y = -1.0 + (i as f64 + 0.5) / n as f64;
            let width = -2.0 * y;
            for j in 0..n {
                let x = width * (j as f64 + 0.5) / n as f64;
                let da = width / n as f64 / n as f64;
                fz += y * da; // force ∫ h n̂ dA, n̂ = +z
                mx += y * y * da; // (r × h n̂)_x = y·h
                my += -x * y * da; // (r × h n̂)_y = −x·h
            }
        }
        let force = s.force6 / 6.0;
        let torque = s.torque24 / 24.0;
        assert!(
            (force - Vector3::new(0.0, 0.0, fz)).norm() < 1e-6,
            "{force:?} vs {fz}"
        );
        assert!(
            (torque - Vector3::new(mx, my, 0.0)).norm() < 1e-6,
            "{torque:?} vs {mx}, {my}"
        );
    }
}
