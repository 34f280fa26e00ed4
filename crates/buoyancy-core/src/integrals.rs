//! Per-triangle integrals and the waterline clip.
//!
//! Everything here works in the *mesh frame*, on vertex positions relative to a reference point
//! chosen by the caller, with `h` the signed height of each vertex above the water plane
//! (negative under water). Sums are kept with their constant factors (6, 24) pulled out, so the
//! hot loop does no divisions; [`crate::query`] applies them once per evaluation.

use nalgebra::Vector3;

use crate::Real;

/// Running sums of the volume methods, about a reference point `o`.
///
/// For a triangle `(a, b, c)` (positions relative to `o`) the signed tetrahedron
/// `(o, a, b, c)` has volume `V_i = det/6`, `det = a·(b×c)`, and first moment about `o`
/// `V_i·(a+b+c)/4 = det·(a+b+c)/24`. Summed over a closed surface they give the enclosed volume
/// and its first moment (divergence theorem).
#[derive(Debug, Clone, Copy)]
pub(crate) struct VolumeSums<T: Real> {
    /// Σ det = 6·volume.
    pub volume6: T,
    /// Σ det·(a+b+c) = 24·first moment about `o`.
    pub moment24: Vector3<T>,
    pub counts: Counts,
}

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
    pub counts: Counts,
}

/// How many triangles were found fully and partly under water.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Counts {
    pub full: usize,
    pub partial: usize,
}

impl core::ops::Add for Counts {
    type Output = Counts;
    #[inline]
    fn add(self, o: Counts) -> Counts {
        Counts {
            full: self.full + o.full,
            partial: self.partial + o.partial,
        }
    }
}

/// A sum over triangles that can be split and merged: what the reduction in
/// [`crate::query`] needs.
pub(crate) trait Sums: Copy + Send {
    fn zero() -> Self;
    fn merge(self, other: Self) -> Self;
}

impl<T: Real> Sums for VolumeSums<T> {
    #[inline]
    fn zero() -> Self {
        VolumeSums {
            volume6: T::zero(),
            moment24: Vector3::zeros(),
            counts: Counts::default(),
        }
    }
    #[inline]
    fn merge(self, o: Self) -> Self {
        VolumeSums {
            volume6: self.volume6 + o.volume6,
            moment24: self.moment24 + o.moment24,
            counts: self.counts + o.counts,
        }
    }
}

impl<S: Sums> Sums for [S; 2] {
    #[inline]
    fn zero() -> Self {
        [S::zero(), S::zero()]
    }
    #[inline]
    fn merge(self, [c, d]: Self) -> Self {
        let [a, b] = self;
        [a.merge(c), b.merge(d)]
    }
}

