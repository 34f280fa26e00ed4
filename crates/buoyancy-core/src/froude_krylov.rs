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
//! integrated over each wetted piece by the degree-5, 7-point rule of Dunavant, exact for
//! polynomials of degree 5 over a piece.
//!
//! # Quadrature error
//! Measured against a reference that integrates the same wetted pieces with the same pressure
//! on `4³ = 64` congruent sub-triangles each (the same rule on each), so that the two differ
//! only by quadrature; the cut (the waterline interpolated between vertices) and the faceting
//! are not part of this error. Over 240 random poses (the body cut by the surface or submerged,
//! holding at least 5 % of its volume's weight) of a UV sphere (radius 0.5 m, 32×16), a torus
//! (0.6/0.25 m, 32×12) and a unit cube (`n = 4`) in five Airy seas (a long swell, `a` 0.5 m,
//! `λ` 25 m; a moderate sea over 3 m of water, 0.2 m at 4 m and 0.1 m at 6 m; a short steep
//! wave, 0.06 m at 1 m, `k·a` 0.38; a shallow sea, 0.12 m at 2.5 m over 1.2 m of water; five
//! components from 0.15 m at 8 m to 0.025 m at 1.1 m in deep water, spread in direction), the
//! error in force relative to `|F|` and in torque relative to `|F|·R` (`R` the mesh's bounding
//! radius) are:
//!
//! ```text
//! sea                    k·L          force: worst  median     torque: worst  median
//! long, deep             0.03–0.09    1.2e-5        ≤ 1.7e-6   1.5e-5         ≤ 1.2e-7
//! moderate, depth 3 m    0.22–0.56    1.1e-4        ≤ 3.7e-6   4.5e-5         ≤ 2.8e-6
//! short steep, deep      0.87–2.22    5.8e-5        ≤ 1.6e-5   1.3e-5         ≤ 6.3e-6
//! shallow, depth 1.2 m   0.35–0.89    1.2e-4        ≤ 1.5e-5   4.2e-5         ≤ 7.0e-6
//! 5 components, deep     0.79–2.02    8.5e-5        ≤ 2.4e-5   3.3e-5         ≤ 1.5e-5
//! ```
//!
//! (`k` the largest wavenumber, `L` the mesh's longest edge; the medians are the largest of the
//! three meshes'.) The test asserts a relative error in force below **1e-3** and in torque below
//! **3e-4** `·|F|·R` over these poses; the one-point (centroid) rule fails both (3.6e-3 and
//! 7.6e-3), and the reference moves by less than 6e-6 from 16 to 64 sub-triangles a piece
//! (its own error is smaller still). The per-mesh table is printed by
//!
//! ```text
//! cargo test -p buoyancy-core --lib froude_krylov -- --nocapture
//! ```
//!
//! What the error depends on:
//! * Where the pressure is smooth over a piece (a piece wholly below or wholly above the still
//!   plane) the rule's error is of order `(k·L)⁶` relative to the wave part, `L` the size of the
//!   piece: measured once with `P` made smooth across the still plane (`e^{kz}` above it too),
//!   1e-9 to 2e-7 on these meshes, falling by about 2⁷ when `L` halves.
//! * The figures above are dominated by the still plane: the wave part's vertical derivative
//!   jumps there, from `a·P′(0)·cos θ` (`k·a·cos θ` in deep water) below to zero above (the
//!   crest's hydrostatic extrapolation), so on a piece that straddles the still plane under a
//!   crest the pressure is only continuous, and the rule's error on it is of order `k·a·L` times
//!   its area instead of `(k·L)⁶`. Summed over the pieces along the waterline, the error grows
//!   with the slope `k·a` and is of second order in `L`: halving `L` (sphere 32×16 → 64×32 →
//!   128×64, cube `n` 4 → 8 → 16, the same 24 poses per sea) divided the RMS error by 3 to 13,
//!   about 5 on average. This is why a long swell (`k·L` 0.03) still shows 1e-5 at worst, while
//!   its poses where no wetted piece reaches the still plane are at round-off.
//! * Clipping the pressure at zero contributes nothing measurable: removing the clip left every
//!   figure unchanged.

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
    use alloc::string::String;
    use alloc::vec;
    use alloc::vec::Vec;
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
            (
                "long, deep",
                sea(vec![component(0.5, 25.0, 0.3, 0.0)], None),
            ),
            (
                "moderate, depth 3 m",
                sea(
                    vec![component(0.2, 4.0, 0.0, 0.4), component(0.1, 6.0, 1.1, 2.0)],
                    Some(3.0),
                ),
            ),
            (
                "short steep, deep",
                sea(vec![component(0.06, 1.0, 0.7, 1.0)], None),
            ),
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
            (
                "torus 0.6/0.25, 32×12",
                mesh(shape::torus(0.6, 0.25, 32, 12)),
            ),
            ("cube 1 m, n 4", mesh(shape::cube(4))),
        ]
    }

    /// Worst and median of `errors`.
    fn worst_and_median(errors: &mut [f64]) -> (f64, f64) {
        errors.sort_by(f64::total_cmp);
        (errors[errors.len() - 1], errors[errors.len() / 2])
    }

    /// The bound on the relative error in force stated in the module documentation.
    const FORCE_BOUND: f64 = 1e-3;
    /// The bound on the error in torque relative to `|F|·R` stated in the module documentation.
    const TORQUE_BOUND: f64 = 3e-4;

    /// The production rule against the same pieces and pressure integrated on `4³ = 64`
    /// sub-triangles each; prints the table of the module documentation.
    #[test]
    fn the_quadrature_error_against_a_subdivided_reference() {
        let water = Water::default();
        let mut random = Random(0x9e37_79b9_7f4a_7c15);
        let poses = 16;
        let (mut worst_force, mut worst_torque) = (0.0f64, 0.0f64);
        let (mut worst_centroid, mut worst_reference) = ((0.0f64, 0.0f64), 0.0f64);
        let mut table = String::from(concat!(
            "sea                   mesh                     kL   force: worst  median",
            "  torque: worst  median  centroid: force  torque  reference\n",
        ));
        for (sea_name, waves) in seas() {
            let k = waves
                .components()
                .iter()
                .map(|c| c.wavenumber())
                .fold(0.0, f64::max);
            for (mesh_name, mesh) in meshes() {
                let size = mesh.bounding_radius();
                let wet = 0.05 * water.specific_weight() * mesh.volume();
                let (mut force, mut torque) = (Vec::new(), Vec::new());
                let (mut centroid, mut reference) = ((0.0f64, 0.0f64), 0.0f64);
                while force.len() < poses {
                    let pose = Pose::from_parts(
                        Translation3::new(
                            random.between(-5.0, 5.0),
                            random.between(-0.7, 0.4),
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
                    let exact = by(3);
                    let scale = exact.force.norm();
                    if scale < wet {
                        // Barely wet: the relative error is not the quadrature's.
                        continue;
                    }
                    let errors = |b: &Buoyancy<f64>| {
                        (
                            (b.force - exact.force).norm() / scale,
                            (b.torque - exact.torque).norm() / (scale * size),
                        )
                    };
                    let (f, t) = errors(
                        &mesh
                            .buoyancy_froude_krylov(&pose, &water, &waves, time)
                            .unwrap(),
                    );
                    force.push(f);
                    torque.push(t);
                    let (f, t) = errors(
                        &mesh
                            .froude_krylov_by(&pose, &water, &waves, time, &Centroid)
                            .unwrap(),
                    );
                    centroid = (centroid.0.max(f), centroid.1.max(t));
                    // The reference's own error is below its change from 16 sub-triangles.
                    let (f, t) = errors(&by(2));
                    reference = reference.max(f.max(t));
                }
                let (force_worst, force_median) = worst_and_median(&mut force);
                let (torque_worst, torque_median) = worst_and_median(&mut torque);
                worst_force = worst_force.max(force_worst);
                worst_torque = worst_torque.max(torque_worst);
                worst_centroid = (
                    worst_centroid.0.max(centroid.0),
                    worst_centroid.1.max(centroid.1),
                );
                worst_reference = worst_reference.max(reference);
                let edge = k * mesh.longest_edge;
                table += &alloc::format!(
                    "{sea_name:<21} {mesh_name:<22} {edge:5.2} {force_worst:13.1e} {:7.1e}",
                    force_median,
                );
                table += &alloc::format!(
                    " {torque_worst:14.1e} {torque_median:7.1e} {:15.1e} {:7.1e} {:10.1e}\n",
                    centroid.0,
                    centroid.1,
                    reference,
                );
            }
        }
        #[cfg(feature = "std")]
        std::println!("{table}");
        assert!(worst_force < FORCE_BOUND, "force: {worst_force:e}\n{table}");
        assert!(
            worst_torque < TORQUE_BOUND,
            "torque: {worst_torque:e}\n{table}"
        );
        // The reference is converged far below the bounds, and the bounds reject a degree-1 rule.
        assert!(
            worst_reference < TORQUE_BOUND / 20.0,
            "reference: {worst_reference:e}\n{table}"
        );
        assert!(
            worst_centroid.0 > FORCE_BOUND && worst_centroid.1 > TORQUE_BOUND,
            "centroid: {worst_centroid:?}\n{table}"
        );
    }
}
