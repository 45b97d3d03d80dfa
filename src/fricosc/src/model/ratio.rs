//! `mu_macro/mu0` and its complement, the reduction, checked before they leave
//! the solver: a non-finite or out-of-range intermediate is an
//! [`Error::Internal`], never a valid-looking number.

use crate::error::{Error, Result};

/// How far outside `[0, 1]` rounding may put a ratio or a reduction that is
/// mathematically inside: a few ulps of 1. Such values are rounded onto the
/// interval; anything further out is a bug and an error.
pub(crate) const ROUNDING_SLACK: f64 = 8.0 * f64::EPSILON;

/// Relative rounding error of one spring's means and one quadrature weight, in
/// units of the machine epsilon: the closed-form phases are cancellation-free
/// (a few roundings each; `src/fricosc/tests/library/flat_events.rs` measures at most 3.3 eps) and
/// Golub-Welsch weights carry a few more.
pub(crate) const ROUNDING_PER_TERM: f64 = 16.0;

/// Rounding part of the error estimate of `mu_ratio` computed as `1 - dd/nn`
/// from two sums of `terms` positive terms: each term carries
/// [`ROUNDING_PER_TERM`] eps, the sums accumulate like `sqrt(terms)`, the
/// quotient adds both, and `1 - reduction` half an ulp of 1.
pub(crate) fn rounding_estimate(reduction: f64, terms: usize) -> f64 {
    quotient_rounding(reduction, terms) + 0.5 * f64::EPSILON
}

/// Rounding part of the error estimate of a quotient `q` of two sums of `terms`
/// positive terms, each with [`ROUNDING_PER_TERM`] eps: the sums accumulate
/// like `sqrt(terms)` and the quotient adds both.
pub(crate) fn quotient_rounding(q: f64, terms: usize) -> f64 {
    f64::EPSILON * 2.0 * (ROUNDING_PER_TERM + (terms as f64).sqrt()) * q.abs()
}

/// The ratio and its error estimate from a quadrature's three sums over the
/// springs, `[nn, dd, tt]` = the mean normal force, the deficit and the mean
/// tangential force (each spring's from its own cancellation-free form, so
/// that `tt` keeps its relative accuracy where it is small), with their
/// truncation estimates `errors` and the `terms` they summed. Where `mu` is the
/// small one (a reduction above 1/2: `amp` near or above 1 and `vbar -> 0`) it
/// is `tt/nn`, so that it keeps its relative accuracy; else the reduction
/// `dd/nn` (its complement `1 - dd/nn` would keep only the absolute accuracy of
/// 1 where `mu` is small, and `1 - tt/nn` likewise where the reduction is).
pub(crate) fn from_sums(sums: [f64; 3], errors: [f64; 3], terms: usize, context: &str) -> Result<(Ratio, f64)> {
    let (nn, k) = (sums[0], numerator(sums));
    let q = if nn > 0.0 { sums[k] / nn } else { 0.0 };
    let truncation = quotient_error(nn, sums[k], errors[0], errors[k]);
    if k == 2 {
        let estimate = truncation + quotient_rounding(q, terms);
        Ok((Ratio::from_mu_within(q, estimate, context)?, estimate))
    } else {
        let estimate = truncation + rounding_estimate(q, terms);
        Ok((Ratio::from_deficit_within(sums[1], nn, estimate, context)?, estimate))
    }
}

/// The error of [`from_sums`]'s ratio that a second evaluation `other` of the
/// same sums (on a coarser table) implies: the differences of the numerator
/// and of `nn` propagated through the quotient separately, in absolute value,
/// so that they cannot cancel (the difference of the two ratios can vanish by
/// accident where the error does not: for the suite's tabulated sphere at
/// `amp = 1, vbar = 0.01` it was 1.9e-14, the error against the true sphere
/// 3.9e-14).
pub(crate) fn sums_difference(sums: [f64; 3], other: [f64; 3]) -> f64 {
    let k = numerator(sums);
    quotient_error(sums[0], sums[k], (other[0] - sums[0]).abs(), (other[k] - sums[k]).abs())
}

/// Which of `[nn, dd, tt]` [`from_sums`] divides by `nn`: `tt` (2) where the
/// reduction exceeds 1/2, else `dd` (1).
fn numerator(sums: [f64; 3]) -> usize {
    if sums[0] > 0.0 && sums[1] / sums[0] > 0.5 {
        2
    } else {
        1
    }
}

/// Truncation part of the error estimate of the reduction `dd/nn`, from the
/// estimated errors `en` of `nn` and `ed` of `dd` (first-order propagation
/// through the quotient: `ed/nn + dd en/nn^2`); 0 without normal force.
pub(crate) fn quotient_error(nn: f64, dd: f64, en: f64, ed: f64) -> f64 {
    if nn > 0.0 {
        ed / nn + dd * en / (nn * nn)
    } else {
        0.0
    }
}

