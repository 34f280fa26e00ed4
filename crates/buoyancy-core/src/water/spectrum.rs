//! Irregular seas from a wave spectrum: Pierson–Moskowitz and JONSWAP, as a sum of Airy
//! components drawn deterministically from a seed.

use nalgebra::{UnitQuaternion, Vector3};

use super::{AiryComponent, AiryWaves, horizontal_direction};
use crate::{Error, Real, Water};

/// The shape of a wave spectrum `S(ω)` (m²·s), given the significant height `H_s` and the peak
/// frequency `ω_p = 2π/T_p`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spectrum<T: Real> {
    /// A fully developed sea: `S(ω) = (5/16)·H_s²·ω_p⁴·ω⁻⁵·exp(−(5/4)·(ω_p/ω)⁴)`.
    PiersonMoskowitz,
    /// A fetch-limited sea: Pierson–Moskowitz times the peak enhancement
    /// `γ^exp(−(ω − ω_p)²/(2σ²ω_p²))`, `σ = 0.07` below the peak and `0.09` above. `γ ≥ 1`
    /// (3.3 is the North Sea mean; 1 is Pierson–Moskowitz).
    Jonswap {
        /// The peak enhancement factor `γ`.
        gamma: T,
    },
}

/// A sea state: a spectrum, its significant height and peak period, a mean direction, an
/// optional directional spreading, and how to discretise it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeaState<T: Real> {
    /// The spectrum's shape.
    pub spectrum: Spectrum<T>,
    /// `H_s`, the significant wave height, m: four times the standard deviation of `η`.
    pub significant_height: T,
    /// `T_p`, the peak period, s.
    pub peak_period: T,
    /// The mean direction the waves travel in, world frame (projected onto the still plane).
    pub direction: Vector3<T>,
    /// The exponent `s` of the `cos^{2s}((θ − θ₀)/2)` directional spreading, or `None` for
    /// long-crested waves, all along `direction`. Larger is narrower (swell about 25, wind sea
    /// about 2 to 10).
    pub spreading: Option<T>,
    /// The number of components.
    pub components: usize,
    /// The seed of the random frequencies within their bins, phases and directions: the same
    /// seed gives the same sea.
    pub seed: u64,
}

impl<T: Real> SeaState<T> {
    /// The spectral density `S(ω)` (m²·s) at the angular frequency `ω` (rad/s), before the
    /// discretisation's normalisation (see [`AiryWaves::from_sea_state`]).
    pub fn density(&self, omega: T) -> T {
        let f = T::from_f64_lossy;
        let peak = T::two_pi() / self.peak_period;
        if omega <= T::zero() {
            return T::zero();
        }
        let ratio = peak / omega;
        let pm = f(5.0 / 16.0) * self.significant_height * self.significant_height * ratio.powi(4)
            / omega
            * (-f(1.25) * ratio.powi(4)).exp();
        match self.spectrum {
            Spectrum::PiersonMoskowitz => pm,
            Spectrum::Jonswap { gamma } => {
                let sigma = if omega <= peak { f(0.07) } else { f(0.09) };
                let x = (omega - peak) / (sigma * peak);
                pm * gamma.powf((-x * x * f(0.5)).exp())
            }
        }
    }
}

/// SplitMix64: a small, fast, deterministic generator (no_std, no dependency).
struct SplitMix64(u64);

