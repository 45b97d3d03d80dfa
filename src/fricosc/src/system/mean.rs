//! The long-time mean of a response without period, with its standard
//! error and drift (`Mean`).

/// Fewest batches a mean's estimate is made of ([`batch_mean`]): two halves of four.
const MIN_BATCHES: usize = 8;

/// The long-time mean of a response without period.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Mean {
    pub mean: f64,
    /// The standard error of `mean` from the batches' scatter.
    pub standard_error: f64,
    /// `|m2 - m1|`, the means of the batches' later and earlier halves: a
    /// transient not yet settled shows here, not in the scatter.
    pub drift: f64,
}

impl Mean {
    /// The error estimate: twice the standard error plus three drifts.
    /// A transient decaying like `c/t` leaves the mean over `[T/2, T]` at
    /// `2 ln 2 c/T` from its limit, while its halves' means are
    /// `4 ln(3/2) c/T` and `4 ln(4/3) c/T`: a drift of `0.47 c/T`, so three
    /// drifts cover it, and any faster decay. A stationary response's drift
    /// is about 1.6 standard errors, so there the estimate is about 7 of them.
    pub fn error_estimate(&self) -> f64 {
        2.0 * self.standard_error + 3.0 * self.drift
    }
}

/// The mean of `xs` from batches of `size`: its standard error and drift
/// ([`Mean`]). A short tail (a stiff body's 20 periods) is cut into batches
/// small enough that there are at least [`MIN_BATCHES`]: with one batch the
/// scatter and the drift would both be 0, an estimate of 0 for a mean that
/// has not settled.
pub(crate) fn batch_mean(xs: &[f64], size: usize) -> Mean {
    let avg = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let size = size.min(xs.len() / MIN_BATCHES).max(1);
    let batches: Vec<f64> = xs.chunks_exact(size).map(avg).collect();
    let n = batches.len() as f64;
    let mean = avg(&batches);
    let var = batches.iter().map(|b| (b - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    let (early, late) = batches.split_at(batches.len() / 2);
    let drift = if early.is_empty() { 0.0 } else { (avg(late) - avg(early)).abs() };
    Mean { mean, standard_error: (var / n).sqrt(), drift }
}

#[cfg(test)]
mod tests {
    use super::batch_mean;

    /// A transient decaying like `1/t` over the tail `[1000, 2000)`: the
    /// mean is 2.94 drifts from its limit (derivation at `Mean::error_estimate`),
    /// within the estimate; with two drifts it would not be.
    #[test]
    fn the_estimate_covers_a_transient_decaying_like_one_over_t() {
        let xs: Vec<f64> = (1000..2000).map(|t| 1.0 - 1e-3 / t as f64).collect();
        let m = batch_mean(&xs, 10);
        let error = 1.0 - m.mean;
        assert!(error <= m.error_estimate() && error > 2.9 * m.drift, "{m:?}");
    }

    /// A short tail (10 periods, as a stiff body runs 20): batches small
    /// enough for a scatter and a drift. With batches of 10 it was one batch,
    /// and the estimate 0 for a mean 3e-4 from its limit.
    #[test]
    fn a_short_tail_still_has_an_estimate() {
        let xs: Vec<f64> = (10..20).map(|t| 1.0 - 1e-3 / t as f64).collect();
        let m = batch_mean(&xs, 10);
        let error = 1.0 - m.mean;
        assert!(error > 0.0 && error <= m.error_estimate(), "{m:?}");
    }

    /// The batches are of the size asked for, and the standard error is
    /// their sample deviation over `sqrt(n)` (cargo-mutants: a `%` for the
    /// `/` sizing the batches, `n + 1` or `n` for `n - 1` passed). Eight
    /// batches of 10 whose means alternate 0, 1: `sqrt((8/4)/7/8) =
    /// sqrt(1/28)`; within each batch values alternate too, so batches of 1
    /// would scatter more.
    #[test]
    fn the_standard_error_is_the_batches_sample_deviation() {
        let xs: Vec<f64> = (0..80).map(|i| ((i / 10) % 2) as f64 + if i % 2 == 0 { 0.25 } else { -0.25 }).collect();
        let m = batch_mean(&xs, 10);
        assert_eq!(m.mean, 0.5);
        assert!((m.standard_error - (1.0f64 / 28.0).sqrt()).abs() <= 1e-15, "{m:?}");
        let alternating: Vec<f64> = (0..2000).map(|i| (i % 2) as f64).collect();
        let m = batch_mean(&alternating, 10);
        assert_eq!((m.mean, m.standard_error, m.drift), (0.5, 0.0, 0.0), "{m:?}");
    }

    /// A stationary response (a fixed pseudo-random sequence): the estimate
    /// covers the mean's error and is a few standard errors, not more.
    #[test]
    fn a_stationary_response_is_a_few_standard_errors() {
        let mut s = 12345u64;
        let xs: Vec<f64> = (0..2000)
            .map(|_| {
                s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                0.5 + ((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 1e-3
            })
            .collect();
        let m = batch_mean(&xs, 10);
        assert!((m.mean - 0.5).abs() <= m.error_estimate(), "{m:?}");
        assert!(m.error_estimate() <= 12.0 * m.standard_error && m.standard_error < 1e-5, "{m:?}");
    }
}
