use nalgebra::RealField;

/// The scalar type of a computation: `f32` (what rapier uses) or `f64` (what Python uses).
///
/// Every type of this crate is generic over it; there is no mixed precision inside an
/// evaluation.
pub trait Real: RealField + Copy + Send + Sync + 'static {
    /// Converts an `f64` to this scalar type, rounding to the nearest `f32` for `f32`.
    fn from_f64_lossy(x: f64) -> Self;
    /// Converts to `f64` (exact for both implementors).
    fn to_f64(self) -> f64;
    /// Converts from `f32` (exact for both implementors).
    fn from_f32_exact(x: f32) -> Self;
}

impl Real for f32 {
    #[inline(always)]
    fn from_f64_lossy(x: f64) -> Self {
        x as f32
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        self as f64
    }
    #[inline(always)]
    fn from_f32_exact(x: f32) -> Self {
        x
    }
}

impl Real for f64 {
    #[inline(always)]
    fn from_f64_lossy(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline(always)]
    fn from_f32_exact(x: f32) -> Self {
        x as f64
    }
}
