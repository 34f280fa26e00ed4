//! Linear (Airy) waves: a sum of sinusoidal components; the dispersion relation and the
//! resolution of wave components for a water, which Gerstner waves and sea states share.

use alloc::vec::Vec;

use nalgebra::{Point3, Vector3};

use super::WaterSurface;
use super::cosine::{self, CosineTerm};
use crate::{Error, Real, Water};

/// One linear wave component: `η = a·cos(k·q − ω·t + φ)`, with `k = 2π/λ` along `direction`
/// (projected onto the still plane) and `ω` from the dispersion relation (see [`AiryWaves`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AiryComponent<T: Real> {
    /// `a`, the amplitude (half the height from trough to crest), m, finite and non-negative.
    pub amplitude: T,
    /// `λ`, the wavelength, m, finite and positive.
    pub wavelength: T,
    /// The direction the wave travels in, world frame; its component along the water's up
    /// normal is ignored. Finite, not along the normal.
    pub direction: Vector3<T>,
    /// `φ`, the phase at the world origin at `t = 0`, rad.
    pub phase: T,
}

impl<T: Real> AiryComponent<T> {
    /// The wave number `k = 2π/λ`, rad/m.
    pub fn wavenumber(&self) -> T {
        T::two_pi() / self.wavelength
    }
}

/// Linear (Airy) waves: the sum of [`AiryComponent`]s over water of a finite depth `h` or
/// infinitely deep, `η(q, t) = Σ aᵢ·cos(kᵢ·q − ωᵢ·t + φᵢ)`, where the angular frequency of each
/// component follows the dispersion relation `ω² = g·k·tanh(k·h)` (`ω² = g·k` in deep water).
///
/// ```
/// use buoyancy_core::water::{AiryComponent, AiryWaves, WaterSurface};
/// use buoyancy_core::Water;
/// use nalgebra::{Point3, Vector3};
///
/// let swell = AiryWaves::new(
///     vec![AiryComponent { amplitude: 0.5, wavelength: 20.0, direction: Vector3::x(), phase: 0.0 }],
///     None, // deep water
/// )?;
/// let water = Water::default(); // y up
/// let mut eta = [0.0f64; 2];
/// swell.elevations(&water, &[Point3::origin(), Point3::new(5.0, 0.0, 0.0)], 0.0, &mut eta)?;
/// assert!((eta[0] - 0.5).abs() < 1e-12 && eta[1].abs() < 1e-12); // a crest, a quarter wave on
/// // Deep water: ω = √(g·k), a period of about 3.58 s for 20 m.
/// let period = 2.0 * std::f64::consts::PI / swell.angular_frequency(0, water.gravity());
/// assert!((period - 3.579).abs() < 1e-3);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct AiryWaves<T: Real> {
    components: Vec<AiryComponent<T>>,
    depth: Option<T>,
}

/// The steepness `H/λ` above which a wave breaks in deep water (Michell's limit, 1/7): see
/// [`AiryWaves::steepest`].
pub const BREAKING_STEEPNESS: f64 = 1.0 / 7.0;

