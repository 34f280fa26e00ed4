//! `SurfaceSums`: the running sums of the surface methods over the wetted triangles, and what
//! one triangle (whole or cut at the waterline) adds to them.

use nalgebra::Vector3;

use crate::Real;
use crate::query::clip::{TriangleClass, WaterlineCut, classify, cut_at_waterline};
use crate::query::reduction::Sums;
use crate::query::result::TriangleCounts;

/// Running sums of the surface methods, moments about a reference point `o`.
///
/// With `A = (b−a)×(c−a)/2` the outward area vector and `h` linear over the triangle, the
/// exact integrals over a triangle are (for linear f, g: `∫ f g dA = |A|/12·(Σ fᵢgᵢ + Σfᵢ·Σgᵢ)`)
///
/// * pressure force `∫ h n̂ dA = (Σhᵢ/3)·A`, in units of ρg;
/// * pressure moment `∫ r × h n̂ dA = w × A / 12`, `w = Σ hᵢ rᵢ + Σhᵢ·Σrᵢ`;
/// * `∫ h r (n·n̂) dA = (n·A)·w/12` and `∫ h² (n·n̂) dA = (n·A)·q/12`, `q = Σhᵢ² + (Σhᵢ)²`.
///
/// The last two give the first moment of the submerged volume from the wetted surface alone,
/// with no cap on the water plane: the fields `f·h·n` (f linear, `∇f ⊥ n`) and `h²n/2` vanish
/// on the plane and have divergence `f` and `h`; see [`SurfaceSums::add_triangle`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct SurfaceSums<T: Real> {
    /// Σ (Σhᵢ)·2A = 6·∫ h dA (force, in units of ρg).
    pub force6: Vector3<T>,
    /// Σ w × 2A = 24·∫ r × h dA (moment about `o`, in units of ρg).
    pub torque24: Vector3<T>,
    /// Σ (n·2A)·(w − q n/2) = 24·(first moment of the submerged volume about `o`).
    pub moment24: Vector3<T>,
    /// Triangles found fully and partly under water, and twice their wetted area.
    pub counts: TriangleCounts<T>,
}

impl<T: Real> Sums for SurfaceSums<T> {
    #[inline]
    fn zero() -> Self {
        SurfaceSums {
            force6: Vector3::zeros(),
            torque24: Vector3::zeros(),
            moment24: Vector3::zeros(),
            counts: TriangleCounts::default(),
        }
    }
    #[inline]
    fn merge(self, o: Self) -> Self {
        SurfaceSums {
            force6: self.force6 + o.force6,
            torque24: self.torque24 + o.torque24,
            moment24: self.moment24 + o.moment24,
            counts: self.counts + o.counts,
        }
    }
}

impl<T: Real> SurfaceSums<T> {
    /// Adds the pressure integrals of triangle `r` (positions relative to `o`) whose vertices
    /// have heights `h` above the plane of unit up normal `n`, and returns its `2A`.
    ///
    /// The first moment uses `r = r⊥ + (n·r) n` with `n·r = h − h_o` (`h_o` the height of `o`):
    /// `∫_V r dV = ∫_S h r⊥ (n·dA) + n ∫_S (h²/2 − h_o h)(n·dA)
    ///          = ∫_S h r (n·dA) − (n/2) ∫_S h² (n·dA)`,
    /// the `h_o` terms cancelling, so `o` may be anywhere.
    #[inline(always)]
    pub fn add_triangle(&mut self, n: &Vector3<T>, r: [Vector3<T>; 3], h: [T; 3]) -> Vector3<T> {
        let area2 = (r[1] - r[0]).cross(&(r[2] - r[0]));
        let sum_h = h[0] + h[1] + h[2];
        let w = r[0] * h[0] + r[1] * h[1] + r[2] * h[2] + (r[0] + r[1] + r[2]) * sum_h;
        let q = h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + sum_h * sum_h;
        self.force6 += area2 * sum_h;
        self.torque24 += w.cross(&area2);
        self.moment24 += (w - n * (q * T::from_f64_lossy(0.5))) * n.dot(&area2);
        area2
    }

    /// Adds `sign` times [`add_triangle`](Self::add_triangle) of the corner `[a, ab, ca]` cut
    /// off a triangle at the waterline, whose heights are `[h_a, 0, 0]`: then `Σh = h_a`,
    /// `w = h_a (2a + ab + ca)` and `q = 2h_a²`. Returns the corner's `2A` times `sign`.
    #[inline(always)]
    pub fn add_corner(
        &mut self,
        n: &Vector3<T>,
        [a, ab, ca]: [Vector3<T>; 3],
        h_a: T,
        sign: T,
    ) -> Vector3<T> {
        let area2 = (ab - a).cross(&(ca - a)) * sign;
        let w = (a + a + ab + ca) * h_a;
        self.force6 += area2 * h_a;
        self.torque24 += w.cross(&area2);
        self.moment24 += (w - n * (h_a * h_a)) * n.dot(&area2);
        area2
    }

    /// Adds the pressure integrals of the wetted part of triangle `v` (vertex heights `h` above
    /// the surface, linear over the triangle; up normal `n`) and counts it, with its area
    /// (`double_area` is the triangle's stored `2A`): the whole triangle if it is submerged; if
    /// the waterline cuts it, with `exact` its part under water (the corner at the odd vertex,
    /// or the whole triangle minus it, times its share [`WaterlineCut::wetted_share`] of the
    /// area: no square root), else nothing.
    #[inline(always)]
    pub fn add_wetted_part(
        &mut self,
        n: &Vector3<T>,
        v: [Vector3<T>; 3],
        h: [T; 3],
        exact: bool,
        double_area: &T,
    ) {
        match classify(&h) {
            TriangleClass::Submerged => {
                self.add_triangle(n, v, h);
                self.counts.full += 1;
                self.counts.wetted_area2 += *double_area;
            }
            TriangleClass::Cut => {
                self.counts.partial += 1;
                if exact {
                    let cut = cut_at_waterline(v, h);
                    self.counts.wetted_area2 += cut.wetted_share() * *double_area;
                    let WaterlineCut {
                        odd_is_below,
                        a,
                        ab,
                        ca,
                        heights,
                        ..
                    } = cut;
                    if odd_is_below {
                        self.add_corner(n, [a, ab, ca], heights[0], T::one());
                    } else {
                        self.add_triangle(n, v, h);
                        self.add_corner(n, [a, ab, ca], heights[0], -T::one());
                    }
                }
            }
            TriangleClass::Dry => {}
        }
    }
}