/// `mu_macro/mu0` and `1 - mu_macro/mu0`, the latter with full relative
/// accuracy. The default is no reduction: `mu_macro = mu0`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct Ratio {
    /// `mu_macro / mu0`.
    pub mu_ratio: f64,
    /// `1 - mu_macro/mu0`, computed directly (not as a difference).
    pub reduction: f64,
}

impl Default for Ratio {
    fn default() -> Self {
        Ratio { mu_ratio: 1.0, reduction: 0.0 }
    }
}

/// `x` in `[0, 1]` up to `slack` (at least [`ROUNDING_SLACK`]: a quadrature
/// passes its own error estimate), rounded onto it; else an internal error.
fn unit_interval(name: &str, x: f64, slack: f64, context: &str) -> Result<f64> {
    let slack = slack.max(ROUNDING_SLACK);
    if x.is_finite() && (-slack..=1.0 + slack).contains(&x) {
        Ok(x.clamp(0.0, 1.0))
    } else {
        Err(Error::Internal { what: format!("{name} = {x:?} is not in [0, 1] ({context})") })
    }
}

impl Ratio {
    /// The ratio whose reduction is `k` times this one's (`k <= 1`): for a
    /// reduction linear in the amplitude ([`crate::contact::AMP_LINEAR`]).
    pub(crate) fn scaled(self, k: f64) -> Ratio {
        let reduction = self.reduction * k;
        Ratio { mu_ratio: 1.0 - reduction, reduction }
    }

    /// From the reduction (the friction lost, over the friction without oscillation).
    ///
    /// # Errors
    /// [`Error::Internal`] for a value that is not finite, or outside `[0, 1]` by more
    /// than rounding (or the given slack): a bug, never an answer.
    pub(crate) fn from_reduction(reduction: f64, context: &str) -> Result<Self> {
        Self::from_reduction_within(reduction, ROUNDING_SLACK, context)
    }

    /// As [`Ratio::from_reduction`] for a value with an error estimate `slack`
    /// that may put it outside `[0, 1]` (a finite non-negative number).
    ///
    /// # Errors
    /// [`Error::Internal`] for a value that is not finite, or outside `[0, 1]` by more
    /// than rounding (or the given slack): a bug, never an answer.
    pub(crate) fn from_reduction_within(reduction: f64, slack: f64, context: &str) -> Result<Self> {
        let reduction = unit_interval("reduction", reduction, slack, context)?;
        Ok(Ratio { mu_ratio: 1.0 - reduction, reduction })
    }

    /// As [`Ratio::from_mu`] for a value with an error estimate `slack`.
    ///
    /// # Errors
    /// [`Error::Internal`] for a value that is not finite, or outside `[0, 1]` by more
    /// than rounding or the given slack.
    pub(crate) fn from_mu_within(mu_ratio: f64, slack: f64, context: &str) -> Result<Self> {
        let mu_ratio = unit_interval("mu_ratio", mu_ratio, slack, context)?;
        Ok(Ratio { mu_ratio, reduction: 1.0 - mu_ratio })
    }

    /// From `mu_macro/mu0` itself (where it is the small one of the two).
    ///
    /// # Errors
    /// [`Error::Internal`] for a value that is not finite, or outside `[0, 1]` by more
    /// than rounding (or the given slack): a bug, never an answer.
    pub(crate) fn from_mu(mu_ratio: f64, context: &str) -> Result<Self> {
        let mu_ratio = unit_interval("mu_ratio", mu_ratio, ROUNDING_SLACK, context)?;
        Ok(Ratio { mu_ratio, reduction: 1.0 - mu_ratio })
    }

    /// Under oscillation in the sliding direction `mu_macro/mu0` may be
    /// negative (the oscillation pushes the body forward): `mu_ratio` in
    /// `[-1, 1]` and `reduction` in `[0, 2]` (each from its own integral), up to
    /// `slack`, rounded onto them.
    ///
    /// # Errors
    /// [`Error::Internal`] for a value that is not finite or outside its range
    /// by more than rounding (or the slack): a bug, never an answer.
    pub(crate) fn signed(mu_ratio: f64, reduction: f64, slack: f64, context: &str) -> Result<Self> {
        let slack = slack.max(ROUNDING_SLACK);
        let within = |name: &str, x: f64, lo: f64, hi: f64| {
            if x.is_finite() && (lo - slack..=hi + slack).contains(&x) {
                Ok(x.clamp(lo, hi))
            } else {
                Err(Error::Internal { what: format!("{name} = {x:?} is not in [{lo}, {hi}] ({context})") })
            }
        };
        Ok(Ratio {
            mu_ratio: within("mu_ratio", mu_ratio, -1.0, 1.0)?,
            reduction: within("reduction", reduction, 0.0, 2.0)?,
        })
    }