impl<T: Real> AiryWaves<T> {
    /// Waves of `components` over water of `depth` (m, from the still level to the bottom), or
    /// infinitely deep for `None`.
    ///
    /// Waves steeper than [`BREAKING_STEEPNESS`] are accepted (linear theory does not stop
    /// there, the sea does): [`steepest`](Self::steepest) finds them, and the Python bindings
    /// warn.
    ///
    /// # Errors
    /// [`Error::InvalidSurface`] naming what is wrong: a negative or non-finite amplitude, a
    /// wavelength that is not finite and positive, a non-finite direction or phase, a depth
    /// that is not finite and positive, or one no deeper than the deepest trough the waves can
    /// reach, the sum of their amplitudes (the seabed would stand in the trough).
    pub fn new(components: Vec<AiryComponent<T>>, depth: Option<T>) -> Result<Self, Error> {
        for c in &components {
            if !(c.amplitude.is_finite() && c.amplitude >= T::zero()) {
                return Err(Error::InvalidSurface {
                    parameter: "amplitude",
                    reason: "a wave amplitude must be finite and non-negative (m)",
                });
            }
            if !(c.wavelength.is_finite() && c.wavelength > T::zero()) {
                return Err(Error::InvalidSurface {
                    parameter: "wavelength",
                    reason: "a wavelength must be finite and positive (m)",
                });
            }
            for (finite, parameter) in [
                (c.direction.iter().all(|x| x.is_finite()), "direction"),
                (c.phase.is_finite(), "phase"),
            ] {
                if !finite {
                    return Err(Error::InvalidSurface {
                        parameter,
                        reason: "a wave direction and phase must be finite",
                    });
                }
            }
        }
        if let Some(h) = depth
            && !(h.is_finite() && h > T::zero())
        {
            return Err(Error::InvalidSurface {
                parameter: "depth",
                reason: "the depth must be finite and positive (m), or None for deep water",
            });
        }
        let deepest_trough = components
            .iter()
            .fold(T::zero(), |sum, c| sum + c.amplitude);
        if let Some(h) = depth
            && h <= deepest_trough
        {
            return Err(Error::InvalidSurface {
                parameter: "depth",
                reason: "the depth must be greater than the deepest trough the waves reach (the \
                         sum of their amplitudes): the seabed would stand in the trough",
            });
        }
        Ok(AiryWaves { components, depth })
    }

    /// The steepest component and its steepness `H/λ = 2a/λ`, if there is a component. Above
    /// [`BREAKING_STEEPNESS`] a real wave has broken: linear theory's surface and pressure are
    /// then a choice of look, not of physics.
    pub fn steepest(&self) -> Option<(usize, T)> {
        self.components
            .iter()
            .map(|c| (c.amplitude + c.amplitude) / c.wavelength)
            .enumerate()
            .fold(None, |best, (k, s)| match best {
                Some((_, b)) if b >= s => best,
                _ => Some((k, s)),
            })
    }

    /// The shortest wavelength of the components, m, if there is a component. A mesh whose
    /// edges are longer than half of it samples that wave too coarsely at its vertices to see
    /// it (the surface is evaluated at the vertices and taken as linear between them).
    pub fn shortest_wavelength(&self) -> Option<T> {
        self.components
            .iter()
            .map(|c| c.wavelength)
            .fold(None, |best, w| Some(best.map_or(w, |b: T| b.min(w))))
    }

    /// The components.
    pub fn components(&self) -> &[AiryComponent<T>] {
        &self.components
    }

    /// The depth of the water, m; `None` for deep water.
    pub fn depth(&self) -> Option<T> {
        self.depth
    }

    /// The angular frequency `ω` of component `index` under gravity `g` (m/s²), rad/s, from
    /// `ω² = g·k·tanh(k·h)` (`g·k` in deep water).
    pub fn angular_frequency(&self, index: usize, gravity: T) -> T {
        angular_frequency(self.components[index].wavenumber(), gravity, self.depth)
    }
}

/// The water's motion at a point under linear waves: its velocity and its local acceleration
/// (`∂u/∂t` at the fixed point), world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaterMotion<T: Real> {
    /// Velocity, m/s.
    pub velocity: Vector3<T>,
    /// Local acceleration `∂u/∂t`, m/s².
    pub acceleration: Vector3<T>,
}

