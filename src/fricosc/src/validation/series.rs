//! Convergence studies: the same table at several resolutions, observed
//! orders, and findings for rows that do not converge.
//!
//! # Row status
//! Each row's errors (above rounding) are classed: `exact` (all at rounding),
//! `resolution_independent` (over a range of resolutions of at least
//! [`STAGNANT_RANGE`], the finest run's error is within a factor 2 of the
//! coarsest's: the error is in the model, not the step), `not_converging`
//! (the observed order is below [`MIN_ORDER`], or the finest error is not below
//! the coarsest), else `converging`. The needed resolution is given only for
//! converging rows, and only up to [`MAX_EXTRAPOLATION`] times the finest
//! resolution (`unreachable` otherwise).

use super::*;

/// Errors at or below this times `sqrt(resolution)` are rounding, not
/// discretisation: no order is fitted to them. A run at resolution `r` sums
/// of order `r` terms a period (steps, springs), whose rounding grows like the
/// square root of their number (an exact row's errors of 2.5e-15, 0, 9.7e-15,
/// 2.2e-16, 3.8e-14, 9.4e-16 are not a failure to converge).
const ROUNDING_ERROR: f64 = 64.0 * f64::EPSILON;

/// Whether `error` at resolution `r` is rounding ([`ROUNDING_ERROR`]).
fn at_rounding(r: f64, error: f64) -> bool {
    error.abs() <= ROUNDING_ERROR * r.max(1.0).sqrt()
}

/// One row of a convergence study: its values at each resolution.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SeriesRow {
    /// Dimensionless velocity.
    pub vbar: f64,
    /// Amplitude.
    pub amp: f64,
    /// What the contact's springs do there ([`crate::Shape::regime`]).
    pub regime: ContactRegime,
    /// The share of the mean normal force carried by springs that lose contact.
    pub jumping_share: f64,
    /// How its errors behave (module docs).
    pub status: RowStatus,
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
    pub needed_resolution: Option<Needed>,
}

/// How a row's errors behave over the series (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum RowStatus {
    /// Every error at rounding.
    Exact,
    /// Errors decreasing at an order of at least 0.5.
    Converging,
    /// Errors not decreasing, or at an order below 0.5.
    NotConverging,
    /// Errors the same at every resolution.
    ResolutionIndependent,
}

/// The resolution a row needs for the target error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Needed {
    /// This resolution (from the row's fit).
    Resolution(f64),
    /// The row does not converge, or the fit asks for more than
    /// 10^6 times the finest resolution.
    Unreachable,
}

#[cfg(feature = "serde")]
impl serde::Serialize for Needed {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Needed::Resolution(r) => s.serialize_f64(*r),
            Needed::Unreachable => s.serialize_str("unreachable"),
        }
    }
}

/// Smallest observed order of a converging row.
pub(crate) const MIN_ORDER: f64 = 0.5;

/// Largest extrapolation of a needed resolution beyond the finest run.
pub(crate) const MAX_EXTRAPOLATION: f64 = 1e6;

/// Smallest ratio of finest to coarsest resolution over which a row's error
/// can be called independent of the resolution.
pub(crate) const STAGNANT_RANGE: f64 = 4.0;

/// The orders observed in one regime.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RegimeOrder {
    /// The regime.
    pub regime: ContactRegime,
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
    /// What looks wrong (the rows that do not converge, and the finest
    /// table's own findings), with hints; row numbers are the rows' indices in
    /// this study.
    pub findings: Vec<Finding>,
    /// What to be careful with (rows whose Richardson value is worse than the
    /// finest run); not findings.
    pub cautions: Vec<Finding>,
    /// The system the rows were compared on, if any ([`Check::system`]).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub system: Option<crate::system::System>,
}

