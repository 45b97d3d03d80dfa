//! Cancellation-free elementary functions used by the closed-form phases.
//!
//! The stick deficit of one spring near the critical velocity is a difference of
//! order-one terms that agree to many digits. Writing it with
//! `S(x) = x - sin x` and `C(x) = x^2/2 - (1 - cos x)` (both exactly zero to high order
//! at `x = 0`) removes the cancellation; these two functions are evaluated here with
//! full relative accuracy (Taylor series for `|x| < 2`, direct formula beyond, where no
//! cancellation is left).

/// `c[k] = (-1)^k / (2k + m)!` for `k < N`: the Taylor coefficients, in powers
/// of `x^2`, of the sine (`m = 3`) and cosine (`m = 4`) remainders below.
const fn alternating_inverse_factorials<const N: usize>(m: usize) -> [f64; N] {
    let mut c = [0.0; N];
    let mut fact = 1.0;
    let mut i = 2;
    while i <= m {
        fact *= i as f64;
        i += 1;
    }
    let mut k = 0;
    while k < N {
        c[k] = if k % 2 == 0 { 1.0 / fact } else { -1.0 / fact };
        let n = (2 * k + m) as f64;
        fact *= (n + 1.0) * (n + 2.0);
        k += 1;
    }
    c
}

/// Taylor coefficients of `(x - sin x) / x^3` in powers of `x^2`: `(-1)^k / (2k+3)!`.
const S_COEF: [f64; 13] = alternating_inverse_factorials::<13>(3);

/// Taylor coefficients of `(x^2/2 - 1 + cos x) / x^4` in powers of `x^2`: `(-1)^k / (2k+4)!`.
const C_COEF: [f64; 14] = alternating_inverse_factorials::<14>(4);

/// Taylor coefficients of `sin x / x` and `cos x` in powers of `x^2`:
/// `(-1)^k / (2k+1)!` and `(-1)^k / (2k)!`.
const SIN_COEF: [f64; 8] = alternating_inverse_factorials::<8>(1);
const COS_COEF: [f64; 8] = alternating_inverse_factorials::<8>(0);

/// Largest `|x|` [`sin_cos_small`] takes: the first omitted terms,
/// `x^16/17!` and `x^16/16!`, are below `1e-24` there.
pub(crate) const SIN_COS_SMALL_LIMIT: f64 = 0.2;

/// `(sin x, cos x)` for `|x| <=` [`SIN_COS_SMALL_LIMIT`] by their Taylor
/// series (within an ulp of the library's, tested; inlined, without the
/// library's argument checks). Beyond the limit, the library's.
pub(crate) fn sin_cos_small(x: f64) -> (f64, f64) {
    if x.abs() <= SIN_COS_SMALL_LIMIT {
        let y = x * x;
        (x * horner(&SIN_COEF, y), horner(&COS_COEF, y))
    } else {
        libm::sincos(x)
    }
}

/// Below this `|x|` the Taylor series is used (its terms are all below `2^(2k)/(2k)!`).
const SERIES_LIMIT: f64 = 2.0;

/// Below this `x^2` the first [`SHORT_TERMS`] Taylor coefficients suffice:
/// every series here has terms below `x^(2k)/(2k+1)!` relative to its first
/// (times at most `4^k`), and at `k = 8`, `x = 0.4` that is under `1e-18`.
const SHORT_SERIES_SQ: f64 = 0.16;
/// Terms used below [`SHORT_SERIES_SQ`].
const SHORT_TERMS: usize = 8;

/// The power series with coefficients `coef` in `y = x^2`, by Horner's rule,
/// shortened for small `y`. Both lengths are known at compile time, so each
/// loop is unrolled (these series run at every node of a curved contact).
fn horner<const N: usize>(coef: &[f64; N], y: f64) -> f64 {
    match coef.first_chunk::<SHORT_TERMS>() {
        Some(short) if y < SHORT_SERIES_SQ => horner_fixed(short, y),
        _ => horner_fixed(coef, y),
    }
}

/// Horner's rule over all of `coef`.
#[inline(always)]
fn horner_fixed<const N: usize>(coef: &[f64; N], y: f64) -> f64 {
    coef.iter().rev().fold(0.0, |acc, &c| acc * y + c)
}

