//! Errors of order one (`|mu - exact| > LARGE_ERROR`, where `mu` lies in
//! `[-1, 1]`) are not a discretisation's: a table that has them gets a
//! finding whatever else it shows. Under oscillation in the sliding direction
//! the usual causes are conventions, each cheap to try against the exact
//! solver: the phase's sign, the phase measured from the normal force's
//! maximum instead of its minimum (`phase + pi`), a phase in degrees read as
//! radians, and the tangential amplitude as peak to peak (or half of it);
//! across the sliding direction the same for its phase and amplitude. A
//! convention fits where the table's values, read with it, are within a
//! tenth of the largest error and within [`LARGE_ERROR`] everywhere; the best
//! fit is named.

use super::{finding, Finding, FindingKind};
use crate::conditions::Conditions;
use crate::shape::Shape;
use std::f64::consts::PI;

/// The largest error a discretisation is credited with.
pub(crate) const LARGE_ERROR: f64 = 0.05;

/// How a convention reads a row's `[vhat, amp, T, phase, W, psi]`.
type Read = fn([f64; 6]) -> [f64; 6];

/// A convention: how it reads a row, and its name.
type Convention = (Read, &'static str);

const CONVENTIONS: [Convention; 10] = [
    (|[v, a, t, p, w, q]| [v, a, t, -p, w, q], "the phase's sign reversed (-phase)"),
    (|[v, a, t, p, w, q]| [v, a, t, p + PI, w, q], "the phase measured from the normal force's maximum (phase + pi)"),
    (|[v, a, t, p, w, q]| [v, a, t, p * (PI / 180.0), w, q], "the phase in degrees (phase pi/180)"),
    (|[v, a, t, p, w, q]| [v, a, 0.5 * t, p, w, q], "the tangential amplitude as peak to peak (T/2)"),
    (|[v, a, t, p, w, q]| [v, a, 2.0 * t, p, w, q], "the tangential amplitude as half of it (2 T)"),
    (|[v, a, t, p, w, q]| [v, a, t, p, w, -q], "the transverse phase's sign reversed (-psi)"),
    (
        |[v, a, t, p, w, q]| [v, a, t, p, w, q + PI],
        "the transverse phase measured from the normal force's maximum (psi + pi)",
    ),
    (|[v, a, t, p, w, q]| [v, a, t, p, w, q * (PI / 180.0)], "the transverse phase in degrees (psi pi/180)"),
    (|[v, a, t, p, w, q]| [v, a, t, p, 0.5 * w, q], "the transverse amplitude as peak to peak (W/2)"),
    (|[v, a, t, p, w, q]| [v, a, t, p, 2.0 * w, q], "the transverse amplitude as half of it (2 W)"),
];

/// The rows whose error is of order one.
pub(crate) fn large(errors: impl Iterator<Item = (usize, f64)>) -> Vec<usize> {
    errors.filter(|&(_, e)| e.is_nan() || e.abs() > LARGE_ERROR).map(|(i, _)| i).collect()
}

/// The finding of a table with errors of order one (none without).
pub(crate) fn large_errors(rows: Vec<usize>, worst: f64) -> Option<Finding> {
    let hint = format!(
        "errors of order one (up to {worst:.3}): not the discretisation but the model or a convention: \
         the normalisation (mu0 times the period-averaged normal force), the velocity's scaling, the \
         sign of the tangential force, contact loss (a spring out of contact carries no force and \
         enters contact relaxed)"
    );
    finding(FindingKind::LargeErrors, rows, &hint)
}

/// Under oscillation in the sliding direction: which convention, if any,
/// explains errors of order one in `rows` (with their `errors`, the larger
/// of along and across). `None` when the errors are not of order one.
pub(crate) fn oscillation_finding(shape: &Shape, rows: &[super::OscillationInput], errors: &[f64]) -> Option<Finding> {
    let bad = large(errors.iter().copied().enumerate());
    if bad.is_empty() {
        return None;
    }
    let worst = errors.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    let fit = |read: Read| -> Option<f64> {
        let errs = crate::numerics::par::map(rows, |r| {
            let c = conditions(read, [r.vhat, r.amp, r.tangential_amp, r.phase, r.transverse_amp, r.transverse_phase])?;
            let e = shape.evaluate(&c)?;
            let across = match (r.transverse_ratio, e.transverse_ratio) {
                (Some(v), Some(x)) => (v - x).abs(),
                (Some(v), None) => v.abs(),
                _ => 0.0,
            };
            Ok::<f64, crate::error::Error>((r.mu_ratio - e.ratio.mu_ratio).abs().max(across))
        });
        let mut m = 0.0f64;
        for e in errs {
            m = m.max(e.ok()?);
        }
        Some(m)
    };
    named(&bad, worst, &fit).or_else(|| large_errors(bad, worst))
}

/// A history under the conditions `c` with errors of order one at the samples
/// `bad` (largest `worst`): the convention that explains them, given the
/// largest error of the history against the exact one under other conditions.
pub(crate) fn history_finding(
    c: &Conditions,
    bad: &[usize],
    worst: f64,
    error_under: &dyn Fn(&Conditions) -> Option<f64>,
) -> Option<Finding> {
    let (t, phase) = c.tangential()?;
    let point = [c.as_vhat(), c.amp(), t, phase, 0.0, 0.0];
    named(bad, worst, &|read| error_under(&conditions(read, point).ok()?))
}

/// `[vhat, amp, T, phase, W, psi]` read with a convention, as conditions
/// (as a table's row is read).
fn conditions(read: Read, point: [f64; 6]) -> crate::error::Result<Conditions> {
    let [v, a, t, p, w, q] = read(point);
    super::OscillationInput::new(v, a, 0.0).with_tangential(t, p).with_transverse(w, q, None).conditions()
}

/// The finding naming the convention with the smallest largest error
/// (`error(read)`), if that is within a tenth of `worst` and within
/// [`LARGE_ERROR`].
fn named(bad: &[usize], worst: f64, error: &dyn Fn(Read) -> Option<f64>) -> Option<Finding> {
    let bar = (0.1 * worst).min(LARGE_ERROR);
    let fits = CONVENTIONS.iter().filter_map(|&(read, name)| error(read).filter(|&m| m <= bar).map(|m| (m, name)));
    let (m, name) = fits.min_by(|x, y| x.0.total_cmp(&y.0))?;
    finding(
        FindingKind::Convention,
        bad.to_vec(),
        &format!(
            "your values match the exact ones read with {name}: largest error {m:.1e} there, {worst:.3} \
                 as read; fricosc's body moves as vhat tau + T sin(tau + phase) while the indentation is \
                 u0 - du cos tau (phase in radians, T the amplitude)"
        ),
    )
}
