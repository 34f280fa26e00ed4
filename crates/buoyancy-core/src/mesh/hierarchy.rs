//! A bounding-volume hierarchy over a mesh's triangles, so that a query opens only the nodes
//! the water plane crosses.
//!
//! # What a node stores
//! For the triangles under a node, in the mesh frame relative to the mesh centroid, the
//! axis-aligned box of their vertices, corners `lo` and `hi`, in `f32` rounded outward (so the
//! stored box holds the exact one whatever `T` is, in 24 bytes), with the triangle count and a
//! link: 32 bytes, two nodes to a cache line, all the walk reads. What a node entirely under
//! water adds for each method lives beside the nodes, indexed by node (see `node_sums`).
//!
//! # The walk
//! With `n` the up normal and `h_c` the centroid's height (both in the mesh frame), the heights
//! of the points of a node's box lie in `[Σₖ min(nₖloₖ, nₖhiₖ) + h_c, Σₖ max(nₖloₖ, nₖhiₖ) + h_c]`.
//! Computed in `T`, either end is within `4ε·(M + |h_c|)` of its exact value, and so is every
//! vertex height the scan computes, with `M = Σₖ max(|loₖ|, |hiₖ|)` over the root's box (a bound
//! for every node): [`Hierarchy::height_round_off`]. A node whose interval lies below zero by
//! more than the margin `8ε·(M + |h_c|)` has every triangle fully submerged, with no vertex in
//! the surface, and contributes its stored sums; one above zero by the margin contributes
//! nothing; any other is
//! opened, down to the leaves, whose triangles go through the same per-triangle code as the scan.
//! The classification of every triangle is therefore the scan's own, and the result equals the
//! scan's up to the order of summation. The cost follows the number of nodes the plane crosses,
//! about the waterline triangles times the depth.

use alloc::vec::Vec;

use nalgebra::Vector3;

use crate::Real;
use crate::query::reduction::{Sums, join};

/// Most triangles in a leaf: a node with more triangles is an inner node.
const LEAF_SIZE: u32 = 8;

/// Depth down to which [`Hierarchy::reduce`] sums the subtrees apart (at most 16 of them).
const SPLIT_DEPTH: u32 = 4;

/// Fewest triangles under a node for [`Hierarchy::reduce`] to sum its halves in parallel.
const PARALLEL_TRIANGLES: u32 = 100_000;

/// A node of the hierarchy (see the module documentation): what the walk reads.
#[derive(Debug, Clone, Copy)]
#[repr(C, align(32))]
pub(crate) struct Node {
    /// `[lo.x, lo.y, lo.z, hi.x, hi.y, hi.z]`, the box of the node's vertices rounded outward.
    pub bounds: [f32; 6],
    /// Number of triangles under the node; at most [`LEAF_SIZE`] for a leaf.
    pub count: u32,
    /// Leaf: the position of its first triangle in leaf order. Inner node: the index of its right
    /// child (the left child follows the node directly).
    pub link: u32,
}

impl Node {
    #[inline(always)]
    fn is_leaf(&self) -> bool {
        self.count <= LEAF_SIZE
    }
}

/// The hierarchy: nodes in depth-first order, root first. The triangles are numbered in leaf
/// order (see [`Hierarchy::build`]), so a leaf's triangles are a range.
#[derive(Debug, Clone)]
pub(crate) struct Hierarchy<T: Real> {
    pub nodes: Vec<Node>,
    /// `Σₖ max(|loₖ|, |hiₖ|)` of the root's box: bounds the size of the numbers in every node
    /// test and vertex height, for the round-off margin.
    magnitude: T,
}

/// What the walk found: a node entirely under water, or a leaf's triangles to examine one by one.
pub(crate) enum Visit {
    /// A node (inner or leaf) entirely under water, with every one of its triangles.
    SubmergedNode {
        /// The node's index.
        node: usize,
        /// Its number of triangles.
        triangle_count: u32,
    },
    /// A leaf the surface may cross: its triangles, in leaf order, each to be classified.
    CrossedLeaf {
        /// The leaf's triangles.
        triangles: core::ops::Range<usize>,
    },
}

