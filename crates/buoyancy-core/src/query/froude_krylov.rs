//! The linear Froude–Krylov pressure of Airy and spectral seas integrated over the wetted
//! surface by quadrature: see [the guide](crate::query#waves-the-froude-krylov-pressure).

use nalgebra::{Point3, Vector3};

use crate::query::clip::{TriangleClass, WaterlineCut, classify, clip_below, cut_at_waterline};
use crate::query::result::TriangleCounts;
use crate::query::waves::on_line_of_action;
use crate::water::{AiryWaves, ResolvedWave, pressure_ratio, resolve};
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

/// A rule integrating the pressure over a triangle.
trait Rule {
    /// `∫p dA / A` and `∫r·p dA / A` over the triangle `q` of area `A`.
    fn mean<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (T, Vector3<T>);
}

/// The production rule: [`RULE`] once over the triangle.
struct Dunavant;

impl Rule for Dunavant {
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

/// The one-point (centroid) rule, of degree 1: the tests check that their bounds reject it.
#[cfg(test)]
struct Centroid;

#[cfg(test)]
impl Rule for Centroid {
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

/// `−∫p·n̂ dA` and `−∫r × p·n̂ dA` over the triangle `q` by `rule`, `n̂` its outward normal
/// (the one `q`'s order gives).
#[inline(always)]
fn load<T: Real>(
    rule: &impl Rule,
    q: &[Vector3<T>; 3],
    pressure: &impl Fn(&Vector3<T>) -> T,
) -> (Vector3<T>, Vector3<T>) {
    let area = (q[1] - q[0]).cross(&(q[2] - q[0])) * T::from_f64_lossy(0.5);
    let (mean, moment) = rule.mean(q, pressure);
    (-(area * mean), -moment.cross(&area))
}

/// Calls `emit` with the three triangles into which the still plane cuts the flat triangle `q`
/// whose vertices lie `z` above it (precondition: `min(z) < 0 < max(z)`), each with the
/// orientation of `q` and wholly on one side of the plane (or on it). The two cut points are
/// computed once and shared, so the three cover `q` without gap or overlap.
#[inline(always)]
fn split_at_still_plane<T: Real>(
    q: [Vector3<T>; 3],
    z: [T; 3],
    mut emit: impl FnMut(&[Vector3<T>; 3]),
) {
    // `a` alone on its side; the still plane runs from `ab` (on a→b) to `ca` (on c→a).
    let WaterlineCut {
        a, b, c, ab, ca, ..
    } = cut_at_waterline(q, z);
    emit(&[a, ab, ca]);
    emit(&[ab, b, c]);
    emit(&[ab, c, ca]);
}

/// How the pressure is integrated over a wetted piece.
trait Quadrature {
    /// `−∫p·n̂ dA` and `−∫r × p·n̂ dA` over the wetted piece `q`, whose vertices lie `z` above
    /// the still plane.
    fn load<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        z: &[T; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (Vector3<T>, Vector3<T>);
}

/// The production quadrature: a piece that straddles the still plane is cut along it (where
/// the pressure's vertical derivative jumps under a crest), and `R` integrates each side, over
/// which the pressure is smooth.
struct AtStillPlane<R>(R);

impl<R: Rule> Quadrature for AtStillPlane<R> {
    #[inline(always)]
    fn load<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        z: &[T; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (Vector3<T>, Vector3<T>) {
        if classify(z) != TriangleClass::Cut {
            return load(&self.0, q, pressure);
        }
        let (mut force, mut torque) = (Vector3::zeros(), Vector3::zeros());
        split_at_still_plane(*q, *z, |side| {
            let (f, t) = load(&self.0, side, pressure);
            force += f;
            torque += t;
        });
        (force, torque)
    }
}

/// `R` over the whole piece, cut or not by the still plane: the quadrature before the cut,
/// which the tests check the bounds reject in some sea.
#[cfg(test)]
struct Whole<R>(R);

#[cfg(test)]
impl<R: Rule> Quadrature for Whole<R> {
    fn load<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        _: &[T; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (Vector3<T>, Vector3<T>) {
        load(&self.0, q, pressure)
    }
}

/// The tests' reference, which cuts no piece the way production does: each piece split at its
/// edges' midpoints `levels` times (`4^levels` congruent sub-triangles); then, up to `refine`
/// times more, each sub-triangle on which the pressure is clipped to zero at some but not all
/// of its vertices and the rule's points (the clip's kink, along a curve that no planar cut
/// follows); then each sub-triangle that straddles the still plane or the `bottom` (the other
/// kinks, planar) cut along it by [`clip_below`]; [`RULE`] on each part.
#[cfg(test)]
#[derive(Clone, Copy)]
struct Subdivided {
    levels: u32,
    refine: u32,
    bottom: Option<f64>,
}

#[cfg(test)]
impl Subdivided {
    /// Whether the pressure is clipped to zero at some but not all of the vertices of `q` and
    /// the rule's points on it.
    fn partly_clipped<T: Real>(q: &[Vector3<T>; 3], pressure: &impl Fn(&Vector3<T>) -> T) -> bool {
        let (mut clipped, mut wet) = (false, false);
        let mut sample = |r: &Vector3<T>| {
            if pressure(r) > T::zero() {
                wet = true;
            } else {
                clipped = true;
            }
        };
        q.iter().for_each(&mut sample);
        for &(alpha, beta, _) in &RULE {
            let (alpha, beta) = (T::from_f64_lossy(alpha), T::from_f64_lossy(beta));
            for j in 0..3 {
                sample(&(q[j] * alpha + q[(j + 1) % 3] * beta + q[(j + 2) % 3] * beta));
            }
        }
        clipped && wet
    }