/// Taylor coefficients of `(asin s - s)/s^3` in powers of `s^2`:
/// `(2k)! / (4^k (k!)^2 (2k + 1))` for `k = 1, 2, ...`.
const ASIN_COEF: [f64; 9] = {
    let mut c = [0.0; 9];
    let mut binom = 1.0; // (2k)! / (4^k (k!)^2)
    let mut k = 1;
    while k <= 9 {
        binom *= (2 * k - 1) as f64 / (2 * k) as f64;
        c[k - 1] = binom / (2 * k + 1) as f64;
        k += 1;
    }
    c
};

/// Below this `s` [`asin_small`] uses its series: the first omitted term is
/// below `0.1^20 / 20`, relative.
pub(crate) const ASIN_SERIES_LIMIT: f64 = 0.1;

/// `asin s` for `0 <= s < ASIN_SERIES_LIMIT` by its Taylor series (cheaper than
/// the library call, to the last bit), `s.asin()` above.
pub(crate) fn asin_small(s: f64) -> f64 {
    if s < ASIN_SERIES_LIMIT {
        let y = s * s;
        s + s * y * ASIN_COEF.iter().rev().fold(0.0, |acc, &c| acc * y + c)
    } else {
        s.asin()
    }
}

/// `x`, with a negative value (rounding of a mean that is mathematically
/// `>= 0`) put to 0: unlike `x.max(0.0)`, a NaN stays NaN, for the checks
/// downstream ([`crate::ratio::Ratio`]) to refuse.
pub(crate) fn nonneg(x: f64) -> f64 {
    if x < 0.0 {
        0.0
    } else {
        x
    }
}

/// `S(x) = x - sin x` with full relative accuracy, odd in `x`, about `x^3/6` near 0.
pub(crate) fn x_minus_sin(x: f64) -> f64 {
    // `sin x` is needed only beyond the series' range.
    x_minus_sin_with(x, if x.abs() < SERIES_LIMIT { 0.0 } else { x.sin() })
}

/// [`x_minus_sin`] given `sin x` (used beyond the series' range only).
pub(crate) fn x_minus_sin_with(x: f64, sin_x: f64) -> f64 {
    if x.abs() < SERIES_LIMIT {
        x * x * x * horner(&S_COEF, x * x)
    } else {
        x - sin_x
    }
}

/// `C(x) = x^2/2 - (1 - cos x)` with full relative accuracy, even, about `x^4/24` near 0.
/// It is the antiderivative of [`x_minus_sin`] that vanishes at 0.
pub(crate) fn half_sq_minus_versin(x: f64) -> f64 {
    // `cos x` is needed only beyond the series' range.
    half_sq_minus_versin_with(x, if x.abs() < SERIES_LIMIT { 0.0 } else { x.cos() })
}

/// [`half_sq_minus_versin`] given `cos x` (used beyond the series' range only).
pub(crate) fn half_sq_minus_versin_with(x: f64, cos_x: f64) -> f64 {
    if x.abs() < SERIES_LIMIT {
        let y = x * x;
        y * y * horner(&C_COEF, y)
    } else {
        0.5 * x * x - 1.0 + cos_x
    }
}

/// Taylor coefficients of `W(x) / x^5` (below) in powers of `x^2`:
/// `(-1)^k (4^k - 4) / (2 (2k+1)!)` for `k = 2, 3, ...`.
const W_COEF: [f64; 16] = {
    let mut c = [0.0; 16];
    let (mut fact, mut pow4) = (120.0, 16.0); // 5!, 4^2
    let mut j = 0;
    while j < 16 {
        let k = j + 2;
        let t = (pow4 - 4.0) / (2.0 * fact);
        c[j] = if k % 2 == 0 { t } else { -t };
        fact *= ((2 * k + 2) * (2 * k + 3)) as f64;
        pow4 *= 4.0;
        j += 1;
    }
    c
};

/// `W(x) = int_0^x (1 - cos t)^2 dt = (3x - 4 sin x + sin(2x)/2) / 2` with full
/// relative accuracy for `0 <= x <= pi/2` (about `x^5/20` near 0, where the
/// direct formula loses everything): the Taylor series, whose largest term at
/// `x = pi/2` is about 4 times the value.
pub(crate) fn versin_sq_integral(x: f64) -> f64 {
    let y = x * x;
    y * y * x * horner(&W_COEF, y)
}

