//! Validation of a table under oscillation in the sliding direction
//! ([`crate::combined`]): rows `(vhat, amp, tangential_amp, phase, mu_ratio)`
//! compared with the exact solver, errors per regime (the flat punch's
//! spring, or a curved contact's band sequence), and findings: values outside
//! `[-1, 1]` (negative values are allowed here: the oscillation may push the
//! body forward), and errors ten times the stepping peer's.

use super::{finding, FindingKind, Summary};
use crate::error::{Error, Result};
use crate::shape::Shape;
use crate::Conditions;

/// One compared row.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct OscillationRow {
    /// Input index.
    pub row: usize,
    /// `vhat` (eq. 15).
    pub vhat: f64,
    /// `du/u0`.
    pub amp: f64,
    /// `dx/l`.
    pub tangential_amp: f64,
    /// Radians, as given.
    pub phase: f64,
    /// The table's value.
    pub mu_ratio: f64,
    /// The exact value.
    pub exact: f64,
    /// `mu_ratio - exact`.
    pub error: f64,
    /// `error / |exact|` where `exact != 0`.
    pub relative_error: Option<f64>,
    /// The flat punch's spring regime (`jumping: stick, backward, ...`), or a
    /// curved contact's bands joined by ` | `.
    pub regime: String,
    /// With a peer: the stepping peer's error on the same row.
    pub peer_error: Option<f64>,
    /// On a system: the exact value's error estimate (a curved body's, or a
    /// mean's where the response has no period).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub exact_error_estimate: Option<f64>,
}

/// The periods the stepping peer runs on a system (the attractor must be
/// reached within them; the last period is its answer).
pub const SYSTEM_PEER_PERIODS: usize = 40;

/// One row's exact answer: `mu`, its regime, its error estimate on a system.
fn exact_row(
    shape: &Shape,
    c: &Conditions,
    system: Option<&crate::system::System>,
) -> Result<(f64, String, Option<f64>)> {
    if let Some(&sys) = system {
        let crate::Report::System(r) = shape.report(&c.with_system(sys))? else {
            return Err(Error::Internal { what: "a report on a system is the system's".into() });
        };
        return Ok((r.mu_ratio, r.regime(), Some(r.error_estimate)));
    }
    let e = crate::combined::evaluate(shape, c)?;
    let regime = match &e.spring {
        Some(s) => s.regime.clone(),
        None if c.tangential().is_none_or(|t| t.0 == 0.0) => "no tangential oscillation (the seed's problem)".into(),
        None if e.bands.is_empty() => "slides forward all the time".into(),
        None => e.bands.iter().map(|b| b.regime.as_str()).collect::<Vec<_>>().join(" | "),
    };
    Ok((e.ratio.mu_ratio, regime, None))
}

/// The errors of one regime.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct OscillationRegime {
    /// The regime ([`OscillationRow::regime`]).
    pub regime: String,
    /// Its rows' errors.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub summary: Summary,
}

/// The comparison of a whole table.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct OscillationValidation {
    /// Shape name.
    pub shape: String,
    /// Tolerance of the range checks.
    pub tolerance: f64,
    /// All rows' errors.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub summary: Summary,
    /// Errors per regime (in order of first appearance).
    pub by_regime: Vec<OscillationRegime>,
    /// What looks wrong (empty: nothing found).
    pub findings: Vec<super::Finding>,
    /// The stepping peer's resolution and errors, with a peer.
    pub peer: Option<super::PeerSummary>,
    /// The system the rows were compared on, if any.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub system: Option<crate::system::System>,
    /// Every row.
    pub rows: Vec<OscillationRow>,
}

