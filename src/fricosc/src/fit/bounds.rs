//! Bounds set by the user on fitted parameters ([`super::Fixed::bounds`]):
//! Levenberg-Marquardt's steps are projected onto them (in the logarithms,
//! where the iteration runs), and a parameter that ends on its bound is
//! named in a verdict and gets no standard error (the chi-square's
//! curvature there says nothing about how far the rows would take it);
//! the others' covariance is that of the fit with it held there.

use super::{Values, NAMES, NP};
use crate::error::{Error, Result};

/// Each parameter's interval, `[0, inf)` where none is set.
pub(crate) type Bounds = [[f64; 2]; NP];

/// A parameter this close to its bound (relative) rests on it.
const ON_BOUND: f64 = 1e-9;

/// The bounds of `fixed`, checked: each `[lo, hi]` with `0 <= lo < hi <=
/// inf`, on a parameter that is fitted (a held one has no bounds).
pub(crate) fn checked(fixed: &super::Fixed, given: &[Option<f64>; NP]) -> Result<Bounds> {
    let mut out = [[0.0, f64::INFINITY]; NP];
    for (k, b) in fixed.bounds.iter().enumerate() {
        let Some([lo, hi]) = *b else { continue };
        let name = NAMES[k];
        if !(lo.is_finite() && lo >= 0.0) {
            return Err(Error::param(name, lo, "a lower bound must be finite and >= 0"));
        }
        if hi.is_nan() || hi <= lo {
            return Err(Error::param(name, hi, "an upper bound must be above the lower bound"));
        }
        if given[k].is_some() {
            return Err(Error::param(name, lo, "bounds apply to a fitted parameter, not a held one"));
        }
        out[k] = [lo, hi];
    }
    Ok(out)
}

/// `p` with its `free` parameters moved into their bounds (a lower bound of
/// 0 is the logarithm's own; a value on a bound of 0 would have no logarithm).
pub(crate) fn project(mut p: Values, free: &[usize], bounds: &Bounds) -> Values {
    for &k in free {
        let [lo, hi] = bounds[k];
        p[k] = p[k].min(hi);
        if lo > 0.0 {
            p[k] = p[k].max(lo);
        }
    }
    p
}

/// The `free` parameters of `p` that rest on a bound set by the user.
pub(crate) fn resting(p: &Values, free: &[usize], bounds: &Bounds) -> Vec<usize> {
    free.iter().copied().filter(|&k| on(p[k], bounds[k][0]) || on(p[k], bounds[k][1])).collect()
}

/// Whether `x` is on the bound `b` (one set: positive and finite).
fn on(x: f64, b: f64) -> bool {
    b > 0.0 && b.is_finite() && (x - b).abs() <= ON_BOUND * b
}

/// The columns (indices into `free`) of the parameters on a bound that the
/// descent `-g` (the gradient of the chi-square in the logarithms) pushes
/// beyond it: held there for the step (an active set), so that the others'
/// step is their own minimum's, not a projection of a joint one.
pub(crate) fn held_columns(p: &Values, free: &[usize], bounds: &Bounds, g: &[f64]) -> Vec<usize> {
    (0..free.len())
        .filter(|&c| {
            let ([lo, hi], x) = (bounds[free[c]], p[free[c]]);
            (on(x, hi) && g[c] < 0.0) || (on(x, lo) && g[c] > 0.0)
        })
        .collect()
}

/// The verdict of a parameter resting on its bound.
pub(crate) fn verdict(k: usize, value: f64) -> String {
    format!(
        "{} rests on its bound {value:e}: the rows would take it beyond, so it has no standard error (the \
         others' are those with it held there); widen the bound or check the model",
        NAMES[k]
    )
}
