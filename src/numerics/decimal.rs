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
pub(crate) fn tidy(values: &mut [f64], start: f64, stop: f64) {
    let n = values.len();
    for k in 1..n.saturating_sub(1) {
        let (x, r) = (values[k], decimal(values[k]));
        let ulp = f64::from_bits(x.abs().to_bits() + 1) - x.abs();
        if (r - x).abs() <= 2.0 * ulp && r > values[k - 1] && r < stop && r >= start {
            values[k] = r;
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn binary_noise_is_removed_and_the_ends_kept() {
        let mut v = vec![0.0, 0.1 * 3.0, 1.0];
        super::tidy(&mut v, 0.0, 1.0);
        assert_eq!(v, [0.0, 0.3, 1.0]);
    }
}
