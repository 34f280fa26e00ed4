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
    cos_in_range_with::<false>(x)
}

/// [`cos_in_range`], its multiply-adds fused when `FUSED` (one rounding each: as accurate or
/// more; only worth it where the CPU has FMA, see [`add_cosines`]).
#[inline(always)]
fn cos_in_range_with<const FUSED: bool>(x: f64) -> f64 {
    let shifted = madd::<FUSED>(x, FRAC_1_PI, -0.5) + ROUND;
    let m = shifted - ROUND;
    let q = m + m + 1.0;
    // `q·PIO2_HI` is exact (`q < 2²⁰`, 33 bits), and so is its difference with `x` but for
    // `q = ±1` (Sterbenz), where it is within half an ulp of `π/2`.
    let d = madd::<FUSED>(-q, PIO2_LO, madd::<FUSED>(-q, PIO2_HI, x));
    let s = d * d;
    let mut u = SIN[0];
    for c in &SIN[1..] {
        u = madd::<FUSED>(u, s, *c);
    }
    let sin = madd::<FUSED>(d * s, u, d);
    // m even: −sin d; m odd: +sin d.
    let sign = ((shifted.to_bits() & 1) ^ 1) << 63;
    f64::from_bits(sin.to_bits() ^ sign)
}

/// `a·b + c`: rounded once when `FUSED` (only ever set with `std`, where `f64::mul_add` is),
/// twice otherwise.
#[inline(always)]
fn madd<const FUSED: bool>(a: f64, b: f64, c: f64) -> f64 {
    #[cfg(feature = "std")]
    if FUSED {
        return a.mul_add(b, c);
    }
    a * b + c
}

/// One term `amplitude·cos(k·p + offset)` of a sum of cosines over points `p`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CosineTerm {
    /// The wave vector (rad/m).
    pub k: [f64; 3],
    /// The phase at the origin (rad).
    pub offset: f64,
    /// The amplitude (m).
    pub amplitude: f64,
    /// Whether every phase of the points is within the range of [`cos_in_range`].
    pub in_range: bool,
}

/// Points at a time: four arrays of 8 KiB, which stay in the L1 cache across the terms.
pub(crate) const BLOCK: usize = 1024;

/// `sum[i] += Σ amplitude·cos(k·(x[i], y[i], z[i]) + offset)` over `terms`. With `std` on
/// x86-64, on a CPU with AVX-512 (found at run time), the loop runs eight points to a vector
/// with fused multiply-adds; with AVX2 and FMA, four; two to a vector on the baseline target
/// otherwise. The fused paths give the same bits; all agree with `libm::cos` to the rounding
/// of the phases (tested).
pub(crate) fn add_cosines(sum: &mut [f64], x: &[f64], y: &[f64], z: &[f64], terms: &[CosineTerm]) {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    {
        type Path = unsafe fn(&mut [f64], &[f64], &[f64], &[f64], &[CosineTerm]);
        let (avx512f, avx2, fma) = (
            std::is_x86_feature_detected!("avx512f"),
            std::is_x86_feature_detected!("avx2"),
            std::is_x86_feature_detected!("fma"),
        );
        let fused: Option<Path> = match (avx512f, avx2, fma) {
            (true, true, true) => Some(add_cosines_avx512),
            (_, true, true) => Some(add_cosines_avx2_fma),
            _ => None,
        };
        if let Some(path) = fused {
            // SAFETY: each path needs the CPU features it was compiled for, and this CPU has
            // them (checked just above); it is otherwise the safe `add_cosines_with`.
            #[allow(unsafe_code)]
            unsafe {
                path(sum, x, y, z, terms)
            };
            return;
        }
    }
    add_cosines_with::<false>(sum, x, y, z, terms);
}

/// [`add_cosines_with`] compiled for AVX2 and FMA.
#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx2,fma")]
fn add_cosines_avx2_fma(sum: &mut [f64], x: &[f64], y: &[f64], z: &[f64], terms: &[CosineTerm]) {
    add_cosines_with::<true>(sum, x, y, z, terms);
}

/// [`add_cosines_with`] compiled for AVX-512F and FMA.
#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx512f,avx2,fma")]
fn add_cosines_avx512(sum: &mut [f64], x: &[f64], y: &[f64], z: &[f64], terms: &[CosineTerm]) {
    add_cosines_with::<true>(sum, x, y, z, terms);
}