impl<T: Real> AiryWaves<T> {
    /// The orbital velocity and local acceleration of the water at the world point `point` at
    /// `time`, by linear theory: with `z` the height above the still plane, `θ = k·q − ω·t + φ`
    /// and `d` the component's direction,
    ///
    /// ```text
    /// u = Σ a·ω·C(z)·cos θ·d + a·ω·S(z)·sin θ·n,   ∂u/∂t = Σ a·ω²·C(z)·sin θ·d − a·ω²·S(z)·cos θ·n,
    /// C(z) = cosh k(z+h)/sinh kh,   S(z) = sinh k(z+h)/sinh kh   (both e^{kz} in deep water).
    /// ```
    ///
    /// Above the still plane (in a crest) the values at the still plane are used (no
    /// stretching); below the bottom, those at the bottom.
    ///
    /// ```
    /// use buoyancy_core::water::{AiryComponent, AiryWaves};
    /// use buoyancy_core::Water;
    /// use nalgebra::{Point3, Vector3};
    ///
    /// let swell = AiryWaves::<f64>::new(
    ///     vec![AiryComponent { amplitude: 0.5, wavelength: 20.0, direction: Vector3::x(), phase: 0.0 }],
    ///     None,
    /// )?;
    /// let water = Water::default();
    /// // Under the crest the water moves with the wave at a·ω, less with depth: e^{kz}.
    /// let omega = swell.angular_frequency(0, water.gravity());
    /// let k = swell.components()[0].wavenumber();
    /// let motion = swell.water_motion(&water, &Point3::new(0.0, -2.0, 0.0), 0.0)?;
    /// assert!((motion.velocity.x - 0.5 * omega * (-2.0 * k).exp()).abs() < 1e-12);
    /// # Ok::<(), buoyancy_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidSurface`] if a direction is along the water's up normal.
    pub fn water_motion(
        &self,
        water: &Water<T>,
        point: &Point3<T>,
        time: T,
    ) -> Result<WaterMotion<T>, Error> {
        let n = water.normal().into_inner();
        let height = water.height(point).min(T::zero());
        let q = water.project(point);
        let mut motion = WaterMotion {
            velocity: Vector3::zeros(),
            acceleration: Vector3::zeros(),
        };
        for w in resolve(&self.components, water, self.depth)? {
            let (cosh_ratio, sinh_ratio) = depth_ratios(w.wavenumber, height, self.depth);
            let (sin, cos) = w.phase_at(&q.coords, time).sin_cos();
            let speed = w.amplitude * w.omega;
            motion.velocity +=
                w.direction * (speed * cosh_ratio * cos) + n * (speed * sinh_ratio * sin);
            motion.acceleration += w.direction * (speed * w.omega * cosh_ratio * sin)
                - n * (speed * w.omega * sinh_ratio * cos);
        }
        Ok(motion)
    }
}

/// The unit vector along `direction` within the still plane of `water` (its component along
/// the normal removed).
///
/// # Errors
/// [`Error::InvalidSurface`] if `direction` is not finite or is (nearly) along the normal.
pub(crate) fn horizontal_direction<T: Real>(
    water: &Water<T>,
    direction: &Vector3<T>,
) -> Result<Vector3<T>, Error> {
    let n = water.normal();
    let horizontal = direction - n.into_inner() * n.dot(direction);
    let norm = horizontal.norm();
    if !(norm.is_finite() && norm > T::default_epsilon().sqrt() * direction.norm()) {
        return Err(Error::InvalidSurface {
            parameter: "direction",
            reason: "a wave direction must be finite and not along the water's up normal",
        });
    }
    Ok(horizontal / norm)
}

/// A wave component resolved for one water: its unit direction in the still plane, its wave
/// vector and its angular frequency by the dispersion relation.
pub(crate) struct ResolvedWave<T: Real> {
    pub direction: Vector3<T>,
    /// `k·direction`.
    pub k: Vector3<T>,
    /// `k = 2π/λ`.
    pub wavenumber: T,
    pub omega: T,
    pub amplitude: T,
    pub phase: T,
}

impl<T: Real> ResolvedWave<T> {
    /// `θ = k·p − ω·t + φ` at the horizontal position (or particle rest position) `p`.
    #[inline(always)]
    pub fn phase_at(&self, p: &Vector3<T>, time: T) -> T {
        self.k.dot(p) - self.omega * time + self.phase
    }
}

/// `components` resolved for `water` over water of `depth` (`None`: deep).
///
/// # Errors
/// [`Error::InvalidSurface`] if a direction is along the water's up normal.
pub(crate) fn resolve<T: Real>(
    components: &[AiryComponent<T>],
    water: &Water<T>,
    depth: Option<T>,
) -> Result<Vec<ResolvedWave<T>>, Error> {
    components
        .iter()
        .map(|c| {
            let direction = horizontal_direction(water, &c.direction)?;
            let wavenumber = c.wavenumber();
            Ok(ResolvedWave {
                direction,
                k: direction * wavenumber,
                wavenumber,
                omega: angular_frequency(wavenumber, water.gravity(), depth),
                amplitude: c.amplitude,
                phase: c.phase,
            })
        })
        .collect()
}

