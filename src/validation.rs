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

impl Summary {
    fn of<'a>(rows: impl Iterator<Item = &'a Row>) -> Option<Summary> {
        let (mut n, mut sq, mut max_abs, mut max_rel, mut worst) = (0usize, 0.0, -1.0f64, 0.0f64, 0usize);
        for r in rows {
            n += 1;
            sq += r.error * r.error;
            if r.error.abs() > max_abs {
                max_abs = r.error.abs();
                worst = r.row;
            }
            max_rel = max_rel.max(r.relative_error.map_or(0.0, f64::abs));
        }
        (n > 0).then(|| Summary {
            n,
            max_abs_error: max_abs,
            rms_error: (sq / n as f64).sqrt(),
            max_rel_error: max_rel,
            worst_row: worst,
        })
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
pub fn exact_value(shape: &Shape, vbar: f64, amp: f64, at_rest: AtRest) -> Result<f64> {
    if vbar == 0.0 && at_rest == AtRest::Relaxed {
        return Ok(0.0);
    }
    Ok(shape.evaluate(vbar, amp)?.ratio.mu_ratio)
}

/// Compare `rows` of `(vbar, amp, mu_ratio)` with the exact solver for `shape`;
/// `tolerance` (`>= 0`) is how far a value may be from a bound (0, 1) or from
/// monotonicity before it is a finding.
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

/// Errors at or below this are rounding, not discretisation: no order is fitted to them.
const ROUNDING_ERROR: f64 = 64.0 * f64::EPSILON;

/// One row of a convergence study: its values at each resolution.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SeriesRow {
    /// Dimensionless velocity.
    pub vbar: f64,
    /// Amplitude.
    pub amp: f64,
    /// The point's regime.
    pub regime: RowRegime,
    /// The exact value.
    pub exact: f64,
    /// The values, one per resolution (in increasing resolution).
    pub values: Vec<f64>,
    /// `value - exact`, one per resolution.
    pub errors: Vec<f64>,
    /// The observed order `p`: least-squares slope of `-ln|error|` against
    /// `ln(resolution)` over the resolutions whose error is above rounding
    /// (absent with fewer than two).
    pub order: Option<f64>,
    /// The error constant `C` of `|error| = C resolution^-p` from the same fit.
    pub constant: Option<f64>,
    /// Richardson extrapolation of the last two values with the observed order.
    pub richardson: Option<f64>,
    /// `richardson - exact`.
    pub richardson_error: Option<f64>,
    /// The resolution at which the fit reaches the target error (with `target`).
    pub needed_resolution: Option<f64>,
}

/// The orders observed in one regime.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RegimeOrder {
    /// The regime.
    pub regime: RowRegime,
    /// Rows with an observed order.
    pub n: usize,
    /// Their median order.
    pub median_order: f64,
    /// The smallest and largest.
    pub min_order: f64,
    /// The largest.
    pub max_order: f64,
}

/// A convergence study: one table at several resolutions (e.g. steps per period).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Convergence {
    /// Shape name.
    pub shape: String,
    /// The resolutions, increasing.
    pub resolutions: Vec<f64>,
    /// The target error, if asked.
    pub target: Option<f64>,
    /// Every row present in all tables (matched by `(vbar, amp)`).
    pub rows: Vec<SeriesRow>,
    /// Median, smallest and largest order per regime.
    pub by_regime: Vec<RegimeOrder>,
}

/// Least squares of `y = a + b x`: `(a, b)`.
fn line_fit(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let n = points.len() as f64;
    if points.len() < 2 {
        return None;
    }
    let (sx, sy) = points.iter().fold((0.0, 0.0), |(a, b), &(x, y)| (a + x, b + y));
    let (mx, my) = (sx / n, sy / n);
    let sxx: f64 = points.iter().map(|&(x, _)| (x - mx) * (x - mx)).sum();
    let sxy: f64 = points.iter().map(|&(x, y)| (x - mx) * (y - my)).sum();
    (sxx > 0.0).then(|| (my - sxy / sxx * mx, sxy / sxx))
}

