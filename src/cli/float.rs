//! A fast path for reading the decimal numbers of batch inputs: the
//! correctly rounded `f64` of a JSON number with at most 19 digits and a
//! decimal exponent `q` (of the last digit) within `[-27, 27]` (or Clinger's
//! case below), else `None`, where the caller falls back to `str::parse`
//! (whose value this path gives bit for bit: the tests compare the two on
//! millions of strings, near-halfway cases included).
//!
//! Why: `str::parse::<f64>` takes ~270 instructions for a 17-digit number
//! (its grammar checks, a digit loop, then the same Eisel-Lemire step); this
//! path, inside the batch scanner, ~130 with the check of the digits
//! (measured): eight digits at a time, then
//! - Clinger's exact case: the digits `w <= 2^53` and `|q| <= 22`, so that
//!   `w` and `10^|q|` are exact doubles and one product or quotient is the
//!   correctly rounded value;
//! - else the Eisel-Lemire step (Lemire, "Number parsing at a gigabyte per
//!   second", Software: Practice and Experience 51, 2021): `w` normalised
//!   times a 128-bit truncation of `5^q`, whose high 55 bits decide the
//!   rounding (an exact halfway case rounds to even). Within `q in [-27,
//!   55]` a truncated product whose low word is all ones cannot mislead (the
//!   paper's "safe" range), so that test is not needed here; and with at
//!   most 19 digits and `|q| <= 27` the value is a normal double, so the
//!   step's subnormal and overflow guards (`None`) are never taken.

/// The 128-bit significands of `5^q`, `q` in `[-27, 27]`, as `(high, low)`
/// words: for `q >= 0` the exact power shifted up to bit 127; for `q < 0`
/// `floor(2^b / 5^-q) + 1` with `b = z + 127`, `2^z` the least power of two
/// `>= 5^-q` (so that the value lies in `[2^127, 2^128)`).
const POWERS: [(u64, u64); 55] = powers();

/// The least `q` of [`POWERS`].
const Q_MIN: i64 = -27;
/// The greatest.
const Q_MAX: i64 = 27;

const fn powers() -> [(u64, u64); 55] {
    let mut t = [(0u64, 0u64); 55];
    let mut k = 0;
    while k < 55 {
        let q = k as i64 + Q_MIN;
        let mut p: u64 = 1;
        let mut j = 0;
        while j < q.unsigned_abs() {
            p *= 5;
            j += 1;
        }
        let v: u128 = if q >= 0 {
            (p as u128) << (p as u128).leading_zeros()
        } else {
            // z: the least with 2^z >= p, p's bit length (5^k is no power of
            // two); then floor(2^(z + 127) / p) + 1 by long division (p < 2^63,
            // so the remainder's double fits).
            let z = 64 - p.leading_zeros();
            let b = z + 127;
            // 2^b is a one followed by b zeros: bring them down one at a time.
            let (mut quotient, mut rem): (u128, u128) = (0, 1);
            let mut j = 0;
            while j < b {
                rem *= 2;
                quotient <<= 1;
                if rem >= p as u128 {
                    rem -= p as u128;
                    quotient |= 1;
                }
                j += 1;
            }
            quotient + 1
        };
        t[k] = ((v >> 64) as u64, v as u64);
        k += 1;
    }
    t
}

/// Exact powers of ten as doubles (to `10^22`, the last one exact).
const TENS: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20,
    1e21, 1e22,
];

/// The value of eight ASCII digits (little-endian in `v`, first digit lowest).
#[inline]
fn eight_digits(v: u64) -> u64 {
    const MASK: u64 = 0x0000_00FF_0000_00FF;
    const MUL1: u64 = 0x000F_4240_0000_0064; // 100 + (1_000_000 << 32)
    const MUL2: u64 = 0x0000_2710_0000_0001; // 1 + (10_000 << 32)
    let v = v - 0x3030_3030_3030_3030;
    // Pairs: each even byte becomes 10 * its digit + the next one.
    let v = v * 10 + (v >> 8);
    (((v & MASK).wrapping_mul(MUL1)).wrapping_add(((v >> 16) & MASK).wrapping_mul(MUL2))) >> 32
}

