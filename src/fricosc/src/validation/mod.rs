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
//! state; a `vbar = 0` value that matches the other start; `vbar = 0` values as
//! far off as the rows that stick and slip, although nothing moves there, the
//! signature of the averaging window, the normalisation or the start; errors
//! ten times those of the built-in stepping peer at the same resolution). A
//! finding means something is wrong: the command line exits 1 on any.

mod convention;
mod findings;
mod history;
mod oscillation;
mod series;
mod system;
mod table;
mod text;

pub use oscillation::{
    compare_oscillation, OscillationInput, OscillationRegime, OscillationRow, OscillationValidation, TransverseRow,
    SYSTEM_PEER_PERIODS,
};

pub use history::{
    compare_history, to_static_units, EventSeries, FoundEvent, HistoryData, HistorySample, HistorySeries,
    HistoryValidation, NormalComparison, OriginSource, TimeAxis, TimeOrigin, TransverseComparison,
};
pub(crate) use series::observed_order;
pub use series::{convergence, Convergence, Needed, RegimeOrder, RowStatus, SeriesRow};
pub use table::{Column, Table};
pub(crate) use text::findings_text;

use crate::contact::regime::ContactRegime;
use crate::error::{Error, Result};
use crate::shape::Shape;
use crate::stepper::Stepping;

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

/// What a check compares and how strictly.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Check {
    /// What a `vbar = 0` row is compared with.
    pub at_rest: AtRest,
    /// How far a value may be from a bound (0, 1) or from monotonicity before
    /// it is a finding (`>= 0`).
    pub tolerance: f64,
    /// Run the built-in stepping peer at this resolution on every row and set
    /// its error beside the table's ([`FindingKind::WorseThanPeer`]).
    pub peer: Option<Stepping>,
    /// The body on this system with mass and stiffness ([`crate::system`]):
    /// the table is compared with its attractors.
    pub system: Option<crate::system::System>,
    /// The largest `|error|` accepted: rows beyond it by more than the
    /// exact value's own error estimate are a finding
    /// ([`FindingKind::MaxError`]).
    pub max_error: Option<f64>,
}

impl Default for Check {
    fn default() -> Self {
        Check { at_rest: AtRest::Sliding, tolerance: 1e-9, peer: None, system: None, max_error: None }
    }
}

impl Check {
    /// With this `vbar = 0` convention.
    #[must_use]
    pub fn with_at_rest(self, at_rest: AtRest) -> Self {
        Check { at_rest, ..self }
    }
    /// With this tolerance of the value checks.
    #[must_use]
    pub fn with_tolerance(self, tolerance: f64) -> Self {
        Check { tolerance, ..self }
    }
    /// With the stepping peer at this resolution.
    #[must_use]
    pub fn with_peer(self, peer: Option<Stepping>) -> Self {
        Check { peer, ..self }
    }
    /// On this system (or stiff: `None`).
    #[must_use]
    pub fn with_system(self, system: Option<crate::system::System>) -> Self {
        Check { system, ..self }
    }
    /// With this largest `|error|` accepted (or none).
    #[must_use]
    pub fn with_max_error(self, max_error: Option<f64>) -> Self {
        Check { max_error, ..self }
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
    /// The velocity `vhat`, where the table gives it ([`Validation::key_by`]).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub vhat: Option<f64>,
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
    /// What the contact's springs do there ([`crate::Shape::regime`]).
    pub regime: ContactRegime,
    /// The share of the mean normal force carried by springs that lose contact
    /// ([`crate::Shape::jumping_share`]).
    pub jumping_share: f64,
    /// The stepping peer's error at the same point and resolution (with a peer).
    pub peer_error: Option<f64>,
    /// On a system: the attractor's period (`None` there: no period, a mean).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub period: Option<usize>,
    /// On a system: the exact value's error estimate.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub exact_error_estimate: Option<f64>,
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
        Summary::of_errors(rows.map(|r| (r.row, r.error, r.relative_error)))
    }

    /// The summary of `(row, error, relative error)` triples.
    pub(crate) fn of_errors(errors: impl Iterator<Item = (usize, f64, Option<f64>)> + Clone) -> Option<Summary> {
        let rms_error = rms(errors.clone().map(|r| r.1));
        let (mut n, mut max_abs, mut max_rel, mut worst) = (0usize, -1.0f64, 0.0f64, 0usize);
        for (row, error, rel) in errors {
            n += 1;
            if error.abs() > max_abs {
                max_abs = error.abs();
                worst = row;
            }
            max_rel = max_rel.max(rel.map_or(0.0, f64::abs));
        }
        // No error compares (every one NaN): the largest is NaN too.
        let max_abs_error = if max_abs < 0.0 { f64::NAN } else { max_abs };
        (n > 0).then_some(Summary { n, max_abs_error, rms_error, max_rel_error: max_rel, worst_row: worst })
    }
}

