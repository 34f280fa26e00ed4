//! The buoyancy query, [`Mesh::buoyancy`]: one entry point for still water and waves.
//!
//! In still water each evaluation brings the water plane into the mesh frame ([`Frame`]), chooses the
//! traversal ([`Traversal`]), and hands over to the volume methods (`volume`) or the surface
//! methods (`surface_integral`), which sum per-triangle terms deterministically (`reduction`).
//!
//! # Determinism
//! The scan sums the triangles in fixed chunks combined pairwise in a fixed tree; the hierarchy
//! sums its top subtrees apart and merges them up the tree (see `hierarchy`). Either way the
//! pieces are the same whether they run on one thread or on rayon's pool: the serial and
//! parallel results are bit-identical and the same input always gives the same output.

use nalgebra::{Point3, Vector3};

use crate::query::frame::Frame;
use crate::query::result::TriangleCounts;
use crate::query::waves::check_time;
use crate::query::{Pressure, Query, Sea};
use crate::{Buoyancy, Error, Mesh, Method, Pose, Real, Traversal, Water};

impl<T: Real> Mesh<T> {
    /// The buoyancy of this mesh placed by `pose` (mesh → world) in `sea`, computed as `query`
    /// says: the force and torque of the water's pressure over the wetted surface, world frame,
    /// the torque about the body's center of mass (see [`Buoyancy::about`] for another point).
    ///
    /// `sea` is a [`Water`] for still water (`&water` will do) or a [`Sea`]: the still water
    /// under a moving free surface at a time, with the hydrostatic or the Froude–Krylov
    /// pressure. `query` is a [`Method`] or a [`Query`] (the method, the traversal, the threads).
    /// See the [guide](crate::query) for the model of each case.
    ///
    /// * **Still water** (no surface, or one whose elevation bound is zero): every method;
    ///   the traversal as asked ([`Traversal::Auto`]: the hierarchy from
    ///   [`Traversal::CROSSOVER`] triangles, so that the cost follows the waterline). No
    ///   allocation.
    /// * **Waves, hydrostatic pressure**: the exact integral of `ρ·g·(η − h)` over the wetted
    ///   surface, for [`Method::Exact`] and [`Method::ExactSurface`] alike (for a flat surface
    ///   they agree to round-off; the volume formula is still water's way to the same
    ///   integral). The hierarchy is walked against the layer the surface lies in
    ///   ([`Traversal::Scan`]: every vertex evaluated, every triangle integrated on its own). It
    ///   allocates a number per vertex and a point per vertex that may be wet.
    /// * **Waves, Froude–Krylov pressure**: the same methods, every wetted piece integrated by
    ///   a degree-5 quadrature, on the calling thread.
    ///
    /// Parallel (feature `rayon`, [`Query::in_parallel`]): the work is cut in pieces fixed by
    /// the mesh (chunks of triangles for the scan, subtrees for the hierarchy, 16,384 vertices
    /// for a surface), never by the number of threads, and merged in a fixed order: the result
    /// is bit-identical to the serial one. Only large meshes are split: the hierarchy's halves
    /// from 100,000 triangles, the scan's chunks of 4,096. On 2 threads the hierarchy of a
    /// 10⁶-triangle mesh runs about 1.3–1.5× faster (`cargo bench --bench rounds --features
    /// rayon -- large parallel hierarchy`). For many bodies or poses, parallelise across them
    /// instead.
    ///
    /// ```
    /// use buoyancy_core::query::Query;
    /// use buoyancy_core::{mesh::primitives, Mesh, Method, Pose, Traversal, Water};
    /// use nalgebra::{Translation3, UnitQuaternion};
    ///
    /// let (v, t) = primitives::uv_sphere::<f64>(0.5, 32, 16)?;
    /// let ball = Mesh::new(v, t)?;
    /// let pose = Pose::from_parts(Translation3::new(0.0, 0.1, 0.0), UnitQuaternion::identity());
    /// let water = Water::default();
    /// let auto = ball.buoyancy(&pose, &water, Method::Exact)?;
    /// let scan = ball.buoyancy(&pose, &water, Query::new(Method::Exact).with_traversal(Traversal::Scan))?;
    /// assert!((auto.force - scan.force).norm() < 1e-9);
    /// # Ok::<(), buoyancy_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// * [`Error::InvalidPose`] if the pose has a NaN or infinite component or a zero
    ///   quaternion (a non-unit quaternion is normalised);
    /// * [`Error::Unsupported`] for [`Method::Fast`], [`Method::Improved`] or
    ///   [`Method::FastSurface`] under waves (they assume a flat surface), or the Froude–Krylov
    ///   pressure under a surface that is not [`AiryWaves`](crate::water::AiryWaves);
    /// * [`Error::InvalidSurface`] for a non-finite time or what the surface reports;
    /// * [`Error::NonFiniteResult`] if the pose or water is so large that the result overflows.
    pub fn buoyancy<'a>(
        &self,
        pose: &Pose<T>,
        sea: impl Into<Sea<'a, T>>,
        query: impl Into<Query>,
    ) -> Result<Buoyancy<T>, Error> {
        let (sea, query) = (sea.into(), query.into());
        let method = query.method();
        let scan = query.traversal() == Traversal::Scan;
        let water = sea.water();
        if sea.surface().is_some() {
            check_time(sea.time())?;
        }
        match sea.surface() {
            Some(surface) if !sea.is_calm() => {
                check_wave_method(method)?;
                match sea.pressure() {
                    Pressure::Hydrostatic => self.hydrostatic_in_waves(
                        pose,
                        water,
                        surface,
                        sea.time(),
                        scan,
                        query.is_parallel(),
                    ),
                    Pressure::FroudeKrylov => {
                        self.froude_krylov(pose, water, sea.airy_waves()?, sea.time())
                    }
                }
            }
            _ => {
                if sea.pressure() == Pressure::FroudeKrylov && sea.surface().is_some() {
                    // Checked even when calm: a grid at rest is no Airy sea.
                    sea.airy_waves()?;
                }
                self.in_still_water(pose, water, method, query.traversal(), query.is_parallel())
            }
        }
    }

    fn in_still_water(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        method: Method,
        traversal: Traversal,
        parallel: bool,
    ) -> Result<Buoyancy<T>, Error> {
        let frame = Frame::new(self, pose, water)?.nearer_when_submerged(self);
        let hierarchy = match traversal {
            Traversal::Auto => self.triangles.len() >= Traversal::CROSSOVER,
            Traversal::Scan => false,
            Traversal::Hierarchy => true,
        };
        let result = match method {
            Method::Fast => self.fast(&frame, water, hierarchy, parallel),
            Method::Improved | Method::Exact => {
                self.exact_or_improved(&frame, water, method, hierarchy, parallel)
            }
            Method::FastSurface | Method::ExactSurface => {
                self.surface(&frame, water, method, hierarchy, parallel)
            }
        };
        result.checked()
    }

    /// The corners of triangle `i` (in leaf order), relative to the centroid, mesh frame.
    #[inline(always)]
    pub(crate) fn corners(&self, i: usize) -> [Vector3<T>; 3] {
        let [a, b, c] = self.leaf_triangles[i];
        [
            self.vertices[a as usize],
            self.vertices[b as usize],
            self.vertices[c as usize],
        ]
    }

    /// Below this |volume|, the center of buoyancy is round-off and is replaced by the surface point.
    pub(crate) fn volume_tolerance(&self) -> T {
        self.volume_scale * T::default_epsilon() * T::from_f64_lossy(64.0)
    }

    /// The result, with the torque about the center of mass; the wetted area is half of
    /// `counts.wetted_area2`.
    pub(crate) fn finish(
        &self,
        frame: &Frame<T>,
        counts: TriangleCounts<T>,
        submerged_volume: T,
        center_of_buoyancy: Point3<T>,
        force: Vector3<T>,
        torque: Vector3<T>,
    ) -> Buoyancy<T> {
        Buoyancy {
            submerged_volume,
            center_of_buoyancy,
            force,
            torque,
            torque_point: frame.center_of_mass,
            fully_submerged: counts.full,
            partially_submerged: counts.partial,
            wetted_area: counts.wetted_area2 * T::from_f64_lossy(0.5),
        }
    }
}