/// Where a node's box lies against the water plane, round-off margin included.
enum NodeClass {
    /// Every point below the surface.
    Submerged,
    /// Every point above it.
    Dry,
    /// The surface may cross the box.
    Straddling,
}

/// One evaluation's water plane in the form the node test wants (see the module documentation),
/// thickened by `reach` on either side: a node is submerged when all of it lies more than
/// `reach` below the plane, dry when more than `reach` above it.
struct PlaneTest<T: Real> {
    normal: [T; 3],
    height: T,
    margin: T,
    reach: T,
    /// Per axis, the index in `Node::bounds` of the box's lower (`near`) and upper (`far`) end
    /// along the normal.
    near: [usize; 3],
    far: [usize; 3],
}

impl<T: Real> PlaneTest<T> {
    fn new(hierarchy: &Hierarchy<T>, normal: &Vector3<T>, height: T, reach: T) -> Self {
        let normal = [normal.x, normal.y, normal.z];
        let near: [usize; 3] =
            core::array::from_fn(|k| if normal[k] >= T::zero() { k } else { k + 3 });
        PlaneTest {
            normal,
            height,
            margin: hierarchy.height_round_off(height) * T::from_f64_lossy(2.0),
            reach,
            near,
            far: near.map(|k| (k + 3) % 6),
        }
    }

    #[inline(always)]
    fn classify(&self, node: &Node) -> NodeClass {
        let (n, b) = (&self.normal, &node.bounds);
        let at = |corner: &[usize; 3]| {
            n[0] * T::from_f32_exact(b[corner[0]])
                + n[1] * T::from_f32_exact(b[corner[1]])
                + n[2] * T::from_f32_exact(b[corner[2]])
                + self.height
        };
        if at(&self.far) + self.margin < -self.reach {
            NodeClass::Submerged
        } else if at(&self.near) - self.margin > self.reach {
            NodeClass::Dry
        } else {
            NodeClass::Straddling
        }
    }
}

impl<T: Real> Hierarchy<T> {
    /// Builds the hierarchy by median splits along the longest axis of the triangle centroids,
    /// and returns it with the leaf order: the triangles (indices into `triangles`) listed leaf
    /// by leaf. The hierarchy numbers triangles by their position in that order.
    ///
    /// `vertices` are the stored vertices (relative to the centroid). What the nodes carry for
    /// the methods is built afterwards, in the leaf order (see `node_sums`).
    pub fn build(vertices: &[Vector3<T>], triangles: &[[u32; 3]]) -> (Self, Vec<u32>) {
        let mut order: Vec<u32> = (0..triangles.len() as u32).collect();
        let centers: Vec<Vector3<f64>> = triangles
            .iter()
            .map(|t| {
                t.iter()
                    .map(|&k| vertices[k as usize].map(T::to_f64))
                    .sum::<Vector3<f64>>()
                    / 3.0
            })
            .collect();
        let capacity = 2 * triangles.len() / LEAF_SIZE as usize + 1;
        let mut hierarchy = Hierarchy {
            nodes: Vec::with_capacity(capacity),
            magnitude: T::zero(),
        };
        let builder = Builder {
            vertices,
            triangles,
            centers: &centers,
        };
        builder.node(&mut hierarchy, &mut order, 0);
        let b = &hierarchy.nodes[0].bounds;
        let magnitude: f64 = (0..3)
            .map(|k| f64::from(b[k].abs().max(b[k + 3].abs())))
            .sum();
        hierarchy.magnitude = T::from_f64_lossy(magnitude);
        (hierarchy, order)
    }

