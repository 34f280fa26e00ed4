//! Trochoidal (Gerstner) waves: water particles on circles, crests sharper than troughs.

use alloc::vec::Vec;

use nalgebra::{Matrix3, Point3, Vector3};

use super::{AiryComponent, WaterSurface, amplitude_sum, resolve};
use crate::{Error, Real, Water};

/// Trochoidal (Gerstner) waves in deep water: the particle at rest at horizontal position `p`
/// moves to
///
/// ```text
/// x(p, t) = p − Σ dᵢ·aᵢ·sin θᵢ,   η = Σ aᵢ·cos θᵢ,   θᵢ = kᵢ·p − ωᵢ·t + φᵢ,   ωᵢ² = g·kᵢ,
/// ```
///
/// (`dᵢ` the unit direction of component `i`, `kᵢ = kᵢ·dᵢ`). The surface is the set of those
/// points, so the elevation at a fixed point `q` needs the particle that is there: `p` is
/// solved from `x(p, t) = q` by a safeguarded Newton's method, to `10⁻¹² · Σ aᵢ` or the
/// round-off of the position, whichever is larger (hence `η` too, its slope being below 1).
/// The map is one-to-one while the steepness `Σ kᵢ·aᵢ` is below 1; at 1 the
/// crests become cusps and beyond they fold over, which [`GerstnerWaves::new`] rejects.
///
/// ```
/// use buoyancy_core::water::{AiryComponent, GerstnerWaves, WaterSurface};
/// use buoyancy_core::Water;
/// use nalgebra::{Point3, Vector3};
///
/// let wave = AiryComponent { amplitude: 1.0, wavelength: 30.0, direction: Vector3::x(), phase: 0.0 };
/// let gerstner = GerstnerWaves::new(vec![wave])?;
/// // The crest is at x = 0, 1 m high; the trough, half a wavelength on, 1 m deep.
/// let mut eta = [0.0f64; 2];
/// gerstner.elevations(&Water::default(), &[Point3::origin(), Point3::new(15.0, 0.0, 0.0)], 0.0, &mut eta)?;
/// assert!((eta[0] - 1.0).abs() < 1e-10 && (eta[1] + 1.0).abs() < 1e-10);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct GerstnerWaves<T: Real> {
    components: Vec<AiryComponent<T>>,
}

impl<T: Real> GerstnerWaves<T> {
    /// Gerstner waves of `components` (amplitude, wavelength, direction, phase as for Airy
    /// waves), in deep water.
    ///
    /// # Errors
    /// [`Error::InvalidSurface`] for a component that is not valid as an Airy component, and
    /// for a steepness `Σ kᵢ·aᵢ` of 1 or more: the surface would fold over.
    pub fn new(components: Vec<AiryComponent<T>>) -> Result<Self, Error> {
        let components = super::AiryWaves::new(components, None)?
            .components()
            .to_vec();
        let steepness = components
            .iter()
            .fold(T::zero(), |s, c| s + c.wavenumber() * c.amplitude);
        if steepness >= T::one() {
            return Err(Error::InvalidSurface {
                parameter: "components",
                reason: "a Gerstner sea with steepness Σ k·a of 1 or more folds over: lower the amplitudes",
            });
        }
        Ok(GerstnerWaves { components })
    }

    /// The components.
    pub fn components(&self) -> &[AiryComponent<T>] {
        &self.components
    }

    /// The position at `time` and the elevation of the particle at rest at horizontal position
    /// `rest` (world frame, on the still plane of `water`).
    ///
    /// # Errors
    /// [`Error::InvalidSurface`] if a direction is along the water's up normal.
    pub fn particle(
        &self,
        water: &Water<T>,
        rest: &Point3<T>,
        time: T,
    ) -> Result<(Point3<T>, T), Error> {
        let waves = resolve(&self.components, water, None)?;
        let (mut position, mut eta) = (*rest, T::zero());
        for w in &waves {
            let theta = w.phase_at(&rest.coords, time);
            position -= w.direction * (w.amplitude * theta.sin());
            eta += w.amplitude * theta.cos();
        }
        Ok((position, eta))
    }
}

