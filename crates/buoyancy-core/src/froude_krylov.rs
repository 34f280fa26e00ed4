//! Linear Froude–Krylov pressure under Airy and spectral seas: the pressure of the undisturbed
//! wave, whose wave part decays with depth, integrated over the wetted surface by quadrature.
//!
//! # The model
//! At a point `z` above the still plane (horizontal position `q`), in units of `ρ·g`,
//!
//! ```text
//! p = −z + Σ aᵢ·P(z)·cos θᵢ,   P(z) = cosh k(z+h)/cosh kh   (e^{kz} in deep water),
//! ```
//!
//! `θᵢ = kᵢ·q − ωᵢ·t + φᵢ`. Above the still plane (in a crest) `P = 1`: the pressure is the
//! hydrostatic one below the local surface (a linear extrapolation of the wave part, no
//! stretching). The pressure is never negative: it is clipped at zero.
//!
//! The wetted surface is the hydrostatic one (each triangle cut where the depth below the
//! surface, interpolated from its vertices, is zero; see `wave_pressure`), and the pressure is
//! integrated over each wetted piece by the degree-5, 7-point rule of Dunavant: exact for
//! polynomials of degree 5 over a piece; for a wave of number `k` over a piece of size `L` its
//! error falls as `(k·L)⁶`.

use nalgebra::{Point3, Vector3};

use crate::buoyancy::TriangleCounts;
use crate::clip::{TriangleClass, classify, clip_below};
use crate::wave_pressure::on_line_of_action;
use crate::waves::{AiryWaves, ResolvedWave, pressure_ratio, resolve};
use crate::{Buoyancy, Error, Mesh, Pose, Real, Water};

/// Dunavant's degree-5 rule on a triangle: barycentric coordinates `(α, β, β)` (and their
/// permutations) with weights summing to 1.
const RULE: [(f64, f64, f64); 3] = [
    (1.0 / 3.0, 1.0 / 3.0, 0.225),
    (
        0.059_715_871_789_770,
        0.470_142_064_105_115,
        0.132_394_152_788_506,
    ),
    (
        0.797_426_985_353_087,
        0.101_286_507_323_456,
        0.125_939_180_544_827,
    ),
];

/// One evaluation's sea: its components resolved for the water, and the depth.
struct Sea<T: Real> {
    waves: alloc::vec::Vec<ResolvedWave<T>>,
    depth: Option<T>,
}

impl<T: Real> Sea<T> {
    /// The pressure, in units of `ρ·g`, at a point of height `z` above the still plane and
    /// horizontal position `q` at `time` (see the module documentation).
    fn pressure(&self, q: &Point3<T>, z: T, time: T) -> T {
        let below = z.min(T::zero());
        let wave = self.waves.iter().fold(T::zero(), |sum, w| {
            sum + w.amplitude
                * pressure_ratio(w.wavenumber, below, self.depth)
                * w.phase_at(&q.coords, time).cos()
        });
        (wave - z).max(T::zero())
    }
}