/// The observed order `p` and constant `C` of `|error| = C resolution^-p`: the
/// least-squares line through `(ln resolution, ln |error|)` over the errors
/// above rounding (none with fewer than two).
pub fn observed_order(resolutions: &[f64], errors: &[f64]) -> (Option<f64>, Option<f64>) {
    let points: Vec<(f64, f64)> = resolutions
        .iter()
        .zip(errors)
        .filter(|(_, e)| e.abs() > ROUNDING_ERROR)
        .map(|(r, e)| (r.ln(), e.abs().ln()))
        .collect();
    let fit = line_fit(&points);
    (fit.map(|(_, b)| -b), fit.map(|(a, _)| a.exp()))
}

/// Compare `tables` (rows `(vbar, amp, mu_ratio)`) at `resolutions` (one each,
/// positive and distinct) with the exact values: per row the observed order,
/// error constant, Richardson value and (with `target`) the resolution needed;
/// per regime the median order. Rows are matched by their `(vbar, amp)`; a row
/// missing from one table is an error.
pub fn convergence(
    shape: &Shape,
    resolutions: &[f64],
    tables: &[Vec<(f64, f64, f64)>],
    at_rest: AtRest,
    target: Option<f64>,
) -> Result<Convergence> {
    if resolutions.len() != tables.len() || resolutions.len() < 2 {
        return Err(Error::param("resolutions", resolutions.len() as f64, "a series needs two tables or more"));
    }
    if let Some(t) = target {
        if !(t.is_finite() && t > 0.0) {
            return Err(Error::param("target", t, "must be finite and > 0"));
        }
    }
    let mut order: Vec<usize> = (0..resolutions.len()).collect();
    order.sort_by(|&i, &j| resolutions[i].total_cmp(&resolutions[j]));
    let res: Vec<f64> = order.iter().map(|&i| resolutions[i]).collect();
    if res.iter().any(|r| !(r.is_finite() && *r > 0.0)) || res.windows(2).any(|w| w[0] == w[1]) {
        return Err(Error::param("resolutions", res[0], "must be finite, > 0 and distinct"));
    }
    let first = &tables[order[0]];
    let mut rows = vec![];
    for &(vbar, amp, _) in first {
        let mut values = vec![];
        for &k in &order {
            let found = tables[k].iter().find(|r| r.0 == vbar && r.1 == amp).ok_or_else(|| Error::Parse {
                context: format!("the table at resolution {}", resolutions[k]),
                reason: format!("it lacks the row vbar = {vbar:?}, amp = {amp:?}"),
            })?;
            values.push(found.2);
        }
        let exact = exact_value(shape, vbar, amp, at_rest)?;
        let errors: Vec<f64> = values.iter().map(|v| v - exact).collect();
        let (p, constant) = observed_order(&res, &errors);
        let n = values.len();
        let ratio = res[n - 1] / res[n - 2];
        let richardson =
            p.filter(|p| *p > 0.0).map(|p| values[n - 1] + (values[n - 1] - values[n - 2]) / (ratio.powf(p) - 1.0));
        let needed = match (target, p, constant) {
            (Some(t), Some(p), Some(c)) if p > 0.0 => Some((c / t).powf(1.0 / p)),
            _ => None,
        };
        rows.push(SeriesRow {
            vbar,
            amp,
            regime: RowRegime::of(vbar, amp),
            exact,
            values,
            errors,
            order: p,
            constant,
            richardson,
            richardson_error: richardson.map(|r| r - exact),
            needed_resolution: needed,
        });
    }
    let mut regimes: Vec<RowRegime> = rows.iter().map(|r| r.regime).collect();
    regimes.sort();
    regimes.dedup();
    let by_regime = regimes
        .into_iter()
        .filter_map(|g| {
            let mut ps: Vec<f64> = rows.iter().filter(|r| r.regime == g).filter_map(|r| r.order).collect();
            ps.sort_by(f64::total_cmp);
            let n = ps.len();
            (n > 0).then(|| RegimeOrder {
                regime: g,
                n,
                median_order: if n % 2 == 1 { ps[n / 2] } else { 0.5 * (ps[n / 2 - 1] + ps[n / 2]) },
                min_order: ps[0],
                max_order: ps[n - 1],
            })
        })
        .collect();
    Ok(Convergence { shape: shape.name().to_string(), resolutions: res, target, rows, by_regime })
}