/// `x y` as an unevaluated sum `hi + lo` (exact, by one fused multiply-add).
fn two_prod(x: f64, y: f64) -> (f64, f64) {
    let hi = x * y;
    (hi, x.mul_add(y, -hi))
}

/// `x + y` as an unevaluated sum `hi + lo` (exact; Knuth's two-sum).
fn two_sum(x: f64, y: f64) -> (f64, f64) {
    let hi = x + y;
    let z = hi - x;
    (hi, (x - (hi - z)) + (y - z))
}

/// `s^2 + v^2 - 1` (that is `s^2 - c^2`, `c = sqrt(1 - v^2)`) with
/// error-free products and sums, for inputs taken as exact: where `1 - s` is
/// not a double (`s < 0`), [`square_margin`] would need it rounded.
pub(crate) fn squares_minus_one(s: f64, v: f64) -> f64 {
    let (p, pe) = two_prod(s, s);
    let (q, qe) = two_prod(v, v);
    let (h, l) = two_sum(p, q);
    let (g, m) = two_sum(h, -1.0);
    g + (m + l + pe + qe)
}

/// `1 - a sqrt(1 - v^2)` for `a, v >= 0` with full relative accuracy wherever
/// the result is at least about `1e-30 a^2` (it is the normal force, over the
/// mean, where a stick starts on the bound; it vanishes where the spring's
/// regime changes from slip-first to stick-first, and at `a = 1, v -> 0`).
///
/// Written as `d / (1 + a c)` with `c = sqrt(1 - v^2)` and
/// `d = 1 - a^2 (1 - v^2) = 1 - a^2 + (a v)^2`, whose three terms are summed
/// exactly in double-double arithmetic: the cancellation is then harmless.
/// `v^2 - a (1 + s)`, the sign of `s^2 - (1 - v^2)` when `a = 1 - s`, with
/// error-free products and sums: exact to a few ulps of the terms' rounding
/// (the inputs are taken as exact).
pub(crate) fn square_margin(v: f64, a: f64, s: f64) -> f64 {
    let (b, be) = two_sum(1.0, s);
    let (q, qe) = two_prod(v, v);
    let (p, pe) = two_prod(a, b);
    let (h, l) = two_sum(q, -p);
    h + (l + qe - pe - a * be)
}

pub(crate) fn one_minus_a_cos_asin(a: f64, v: f64) -> f64 {
    if v == 0.0 {
        // 1 - a, rounded once (exact for a in [1/2, 2]).
        return 1.0 - a;
    }
    let c = ((1.0 - v) * (1.0 + v)).sqrt();
    let (r, re) = two_prod(a, a);
    let (p, pe) = two_prod(a, v);
    let (q, qe) = two_prod(p, p);
    // d = 1 - r - re + q + qe + 2 p pe, summed with the large parts first.
    let (h1, l1) = two_sum(1.0, -r);
    let (h2, l2) = two_sum(h1, q);
    let d = h2 + (l1 + l2 + (qe - re) + 2.0 * p * pe);
    d / (1.0 + a * c)
}

/// `x^e` (`x >= 0`), the exponents the power-law shapes use most without
/// the library's general `powf`: `1/2` (the
/// paraboloid's `1/n`) as the square root, correctly rounded like `powf`,
/// and `1` and `2` as exact products.
pub(crate) fn powf(x: f64, e: f64) -> f64 {
    if e == 0.5 {
        x.sqrt()
    } else if e == 2.0 {
        x * x
    } else if e == 1.0 {
        x
    } else {
        x.powf(e)
    }
}

/// Compensated (Kahan) summation.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Kahan {
    pub(crate) sum: f64,
    carry: f64,
}

impl Kahan {
    pub(crate) fn add(&mut self, x: f64) {
        let y = x - self.carry;
        let t = self.sum + y;
        self.carry = (t - self.sum) - y;
        self.sum = t;
    }
}

#[cfg(test)]
mod tests {
    /// [`powf`]'s shortcuts give the library's values bit for bit (the
    /// square root and the products are correctly rounded, as glibc's `pow`
    /// is on these), over 40 decades and at the ends.
    #[test]
    fn the_common_powers_are_the_librarys() {
        let mut xs = vec![0.0, f64::MIN_POSITIVE, 1.0, 2.0, 1e300];
        xs.extend((0..4000).map(|i| 10f64.powf(-20.0 + 40.0 * i as f64 / 4000.0) * (1.0 + 1e-3 * (i % 7) as f64)));
        for x in xs {
            for e in [0.5, 1.0, 2.0, 1.5, 1.0 / 3.0] {
                assert_eq!(super::powf(x, e).to_bits(), x.powf(e).to_bits(), "{x:e}^{e}");
            }
        }
    }

