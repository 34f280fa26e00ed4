//! The volume methods, `Fast`, `Improved` and `Exact`: the submerged volume and its first
//! moment as sums of signed tetrahedra (divergence theorem).
//!
//! # Cost
//! `Fast` sums precomputed tetrahedra (centroid to triangle) over the fully submerged
//! triangles. `Exact` adds to the same sums the clipped waterline triangles and the cap: the
//! part of the water plane inside the body, as a fan of tetrahedra from `o` over the waterline
//! segments (and over mesh edges lying exactly in the plane, where a submerged triangle meets a
//! dry one). So `Exact` costs `Fast` plus work on the waterline triangles only. `Improved` is
//! `Exact` about `o` minus the clipped parts, i.e. the tetrahedra from `o` to the fully
//! submerged triangles. A body with only a sliver under water takes a second pass, which sums
//! the volume about the plane (see [`ExactSums`]). With the hierarchy, whole nodes under water add their stored sums (see
//! `hierarchy`), and the cost follows the waterline.

use nalgebra::Vector3;

use crate::mesh::hierarchy::Visit;
use crate::mesh::node_sums::VolumeNodeSums;
use crate::query::clip::{TriangleClass, WaterlineCut, classify, cut_at_waterline};
use crate::query::frame::Frame;
use crate::query::reduction::{Sums, reduce};
use crate::query::result::TriangleCounts;
use crate::{Buoyancy, Mesh, Method, Real, Water};

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
    /// Triangles found fully and partly under water, and twice their wetted area.
    pub counts: TriangleCounts<T>,
}