    /// Adds to `total` the load on the parts of `q` (heights `z`) cut along the horizontal
    /// planes at the heights `planes`, [`RULE`] on each.
    fn cut<T: Real>(
        q: &[Vector3<T>; 3],
        z: &[T; 3],
        planes: &[T],
        pressure: &impl Fn(&Vector3<T>) -> T,
        total: &mut (Vector3<T>, Vector3<T>),
    ) {
        let Some((&level, rest)) = planes.split_first() else {
            let (f, t) = load(&Dunavant, q, pressure);
            total.0 += f;
            total.1 += t;
            return;
        };
        let h = z.map(|z| z - level);
        if classify(&h) != TriangleClass::Cut {
            return Self::cut(q, z, rest, pressure, total);
        }
        // The part below the plane, then the part above it.
        clip_below(*q, h, |part, h| {
            Self::cut(&part, &h.map(|h| h + level), rest, pressure, total);
        });
        clip_below(*q, h.map(|h| -h), |part, h| {
            Self::cut(&part, &h.map(|h| level - h), rest, pressure, total);
        });
    }
}

#[cfg(test)]
impl Quadrature for Subdivided {
    fn load<T: Real>(
        &self,
        q: &[Vector3<T>; 3],
        z: &[T; 3],
        pressure: &impl Fn(&Vector3<T>) -> T,
    ) -> (Vector3<T>, Vector3<T>) {
        let mut total = (Vector3::zeros(), Vector3::zeros());
        let finer = if self.levels > 0 {
            Subdivided {
                levels: self.levels - 1,
                ..*self
            }
        } else if self.refine > 0 && Self::partly_clipped(q, pressure) {
            Subdivided {
                refine: self.refine - 1,
                ..*self
            }
        } else {
            let planes = [T::zero(), -T::from_f64_lossy(self.bottom.unwrap_or(0.0))];
            let planes = if self.bottom.is_some() {
                &planes[..]
            } else {
                &planes[..1]
            };
            Self::cut(q, z, planes, pressure, &mut total);
            return total;
        };
        let half = T::from_f64_lossy(0.5);
        let mid = |i: usize, j: usize| ((q[i] + q[j]) * half, (z[i] + z[j]) * half);
        let ((ab, zab), (bc, zbc), (ca, zca)) = (mid(0, 1), mid(1, 2), mid(2, 0));
        let ([a, b, c], [za, zb, zc]) = (*q, *z);
        for (child, zs) in [
            ([a, ab, ca], [za, zab, zca]),
            ([ab, b, bc], [zab, zb, zbc]),
            ([ca, bc, c], [zca, zbc, zc]),
            ([bc, ca, ab], [zbc, zca, zab]),
        ] {
            let (f, t) = finer.load(&child, &zs, pressure);
            total.0 += f;
            total.1 += t;
        }
        total
    }
}

/// One evaluation's sea: its components resolved for the water, and the depth.
struct DecayingWaves<T: Real> {
    waves: alloc::vec::Vec<ResolvedWave<T>>,
    depth: Option<T>,
}

impl<T: Real> DecayingWaves<T> {
    /// The pressure, in units of `ρ·g`, at a point of height `z` above the still plane and
    /// horizontal position `q` at `time` (see the module documentation).
    fn pressure(&self, q: &Point3<T>, z: T, time: T) -> T {
        (self.wave_part(q, z, time) - z).max(T::zero())
    }

