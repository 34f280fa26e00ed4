//! The cosine of the wave phases, the hot loop of the Airy and spectral seas.
//!
//! `cos x` for `|x| ≤ 2¹⁸·π/2` (about 4.1·10⁵ rad): `x = q·π/2 + d` with `q` odd and
//! `|d| ≤ π/2`, `d` taken off in two parts of `π/2` (Cody and Waite: the first, of 33 bits,
//! times `q` is exact), then `cos x = ±sin d` from one odd polynomial. No call, no table, no
//! branch but the range check; beyond the range, [`libm::cos`]. The absolute error is below
//! `3·10⁻¹⁶` (tested against `libm::cos` at 200,000 points across the range and beside the
//! multiples of `π/2`). A phase of `4·10⁵` rad is a wave of 10 m seen 650 km from the origin,
//! or one of period 8 s after 6 days.

/// Largest `|x|` reduced here: `q` stays below `2²⁰`, so `q·PIO2_HI` is exact.
const LIMIT: f64 = 411_774.8;
/// `1.5·2⁵²`: adding and subtracting it rounds a number below `2⁵¹` to the nearest integer.
const ROUND: f64 = 6_755_399_441_055_744.0;
const FRAC_1_PI: f64 = core::f64::consts::FRAC_1_PI;
/// The first 33 bits of `π/2`, and the rest.
const PIO2_HI: f64 = 1.570_796_326_734_125_6;
const PIO2_LO: f64 = 6.077_100_506_506_192e-11;

/// `sin d = d + d·s·u(s)`, `s = d²`, `|d| ≤ π/2`: the coefficients of `u`, highest first
/// (minimax, as in SLEEF's `sin`).
const SIN: [f64; 9] = [
    -7.972_559_550_090_379e-18,
    2.810_099_727_108_632e-15,
    -7.647_122_191_181_588e-13,
    1.605_904_306_056_645e-10,
    -2.505_210_837_635_020_5e-8,
    2.755_731_922_391_987_5e-6,
    -1.984_126_984_126_961_6e-4,
    8.333_333_333_333_33e-3,
    -1.666_666_666_666_666_6e-1,
];

/// `cos x` (see the module documentation).
#[inline(always)]
pub(crate) fn cos(x: f64) -> f64 {
    // Written so that NaN and infinities take the call too.
    if x.abs() <= LIMIT {
        cos_in_range(x)
    } else {
        libm::cos(x)
    }
}

/// Whether every `|x| ≤ bound` is in the range of [`cos_in_range`].
#[inline]
pub(crate) fn in_range(bound: f64) -> bool {
    bound <= LIMIT
}

/// `cos x` for `|x| ≤ 2¹⁸·π/2` (anything, not a panic, outside): straight-line code, so that a
/// loop of it over an array vectorises. `x = q·π/2 + d` with `q = 2m + 1` odd, `m` the
/// nearest integer to `x/π − ½` (read, with its parity, from `x/π − ½ + 1.5·2⁵²`, whose unit in
/// the last place is 1), and `|d| ≤ π/2`; then `cos x = ∓sin d`, the sign from the parity of
/// `m`, and `sin d` from one odd polynomial of degree 17.
#[inline(always)]
pub(crate) fn cos_in_range(x: f64) -> f64 {
    let shifted = x * FRAC_1_PI - 0.5 + ROUND;
    let m = shifted - ROUND;
    let q = m + m + 1.0;
    // `q·PIO2_HI` is exact (`q < 2²⁰`, 33 bits), and so is its difference with `x` but for
    // `q = ±1` (Sterbenz), where it is within half an ulp of `π/2`.
    let d = (x - q * PIO2_HI) - q * PIO2_LO;
    let s = d * d;
    let mut u = SIN[0];
    for c in &SIN[1..] {
        u = u * s + c;
    }
    let sin = d + d * s * u;
    // m even: −sin d; m odd: +sin d.
    let sign = ((shifted.to_bits() & 1) ^ 1) << 63;
    f64::from_bits(sin.to_bits() ^ sign)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_libm_across_the_range() {
        // A deterministic spread over the range, and the neighbourhoods of multiples of π/2
        // where the reduction cancels most.
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut worst: f64 = 0.0;
        for k in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let unit = (state >> 11) as f64 / (1u64 << 53) as f64;
            let x = match k % 3 {
                0 => (2.0 * unit - 1.0) * LIMIT,
                1 => (2.0 * unit - 1.0) * 20.0,
                _ => {
                    let m = ((state >> 40) % 500_000) as f64;
                    m * core::f64::consts::FRAC_PI_2 + (unit - 0.5) * 1e-9
                }
            };
            worst = worst.max((cos(x) - libm::cos(x)).abs());
        }
        assert!(worst < 3e-16, "{worst:e}");
    }

    #[test]
    fn takes_the_call_outside_the_range() {
        for x in [LIMIT * 1.01, -1e12, 1e300] {
            assert_eq!(cos(x), libm::cos(x));
        }
        assert!(cos(f64::NAN).is_nan());
        assert!(cos(f64::INFINITY).is_nan());
        assert_eq!(cos(0.0), 1.0);
    }
}
