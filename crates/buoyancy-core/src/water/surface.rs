//! The free surface: the [`WaterSurface`] trait every surface implements, the calm surface and a
//! surface given by a function.

use nalgebra::{Point3, Vector3};

use super::AiryWaves;
#[cfg(doc)]
use crate::Mesh;
use crate::{Error, Real, Water};

/// A free surface: the elevation `η` (m) above the still plane of a [`Water`] at horizontal
/// positions and a time (see the [module documentation](crate::water)).
pub trait WaterSurface<T: Real>: Sync {
    /// Writes `η(points[i], time)` into `elevations[i]`, for horizontal positions `points`
    /// (world frame, on the still plane of `water`) at `time` (s). `elevations` has the length
    /// of `points`.
    ///
    /// # Errors
    /// A typed [`Error`] if the surface cannot be evaluated there (e.g. a non-finite height).
    fn elevations(
        &self,
        water: &Water<T>,
        points: &[Point3<T>],
        time: T,
        elevations: &mut [T],
    ) -> Result<(), Error>;

    /// A bound on `|η|` everywhere and at all times (m), if the surface knows one: what lets
    /// [`Mesh::buoyancy`] under waves walk its hierarchy. A vertex higher above the still plane
    /// than this bound plus the mesh's longest edge belongs to dry triangles only, so the
    /// surface is not evaluated there; the nodes more than the bound below the still plane are
    /// summed whole. `Some(0)` is still water. `None` (the default): every vertex evaluated,
    /// every triangle integrated on its own. A bound that is exceeded gives wrong results.
    fn elevation_bound(&self) -> Option<T> {
        None
    }

    /// Bounds `(low, high)` on `η` (m) over the horizontal disc of `radius` (m) about the
    /// horizontal position of `center` (world frame) at `time` (s), if the surface knows them:
    /// the layer [`Mesh::buoyancy`] walks its hierarchy against under waves, tighter than
    /// [`elevation_bound`](Self::elevation_bound) where the waves are long against the body.
    /// The default is `(−b, b)` with `b` the elevation bound. [`AiryWaves`] bound each
    /// component over the phases the disc spans, [`HeightGrid`](super::HeightGrid) takes the extremes of the
    /// samples around the disc. Bounds that are exceeded give wrong results.
    fn elevation_range(
        &self,
        water: &Water<T>,
        center: &Point3<T>,
        radius: T,
        time: T,
    ) -> Option<(T, T)> {
        let _ = (water, center, radius, time);
        self.elevation_bound().map(|b| (-b, b))
    }

    /// The velocity of the water at the world point `point` at `time` (m/s, world frame), if
    /// the surface models it: what a floating body's damping is taken relative to (see
    /// [`controller`](crate::controller)). `None` (the default): the water does not move with
    /// this surface. [`AiryWaves`] give their orbital velocity.
    fn water_velocity(&self, water: &Water<T>, point: &Point3<T>, time: T) -> Option<Vector3<T>> {
        let _ = (water, point, time);
        None
    }

    /// This surface as [`AiryWaves`], if it is: the components the
    /// [Froude–Krylov](crate::query::Pressure::FroudeKrylov) pressure decays with depth. `None`
    /// (the default) for every other surface.
    fn as_airy_waves(&self) -> Option<&AiryWaves<T>> {
        None
    }
}

/// Still water: `η = 0` everywhere, at all times.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CalmSurface;

impl<T: Real> WaterSurface<T> for CalmSurface {
    fn elevations(
        &self,
        _: &Water<T>,
        _: &[Point3<T>],
        _: T,
        elevations: &mut [T],
    ) -> Result<(), Error> {
        elevations.fill(T::zero());
        Ok(())
    }

    /// Zero: the surface is the still plane.
    fn elevation_bound(&self) -> Option<T> {
        Some(T::zero())
    }
}

/// A surface given by a function `η(q, t)` of the horizontal position `q` (world frame, on the
/// still plane) and the time `t`, called once per point.
///
/// ```
/// use buoyancy_core::water::{SurfaceFn, WaterSurface};
/// use buoyancy_core::Water;
/// use nalgebra::Point3;
///
/// // A plane tilted along x: η = 0.1·x.
/// let ramp = SurfaceFn(|q: &Point3<f64>, _t: f64| 0.1 * q.x);
/// let mut eta = [0.0; 2];
/// ramp.elevations(&Water::default(), &[Point3::new(1.0, 0.0, 0.0), Point3::new(-2.0, 0.0, 5.0)], 0.0, &mut eta)?;
/// assert_eq!(eta, [0.1, -0.2]);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct SurfaceFn<F>(pub F);

impl<T: Real, F: Fn(&Point3<T>, T) -> T + Sync> WaterSurface<T> for SurfaceFn<F> {
    fn elevations(
        &self,
        _: &Water<T>,
        points: &[Point3<T>],
        time: T,
        elevations: &mut [T],
    ) -> Result<(), Error> {
        for (eta, q) in elevations.iter_mut().zip(points) {
            *eta = (self.0)(q, time);
            if !eta.is_finite() {
                return Err(Error::InvalidSurface {
                    parameter: "surface",
                    reason: "the surface function returned a NaN or infinite elevation",
                });
            }
        }
        Ok(())
    }
}