/// The errors of one regime.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RegimeSummary {
    /// The regime.
    pub regime: ContactRegime,
    /// The smallest and largest share of the load on springs that lose contact.
    pub jumping_share: [f64; 2],
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
    /// `vbar = 0` values off by as much as the rows that stick and slip.
    StaticLimit,
    /// Errors ten times those of the stepping peer at the same resolution.
    WorseThanPeer,
    /// A convergence study's rows whose errors do not decrease at an order of
    /// at least 0.5.
    NotConverging,
    /// A convergence study's rows whose errors do not depend on the resolution.
    ResolutionIndependent,
    /// Rows whose Richardson value is further from the exact one than the
    /// finest run (a caution, not a finding).
    RichardsonUntrustworthy,
    /// A history's normal force whose mean disagrees with the exact one.
    NormalScale,
    /// A history's normal force that differs in shape from the exact one.
    NormalShape,
    /// A history not yet periodic.
    NotPeriodic,
    /// A history's tangential force above its Coulomb bound.
    AboveBound,
    /// An exact event without counterpart in a history.
    MissingEvent,
    /// Values below -1 (under oscillation in the sliding direction, where
    /// negative values are allowed).
    BelowMinusOne,
    /// A history's normal force below 0: contact loss not modelled.
    NegativeNormal,
    /// A history's tangential force where the normal force is 0: the spring
    /// not relaxed out of contact.
    ForceOutOfContact,
    /// Rows where the contact opens (`du/u0 > 1`) far off while the others agree:
    /// contact loss not modelled as the seed does.
    ContactLoss,
    /// Errors of order one that no other finding explains.
    LargeErrors,
    /// Errors of order one that vanish under another convention (the phase's
    /// sign or origin, degrees, the amplitude's definition), or on a system
    /// under a usual mistake of its equation (the damping left out, `Omega`
    /// for `Omega^2`, the system left out, ...).
    Convention,
    /// Rows whose value is not a number or infinite: the run diverged.
    Diverged,
    /// Rows whose `|error|` exceeds the largest accepted ([`Check::max_error`])
    /// by more than the exact value's error estimate (beyond it whatever
    /// the exact value's own error).
    MaxError,
}

/// Something wrong with the table, and where.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Finding {
    /// What.
    pub kind: FindingKind,
    /// How many rows (or samples) show it; 0 for a finding about the whole input.
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
    /// Errors per regime, in the order of [`ContactRegime`].
    pub by_regime: Vec<RegimeSummary>,
    /// Errors per amplitude, in increasing amplitude.
    pub by_amp: Vec<AmpSummary>,
    /// What looks wrong, with hints (empty: nothing found).
    pub findings: Vec<Finding>,
    /// The stepping peer's errors, with a peer.
    pub peer: Option<PeerSummary>,
    /// The system the rows were compared on, if any.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub system: Option<crate::system::System>,
    /// Every row.
    pub rows: Vec<Row>,
}

/// The stepping peer's errors on the same rows.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PeerSummary {
    /// Its time steps per period.
    pub steps_per_period: usize,
    /// Its springs (the flat punch has one).
    pub springs: usize,
    /// Its largest `|error|`.
    pub max_abs_error: f64,
    /// Its root mean square error.
    pub rms_error: f64,
}

/// The exact value of row `(vbar, amp)` under `at_rest`.
///
/// # Errors
/// The solver's errors for a bad `(vbar, amp)`.
pub(crate) fn exact_value(shape: &Shape, vbar: f64, amp: f64, at_rest: AtRest) -> Result<f64> {
    if vbar == 0.0 && at_rest == AtRest::Relaxed {
        return Ok(0.0);
    }
    Ok(shape.ratio(&crate::Conditions::vbar(vbar, amp)?)?.mu_ratio)
}

/// Most stepping-peer work of one check: rows x steps per period x springs
/// (the stepping peer's own bound on one point, [`crate::stepper::MAX_STEPPING_WORK`]).
pub(crate) const MAX_PEER_WORK: u128 = crate::stepper::MAX_STEPPING_WORK;

