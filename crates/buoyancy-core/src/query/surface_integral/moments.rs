//! The surface methods' pressure integrals over a group of fully submerged triangles, as
//! polynomials in the water plane whose coefficients depend on the triangles only, so that the
//! hierarchy can store them per node and a query adds them without looking at the triangles.
//!
//! # Derivation
//! Mesh frame, positions `vₖ` relative to the mesh centroid. The water plane enters through the
//! up normal `n` (unit, mesh frame) and the centroid's height `H` above the surface: a vertex
//! has height `hₖ = n·vₖ + H`. For one triangle let `s = v₀ + v₁ + v₂`,
//! `A = (v₁ − v₀) × (v₂ − v₀)` (twice the area vector) and
//! `Q = Σₖ vₖvₖᵀ + s sᵀ` (symmetric). The three sums of the surface kernel
//! ([`SurfaceSums::add_triangle`]) are then, with `Σh = n·s + 3H`,
//! `w = Σ hₖvₖ + (Σh) s = Q n + 4H s` and `q = Σ hₖ² + (Σh)² = nᵀQn + 8H n·s + 12H²`:
//!
//! * force: `(Σh) A = G n + 3H a`;
//! * moment of the pressure: `w × A = (Q n) × A + 4H s × A`, whose `i`-th component is
//!   `εᵢⱼₖ Mⱼₖ + 4H εᵢⱼₖ Gₖⱼ`;
//! * first moment of the submerged volume: `(n·A)(w − q n/2)
//!   = M n + 4H Gᵀn − (n/2)(n·M n + 8H nᵀG n + 12H² n·a)`;
//!
//! where, summed over the group, `a = Σ A`, `G = Σ A sᵀ` and `Mⱼₖ = Σₗ Tⱼₗₖ nₗ` with the third
//! order `Tⱼₗₖ = Σ Qⱼₗ Aₖ`, symmetric in `j, l`. So a group is known, for every pose and every
//! flat water plane, by `a` (3 numbers), `G` (9) and `T` (18): 30 numbers, summed once in `f64`
//! at build time. Because the polynomials are linear in the coefficients, the coefficients of
//! all nodes taken whole in one query are first added up and the polynomial is evaluated once.
//! Beside them a group keeps its area, `Σ |A|`, which it adds to the wetted area whatever the
//! plane.
//!
//! Sums about the mesh centroid keep the digits of a mesh far from its own origin, as elsewhere.

use nalgebra::{Matrix3, Vector3};

use crate::Real;
use crate::query::surface_integral::sums::SurfaceSums;

/// The pair `(j, l)` of each stored slice of `T`, in storage order.
const PAIRS: [(usize, usize); 6] = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];

/// Storage position of the symmetric pair `(j, l)` in [`PAIRS`].
const fn pair(j: usize, l: usize) -> usize {
    match (j, l) {
        (0, 0) => 0,
        (1, 1) => 1,
        (2, 2) => 2,
        (0, 1) | (1, 0) => 3,
        (0, 2) | (2, 0) => 4,
        _ => 5,
    }
}

/// The pressure-integral coefficients of a group of triangles (see the module documentation),
/// mesh frame, about the mesh centroid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SurfaceMoments<T: Real> {
    /// `a = Σ A`.
    pub area2: Vector3<T>,
    /// `G = Σ A sᵀ`.
    pub area_position: Matrix3<T>,
    /// `T[(j, l)] = Σ Qⱼₗ A` for the six pairs `j ≤ l` of [`PAIRS`].
    pub second: [Vector3<T>; 6],
    /// `Σ |A|`: twice the area, for the wetted area (a constant, not a polynomial).
    pub double_area: T,
}

impl<T: Real> SurfaceMoments<T> {
    pub fn zero() -> Self {
        SurfaceMoments {
            area2: Vector3::zeros(),
            area_position: Matrix3::zeros(),
            second: [Vector3::zeros(); 6],
            double_area: T::zero(),
        }
    }

    #[inline]
    pub fn add(&mut self, other: &Self) {
        self.area2 += other.area2;
        self.area_position += other.area_position;
        for (a, b) in self.second.iter_mut().zip(&other.second) {
            *a += b;
        }
        self.double_area += other.double_area;
    }