impl<T: Real> WaterSurface<T> for GerstnerWaves<T> {
    fn elevations(
        &self,
        water: &Water<T>,
        points: &[Point3<T>],
        time: T,
        elevations: &mut [T],
    ) -> Result<(), Error> {
        let waves = resolve(&self.components, water, None)?;
        let total = amplitude_sum(&self.components);
        // The map p ↦ q + Σ dᵢaᵢ sin θᵢ(p) contracts by the steepness L = Σ kᵢaᵢ < 1, so a
        // residual below 10⁻¹²·Σa·(1 − L) puts p within 10⁻¹²·Σa of the particle.
        let steepness = waves
            .iter()
            .fold(T::zero(), |s, w| s + w.wavenumber * w.amplitude);
        let tolerance = T::from_f64_lossy(1e-12) * total * (T::one() - steepness);
        // r(p) = p − Σ dᵢaᵢ sin θᵢ − q and its Jacobian I − Σ aᵢ cos θᵢ dᵢ kᵢᵀ.
        let residual = |p: &Vector3<T>, q: &Point3<T>| {
            let mut r = p - q.coords;
            let mut jacobian = Matrix3::identity();
            for w in &waves {
                let (sin, cos) = w.phase_at(p, time).sin_cos();
                r -= w.direction * (w.amplitude * sin);
                jacobian -= w.direction * w.k.transpose() * (w.amplitude * cos);
            }
            (r, jacobian)
        };
        for (eta, q) in elevations.iter_mut().zip(points) {
            // Newton's method, safeguarded: a Newton step that does not lower the residual is
            // replaced by a step of the contraction, p − r(p), which lowers it by the factor L.
            let mut p = q.coords;
            let (mut r, mut jacobian) = residual(&p, q);
            // Nor can the residual go below the round-off of the position itself.
            let floor = T::default_epsilon() * T::from_f64_lossy(8.0) * (q.coords.norm() + total);
            let tolerance = tolerance.max(floor);
            let mut converged = false;
            for _ in 0..10_000 {
                if r.norm() <= tolerance {
                    converged = true;
                    break;
                }
                let newton = jacobian.lu().solve(&r).map(|step| p - step);
                let next = newton
                    .map(|candidate| (candidate, residual(&candidate, q)))
                    .filter(|(_, (next, _))| next.norm() < r.norm())
                    .unwrap_or_else(|| {
                        let contracted = p - r;
                        (contracted, residual(&contracted, q))
                    });
                (p, (r, jacobian)) = next;
            }
            if !converged {
                return Err(Error::InvalidSurface {
                    parameter: "time",
                    reason: "the Gerstner particle at a point did not converge (the time or position is too large for the scalar type)",
                });
            }
            *eta = waves.iter().fold(T::zero(), |e, w| {
                e + w.amplitude * w.phase_at(&p, time).cos()
            });
        }
        Ok(())
    }

    /// `Σ aᵢ`.
    fn elevation_bound(&self) -> Option<T> {
        Some(amplitude_sum(&self.components))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;
    use nalgebra::Vector3;

    fn sea() -> GerstnerWaves<f64> {
        GerstnerWaves::new(vec![
            AiryComponent {
                amplitude: 0.8,
                wavelength: 20.0,
                direction: Vector3::x(),
                phase: 0.1,
            },
            AiryComponent {
                amplitude: 0.4,
                wavelength: 9.0,
                direction: Vector3::new(1.0, 0.0, 1.0),
                phase: 2.0,
            },
            AiryComponent {
                amplitude: 0.1,
                wavelength: 4.0,
                direction: Vector3::new(-0.3, 0.0, 1.0),
                phase: -1.0,
            },
        ])
        .unwrap()
    }

    #[test]
    fn round_trip_from_the_particle_to_the_elevation() {
        let (waves, water) = (sea(), Water::default());
        let mut worst: f64 = 0.0;
        for i in 0..200 {
            let rest = Point3::new(
                (i as f64 * 0.37).sin() * 40.0,
                0.0,
                (i as f64 * 0.71).cos() * 40.0,
            );
            let time = i as f64 * 0.13;
            let (position, eta) = waves.particle(&water, &rest, time).unwrap();
            let mut found = [0.0];
            waves
                .elevations(&water, &[position], time, &mut found)
                .unwrap();
            worst = worst.max((found[0] - eta).abs());
        }
        assert!(worst <= 1e-10, "{worst:e}");
    }

    #[test]
    fn crests_are_sharper_than_troughs() {
        // One component: the crest is narrower than the trough, the mean level is below zero
        // at fixed points (the Stokes-like asymmetry of a trochoid).
        let waves = GerstnerWaves::new(vec![AiryComponent {
            amplitude: 1.0,
            wavelength: 12.0,
            direction: Vector3::x(),
            phase: 0.0,
        }])
        .unwrap();
        let n = 1200;
        let points: Vec<_> = (0..n)
            .map(|i| Point3::new(12.0 * i as f64 / n as f64, 0.0, 0.0))
            .collect();
        let mut eta = vec![0.0; n];
        waves
            .elevations(&Water::default(), &points, 0.0, &mut eta)
            .unwrap();
        let above = eta.iter().filter(|e| **e > 0.0).count();
        assert!(above < n / 2, "{above} of {n} above the still level");
        let mean: f64 = eta.iter().sum::<f64>() / n as f64;
        // Mean level of a trochoid at fixed points: −k·a²/2.
        let k = 2.0 * core::f64::consts::PI / 12.0;
        assert!((mean + k / 2.0).abs() < 1e-3, "{mean}");
    }

    #[test]
    fn a_sea_that_would_fold_is_an_error() {
        let steep = AiryComponent {
            amplitude: 2.0,
            wavelength: 12.0,
            direction: Vector3::x(),
            phase: 0.0,
        };
        assert!(matches!(
            GerstnerWaves::new(vec![steep]),
            Err(Error::InvalidSurface { .. })
        ));
    }
}