/// [`add_cosines`] on the given path, block by block of points.
#[inline(always)]
fn add_cosines_with<const FUSED: bool>(
    sum: &mut [f64],
    x: &[f64],
    y: &[f64],
    z: &[f64],
    terms: &[CosineTerm],
) {
    let n = sum.len().min(x.len()).min(y.len()).min(z.len());
    let mut start = 0;
    while start < n {
        let end = (start + BLOCK).min(n);
        let (sum, x, y, z) = (
            &mut sum[start..end],
            &x[start..end],
            &y[start..end],
            &z[start..end],
        );
        // Four terms to a pass over the points where all four are in range, so that each point
        // is loaded and its sum stored once for four cosines, whose chains interleave; each
        // point's sum still adds the terms in their order.
        let mut rest = terms;
        while let [a, b, c, d, tail @ ..] = rest {
            if a.in_range && b.in_range && c.in_range && d.in_range {
                for (eta, ((x, y), z)) in sum.iter_mut().zip(x.iter().zip(y).zip(z)) {
                    let p = [a, b, c, d].map(|t| phase::<FUSED>(t, *x, *y, *z));
                    let mut s = *eta;
                    for (t, p) in [a, b, c, d].iter().zip(p) {
                        s = madd::<FUSED>(t.amplitude, cos_in_range_with::<FUSED>(p), s);
                    }
                    *eta = s;
                }
            } else {
                for t in [a, b, c, d] {
                    add_term::<FUSED>(sum, x, y, z, t);
                }
            }
            rest = tail;
        }
        for t in rest {
            add_term::<FUSED>(sum, x, y, z, t);
        }
        start = end;
    }
}

/// `((kx·x + ky·y) + kz·z) + offset`, the phase of term `t` at `(x, y, z)`.
#[inline(always)]
fn phase<const FUSED: bool>(t: &CosineTerm, x: f64, y: f64, z: f64) -> f64 {
    let [kx, ky, kz] = t.k;
    madd::<FUSED>(kz, z, madd::<FUSED>(ky, y, kx * x)) + t.offset
}