/// True when the eight bytes of `v` are all ASCII digits.
#[inline]
pub(crate) fn all_digits(v: u64) -> bool {
    // Each byte 0x30..=0x39: high nibble 3, and still 3 after adding 6.
    const HIGH: u64 = 0xF0F0_F0F0_F0F0_F0F0;
    const THREES: u64 = 0x3030_3030_3030_3030;
    v & HIGH == THREES && v.wrapping_add(0x0606_0606_0606_0606) & HIGH == THREES
}

/// Digits of `b` from `i` accumulated into `w` (wrapping beyond 19): the
/// end, and the count.
#[inline]
fn digits(b: &[u8], mut i: usize, w: &mut u64) -> (usize, usize) {
    let start = i;
    while let Some(c) = b.get(i..i + 8) {
        let v = u64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]);
        if !all_digits(v) {
            break;
        }
        *w = w.wrapping_mul(100_000_000).wrapping_add(eight_digits(v));
        i += 8;
    }
    while let Some(&c) = b.get(i) {
        if !c.is_ascii_digit() {
            break;
        }
        *w = w.wrapping_mul(10).wrapping_add((c - b'0') as u64);
        i += 1;
    }
    (i, i - start)
}

/// The JSON number at `b[i]` (`-` or a digit; RFC 8259's grammar): its
/// end and its value, NaN where this path does not decide it (more than 19
/// digits, leading zeros of a fraction included; an exponent of more than
/// three digits, or `q` outside `[-27, 27]` unless Clinger's case holds), or
/// `None` when it is malformed. One pass: the digits are checked and summed
/// eight at a time. (The batch scanner reads each number of a plain row with
/// this, on its way through the row; inlined there: ~90 instructions a
/// row fewer than a call, measured.)
#[inline(always)]
pub fn json_number(b: &[u8], i: usize) -> Option<(usize, f64)> {
    let negative = b.get(i) == Some(&b'-');
    let mut j = i + negative as usize;
    let (mut w, mut n) = (0u64, 0usize);
    match b.get(j) {
        Some(b'0') => {
            j += 1;
            if b.get(j).is_some_and(u8::is_ascii_digit) {
                return None;
            }
        }
        Some(b'1'..=b'9') => (j, n) = digits(b, j, &mut w),
        _ => return None,
    }
    let mut q = 0i64;
    if b.get(j) == Some(&b'.') {
        let (k, m) = digits(b, j + 1, &mut w);
        if m == 0 {
            return None;
        }
        (j, n, q) = (k, n + m, -(m as i64));
    }
    // At most 19 digits: w < 10^19 < 2^64.
    let mut decided = n <= 19;
    if let Some(b'e' | b'E') = b.get(j) {
        j += 1;
        let minus = b.get(j) == Some(&b'-');
        j += matches!(b.get(j), Some(b'+' | b'-')) as usize;
        let mut e = 0u64;
        let (k, m) = digits(b, j, &mut e);
        if m == 0 {
            return None;
        }
        j = k;
        decided &= m <= 3;
        q += if minus { -(e as i64) } else { e as i64 };
    }
    let x = match decided.then(|| value(w, q)).flatten() {
        Some(x) if negative => -x,
        Some(x) => x,
        None => f64::NAN,
    };
    Some((j, x))
}

/// The correctly rounded value of `s` when it is a JSON number this path
/// decides ([`json_number`]), else `None`.
pub fn parse(s: &str) -> Option<f64> {
    match json_number(s.as_bytes(), 0) {
        Some((end, x)) if end == s.len() && !x.is_nan() => Some(x),
        _ => None,
    }
}

/// `w 10^q`, correctly rounded, or `None` where this path does not decide.
#[inline]
fn value(w: u64, q: i64) -> Option<f64> {
    if w == 0 {
        return Some(0.0);
    }
    if w <= 1 << 53 && (-22..=22).contains(&q) {
        // Clinger: both operands exact, one correctly rounded operation.
        let x = w as f64;
        return Some(if q >= 0 { x * TENS[q as usize] } else { x / TENS[(-q) as usize] });
    }
    if !(Q_MIN..=Q_MAX).contains(&q) {
        return None;
    }
    eisel_lemire(w, q)
}