/// Check the rows (`vbar, amp` finite and `>= 0`; a value that is not finite
/// is a diverged row, a finding), the tolerance and the peer's work.
fn check_rows(shape: &Shape, rows: &[(f64, f64, f64)], check: &Check) -> Result<()> {
    crate::error::check_nonneg("tolerance", check.tolerance)?;
    if let Some(m) = check.max_error {
        crate::error::check_nonneg("max-error", m)?;
    }
    if rows.is_empty() {
        return Err(Error::Parse {
            context: "table".into(),
            reason: "the table has no rows (nothing to compare)".into(),
        });
    }
    for (i, &(v, a, _)) in rows.iter().enumerate() {
        let at = |e: Error| Error::Parse { context: format!("row {i}"), reason: e.to_string() };
        crate::error::check_nonneg("vbar", v).map_err(at)?;
        crate::error::check_nonneg("amp", a).map_err(at)?;
    }
    check_peer_work(shape, rows.len(), check.peer)?;
    if let (Some(_), Some(st)) = (&check.system, check.peer) {
        // The peer on a system runs SYSTEM_PEER_PERIODS periods, not three.
        check_peer_work(shape, rows.len() * SYSTEM_PEER_PERIODS.div_ceil(3), Some(st))?;
    }
    Ok(())
}

/// The stepping peer's resolution and total work for `rows` rows, checked
/// against [`MAX_PEER_WORK`] before any work.
pub(crate) fn check_peer_work(shape: &Shape, rows: usize, peer: Option<Stepping>) -> Result<()> {
    if let Some(st) = peer {
        st.check(shape)?;
        let springs = if shape.is_flat() { 1 } else { st.springs };
        let work = rows as u128 * st.steps_per_period as u128 * springs as u128;
        if work > MAX_PEER_WORK {
            return Err(Error::TooLarge {
                what: "stepping-peer work (rows x steps per period x springs)".into(),
                count: work,
                limit: MAX_PEER_WORK,
            });
        }
    }
    Ok(())
}

/// The stepping peer's value at a row, by the same `vbar = 0` convention
/// (a relaxed start stays at 0 in any stepper); on a system the stepper
/// with the body.
fn peer_value(shape: &Shape, vbar: f64, amp: f64, check: &Check, st: Stepping) -> Result<f64> {
    if vbar == 0.0 && check.at_rest == AtRest::Relaxed {
        return Ok(0.0);
    }
    let c = crate::Conditions::vbar(vbar, amp)?;
    match check.system {
        Some(sys) => system::peer(shape, &c, sys, st),
        None => Ok(crate::stepper::evaluate(shape, &c, st)?.ratio.mu_ratio),
    }
}

