//! Fork-join on rayon's pool with the `rayon` feature, sequential without it.

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