    /// Adds to `sums` the force, pressure moment and volume moment of the group, with the up
    /// normal `n` (unit) and the centroid's height `height`, both in the mesh frame: exactly
    /// what [`SurfaceSums::add_triangle`] adds for each triangle of the group; and its area to
    /// the wetted area.
    pub fn add_to(&self, n: &Vector3<T>, height: T, sums: &mut SurfaceSums<T>) {
        let g = &self.area_position;
        let t = &self.second;
        let (three, four, eight, twelve) = (
            T::from_f64_lossy(3.0),
            T::from_f64_lossy(4.0),
            T::from_f64_lossy(8.0),
            T::from_f64_lossy(12.0),
        );
        // Row j of M: Σₗ nₗ T[(j, l)].
        let m = Matrix3::from_rows(&[
            (t[pair(0, 0)] * n.x + t[pair(0, 1)] * n.y + t[pair(0, 2)] * n.z).transpose(),
            (t[pair(1, 0)] * n.x + t[pair(1, 1)] * n.y + t[pair(1, 2)] * n.z).transpose(),
            (t[pair(2, 0)] * n.x + t[pair(2, 1)] * n.y + t[pair(2, 2)] * n.z).transpose(),
        ]);
        let gn = g * n;
        let gtn = g.tr_mul(n);
        let mn = m * n;
        sums.force6 += gn + self.area2 * (three * height);
        let pressure = Vector3::new(m.m23 - m.m32, m.m31 - m.m13, m.m12 - m.m21);
        let s_cross_a = Vector3::new(g.m32 - g.m23, g.m13 - g.m31, g.m21 - g.m12);
        sums.torque24 += pressure + s_cross_a * (four * height);
        let q = n.dot(&mn)
            + eight * height * n.dot(&gn)
            + twelve * height * height * n.dot(&self.area2);
        sums.moment24 += mn + gtn * (four * height) - n * (q * T::from_f64_lossy(0.5));
        sums.counts.wetted_area2 += self.double_area;
    }
}

impl SurfaceMoments<f64> {
    /// The coefficients of one triangle, corners relative to the centroid, mesh frame.
    pub fn triangle(v: [Vector3<f64>; 3]) -> Self {
        let s = v[0] + v[1] + v[2];
        let area2 = (v[1] - v[0]).cross(&(v[2] - v[0]));
        let q = v[0] * v[0].transpose()
            + v[1] * v[1].transpose()
            + v[2] * v[2].transpose()
            + s * s.transpose();
        SurfaceMoments {
            area2,
            area_position: area2 * s.transpose(),
            second: PAIRS.map(|(j, l)| area2 * q[(j, l)]),
            double_area: area2.norm(),
        }
    }

    /// The same coefficients in `T`.
    pub fn cast<T: Real>(&self) -> SurfaceMoments<T> {
        SurfaceMoments {
            area2: self.area2.map(T::from_f64_lossy),
            area_position: self.area_position.map(T::from_f64_lossy),
            second: self.second.map(|v| v.map(T::from_f64_lossy)),
            double_area: T::from_f64_lossy(self.double_area),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::reduction::Sums;
    use alloc::vec::Vec;

    fn triangles() -> Vec<[Vector3<f64>; 3]> {
        // Deterministic, unstructured triangles.
        let mut x = 0.3_f64;
        let mut next = move || {
            x = (x * 997.0 + 0.123).fract();
            x * 4.0 - 2.0
        };
        (0..7)
            .map(|_| [0, 1, 2].map(|_| Vector3::new(next(), next(), next())))
            .collect()
    }

    #[test]
    fn polynomial_equals_the_kernel() {
        let n = Vector3::new(0.3, -0.5, 0.7).normalize();
        for height in [-3.0, -0.4, 0.0, 1.7] {
            // The kernel, triangle by triangle.
            let mut direct = SurfaceSums::<f64>::zero();
            let mut group = SurfaceMoments::zero();
            for v in triangles() {
                let h = v.map(|p| n.dot(&p) + height);
                direct.add_triangle(&n, v, h);
                group.add(&SurfaceMoments::triangle(v));
            }
            let mut summed = SurfaceSums::zero();
            group.add_to(&n, height, &mut summed);
            for (a, b, what) in [
                (summed.force6, direct.force6, "force"),
                (summed.torque24, direct.torque24, "pressure moment"),
                (summed.moment24, direct.moment24, "volume moment"),
            ] {
                assert!(
                    (a - b).norm() < 1e-12 * (1.0 + b.norm()),
                    "{what} at H = {height}: {a:?} vs {b:?}"
                );
            }
        }
    }

    #[test]
    fn pair_indexing_is_symmetric() {
        for (k, &(j, l)) in PAIRS.iter().enumerate() {
            assert_eq!(pair(j, l), k);
            assert_eq!(pair(l, j), k);
        }
    }
}
