//! Per-vertex coefficients of the pressure integrals that are linear in the vertex heights, for
//! the parts of a body under a non-flat surface (see `wave_pressure`).
//!
//! Over a triangle `t` with corners `rᵢ` (relative to the centroid, mesh frame), outward area
//! vector `A_t`, `R_t = Σ rᵢ` and heights `hᵢ` above the free surface, the surface sums of
//! [`SurfaceSums::add_triangle`](crate::query::surface_integral::SurfaceSums::add_triangle) are
//!
//! ```text
//! force6   = Σᵢ hᵢ · 2A_t
//! torque24 = Σᵢ hᵢ · (rᵢ + R_t) × 2A_t
//! moment24 = Σᵢ hᵢ · (rᵢ + R_t)(n·2A_t)  −  (n/2)(n·2A_t)·(Σhᵢ² + (Σhᵢ)²)
//! ```
//!
//! The first three terms are linear in the heights: summed over the triangles of a region they
//! are `Σ_v h_v · c_v`, one coefficient per vertex. With, per vertex `v`, over the triangles
//! around it,
//!
//! ```text
//! a_v = Σ_t 2A_t,    M_v = Σ_t (r_v + R_t) ⊗ 2A_t,
//! ```
//!
//! `force6 = Σ h_v a_v`, `moment24`'s linear part is `(Σ h_v M_v)·n` and `torque24` is the
//! axial vector of the antisymmetric part of `Σ h_v M_v` (`(u ⊗ v)` has `u × v` there). Twelve
//! numbers per vertex replace the per-triangle work wherever every triangle around a vertex is
//! under water; only the quadratic term stays per triangle.

use alloc::vec::Vec;

use nalgebra::{Matrix3, Vector3};

use crate::Real;

/// The coefficients of one vertex (see the module documentation), mesh frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct VertexTerms<T: Real> {
    /// `a_v = Σ_t 2A_t` over the triangles around the vertex, m².
    pub area2: Vector3<T>,
    /// `M_v = Σ_t (r_v + R_t) ⊗ 2A_t`, m³.
    pub moment: Matrix3<T>,
}

impl<T: Real> VertexTerms<T> {
    /// The terms of every vertex of `vertices` (relative to the centroid) over `triangles`,
    /// summed in `f64`.
    pub fn build(vertices: &[Vector3<T>], triangles: &[[u32; 3]]) -> Vec<Self> {
        let mut sums =
            alloc::vec![(Vector3::<f64>::zeros(), Matrix3::<f64>::zeros()); vertices.len()];
        for t in triangles {
            let r = t.map(|k| vertices[k as usize].map(T::to_f64));
            let area2 = (r[1] - r[0]).cross(&(r[2] - r[0]));
            let sum = r[0] + r[1] + r[2];
            for (k, ri) in t.iter().zip(&r) {
                let (a, m) = &mut sums[*k as usize];
                *a += area2;
                *m += (ri + sum) * area2.transpose();
            }
        }
        sums.into_iter()
            .map(|(a, m)| VertexTerms {
                area2: a.map(T::from_f64_lossy),
                moment: m.map(T::from_f64_lossy),
            })
            .collect()
    }
}

/// Running sums of `h_v · a_v` and `h_v · M_v` (see the module documentation).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LinearSums<T: Real> {
    /// `Σ h_v a_v`.
    pub force6: Vector3<T>,
    /// `Σ h_v M_v`.
    pub moment: Matrix3<T>,
}

impl<T: Real> LinearSums<T> {
    pub fn zero() -> Self {
        LinearSums {
            force6: Vector3::zeros(),
            moment: Matrix3::zeros(),
        }
    }

    pub fn merge(self, other: Self) -> Self {
        LinearSums {
            force6: self.force6 + other.force6,
            moment: self.moment + other.moment,
        }
    }

    /// Adds `h · (a, M)`.
    #[inline(always)]
    pub fn add(&mut self, h: T, terms: &VertexTerms<T>) {
        self.force6 += terms.area2 * h;
        self.moment += terms.moment * h;
    }

    /// Takes away the share of triangle `r` (area vector `area2`, `Σ rᵢ = sum`) in the terms of
    /// its corner `k` at height `h`: `h · (2A_t, (r_k + R_t) ⊗ 2A_t)`.
    #[inline(always)]
    pub fn remove_share(&mut self, h: T, r_k: &Vector3<T>, sum: &Vector3<T>, area2: &Vector3<T>) {
        let scaled = area2 * h;
        self.force6 -= scaled;
        self.moment -= (r_k + sum) * scaled.transpose();
    }

    /// `force6`, `torque24` and `moment24`'s linear part for the up normal `n`.
    pub fn surface_terms(&self, n: &Vector3<T>) -> [Vector3<T>; 3] {
        let m = &self.moment;
        let torque24 = Vector3::new(
            m[(1, 2)] - m[(2, 1)],
            m[(2, 0)] - m[(0, 2)],
            m[(0, 1)] - m[(1, 0)],
        );
        [self.force6, torque24, m * n]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::reduction::Sums;
    use crate::query::surface_integral::SurfaceSums;
    use alloc::vec;

    #[test]
    fn vertex_sums_equal_triangle_sums_without_the_quadratic_term() {
        // A tetrahedron with arbitrary heights: Σ_v h_v c_v against add_triangle with the
        // quadratic term removed (it is (n/2)(n·2A)·q per triangle).
        let v: Vec<Vector3<f64>> = vec![
            Vector3::new(0.1, -0.2, 0.3),
            Vector3::new(1.2, 0.1, -0.4),
            Vector3::new(-0.3, 0.9, 0.2),
            Vector3::new(0.2, 0.3, 1.1),
        ];
        let t: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let h = [-0.7, 0.4, -1.3, 0.25];
        let n = Vector3::new(0.3, 0.8, -0.2).normalize();
        let terms = VertexTerms::build(&v, &t);
        let mut linear = LinearSums::zero();
        for (k, term) in terms.iter().enumerate() {
            linear.add(h[k], term);
        }
        let [force6, torque24, moment24] = linear.surface_terms(&n);
        let mut sums = SurfaceSums::<f64>::zero();
        let mut quadratic = Vector3::zeros();
        for tri in &t {
            let r = tri.map(|k| v[k as usize]);
            let hh = tri.map(|k| h[k as usize]);
            sums.add_triangle(&n, r, hh);
            let area2 = (r[1] - r[0]).cross(&(r[2] - r[0]));
            let s = hh[0] + hh[1] + hh[2];
            let q = hh[0] * hh[0] + hh[1] * hh[1] + hh[2] * hh[2] + s * s;
            quadratic -= n * (q * 0.5 * n.dot(&area2));
        }
        assert!((force6 - sums.force6).norm() < 1e-14);
        assert!((torque24 - sums.torque24).norm() < 1e-13);
        assert!((moment24 + quadratic - sums.moment24).norm() < 1e-13);
    }
}
