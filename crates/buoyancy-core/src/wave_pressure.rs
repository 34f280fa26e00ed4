//! Buoyancy under a moving, non-planar free surface: the hydrostatic pressure of the waves
//! integrated exactly over the wetted surface.
//!
//! # The model
//! With `η` the elevation of the free surface above the still plane (see [`waves`](crate::waves)),
//! a vertex `x` lies `h = n·x − level − η(q)` above the surface, `q` its horizontal position.
//! Over each triangle `h` is taken linear between its vertices (the surface is sampled at the
//! vertices, once per vertex per evaluation), the triangle is cut exactly where `h = 0` (both
//! triangles of an edge cut it at the same point: no gaps, no overlaps), and the hydrostatic
//! pressure `p = −ρ·g·h ≥ 0` is integrated in closed form over the part under water, force and
//! moment, as [`Method::ExactSurface`](crate::Method::ExactSurface) does under still water:
//!
//! ```text
//! F = −∫ p n̂ dA,    τ = −∫ (r − c) × p n̂ dA   over the wetted surface.
//! ```
//!
//! The horizontal forces from the wave slope are part of it. For the calm surface the result is
//! `ExactSurface`'s, bit for bit with [`Traversal::Scan`](crate::Traversal::Scan).
//!
//! The result is a [`Buoyancy`]: `submerged_volume` is the volume implied by the vertical force,
//! `n·F/(ρ·g)`; `center_of_buoyancy` is a point of the force's line of action (the central axis
//! of the force and torque): the one nearest the still-water center of buoyancy formula applied
//! to the wetted surface, which under still water lies on that line already.

use alloc::vec::Vec;

use nalgebra::{Point3, Vector3};

use crate::frame::Frame;
use crate::reduction::reduce;
use crate::surface::SurfaceSums;
use crate::waves::WaterSurface;
use crate::{Buoyancy, Error, Mesh, Pose, Real, Water};

impl<T: Real> Mesh<T> {
    /// The buoyancy of this mesh placed by `pose` (mesh → world) in `water` whose free surface
    /// is `surface` at `time` (s): the hydrostatic pressure of the waves integrated exactly over
    /// the wetted surface (see the [module documentation](crate::wave_pressure)). The torque is
    /// about the body's center of mass.
    ///
    /// One evaluation of the surface per vertex that may be wet (see
    /// [`WaterSurface::elevation_bound`]); every triangle is visited (the hierarchy's stored
    /// sums assume a flat surface). It allocates three buffers of one number or point per vertex.
    ///
    /// ```
    /// use buoyancy_core::waves::{AiryComponent, AiryWaves, CalmSurface};
    /// use buoyancy_core::{shape, Mesh, Method, Pose, Traversal, Water};
    /// use nalgebra::{Translation3, UnitQuaternion, Vector3};
    ///
    /// let (v, t) = shape::cube::<f64>(4)?;
    /// let cube = Mesh::new(v, t)?;
    /// let pose = Pose::from_parts(Translation3::new(0.0, -0.2, 0.0), UnitQuaternion::identity());
    /// let water = Water::default();
    ///
    /// // Calm water: Exact Surface.
    /// let calm = cube.buoyancy_in_waves(&pose, &water, &CalmSurface, 0.0)?;
    /// let still = cube.buoyancy_with(&pose, &water, Method::ExactSurface, Traversal::Scan)?;
    /// assert_eq!(calm.force, still.force);
    ///
    /// // A long swell whose crest is over the cube: more under water, pushed up harder.
    /// let swell = AiryWaves::new(
    ///     vec![AiryComponent { amplitude: 0.1, wavelength: 50.0, direction: Vector3::x(), phase: 0.0 }],
    ///     None,
    /// )?;
    /// let crest = cube.buoyancy_in_waves(&pose, &water, &swell, 0.0)?;
    /// assert!(crest.force.y > still.force.y);
    /// # Ok::<(), buoyancy_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidPose`] for a non-finite pose; [`Error::InvalidSurface`] for a non-finite
    /// time or what the surface reports; [`Error::NonFiniteResult`] if the result overflows.
    pub fn buoyancy_in_waves(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
    ) -> Result<Buoyancy<T>, Error> {
        let (frame, heights) = self.under_waves(pose, water, surface, time)?;
        let n = frame.normal_local;
        let triangle = |s: &mut SurfaceSums<T>, i: usize| {
            let [a, b, c] = self.leaf_triangles[i];
            let h = [
                heights[a as usize],
                heights[b as usize],
                heights[c as usize],
            ];
            s.add_wetted_part(&n, self.corners(i), h, true);
        };
        let sums = reduce(self.triangles.len(), false, &triangle);
        let result = self.wave_result(&frame, water, sums);
        result.checked()
    }