    /// Sums `visit` over every node entirely under water and every leaf the surface may cross,
    /// given the up normal `normal` and the centroid's height `height`, both in the mesh frame.
    ///
    /// The sum has a fixed shape, whatever `parallel` is: the subtrees the surface crosses down
    /// to depth [`SPLIT_DEPTH`] are summed apart, each from `S::zero()`, and merged pairwise up
    /// the tree; with `parallel` (and the `rayon` feature), the two halves of a node of at least
    /// [`PARALLEL_TRIANGLES`] triangles are summed on rayon's pool. So the result does not
    /// depend on the threads. No allocation: below the split, the pending nodes are kept on a
    /// fixed stack (the depth is at most log₂ of the triangle count, below 64).
    #[inline]
    pub fn reduce<S: Sums>(
        &self,
        normal: &Vector3<T>,
        height: T,
        parallel: bool,
        visit: &(impl Fn(&mut S, Visit) + Sync),
    ) -> S {
        self.reduce_in_layer(normal, height, T::zero(), parallel, visit)
    }

    /// [`Hierarchy::reduce`] for a surface anywhere within `reach` of the plane: a node is taken
    /// as submerged when every point of it lies more than `reach` below the plane (up to the
    /// same round-off margin), skipped when more than `reach` above it, and opened otherwise.
    #[inline]
    pub fn reduce_in_layer<S: Sums>(
        &self,
        normal: &Vector3<T>,
        height: T,
        reach: T,
        parallel: bool,
        visit: &(impl Fn(&mut S, Visit) + Sync),
    ) -> S {
        let plane = PlaneTest::new(self, normal, height, reach);
        self.reduce_subtree(&plane, 0, 0, parallel, visit)
    }

    fn reduce_subtree<S: Sums>(
        &self,
        plane: &PlaneTest<T>,
        index: u32,
        depth: u32,
        parallel: bool,
        visit: &(impl Fn(&mut S, Visit) + Sync),
    ) -> S {
        let node = &self.nodes[index as usize];
        if depth == SPLIT_DEPTH || node.is_leaf() {
            let mut sums = S::zero();
            self.walk_from(plane, index, |v| visit(&mut sums, v));
            return sums;
        }
        match plane.classify(node) {
            NodeClass::Submerged => {
                let mut sums = S::zero();
                visit(
                    &mut sums,
                    Visit::SubmergedNode {
                        node: index as usize,
                        triangle_count: node.count,
                    },
                );
                sums
            }
            NodeClass::Dry => S::zero(),
            NodeClass::Straddling => {
                let (left, right) = join(
                    parallel && node.count >= PARALLEL_TRIANGLES,
                    || self.reduce_subtree(plane, index + 1, depth + 1, parallel, visit),
                    || self.reduce_subtree(plane, node.link, depth + 1, parallel, visit),
                );
                left.merge(right)
            }
        }
    }

    /// Calls `visit` for every node entirely under water and every leaf the surface may cross,
    /// one after the other (depth first, left before right).
    #[inline]
    pub fn walk(&self, normal: &Vector3<T>, height: T, visit: impl FnMut(Visit)) {
        self.walk_from(&PlaneTest::new(self, normal, height, T::zero()), 0, visit);
    }

