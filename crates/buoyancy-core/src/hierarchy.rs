//! A bounding-volume hierarchy over a mesh's triangles whose nodes carry their triangles'
//! summed volume elements, so that a query opens only the nodes the water plane crosses.
//!
//! # What a node stores
//! For the triangles `i` under a node, in the mesh frame relative to the mesh centroid `c`:
//!
//! * the axis-aligned box of their vertices, as center `m` and half extents `e`;
//! * `Σ detᵢ` and `Σ detᵢ·(aᵢ + bᵢ + cᵢ)`, `detᵢ = aᵢ·(bᵢ×cᵢ)`: six times the volume and
//!   twenty-four times the first moment about `c` of the tetrahedra from `c` to the triangles,
//!   the sums the `Fast` method adds over the fully submerged triangles.
//!
//! Sums are accumulated in `f64` at build time and taken about the centroid, so that a mesh far
//! from its own origin does not lose digits.
//!
//! The surface methods' coefficients of the inner nodes live beside the nodes, in
//! [`crate::surface_moments::NodeMoments`], indexed by node.
//!
//! # Query
//! With `n` the up normal and `h_c` the centroid's height (both in the mesh frame), the heights
//! of the points of a node's box lie in `n·m + h_c ± |n|·e` (`|n|` taken component-wise). A node
//! whose interval lies below zero by more than the round-off margin has every triangle fully
//! submerged, with no vertex in the surface, and contributes its stored sums; one above zero
//! contributes nothing; any other is opened, down to the leaves, whose triangles go through the
//! same per-triangle code as the scan. The classification of every triangle is therefore the
//! scan's own, and the result equals the scan's up to the order of summation. The cost follows
//! the number of nodes the plane crosses, about the waterline triangles times the depth.

use alloc::vec::Vec;

use nalgebra::Vector3;

use crate::Real;

/// Most triangles in a leaf.
const LEAF_SIZE: usize = 4;

/// A node of the hierarchy (see the module documentation).
#[derive(Debug, Clone)]
pub(crate) struct Node<T: Real> {
    /// Center and half extents of the box of the node's vertices.
    pub center: Vector3<T>,
    pub half: Vector3<T>,
    /// `Σₖ |centerₖ| + halfₖ`: the size of the numbers in the node test, for its round-off margin.
    pub magnitude: T,
    pub volume6: T,
    pub moment24: Vector3<T>,
    /// Number of triangles under the node.
    pub count: u32,
    /// Leaf: the position of its first triangle in leaf order. Inner node: the index of its right
    /// child (the left child follows the node directly).
    pub link: u32,
    pub leaf: bool,
}

/// The hierarchy: nodes in depth-first order, root first. The triangles are numbered in leaf
/// order (see [`Hierarchy::build`]), so a leaf's triangles are a range.
#[derive(Debug, Clone)]
pub(crate) struct Hierarchy<T: Real> {
    pub nodes: Vec<Node<T>>,
}

/// What the walk found: a node entirely under water, or a leaf's triangles to examine one by one.
pub(crate) enum Visit<'a, T: Real> {
    /// The node at this index, entirely under water.
    Submerged(usize, &'a Node<T>),
    Triangles(core::ops::Range<usize>),
}

impl<T: Real> Hierarchy<T> {
    /// Builds the hierarchy by median splits along the longest axis of the triangle centroids,
    /// and returns it with the leaf order: the triangles (indices into `triangles`) listed leaf
    /// by leaf. The hierarchy numbers triangles by their position in that order.
    ///
    /// `vertices` are the stored vertices (relative to the centroid); `volume6` and `moment24`
    /// the per-triangle sums, in `f64`.
    pub fn build(
        vertices: &[Vector3<T>],
        triangles: &[[u32; 3]],
        volume6: &[f64],
        moment24: &[Vector3<f64>],
    ) -> (Self, Vec<u32>) {
        let mut order: Vec<u32> = (0..triangles.len() as u32).collect();
        let centers: Vec<Vector3<f64>> = triangles
            .iter()
            .map(|t| t.iter().map(|&k| vertices[k as usize].map(T::to_f64)).sum::<Vector3<f64>>() / 3.0)
            .collect();
        let mut nodes = Vec::with_capacity(2 * triangles.len() / LEAF_SIZE + 1);
        let builder = Builder { vertices, triangles, volume6, moment24, centers: &centers };
        builder.node(&mut nodes, &mut order, 0);
        (Hierarchy { nodes }, order)
    }