impl<T: Real> Mesh<T> {
    /// The buoyancy of this mesh placed by `pose` in `water` under the Airy or spectral sea
    /// `waves` at `time` (s), by the linear Froude–Krylov pressure (see the
    /// [module documentation](crate::froude_krylov)): the pressure of the undisturbed wave,
    /// whose wave part decays with depth, integrated over the wetted surface. The torque is
    /// about the center of mass; the center is the point of the force's line of action nearest
    /// the center of mass; the volume is the one implied by the vertical force.
    ///
    /// ```
    /// use buoyancy_core::waves::{AiryComponent, AiryWaves};
    /// use buoyancy_core::{shape, Mesh, Pose, Water};
    /// use nalgebra::{Translation3, UnitQuaternion, Vector3};
    ///
    /// // A ball 3 m under a 10 m swell: the wave part of the pressure has decayed by e^{−k·3}.
    /// let (v, t) = shape::uv_sphere::<f64>(0.5, 48, 24)?;
    /// let ball = Mesh::new(v, t)?;
    /// let swell = AiryWaves::new(
    ///     vec![AiryComponent { amplitude: 0.5, wavelength: 10.0, direction: Vector3::x(), phase: 0.0 }],
    ///     None,
    /// )?;
    /// let deep = Pose::from_parts(Translation3::new(0.0, -3.0, 0.0), UnitQuaternion::identity());
    /// let b = ball.buoyancy_froude_krylov(&deep, &Water::default(), &swell, 0.0)?;
    /// let still = 1000.0 * 9.81 * ball.volume();
    /// assert!((b.force.y / still - 1.0).abs() < 0.05);
    /// # Ok::<(), buoyancy_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidPose`] for a non-finite pose; [`Error::InvalidSurface`] for a non-finite
    /// time or a wave direction along the up normal; [`Error::NonFiniteResult`] if the result
    /// overflows.
    pub fn buoyancy_froude_krylov(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        waves: &AiryWaves<T>,
        time: T,
    ) -> Result<Buoyancy<T>, Error> {
        let (frame, heights) = self.under_waves(pose, water, waves, time)?;
        let sea = Sea {
            waves: resolve(waves.components(), water, waves.depth())?,
            depth: waves.depth(),
        };
        // Pressure at a point relative to the centroid, mesh frame, in units of ρg.
        let pressure = |r: &Vector3<T>| {
            let z = frame.normal_local.dot(r) + frame.height;
            let x = frame.center_of_mass + frame.rotation * r;
            sea.pressure(&(x - frame.normal * z), z, time)
        };
        let (mut force, mut torque) = (Vector3::zeros(), Vector3::zeros());
        let mut piece = |q: [Vector3<T>; 3]| {
            let area = (q[1] - q[0]).cross(&(q[2] - q[0])) * T::from_f64_lossy(0.5);
            let (mut mean, mut moment) = (T::zero(), Vector3::zeros());
            for &(alpha, beta, weight) in &RULE {
                let (alpha, beta, weight) = (
                    T::from_f64_lossy(alpha),
                    T::from_f64_lossy(beta),
                    T::from_f64_lossy(weight),
                );
                // The center once, the other points in their three permutations.
                let permutations = if alpha == beta { 1 } else { 3 };
                for j in 0..permutations {
                    let r = q[j] * alpha + q[(j + 1) % 3] * beta + q[(j + 2) % 3] * beta;
                    let p = pressure(&r) * weight;
                    mean += p;
                    moment += r * p;
                }
            }
            // −∫ p n̂ dA and −∫ r × p n̂ dA about the centroid.
            force -= area * mean;
            torque -= moment.cross(&area);
        };
        let mut counts = TriangleCounts::default();
        for i in 0..self.triangles.len() {
            let [a, b, c] = self.leaf_triangles[i];
            let h = [
                heights[a as usize],
                heights[b as usize],
                heights[c as usize],
            ];
            let v = self.corners(i);
            match classify(&h) {
                TriangleClass::Submerged => {
                    counts.full += 1;
                    piece(v);
                }
                TriangleClass::Cut => {
                    counts.partial += 1;
                    clip_below(v, h, |q, _| piece(q));
                }
                TriangleClass::Dry => {}
            }
        }
        let weight = water.specific_weight();
        let world_force = frame.rotation * force * weight;
        let world_torque = frame.rotation * torque * weight;
        let volume = frame.normal_local.dot(&force);
        let center = if volume.abs() > self.volume_tolerance() {
            on_line_of_action(
                &frame.center_of_mass,
                &world_force,
                &world_torque,
                &frame.center_of_mass,
            )
        } else {
            frame.surface_point()
        };
        let result = self.finish(&frame, counts, volume, center, world_force, world_torque);
        result.checked()
    }
}