/// The dispersion relation: `ω = √(g·k·tanh(k·h))`, `√(g·k)` in deep water (`depth` `None`).
pub(crate) fn angular_frequency<T: Real>(wavenumber: T, gravity: T, depth: Option<T>) -> T {
    let depth_factor = match depth {
        Some(h) => (wavenumber * h).tanh(),
        None => T::one(),
    };
    (gravity * wavenumber * depth_factor).sqrt()
}

/// `Σ aᵢ`: a bound on `|η|` for a sum of components.
pub(crate) fn amplitude_sum<T: Real>(components: &[AiryComponent<T>]) -> T {
    components.iter().fold(T::zero(), |s, c| s + c.amplitude)
}

/// The least and the greatest of `cos` over `[theta − spread, theta + spread]` (`spread ≥ 0`):
/// `1` where the interval holds a multiple of `2π`, `−1` where it holds an odd multiple of `π`,
/// else the larger or smaller of the ends.
fn cos_range<T: Real>(theta: T, spread: T) -> (T, T) {
    let one = T::one();
    let pi = T::pi();
    // A NaN spread reaches everything too.
    if spread.partial_cmp(&pi) != Some(core::cmp::Ordering::Less) {
        return (-one, one);
    }
    let two_pi = pi + pi;
    let (a, b) = (theta - spread, theta + spread);
    let (ca, cb) = (a.cos(), b.cos());
    let holds = |shift: T| two_pi * ((a - shift) / two_pi).ceil() + shift <= b;
    let high = if holds(T::zero()) { one } else { ca.max(cb) };
    let low = if holds(pi) { -one } else { ca.min(cb) };
    (low, high)
}

/// `cosh k(z+h)/cosh kh`, the decay with depth of linear waves' dynamic pressure, at height
/// `z ≤ 0` (clamped to the bottom `−h`): `(e^{kz} + e^{−k(z+2h)})/(1 + e^{−2kh})`; `e^{kz}` in
/// deep water.
pub(crate) fn pressure_ratio<T: Real>(k: T, z: T, depth: Option<T>) -> T {
    match depth {
        None => (k * z).exp(),
        Some(h) => {
            let z = z.max(-h);
            let two = T::from_f64_lossy(2.0);
            ((k * z).exp() + (-k * (z + two * h)).exp()) / (T::one() + (-two * k * h).exp())
        }
    }
}

/// `cosh k(z+h)/sinh kh` and `sinh k(z+h)/sinh kh` at height `z ≤ 0` (clamped to the bottom
/// `−h`), written with decaying exponentials so that neither overflows for deep water:
/// `(e^{kz} ± e^{−k(z+2h)})/(1 − e^{−2kh})`; `e^{kz}` for both in deep water.
fn depth_ratios<T: Real>(k: T, z: T, depth: Option<T>) -> (T, T) {
    match depth {
        None => {
            let e = (k * z).exp();
            (e, e)
        }
        Some(h) => {
            let z = z.max(-h);
            let two = T::from_f64_lossy(2.0);
            let up = (k * z).exp();
            let down = (-k * (z + two * h)).exp();
            let denominator = T::one() - (-two * k * h).exp();
            ((up + down) / denominator, (up - down) / denominator)
        }
    }
}

impl<T: Real> WaterSurface<T> for AiryWaves<T> {
    /// These waves.
    fn as_airy_waves(&self) -> Option<&AiryWaves<T>> {
        Some(self)
    }

