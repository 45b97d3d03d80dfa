//! Whether the rows determine each fitted parameter, by its profile: held
//! away from its value (in its logarithm, the fit's own coordinate) with the
//! others refitted, the chi-square rises by 1 (in units of the errors'
//! scale) one standard error out where the Gaussian error is right. The
//! ends where it rises by 1 are found on each side by regula falsi on the
//! square root of the rise, bracketed by doubling the step (an end it does
//! not reach within [`SECANT_STEPS`] is not known: the Gaussian error
//! stands, with no interval beside it). Where it has not
//! risen by 1 at 32 standard errors out, the rows do not bound the parameter
//! on that side (a direction the Jacobian's condition number did not show:
//! rows at two conditions, say): no standard error; where an end is more
//! than [`DIFFER`] from one standard error, the profile interval is reported
//! beside the Gaussian one.

use super::bounds::Bounds;
use super::{fit_checked, FitReport, Measurement, NAMES, NP};
use crate::shape::Shape;

/// How far (relative) a profile interval's half-width may differ from the
/// standard error before it is reported.
const DIFFER: f64 = 0.2;

/// Most steps of regula falsi towards a profile interval's end, how close
/// its `sqrt(rise)` comes to 1 where they stop early, and the most
/// doublings of the step (to 32 standard errors) before a side is unbounded.
const SECANT_STEPS: usize = 10;
const RISE_TOLERANCE: f64 = 0.005;
const MAX_DOUBLINGS: usize = 5;

/// The smallest relative standard error whose profile is computed.
const MIN_STEP: f64 = 1e-7;

/// Most rows whose profiles are computed (beyond, the refits would cost
/// more than the fit, and the Gaussian approximation is the better one).
const PROFILE_ROWS: usize = 20_000;

/// The profile of each fitted parameter of `r` (module docs): undetermined
/// ones lose their standard error (a verdict says why), skewed ones get
/// their profile interval.
pub(super) fn profile(
    shape: &Shape,
    rows: &[Measurement],
    (given, bounds): (&[Option<f64>; NP], &Bounds),
    r: &mut FitReport,
) {
    let scale = if r.weighted { 1.0 } else { r.reduced_chi2 };
    if !r.weighted && r.chi2 == 0.0 && given.iter().any(Option::is_none) {
        for k in (0..NP).filter(|&k| given[k].is_none()) {
            set_stderr(r, k, None);
        }
        r.verdicts.push(
            "no sigma and no scatter about the model (chi-square 0): the standard errors cannot be estimated \
             from these rows; give sigma"
                .into(),
        );
        return;
    }
    if rows.len() > PROFILE_ROWS || !(scale > 0.0 && scale.is_finite()) {
        return;
    }
    for k in (0..NP).filter(|&k| given[k].is_none()) {
        let Some(&p) = r.parameter(NAMES[k]) else { continue };
        // Over relative errors below MIN_STEP the chi-square is quadratic:
        // the Gaussian error stands, and refits would only confirm it.
        let Some(se) = p.stderr.filter(|&se| se > MIN_STEP * p.value) else { continue };
        // The rise of the chi-square with the parameter held at `ln(value) + t`.
        let rise = |t: f64| -> Option<f64> {
            let mut held = *given;
            held[k] = Some(p.value * t.exp());
            let f = fit_checked(shape, rows, &held, bounds).ok()?;
            Some(((f.chi2 - r.chi2) / scale).max(0.0))
        };
        let step = se / p.value;
        // Each side's half-width where the rise is 1 (`None`: unbounded there).
        let side = |sign: f64| -> Option<Option<f64>> {
            // A bracket: `rise(a) < 1 <= rise(b)`, doubling out from one step.
            let (mut a, mut ga, mut b) = (0.0, -1.0, step);
            let mut gb = rise(sign * b)?.sqrt() - 1.0;
            let mut doublings = 0;
            while gb < 0.0 {
                if doublings == MAX_DOUBLINGS {
                    return Some(None);
                }
                (a, ga, b) = (b, gb, 2.0 * b);
                gb = rise(sign * b)?.sqrt() - 1.0;
                doublings += 1;
            }
            // Regula falsi on `sqrt(rise) - 1`, nearly linear in the half-width;
            // an end it does not reach within its steps is not known (`None`).
            for _ in 0..SECANT_STEPS {
                let w = a - ga * (b - a) / (gb - ga);
                let g = rise(sign * w)?.sqrt() - 1.0;
                if g.abs() <= RISE_TOLERANCE {
                    return Some(Some(w));
                }
                if g < 0.0 {
                    (a, ga) = (w, g);
                } else {
                    (b, gb) = (w, g);
                }
            }
            None
        };
        let (Some(hi), Some(lo)) = (side(1.0), side(-1.0)) else { continue };
        let (Some(hi), Some(lo)) = (hi, lo) else {
            set_stderr(r, k, None);
            let which = if hi.is_none() { "above" } else { "below" };
            r.verdicts.push(format!(
                "{}: not bounded {which} by these rows: held 32 standard errors away, the others refitted, the \
                 chi-square rises by less than 1; rows at more conditions (more velocities below vbar = 1, a second \
                 amplitude) would determine it",
                NAMES[k]
            ));
            continue;
        };
        if ((hi / step) - 1.0).abs() > DIFFER || ((lo / step) - 1.0).abs() > DIFFER {
            if let Some(q) = r.parameter_mut(k) {
                // Within the bounds set (the held fits beyond them are the model's, not the fit's).
                let [b0, b1] = bounds[k];
                q.profile = Some([(p.value * (-lo).exp()).max(b0), (p.value * hi.exp()).min(b1)]);
            }
        }
    }
}

fn set_stderr(r: &mut FitReport, k: usize, stderr: Option<f64>) {
    if let Some(p) = r.parameter_mut(k) {
        p.stderr = stderr;
    }
}
