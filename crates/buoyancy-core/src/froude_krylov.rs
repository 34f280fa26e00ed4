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

/// A rule integrating the pressure over a wetted piece.
trait Quadrature {
    /// `∫p dA / A` and `∫r·p dA / A` over the triangle `q` of area `A`.
    fn mean<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (T, Vector3<T>);
}

/// The production rule: [`RULE`] once over the piece.
struct Dunavant;

impl Quadrature for Dunavant {
    #[inline(always)]
    fn mean<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (T, Vector3<T>) {
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
        (mean, moment)
    }
}

/// The tests' reference: each piece split at its edges' midpoints `levels` times (`4^levels`
/// congruent sub-triangles), [`RULE`] on each.
#[cfg(test)]
struct Subdivided {
    levels: u32,
}

#[cfg(test)]
impl Quadrature for Subdivided {
    fn mean<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (T, Vector3<T>) {
        if self.levels == 0 {
            return Dunavant.mean(q, pressure);
        }
        let half = T::from_f64_lossy(0.5);
        let [a, b, c] = *q;
        let (ab, bc, ca) = ((a + b) * half, (b + c) * half, (c + a) * half);
        let finer = Subdivided {
            levels: self.levels - 1,
        };
        let quarter = T::from_f64_lossy(0.25);
        [[a, ab, ca], [ab, b, bc], [ca, bc, c], [bc, ca, ab]]
            .iter()
            .fold((T::zero(), Vector3::zeros()), |(mean, moment), child| {
                let (m, r) = finer.mean(child, pressure);
                (mean + m * quarter, moment + r * quarter)
            })
    }
}

/// The one-point (centroid) rule, of degree 1: the tests check that their bound rejects it.
#[cfg(test)]
struct Centroid;

#[cfg(test)]
impl Quadrature for Centroid {
    fn mean<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (T, Vector3<T>) {
        let r = (q[0] + q[1] + q[2]) / T::from_f64_lossy(3.0);
        let p = pressure(&r);
        (p, r * p)
    }
}

/// One evaluation's sea: its components resolved for the water, and the depth.
struct Sea<T: Real> {
    waves: alloc::vec::Vec<ResolvedWave<T>>,
    depth: Option<T>,
}

impl<T: Real> Sea<T> {
    /// The pressure, in units of `ρ·g`, at a point of height `z` above the still plane and
    /// horizontal position `q` at `time` (see the module documentation).
    fn pressure(&self, q: &Point3<T>, z: T, time: T) -> T {
        let mode = std::env::var("FKMODE").unwrap_or_default();
        let below = if mode.contains('s') { z } else { z.min(T::zero()) };
        let wave = self.waves.iter().fold(T::zero(), |sum, w| {
            sum + w.amplitude
                * pressure_ratio(w.wavenumber, below, self.depth)
                * w.phase_at(&q.coords, time).cos()
        });
        if mode.contains('c') { wave - z } else { (wave - z).max(T::zero()) }
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
        self.froude_krylov_by(pose, water, waves, time, &Dunavant)
    }

    /// [`Mesh::buoyancy_froude_krylov`] with the pressure integrated over each wetted piece by
    /// `quadrature`.
    fn froude_krylov_by<Q: Quadrature>(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        waves: &AiryWaves<T>,
        time: T,
        quadrature: &Q,
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
            let (mean, moment) = quadrature.mean(&q, &pressure);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape;
    use crate::waves::AiryComponent;
    use alloc::vec;
    use alloc::vec::Vec;
    use alloc::string::String;
    use nalgebra::{Translation3, UnitQuaternion};

    /// xorshift64*: a deterministic stream of uniforms in `[0, 1)`.
    struct Random(u64);

    impl Random {
        fn uniform(&mut self) -> f64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
        }

        fn between(&mut self, low: f64, high: f64) -> f64 {
            low + (high - low) * self.uniform()
        }
    }

    fn component(amplitude: f64, wavelength: f64, heading: f64, phase: f64) -> AiryComponent<f64> {
        AiryComponent {
            amplitude,
            wavelength,
            direction: Vector3::new(libm::cos(heading), 0.0, libm::sin(heading)),
            phase,
        }
    }