    /// [`Hierarchy::walk`] of the subtree at `root`.
    #[inline]
    fn walk_from(&self, plane: &PlaneTest<T>, root: u32, mut visit: impl FnMut(Visit)) {
        let mut stack = [0u32; 64];
        stack[0] = root;
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let index = stack[top];
            let node = &self.nodes[index as usize];
            match plane.classify(node) {
                NodeClass::Submerged => visit(Visit::SubmergedNode {
                    node: index as usize,
                    triangle_count: node.count,
                }),
                NodeClass::Dry => {}
                NodeClass::Straddling if node.is_leaf() => {
                    let first = node.link as usize;
                    visit(Visit::CrossedLeaf {
                        triangles: first..first + node.count as usize,
                    });
                }
                NodeClass::Straddling => {
                    // Right child below the left one (the node after this), which goes first.
                    stack[top] = node.link;
                    stack[top + 1] = index + 1;
                    top += 2;
                }
            }
        }
    }

    /// The children of node `index`, `None` for a leaf.
    pub fn children(&self, index: usize) -> Option<(usize, usize)> {
        let node = &self.nodes[index];
        (!node.is_leaf()).then(|| (index + 1, node.link as usize))
    }

    /// The triangles (in leaf order) under node `index`: its leaves' ranges, which are adjacent
    /// (a leaf's own range for a leaf).
    pub fn range(&self, index: usize) -> core::ops::Range<usize> {
        let mut first = index;
        while let Some((left, _)) = self.children(first) {
            first = left;
        }
        let start = self.nodes[first].link as usize;
        start..start + self.nodes[index].count as usize
    }

    /// `4ε·(M + |h_c|)`: a bound on the round-off of every vertex height and node bound computed
    /// for a centroid at `height` above the surface (see the module documentation).
    #[inline]
    pub fn height_round_off(&self, height: T) -> T {
        T::default_epsilon() * T::from_f64_lossy(4.0) * (self.magnitude + height.abs())
    }

    /// Bytes of memory the hierarchy uses.
    pub fn memory(&self) -> usize {
        self.nodes.len() * core::mem::size_of::<Node>()
    }
}

/// `x` rounded to an `f32` no greater (`down`) or no less than it.
fn to_f32_outward(x: f64, down: bool) -> f32 {
    let y = x as f32;
    match (down, f64::from(y).partial_cmp(&x)) {
        (true, Some(core::cmp::Ordering::Greater)) => y.next_down(),
        (false, Some(core::cmp::Ordering::Less)) => y.next_up(),
        _ => y,
    }
}

struct Builder<'a, T: Real> {
    vertices: &'a [Vector3<T>],
    triangles: &'a [[u32; 3]],
    centers: &'a [Vector3<f64>],
}

impl<T: Real> Builder<'_, T> {
    /// Appends the node of the triangles `order` (which start at slot `first`) and its subtree.
    fn node(&self, hierarchy: &mut Hierarchy<T>, order: &mut [u32], first: usize) {
        let mut lo = self.vertices[self.triangles[order[0] as usize][0] as usize].map(T::to_f64);
        let mut hi = lo;
        for &i in order.iter() {
            for &k in &self.triangles[i as usize] {
                let v = self.vertices[k as usize].map(T::to_f64);
                lo = lo.inf(&v);
                hi = hi.sup(&v);
            }
        }
        let index = hierarchy.nodes.len();
        let bounds = [lo.x, lo.y, lo.z, hi.x, hi.y, hi.z];
        hierarchy.nodes.push(Node {
            bounds: core::array::from_fn(|k| to_f32_outward(bounds[k], k < 3)),
            count: order.len() as u32,
            link: first as u32,
        });
        if hierarchy.nodes[index].is_leaf() {
            return;
        }
        let (c_lo, c_hi) = order.iter().fold(
            (
                Vector3::repeat(f64::INFINITY),
                Vector3::repeat(f64::NEG_INFINITY),
            ),
            |(l, h), &i| {
                (
                    l.inf(&self.centers[i as usize]),
                    h.sup(&self.centers[i as usize]),
                )
            },
        );
        let axis = (c_hi - c_lo).imax();
        let mid = order.len() / 2;
        order.select_nth_unstable_by(mid, |&a, &b| {
            self.centers[a as usize][axis].total_cmp(&self.centers[b as usize][axis])
        });
        let (left, right) = order.split_at_mut(mid);
        self.node(hierarchy, left, first);
        hierarchy.nodes[index].link = hierarchy.nodes.len() as u32;
        self.node(hierarchy, right, first + mid);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boxes_round_outward() {
        for x in [
            0.1,
            -0.1,
            1.0 / 3.0,
            -2.0 / 3.0,
            1e-30,
            12_345.678_9,
            0.5,
            0.0,
        ] {
            let (down, up) = (to_f32_outward(x, true), to_f32_outward(x, false));
            assert!(f64::from(down) <= x && x <= f64::from(up), "{x}");
            assert!(up == down || up == down.next_up(), "{x}: {down} {up}");
        }
    }
}
