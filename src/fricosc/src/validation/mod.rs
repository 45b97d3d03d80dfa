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
mod history;
mod oscillation;
mod series;
mod table;
mod text;

pub use oscillation::{compare_oscillation, OscillationRegime, OscillationRow, OscillationValidation};

pub use history::{
    compare_history, to_static_units, EventSeries, FoundEvent, HistoryData, HistorySample, HistorySeries,
    HistoryValidation, NormalComparison, OriginSource, TimeAxis, TimeOrigin,
};
pub(crate) use series::observed_order;
pub use series::{convergence, Convergence, Needed, RegimeOrder, RowStatus, SeriesRow};
pub use table::{Column, Table};
pub(crate) use text::findings_text;

use crate::contact::regime::ContactRegime;
use crate::error::{Error, Result};
use crate::model::spring::Spring;
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
}

impl Default for Check {
    fn default() -> Self {
        Check { at_rest: AtRest::Sliding, tolerance: 1e-9, peer: None }
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
    /// What the contact's springs do there ([`crate::report::regime`]).
    pub regime: ContactRegime,
    /// The share of the mean normal force carried by springs that lose contact
    /// ([`crate::contact::regime::jumping_share`]).
    pub jumping_share: f64,
    /// The stepping peer's error at the same point and resolution (with a peer).
    pub peer_error: Option<f64>,
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
        (n > 0).then_some(Summary { n, max_abs_error: max_abs, rms_error, max_rel_error: max_rel, worst_row: worst })
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
    /// Errors of order one that no other finding explains.
    LargeErrors,
    /// Errors of order one that vanish under another convention (the phase's
    /// sign or origin, degrees, the amplitude's definition).
    Convention,
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

/// Check the rows (finite, `vbar, amp >= 0`), the tolerance and the peer's work.
fn check_rows(shape: &Shape, rows: &[(f64, f64, f64)], check: &Check) -> Result<()> {
    crate::error::check_nonneg("tolerance", check.tolerance)?;
    if rows.is_empty() {
        return Err(Error::Parse {
            context: "table".into(),
            reason: "the table has no rows (nothing to compare)".into(),
        });
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
    check_peer_work(shape, rows.len(), check.peer)
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
/// (a relaxed start stays at 0 in any stepper).
fn peer_value(shape: &Shape, vbar: f64, amp: f64, at_rest: AtRest, st: Stepping) -> Result<f64> {
    if vbar == 0.0 && at_rest == AtRest::Relaxed {
        return Ok(0.0);
    }
    Ok(crate::stepper::evaluate(shape, &crate::Conditions::vbar(vbar, amp)?, st)?.ratio.mu_ratio)
}

/// Compare `rows` of `(vbar, amp, mu_ratio)` with the exact solver for `shape`,
/// under `check` (the `vbar = 0` convention, the tolerance of the findings, and
/// optionally the stepping peer).
///
/// # Errors
/// [`Error::Parse`] naming the row for a bad value; [`Error::TooLarge`] for a
/// peer beyond 10^11 spring-steps; the solver's errors.
pub fn compare(shape: &Shape, rows: &[(f64, f64, f64)], check: &Check) -> Result<Validation> {
    check_rows(shape, rows, check)?;
    let (at_rest, tolerance) = (check.at_rest, check.tolerance);
    let exact: Vec<Result<f64>> = crate::numerics::par::map(rows, |&(v, a, _)| exact_value(shape, v, a, at_rest));
    let peer: Option<Vec<f64>> = match check.peer {
        Some(st) => Some(
            crate::numerics::par::map(rows, |&(v, a, _)| peer_value(shape, v, a, at_rest, st))
                .into_iter()
                .collect::<Result<Vec<f64>>>()?,
        ),
        None => None,
    };
    let mut amps: Vec<f64> = rows.iter().map(|r| r.1).collect();
    amps.sort_by(f64::total_cmp);
    amps.dedup();
    let shares: Vec<f64> =
        amps.iter().map(|&a| crate::contact::regime::jumping_share(shape, a)).collect::<Result<Vec<f64>>>()?;
    let share_of = |a: f64| shares[amps.partition_point(|&x| x < a)];
    let mut out = Vec::with_capacity(rows.len());
    for (i, (&(vbar, amp, mu_ratio), e)) in rows.iter().zip(exact).enumerate() {
        let exact = e?;
        let error = mu_ratio - exact;
        let peer_error = peer.as_ref().map(|p| p[i] - exact);
        out.push(Row {
            row: i,
            vbar,
            amp,
            mu_ratio,
            exact,
            error,
            relative_error: (exact != 0.0).then(|| error / exact),
            regime: crate::contact::regime::regime(shape, vbar, amp)?,
            jumping_share: share_of(amp),
            peer_error,
        });
    }
    let all = Summary::of(out.iter()).ok_or_else(|| Error::Internal { what: "no rows to summarise".into() })?;
    let mut regimes: Vec<ContactRegime> = out.iter().map(|r| r.regime).collect();
    regimes.sort();
    regimes.dedup();
    let by_regime = regimes
        .into_iter()
        .filter_map(|g| {
            let group = || out.iter().filter(move |r| r.regime == g);
            let lo = group().map(|r| r.jumping_share).fold(f64::INFINITY, f64::min);
            let hi = group().map(|r| r.jumping_share).fold(f64::NEG_INFINITY, f64::max);
            Summary::of(group()).map(|summary| RegimeSummary { regime: g, jumping_share: [lo, hi], summary })
        })
        .collect();
    let by_amp = amps
        .iter()
        .filter_map(|&a| Summary::of(out.iter().filter(|r| r.amp == a)).map(|summary| AmpSummary { amp: a, summary }))
        .collect();
    let findings = findings(shape, &out, &amps, at_rest, tolerance)?;
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
        rows: out,
    })
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
    out.extend(finding(
        FindingKind::NotMonotone,
        decreasing(rows, amps, tol),
        "mu/mu0 decreases with velocity at these rows (the exact curve never does): check convergence there \
         (time step, number of periods, springs)",
    ));
    out.extend(finding(
        FindingKind::NotSteady,
        not_steady(rows, amps, tol),
        "errors grow towards vbar -> 0, ten times those at the same amplitude's higher velocities: the \
         steady state takes longer to reach at low velocity (the tangential force builds up at a rate \
         proportional to vbar); run more periods and average the last one",
    ));
    at_rest_findings(shape, rows, amps, at_rest, tol, &mut out)?;
    out.extend(finding(
        FindingKind::WorseThanPeer,
        worse_than_peer(rows, amps, tol),
        "errors ten times (or more) those of fricosc's stepping peer (the seed's scheme) at the same resolution: \
         not the discretisation but a bug (see the peer_error column)",
    ));
    if out.is_empty() {
        let worst = rows.iter().fold(0.0f64, |m, r| m.max(r.error.abs()));
        out.extend(convention::large_errors(convention::large(rows.iter().map(|r| (r.row, r.error))), worst));
    }
    Ok(out)
}

/// Rows where `mu` decreases in `vbar` at one amplitude (rows sorted by vbar;
/// vbar = 0 rows follow the chosen convention, so a relaxed 0 is not a decrease).
fn decreasing(rows: &[Row], amps: &[f64], tol: f64) -> Vec<usize> {
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
    decreasing
}

/// Rows whose errors are far larger at low velocity than at the same
/// amplitude's higher velocities (below the critical one): the transient.
/// Compared within one amplitude, so that a scheme's larger error in the
/// jumping regimes is not mistaken for it. Only where some spring never loses
/// contact (`amp < 1`): a spring that loses contact enters it relaxed every
/// period, so its steady state is reached in the first; and with a peer, only
/// rows ten times worse than the peer at the same resolution (a peer as far
/// off has the same discretisation, not a transient).
fn not_steady(rows: &[Row], amps: &[f64], tol: f64) -> Vec<usize> {
    let mut slow = vec![];
    for &a in amps.iter().filter(|&&a| a < 1.0) {
        let rest: Vec<f64> =
            rows.iter().filter(|r| r.amp == a && r.vbar >= LOW_VBAR && r.vbar < 1.0).map(|r| r.error.abs()).collect();
        if rest.is_empty() {
            continue;
        }
        let bar = (NOT_STEADY_FACTOR * rest.iter().sum::<f64>() / rest.len() as f64).max(tol);
        slow.extend(
            rows.iter()
                .filter(|r| r.amp == a && r.vbar > 0.0 && r.vbar < LOW_VBAR && r.error.abs() > bar)
                .filter(|r| r.peer_error.is_none_or(|p| r.error.abs() > 10.0 * p.abs()))
                .map(|r| r.row),
        );
    }
    slow.sort_unstable();
    slow
}

/// The findings about `vbar = 0` rows: those that match the other convention
/// rather than the chosen one, and those off by as much as the sliding rows.
fn at_rest_findings(
    shape: &Shape,
    rows: &[Row],
    amps: &[f64],
    at_rest: AtRest,
    tol: f64,
    out: &mut Vec<Finding>,
) -> Result<()> {
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
    out.extend(finding(FindingKind::AtRestConvention, mismatched.clone(), hint));
    out.extend(finding(
        FindingKind::StaticLimit,
        static_limit(rows, amps, at_rest, tol, &mismatched),
        "at vbar = 0 nothing sticks or slips (mu/mu0 is the closed form N_min/N_mean: 1 - amp for the flat \
         punch up to amp = 1), so a stepper gets these rows far more accurately than the rows at sliding \
         velocities, yet they are as far off: the error is in what every row shares: the averaging (over whole \
         periods?), the normalisation by the mean normal force, or the start",
    ));
    Ok(())
}

/// A `vbar = 0` row's error is a finding when it exceeds this share of the
/// median error of the same amplitude's rows at `0 < vbar < 1`: a stepper's
/// error there is the spring grid's alone (none for the flat punch), which
/// enters every other row too, on top of the stick-slip's.
const STATIC_SHARE: f64 = 0.25;

/// [`FindingKind::StaticLimit`]: `vbar = 0` rows (compared with the sliding
/// limit, and not already explained by the other convention) off by more than
/// [`STATIC_SHARE`] of the median error at the same amplitude's sliding
/// velocities below 1 (or by more than the tolerance, where there are none).
fn static_limit(rows: &[Row], amps: &[f64], at_rest: AtRest, tol: f64, explained: &[usize]) -> Vec<usize> {
    if at_rest != AtRest::Sliding {
        return vec![];
    }
    let mut out = vec![];
    for &a in amps {
        let mut moving: Vec<f64> =
            rows.iter().filter(|r| r.amp == a && r.vbar > 0.0 && r.vbar < 1.0).map(|r| r.error.abs()).collect();
        moving.sort_by(f64::total_cmp);
        let bar = match moving.len() {
            0 => tol,
            n => (STATIC_SHARE * moving[n / 2]).max(tol),
        };
        out.extend(
            rows.iter()
                .filter(|r| r.amp == a && r.vbar == 0.0 && r.error.abs() > bar && !explained.contains(&r.row))
                .map(|r| r.row),
        );
    }
    out.sort_unstable();
    out
}

/// How many times the peer's error a row's error may be before it is a
/// [`FindingKind::WorseThanPeer`] finding.
const PEER_FACTOR: f64 = 10.0;

/// [`FindingKind::WorseThanPeer`]: rows whose error exceeds [`PEER_FACTOR`]
/// times the peer's there or (where the peer happens to be near a zero of its
/// error) the median of the peer's errors at the same amplitude.
fn worse_than_peer(rows: &[Row], amps: &[f64], tol: f64) -> Vec<usize> {
    let mut out = vec![];
    for &a in amps {
        let mut peer: Vec<f64> =
            rows.iter().filter(|r| r.amp == a).filter_map(|r| r.peer_error.map(f64::abs)).collect();
        if peer.is_empty() {
            continue;
        }
        peer.sort_by(f64::total_cmp);
        let median = peer[peer.len() / 2];
        out.extend(
            rows.iter()
                .filter(|r| r.amp == a)
                .filter(|r| r.peer_error.is_some_and(|p| r.error.abs() > (PEER_FACTOR * p.abs().max(median)).max(tol)))
                .map(|r| r.row),
        );
    }
    out.sort_unstable();
    out
}