/// Compare `rows` of `(vbar, amp, mu_ratio)` with the exact solver for `shape`,
/// under `check` (the `vbar = 0` convention, the tolerance of the findings,
/// optionally the stepping peer, the system the body is on, the largest
/// error accepted). A value that is not finite is a diverged row: a finding,
/// left out of the summaries.
///
/// # Errors
/// [`Error::Parse`] naming the row for a bad input; [`Error::TooLarge`] for a
/// peer beyond 10^11 spring-steps; the solver's errors.
pub fn compare(shape: &Shape, rows: &[(f64, f64, f64)], check: &Check) -> Result<Validation> {
    check_rows(shape, rows, check)?;
    let (at_rest, tolerance) = (check.at_rest, check.tolerance);
    let exact = crate::numerics::par::map(rows, |&(v, a, _)| system::exact(shape, v, a, check));
    let peer: Option<Vec<f64>> = match check.peer {
        Some(st) => Some(
            crate::numerics::par::map(rows, |&(v, a, _)| peer_value(shape, v, a, check, st))
                .into_iter()
                .collect::<Result<Vec<f64>>>()?,
        ),
        None => None,
    };
    let mut amps: Vec<f64> = rows.iter().map(|r| r.1).collect();
    amps.sort_by(f64::total_cmp);
    amps.dedup();
    let shares: Vec<f64> = amps.iter().map(|&a| shape.jumping_share(a)).collect::<Result<Vec<f64>>>()?;
    let critical = system::critical(shape, &amps, check.system.as_ref())?;
    let at_amp = |a: f64| amps.partition_point(|&x| x < a);
    let mut out = Vec::with_capacity(rows.len());
    for (i, (&(vbar, amp, mu_ratio), e)) in rows.iter().zip(exact).enumerate() {
        let e = e?;
        let error = mu_ratio - e.mu;
        out.push(Row {
            vhat: None,
            row: i,
            vbar,
            amp,
            mu_ratio,
            exact: e.mu,
            error,
            relative_error: (e.mu != 0.0).then(|| error / e.mu),
            regime: system::regime(shape, vbar, amp, critical.as_ref().map(|c| c[at_amp(amp)]))?,
            jumping_share: shares[at_amp(amp)],
            peer_error: peer.as_ref().map(|p| p[i] - e.mu),
            period: e.period,
            exact_error_estimate: e.estimate,
        });
    }
    // Diverged rows are a finding of their own, not part of the statistics.
    let finite: Vec<Row> = out.iter().filter(|r| r.mu_ratio.is_finite()).copied().collect();
    let all = Summary::of(finite.iter())
        .or_else(|| Summary::of(out.iter()))
        .ok_or_else(|| Error::Internal { what: "no rows to summarise".into() })?;
    let mut regimes: Vec<ContactRegime> = finite.iter().map(|r| r.regime).collect();
    regimes.sort();
    regimes.dedup();
    let by_regime = regimes
        .into_iter()
        .filter_map(|g| {
            let group = || finite.iter().filter(move |r| r.regime == g);
            let lo = group().map(|r| r.jumping_share).fold(f64::INFINITY, f64::min);
            let hi = group().map(|r| r.jumping_share).fold(f64::NEG_INFINITY, f64::max);
            Summary::of(group()).map(|summary| RegimeSummary { regime: g, jumping_share: [lo, hi], summary })
        })
        .collect();
    let by_amp = amps
        .iter()
        .filter_map(|&a| {
            Summary::of(finite.iter().filter(|r| r.amp == a)).map(|summary| AmpSummary { amp: a, summary })
        })
        .collect();
    let mut findings = findings::findings(shape, &finite, &amps, check, critical.as_deref())?;
    findings.extend(diverged(out.iter().map(|r| (r.row, r.mu_ratio))));
    findings.extend(beyond_max_error(out.iter().map(|r| (r.row, r.error, r.exact_error_estimate)), check.max_error));
    let peer = check.peer.map(|st| PeerSummary {
        steps_per_period: st.steps_per_period,
        springs: if shape.is_flat() { 1 } else { st.springs },
        max_abs_error: out.iter().filter_map(|r| r.peer_error).fold(0.0f64, |m, e| m.max(e.abs())),
        rms_error: rms(out.iter().filter_map(|r| r.peer_error)),
    });
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
        peer,
        system: check.system,
        rows: out,
    })
}

/// [`FindingKind::Diverged`]: the rows of `(row, value)` whose value is not finite.
pub(crate) fn diverged(values: impl Iterator<Item = (usize, f64)>) -> Option<Finding> {
    finding(
        FindingKind::Diverged,
        values.filter(|v| !v.1.is_finite()).map(|v| v.0).collect(),
        "values that are not finite (NaN or infinite): the run diverged at these rows (a time step beyond the \
         stability limit, a wrong sign of a restoring force, a division by zero); the other rows are compared",
    )
}

/// [`FindingKind::MaxError`]: the rows of `(row, error, the exact value's
/// estimate)` beyond `max_error` by more than that estimate (a NaN error is
/// beyond any bound): a row within it may be exact, its error the exact
/// value's own.
pub(crate) fn beyond_max_error(
    errors: impl Iterator<Item = (usize, f64, Option<f64>)>,
    max_error: Option<f64>,
) -> Option<Finding> {
    let bound = max_error?;
    let (mut rows, mut worst, mut diverged) = (vec![], 0.0f64, false);
    for (i, e, estimate) in errors {
        if e.is_nan() || e.abs() > bound + estimate.unwrap_or(0.0) {
            rows.push(i);
            diverged |= e.is_nan();
            worst = worst.max(e.abs());
        }
    }
    let and = if diverged { ", and rows that diverged" } else { "" };
    let hint = format!(
        "errors above the largest accepted (--max-error {bound:e}) by more than the exact values' estimates: up to \
         {worst:.3e}{and}"
    );
    finding(FindingKind::MaxError, rows, &hint)
}

/// A finding about the whole input (no rows: `count` 0).
pub(crate) fn general(kind: FindingKind, hint: String) -> Finding {
    Finding { kind, count: 0, rows: vec![], hint }
}

pub(crate) fn finding(kind: FindingKind, rows: Vec<usize>, hint: &str) -> Option<Finding> {
    (!rows.is_empty()).then(|| Finding {
        kind,
        count: rows.len(),
        rows: rows.into_iter().take(FINDING_ROWS).collect(),
        hint: hint.into(),
    })
}