/// Compare `rows` of `[vhat, amp, tangential_amp, phase, mu_ratio]` with the
/// exact values of `shape` (at [`crate::DEFAULT_TOL`]), or on `check.system`
/// with its attractors ([`crate::Conditions::with_system`]; the regime is the period);
/// `check.peer` runs the stepping peer ([`crate::stepper::evaluate`], three
/// periods; on a system [`crate::stepper::system`], 40 periods)
/// on every row too. `check.at_rest` does not apply (a `vhat = 0` row is the
/// limit `vhat -> 0+`).
///
/// # Errors
/// [`Error::Parse`] naming the first bad row (inputs out of range, a value
/// that is not finite), [`Error::TooLarge`] for a peer beyond
/// 10^11 spring-steps, the solver's errors.
pub fn compare_oscillation(shape: &Shape, rows: &[[f64; 5]], check: &super::Check) -> Result<OscillationValidation> {
    let oscillations = checked(shape, rows, check)?;
    let system = check.system.as_ref();
    let exact = crate::numerics::par::map(&oscillations, |c| exact_row(shape, c, system));
    let peer = peer_values(shape, &oscillations, check)?;
    let mut out = Vec::with_capacity(rows.len());
    for (i, (r, e)) in rows.iter().zip(exact).enumerate() {
        let (x, regime, estimate) = e?;
        out.push(OscillationRow {
            row: i,
            vhat: r[0],
            amp: r[1],
            tangential_amp: r[2],
            phase: r[3],
            mu_ratio: r[4],
            exact: x,
            error: r[4] - x,
            relative_error: (x != 0.0).then(|| (r[4] - x) / x.abs()),
            regime,
            peer_error: peer.as_ref().map(|p| p[i] - x),
            exact_error_estimate: estimate,
        });
    }
    let errors = |rows: &[&OscillationRow]| {
        Summary::of_errors(rows.iter().map(|r| (r.row, r.error, r.relative_error)).collect::<Vec<_>>().into_iter())
    };
    // Diverged rows are a finding of their own, not part of the statistics.
    let finite: Vec<&OscillationRow> = out.iter().filter(|r| r.mu_ratio.is_finite()).collect();
    let all: Vec<&OscillationRow> = out.iter().collect();
    let summary = errors(&finite)
        .or_else(|| errors(&all))
        .ok_or_else(|| Error::Internal { what: "no rows to summarise".into() })?;
    let mut names: Vec<&str> = vec![];
    for r in &finite {
        if !names.contains(&r.regime.as_str()) {
            names.push(&r.regime);
        }
    }
    let by_regime = names
        .iter()
        .filter_map(|&n| {
            let rows: Vec<&OscillationRow> = finite.iter().copied().filter(|r| r.regime == n).collect();
            errors(&rows).map(|summary| OscillationRegime { regime: n.to_string(), summary })
        })
        .collect();
    let tol = check.tolerance;
    let pick = |f: &dyn Fn(&OscillationRow) -> bool| out.iter().filter(|r| f(r)).map(|r| r.row).collect::<Vec<_>>();
    let mut findings = vec![];
    findings.extend(finding(
        FindingKind::AboveOne,
        pick(&|r| r.mu_ratio > 1.0 + tol),
        "values above 1: check the normalisation by the mean normal force (mu0 times the period-averaged \
         normal force)",
    ));
    findings.extend(finding(
        FindingKind::BelowMinusOne,
        pick(&|r| r.mu_ratio < -1.0 - tol),
        "values below -1: the tangential force never exceeds mu0 times the normal force in either direction; \
         check the sign convention and the normalisation",
    ));
    let peer_summary = check.peer.zip(peer.as_ref()).map(|(st, p)| {
        let errs: Vec<f64> = p.iter().zip(&out).map(|(v, r)| v - r.exact).collect();
        super::PeerSummary {
            steps_per_period: st.steps_per_period,
            springs: if shape.is_flat() { 1 } else { st.springs },
            max_abs_error: errs.iter().fold(0.0f64, |m, e| m.max(e.abs())),
            rms_error: super::rms(errs.iter().copied()),
        }
    });
    findings.extend(finding(
        FindingKind::WorseThanPeer,
        pick(&|r| r.peer_error.is_some_and(|p| r.error.abs() > 10.0 * p.abs() && r.error.abs() > tol)),
        "errors ten times (or more) those of fricosc's stepping peer at the same resolution: not the \
         discretisation but a bug (see the peer_error column)",
    ));
    if system.is_none() {
        // A diverged row (its own finding) is not an error of order one.
        let errors: Vec<f64> = out.iter().map(|r| if r.mu_ratio.is_finite() { r.error } else { 0.0 }).collect();
        findings.extend(super::convention::oscillation_finding(shape, rows, &errors));
    }
    findings.extend(super::diverged(out.iter().map(|r| (r.row, r.mu_ratio))));
    findings.extend(super::beyond_max_error(out.iter().map(|r| (r.row, r.error)), check.max_error));
    Ok(OscillationValidation {
        shape: shape.name().to_string(),
        tolerance: tol,
        summary,
        by_regime,
        findings,
        peer: peer_summary,
        system: check.system,
        rows: out,
    })
}

/// The stepping peer's value at every row, with a peer: on a system the
/// stepper with the body ([`SYSTEM_PEER_PERIODS`] periods).
fn peer_values(shape: &Shape, oscillations: &[Conditions], check: &super::Check) -> Result<Option<Vec<f64>>> {
    let Some(st) = check.peer else { return Ok(None) };
    let values = crate::numerics::par::map(oscillations, |o| match check.system {
        Some(sys) => super::system::peer(shape, o, sys, st),
        None => crate::stepper::evaluate(shape, o, st).map(|e| e.ratio.mu_ratio),
    });
    Ok(Some(values.into_iter().collect::<Result<Vec<f64>>>()?))
}

/// Every row's oscillation, checked (the first bad row named), and the peer's work.
fn checked(shape: &Shape, rows: &[[f64; 5]], check: &super::Check) -> Result<Vec<Conditions>> {
    crate::error::check_nonneg("tolerance", check.tolerance)?;
    if rows.is_empty() {
        return Err(Error::Parse {
            context: "table".into(),
            reason: "the table has no rows (nothing to compare)".into(),
        });
    }
    let mut oscillations = Vec::with_capacity(rows.len());
    for (i, r) in rows.iter().enumerate() {
        let at = |reason: String| Error::Parse { context: format!("row {i}"), reason };
        let c = Conditions::vhat(r[0], r[1]).and_then(|c| c.with_tangential(r[2], r[3]));
        oscillations.push(c.map_err(|e| at(e.to_string()))?);
    }
    if let Some(m) = check.max_error {
        crate::error::check_nonneg("max-error", m)?;
    }
    super::check_peer_work(shape, rows.len(), check.peer)?;
    if let (Some(_), Some(st)) = (&check.system, check.peer) {
        // The peer on a system runs SYSTEM_PEER_PERIODS periods, not three.
        super::check_peer_work(shape, rows.len() * SYSTEM_PEER_PERIODS.div_ceil(3), Some(st))?;
    }
    Ok(oscillations)
}