/// Checks `method` under waves: the exact methods are allowed, both the exact integral of the pressure.
///
/// # Errors
/// [`Error::Unsupported`] (`method`) for the methods that assume a flat surface.
fn check_wave_method(method: Method) -> Result<(), Error> {
    let reason = match method {
        Method::Exact | Method::ExactSurface => return Ok(()),
        Method::Fast => {
            "fast counts the triangles below a flat water plane, and the water has waves: \
             under waves give exact or exact_surface (the exact integral of the pressure)"
        }
        Method::Improved => {
            "improved cuts the triangles at a flat water plane, and the water has waves: \
             under waves give exact or exact_surface (the exact integral of the pressure)"
        }
        Method::FastSurface => {
            "fast_surface integrates below a flat water plane, and the water has waves: \
             under waves give exact or exact_surface (the exact integral of the pressure)"
        }
    };
    Err(Error::Unsupported {
        parameter: "method",
        reason,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use nalgebra::{Translation3, UnitQuaternion, Vector3};

    fn at(x: f64, y: f64, z: f64) -> Pose<f64> {
        Pose::from_parts(Translation3::new(x, y, z), UnitQuaternion::identity())
    }

    #[test]
    fn half_submerged_cube_all_methods() {
        let (v, t) = primitives::cube::<f64>(4).unwrap();
        let cube = Mesh::new(v, t).unwrap();
        let water = Water::default();
        for method in Method::ALL {
            let b = cube.buoyancy(&at(0.0, 0.0, 0.0), &water, method).unwrap();
            assert!(b.force.x.abs() < 1e-9 && b.force.z.abs() < 1e-9, "{method}");
            if method.is_exact() {
                assert!((b.submerged_volume - 0.5).abs() < 1e-14, "{method}: {b:?}");
                assert!((b.center_of_buoyancy - Point3::new(0.0, -0.25, 0.0)).norm() < 1e-14);
                assert!((b.force.y - 0.5 * 9810.0).abs() < 1e-9);
                assert!(b.torque.norm() < 1e-10, "{method}: {:?}", b.torque);
            }
        }
    }

    #[test]
    fn dry_body_has_no_force_and_a_finite_center() {
        let (v, t) = primitives::cube::<f64>(2).unwrap();
        let cube = Mesh::new(v, t).unwrap();
        for method in Method::ALL {
            let b = cube
                .buoyancy(&at(1.0, 3.0, 2.0), &Water::default(), method)
                .unwrap();
            assert_eq!(b.submerged_volume, 0.0);
            assert_eq!(b.force, Vector3::zeros());
            assert_eq!(b.torque, Vector3::zeros());
            assert_eq!(b.center_of_buoyancy, Point3::new(1.0, 0.0, 2.0));
            assert_eq!((b.fully_submerged, b.partially_submerged), (0, 0));
        }
    }

    #[test]
    fn invalid_poses_are_errors() {
        let (v, t) = primitives::cube::<f64>(1).unwrap();
        let cube = Mesh::new(v, t).unwrap();
        let w = Water::default();
        let e = cube
            .buoyancy(&at(f64::NAN, 0.0, 0.0), &w, Method::Exact)
            .unwrap_err();
        assert!(matches!(e, Error::InvalidPose { .. }), "{e}");
        let mut pose = at(0.0, 0.0, 0.0);
        pose.rotation =
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(0.0, 0.0, 0.0, 0.0));
        assert!(matches!(
            cube.buoyancy(&pose, &w, Method::Exact),
            Err(Error::InvalidPose { .. })
        ));
        pose.rotation =
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(f64::INFINITY, 0.0, 0.0, 0.0));
        assert!(matches!(
            cube.buoyancy(&pose, &w, Method::Exact),
            Err(Error::InvalidPose { .. })
        ));
        // A drifted quaternion is renormalised.
        pose.rotation =
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(2.0, 0.0, 0.0, 0.0));
        let b = cube.buoyancy(&pose, &w, Method::Exact).unwrap();
        assert!((b.submerged_volume - 0.5).abs() < 1e-14);
        // Overflow is reported, not returned as infinity.
        let huge = at(0.0, -1e300, 0.0);
        let big_water = Water::new(1e300, 1e10, Vector3::y(), 0.0).unwrap();
        assert_eq!(
            cube.buoyancy(&huge, &big_water, Method::Exact),
            Err(Error::NonFiniteResult)
        );
    }
}
