//! The cosine of the wave phases, the hot loop of the Airy and spectral seas.
//!
//! `cos x` for `|x| ≤ 2¹⁹·π/2` (about 8.2·10⁵ rad): `x = m·π/2 + r` with `m` the nearest
//! integer to `2x/π` and `|r| ≤ π/4`, `r` taken off in two parts of `π/2` (Cody and Waite:
//! the first, of 33 bits, times `m` is exact), then the sine or cosine of `r` from fdlibm's
//! kernel polynomials, chosen and signed by `m mod 4`. No call, no table, no branch but the
//! range check; beyond the range, [`libm::cos`]. The absolute error is below `2·10⁻¹⁶`
//! (tested against `libm::cos`). A phase of `8·10⁵` rad is a wave of 10 m seen 1,300 km from
//! the origin, or one of period 8 s after 12 days.

/// Largest `|x|` reduced here: `m` stays below `2²⁰`, so `m·PIO2_HI` is exact.
const LIMIT: f64 = 823_549.6;
/// `1.5·2⁵²`: adding and subtracting it rounds a number below `2⁵¹` to the nearest integer.
const ROUND: f64 = 6_755_399_441_055_744.0;
const TWO_OVER_PI: f64 = core::f64::consts::FRAC_2_PI;
/// The first 33 bits of `π/2`, and the rest.
const PIO2_HI: f64 = 1.570_796_326_734_125_6;
const PIO2_LO: f64 = 6.077_100_506_506_192e-11;

const S1: f64 = -0.166_666_666_666_666_32;
const S2: f64 = 0.008_333_333_333_322_49;
const S3: f64 = -0.000_198_412_698_298_579_5;
const S4: f64 = 2.755_731_370_707_006_8e-6;
const S5: f64 = -2.505_076_025_340_686_3e-8;
const S6: f64 = 1.589_690_995_211_55e-10;

const C1: f64 = 0.041_666_666_666_666_6;
const C2: f64 = -0.001_388_888_888_887_411;
const C3: f64 = 2.480_158_728_947_673e-5;
const C4: f64 = -2.755_731_435_139_066_3e-7;
const C5: f64 = 2.087_572_321_298_175e-9;
const C6: f64 = -1.135_964_755_778_819_5e-11;

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

/// `cos x` for `|x| ≤ 2¹⁹·π/2` (anything, not a panic, outside): straight-line code, so that a
/// loop of it over an array vectorises. The quadrant `m mod 4` is read from the low bits of
/// `2x/π + 1.5·2⁵²` (whose unit in the last place is 1), and the sine or cosine kernel chosen
/// and signed with bit masks.
#[inline(always)]
pub(crate) fn cos_in_range(x: f64) -> f64 {
    let shifted = x * TWO_OVER_PI + ROUND;
    let m = shifted - ROUND;
    let quadrant = shifted.to_bits();
    let r = (x - m * PIO2_HI) - m * PIO2_LO;
    let z = r * r;
    let sin = r + r * z * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))));
    let half = 0.5 * z;
    let w = 1.0 - half;
    let cos = w
        + (((1.0 - w) - half) + z * z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6))))));
    // Quadrant 0: cos r; 1: −sin r; 2: −cos r; 3: sin r.
    let odd = (quadrant & 1).wrapping_neg();
    let sign = (quadrant.wrapping_add(1) & 2) << 62;
    f64::from_bits(((cos.to_bits() & !odd) | (sin.to_bits() & odd)) ^ sign)
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
        assert!(worst < 2e-16, "{worst:e}");
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