    /// The frame of the evaluation and the heights of the vertices above the free surface.
    ///
    /// # Errors
    /// As [`Mesh::buoyancy_in_waves`].
    pub(crate) fn under_waves(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
    ) -> Result<(Frame<T>, Vec<T>), Error> {
        let frame = Frame::new(self, pose, water)?;
        if !time.is_finite() {
            return Err(Error::InvalidSurface {
                parameter: "time",
                reason: "the time must be finite (s)",
            });
        }
        let heights = self.heights_below_waves(&frame, water, surface, time)?;
        Ok((frame, heights))
    }

    /// The height of every stored vertex above the free surface, `n·x − level − η(q, time)`.
    /// With a bound `b` on `|η|`, a vertex higher than `b` plus the longest edge above the
    /// still plane belongs to dry triangles only: it gets `n·x − level − b > 0` and the surface
    /// is not evaluated there.
    fn heights_below_waves(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
    ) -> Result<Vec<T>, Error> {
        let n = frame.normal_local;
        // Heights above the still plane.
        let mut heights: Vec<T> = self
            .vertices
            .iter()
            .map(|v| n.dot(v) + frame.height)
            .collect();
        let bound = surface.elevation_bound().filter(|b| b.is_finite());
        let reach = bound.map(|b| b + self.longest_edge);
        let wet = |h: &T| reach.is_none_or(|r| *h <= r);
        // The horizontal positions, world frame, of the vertices that may be wet.
        let points: Vec<Point3<T>> = self
            .vertices
            .iter()
            .zip(&heights)
            .filter(|(_, h)| wet(h))
            .map(|(v, h)| frame.center_of_mass + frame.rotation * v - frame.normal * *h)
            .collect();
        let mut elevations = alloc::vec![T::zero(); points.len()];
        surface.elevations(water, &points, time, &mut elevations)?;
        let mut eta = elevations.iter();
        for h in heights.iter_mut() {
            if wet(h) {
                let eta = *eta.next().unwrap_or(&T::zero());
                if !eta.is_finite() {
                    return Err(Error::InvalidSurface {
                        parameter: "surface",
                        reason: "the surface gave a NaN or infinite elevation",
                    });
                }
                *h -= eta;
            } else if let Some(b) = bound {
                *h -= b;
            }
        }
        Ok(heights)
    }

    /// The result from the surface sums about the centroid (mesh frame): the force and torque
    /// as `ExactSurface`'s, the center moved onto the force's line of action.
    fn wave_result(&self, frame: &Frame<T>, water: &Water<T>, sums: SurfaceSums<T>) -> Buoyancy<T> {
        let weight = water.specific_weight();
        let force_local = sums.force6 / T::from_f64_lossy(6.0);
        let volume = frame.normal_local.dot(&force_local);
        let force = frame.rotation * force_local * weight;
        let torque = frame.rotation * sums.torque24 * (weight / T::from_f64_lossy(24.0));
        let center_of_buoyancy = if volume.abs() > self.volume_tolerance() {
            let still_water_center = frame.center_of_mass
                + frame.rotation * (sums.moment24 / (T::from_f64_lossy(24.0) * volume));
            on_line_of_action(&frame.center_of_mass, &force, &torque, &still_water_center)
        } else {
            frame.surface_point()
        };
        self.finish(
            frame,
            sums.counts,
            volume,
            center_of_buoyancy,
            force,
            torque,
        )
    }
}

/// The point of the central axis of the force system (`force`, `torque` about `about`) nearest
/// to `near`: the axis passes through `about + force × torque / |force|²` along `force`.
pub(crate) fn on_line_of_action<T: Real>(
    about: &Point3<T>,
    force: &Vector3<T>,
    torque: &Vector3<T>,
    near: &Point3<T>,
) -> Point3<T> {
    let f2 = force.norm_squared();
    if f2 <= T::zero() || !f2.is_finite() {
        return *near;
    }
    let on_axis = about + force.cross(torque) / f2;
    on_axis + force * (force.dot(&(near - on_axis)) / f2)
}
