//! Validation of a table under oscillation in the sliding direction
//! ([`crate::combined`]) or across it ([`crate::plane`]): rows
//! ([`OscillationInput`]) compared with the exact solver, errors per regime
//! (the flat punch's spring, a curved contact's band sequence, the events
//! of a period in the plane), and findings: values outside `[-1, 1]`
//! (negative values are allowed here: the oscillation may push the body
//! forward), conventions that explain errors of order one, and errors ten
//! times the stepping peer's (in the plane, [`crate::stepper::transverse`]).
//! A table that gives the mean force across (`transverse_ratio`) has it
//! compared as well: its errors are summarised apart, and count towards
//! `max_error`.

use super::{finding, FindingKind, Summary};
use crate::error::{Error, Result};
use crate::shape::Shape;
use crate::Conditions;

/// One row of a table under oscillation: the conditions and the table's values.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct OscillationInput {
    /// `vhat` (eq. 15).
    pub vhat: f64,
    /// `du/u0`.
    pub amp: f64,
    /// `dx/l` (0: none).
    pub tangential_amp: f64,
    /// Radians.
    pub phase: f64,
    /// `dy/l`, across the sliding direction (0: none).
    pub transverse_amp: f64,
    /// Radians, against the normal oscillation.
    pub transverse_phase: f64,
    /// The table's `mu_macro/mu0`.
    pub mu_ratio: f64,
    /// The table's mean force across, `<f_y>/<B>`, if it gives one.
    pub transverse_ratio: Option<f64>,
}

impl OscillationInput {
    /// A row at `vhat`, `amp` with the table's `mu_ratio`, without tangential
    /// or transverse oscillation (add them with the `with_` methods).
    #[must_use]
    pub fn new(vhat: f64, amp: f64, mu_ratio: f64) -> OscillationInput {
        OscillationInput {
            vhat,
            amp,
            tangential_amp: 0.0,
            phase: 0.0,
            transverse_amp: 0.0,
            transverse_phase: 0.0,
            mu_ratio,
            transverse_ratio: None,
        }
    }

    /// The oscillation in the sliding direction, `T sin(tau + phase)`.
    #[must_use]
    pub fn with_tangential(self, tangential_amp: f64, phase: f64) -> OscillationInput {
        OscillationInput { tangential_amp, phase, ..self }
    }

    /// The oscillation across it, `W sin(tau + psi)`, and the table's mean
    /// force across, if it gives one.
    #[must_use]
    pub fn with_transverse(self, amp: f64, phase: f64, ratio: Option<f64>) -> OscillationInput {
        OscillationInput { transverse_amp: amp, transverse_phase: phase, transverse_ratio: ratio, ..self }
    }

    /// The row's conditions, checked.
    pub(crate) fn conditions(&self) -> Result<Conditions> {
        let c = Conditions::vhat(self.vhat, self.amp)?.with_tangential(self.tangential_amp, self.phase)?;
        if self.transverse_amp == 0.0 && self.transverse_phase == 0.0 {
            return Ok(c);
        }
        Ok(c.with_transverse(crate::plane::Transverse::new(self.transverse_amp, self.transverse_phase)?))
    }
}

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
    /// The exact value's error estimate.
    pub exact_error_estimate: f64,
    /// Across the sliding direction: the row's oscillation and the mean
    /// force across, the table's against the exact one.
    #[cfg_attr(feature = "serde", serde(flatten, skip_serializing_if = "Option::is_none"))]
    pub transverse: Option<TransverseRow>,
}

/// A row's oscillation across the sliding direction and its mean force across.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct TransverseRow {
    /// `dy/l`.
    pub transverse_amp: f64,
    /// Radians, as given.
    pub transverse_phase: f64,
    /// The exact `<f_y>/<B>`.
    pub transverse_exact: f64,
    /// The table's, if it gives one.
    pub transverse_ratio: Option<f64>,
    /// `transverse_ratio - transverse_exact`.
    pub transverse_error: Option<f64>,
    /// With a peer: the stepping peer's error of the force across.
    pub transverse_peer_error: Option<f64>,
}

/// The periods the stepping peer runs on a system (the attractor must be
/// reached within them; the last period is its answer).
pub const SYSTEM_PEER_PERIODS: usize = 40;

/// One row's exact answer: `mu`, its regime, its error estimate, the mean
/// force across in the plane.
struct Exact {
    mu: f64,
    regime: String,
    estimate: f64,
    transverse: Option<f64>,
}