/// The Eisel-Lemire step for binary64 (`w != 0`, `q` within [`POWERS`]).
fn eisel_lemire(w: u64, q: i64) -> Option<f64> {
    const SIG: i32 = 52;
    let lz = w.leading_zeros();
    let w = w << lz;
    let (hi5, lo5) = POWERS[(q - Q_MIN) as usize];
    // The product's high 128 bits, the low word's contribution added only
    // where the high word's low 9 bits (below the 55 kept) are all ones.
    let full = |a: u64, b: u64| {
        let p = a as u128 * b as u128;
        ((p >> 64) as u64, p as u64)
    };
    let (mut hi, mut lo) = full(w, hi5);
    const MASK: u64 = u64::MAX >> (SIG + 3);
    if hi & MASK == MASK {
        let (second_hi, _) = full(w, lo5);
        lo = lo.wrapping_add(second_hi);
        if second_hi > lo {
            hi += 1;
        }
    }
    let upper = (hi >> 63) as i32;
    let shift = upper + 64 - SIG - 3;
    let mut mantissa = hi >> shift;
    // floor(log2(10^q)) + 63, biased: the binary exponent of the product.
    let mut power2 = (((152_170 + 65_536) * q as i32) >> 16) + 63 + upper - lz as i32 + 1023;
    if power2 <= 0 {
        return None;
    }
    // Exactly halfway between two doubles (only possible for small |q|):
    // round to even.
    if lo <= 1 && (-4..=23).contains(&q) && mantissa & 3 == 1 && mantissa << shift == hi {
        mantissa &= !1;
    }
    mantissa += mantissa & 1;
    mantissa >>= 1;
    if mantissa >= 2 << SIG {
        mantissa = 1 << SIG;
        power2 += 1;
    }
    if power2 >= 0x7FF {
        return None;
    }
    Some(f64::from_bits(((power2 as u64) << SIG) | (mantissa & !(1 << SIG))))
}

