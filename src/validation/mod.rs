//! Validating another code's table of `mu_macro/mu0`: per-row errors against
//! the exact solver, summaries by regime and by amplitude, and findings that
//! point at the usual bugs of a time-stepping code.
//!
//! # The value at `vbar = 0`
//! At zero sliding velocity the tangential force is not fixed by the
//! oscillation; it depends on the start ([`AtRest`]):
//! - `Sliding` (the default): the limit `vbar -> 0+`, the steady state of a
//!   contact that was sliding. A spring that sticks whenever the bound allows
//!   keeps the smallest bound it has seen, so the tangential force settles at
//!   `mu0` times the minimum normal force: `mu/mu0 = N_min / N_mean`
//!   (`mu_static`; the seed's section 4).
//! - `Relaxed`: a stepper started from relaxed springs (`F = 0`) at exactly
//!   `v0 = 0`: each update is `F <- min(F + 0, mu0 N)`, so `F` never leaves 0 and
//!   `mu/mu0 = 0` for every shape and amplitude.
//!
//! # Findings
//! Each finding names the rows it concerns and says in plain words what to look
//! at; they are computed from the table alone (values outside `[0, 1]`, not 1
//! above the critical velocity, decreasing in `vbar`) or from its errors (errors
//! growing towards `vbar -> 0`, the signature of a run too short for the steady
//! state; a `vbar = 0` value that matches the other start).

mod history;
mod series;

pub use history::{compare_history, phases, FoundEvent, HistoryValidation, HISTORY_REFERENCE_SPRINGS};
pub use series::{convergence, observed_order, Convergence, RegimeOrder, SeriesRow};

use crate::error::{Error, Result};
use crate::shape::Shape;
use crate::spring::{Regime, Spring};

/// The start a `vbar = 0` row is compared with (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum AtRest {
    /// The limit `vbar -> 0+` (steady sliding): `mu_static`.
    #[default]
    Sliding,
    /// Springs started relaxed at exactly zero velocity: 0.
    Relaxed,
}

/// The regime of a point, from the spring at the contact's centre (for the flat
/// punch, the whole contact): how the tests of other codes usually split.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum RowRegime {
    /// `vbar = 0`: compared with the [`AtRest`] convention.
    AtRest,
    /// No spring ever sticks: `vbar >= 1` or `amp = 0` (`mu = mu0`).
    NoStick,
    /// `amp <= 1`: the centre never loses contact.
    PermanentContact,
    /// `amp > 1`, the centre slips first after contact, then sticks.
    JumpingSlipFirst,
    /// `amp > 1`, the centre sticks from the moment of contact.
    JumpingStickFirst,
}

impl RowRegime {
    /// The regime of `(vbar, amp)` (both finite and `>= 0`).
    #[must_use]
    pub fn of(vbar: f64, amp: f64) -> RowRegime {
        if vbar == 0.0 {
            return RowRegime::AtRest;
        }
        if vbar >= 1.0 || amp == 0.0 {
            return RowRegime::NoStick;
        }
        match Spring::new(crate::flat::spring_s(amp), vbar).regime {
            Regime::JumpingStickFirst => RowRegime::JumpingStickFirst,
            Regime::JumpingSlipFirst | Regime::JumpingSlip => RowRegime::JumpingSlipFirst,
            _ => RowRegime::PermanentContact,
        }
    }
}

/// One compared row.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Row {
    /// Index of the row in the input (0-based, header not counted).
    pub row: usize,
    /// Dimensionless velocity.
    pub vbar: f64,
    /// Amplitude `du/u0`.
    pub amp: f64,
    /// The value under test.
    pub mu_ratio: f64,
    /// The exact value (at `vbar = 0`, by the [`AtRest`] convention).
    pub exact: f64,
    /// `mu_ratio - exact`.
    pub error: f64,
    /// `error / exact` (absent where the exact value is 0).
    pub relative_error: Option<f64>,
    /// The point's regime.
    pub regime: RowRegime,
}

/// Errors of a group of rows.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Summary {
    /// Rows in the group.
    pub n: usize,
    /// Largest `|error|`.
    pub max_abs_error: f64,
    /// Root mean square of the errors.
    pub rms_error: f64,
    /// Largest `|relative_error|` (0 if no row has one).
    pub max_rel_error: f64,
    /// The row (input index) with the largest `|error|`.
    pub worst_row: usize,
}