    fn elevations(
        &self,
        water: &Water<T>,
        points: &[Point3<T>],
        time: T,
        elevations: &mut [T],
    ) -> Result<(), Error> {
        // The positions apart, each axis contiguous, and the sum in f64, so that the loop over
        // the points vectorises (see `cosine`); a block of points at a time, on the stack, each
        // term's range checked against the block's extent.
        let mut terms = resolve(&self.components, water, self.depth)?
            .into_iter()
            .map(|w| {
                // The phase `k·q − ωt + φ`.
                let k = w.k.map(T::to_f64);
                CosineTerm {
                    k: [k.x, k.y, k.z],
                    offset: (w.phase - w.omega * time).to_f64(),
                    amplitude: w.amplitude.to_f64(),
                    in_range: false,
                }
            })
            .collect::<Vec<_>>();
        let mut block = [[0.0_f64; cosine::BLOCK]; 4];
        for (points, elevations) in points
            .chunks(cosine::BLOCK)
            .zip(elevations.chunks_mut(cosine::BLOCK))
        {
            let n = points.len().min(elevations.len());
            let [x, y, z, sum] = &mut block;
            let mut extent = [0.0_f64; 3];
            for (i, q) in points[..n].iter().enumerate() {
                (x[i], y[i], z[i]) = (q.x.to_f64(), q.y.to_f64(), q.z.to_f64());
                extent[0] = extent[0].max(x[i].abs());
                extent[1] = extent[1].max(y[i].abs());
                extent[2] = extent[2].max(z[i].abs());
            }
            for t in &mut terms {
                let [kx, ky, kz] = t.k;
                let bound = kx.abs() * extent[0] + ky.abs() * extent[1] + kz.abs() * extent[2];
                t.in_range = cosine::in_range(bound + t.offset.abs());
            }
            let sum = &mut sum[..n];
            sum.fill(0.0);
            cosine::add_cosines(sum, &x[..n], &y[..n], &z[..n], &terms);
            for (eta, s) in elevations.iter_mut().zip(sum.iter()) {
                *eta = T::from_f64_lossy(*s);
            }
        }
        Ok(())
    }

    /// `Σ aᵢ`.
    fn elevation_bound(&self) -> Option<T> {
        Some(amplitude_sum(&self.components))
    }

    /// Per component, `a·cos θ` over the phases the disc spans, `θ(center) ± k·radius`, at
    /// its extremes (`±a` where a crest or a trough is within reach); summed, and widened by the
    /// round-off of the phases at the points, `64ε·(1 + |θ| + k·radius)` per unit amplitude.
    fn elevation_range(
        &self,
        water: &Water<T>,
        center: &Point3<T>,
        radius: T,
        time: T,
    ) -> Option<(T, T)> {
        let Ok(waves) = resolve(&self.components, water, self.depth) else {
            let bound = amplitude_sum(&self.components);
            return Some((-bound, bound));
        };
        let q = water.project(center).coords;
        let (mut low, mut high, mut slack) = (T::zero(), T::zero(), T::zero());
        for w in &waves {
            let theta = w.phase_at(&q, time);
            let spread = w.wavenumber * radius.abs();
            let (lo, hi) = cos_range(theta, spread);
            low += w.amplitude * lo;
            high += w.amplitude * hi;
            slack += w.amplitude * (T::one() + theta.abs() + spread);
        }
        let slack = slack * T::default_epsilon() * T::from_f64_lossy(64.0);
        let range = (low - slack, high + slack);
        (range.0.is_finite() && range.1.is_finite()).then_some(range)
    }