impl SplitMix64 {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

impl<T: Real> AiryWaves<T> {
    /// Airy components of the sea state `sea` in `water` of `depth` (m, `None` for deep water).
    ///
    /// The frequencies from `0.5·ω_p` to `4·ω_p` are cut into `sea.components` equal bins; each
    /// component takes a frequency drawn uniformly within its bin, the amplitude
    /// `√(2·S(ω)·Δω)`, a uniform random phase, the wavelength of its frequency by the dispersion
    /// relation, and, with spreading, a direction drawn from `cos^{2s}((θ − θ₀)/2)`. The
    /// amplitudes are then scaled so that the components' significant height
    /// `4·√(Σ aᵢ²/2)` is `H_s` exactly (the bins hold over 99 % of the spectrum's energy; the
    /// scaling also stands for JONSWAP's normalising factor).
    ///
    /// ```
    /// use buoyancy_core::water::{AiryWaves, SeaState, Spectrum};
    /// use buoyancy_core::Water;
    /// use nalgebra::Vector3;
    ///
    /// let sea = SeaState {
    ///     spectrum: Spectrum::Jonswap { gamma: 3.3 },
    ///     significant_height: 2.0,
    ///     peak_period: 8.0,
    ///     direction: Vector3::x(),
    ///     spreading: Some(10.0),
    ///     components: 64,
    ///     seed: 7,
    /// };
    /// let waves = AiryWaves::from_sea_state(&sea, &Water::default(), None)?;
    /// let m0: f64 = waves.components().iter().map(|c| c.amplitude * c.amplitude / 2.0).sum();
    /// assert!((4.0 * m0.sqrt() - 2.0).abs() < 1e-12);
    /// assert_eq!(waves, AiryWaves::from_sea_state(&sea, &Water::default(), None)?); // same seed
    /// # Ok::<(), buoyancy_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidSurface`] if `H_s` is negative or not finite, `T_p` not finite and
    /// positive, `γ` below 1, the spreading not finite and positive, no component is asked for,
    /// the direction is along the up normal, or the depth is not finite and positive.
    pub fn from_sea_state(
        sea: &SeaState<T>,
        water: &Water<T>,
        depth: Option<T>,
    ) -> Result<Self, Error> {
        let invalid = |parameter, reason| Err(Error::InvalidSurface { parameter, reason });
        if !(sea.significant_height.is_finite() && sea.significant_height >= T::zero()) {
            return invalid(
                "significant_height",
                "the significant height must be finite and non-negative (m)",
            );
        }
        if !(sea.peak_period.is_finite() && sea.peak_period > T::zero()) {
            return invalid(
                "peak_period",
                "the peak period must be finite and positive (s)",
            );
        }
        if let Spectrum::Jonswap { gamma } = sea.spectrum
            && !(gamma.is_finite() && gamma >= T::one())
        {
            return invalid(
                "gamma",
                "JONSWAP's peak enhancement γ must be finite and at least 1",
            );
        }
        if let Some(s) = sea.spreading
            && !(s.is_finite() && s > T::zero())
        {
            return invalid(
                "spreading",
                "the spreading exponent must be finite and positive",
            );
        }
        if sea.components == 0 {
            return invalid("components", "a sea state needs at least one component");
        }
        let mean = horizontal_direction(water, &sea.direction)?;
        if let Some(h) = depth
            && !(h.is_finite() && h > T::zero())
        {
            return invalid(
                "depth",
                "the depth must be finite and positive (m), or None for deep water",
            );
        }
        let up = water.normal();
        let f = T::from_f64_lossy;
        let peak = T::two_pi() / sea.peak_period;
        let (lo, hi) = (peak * f(0.5), peak * f(4.0));
        let bin = (hi - lo) / f(sea.components as f64);
        let mut random = SplitMix64(sea.seed);
        let mut components = crate::error::vec_with_capacity(sea.components, "components")?;
        for i in 0..sea.components {
            let omega = lo + bin * (f(i as f64) + f(random.unit()));
            let amplitude = (f(2.0) * sea.density(omega) * bin).sqrt();
            let phase = T::two_pi() * f(random.unit());
            let direction = match sea.spreading {
                None => mean,
                Some(s) => {
                    UnitQuaternion::from_axis_angle(
                        up,
                        spread_angle(s.to_f64(), &mut random).map(f)?,
                    ) * mean
                }
            };
            let k = wavenumber(omega, water.gravity(), depth);
            components.push(AiryComponent {
                amplitude,
                wavelength: T::two_pi() / k,
                direction,
                phase,
            });
        }
        let m0: T = components
            .iter()
            .fold(T::zero(), |m, c| m + c.amplitude * c.amplitude * f(0.5));
        if m0 > T::zero() {
            let scale = sea.significant_height / (f(4.0) * m0.sqrt());
            for c in &mut components {
                c.amplitude *= scale;
            }
        }
        AiryWaves::new(components, depth)
    }
}

/// An angle `θ − θ₀` (rad) drawn from `cos^{2s}((θ − θ₀)/2)` on `(−π, π]` by rejection.
fn spread_angle(s: f64, random: &mut SplitMix64) -> Result<f64, Error> {
    for _ in 0..100_000 {
        let theta = (random.unit() * 2.0 - 1.0) * core::f64::consts::PI;
        if random.unit() <= libm::pow(libm::cos(theta / 2.0), 2.0 * s) {
            return Ok(theta);
        }
    }
    Err(Error::InvalidSurface {
        parameter: "spreading",
        reason: "the spreading exponent is too large to sample; use None for long-crested waves",
    })
}

/// The wavenumber `k` (rad/m) of angular frequency `ω` under gravity `g` by the dispersion
/// relation `ω² = g·k·tanh(k·h)`: `ω²/g` in deep water, Newton's method otherwise.
pub(crate) fn wavenumber<T: Real>(omega: T, gravity: T, depth: Option<T>) -> T {
    let deep = omega * omega / gravity;
    let Some(h) = depth else {
        return deep;
    };
    // The residual g·k·tanh(k·h) − ω² is increasing and concave in k: from any start Newton's
    // first step lands at or below the root, and the iteration then rises to it monotonically.
    let shallow = omega / (gravity * h).sqrt();
    let mut k = deep.max(shallow);
    for _ in 0..50 {
        let t = (k * h).tanh();
        let residual = gravity * k * t - omega * omega;
        let slope = gravity * (t + k * h * (T::one() - t * t));
        let step = residual / slope;
        k -= step;
        if step.abs() <= T::default_epsilon() * k {
            break;
        }
    }
    k
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sea(spectrum: Spectrum<f64>, spreading: Option<f64>, seed: u64) -> SeaState<f64> {
        SeaState {
            spectrum,
            significant_height: 3.0,
            peak_period: 9.0,
            direction: Vector3::new(1.0, 0.0, 1.0),
            spreading,
            components: 128,
            seed,
        }
    }

    #[test]
    fn the_components_have_the_requested_significant_height() {
        for spectrum in [Spectrum::PiersonMoskowitz, Spectrum::Jonswap { gamma: 3.3 }] {
            let waves = AiryWaves::from_sea_state(
                &sea(spectrum, Some(4.0), 1),
                &Water::default(),
                Some(30.0),
            )
            .unwrap();
            let m0: f64 = waves
                .components()
                .iter()
                .map(|c| c.amplitude * c.amplitude / 2.0)
                .sum();
            assert!((4.0 * m0.sqrt() / 3.0 - 1.0).abs() < 0.01);
            // The normalisation is small: the bins hold nearly all of the spectrum's energy.
            let s = sea(spectrum, None, 1);
            let peak = 2.0 * core::f64::consts::PI / 9.0;
            let (n, lo, hi) = (20_000, 0.5 * peak, 4.0 * peak);
            let in_bins: f64 = (0..n)
                .map(|i| {
                    s.density(lo + (i as f64 + 0.5) * (hi - lo) / n as f64) * (hi - lo) / n as f64
                })
                .sum();
            let all: f64 = (0..200_000)
                .map(|i| {
                    s.density((i as f64 + 0.5) * 20.0 * peak / 200_000.0) * 20.0 * peak / 200_000.0
                })
                .sum();
            assert!(in_bins / all > 0.99, "{spectrum:?}: {}", in_bins / all);
            if spectrum == Spectrum::PiersonMoskowitz {
                // Pierson–Moskowitz integrates to H_s²/16 by itself.
                assert!((all / (9.0 / 16.0) - 1.0).abs() < 1e-3, "{all}");
            }
        }
    }

    #[test]
    fn the_same_seed_gives_the_same_sea_and_another_seed_another() {
        let s = sea(Spectrum::Jonswap { gamma: 2.0 }, Some(6.0), 42);
        let a = AiryWaves::from_sea_state(&s, &Water::default(), None).unwrap();
        assert_eq!(
            a,
            AiryWaves::from_sea_state(&s, &Water::default(), None).unwrap()
        );
        let other = SeaState { seed: 43, ..s };
        assert_ne!(
            a,
            AiryWaves::from_sea_state(&other, &Water::default(), None).unwrap()
        );
    }

    #[test]
    fn directions_spread_about_the_mean_in_the_still_plane() {
        let waves = AiryWaves::from_sea_state(
            &sea(Spectrum::PiersonMoskowitz, Some(2.0), 5),
            &Water::default(),
            None,
        )
        .unwrap();
        let mean = Vector3::new(1.0, 0.0, 1.0).normalize();
        let mut sum = Vector3::zeros();
        for c in waves.components() {
            assert!(c.direction.y.abs() < 1e-12 && (c.direction.norm() - 1.0).abs() < 1e-12);
            sum += c.direction;
        }
        assert!(sum.normalize().dot(&mean) > 0.95);
        assert!(
            waves
                .components()
                .iter()
                .any(|c| c.direction.dot(&mean) < 0.9)
        );
        let long_crested = AiryWaves::from_sea_state(
            &sea(Spectrum::PiersonMoskowitz, None, 5),
            &Water::default(),
            None,
        )
        .unwrap();
        assert!(
            long_crested
                .components()
                .iter()
                .all(|c| (c.direction - mean).norm() < 1e-12)
        );
    }

    #[test]
    fn the_dispersion_relation_is_solved() {
        for depth in [None, Some(0.5), Some(5.0), Some(500.0)] {
            for omega in [0.2, 1.0, 3.0] {
                let k = wavenumber(omega, 9.81, depth);
                let tanh = depth.map_or(1.0, |h: f64| (k * h).tanh());
                assert!(
                    (9.81 * k * tanh / (omega * omega) - 1.0).abs() < 1e-12,
                    "{depth:?} {omega}"
                );
            }
        }
    }

    #[test]
    fn invalid_sea_states_are_errors() {
        let water = Water::default();
        let good = sea(Spectrum::Jonswap { gamma: 3.3 }, None, 0);
        for bad in [
            SeaState {
                significant_height: -1.0,
                ..good
            },
            SeaState {
                peak_period: 0.0,
                ..good
            },
            SeaState {
                spectrum: Spectrum::Jonswap { gamma: 0.5 },
                ..good
            },
            SeaState {
                spreading: Some(f64::NAN),
                ..good
            },
            SeaState {
                components: 0,
                ..good
            },
            SeaState {
                direction: Vector3::y(),
                ..good
            },
        ] {
            assert!(
                matches!(
                    AiryWaves::from_sea_state(&bad, &water, None),
                    Err(Error::InvalidSurface { .. })
                ),
                "{bad:?}"
            );
        }
    }
}