impl<T: Real> Sums for VolumeSums<T> {
    #[inline]
    fn zero() -> Self {
        VolumeSums {
            volume6: T::zero(),
            moment24: Vector3::zeros(),
            counts: TriangleCounts::default(),
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

impl<T: Real> VolumeSums<T> {
    /// Adds the tetrahedron `(o, a, b, c)`, positions relative to `o`.
    #[inline(always)]
    pub fn add_tetrahedron(&mut self, [a, b, c]: [Vector3<T>; 3]) {
        let det = a.dot(&b.cross(&c));
        self.volume6 += det;
        self.moment24 += (a + b + c) * det;
    }
}

/// `Exact`'s and `Improved`'s sums.
///
/// The first pass sums the volume and the moments about the centroid (`exact`: the
/// precomputed tetrahedra of the fully submerged triangles, the clipped parts of the cut ones
/// and the cap, a fan from `apex`, the projection of the centroid on the water plane) and, for
/// `Improved`, the clipped parts about `apex` (`clipped`). Those sums add terms of the size of
/// the body, so their round-off, about `ε·M³` (`M` the size of the body), is fixed whatever is
/// under water: it swamps the volume of a thin part (a corner or an edge dipping into the water,
/// a face lying in it), whose sign it can flip below about `ε` of the body's volume.
///
/// So when the first pass finds under `√ε·Σ|Vᵢ|` under water (`Σ|Vᵢ|` the mesh's volume
/// scale; a choice of cost, well above where the sign is lost), a second pass (`ROBUST`) sums
/// the volume about `apex`, where the cap contributes nothing: the fully submerged triangles as
/// `Σ detᵢ − apex·Σ 2Aᵢ` (`2Aᵢ = (bᵢ − aᵢ)×(cᵢ − aᵢ)`, from the precomputed `detᵢ` about the
/// centroid; a triangle lying within round-off of the surface adds nothing) and each cut
/// triangle's submerged part `P` as `(ab − apex)·2A_P`, with `ab` a waterline point of `P`: its
/// area times the distance from `apex` to its plane, a term of about `M·δ²` for a part of size
/// `δ`. The round-off is then about `ε·M²·δ`, and the volume keeps its sign for dips down to
/// about `√ε·M`; a volume left below zero by thinner dips is taken as zero.
///
/// The hierarchy adds the nodes whose vertices all lie below the surface, within round-off of
/// it included, where the scan's robust pass leaves out a triangle lying within round-off of the
/// surface: the two differ by round-off.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ExactSums<T: Real> {
    /// The submerged volume's sums about the centroid: fully submerged triangles, clipped
    /// waterline triangles and the cap.
    pub exact: VolumeSums<T>,
    /// `Σ detᵢ` over the fully submerged triangles not lying in the surface: the nodes' in both
    /// passes (they cost nothing), the scanned triangles' in the `ROBUST` pass only.
    pub submerged_volume6: T,
    /// `Σ 2Aᵢ` over the same triangles, likewise.
    pub submerged_area2: Vector3<T>,
    /// `ROBUST` only: `Σ (ab − apex)·2A_P` over the submerged parts of the cut triangles.
    pub cut_volume6: T,
    /// `Improved` only: the clipped parts of the waterline triangles, about `apex`.
    pub clipped: VolumeSums<T>,
}

impl<T: Real> ExactSums<T> {
    /// Six times the submerged volume, about `apex` (see the type's documentation).
    fn volume6(&self, apex: &Vector3<T>) -> T {
        self.submerged_volume6 - apex.dot(&self.submerged_area2) + self.cut_volume6
    }

    /// Six times the volume of the tetrahedra from `apex` to the fully submerged triangles:
    /// `Improved`'s volume.
    fn submerged_volume6_about(&self, apex: &Vector3<T>) -> T {
        self.submerged_volume6 - apex.dot(&self.submerged_area2)
    }
}

impl<T: Real> Sums for ExactSums<T> {
    #[inline]
    fn zero() -> Self {
        ExactSums {
            exact: VolumeSums::zero(),
            submerged_volume6: T::zero(),
            submerged_area2: Vector3::zeros(),
            cut_volume6: T::zero(),
            clipped: VolumeSums::zero(),
        }
    }
    #[inline]
    fn merge(self, o: Self) -> Self {
        ExactSums {
            exact: self.exact.merge(o.exact),
            submerged_volume6: self.submerged_volume6 + o.submerged_volume6,
            submerged_area2: self.submerged_area2 + o.submerged_area2,
            cut_volume6: self.cut_volume6 + o.cut_volume6,
            clipped: self.clipped.merge(o.clipped),
        }
    }
}

/// Sums a volume method accumulates, which take the hierarchy's stored sums of the nodes
/// entirely under water.
trait WithSubmergedNodes<T: Real>: Sums {
    fn add_submerged_node(&mut self, node: &VolumeNodeSums<T>, triangle_count: u32);
}

impl<T: Real> WithSubmergedNodes<T> for VolumeSums<T> {
    #[inline(always)]
    fn add_submerged_node(&mut self, node: &VolumeNodeSums<T>, triangle_count: u32) {
        self.volume6 += node.volume6;
        self.moment24 += node.moment24;
        self.counts.full += triangle_count as usize;
        self.counts.wetted_area2 += node.double_area;
    }
}

impl<T: Real> WithSubmergedNodes<T> for ExactSums<T> {
    #[inline(always)]
    fn add_submerged_node(&mut self, node: &VolumeNodeSums<T>, triangle_count: u32) {
        self.exact.add_submerged_node(node, triangle_count);
        self.submerged_volume6 += node.volume6;
        self.submerged_area2 += node.area2;
    }
}

impl<T: Real> Mesh<T> {
    /// `Fast`: the precomputed tetrahedra (centroid to triangle) of the fully submerged
    /// triangles; moments about the centroid.
    pub(crate) fn fast(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        hierarchy: bool,
        parallel: bool,
    ) -> Buoyancy<T> {
        let sums = self.volume_sums(frame, hierarchy, parallel, |s: &mut VolumeSums<T>, i| {
            self.fast_triangle(frame, s, i)
        });
        self.volume_result(frame, water, sums, Vector3::zeros())
    }

    /// `Exact` or `Improved`.
    ///
    /// Sums about the centroid: the fully submerged triangles contribute the precomputed
    /// tetrahedra of `Fast`, the waterline triangles their clipped part, and the cap closing the
    /// submerged volume on the water plane a fan of tetrahedra from `apex`, the projection of the
    /// centroid on the plane, over the waterline segments. Only the waterline costs more than
    /// `Fast`. When less than `√ε` of the mesh's volume scale is found under water, a second pass
    /// sums the volume about the plane, which keeps its sign (see [`ExactSums`]).
    pub(crate) fn exact_or_improved(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        method: Method,
        hierarchy: bool,
        parallel: bool,
    ) -> Buoyancy<T> {
        let apex = frame.normal_local * -frame.height;
        let improved = method == Method::Improved;
        let first = self.volume_sums(frame, hierarchy, parallel, |s: &mut ExactSums<T>, i| {
            self.exact_triangle::<false>(frame, &apex, improved, s, i)
        });
        let volume6 = if improved {
            first.exact.volume6 - first.clipped.volume6
        } else {
            first.exact.volume6
        };
        let thin = T::from_f64_lossy(6.0) * T::default_epsilon().sqrt() * self.volume_scale;
        let counts = first.exact.counts;
        let (sums, volume6) = if volume6.abs() > thin || counts.full + counts.partial == 0 {
            (first, volume6)
        } else {
            // A thin part under water: the volume about the plane (see `ExactSums`).
            let sums = self.volume_sums(frame, hierarchy, parallel, |s: &mut ExactSums<T>, i| {
                self.exact_triangle::<true>(frame, &apex, improved, s, i)
            });
            let volume6 = if improved {
                sums.submerged_volume6_about(&apex)
            } else {
                // The submerged volume of a closed mesh is never negative. For dips below about
                // √ε·M the round-off can still flip its sign (tests/contact.rs finds such
                // cases): what is left below zero is nothing measurable under water.
                sums.volume6(&apex).max(T::zero())
            };
            (sums, volume6)
        };
        let ExactSums { exact, clipped, .. } = sums;
        if !improved {
            let sums = VolumeSums { volume6, ..exact };
            return self.volume_result(frame, water, sums, Vector3::zeros());
        }
        // Improved = tetrahedra from `apex` over the fully submerged triangles. First moment
        // about apex: the exact volume's about `apex` minus the clipped parts',
        // Σ det·(a+b+c − 4·apex) = moment24 − 4·apex·volume6.
        let moment24 =
            exact.moment24 - apex * (T::from_f64_lossy(4.0) * exact.volume6) - clipped.moment24;
        let sums = VolumeSums {
            volume6,
            moment24,
            counts: exact.counts,
        };
        self.volume_result(frame, water, sums, apex)
    }

    /// Sums `triangle` over the triangles: over all of them (the scan, in parallel chunks when
    /// `parallel`), or over the leaves of the hierarchy the surface crosses, adding the stored
    /// sums of the nodes entirely under water.
    fn volume_sums<S: WithSubmergedNodes<T>>(
        &self,
        frame: &Frame<T>,
        hierarchy: bool,
        parallel: bool,
        triangle: impl Fn(&mut S, usize) + Sync,
    ) -> S {
        if !hierarchy {
            return reduce(self.triangles.len(), parallel, &triangle);
        }
        self.hierarchy.reduce(
            &frame.normal_local,
            frame.height,
            parallel,
            &|sums: &mut S, visit| match visit {
                Visit::SubmergedNode {
                    node,
                    triangle_count,
                } => sums.add_submerged_node(self.node_sums.volume(node), triangle_count),
                Visit::CrossedLeaf { triangles } => {
                    for i in triangles {
                        triangle(sums, i);
                    }
                }
            },
        )
    }

    /// `Fast`'s contribution of triangle `i`: its precomputed tetrahedron to the centroid, and
    /// its area, if it is fully under water.
    #[inline(always)]
    fn fast_triangle(&self, frame: &Frame<T>, s: &mut VolumeSums<T>, i: usize) {
        match classify(&frame.heights(&self.corners(i))) {
            TriangleClass::Submerged => {
                s.volume6 += self.tetra_volume6[i];
                s.moment24 += self.tetra_moment24[i];
                s.counts.full += 1;
                s.counts.wetted_area2 += self.double_areas[i];
            }
            TriangleClass::Cut => s.counts.partial += 1,
            TriangleClass::Dry => {}
        }
    }

    /// `Exact`'s contribution of triangle `i`, about the centroid, in `exact` (with its wetted
    /// area: all of it, or its share under water if the waterline cuts it); with `improved`, its
    /// clipped part about `apex` in `clipped` too.
    #[inline(always)]
    fn exact_triangle<const ROBUST: bool>(
        &self,
        frame: &Frame<T>,
        apex: &Vector3<T>,
        improved: bool,
        sums: &mut ExactSums<T>,
        i: usize,
    ) {
        let v = self.corners(i);
        let h = frame.heights(&v);
        let exact = &mut sums.exact;
        match classify(&h) {
            TriangleClass::Submerged => {
                exact.volume6 += self.tetra_volume6[i];
                exact.moment24 += self.tetra_moment24[i];
                exact.counts.full += 1;
                exact.counts.wetted_area2 += self.double_areas[i];
                let zero = T::zero();
                let r = frame.round_off;
                if ROBUST && (h[0] < -r || h[1] < -r || h[2] < -r) {
                    // About `apex` a triangle lying in the surface adds nothing.
                    sums.submerged_volume6 += self.tetra_volume6[i];
                    sums.submerged_area2 += (v[1] - v[0]).cross(&(v[2] - v[0]));
                }
                // An edge lying in the surface bounds the cap too, unless the neighbour across
                // it is submerged and cancels it.
                if h[0] == zero || h[1] == zero || h[2] == zero {
                    for k in 0..3 {
                        let j = (k + 1) % 3;
                        if h[k] == zero && h[j] == zero {
                            exact.add_tetrahedron([*apex, v[j], v[k]]);
                        }
                    }
                }
            }
            TriangleClass::Cut => {
                exact.counts.partial += 1;
                // The submerged part and its share of the cap from one small tetrahedron at the
                // odd vertex: with `x = ab × ca`, the part (a, ab, ca) and the cap's triangle
                // (apex, ca, ab) give `det = a·x − apex·x`. When `a` is the one vertex above,
                // the submerged part is the whole triangle (its precomputed tetrahedron) minus
                // (a, ab, ca), and the cap's triangle is reversed: the same terms, negated.
                let cut = cut_at_waterline(v, h);
                exact.counts.wetted_area2 += cut.wetted_share() * self.double_areas[i];
                let WaterlineCut {
                    odd_is_below,
                    a,
                    b,
                    c,
                    ab,
                    ca,
                    ..
                } = cut;
                // The submerged part's area vector, (a, ab, ca) or the quadrilateral
                // (ab, b, c, ca) from its diagonals, and its tetrahedron from `apex`.
                if ROBUST {
                    let area2 = if odd_is_below {
                        (ab - a).cross(&(ca - a))
                    } else {
                        (c - ab).cross(&(ca - b))
                    };
                    sums.cut_volume6 += (ab - apex).dot(&area2);
                }
                let x = ab.cross(&ca);
                let (part, cap) = (a.dot(&x), apex.dot(&x));
                let rim = ab + ca;
                let volume6 = part - cap;
                let moment24 = (a + rim) * part - (apex + rim) * cap;
                if odd_is_below {
                    exact.volume6 += volume6;
                    exact.moment24 += moment24;
                } else {
                    exact.volume6 += self.tetra_volume6[i] - volume6;
                    exact.moment24 += self.tetra_moment24[i] - moment24;
                }
                if improved {
                    let clipped = &mut sums.clipped;
                    // Improved leaves the submerged part out; remember it about `apex`:
                    // (a, ab, ca), or the whole triangle minus it.
                    let (a, b, c, ab, ca) = (a - apex, b - apex, c - apex, ab - apex, ca - apex);
                    let part = a.dot(&ab.cross(&ca));
                    let part_moment = (a + ab + ca) * part;
                    if odd_is_below {
                        clipped.volume6 += part;
                        clipped.moment24 += part_moment;
                    } else {
                        let whole = a.dot(&b.cross(&c));
                        clipped.volume6 += whole - part;
                        clipped.moment24 += (a + b + c) * whole - part_moment;
                    }
                }
            }
            TriangleClass::Dry => {}
        }
    }

    /// Builds the result of a volume method from sums about `origin` (mesh frame, relative to
    /// the centroid).
    ///
    /// With `M` the first moment about `origin`, `C − w = R(origin + M/V)` and
    /// `τ = (C − w) × ρgV n = ρg R(origin×n_l·V + M × n_l)`; `origin` is either 0 or along
    /// `n_l`, so `τ = ρg R(M × n_l)`, with no division by V.
    fn volume_result(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        sums: VolumeSums<T>,
        origin: Vector3<T>,
    ) -> Buoyancy<T> {
        let volume = sums.volume6 / T::from_f64_lossy(6.0);
        let moment = sums.moment24 / T::from_f64_lossy(24.0);
        let weight = water.specific_weight();
        let center_of_buoyancy = if volume.abs() > self.volume_tolerance() {
            frame.center_of_mass + frame.rotation * (origin + moment / volume)
        } else {
            frame.surface_point()
        };
        self.finish(
            frame,
            sums.counts,
            volume,
            center_of_buoyancy,
            frame.normal * (weight * volume),
            frame.rotation * moment.cross(&frame.normal_local) * weight,
        )
    }
}
