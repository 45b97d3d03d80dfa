//! Sequences without binary noise: `k * step` prints as 0.30000000000000004;
//! its 15-digit decimal, 0.3, is what the user meant.

/// Round to 15 significant digits.
fn decimal(x: f64) -> f64 {
    format!("{x:.14e}").parse().unwrap_or(x)
}

/// Replace each interior value of the increasing sequence `values` (from
/// `start` to `stop`) by its 15-digit decimal where that is within two ulps of
/// the computed value and keeps the sequence strictly increasing and inside
/// `[start, stop]`; the first and last values stay as they are.
fn tidy(values: &mut [f64], start: f64, stop: f64) {
    let n = values.len();
    for k in 1..n.saturating_sub(1) {
        let (x, r) = (values[k], decimal(values[k]));
        let ulp = f64::from_bits(x.abs().to_bits() + 1) - x.abs();
        if (r - x).abs() <= 2.0 * ulp && r > values[k - 1] && r < stop && r >= start {
            values[k] = r;
        }
    }
}

/// `count` values from `start` to `stop` (inclusive, `start <= stop`),
/// evenly spaced, or geometrically with `log` (then `start > 0`), each
/// interior value replaced by its 15-digit decimal where that is within two
/// ulps and keeps the sequence increasing (`0:1.2:13` gives 0.1, 0.2, ...,
/// not 0.30000000000000004). Ranges across most of f64 (`-1e308:1e308`,
/// whose span overflows) are spaced as `start (1 - t) + stop t`. One value
/// is `start`; no value where `count` is 0.
///
/// ```
/// assert_eq!(fricosc::spaced(0.0, 0.3, 4, false), [0.0, 0.1, 0.2, 0.3]);
/// assert_eq!(fricosc::spaced(1.0, 100.0, 3, true), [1.0, 10.0, 100.0]);
/// ```
#[must_use]
pub fn spaced(start: f64, stop: f64, count: usize, log: bool) -> Vec<f64> {
    if count <= 1 {
        return if count == 1 { vec![start] } else { vec![] };
    }
    let span = stop - start;
    let last = (count - 1) as f64;
    let at = |k: usize| {
        let t = k as f64 / last;
        if log {
            start * (stop / start).powf(t)
        } else if span.is_finite() {
            start + span * t
        } else {
            start * (1.0 - t) + stop * t
        }
    };
    let mut out: Vec<f64> = (0..count).map(|k| if k + 1 == count { stop } else { at(k) }).collect();
    tidy(&mut out, start, stop);
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn binary_noise_is_removed_and_the_ends_kept() {
        let mut v = vec![0.0, 0.1 * 3.0, 1.0];
        super::tidy(&mut v, 0.0, 1.0);
        assert_eq!(v, [0.0, 0.3, 1.0]);
    }

    /// A value whose 15-digit decimal lies more than two ulps away (1/6:
    /// 0.166666666666667 is 12 ulps off) is kept as computed; one within two
    /// (0.1 * 3, one ulp from 0.3) is replaced.
    #[test]
    fn values_far_from_their_decimal_are_kept() {
        let mut v: Vec<f64> = (0..=6).map(|k| k as f64 / 6.0).collect();
        let before = v.clone();
        super::tidy(&mut v, 0.0, 1.0);
        assert_eq!(v[1], 1.0 / 6.0);
        assert_eq!(v[3], 0.5);
        assert_eq!(v, before);
    }

    /// A decimal that would not keep the sequence strictly increasing inside
    /// `[start, stop]` is not taken: one equal to the value before it, one at
    /// `stop`, one below `start`.
    #[test]
    fn decimals_keep_the_sequence_increasing_and_inside() {
        // 0.1 * 3 becomes 0.3; its successor two ulps up would become 0.3 too.
        let next = 0.3000000000000001;
        let mut v = vec![0.0, 0.1 * 3.0, next, 1.0];
        super::tidy(&mut v, 0.0, 1.0);
        assert_eq!(v, [0.0, 0.3, next, 1.0]);
        // One ulp below the end: its decimal is the end itself.
        let below = 1.0 - f64::EPSILON / 2.0;
        let mut v = vec![0.0, 0.5, below, 1.0];
        super::tidy(&mut v, 0.0, 1.0);
        assert_eq!(v, [0.0, 0.5, below, 1.0]);
        // A start above its own decimal: the interior value's decimal lies below it.
        let start = 0.1 * 3.0;
        let inner = 0.3000000000000001;
        let mut v = vec![start, inner, 1.0];
        super::tidy(&mut v, start, 1.0);
        assert_eq!(v, [start, inner, 1.0]);
    }
}