    /// The wave part of [`pressure`](Self::pressure), in units of `ρ·g`: `Σ aᵢ·Kᵢ(z)·cos θᵢ`.
    fn wave_part(&self, q: &Point3<T>, z: T, time: T) -> T {
        let below = z.min(T::zero());
        self.waves.iter().fold(T::zero(), |sum, w| {
            sum + w.amplitude
                * pressure_ratio(w.wavenumber, below, self.depth)
                * w.phase_at(&q.coords, time).cos()
        })
    }
}

impl<T: Real> Mesh<T> {
    /// The buoyancy under the Airy or spectral sea `waves` at `time` (s) by the linear
    /// Froude–Krylov pressure (see the [guide](crate::query#waves-the-froude-krylov-pressure)):
    /// the torque about the center of mass, the center the point of the force's line of action
    /// nearest the center of mass, the volume the one implied by the vertical force.
    pub(crate) fn froude_krylov(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        waves: &AiryWaves<T>,
        time: T,
    ) -> Result<Buoyancy<T>, Error> {
        self.froude_krylov_by(pose, water, waves, time, &AtStillPlane(Dunavant))
    }

    /// [`Mesh::froude_krylov`] with the pressure integrated over each wetted piece by
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
        let sea = DecayingWaves {
            waves: resolve(waves.components(), water, waves.depth())?,
            depth: waves.depth(),
        };
        // A body whose bounding sphere lies below the still plane and every vertex under the
        // surface: the pressure is positive all over, and its hydrostatic part is taken
        // relative to the centroid's level, `−(z − h_c)`. The constant `−h_c` it leaves out
        // changes neither the force nor the torque on the closed surface, and far below the
        // surface it would keep the depth's digits and lose the body's.
        let offset = if frame.height + self.bounding_radius < T::zero()
            && heights.iter().all(|h| *h < T::zero())
        {
            frame.height
        } else {
            T::zero()
        };
        // Pressure at a point relative to the centroid, mesh frame, in units of ρg.
        let pressure = |r: &Vector3<T>| {
            let local = frame.normal_local.dot(r);
            let z = local + frame.height;
            let x = frame.center_of_mass + frame.rotation * r;
            let q = x - frame.normal * z;
            if offset == T::zero() {
                sea.pressure(&q, z, time)
            } else {
                sea.wave_part(&q, z, time) - (local + (frame.height - offset))
            }
        };
        let (mut force, mut torque) = (Vector3::zeros(), Vector3::zeros());
        let mut piece = |q: [Vector3<T>; 3]| {
            // −∫ p n̂ dA and −∫ r × p n̂ dA about the centroid.
            let z = q.map(|r| frame.normal_local.dot(&r) + frame.height);
            let (f, t) = quadrature.load(&q, &z, &pressure);
            force += f;
            torque += t;
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
                    counts.wetted_area2 += self.double_areas[i];
                    piece(v);
                }
                TriangleClass::Cut => {
                    counts.partial += 1;
                    counts.wetted_area2 +=
                        cut_at_waterline(v, h).wetted_share() * self.double_areas[i];
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
    use crate::Method;
    use crate::mesh::primitives;
    use crate::query::{Pressure, Sea};
    use crate::water::AiryComponent;
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

    /// A sea of the error test, with the bounds it asserts on the relative errors in force and
    /// torque.
    struct TestSea {
        name: &'static str,
        waves: AiryWaves<f64>,
        force_bound: f64,
        torque_bound: f64,
    }

    fn seas() -> Vec<TestSea> {
        let sea = |name, components, depth, force_bound, torque_bound| TestSea {
            name,
            waves: AiryWaves::new(components, depth).unwrap(),
            force_bound,
            torque_bound,
        };
        vec![
            sea(
                "long, deep",
                vec![component(0.5, 25.0, 0.3, 0.0)],
                None,
                5e-13,
                1e-11,
            ),
            sea(
                "moderate, depth 3 m",
                vec![component(0.2, 4.0, 0.0, 0.4), component(0.1, 6.0, 1.1, 2.0)],
                Some(3.0),
                2e-6,
                1e-6,
            ),
            sea(
                "short steep, deep",
                vec![component(0.06, 1.0, 0.7, 1.0)],
                None,
                1e-4,
                5e-5,
            ),
            sea(
                "shallow, depth 1.2 m",
                vec![component(0.12, 2.5, -0.4, 0.2)],
                Some(1.2),
                2e-6,
                1e-6,
            ),
            sea(
                "5 components, deep",
                vec![
                    component(0.15, 8.0, 0.0, 0.0),
                    component(0.1, 4.0, 0.5, 1.0),
                    component(0.06, 2.5, -0.8, 2.0),
                    component(0.04, 1.6, 1.6, 3.0),
                    component(0.025, 1.1, 2.5, 4.0),
                ],
                None,
                2e-4,
                1e-4,
            ),
        ]
    }

    fn meshes() -> Vec<(&'static str, Mesh<f64>)> {
        let mesh = |s: Result<primitives::Shape<f64>, Error>| {
            let (v, t) = s.unwrap();
            Mesh::new(v, t).unwrap()
        };
        vec![
            (
                "sphere r 0.5, 32×16",
                mesh(primitives::uv_sphere(0.5, 32, 16)),
            ),
            (
                "torus 0.6/0.25, 32×12",
                mesh(primitives::torus(0.6, 0.25, 32, 12)),
            ),
            ("cube 1 m, n 4", mesh(primitives::cube(4))),
        ]
    }

    /// Worst and median of `errors`.
    fn worst_and_median(errors: &mut [f64]) -> (f64, f64) {
        errors.sort_by(f64::total_cmp);
        (errors[errors.len() - 1], errors[errors.len() / 2])
    }

    /// The larger of each of two pairs of errors.
    fn larger(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
        (a.0.max(b.0), a.1.max(b.1))
    }

    /// The production quadrature against a reference (the same pieces and pressure, 16
    /// sub-triangles each, refined up to 6 times more where the pressure is partly clipped,
    /// cut along the still plane and the bottom by the waterline's clipping; see
    /// [`Subdivided`]) in every sea's bounds; the bounds reject the centroid rule in every sea
    /// and the rule on uncut pieces in some; prints the table of the module documentation (the
    /// last column: the reference's change from one level less, over the bounds).
    #[test]
    fn the_quadrature_error_against_a_subdivided_reference() {
        let water = Water::default();
        let mut random = Random(0x9e37_79b9_7f4a_7c15);
        let poses = 16;
        let mut table = String::from(concat!(
            "sea                   mesh                     kL   force: worst  median",
            "  torque: worst  median  uncut: force  torque  centroid: force  torque  ref./bound\n",
        ));
        let (mut uncut_rejected, mut failures) = (Vec::new(), Vec::<String>::new());
        for sea in seas() {
            let waves = &sea.waves;
            let k = waves
                .components()
                .iter()
                .map(|c| c.wavenumber())
                .fold(0.0, f64::max);
            let bounds = (sea.force_bound, sea.torque_bound);
            let (mut worst, mut uncut, mut centroid) = ((0.0, 0.0), (0.0, 0.0), (0.0, 0.0));
            let mut worst_reference = 0.0f64;
            for (mesh_name, mesh) in meshes() {
                let size = mesh.bounding_radius();
                let wet = 0.05 * water.specific_weight() * mesh.volume();
                let (mut force, mut torque) = (Vec::new(), Vec::new());
                let (mut mesh_uncut, mut mesh_centroid) = ((0.0, 0.0), (0.0, 0.0));
                let mut reference = 0.0f64;
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
                    let reference_by = |levels, refine| {
                        let subdivided = Subdivided {
                            levels,
                            refine,
                            bottom: waves.depth(),
                        };
                        mesh.froude_krylov_by(&pose, &water, waves, time, &subdivided)
                            .unwrap()
                    };
                    let exact = reference_by(2, 6);
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
                            .buoyancy(
                                &pose,
                                Sea::new(&water, waves, time).with_pressure(Pressure::FroudeKrylov),
                                Method::ExactSurface,
                            )
                            .unwrap(),
                    );
                    force.push(f);
                    torque.push(t);
                    let (f, t) = errors(
                        &mesh
                            .froude_krylov_by(&pose, &water, waves, time, &Whole(Dunavant))
                            .unwrap(),
                    );
                    mesh_uncut = larger(mesh_uncut, (f, t));
                    let (f, t) = errors(
                        &mesh
                            .froude_krylov_by(&pose, &water, waves, time, &AtStillPlane(Centroid))
                            .unwrap(),
                    );
                    mesh_centroid = larger(mesh_centroid, (f, t));
                    let (f, t) = errors(&reference_by(1, 5));
                    reference = reference.max((f / bounds.0).max(t / bounds.1));
                }
                let (force_worst, force_median) = worst_and_median(&mut force);
                let (torque_worst, torque_median) = worst_and_median(&mut torque);
                worst = larger(worst, (force_worst, torque_worst));
                uncut = larger(uncut, mesh_uncut);
                centroid = larger(centroid, mesh_centroid);
                worst_reference = worst_reference.max(reference);
                let edge = k * mesh.longest_edge;
                table += &alloc::format!(
                    "{:<21} {mesh_name:<22} {edge:5.2} {force_worst:13.1e} {:7.1e}",
                    sea.name,
                    force_median,
                );
                table += &alloc::format!(
                    " {torque_worst:14.1e} {torque_median:7.1e} {:13.1e} {:7.1e}",
                    mesh_uncut.0,
                    mesh_uncut.1,
                );
                table += &alloc::format!(
                    " {:15.1e} {:7.1e} {reference:10.1e}\n",
                    mesh_centroid.0,
                    mesh_centroid.1,
                );
            }
            let name = sea.name;
            if worst.0 >= bounds.0 || worst.1 >= bounds.1 {
                failures.push(alloc::format!("{name}: {worst:?} not below {bounds:?}"));
            }
            // The reference is converged below the bounds: its change from one level less
            // everywhere (4 sub-triangles a piece, refined 5 times) is below a quarter of them.
            if worst_reference >= 0.25 {
                failures.push(alloc::format!("{name}: reference {worst_reference:e}"));
            }
            // The bounds reject a degree-1 rule.
            if centroid.0 <= bounds.0 || centroid.1 <= bounds.1 {
                failures.push(alloc::format!("{name}: centroid {centroid:?}"));
            }
            if uncut.0 > bounds.0 || uncut.1 > bounds.1 {
                uncut_rejected.push(name);
            }
        }
        #[cfg(feature = "std")]
        std::println!("{table}");
        assert!(failures.is_empty(), "{failures:?}\n{table}");
        // The bounds reject the rule without the cut along the still plane.
        assert!(!uncut_rejected.is_empty(), "uncut rule accepted\n{table}");
    }