/// Root mean square of `errors`, scaled by the largest (as `hypot` does), so
/// that errors of 1e200 or 1e308 give their rms, not an overflow to `inf`.
pub(crate) fn rms(errors: impl Iterator<Item = f64> + Clone) -> f64 {
    let (mut n, mut top) = (0usize, 0.0f64);
    for e in errors.clone() {
        n += 1;
        // A NaN stays visible (f64::max would drop it).
        top = if e.is_nan() || top.is_nan() { f64::NAN } else { top.max(e.abs()) };
    }
    if n == 0 || top == 0.0 || !top.is_finite() {
        return if n == 0 { 0.0 } else { top };
    }
    let sq: f64 = errors.map(|e| (e / top) * (e / top)).sum();
    top * (sq / n as f64).sqrt()
}

impl Summary {
    fn of<'a>(rows: impl Iterator<Item = &'a Row> + Clone) -> Option<Summary> {
        let rms_error = rms(rows.clone().map(|r| r.error));
        let (mut n, mut max_abs, mut max_rel, mut worst) = (0usize, -1.0f64, 0.0f64, 0usize);
        for r in rows {
            n += 1;
            if r.error.abs() > max_abs {
                max_abs = r.error.abs();
                worst = r.row;
            }
            max_rel = max_rel.max(r.relative_error.map_or(0.0, f64::abs));
        }
        (n > 0).then_some(Summary { n, max_abs_error: max_abs, rms_error, max_rel_error: max_rel, worst_row: worst })
    }
}

/// The errors of one regime.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RegimeSummary {
    /// The regime.
    pub regime: RowRegime,
    /// Its rows' errors.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub summary: Summary,
}

/// The errors at one amplitude.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AmpSummary {
    /// The amplitude.
    pub amp: f64,
    /// Its rows' errors.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub summary: Summary,
}

/// The kind of a finding.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum FindingKind {
    /// Values above 1.
    AboveOne,
    /// Negative values.
    Negative,
    /// Not 1 at or above the critical velocity `vbar = 1`.
    NotOneAboveCritical,
    /// Decreasing in `vbar` at fixed amplitude.
    NotMonotone,
    /// Errors growing towards `vbar -> 0`: not yet in steady state.
    NotSteady,
    /// A `vbar = 0` value that matches the other [`AtRest`] convention.
    AtRestConvention,
}

/// Something wrong with the table, and where.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Finding {
    /// What.
    pub kind: FindingKind,
    /// How many rows show it.
    pub count: usize,
    /// The first few of them (input indices).
    pub rows: Vec<usize>,
    /// What to check, in plain words.
    pub hint: String,
}

/// Rows listed per finding.
const FINDING_ROWS: usize = 5;

/// The comparison of a whole table.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Validation {
    /// Shape name.
    pub shape: String,
    /// The `vbar = 0` convention used.
    pub at_rest: AtRest,
    /// Tolerance of the value checks (findings).
    pub tolerance: f64,
    /// Number of rows.
    pub n: usize,
    /// Largest `|error|` over all rows.
    pub max_abs_error: f64,
    /// Root mean square of the errors.
    pub rms_error: f64,
    /// The row with the largest `|error|`.
    pub worst: Row,
    /// Errors per regime, in the order of [`RowRegime`].
    pub by_regime: Vec<RegimeSummary>,
    /// Errors per amplitude, in increasing amplitude.
    pub by_amp: Vec<AmpSummary>,
    /// What looks wrong, with hints (empty: nothing found).
    pub findings: Vec<Finding>,
    /// Every row.
    pub rows: Vec<Row>,
}

/// `(vbar, amp, mu_ratio)` rows from a table's columns: `velocity` is `vbar`,
/// or `vhat` (eq. 15) if `vhat` (then `vbar = vhat / amp`); `friction` is
/// `mu_ratio`, or `mu` if `mu` (then `mu_ratio = mu / mu0`, and `mu0` is
/// required; refused otherwise, where the values are already ratios).
///
/// # Errors
/// [`Error::Parse`] naming the row for a bad value, columns of different lengths,
/// or `mu` without `mu0`.
pub fn rows_from_columns(
    velocity: &[f64],
    amp: &[f64],
    friction: &[f64],
    vhat: bool,
    mu: bool,
    mu0: Option<f64>,
) -> Result<Vec<(f64, f64, f64)>> {
    let bad = |reason: &str| Error::Parse { context: "mu0".into(), reason: reason.into() };
    if velocity.len() != amp.len() || amp.len() != friction.len() {
        return Err(Error::Parse { context: "columns".into(), reason: "they differ in length".into() });
    }
    let mu0 = match (mu, mu0) {
        (true, Some(m)) if m.is_finite() && m > 0.0 => m,
        (true, Some(m)) => return Err(Error::param("mu0", m, "must be finite and > 0")),
        (true, None) => return Err(bad("the table gives 'mu': mu0 is needed (mu_ratio = mu / mu0)")),
        (false, Some(_)) => return Err(bad("given, but the table gives 'mu_ratio' (already divided by mu0)")),
        (false, None) => 1.0,
    };
    (0..amp.len())
        .map(|i| {
            let at = |e: Error| Error::Parse { context: format!("row {i}"), reason: e.to_string() };
            let a = crate::error::check_nonneg("amp", amp[i]).map_err(at)?;
            let v = if vhat {
                crate::model::vbar_from_vhat(velocity[i], a).map_err(at)?
            } else {
                crate::error::check_nonneg("vbar", velocity[i]).map_err(at)?
            };
            Ok((v, a, friction[i] / mu0))
        })
        .collect()
}