    /// Calls `visit` for every node entirely under water and every leaf the surface may cross,
    /// given the up normal `normal` and the centroid's height `height`, both in the mesh frame.
    /// No allocation: the pending nodes are kept on a fixed stack (the depth is at most
    /// log₂ of the triangle count, below 64).
    #[inline]
    pub fn walk(&self, normal: &Vector3<T>, height: T, mut visit: impl FnMut(Visit<'_, T>)) {
        let eight_eps = T::default_epsilon() * T::lit(8.0);
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let index = stack[top];
            let node = &self.nodes[index as usize];
            let middle = normal.dot(&node.center) + height;
            let radius = normal.abs().dot(&node.half);
            let margin = eight_eps * (node.magnitude + height.abs());
            let (low, high) = (middle - radius, middle + radius);
            if high + margin < T::zero() {
                visit(Visit::Submerged(index as usize, node));
            } else if low - margin > T::zero() {
                // Dry.
            } else if node.leaf {
                let first = node.link as usize;
                visit(Visit::Triangles(first..first + node.count as usize));
            } else {
                // Right child below the left one (the node after this), which goes first.
                stack[top] = node.link;
                stack[top + 1] = index + 1;
                top += 2;
            }
        }
    }

    /// The children of node `index`, `None` for a leaf.
    pub fn children(&self, index: usize) -> Option<(usize, usize)> {
        let node = &self.nodes[index];
        (!node.leaf).then(|| (index + 1, node.link as usize))
    }

    /// The triangles (in leaf order) of leaf `index`.
    pub fn triangles(&self, index: usize) -> core::ops::Range<usize> {
        let node = &self.nodes[index];
        debug_assert!(node.leaf);
        node.link as usize..(node.link + node.count) as usize
    }

    /// Bytes of memory the hierarchy uses.
    pub fn memory(&self) -> usize {
        self.nodes.len() * core::mem::size_of::<Node<T>>()
    }
}

struct Builder<'a, T: Real> {
    vertices: &'a [Vector3<T>],
    triangles: &'a [[u32; 3]],
    volume6: &'a [f64],
    moment24: &'a [Vector3<f64>],
    centers: &'a [Vector3<f64>],
}

impl<T: Real> Builder<'_, T> {
    /// Appends the node of the triangles `order` (which start at slot `first`) and its subtree.
    fn node(&self, nodes: &mut Vec<Node<T>>, order: &mut [u32], first: usize) {
        let mut lo = self.vertices[self.triangles[order[0] as usize][0] as usize];
        let mut hi = lo;
        let (mut volume6, mut moment24) = (0.0, Vector3::zeros());
        for &i in order.iter() {
            for &k in &self.triangles[i as usize] {
                let v = &self.vertices[k as usize];
                lo = lo.inf(v);
                hi = hi.sup(v);
            }
            volume6 += self.volume6[i as usize];
            moment24 += self.moment24[i as usize];
        }
        let index = nodes.len();
        // Computed in f64 and widened by the round-off margin of the walk; the margin also
        // covers rounding these to `T`.
        let (lo, hi) = (lo.map(T::to_f64), hi.map(T::to_f64));
        let (center, half) = ((lo + hi) / 2.0, (hi - lo) / 2.0);
        nodes.push(Node {
            center: center.map(T::lit),
            half: half.map(T::lit),
            magnitude: T::lit(center.abs().sum() + half.sum()),
            volume6: T::lit(volume6),
            moment24: moment24.map(T::lit),
            count: order.len() as u32,
            link: first as u32,
            leaf: order.len() <= LEAF_SIZE,
        });
        if order.len() <= LEAF_SIZE {
            return;
        }
        let (c_lo, c_hi) = order.iter().fold(
            (Vector3::repeat(f64::INFINITY), Vector3::repeat(f64::NEG_INFINITY)),
            |(l, h), &i| (l.inf(&self.centers[i as usize]), h.sup(&self.centers[i as usize])),
        );
        let axis = (c_hi - c_lo).imax();
        let mid = order.len() / 2;
        order.select_nth_unstable_by(mid, |&a, &b| {
            self.centers[a as usize][axis].total_cmp(&self.centers[b as usize][axis])
        });
        let (left, right) = order.split_at_mut(mid);
        self.node(nodes, left, first);
        nodes[index].link = nodes.len() as u32;
        self.node(nodes, right, first + mid);
    }
}
