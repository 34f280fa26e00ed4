//! Deterministic sums over triangles, serial or on rayon's pool.
//!
//! Every evaluation sums per-triangle terms. To give the same bits whatever the number of
//! threads, the work is cut in pieces fixed by the input, never by the threads: the scan in
//! chunks of [`CHUNK`] triangles combined in a fixed pairwise tree ([`reduce`]), the hierarchy in
//! its own subtrees (see [`Hierarchy::reduce`](crate::mesh::hierarchy::Hierarchy::reduce)). [`join`]
//! runs the two halves of a piece on rayon's pool with the `rayon` feature, one after the other
//! without it; the order of the merges is the same either way.

/// Number of triangles summed sequentially before the pairwise combination.
pub(crate) const CHUNK: usize = 4096;

/// A running sum over triangles that can start from zero and be merged with another: what
/// [`reduce`] and the hierarchy's walk need.
pub(crate) trait Sums: Copy + Send {
    /// The sum over no triangle.
    fn zero() -> Self;
    /// The sum over the triangles of `self` and of `other`.
    fn merge(self, other: Self) -> Self;
}

/// Sums `add(&mut sums, i)` over `i in 0..len`, in chunks of [`CHUNK`] combined in a fixed
/// pairwise tree, on rayon's pool when `parallel` (and the `rayon` feature) is on.
pub(crate) fn reduce<S: Sums, F: Fn(&mut S, usize) + Sync>(
    len: usize,
    parallel: bool,
    add: &F,
) -> S {
    fn range<S: Sums, F: Fn(&mut S, usize) + Sync>(
        lo: usize,
        hi: usize,
        parallel: bool,
        add: &F,
    ) -> S {
        if hi - lo <= CHUNK {
            let mut sums = S::zero();
            for i in lo..hi {
                add(&mut sums, i);
            }
            return sums;
        }
        let mid = lo + (hi - lo).div_ceil(CHUNK) / 2 * CHUNK;
        let (left, right) = join(
            parallel,
            || range(lo, mid, parallel, add),
            || range(mid, hi, parallel, add),
        );
        left.merge(right)
    }
    range(0, len, parallel, add)
}

/// Runs `a` and `b`, on rayon's pool when `parallel` (potentially at the same time), and
/// returns both results.
#[cfg(feature = "rayon")]
#[inline]
pub(crate) fn join<A: Send, B: Send>(
    parallel: bool,
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    if parallel {
        rayon::join(a, b)
    } else {
        (a(), b())
    }
}

/// Runs `a`, then `b` (the `rayon` feature is off).
#[cfg(not(feature = "rayon"))]
#[inline]
pub(crate) fn join<A, B>(_parallel: bool, a: impl FnOnce() -> A, b: impl FnOnce() -> B) -> (A, B) {
    (a(), b())
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec::Vec;

    /// The order in which the terms were merged, written as a bracketed expression: the shape
    /// of the reduction tree.
    #[derive(Clone, Copy)]
    struct Shape {
        /// A hash of the merge tree: not commutative, not associative.
        tree: u64,
        /// The first and one past the last index summed.
        lo: usize,
        hi: usize,
    }

    impl Sums for Shape {
        fn zero() -> Self {
            Shape {
                tree: 0,
                lo: usize::MAX,
                hi: 0,
            }
        }
        fn merge(self, o: Self) -> Self {
            // Left and right must be adjacent ranges, left first.
            assert!(self.hi == o.lo || self.lo == usize::MAX || o.lo == usize::MAX);
            Shape {
                tree: self
                    .tree
                    .wrapping_mul(1_000_003)
                    .wrapping_add(o.tree)
                    .rotate_left(7)
                    ^ 0x9e37,
                lo: self.lo.min(o.lo),
                hi: self.hi.max(o.hi),
            }
        }
    }

    fn shape(len: usize, parallel: bool) -> Shape {
        reduce(len, parallel, &|s: &mut Shape, i| {
            if s.lo == usize::MAX {
                s.lo = i;
            }
            assert_eq!(s.hi.max(s.lo), i, "terms of a chunk are added in order");
            s.hi = i + 1;
            s.tree = s.tree.wrapping_mul(31).wrapping_add(i as u64 + 1);
        })
    }

    #[test]
    fn the_merge_tree_depends_on_the_length_only() {
        // The same tree, serial or parallel, and different trees for different lengths: the
        // summation order, which decides the rounding, is fixed by the input.
        let lengths = [0, 1, CHUNK - 1, CHUNK, CHUNK + 1, 3 * CHUNK, 5 * CHUNK + 7];
        let trees: Vec<u64> = lengths
            .iter()
            .map(|&len| {
                let serial = shape(len, false);
                #[cfg(feature = "rayon")]
                assert_eq!(serial.tree, shape(len, true).tree, "length {len}");
                if len > 0 {
                    assert_eq!((serial.lo, serial.hi), (0, len), "every index once");
                }
                serial.tree
            })
            .collect();
        for (i, a) in trees.iter().enumerate() {
            for b in &trees[i + 1..] {
                assert_ne!(a, b);
            }
        }
    }

    #[cfg(feature = "rayon")]
    #[test]
    fn floating_point_sums_are_bit_identical_serial_and_parallel() {
        // Terms of wildly different sizes, whose rounded sum depends on the order.
        let term =
            |i: usize| ((i as f64) * 0.618_033_988_749).fract() * 10f64.powi((i % 23) as i32 - 11);
        #[derive(Clone, Copy)]
        struct Sum(f64);
        impl Sums for Sum {
            fn zero() -> Self {
                Sum(0.0)
            }
            fn merge(self, o: Self) -> Self {
                Sum(self.0 + o.0)
            }
        }
        let len = 7 * CHUNK + 123;
        let serial = reduce(len, false, &|s: &mut Sum, i| s.0 += term(i));
        let parallel = reduce(len, true, &|s: &mut Sum, i| s.0 += term(i));
        assert_eq!(serial.0.to_bits(), parallel.0.to_bits());
        // A plain left-to-right sum rounds differently: the tree is not the naive order.
        let naive: f64 = (0..len).map(term).sum();
        assert_ne!(serial.0.to_bits(), naive.to_bits());
    }
}