/// The exact value of row `(vbar, amp)` under `at_rest`.
///
/// # Errors
/// The solver's errors for a bad `(vbar, amp)`.
pub fn exact_value(shape: &Shape, vbar: f64, amp: f64, at_rest: AtRest) -> Result<f64> {
    if vbar == 0.0 && at_rest == AtRest::Relaxed {
        return Ok(0.0);
    }
    Ok(shape.evaluate(vbar, amp)?.ratio.mu_ratio)
}

/// Compare `rows` of `(vbar, amp, mu_ratio)` with the exact solver for `shape`;
/// `tolerance` (`>= 0`) is how far a value may be from a bound (0, 1) or from
/// monotonicity before it is a finding.
///
/// # Errors
/// [`Error::Parse`] naming the row for a bad value; the solver's errors.
pub fn compare(shape: &Shape, rows: &[(f64, f64, f64)], at_rest: AtRest, tolerance: f64) -> Result<Validation> {
    crate::error::check_nonneg("tolerance", tolerance)?;
    if rows.is_empty() {
        return Err(Error::param("rows", 0.0, "the table has no rows (nothing to validate)"));
    }
    for (i, &(v, a, m)) in rows.iter().enumerate() {
        let at = |e: Error| Error::Parse { context: format!("row {i}"), reason: e.to_string() };
        crate::error::check_nonneg("vbar", v).map_err(at)?;
        crate::error::check_nonneg("amp", a).map_err(at)?;
        if !m.is_finite() {
            return Err(Error::Parse {
                context: format!("row {i}"),
                reason: format!("mu_ratio = {m:?} is not finite"),
            });
        }
    }
    let exact: Vec<Result<f64>> = crate::numerics::par::map(rows, |&(v, a, _)| exact_value(shape, v, a, at_rest));
    let mut out = Vec::with_capacity(rows.len());
    for (i, (&(vbar, amp, mu_ratio), e)) in rows.iter().zip(exact).enumerate() {
        let exact = e?;
        let error = mu_ratio - exact;
        let relative_error = (exact != 0.0).then(|| error / exact);
        out.push(Row { row: i, vbar, amp, mu_ratio, exact, error, relative_error, regime: RowRegime::of(vbar, amp) });
    }
    let all = Summary::of(out.iter()).ok_or_else(|| Error::Internal { what: "no rows to summarise".into() })?;
    let mut regimes: Vec<RowRegime> = out.iter().map(|r| r.regime).collect();
    regimes.sort();
    regimes.dedup();
    let by_regime = regimes
        .into_iter()
        .filter_map(|g| {
            Summary::of(out.iter().filter(|r| r.regime == g)).map(|summary| RegimeSummary { regime: g, summary })
        })
        .collect();
    let mut amps: Vec<f64> = out.iter().map(|r| r.amp).collect();
    amps.sort_by(f64::total_cmp);
    amps.dedup();
    let by_amp = amps
        .iter()
        .filter_map(|&a| Summary::of(out.iter().filter(|r| r.amp == a)).map(|summary| AmpSummary { amp: a, summary }))
        .collect();
    let findings = findings(shape, &out, &amps, at_rest, tolerance)?;
    Ok(Validation {
        shape: shape.name().to_string(),
        at_rest,
        tolerance,
        n: out.len(),
        max_abs_error: all.max_abs_error,
        rms_error: all.rms_error,
        worst: out[all.worst_row],
        by_regime,
        by_amp,
        findings,
        rows: out,
    })
}

fn finding(kind: FindingKind, rows: Vec<usize>, hint: &str) -> Option<Finding> {
    (!rows.is_empty()).then(|| Finding {
        kind,
        count: rows.len(),
        rows: rows.into_iter().take(FINDING_ROWS).collect(),
        hint: hint.into(),
    })
}