impl<T: Real> Sums for SurfaceSums<T> {
    #[inline]
    fn zero() -> Self {
        SurfaceSums {
            force6: Vector3::zeros(),
            torque24: Vector3::zeros(),
            moment24: Vector3::zeros(),
            counts: Counts::default(),
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

impl<T: Real> VolumeSums<T> {
    /// Adds the tetrahedron `(o, a, b, c)`, positions relative to `o`.
    #[inline(always)]
    pub fn add_tetrahedron(&mut self, [a, b, c]: [Vector3<T>; 3]) {
        let det = a.dot(&b.cross(&c));
        self.volume6 += det;
        self.moment24 += (a + b + c) * det;
    }
}

impl<T: Real> SurfaceSums<T> {
    /// Adds the pressure integrals of triangle `r` (positions relative to `o`) whose vertices
    /// have heights `h` above the plane of unit up normal `n`.
    ///
    /// The first moment uses `r = r⊥ + (n·r) n` with `n·r = h − h_o` (`h_o` the height of `o`):
    /// `∫_V r dV = ∫_S h r⊥ (n·dA) + n ∫_S (h²/2 − h_o h)(n·dA)
    ///          = ∫_S h r (n·dA) − (n/2) ∫_S h² (n·dA)`,
    /// the `h_o` terms cancelling, so `o` may be anywhere.
    #[inline(always)]
    pub fn add_triangle(&mut self, n: &Vector3<T>, r: [Vector3<T>; 3], h: [T; 3]) {
        let area2 = (r[1] - r[0]).cross(&(r[2] - r[0]));
        let sum_h = h[0] + h[1] + h[2];
        let w = r[0] * h[0] + r[1] * h[1] + r[2] * h[2] + (r[0] + r[1] + r[2]) * sum_h;
        let q = h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + sum_h * sum_h;
        self.force6 += area2 * sum_h;
        self.torque24 += w.cross(&area2);
        self.moment24 += (w - n * (q * T::from_f64_lossy(0.5))) * n.dot(&area2);
    }

    /// Adds `sign` times [`add_triangle`](Self::add_triangle) of the corner `[a, ab, ca]` cut
    /// off a triangle at the waterline, whose heights are `[h_a, 0, 0]`: then `Σh = h_a`,
    /// `w = h_a (2a + ab + ca)` and `q = 2h_a²`.
    #[inline(always)]
    pub fn add_corner(&mut self, n: &Vector3<T>, [a, ab, ca]: [Vector3<T>; 3], h_a: T, sign: T) {
        let area2 = (ab - a).cross(&(ca - a)) * sign;
        let w = (a + a + ab + ca) * h_a;
        self.force6 += area2 * h_a;
        self.torque24 += w.cross(&area2);
        self.moment24 += (w - n * (h_a * h_a)) * n.dot(&area2);
    }
}

/// A triangle the water plane crosses, split at the waterline: the "odd" vertex `a`, alone on
/// its side, the other two `b`, `c` in the triangle's order after it, their heights, and the
/// waterline points `ab` on edge a→b and `ca` on edge c→a (heights exactly zero).
pub(crate) struct Split<T: Real> {
    /// Whether `a` is the only vertex under water (else it is the only one above).
    pub odd_is_below: bool,
    pub a: Vector3<T>,
    pub b: Vector3<T>,
    pub c: Vector3<T>,
    pub heights: [T; 3],
    pub ab: Vector3<T>,
    pub ca: Vector3<T>,
}

/// Splits triangle `p` (vertex heights `h`) at the waterline.
///
/// Precondition: the triangle crosses the plane, `min(h) < 0 < max(h)`. A vertex with `h = 0`
/// counts as under water; the result is continuous in `h` either way. The "odd" vertex, alone
/// on its side, is found, and the edges leaving it are cut where `h = 0`; the divisor is never
/// zero because the two ends of a cut edge lie strictly on opposite sides or one is the
/// strictly negative minimum.
#[inline(always)]
pub(crate) fn split<T: Real>(p: [Vector3<T>; 3], h: [T; 3]) -> Split<T> {
    let zero = T::zero();
    let below = [h[0] <= zero, h[1] <= zero, h[2] <= zero];
    let below_count = below.iter().filter(|&&b| b).count();
    // The odd vertex: the only one under water, or the only one above.
    let odd_is_below = below_count == 1;
    let odd = if below[0] == odd_is_below {
        0
    } else if below[1] == odd_is_below {
        1
    } else {
        2
    };
    let (i1, i2) = ((odd + 1) % 3, (odd + 2) % 3);
    let (a, b, c) = (p[odd], p[i1], p[i2]);
    let (ha, hb, hc) = (h[odd], h[i1], h[i2]);
    Split {
        odd_is_below,
        a,
        b,
        c,
        heights: [ha, hb, hc],
        ab: a + (b - a) * (ha / (ha - hb)),
        ca: a + (c - a) * (ha / (ha - hc)),
    }
}

/// Calls `emit` with the part of triangle `p` (vertex heights `h`) that lies under water, as one
/// or two triangles with the orientation of `p` and their vertex heights (exactly zero on the
/// waterline), and returns the waterline segment oriented as the *cap* (the part of the water
/// plane inside the body, facing up) traverses it: opposite to the submerged part's boundary.
///
/// Precondition as for [`split`].
#[inline(always)]
pub(crate) fn clip_below<T: Real>(
    p: [Vector3<T>; 3],
    h: [T; 3],
    mut emit: impl FnMut([Vector3<T>; 3], [T; 3]),
) -> [Vector3<T>; 2] {
    let zero = T::zero();
    let Split {
        odd_is_below,
        a,
        b,
        c,
        heights: [ha, hb, hc],
        ab,
        ca,
    } = split(p, h);
    if odd_is_below {
        // Submerged: (a, ab, ca), whose boundary runs ab → ca along the waterline.
        emit([a, ab, ca], [ha, zero, zero]);
        [ca, ab]
    } else {
        // Submerged: (ab, b, c, ca), whose boundary runs ca → ab along the waterline.
        emit([ab, b, c], [zero, hb, hc]);
        emit([ab, c, ca], [zero, hc, zero]);
        [ab, ca]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri() -> [Vector3<f64>; 3] {
        [
            Vector3::new(0.0, -1.0, 0.0),
            Vector3::new(1.0, 1.0, 0.0),
            Vector3::new(-1.0, 1.0, 0.0),
        ]
    }

    fn area(p: &[Vector3<f64>; 3]) -> Vector3<f64> {
        (p[1] - p[0]).cross(&(p[2] - p[0])) / 2.0
    }

    #[test]
    fn clip_keeps_the_part_below_with_orientation() {
        let p = tri();
        let h = p.map(|v| v.y);
        let mut total = Vector3::zeros();
        let mut parts = 0;
        clip_below(p, h, |q, hq| {
            parts += 1;
            for (v, hv) in q.iter().zip(hq) {
                assert!(v.y <= 1e-15 && (v.y - hv).abs() < 1e-15);
            }
            total += area(&q);
        });
        assert_eq!(parts, 1);
        // The part below y = 0 is a triangle of base 1 and height 1, a quarter of the whole.
        assert!((total - area(&p) / 4.0).norm() < 1e-15);

        // Upside down: two vertices below, three quarters of the area in two triangles.
        let p = p.map(|v| Vector3::new(v.x, -v.y, 0.0));
        let h = p.map(|v| v.y);
        let (mut total, mut parts) = (Vector3::zeros(), 0);
        clip_below(p, h, |q, _| {
            parts += 1;
            total += area(&q);
        });
        assert_eq!(parts, 2);
        assert!((total - area(&p) * 0.75).norm() < 1e-15);
    }

    #[test]
    fn clip_with_a_vertex_on_the_plane() {
        // Heights (-1, 0, +1): the part below is the triangle (a, b, midpoint of c→a).
        let p = [
            Vector3::new(0.0, -1.0, 0.0),
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(0.0, 1.0, 0.0),
        ];
        let h = p.map(|v| v.y);
        let mut total = Vector3::zeros();
        clip_below(p, h, |q, _| total += area(&q));
        assert!((total - area(&p) / 2.0).norm() < 1e-15);
    }

    #[test]
    fn corner_kernel_is_the_triangle_kernel() {
        let n = Vector3::new(0.2, 0.9, -0.3).normalize();
        let (a, ab, ca) = (
            Vector3::new(0.3, -1.2, 0.5),
            Vector3::new(1.1, 0.2, -0.4),
            Vector3::new(-0.7, 0.3, 0.9),
        );
        for sign in [1.0, -1.0] {
            let (mut corner, mut triangle) =
                (SurfaceSums::<f64>::zero(), SurfaceSums::<f64>::zero());
            corner.add_corner(&n, [a, ab, ca], -0.8, sign);
            let (b, c) = if sign > 0.0 { (ab, ca) } else { (ca, ab) };
            triangle.add_triangle(&n, [a, b, c], [-0.8, 0.0, 0.0]);
            assert!((corner.force6 - triangle.force6).norm() < 1e-14);
            assert!((corner.torque24 - triangle.torque24).norm() < 1e-14);
            assert!((corner.moment24 - triangle.moment24).norm() < 1e-14);
        }
    }

    #[test]
    fn pressure_force_on_a_horizontal_triangle() {
        // Unit right triangle facing down at depth 2: force (in units of ρg) = 2·(1/2) up.
        let r = [
            Vector3::new(0.0, -2.0, 0.0),
            Vector3::new(1.0, -2.0, 0.0),
            Vector3::new(0.0, -2.0, 1.0),
        ];
        let mut s = SurfaceSums::<f64>::zero();
        s.add_triangle(&Vector3::y(), r, [-2.0; 3]);
        assert!((s.force6 / 6.0 - Vector3::new(0.0, 1.0, 0.0)).norm() < 1e-15);
        // Uniform pressure acts at the triangle's centroid (1/3, -2, 1/3).
        let torque = s.torque24 / 24.0;
        let expected = Vector3::new(1.0 / 3.0, -2.0, 1.0 / 3.0).cross(&(s.force6 / 6.0));
        assert!((torque - expected).norm() < 1e-15);
    }

    #[test]
    fn pressure_moment_of_a_vertical_triangle_is_exact() {
        // Vertical triangle in the plane z = 0 facing +z, heights from -1 to 0.
        // ∫ h x dA over it, computed by 2D quadrature, must match w/12·|A|.
        let r = [
            Vector3::new(0.0, -1.0, 0.0),
            Vector3::new(2.0, -1.0, 0.0),
            Vector3::new(0.0, 0.0, 0.0),
        ];
        let h = r.map(|v| v.y);
        let mut s = SurfaceSums::<f64>::zero();
        s.add_triangle(&Vector3::y(), r, h);
        // Midpoint rule on a fine grid of the triangle x ∈ [0, 2(−y)], y ∈ [−1, 0].
        let n = 2000;
        let (mut fz, mut mx, mut my) = (0.0, 0.0, 0.0);
        for i in 0..n {
            let y = -1.0 + (i as f64 + 0.5) / n as f64;
            let width = -2.0 * y;
            for j in 0..n {
                let x = width * (j as f64 + 0.5) / n as f64;
                let da = width / n as f64 / n as f64;
                fz += y * da; // force ∫ h n̂ dA, n̂ = +z
                mx += y * y * da; // (r × h n̂)_x = y·h
                my += -x * y * da; // (r × h n̂)_y = −x·h
            }
        }
        let force = s.force6 / 6.0;
        let torque = s.torque24 / 24.0;
        assert!(
            (force - Vector3::new(0.0, 0.0, fz)).norm() < 1e-6,
            "{force:?} vs {fz}"
        );
        assert!(
            (torque - Vector3::new(mx, my, 0.0)).norm() < 1e-6,
            "{torque:?} vs {mx}, {my}"
        );
    }
}