    use super::*;

    /// Values of `x - sin x` and `x^2/2 - 1 + cos x` from a 40-digit evaluation (mpmath).
    #[test]
    fn series_and_direct_forms_agree_with_high_precision_values() {
        let cases = [
            // x, x - sin x, x^2/2 - 1 + cos x
            (1e-08, 1.6666666666666668e-25, 4.166666666666667e-34),
            (0.1, 0.0001665833531718477, 4.165278025766096e-06),
            (1.0, 0.1585290151921035, 0.040302305868139716),
            (1.999, 1.0892868810558047, 0.5827631688015348),
            (2.5, 1.9015278558960436, 1.3238563844530662),
            (-3.0, -2.8588799919401326, 2.5100075033995544),
        ];
        for (x, s, c) in cases {
            let es = (x_minus_sin(x) - s).abs() / s.abs();
            let ec = (half_sq_minus_versin(x) - c).abs() / c.abs();
            assert!(es < 4e-15, "S({x}) rel err {es}");
            assert!(ec < 4e-15, "C({x}) rel err {ec}");
        }
    }

    /// `1 - a sqrt(1 - v^2)` against 40-digit values (mpmath), where it cancels.
    #[allow(clippy::excessive_precision)]
    #[test]
    fn one_minus_a_cos_asin_keeps_relative_accuracy_where_it_cancels() {
        let cases = [
            // a, v, 1 - a sqrt(1 - v^2)
            (1.0, 1e-8, 5.0000000000000003e-17),
            (0.5, 0.3, 0.52303039929152717),
            (1e3, 0.9999995, 1.2504114111604998e-7),
            (1.1547005383792517, 0.5, -1.3435868287034858e-16),
            (2.0, 0.8660254037844386, -1.7381275730402342e-16),
        ];
        for (a, v, exact) in cases {
            let got = one_minus_a_cos_asin(a, v);
            assert!(((got - exact) / exact).abs() < 1e-14, "a={a} v={v}: {got:e} vs {exact:e}");
        }
    }

    /// `int_0^x (1 - cos t)^2 dt` against 40-digit values (mpmath), from where
    /// the direct formula loses every digit to `pi/2`.
    #[test]
    fn versin_sq_integral_agrees_with_high_precision_values() {
        let cases = [
            (1e-5, 4.999999999940476e-27),
            (0.001, 4.999999404761939e-17),
            (0.3, 0.00012020502607968909),
            (1.0, 0.04438238709062741),
            (std::f64::consts::FRAC_PI_2, 0.3561944901923449),
        ];
        for (x, exact) in cases {
            let got = versin_sq_integral(x);
            assert!(((got - exact) / exact).abs() < 4e-15, "W({x}) = {got:e}, exact {exact:e}");
        }
    }

    /// The arcsine series against 40-digit values (mpmath), up to its limit.
    #[test]
    fn asin_series_agrees_with_high_precision_values() {
        let cases = [(1e-9, 1e-9), (0.01, 0.010000166674167113), (0.0999999, 0.10016732065777878)];
        for (s, exact) in cases {
            let got = asin_small(s);
            assert!(((got - exact) / exact).abs() < 2.3e-16, "asin({s}) = {got:e}, exact {exact:e}");
        }
    }

    /// Beyond the series' limit `asin_small` is the library's arcsine (a
    /// series there would be 1e-8 off at 0.5), against 40-digit values.
    #[test]
    fn asin_beyond_the_series_limit_is_the_library_one() {
        for (s, exact) in [(0.5, std::f64::consts::FRAC_PI_6), (0.9, 1.119_769_514_998_634_2)] {
            let got = asin_small(s);
            assert!(((got - exact) / exact).abs() < 2.3e-16, "asin({s}) = {got:e}, exact {exact:e}");
        }
    }