/// A vbar below which errors are compared with those at the same amplitude
/// above it (and below 1) for [`FindingKind::NotSteady`].
const LOW_VBAR: f64 = 0.3;
/// How much larger the errors at low vbar must be than elsewhere to be a finding.
const NOT_STEADY_FACTOR: f64 = 10.0;

fn findings(shape: &Shape, rows: &[Row], amps: &[f64], at_rest: AtRest, tol: f64) -> Result<Vec<Finding>> {
    let pick = |f: &dyn Fn(&Row) -> bool| rows.iter().filter(|r| f(r)).map(|r| r.row).collect::<Vec<_>>();
    let mut out = vec![];
    out.extend(finding(
        FindingKind::AboveOne,
        pick(&|r| r.mu_ratio > 1.0 + tol),
        "values above 1: check the normalisation by the mean normal force (mu0 times the period-averaged \
         normal force, not the static one or its value at one instant)",
    ));
    out.extend(finding(
        FindingKind::Negative,
        pick(&|r| r.mu_ratio < -tol),
        "negative values: check the sign of the tangential force and that every average spans whole periods",
    ));
    out.extend(finding(
        FindingKind::NotOneAboveCritical,
        pick(&|r| r.vbar >= 1.0 && (r.mu_ratio - 1.0).abs() > tol),
        "at vbar >= 1 no spring sticks and mu/mu0 = 1 exactly: check the velocity's normalisation (eq. 3: \
         vbar = (kx/kz) v0 / (mu0 omega du)) and the Coulomb bound",
    ));
    // Decreasing in vbar at one amplitude (rows sorted by vbar; vbar = 0 rows
    // follow the chosen convention, so a relaxed 0 is not a decrease).
    let mut decreasing = vec![];
    for &a in amps {
        let mut line: Vec<&Row> = rows.iter().filter(|r| r.amp == a).collect();
        line.sort_by(|x, y| x.vbar.total_cmp(&y.vbar));
        for w in line.windows(2) {
            if w[1].vbar > w[0].vbar && w[1].mu_ratio < w[0].mu_ratio - tol {
                decreasing.push(w[1].row);
            }
        }
    }
    decreasing.sort_unstable();
    out.extend(finding(
        FindingKind::NotMonotone,
        decreasing,
        "mu/mu0 decreases with velocity at these rows (the exact curve never does): check convergence there \
         (time step, number of periods, springs)",
    ));
    // Errors far larger at low velocity than at the same amplitude's higher
    // velocities (below the critical one): the transient. Compared within one
    // amplitude, so that a scheme's larger error in the jumping regimes is not
    // mistaken for it.
    let mut slow = vec![];
    for &a in amps {
        let rest: Vec<f64> =
            rows.iter().filter(|r| r.amp == a && r.vbar >= LOW_VBAR && r.vbar < 1.0).map(|r| r.error.abs()).collect();
        if rest.is_empty() {
            continue;
        }
        let bar = (NOT_STEADY_FACTOR * rest.iter().sum::<f64>() / rest.len() as f64).max(tol);
        slow.extend(
            rows.iter()
                .filter(|r| r.amp == a && r.vbar > 0.0 && r.vbar < LOW_VBAR && r.error.abs() > bar)
                .map(|r| r.row),
        );
    }
    slow.sort_unstable();
    out.extend(finding(
        FindingKind::NotSteady,
        slow,
        "errors grow towards vbar -> 0, ten times those at the same amplitude's higher velocities: the \
         steady state takes longer to reach at low velocity (the tangential force builds up at a rate \
         proportional to vbar); run more periods and average the last one",
    ));
    // vbar = 0 rows that match the other convention rather than the chosen one.
    let other = match at_rest {
        AtRest::Sliding => AtRest::Relaxed,
        AtRest::Relaxed => AtRest::Sliding,
    };
    let mut mismatched = vec![];
    for r in rows.iter().filter(|r| r.vbar == 0.0) {
        let alt = exact_value(shape, 0.0, r.amp, other)?;
        if r.error.abs() > tol && (r.mu_ratio - alt).abs() <= tol.max(1e-12) {
            mismatched.push(r.row);
        }
    }
    let hint = match other {
        AtRest::Relaxed => {
            "at vbar = 0 these values equal 0, what a stepper started from relaxed springs gives at exactly zero \
             velocity (not the limit vbar -> 0+ of a sliding contact): compare with --at-rest relaxed"
        }
        AtRest::Sliding => {
            "at vbar = 0 these values equal the limit vbar -> 0+ of a sliding contact (mu_static), not the relaxed \
             start: compare with --at-rest sliding"
        }
    };
    out.extend(finding(FindingKind::AtRestConvention, mismatched, hint));
    Ok(out)
}