    /// The orbital velocity of [`AiryWaves::water_motion`].
    fn water_velocity(&self, water: &Water<T>, point: &Point3<T>, time: T) -> Option<Vector3<T>> {
        self.water_motion(water, point, time)
            .ok()
            .map(|motion| motion.velocity)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    fn wave(wavelength: f64) -> AiryComponent<f64> {
        AiryComponent {
            amplitude: 1.0,
            wavelength,
            direction: Vector3::x(),
            phase: 0.0,
        }
    }

    #[test]
    fn the_steepest_and_the_shortest_component() {
        let mut steep = wave(5.0);
        steep.amplitude = 0.5;
        let waves = AiryWaves::new(vec![wave(20.0), steep, wave(8.0)], None).unwrap();
        assert_eq!(waves.steepest(), Some((2, 0.25)));
        assert_eq!(waves.shortest_wavelength(), Some(5.0));
        let none = AiryWaves::<f64>::new(vec![], None).unwrap();
        assert_eq!((none.steepest(), none.shortest_wavelength()), (None, None));
    }

    #[test]
    fn dispersion_tends_to_deep_and_shallow_water_limits() {
        let g = 9.81;
        let deep = AiryWaves::new(vec![wave(10.0)], Some(1000.0)).unwrap();
        let k = wave(10.0).wavenumber();
        assert!((deep.angular_frequency(0, g) - (g * k).sqrt()).abs() < 1e-12);
        // Shallow water: ω ≈ k·√(g·h), within (k·h)²/6 relative (the 1 m wave over 1.5 m).
        let shallow = AiryWaves::new(vec![wave(1000.0)], Some(1.0)).err();
        assert!(
            matches!(
                shallow,
                Some(Error::InvalidSurface {
                    parameter: "depth",
                    ..
                })
            ),
            "a seabed in the trough: {shallow:?}"
        );
        let shallow = AiryWaves::new(vec![wave(1000.0)], Some(1.5)).unwrap();
        let k = wave(1000.0).wavenumber();
        let relative = shallow.angular_frequency(0, g) / (k * (g * 1.5f64).sqrt()) - 1.0;
        assert!(relative.abs() < (k * 1.5).powi(2) / 6.0, "{relative}");
    }

    #[test]
    fn the_wave_travels_at_its_phase_speed() {
        let water = Water::default();
        let waves = AiryWaves::new(vec![wave(30.0)], None).unwrap();
        let c = waves.angular_frequency(0, 9.81) / wave(30.0).wavenumber();
        let (mut now, mut later) = ([0.0], [0.0]);
        waves
            .elevations(&water, &[Point3::new(3.0, 0.0, 7.0)], 0.0, &mut now)
            .unwrap();
        let moved = Point3::new(3.0 + 2.0 * c, 0.0, 7.0);
        waves.elevations(&water, &[moved], 2.0, &mut later).unwrap();
        assert!((now[0] - later[0]).abs() < 1e-12);
    }

    #[test]
    fn invalid_components_are_named() {
        for bad in [
            AiryComponent {
                amplitude: -1.0,
                ..wave(1.0)
            },
            AiryComponent {
                wavelength: 0.0,
                ..wave(1.0)
            },
            AiryComponent {
                phase: f64::NAN,
                ..wave(1.0)
            },
        ] {
            assert!(matches!(
                AiryWaves::new(vec![bad], None),
                Err(Error::InvalidSurface { .. })
            ));
        }
        assert!(AiryWaves::new(vec![wave(1.0)], Some(-2.0)).is_err());
        // A direction along the up normal has no horizontal part.
        let vertical = AiryWaves::new(
            vec![AiryComponent {
                direction: Vector3::y(),
                ..wave(1.0)
            }],
            None,
        )
        .unwrap();
        let mut eta = [0.0];
        assert!(
            vertical
                .elevations(&Water::default(), &[Point3::origin()], 0.0, &mut eta)
                .is_err()
        );
    }

    /// Linear theory's kinematics: incompressible (`∇·u = 0`), the surface moves with the water
    /// (`w = ∂η/∂t` at the still plane), the acceleration is `∂u/∂t`, the velocity decays as
    /// `e^{kz}` in deep water; checked by finite differences.
    #[test]
    fn orbital_motion_is_linear_theory() {
        let water = Water::default();
        for depth in [None, Some(6.0)] {
            let waves = AiryWaves::new(
                vec![
                    AiryComponent {
                        amplitude: 0.3,
                        wavelength: 9.0,
                        direction: Vector3::x(),
                        phase: 0.4,
                    },
                    AiryComponent {
                        amplitude: 0.2,
                        wavelength: 5.0,
                        direction: Vector3::new(0.6, 0.0, 0.8),
                        phase: 1.9,
                    },
                ],
                depth,
            )
            .unwrap();
            let motion = |p: Point3<f64>, t: f64| waves.water_motion(&water, &p, t).unwrap();
            let (p, t, d) = (Point3::new(1.3, -1.1, 0.7), 2.2, 1e-5);
            let divergence = (0..3)
                .map(|axis| {
                    let mut e = Vector3::zeros();
                    e[axis] = d;
                    (motion(p + e, t).velocity[axis] - motion(p - e, t).velocity[axis]) / (2.0 * d)
                })
                .sum::<f64>();
            assert!(divergence.abs() < 1e-7, "{depth:?}: {divergence}");
            let dudt = (motion(p, t + d).velocity - motion(p, t - d).velocity) / (2.0 * d);
            assert!(
                (dudt - motion(p, t).acceleration).norm() < 1e-7,
                "{depth:?}"
            );
            let surface = Point3::new(1.3, 0.0, 0.7);
            let eta = |t: f64| {
                let mut e = [0.0];
                waves.elevations(&water, &[surface], t, &mut e).unwrap();
                e[0]
            };
            let detadt = (eta(t + d) - eta(t - d)) / (2.0 * d);
            assert!(
                (motion(surface, t).velocity.y - detadt).abs() < 1e-7,
                "{depth:?}"
            );
            // Above the still plane: the values at the still plane.
            assert_eq!(motion(Point3::new(1.3, 0.2, 0.7), t), motion(surface, t));
        }
        let deep = AiryWaves::new(vec![wave(10.0)], None).unwrap();
        let k = wave(10.0).wavenumber();
        let at = |y: f64| {
            deep.water_motion(&water, &Point3::new(0.3, y, 0.0), 1.0)
                .unwrap()
                .velocity
                .norm()
        };
        assert!((at(-3.0) / at(0.0) - (-3.0 * k).exp()).abs() < 1e-12);
    }

    /// The range over a disc holds every elevation sampled in it, and for long waves is much
    /// thinner than the amplitude sum; its ends are reached (within the sampling) for one
    /// component.
    #[test]
    fn elevation_range_holds_the_disc() {
        let water = Water::<f64>::default();
        let sea = AiryWaves::new(
            (0..6)
                .map(|i| AiryComponent {
                    amplitude: 0.1 + 0.05 * i as f64,
                    wavelength: 2.0 + 7.0 * i as f64,
                    direction: Vector3::new((i as f64).cos(), 0.0, (i as f64).sin()),
                    phase: 0.3 * i as f64,
                })
                .collect(),
            None,
        )
        .unwrap();
        let one = AiryWaves::new(vec![wave(10.0)], Some(8.0)).unwrap();
        let sum = amplitude_sum(sea.components());
        for (k, radius) in [0.0, 0.05, 0.4, 1.5, 6.0].into_iter().enumerate() {
            for surface in [&sea, &one] {
                let center = Point3::new(3.0 * k as f64 - 5.0, -0.7, 1.1 * k as f64);
                let time = 0.9 * k as f64;
                let (low, high) = surface
                    .elevation_range(&water, &center, radius, time)
                    .unwrap();
                let points: Vec<Point3<f64>> = (0..2000)
                    .map(|j| {
                        let (r, a) = (radius * ((j % 40) as f64 / 39.0), j as f64 * 0.61);
                        Point3::new(center.x + r * a.cos(), 0.0, center.z + r * a.sin())
                    })
                    .collect();
                let mut eta = vec![0.0; points.len()];
                surface.elevations(&water, &points, time, &mut eta).unwrap();
                let (lo, hi) = eta
                    .iter()
                    .fold((f64::MAX, f64::MIN), |(l, h), e| (l.min(*e), h.max(*e)));
                assert!(low <= lo && hi <= high, "{radius}: {low} {lo} {hi} {high}");
                if core::ptr::eq(surface, &one) {
                    // One component: the ends are the extremes over the disc.
                    assert!(
                        lo - low < 2e-3 && high - hi < 2e-3,
                        "{low} {lo} {hi} {high}"
                    );
                }
            }
        }
        // Waves long against the disc: a thin layer.
        let (low, high) = sea
            .elevation_range(&water, &Point3::origin(), 0.05, 0.0)
            .unwrap();
        assert!(high - low < 0.25 * sum, "{low} {high} {sum}");
    }
}