    /// A negative rounding of a non-negative mean becomes 0; zero, positive
    /// values and NaN pass unchanged (NaN for the checks downstream to refuse).
    /// Against the library's `sin_cos` on 20,001 points of `[-0.2, 0.2]`:
    /// within an ulp each (a coefficient off by one factorial is far outside).
    #[test]
    fn small_sin_cos_matches_the_library() {
        let ulp = |x: f64| f64::from_bits(x.abs().to_bits() + 1) - x.abs();
        let mut worst = 0.0f64;
        for i in -10_000..=10_000 {
            let x = SIN_COS_SMALL_LIMIT * i as f64 / 10_000.0;
            let (s, c) = sin_cos_small(x);
            let (ls, lc) = libm::sincos(x);
            if x != 0.0 {
                worst = crate::numerics::worst_of(worst, (s - ls).abs() / ulp(ls));
            }
            worst = crate::numerics::worst_of(worst, (c - lc).abs() / ulp(lc));
        }
        assert!(worst <= 1.0, "{worst} ulps");
        assert_eq!(sin_cos_small(0.5), libm::sincos(0.5));
    }

    #[test]
    fn nonneg_clamps_negatives_only() {
        assert_eq!(nonneg(-1e-300), 0.0);
        assert_eq!(nonneg(-2.5), 0.0);
        assert_eq!(nonneg(3e-310), 3e-310);
        assert_eq!(nonneg(0.25), 0.25);
        assert!(nonneg(f64::NAN).is_nan());
    }

    /// `1 - a sqrt(1 - v^2)` where it nearly cancels (`a` within 2e-15 to 1e-9
    /// of `1/sqrt(1 - v^2)`), and `v^2 - a (1 + s)` at the roundings of its
    /// zero, against 60-digit evaluations of the same f64 inputs (mpmath): the
    /// low-order terms of the double-double sums decide every digit here.
    #[test]
    #[allow(clippy::excessive_precision)] // The references keep their 20 digits.
    fn error_free_sums_keep_every_digit_where_they_cancel() {
        let mut worst = 0.0f64;
        for (v, a, exact) in [
            (0.3, 1.0482848367229665, -9.9989062815871101644e-13),
            (0.3, 1.0482848367216038, 3.0003062672289656769e-13),
            (0.7, 1.4002800840280127, -2.1574694880097347599e-15),
            (0.01, 1.0000500027502626, 9.9999995587015430416e-10),
            (0.999, 22.366272044366, -1.0000716536599078653e-10),
        ] {
            worst = crate::numerics::worst_of(worst, (one_minus_a_cos_asin(a, v) / exact - 1.0).abs());
        }
        assert!(worst < 1e-15, "one_minus_a_cos_asin: {worst:e}");
        let mut worst = 0.0f64;
        for (v, a, s, exact) in [
            (0.714142842854285, 0.30000000000000004, 0.7, -9.6156546990260700153e-17),
            (0.7141428428542849, 0.30000000000000004, 0.7, -2.5472811239187911311e-16),
            (0.7141428428542851, 0.30000000000000004, 0.7, 6.2415018411357737458e-17),
            (0.9923499489846359, 0.876543211, 0.123456789, 2.9207347809678886321e-17),
            (0.9923499489846358, 0.876543211, 0.123456789, -1.9113860455998955547e-16),
            (0.992349948984636, 0.876543211, 0.123456789, 2.4955330017934735277e-16),
            (0.916515138991168, 1.4, -0.4, 5.9970736144848780025e-17),
            (0.9165151389911679, 1.4, -0.4, -1.4353650580025526094e-16),
            (0.9165151389911681, 1.4, -0.4, 2.6347797808995284564e-16),
            (0.04471017781221634, 0.0010000000000000009, 0.999, 4.9465464544091693554e-19),
            (0.04471017781221633, 0.0010000000000000009, 0.999, -1.2582371508667537569e-19),
            (0.044710177812216347, 0.0010000000000000009, 0.999, 1.1151330059685093431e-18),
        ] {
            worst = crate::numerics::worst_of(worst, (square_margin(v, a, s) / exact - 1.0).abs());
        }
        eprintln!("square_margin: worst relative error {worst:e}");
        assert!(worst < 1e-15, "square_margin: {worst:e}");
    }

    #[test]
    fn series_is_continuous_at_the_switch() {
        let below = f64::from_bits(SERIES_LIMIT.to_bits() - 1);
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
        assert!(rel(x_minus_sin(below), x_minus_sin(SERIES_LIMIT)) < 1e-15);
        assert!(rel(half_sq_minus_versin(below), half_sq_minus_versin(SERIES_LIMIT)) < 1e-15);
    }
}