    /// The parts of a piece split along the still plane cover it: the same vector area and first
    /// moment, each part on one side of the plane and oriented as the piece.
    #[test]
    fn the_split_at_the_still_plane_covers_the_piece() {
        let mut random = Random(7);
        let normal = Vector3::new(0.3, 0.9, -0.2).normalize();
        let area = |t: &[Vector3<f64>; 3]| (t[1] - t[0]).cross(&(t[2] - t[0])) / 2.0;
        let (mut tried, mut cut, mut with_a_vertex_on_the_plane) = (0, 0, 0);
        while cut < 1000 {
            tried += 1;
            let mut q: [Vector3<f64>; 3] = core::array::from_fn(|_| {
                Vector3::new(
                    random.between(-1.0, 1.0),
                    random.between(-1.0, 1.0),
                    random.between(-1.0, 1.0),
                )
            });
            let mut z = q.map(|r| normal.dot(&r));
            if tried % 5 == 0 {
                // A vertex on the plane.
                let i = tried % 3;
                q[i] -= normal * z[i];
                z[i] = 0.0;
            }
            if classify(&z) != TriangleClass::Cut {
                continue;
            }
            cut += 1;
            with_a_vertex_on_the_plane += usize::from(z.contains(&0.0));
            let (whole, unit) = (area(&q), area(&q).normalize());
            let moment = |t: &[Vector3<f64>; 3]| (t[0] + t[1] + t[2]) / 3.0 * area(t).dot(&unit);
            let (mut total, mut first) = (Vector3::zeros(), Vector3::zeros());
            split_at_still_plane(q, z, |t| {
                total += area(t);
                first += moment(t);
                // (Up to round-off for the empty part of a piece with a vertex on the plane.)
                assert!(area(t).dot(&unit) > -1e-15);
                let heights = t.map(|r| normal.dot(&r));
                let (low, high) = heights
                    .iter()
                    .fold((0.0f64, 0.0f64), |(l, h), &z| (l.min(z), h.max(z)));
                assert!(low > -1e-15 || high < 1e-15, "{heights:?}");
            });
            assert!((total - whole).norm() < 1e-15, "{total} {whole}");
            assert!(
                (first - moment(&q)).norm() < 1e-15,
                "{first} {}",
                moment(&q)
            );
        }
        assert!(with_a_vertex_on_the_plane > 100);
    }
}