/// `s` as a double: [`parse`] where it decides, else `str::parse`.
pub fn f64_of(s: &str) -> Result<f64, std::num::ParseFloatError> {
    match parse(s) {
        Some(x) => Ok(x),
        None => s.parse(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `c p` for a 128-bit `c` and a 64-bit `p`, as a 192-bit `(top, low)` pair.
    fn mul_192(c: u128, p: u64) -> (u64, u128) {
        let low = (c as u64) as u128 * p as u128;
        let high = (c >> 64) * p as u128 + (low >> 64);
        ((high >> 64) as u64, (high << 64) | (low as u64) as u128)
    }

    /// The table against its definition: for `q >= 0` the exact power shifted
    /// up; for `q < 0` the entry `c` brackets `2^b`: `(c - 1) p <= 2^b < c p`.
    #[test]
    fn the_table_holds_the_powers_of_five() {
        for q in 0..=27u32 {
            let p = 5u128.pow(q);
            let v = p << p.leading_zeros();
            assert_eq!(POWERS[(q as i64 - Q_MIN) as usize], ((v >> 64) as u64, v as u64), "q {q}");
        }
        for k in 1..=27u32 {
            let p = 5u64.pow(k);
            let (hi, lo) = POWERS[(-(k as i64) - Q_MIN) as usize];
            let c = ((hi as u128) << 64) | lo as u128;
            assert_eq!(c >> 127, 1, "q -{k} normalised");
            let z = (0..64).find(|&z| 1u64 << z >= p).unwrap();
            // 2^b as (top, low): b = z + 127 >= 130.
            let two_b = (1u64 << (z + 127 - 128), 0u128);
            assert!(mul_192(c - 1, p) <= two_b, "q -{k}");
            assert!(mul_192(c, p) > two_b, "q -{k}");
        }
    }

    #[test]
    fn eight_digits_at_once() {
        for s in ["00000000", "12345678", "99999999", "10000001", "87654321"] {
            let v = u64::from_le_bytes(s.as_bytes().try_into().unwrap());
            assert!(all_digits(v));
            assert_eq!(eight_digits(v), s.parse::<u64>().unwrap());
        }
        for s in ["1234567a", "/2345678", ":2345678", "1234 678", "12345.78"] {
            assert!(!all_digits(u64::from_le_bytes(s.as_bytes().try_into().unwrap())), "{s}");
        }
    }

    /// Every string the path decides is `str::parse`'s value, bit for bit; and
    /// it decides the common ones.
    fn same(s: &str) -> bool {
        match parse(s) {
            Some(x) => {
                assert_eq!(x.to_bits(), s.parse::<f64>().unwrap().to_bits(), "{s}");
                true
            }
            None => false,
        }
    }

    #[test]
    fn plain_decimals_read_as_the_standard_library_reads_them() {
        for s in [
            "0",
            "-0",
            "1",
            "0.5",
            "1.2",
            "3",
            "0.3",
            "2.5e-3",
            "1E5",
            "1e+22",
            "1e22",
            "1e23",
            "9007199254740993",
            "9007199254740992",
            "0.1",
            "123456789012345678",
            "1234567890123456789",
            "0.16123709293488145",
            "2.542301210811698",
            "1.7976931348623157",
            "4.9406564584124654",
            "8.98846567431158e27",
            "5e-27",
            "1e-27",
            "1.0000000000000002",
            "0.30000000000000004",
            "-7.25e+3",
        ] {
            assert!(same(s), "{s} is decided");
        }
        for s in [
            "",
            "-",
            ".5",
            "1.5.",
            "1e",
            "1e+",
            "e5",
            "+1",
            "1e1000",
            "12345678901234567890",
            "inf",
            "NaN",
            "0x10",
            "1e-28",
            "1e28",
            "1_0",
            " 1",
            "1 ",
            "17.",
            "00012.5",
            "-01",
            "1.e5",
            "0.00000000000000000001",
        ] {
            assert!(parse(s).is_none(), "{s} is left to the library");
        }
    }

    /// Random doubles as printed (shortest round trip, and with fewer digits),
    /// random digit strings, and strings next to the halfway points between
    /// neighbouring doubles (where rounding is decided by the last digit).
    #[test]
    fn random_and_near_halfway_decimals_read_as_the_library_reads_them() {
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut decided = 0;
        let n = 400_000;
        for _ in 0..n {
            let r = next();
            // Binary exponents from -60 to 69, and [0, 3) uniformly.
            let x = f64::from_bits(((1023 - 60 + r % 130) << 52) | (next() >> 12));
            let y = (r >> 11) as f64 / (1u64 << 53) as f64 * 3.0;
            for s in [format!("{x:?}"), format!("{y:?}"), format!("{y:.7}"), format!("{x:e}"), format!("{y:.15e}")] {
                decided += same(&s) as usize;
            }
            // Random digit strings: 1 to 19 digits, a point somewhere, an exponent.
            let digits = (next() % 10_000_000_000_000_000_000).to_string();
            let cut = (next() % (digits.len() as u64 + 1)) as usize;
            let e = (next() % 61) as i64 - 30;
            let s = format!("{}.{}e{e}", &digits[..cut.max(1)], &digits[cut.max(1)..]);
            same(&s);
            // Next to the midpoint of m 2^-52 and its successor (m in [2^52, 2^53)):
            // its 19 leading digits, and one unit above (below and above it).
            let m = (1u64 << 52) | (next() >> 12);
            let d = ((2 * m + 1) as u128 * 10u128.pow(18)) >> 53;
            for d in [d, d + 1] {
                let t = d.to_string();
                same(&format!("{}.{}", &t[..1], &t[1..]));
            }
        }
        assert!(decided > 3 * n, "the common forms are decided ({decided} of {})", 5 * n);
    }

    /// Exact halfway cases (a double's midpoint written out in full, at most
    /// 19 digits): round to even, as the library does.
    #[test]
    fn exact_halfway_cases_round_to_even() {
        // m + 1/2 units at 2^0: integers above 2^53 with an odd last bit of half.
        for m in [(1u64 << 53) + 1, (1 << 53) + 3, (1 << 54) + 2, (1 << 60) + (1 << 7), 9_007_199_254_740_993] {
            let s = m.to_string();
            assert!(same(&s), "{s}");
        }
        // Below 1 unit in the last place (q = -1, -2): halfway at 2^52 and 2^51.
        for s in ["4503599627370496.5", "4503599627370497.5", "2251799813685248.75", "2251799813685248.25"] {
            assert!(same(s), "{s}");
        }
        // Small binary fractions written exactly: 1 + 2^-k (k <= 19).
        for k in 1..20 {
            let x = 1.0 + f64::powi(2.0, -k);
            let s = format!("{x}");
            assert!(same(&s), "{s}");
        }
    }
}