fn exact_row(shape: &Shape, c: &Conditions, system: Option<&crate::system::System>) -> Result<Exact> {
    let of = |mu: f64, regime: String, estimate: f64| Exact { mu, regime, estimate, transverse: None };
    if let Some(&sys) = system {
        let crate::Report::System(r) = shape.report(&c.with_system(sys))? else {
            return Err(Error::Internal { what: "a report on a system is the system's".into() });
        };
        return Ok(of(r.mu_ratio, r.regime(), r.error_estimate));
    }
    if c.transverse().is_some() {
        let crate::Report::Plane(p) = shape.report(c)? else {
            return Err(Error::Internal { what: "a report in the plane is the plane's".into() });
        };
        let regime = match p.events.is_empty() {
            true => "in the plane".to_string(),
            false => {
                let kinds: Vec<&str> = p.events.iter().map(|e| e.kind.name()).collect();
                format!("in the plane: {}", kinds.join(", "))
            }
        };
        return Ok(Exact { transverse: Some(p.transverse_ratio), ..of(p.ratio.mu_ratio, regime, p.error_estimate) });
    }
    let e = crate::combined::evaluate(shape, c)?;
    let regime = match &e.spring {
        Some(s) => s.regime.clone(),
        None if c.tangential().is_none_or(|t| t.0 == 0.0) => "no tangential oscillation (the seed's problem)".into(),
        None if e.bands.is_empty() => "slides forward all the time".into(),
        None => e.bands.iter().map(|b| b.regime.as_str()).collect::<Vec<_>>().join(" | "),
    };
    Ok(of(e.ratio.mu_ratio, regime, e.error_estimate))
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
    /// The errors of the mean force across the sliding direction, where the
    /// table gives it (`transverse_ratio`).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub transverse: Option<Summary>,
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

/// Compare `rows` with the exact values of `shape` (at
/// [`crate::DEFAULT_TOL`]), or on `check.system` with its attractors
/// ([`crate::Conditions::with_system`]; the regime is the period);
/// `check.peer` runs the stepping peer ([`crate::stepper::evaluate`], three
/// periods; on a system [`crate::stepper::system`], 40 periods; in the plane
/// [`crate::stepper::transverse`], three periods) on every row too.
/// `check.at_rest` does not apply (a `vhat = 0` row is the limit `vhat ->
/// 0+`).
///
/// # Errors
/// [`Error::Parse`] naming the first bad row (inputs out of range, a value
/// that is not finite, a row across the sliding direction on a system),
/// [`Error::TooLarge`] for a peer beyond 10^11 spring-steps, the solver's
/// errors.
pub fn compare_oscillation(
    shape: &Shape,
    rows: &[OscillationInput],
    check: &super::Check,
) -> Result<OscillationValidation> {
    let oscillations = checked(shape, rows, check)?;
    let system = check.system.as_ref();
    let exact = crate::numerics::par::map(&oscillations, |c| exact_row(shape, c, system));
    let peer = peer_values(shape, &oscillations, check)?;
    let mut out = Vec::with_capacity(rows.len());
    for (i, (r, e)) in rows.iter().zip(exact).enumerate() {
        let x = e?;
        let p = peer.as_ref().map(|p| p[i]);
        out.push(OscillationRow {
            row: i,
            vhat: r.vhat,
            amp: r.amp,
            tangential_amp: r.tangential_amp,
            phase: r.phase,
            mu_ratio: r.mu_ratio,
            exact: x.mu,
            error: r.mu_ratio - x.mu,
            relative_error: (x.mu != 0.0).then(|| (r.mu_ratio - x.mu) / x.mu.abs()),
            regime: x.regime,
            peer_error: p.map(|p| p[0] - x.mu),
            exact_error_estimate: x.estimate,
            // A row along the sliding direction only has no force across.
            transverse: x.transverse.or(r.transverse_ratio.map(|_| 0.0)).map(|t| TransverseRow {
                transverse_amp: r.transverse_amp,
                transverse_phase: r.transverse_phase,
                transverse_exact: t,
                transverse_ratio: r.transverse_ratio,
                transverse_error: r.transverse_ratio.map(|v| v - t),
                transverse_peer_error: p.map(|p| p[1] - t),
            }),
        });
    }
    let summary = summaries(&out)?;
    let findings = findings_of(shape, rows, &out, check);
    let peer_summary = check.peer.zip(peer.as_ref()).map(|(st, p)| {
        let errs: Vec<f64> = p.iter().zip(&out).map(|(v, r)| v[0] - r.exact).collect();
        super::PeerSummary {
            steps_per_period: st.steps_per_period,
            springs: if shape.is_flat() { 1 } else { st.springs },
            max_abs_error: errs.iter().fold(0.0f64, |m, e| m.max(e.abs())),
            rms_error: super::rms(errs.iter().copied()),
        }
    });
    Ok(OscillationValidation {
        shape: shape.name().to_string(),
        tolerance: check.tolerance,
        summary: summary.0,
        transverse: summary.1,
        by_regime: summary.2,
        findings,
        peer: peer_summary,
        system: check.system,
        rows: out,
    })
}

/// The errors of all rows (the finite ones where any), of the mean force
/// across (where the table gives it), and per regime.
fn summaries(out: &[OscillationRow]) -> Result<(Summary, Option<Summary>, Vec<OscillationRegime>)> {
    let errors = |rows: &[&OscillationRow]| {
        Summary::of_errors(rows.iter().map(|r| (r.row, r.error, r.relative_error)).collect::<Vec<_>>().into_iter())
    };
    // Diverged rows are a finding of their own, not part of the statistics.
    let finite: Vec<&OscillationRow> = out.iter().filter(|r| r.mu_ratio.is_finite()).collect();
    let all: Vec<&OscillationRow> = out.iter().collect();
    let summary = errors(&finite)
        .or_else(|| errors(&all))
        .ok_or_else(|| Error::Internal { what: "no rows to summarise".into() })?;
    let across = out.iter().filter_map(|r| {
        let t = r.transverse.as_ref()?;
        let e = t.transverse_error.filter(|e| e.is_finite())?;
        Some((r.row, e, (t.transverse_exact != 0.0).then(|| e / t.transverse_exact.abs())))
    });
    let transverse = Summary::of_errors(across.collect::<Vec<_>>().into_iter());
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
    Ok((summary, transverse, by_regime))
}

/// What looks wrong in the compared rows `out` (module docs).
fn findings_of(
    shape: &Shape,
    rows: &[OscillationInput],
    out: &[OscillationRow],
    check: &super::Check,
) -> Vec<super::Finding> {
    let tol = check.tolerance;
    let pick = |f: &dyn Fn(&OscillationRow) -> bool| out.iter().filter(|r| f(r)).map(|r| r.row).collect::<Vec<_>>();
    let across = |r: &OscillationRow| r.transverse.as_ref().and_then(|t| t.transverse_ratio);
    let mut findings = vec![];
    findings.extend(finding(
        FindingKind::AboveOne,
        pick(&|r| r.mu_ratio > 1.0 + tol || across(r).is_some_and(|v| v > 1.0 + tol)),
        "values above 1: check the normalisation by the mean normal force (mu0 times the period-averaged \
         normal force)",
    ));
    findings.extend(finding(
        FindingKind::BelowMinusOne,
        pick(&|r| r.mu_ratio < -1.0 - tol || across(r).is_some_and(|v| v < -1.0 - tol)),
        "values below -1: the tangential force never exceeds mu0 times the normal force in either direction; \
         check the sign convention and the normalisation",
    ));
    let worse = |e: f64, p: Option<f64>| p.is_some_and(|p| e.abs() > 10.0 * p.abs() && e.abs() > tol);
    findings.extend(finding(
        FindingKind::WorseThanPeer,
        pick(&|r| {
            worse(r.error, r.peer_error)
                || r.transverse
                    .as_ref()
                    .is_some_and(|t| t.transverse_error.is_some_and(|e| worse(e, t.transverse_peer_error)))
        }),
        "errors ten times (or more) those of fricosc's stepping peer at the same resolution: not the \
         discretisation but a bug (see the peer_error column)",
    ));
    if check.system.is_none() {
        // A diverged row (its own finding) is not an error of order one.
        let errors: Vec<f64> = out.iter().map(|r| if r.mu_ratio.is_finite() { worst_error(r) } else { 0.0 }).collect();
        findings.extend(super::convention::oscillation_finding(shape, rows, &errors));
    }
    findings.extend(super::diverged(out.iter().map(|r| (r.row, r.mu_ratio))));
    findings.extend(super::diverged(out.iter().filter_map(|r| across(r).map(|v| (r.row, v)))));
    let errors = out.iter().map(|r| (r.row, worst_error(r), Some(r.exact_error_estimate)));
    findings.extend(super::beyond_max_error(errors, check.max_error));
    findings
}

/// The larger of a row's errors along and across (NaN where either is).
fn worst_error(r: &OscillationRow) -> f64 {
    let across = r.transverse.as_ref().and_then(|t| t.transverse_error).unwrap_or(0.0);
    if r.error.is_nan() || across.is_nan() {
        return f64::NAN;
    }
    r.error.abs().max(across.abs())
}

/// The stepping peer's `[mu_ratio, transverse_ratio]` at every row, with a
/// peer: on a system the stepper with the body ([`SYSTEM_PEER_PERIODS`]
/// periods), in the plane the plane's stepper.
fn peer_values(shape: &Shape, oscillations: &[Conditions], check: &super::Check) -> Result<Option<Vec<[f64; 2]>>> {
    let Some(st) = check.peer else { return Ok(None) };
    let values = crate::numerics::par::map(oscillations, |o| match (check.system, o.transverse()) {
        (Some(sys), _) => super::system::peer(shape, o, sys, st).map(|m| [m, 0.0]),
        (None, Some(w)) => crate::stepper::transverse(shape, o, w, st, 3).map(|e| [e.mu_ratio, e.transverse_ratio]),
        (None, None) => crate::stepper::evaluate(shape, o, st).map(|e| [e.ratio.mu_ratio, 0.0]),
    });
    Ok(Some(values.into_iter().collect::<Result<Vec<_>>>()?))
}

/// Every row's oscillation, checked (the first bad row named), and the peer's work.
fn checked(shape: &Shape, rows: &[OscillationInput], check: &super::Check) -> Result<Vec<Conditions>> {
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
        let c = r.conditions().map_err(|e| at(e.to_string()))?;
        if c.transverse().is_some() && check.system.is_some() {
            return Err(at("an oscillation across the sliding direction on a system is not solved yet".into()));
        }
        oscillations.push(c);
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