/// An event found in a user's history, matched to the exact one of its kind.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FoundEvent {
    /// What happened.
    pub kind: crate::spring::EventKind,
    /// Its phase in the user's history, in `[0, 2 pi)`.
    pub tau: f64,
    /// The exact event's phase (absent if the exact solution has none of this kind).
    pub exact_tau: Option<f64>,
    /// `tau - exact_tau`, the shortest way round the period.
    pub timing_error: Option<f64>,
}

/// A user's force history against the exact steady state (the flat punch).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HistoryValidation {
    /// Shape name.
    pub shape: String,
    /// Units of the forces compared.
    pub units: String,
    /// Dimensionless velocity.
    pub vbar: f64,
    /// Amplitude.
    pub amp: f64,
    /// Whole periods in the history.
    pub periods: usize,
    /// Samples in the last period (compared).
    pub samples: usize,
    /// Largest `|tangential - exact|` over the last period (units `mu0 kz u0`).
    pub max_abs_error: f64,
    /// Root mean square of the same.
    pub rms_error: f64,
    /// `(tau, tangential - exact)` at every sample of the last period.
    pub sample_errors: Vec<(f64, f64)>,
    /// Largest change of the tangential force from the previous period to the
    /// last at the same phase (linear interpolation), if there are two periods.
    pub period_drift: Option<f64>,
    /// The same between the two periods before, if there are three.
    pub previous_drift: Option<f64>,
    /// True where the drift is within the tolerance (times the peak force).
    pub periodic: Option<bool>,
    /// Periods still needed for the drift to fall below the tolerance, from the
    /// drift's decay between the last periods (absent if it does not decay).
    pub periods_needed: Option<f64>,
    /// The events found in the last period (stick, slip, contact, loss of
    /// contact: from the force against its Coulomb bound), with their timing errors.
    pub events: Vec<FoundEvent>,
    /// Samples (phases, at most 5) of the last period where the tangential force
    /// exceeds the Coulomb bound `mu0 N` (beyond the tolerance): the switch from
    /// stick to slip (eq. 8) is missed there.
    pub above_bound: Vec<f64>,
    /// How many such samples.
    pub above_bound_count: usize,
    /// The exact events of the period.
    pub exact_events: Vec<crate::spring::Event>,
}

/// Phases of a history's samples from its time column `t`: `t` itself if it is
/// the phase (`is_tau`), else `omega t`, else (without `omega`) the period and
/// phase found from the normal force's maxima, where `tau = pi`
/// (`N ~ 1 - amp cos tau`): the mean spacing of the first and last maxima.
pub fn phases(t: &[f64], is_tau: bool, omega: Option<f64>, normal: Option<&[f64]>) -> Result<Vec<f64>> {
    if is_tau {
        return Ok(t.to_vec());
    }
    if let Some(w) = omega {
        if !(w.is_finite() && w > 0.0) {
            return Err(Error::param("omega", w, "must be finite and > 0"));
        }
        return Ok(t.iter().map(|x| w * x).collect());
    }
    let bad = |reason: &str| Error::Parse { context: "history".into(), reason: reason.into() };
    let n = normal.ok_or_else(|| bad("a time column t needs omega, or a normal column to find the period from"))?;
    let peaks: Vec<f64> =
        (1..n.len().saturating_sub(1)).filter(|&i| n[i] > n[i - 1] && n[i] >= n[i + 1]).map(|i| t[i]).collect();
    if peaks.len() < 2 {
        return Err(bad("fewer than two maxima of the normal force: give omega"));
    }
    let period = (peaks[peaks.len() - 1] - peaks[0]) / (peaks.len() - 1) as f64;
    let w = std::f64::consts::TAU / period;
    Ok(t.iter().map(|x| std::f64::consts::PI + w * (x - peaks[0])).collect())
}

