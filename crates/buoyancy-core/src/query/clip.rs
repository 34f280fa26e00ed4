//! Where a triangle lies against the water plane, and its cut at the waterline.
//!
//! Everything here works in the *mesh frame*, on vertex positions relative to a reference point
//! chosen by the caller, with `h` the signed height of each vertex above the water plane
//! (negative under water).

use nalgebra::Vector3;

use crate::Real;

/// Where a triangle lies against the water plane, from its vertex heights.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum TriangleClass {
    /// Every vertex at or below the surface: a triangle lying in the surface is submerged (it
    /// closes the submerged volume).
    Submerged,
    /// Some vertex strictly below the surface, some strictly above: the waterline cuts it.
    Cut,
    /// No vertex strictly below the surface (one touching it from above is dry).
    Dry,
}

/// Where triangle of vertex heights `h` lies; see [`TriangleClass`].
#[inline(always)]
pub(crate) fn classify<T: Real>(h: &[T; 3]) -> TriangleClass {
    let zero = T::zero();
    if h[0] <= zero && h[1] <= zero && h[2] <= zero {
        TriangleClass::Submerged
    } else if h[0] >= zero && h[1] >= zero && h[2] >= zero {
        TriangleClass::Dry
    } else {
        TriangleClass::Cut
    }
}

/// A triangle the water plane crosses, cut at the waterline: the "odd" vertex `a`, alone on
/// its side, the other two `b`, `c` in the triangle's order after it, their heights, and the
/// waterline points `ab` on edge a→b and `ca` on edge c→a (heights exactly zero).
pub(crate) struct WaterlineCut<T: Real> {
    /// Whether `a` is the only vertex under water (else it is the only one above).
    pub odd_is_below: bool,
    pub a: Vector3<T>,
    pub b: Vector3<T>,
    pub c: Vector3<T>,
    pub heights: [T; 3],
    pub ab: Vector3<T>,
    pub ca: Vector3<T>,
    /// Where the edges leaving `a` are cut: `ab = a + (b − a)·fractions[0]` and
    /// `ca = a + (c − a)·fractions[1]`, each in `[0, 1]`.
    pub fractions: [T; 2],
}

impl<T: Real> WaterlineCut<T> {
    /// The share of the triangle's area under water. The corner `(a, ab, ca)` spans
    /// `fractions[0]·(b − a)` and `fractions[1]·(c − a)`: it is `fractions[0]·fractions[1]` of
    /// the triangle, the part under water when `a` is, else the rest. No square root: times the
    /// triangle's precomputed area, the wetted area.
    #[inline(always)]
    pub fn wetted_share(&self) -> T {
        let corner = self.fractions[0] * self.fractions[1];
        if self.odd_is_below {
            corner
        } else {
            T::one() - corner
        }
    }
}

/// Cuts triangle `p` (vertex heights `h`) at the waterline.
///
/// Precondition: the triangle crosses the plane, `min(h) < 0 < max(h)`. A vertex with `h = 0`
/// counts as under water; the result is continuous in `h` either way. The "odd" vertex, alone
/// on its side, is found, and the edges leaving it are cut where `h = 0`; the divisor is never
/// zero because the two ends of a cut edge lie strictly on opposite sides or one is the
/// strictly negative minimum.
#[inline(always)]
pub(crate) fn cut_at_waterline<T: Real>(p: [Vector3<T>; 3], h: [T; 3]) -> WaterlineCut<T> {
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
    let fractions = [ha / (ha - hb), ha / (ha - hc)];
    WaterlineCut {
        odd_is_below,
        a,
        b,
        c,
        heights: [ha, hb, hc],
        ab: a + (b - a) * fractions[0],
        ca: a + (c - a) * fractions[1],
        fractions,
    }
}

/// Calls `emit` with the part of triangle `p` (vertex heights `h`) that lies under water, as one
/// or two triangles with the orientation of `p` and their vertex heights (exactly zero on the
/// waterline), and returns the waterline segment oriented as the *cap* (the part of the water
/// plane inside the body, facing up) traverses it: opposite to the submerged part's boundary.
///
/// Precondition as for [`cut_at_waterline`].
#[inline(always)]
pub(crate) fn clip_below<T: Real>(
    p: [Vector3<T>; 3],
    h: [T; 3],
    mut emit: impl FnMut([Vector3<T>; 3], [T; 3]),
) -> [Vector3<T>; 2] {
    let zero = T::zero();
    let WaterlineCut {
        odd_is_below,
        a,
        b,
        c,
        heights: [ha, hb, hc],
        ab,
        ca,
        ..
    } = cut_at_waterline(p, h);
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
    fn wetted_share_is_the_clipped_area() {
        // Every way the plane crosses a scalene triangle, a vertex in the plane included: the
        // share times the area is the area of the pieces `clip_below` emits.
        let p = [
            Vector3::new(0.2, -0.3, 0.1),
            Vector3::new(1.3, 0.4, -0.2),
            Vector3::new(-0.4, 1.1, 0.6),
        ];
        let whole = area(&p).norm();
        for h in [
            [-1.0, 0.5, 2.0],
            [1.0, -0.5, 2.0],
            [1.0, 0.5, -2.0],
            [-1.0, -0.5, 2.0],
            [1.0, -0.5, -2.0],
            [-1.0, 0.5, -2.0],
            [-1.0, 0.0, 2.0],
            [0.0, 3.0, -0.7],
            [-1e-9, 1.0, 1.0],
            [1e-9, -1.0, -1.0],
        ] {
            let mut clipped = 0.0;
            clip_below(p, h, |q, _| clipped += area(&q).norm());
            let share = cut_at_waterline(p, h).wetted_share();
            assert!((0.0..=1.0).contains(&share), "{h:?}: {share}");
            assert!((share * whole - clipped).abs() < 1e-15, "{h:?}");
        }
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
}