    /// From the mean stick deficit and the mean normal force of the same contact:
    /// the reduction is their quotient. Both must be finite and `>= 0`; a contact
    /// without normal force (never touching) has no reduction.
    ///
    /// # Errors
    /// [`Error::Internal`] for a value that is not finite, or outside `[0, 1]` by more
    /// than rounding (or the given slack): a bug, never an answer.
    pub(crate) fn from_deficit(deficit: f64, mean_normal: f64, context: &str) -> Result<Self> {
        Self::from_deficit_within(deficit, mean_normal, ROUNDING_SLACK, context)
    }

    /// As [`Ratio::from_deficit`] with an error estimate `slack` of the quotient.
    ///
    /// # Errors
    /// [`Error::Internal`] for a value that is not finite, or outside `[0, 1]` by more
    /// than rounding (or the given slack): a bug, never an answer.
    pub(crate) fn from_deficit_within(deficit: f64, mean_normal: f64, slack: f64, context: &str) -> Result<Self> {
        if !(deficit.is_finite() && mean_normal.is_finite() && deficit >= 0.0 && mean_normal >= 0.0) {
            return Err(Error::Internal {
                what: format!("deficit {deficit:?} and mean normal force {mean_normal:?} ({context})"),
            });
        }
        if deficit == 0.0 {
            return Ok(Ratio { mu_ratio: 1.0, reduction: 0.0 });
        }
        Self::from_reduction_within(deficit / mean_normal, slack, context)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nan_and_out_of_range_values_are_errors_not_answers() {
        assert!(Ratio::from_reduction(f64::NAN, "t").is_err());
        assert!(Ratio::from_mu(f64::INFINITY, "t").is_err());
        assert!(Ratio::from_reduction(1.0 + 1e-12, "t").is_err());
        assert!(Ratio::from_mu(-1e-12, "t").is_err());
        assert!(Ratio::from_deficit(f64::NAN, 1.0, "t").is_err());
        assert!(Ratio::from_deficit(1.0, 0.0, "t").is_err(), "a deficit without normal force");
        // Rounding just outside is rounding, and lands on the interval; a quadrature's
        // own estimate widens that, a NaN estimate does not.
        assert!(Ratio::from_reduction_within(1.0 + 1e-12, 2e-12, "t").is_ok());
        assert!(Ratio::from_reduction_within(1.0 + 1e-12, f64::NAN, "t").is_err());
        assert_eq!(Ratio::from_reduction(1.0 + f64::EPSILON, "t").unwrap().mu_ratio, 0.0);
        assert_eq!(Ratio::from_deficit(0.0, 0.0, "t").unwrap().mu_ratio, 1.0);
        // Each guard on its own: 0.5/inf = 0 and -0.5/-1 = 0.5 would pass the range check.
        assert!(Ratio::from_deficit(0.5, f64::INFINITY, "t").is_err());
        assert!(Ratio::from_deficit(-0.5, -1.0, "t").is_err());
        assert!(Ratio::from_deficit(f64::INFINITY, f64::INFINITY, "t").is_err());
        assert_eq!(Ratio::from_deficit(0.5, 2.0, "t").unwrap(), Ratio { mu_ratio: 0.75, reduction: 0.25 });
    }

    #[test]
    fn scaling_the_reduction() {
        let r = Ratio { mu_ratio: 0.6, reduction: 0.4 }.scaled(0.25);
        assert_eq!(r, Ratio { mu_ratio: 0.9, reduction: 0.1 });
    }

    /// Negative friction (the ratchet) is in range; beyond `[-1, 1]` and
    /// `[0, 2]` only rounding or the slack is, rounded onto the ends.
    #[test]
    fn signed_ratios_keep_their_sign_within_their_ranges() {
        let ok = |m: f64, r: f64, slack: f64| Ratio::signed(m, r, slack, "t");
        assert_eq!(ok(-0.5, 1.5, 0.0).unwrap(), Ratio { mu_ratio: -0.5, reduction: 1.5 });
        assert_eq!(ok(-1.0 - 1e-10, 2.0 + 1e-10, 2e-10).unwrap(), Ratio { mu_ratio: -1.0, reduction: 2.0 });
        assert_eq!(ok(1.0 + 1e-10, -1e-10, 2e-10).unwrap(), Ratio { mu_ratio: 1.0, reduction: 0.0 });
        for (m, r) in [(-1.0 - 1e-10, 1.0), (1.0 + 1e-10, 0.0), (0.5, 2.0 + 1e-10), (0.5, -1e-10), (f64::NAN, 0.5)] {
            assert!(ok(m, r, 0.0).is_err(), "{m} {r}");
        }
        assert!(ok(0.5, 0.5, f64::NAN).is_ok(), "a NaN slack is no slack");
        assert!(ok(0.5, f64::INFINITY, 1.0).is_err());
    }
}