/// Largest `|F(tau) - F(tau - 2 pi)|` over samples in `[from, to]`, the earlier
/// value interpolated linearly between the user's samples.
fn drift(taus: &[f64], f: &[f64], from: f64, to: f64) -> Option<f64> {
    let at = |t: f64| -> Option<f64> {
        let j = taus.partition_point(|&x| x < t);
        if j == 0 || j >= taus.len() {
            return (j < taus.len() && taus[j] == t).then(|| f[j]);
        }
        let (t0, t1) = (taus[j - 1], taus[j]);
        if t1 == t0 {
            return Some(f[j]);
        }
        Some(f[j - 1] + (f[j] - f[j - 1]) * (t - t0) / (t1 - t0))
    };
    let mut worst: Option<f64> = None;
    for (i, &t) in taus.iter().enumerate() {
        if t > from && t <= to {
            if let Some(prev) = at(t - std::f64::consts::TAU) {
                worst = Some(worst.unwrap_or(0.0).max((f[i] - prev).abs()));
            }
        }
    }
    worst
}

/// Springs of the reference tangential force of a curved contact's history
/// (the midpoint grid of [`crate::contact::grid`]; second order in the spacing).
pub const HISTORY_REFERENCE_SPRINGS: usize = 20_000;

/// Compare a force history (phases `taus`, nondecreasing; the tangential force
/// in units of `mu0 kz u0` for the flat punch, `mu0 E* x_c u0` for other
/// shapes; the normal force in units of `kz u0` or `E* x_c u0` if known, else
/// the exact one is used for the Coulomb bound) with the steady state of
/// `shape` at `(vbar, amp)`: exact for the flat punch; for other shapes the
/// normal force is exact and the tangential force the sum over
/// [`HISTORY_REFERENCE_SPRINGS`] springs, and events are not compared (the
/// total has none). `tolerance` decides "on the bound", "no contact" and
/// "periodic" (relative to the peak normal force).
pub fn compare_history(
    shape: &Shape,
    vbar: f64,
    amp: f64,
    taus: &[f64],
    tangential: &[f64],
    normal: Option<&[f64]>,
    tolerance: f64,
) -> Result<HistoryValidation> {
    use crate::spring::EventKind;
    use std::f64::consts::TAU;
    crate::error::check_nonneg("vbar", vbar)?;
    crate::error::check_nonneg("amp", amp)?;
    crate::error::check_nonneg("tolerance", tolerance)?;
    if amp == 0.0 {
        return Err(Error::param("amp", amp, "a history without oscillation has no period"));
    }
    let n = taus.len();
    if tangential.len() != n || normal.is_some_and(|x| x.len() != n) {
        return Err(Error::Parse { context: "history".into(), reason: "the columns differ in length".into() });
    }
    for i in 0..n {
        let bad = |what: &str| Error::Parse { context: format!("history sample {i}"), reason: what.into() };
        if !taus[i].is_finite() || !tangential[i].is_finite() || normal.is_some_and(|x| !x[i].is_finite()) {
            return Err(bad("values must be finite"));
        }
        if i > 0 && taus[i] < taus[i - 1] {
            return Err(bad("the phase (time) must not decrease"));
        }
    }
    let span = if n > 1 { taus[n - 1] - taus[0] } else { 0.0 };
    let periods = (span / TAU + 1e-9).floor() as usize;
    if periods < 1 {
        return Err(Error::Parse {
            context: "history".into(),
            reason: format!("it spans {:.3} periods: at least one whole period is needed", span / TAU),
        });
    }
    let flat = shape.is_flat();
    let sp = crate::flat::spring(vbar, amp, crate::spring::Precision::Events);
    // Curved contacts: the reference springs, and the static force at each depth.
    let (dz, springs) = if flat {
        (0.0, vec![])
    } else {
        let (dz, s_of) = crate::contact::grid(shape.contact(), amp, HISTORY_REFERENCE_SPRINGS)?;
        (dz, (0..HISTORY_REFERENCE_SPRINGS).map(|i| Spring::with_events(s_of(i), vbar)).collect())
    };
    let exact_normal = |t: f64| {
        if flat {
            (sp.s - t.cos()).max(0.0) * amp
        } else {
            shape.contact().static_force(1.0 - amp * t.cos())
        }
    };
    let exact_tangential = |t: f64| {
        if flat {
            crate::history::spring_force(&sp, t) * amp
        } else {
            2.0 * amp * dz * springs.iter().map(|s| crate::history::spring_force(s, t)).sum::<f64>()
        }
    };
    let end = taus[n - 1];
    let start = end - TAU;
    let last: Vec<usize> = (0..n).filter(|&i| taus[i] > start + 1e-12 * TAU).collect();
    let (mut max_abs, mut sq) = (0.0f64, 0.0);
    let mut sample_errors = Vec::with_capacity(last.len());
    let exact_last: Vec<f64> = crate::numerics::par::map(&last, |&i| exact_tangential(taus[i]));
    for (&i, &x) in last.iter().zip(&exact_last) {
        let e = tangential[i] - x;
        max_abs = max_abs.max(e.abs());
        sq += e * e;
        sample_errors.push((taus[i], e));
    }
    let peak =
        (0..n).map(|i| normal.map_or(exact_normal(taus[i]), |x| x[i])).fold(0.0f64, f64::max).max(f64::MIN_POSITIVE);
    let period_drift = (periods >= 2).then(|| drift(taus, tangential, start, end)).flatten();
    let previous_drift = (periods >= 3).then(|| drift(taus, tangential, start - TAU, start)).flatten();
    let bar = tolerance * peak;
    let periodic = period_drift.map(|d| d <= bar);
    let periods_needed = match (period_drift, previous_drift) {
        (Some(d), _) if d <= bar => Some(0.0),
        (Some(d), Some(p)) if d < p && d > 0.0 => Some(((bar / d).ln() / (d / p).ln()).ceil()),
        _ => None,
    };
    // States along the last period: 0 no contact, 1 on the bound (slip), 2 below (stick).
    let state = |i: usize| {
        let b = normal.map_or(exact_normal(taus[i]), |x| x[i]);
        if b <= bar {
            0
        } else if (tangential[i] - b).abs() <= bar {
            1
        } else {
            2
        }
    };
    let exact_events = if flat { crate::flat::point(vbar, amp)?.events } else { vec![] };
    let above: Vec<f64> = last
        .iter()
        .filter(|&&i| tangential[i] > normal.map_or(exact_normal(taus[i]), |x| x[i]) + bar)
        .map(|&i| taus[i].rem_euclid(TAU))
        .collect();
    let mut found = vec![];
    let mut prev = last.first().map(|&i| state(i));
    for &i in last.iter().skip(1).filter(|_| flat) {
        let s = state(i);
        let kinds: &[EventKind] = match (prev, s) {
            (Some(0), 1) => &[EventKind::Contact],
            (Some(0), 2) => &[EventKind::Contact, EventKind::Stick],
            (Some(1 | 2), 0) => &[EventKind::LossOfContact],
            (Some(1), 2) => &[EventKind::Stick],
            (Some(2), 1) => &[EventKind::Slip],
            _ => &[],
        };
        // The event lies between the two samples: their midpoint.
        let tau = (0.5 * (taus[i - 1] + taus[i])).rem_euclid(TAU);
        for &kind in kinds {
            let exact = exact_events
                .iter()
                .filter(|e| e.kind == kind)
                .map(|e| {
                    let d = (tau - e.tau + 0.5 * TAU).rem_euclid(TAU) - 0.5 * TAU;
                    (e.tau, d)
                })
                .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()));
            found.push(FoundEvent { kind, tau, exact_tau: exact.map(|x| x.0), timing_error: exact.map(|x| x.1) });
        }
        prev = Some(s);
    }
    let units =
        if flat { "normal: kz u0; tangential: mu0 kz u0" } else { "normal: E* x_c u0; tangential: mu0 E* x_c u0" };
    Ok(HistoryValidation {
        shape: shape.name().to_string(),
        units: units.into(),
        vbar,
        amp,
        periods,
        samples: last.len(),
        max_abs_error: max_abs,
        rms_error: (sq / last.len().max(1) as f64).sqrt(),
        sample_errors,
        period_drift,
        previous_drift,
        periodic,
        periods_needed,
        events: found,
        above_bound_count: above.len(),
        above_bound: above.into_iter().take(FINDING_ROWS).collect(),
        exact_events,
    })
}