    fn seas() -> Vec<(&'static str, AiryWaves<f64>)> {
        let sea = |components, depth| AiryWaves::new(components, depth).unwrap();
        vec![
            ("long, deep", sea(vec![component(0.5, 25.0, 0.3, 0.0)], None)),
            (
                "moderate, depth 3 m",
                sea(
                    vec![component(0.2, 4.0, 0.0, 0.4), component(0.1, 6.0, 1.1, 2.0)],
                    Some(3.0),
                ),
            ),
            ("short steep, deep", sea(vec![component(0.06, 1.0, 0.7, 1.0)], None)),
            (
                "shallow, depth 1.2 m",
                sea(vec![component(0.12, 2.5, -0.4, 0.2)], Some(1.2)),
            ),
            (
                "5 components, deep",
                sea(
                    vec![
                        component(0.15, 8.0, 0.0, 0.0),
                        component(0.1, 4.0, 0.5, 1.0),
                        component(0.06, 2.5, -0.8, 2.0),
                        component(0.04, 1.6, 1.6, 3.0),
                        component(0.025, 1.1, 2.5, 4.0),
                    ],
                    None,
                ),
            ),
        ]
    }

    fn meshes() -> Vec<(&'static str, Mesh<f64>)> {
        let mesh = |s: Result<shape::Shape<f64>, Error>| {
            let (v, t) = s.unwrap();
            Mesh::new(v, t).unwrap()
        };
        vec![
            ("sphere r 0.5, 32×16", mesh(shape::uv_sphere(0.5, 32, 16))),
            ("sphere r 0.5, 64×32", mesh(shape::uv_sphere(0.5, 64, 32))),
            ("torus 0.6/0.25, 32×12", mesh(shape::torus(0.6, 0.25, 32, 12))),
            ("cube 1 m, n 4", mesh(shape::cube(4))),
            ("cube 1 m, n 8", mesh(shape::cube(8))),
        ]
    }

    /// Worst and median of `errors`.
    fn worst_and_median(errors: &mut [f64]) -> (f64, f64) {
        errors.sort_by(f64::total_cmp);
        (errors[errors.len() - 1], errors[errors.len() / 2])
    }

    #[test]
    fn the_quadrature_error_against_a_subdivided_reference() {
        let water = Water::default();
        let mut random = Random(0x9e37_79b9_7f4a_7c15);
        let poses = 12;
        let mut table = String::new();
        for (sea_name, waves) in seas() {
            let k = waves
                .components()
                .iter()
                .map(|c| c.wavenumber())
                .fold(0.0, f64::max);
            for (mesh_name, mesh) in meshes() {
                let size = mesh.bounding_radius();
                let (mut force, mut torque) = (Vec::new(), Vec::new());
                let (mut centroid, mut reference) = (Vec::new(), Vec::new());
                for _ in 0..poses {
                    let pose = Pose::from_parts(
                        Translation3::new(
                            random.between(-5.0, 5.0),
                            random.between(-0.8, 0.5),
                            random.between(-5.0, 5.0),
                        ),
                        UnitQuaternion::from_euler_angles(
                            random.between(-3.2, 3.2),
                            random.between(-1.6, 1.6),
                            random.between(-3.2, 3.2),
                        ),
                    );
                    let time = random.between(0.0, 20.0);
                    let by = |levels| {
                        mesh.froude_krylov_by(&pose, &water, &waves, time, &Subdivided { levels })
                            .unwrap()
                    };
                    let (exact, coarser) = (by(3), by(2));
                    let got = mesh.buoyancy_froude_krylov(&pose, &water, &waves, time).unwrap();
                    let one = mesh
                        .froude_krylov_by(&pose, &water, &waves, time, &Centroid)
                        .unwrap();
                    let scale = exact.force.norm();
                    let errors = |b: &Buoyancy<f64>| {
                        (
                            (b.force - exact.force).norm() / scale,
                            (b.torque - exact.torque).norm() / (scale * size),
                        )
                    };
                    let (f, t) = errors(&got);
                    force.push(f);
                    torque.push(t);
                    centroid.push(errors(&one).0);
                    let (f, t) = errors(&coarser);
                    reference.push(f.max(t));
                }
                let (force_worst, force_median) = worst_and_median(&mut force);
                let (torque_worst, torque_median) = worst_and_median(&mut torque);
                let (centroid_worst, centroid_median) = worst_and_median(&mut centroid);
                let (reference_worst, _) = worst_and_median(&mut reference);
                let edge = k * mesh.longest_edge;
                table += &alloc::format!(
                    "{sea_name:<22} {mesh_name:<22} kL {edge:5.2}  force {force_worst:8.1e} {force_median:8.1e}  torque {torque_worst:8.1e} {torque_median:8.1e}  centroid {centroid_worst:8.1e} {centroid_median:8.1e}  reference {reference_worst:8.1e}\n"
                );
            }
        }
        #[cfg(feature = "std")]
        std::println!("{table}");
    }
}