/// The status of a row with errors `errors` at increasing `res` and observed order `p`.
fn status(res: &[f64], errors: &[f64], p: Option<f64>) -> RowStatus {
    let above: Vec<(f64, f64)> =
        res.iter().zip(errors).filter(|&(&r, &e)| !at_rounding(r, e)).map(|(r, e)| (*r, e.abs())).collect();
    if above.is_empty() {
        return RowStatus::Exact;
    }
    let (coarse, fine) = (errors[0].abs(), errors[errors.len() - 1].abs());
    let range = res[res.len() - 1] / res[0];
    if range >= STAGNANT_RANGE && !at_rounding(res[0], coarse) && fine >= 0.5 * coarse && fine <= 2.0 * coarse {
        return RowStatus::ResolutionIndependent;
    }
    if fine >= coarse || p.is_none_or(|p| p < MIN_ORDER) {
        return RowStatus::NotConverging;
    }
    RowStatus::Converging
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
#[must_use]
pub(crate) fn observed_order(resolutions: &[f64], errors: &[f64]) -> (Option<f64>, Option<f64>) {
    let points: Vec<(f64, f64)> = resolutions
        .iter()
        .zip(errors)
        .filter(|&(&r, &e)| !at_rounding(r, e))
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
///
/// # Errors
/// [`Error::Parse`] for fewer than two tables, bad resolutions or a row missing
/// from a table; the solver's errors.
pub fn convergence(
    shape: &Shape,
    resolutions: &[f64],
    tables: &[Vec<(f64, f64, f64)>],
    check: &Check,
    target: Option<f64>,
) -> Result<Convergence> {
    let (order, res) = checked_series(resolutions, tables.len(), target)?;
    let first = &tables[order[0]];
    // On a system, each amplitude's critical velocity (the regimes').
    let critical = |amp: f64| -> Result<Option<f64>> {
        let vbar = |s| crate::system::critical_vbar(shape, amp, s).map(|c| c.unwrap_or(f64::INFINITY));
        check.system.as_ref().map(vbar).transpose()
    };
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
        let exact = super::system::exact(shape, vbar, amp, check)?.mu;
        let errors: Vec<f64> = values.iter().map(|v| v - exact).collect();
        let (p, constant) = observed_order(&res, &errors);
        let n = values.len();
        let ratio = res[n - 1] / res[n - 2];
        let richardson =
            p.filter(|p| *p > 0.0).map(|p| values[n - 1] + (values[n - 1] - values[n - 2]) / (ratio.powf(p) - 1.0));
        let status = status(&res, &errors, p);
        let needed = target.map(|t| match (p, constant) {
            (Some(p), Some(c)) if status == RowStatus::Converging => {
                let m = (c / t).powf(1.0 / p);
                if m.is_finite() && m <= MAX_EXTRAPOLATION * res[n - 1] {
                    Needed::Resolution(m)
                } else {
                    Needed::Unreachable
                }
            }
            _ if status == RowStatus::Exact => Needed::Resolution(res[0]),
            _ => Needed::Unreachable,
        });
        rows.push(SeriesRow {
            vbar,
            amp,
            regime: super::system::regime(shape, vbar, amp, critical(amp)?)?,
            jumping_share: shape.jumping_share(amp)?,
            status,
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
    let by_regime = orders_by_regime(&rows);
    let finest: Vec<(f64, f64, f64)> = rows.iter().map(|r| (r.vbar, r.amp, r.values[r.values.len() - 1])).collect();
    let mut findings = compare(shape, &finest, &check.with_peer(None))?.findings;
    findings.extend(series_findings(&rows));
    let richardson: Vec<usize> = rows
        .iter()
        .enumerate()
        .filter(|(_, r)| {
            r.richardson_error.is_some_and(|e| e.abs() > r.errors[r.errors.len() - 1].abs() && e.abs() > ROUNDING_ERROR)
        })
        .map(|(i, _)| i)
        .collect();
    let cautions = finding(
        FindingKind::RichardsonUntrustworthy,
        richardson,
        "the Richardson value of these rows is further from the exact one than the finest run: their errors do \
         not follow one order (e.g. first order and erratic where a stick starts at the onset of contact); use \
         the finest value",
    )
    .into_iter()
    .collect();
    let system = check.system;
    Ok(Convergence {
        shape: shape.name().to_string(),
        resolutions: res,
        target,
        rows,
        by_regime,
        findings,
        cautions,
        system,
    })
}

/// The series' resolutions checked (two or more, finite, positive, distinct;
/// a `target` finite and positive): the tables' order by resolution, and the
/// resolutions in it.
fn checked_series(resolutions: &[f64], tables: usize, target: Option<f64>) -> Result<(Vec<usize>, Vec<f64>)> {
    if resolutions.len() != tables || resolutions.len() < 2 {
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
    Ok((order, res))
}

/// The observed orders of each regime's rows.
fn orders_by_regime(rows: &[SeriesRow]) -> Vec<RegimeOrder> {
    let mut regimes: Vec<ContactRegime> = rows.iter().map(|r| r.regime).collect();
    regimes.sort();
    regimes.dedup();
    regimes
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
        .collect()
}

/// The findings of a study's rows: not converging, resolution-independent.
fn series_findings(rows: &[SeriesRow]) -> Vec<Finding> {
    let with = |st: RowStatus| rows.iter().enumerate().filter(|(_, r)| r.status == st).map(|(i, _)| i).collect();
    let mut out = vec![];
    out.extend(finding(
        FindingKind::ResolutionIndependent,
        with(RowStatus::ResolutionIndependent),
        "the error of these rows is the same at every resolution: it comes from the model, not the step (the \
         averaging window, the springs included, the normalisation, a formula), and refining will not remove it",
    ));
    out.extend(finding(
        FindingKind::NotConverging,
        with(RowStatus::NotConverging),
        "the error of these rows does not decrease with the resolution at an order of 0.5 or more: check that \
         every spring that touches during the period is included and that the run reaches the steady state",
    ));
    out
}