/// `sum[i] += amplitude·cos(phase)` of the one term `t` over the points of a block.
#[inline(always)]
fn add_term<const FUSED: bool>(sum: &mut [f64], x: &[f64], y: &[f64], z: &[f64], t: &CosineTerm) {
    let points = x.iter().zip(y).zip(z);
    if t.in_range {
        for (eta, ((x, y), z)) in sum.iter_mut().zip(points) {
            let phase = phase::<FUSED>(t, *x, *y, *z);
            *eta = madd::<FUSED>(t.amplitude, cos_in_range_with::<FUSED>(phase), *eta);
        }
    } else {
        for (eta, ((x, y), z)) in sum.iter_mut().zip(points) {
            *eta += t.amplitude * cos(phase::<FUSED>(t, *x, *y, *z));
        }
    }
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

    /// Both paths of `add_cosines` (the one this CPU takes, and each explicitly) against
    /// `libm::cos`, over points and terms in and out of range, and lengths that are not a
    /// multiple of the block or the vector.
    #[test]
    fn sums_of_cosines_agree_with_libm_on_every_path() {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut unit = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let n = 2 * BLOCK + 37;
        let axis = |unit: &mut dyn FnMut() -> f64| -> alloc::vec::Vec<f64> {
            (0..n).map(|_| (unit() - 0.5) * 200.0).collect()
        };
        let (x, y, z) = (axis(&mut unit), axis(&mut unit), axis(&mut unit));
        let terms: alloc::vec::Vec<CosineTerm> = (0..9)
            .map(|i| {
                let far = i == 4;
                CosineTerm {
                    k: [unit() * 3.0, unit() * 0.1, unit() * 3.0],
                    offset: if far { 1e7 } else { (unit() - 0.5) * 40.0 },
                    amplitude: unit(),
                    in_range: !far,
                }
            })
            .collect();
        let expected: alloc::vec::Vec<f64> = (0..n)
            .map(|i| {
                terms.iter().fold(1.0, |s, t| {
                    let phase = t.k[0] * x[i] + t.k[1] * y[i] + t.k[2] * z[i] + t.offset;
                    s + t.amplitude * libm::cos(phase)
                })
            })
            .collect();
        let run = |path: &dyn Fn(&mut [f64])| {
            let mut sum = alloc::vec![1.0; n];
            path(&mut sum);
            sum.iter()
                .zip(&expected)
                .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()))
        };
        let dispatched = run(&|s| add_cosines(s, &x, &y, &z, &terms));
        let separate = run(&|s| add_cosines_with::<false>(s, &x, &y, &z, &terms));
        // Phases up to about 10³ rad: their own rounding, 10³·ε, bounds the agreement.
        assert!(dispatched < 5e-13, "{dispatched:e}");
        assert!(separate < 5e-13, "{separate:e}");
        #[cfg(feature = "std")]
        {
            let fused = run(&|s| add_cosines_with::<true>(s, &x, &y, &z, &terms));
            assert!(fused < 5e-13, "{fused:e}");
        }
    }

    /// `n` points spread over ±40 m on each axis.
    fn spread_points(n: usize) -> [alloc::vec::Vec<f64>; 3] {
        let point = |i: usize, k: f64| ((i as f64 + 0.5) * k).sin() * 40.0;
        [0.37, 0.11, 0.73].map(|k| (0..n).map(|i| point(i, k)).collect())
    }

    /// 11 terms, the seventh out of range: two passes of four (the second with the one out of
    /// range) and three alone.
    fn eleven_terms() -> alloc::vec::Vec<CosineTerm> {
        (0..11)
            .map(|i| {
                let a = i as f64;
                CosineTerm {
                    k: [(0.3 * a).cos() * 2.0, 0.05 * a, (0.3 * a).sin() * 2.0],
                    offset: if i == 6 { 1e7 } else { 0.9 * a - 20.0 },
                    amplitude: 0.01 + 0.1 * a,
                    in_range: i != 6,
                }
            })
            .collect()
    }

    /// The passes of four terms add each point's terms in their order, one at a time: the
    /// sums equal those of the terms taken one by one, bit for bit, on both paths.
    #[test]
    fn four_terms_to_a_pass_change_no_bit() {
        let n = BLOCK + 13;
        let [x, y, z] = spread_points(n);
        let terms = eleven_terms();
        type AddTerm = fn(&mut [f64], &[f64], &[f64], &[f64], &CosineTerm);
        let one_by_one = |add: AddTerm| {
            let mut sum = alloc::vec![0.25; n];
            for t in &terms {
                add(&mut sum, &x, &y, &z, t);
            }
            sum
        };
        let mut grouped = alloc::vec![0.25; n];
        add_cosines_with::<false>(&mut grouped, &x, &y, &z, &terms);
        assert_eq!(grouped, one_by_one(add_term::<false>));
        #[cfg(feature = "std")]
        {
            let mut grouped = alloc::vec![0.25; n];
            add_cosines_with::<true>(&mut grouped, &x, &y, &z, &terms);
            assert_eq!(grouped, one_by_one(add_term::<true>));
        }
    }

    /// The AVX-512 and AVX2 paths run the same operations, eight lanes or four: the same
    /// bits (where this CPU has both).
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    #[test]
    fn eight_lanes_or_four_give_the_same_bits() {
        if !(std::is_x86_feature_detected!("avx512f")
            && std::is_x86_feature_detected!("avx2")
            && std::is_x86_feature_detected!("fma"))
        {
            std::eprintln!("note: this CPU lacks AVX-512F, AVX2 or FMA; nothing to compare");
            return;
        }
        // 2·BLOCK + 11 points: full vectors of eight, a tail of three, across two blocks.
        let n = 2 * BLOCK + 11;
        let [x, y, z] = spread_points(n);
        let terms = eleven_terms();
        let (mut eight, mut four) = (alloc::vec![0.5; n], alloc::vec![0.5; n]);
        // SAFETY: this CPU has AVX-512F, AVX2 and FMA (checked above).
        #[allow(unsafe_code)]
        unsafe {
            add_cosines_avx512(&mut eight, &x, &y, &z, &terms);
            add_cosines_avx2_fma(&mut four, &x, &y, &z, &terms);
        }
        assert_eq!(eight, four);
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
