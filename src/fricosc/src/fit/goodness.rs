//! How well the fitted model explains the rows: the chi-square's p-value,
//! the rows far from the model, and where the model does not fit, its
//! likely cause, each tried by a refit.

use super::bounds::Bounds;
use super::{fit_checked, FitReport, Measurement, NAMES, NP};
use crate::error::Result;
use crate::shape::Shape;
use statrs::distribution::{ChiSquared, ContinuousCDF, Normal};

/// The least threshold of an outlier: a normal error exceeds 3.5 in size
/// with probability 4.7e-4.
const LEAST_OUTLIER: f64 = 3.5;

/// The chance that any of `n` rows whose errors are normal is named an
/// outlier.
const FALSE_ALARM: f64 = 0.01;

/// The normalised residual beyond which one of `rows` rows is named as
/// outlying: the size a normal error exceeds with probability
/// `FALSE_ALARM / rows` (so that rows with normal errors name none with
/// probability at least 99 %, by the union bound), at least 3.5. It is 3.5 up
/// to 21 rows, 4.4 at 1,000 and 5.7 at 10^6: a fixed threshold would name
/// 4.7e-4 of every set of normal rows.
#[must_use]
pub fn outlier_threshold(rows: usize) -> f64 {
    let tail = 0.5 * FALSE_ALARM / rows.max(1) as f64;
    // The standard normal exists (mean 0, deviation 1 are valid).
    let z = Normal::new(0.0, 1.0).map_or(f64::NAN, |n| -n.inverse_cdf(tail));
    z.max(LEAST_OUTLIER)
}

/// The p-value below which the model does not explain the rows.
const SIGNIFICANCE: f64 = 0.01;

/// Most rows the causes of a bad fit are tried on (evenly spread): beyond,
/// their p-values are those of that many rows.
const CAUSE_ROWS: usize = 20_000;

/// The shapes tried where the fitted one does not fit.
const SHAPES: [&str; 3] = ["flat", "parabolic", "cone"];

/// `P(X >= chi2)` for `X` chi-square with `dof` degrees of freedom (`None`
/// without a degree of freedom).
fn p_value(chi2: f64, dof: usize) -> Option<f64> {
    let d = ChiSquared::new(dof as f64).ok()?;
    Some(d.sf(chi2))
}

/// The goodness of fit of `r` (fitted to `rows` with `fixed` held): its
/// normalised residuals, outliers, p-value, notes and verdicts.
pub(super) fn judge(
    shape: &Shape,
    rows: &[Measurement],
    (given, bounds): (&[Option<f64>; NP], &Bounds),
    r: &mut FitReport,
) -> Result<()> {
    let scale = if r.weighted { 1.0 } else { r.reduced_chi2.sqrt() };
    r.normalised_residuals = r
        .residuals
        .iter()
        .zip(rows)
        .map(|(e, m)| if scale > 0.0 { e / (m.sigma.unwrap_or(1.0) * scale) } else { 0.0 })
        .collect();
    let threshold = r.outlier_threshold;
    r.outliers = (0..rows.len()).filter(|&i| r.normalised_residuals[i].abs() > threshold).collect();
    if !r.converged {
        r.verdicts.push(format!(
            "the iteration stopped after {} iterations without converging: the parameters are not at the \
             chi-square's minimum (a start far off, or a parameter the rows barely determine)",
            r.iterations
        ));
    }
    if r.weighted {
        r.p_value = p_value(r.chi2, r.dof);
        if let Some(p) = r.p_value.filter(|&p| p < SIGNIFICANCE) {
            let verdict = bad_fit(shape, rows, (given, bounds), r, p);
            r.verdicts.push(verdict);
            return Ok(());
        }
    } else {
        r.notes.push(
            "no sigma: the errors' scale is estimated from the scatter (the reduced chi-square taken as 1), which \
             assumes that the model is right and every row equally uncertain; give sigma to test the model"
                .into(),
        );
    }
    if !r.outliers.is_empty() {
        r.verdicts.push(format!(
            "rows {} (counted from 0, in the order given) are more than {threshold:.2} standard uncertainties from \
             the model (normalised residuals {})",
            list(&r.outliers),
            r.outliers.iter().map(|&i| format!("{:.1}", r.normalised_residuals[i])).collect::<Vec<_>>().join(", ")
        ));
    }
    Ok(())
}

/// The rows (indices) as a short list.
fn list(rows: &[usize]) -> String {
    let shown: Vec<String> = rows.iter().take(10).map(usize::to_string).collect();
    let more = if rows.len() > 10 { format!(" and {} more", rows.len() - 10) } else { String::new() };
    format!("{}{more}", shown.join(", "))
}

/// The verdict of a model that does not fit (`p` below [`SIGNIFICANCE`]),
/// with the causes that a refit confirms: without the outlying rows, with a
/// held parameter freed, or with another shape, the p-value reaches 0.01
/// (on at most [`CAUSE_ROWS`] rows).
fn bad_fit(
    shape: &Shape,
    all: &[Measurement],
    (given, bounds): (&[Option<f64>; NP], &Bounds),
    r: &FitReport,
    p: f64,
) -> String {
    // The refits on at most CAUSE_ROWS rows, evenly spread, the outliers among them.
    let every = all.len().div_ceil(CAUSE_ROWS);
    let rows: Vec<Measurement> = all.iter().step_by(every).copied().collect();
    let outlying: Vec<usize> = r.outliers.iter().filter(|&&i| i % every == 0).map(|&i| i / every).collect();
    let refit = |shape: &Shape, rows: &[Measurement], given: &[Option<f64>; NP]| {
        let free = given.iter().filter(|g| g.is_none()).count();
        let f = (rows.len() > free).then(|| fit_checked(shape, rows, given, bounds).ok()).flatten()?;
        let p = p_value(f.chi2, f.dof)?;
        (p >= SIGNIFICANCE).then_some((f, p))
    };
    let mut causes = vec![];
    if !outlying.is_empty() {
        let kept: Vec<Measurement> =
            rows.iter().enumerate().filter(|(i, _)| !outlying.contains(i)).map(|(_, m)| *m).collect();
        if let Some((_, p)) = refit(shape, &kept, given) {
            causes.push(format!("the outlying rows {} (from 0; without them p = {p:.2})", list(&r.outliers)));
        }
    }
    // Each held parameter freed (a system's stiffness where every row has the one value).
    for k in (0..NP).filter(|&k| given[k].is_some_and(|v| !v.is_nan())) {
        let mut freed = *given;
        freed[k] = None;
        if let Some((f, p)) = refit(shape, &rows, &freed) {
            let Some(&q) = f.parameter(NAMES[k]) else { continue };
            let se = q.stderr.map_or("undetermined".into(), |e| format!("{e:.2e}"));
            causes.push(format!(
                "the held {} = {}: fitted, it is {} +- {se} (p = {p:.2})",
                NAMES[k],
                given[k].unwrap_or(f64::NAN),
                q.value
            ));
        }
    }
    // On a system a curved body's refit costs minutes (its points a thousand
    // times a stiff one's): the shapes are tried on stiff rigs only.
    let on_system = all.iter().any(|m| m.system.is_some());
    for name in SHAPES.iter().filter(|&&n| n != shape.name() && !on_system) {
        if let Some((_, p)) = Shape::parse(name).ok().and_then(|s| refit(&s, &rows, given)) {
            causes.push(format!("the shape: {name} fits (p = {p:.2})"));
        }
    }
    let head = format!(
        "the model does not fit the rows: chi-square {:.4} for {} degrees of freedom (p = {p:.1e} < {SIGNIFICANCE})",
        r.chi2, r.dof
    );
    if causes.is_empty() {
        let shapes =
            if on_system { "not the shapes (on a system)".into() } else { format!("the shapes {}", SHAPES.join(", ")) };
        format!(
            "{head}; none of the usual causes explains it (tried: the outlying rows left out, each held parameter \
             freed, {shapes}): check that sigma is the rows' standard uncertainty, and their conditions"
        )
    } else {
        format!("{head}; likely: {}", causes.join("; "))
    }
}

#[cfg(test)]
mod tests {
    /// The chi-square's upper tail against mpmath's regularized incomplete
    /// gamma function `Q(dof/2, chi2/2)` (30 digits): within 1e-12 relative.
    #[test]
    #[allow(clippy::excessive_precision)]
    fn the_p_value_is_the_chi_square_tail() {
        for (chi2, dof, want) in [
            (27.0961, 24, 0.299993591280530580995957596411),
            (59.8114, 24, 0.0000679123699513166767787344208169),
            (3.0, 10, 0.981424063777859325698725820626),
            (100.0, 50, 0.0000345493138298486394214543471332),
        ] {
            let p = super::p_value(chi2, dof).unwrap();
            assert!((p / want - 1.0).abs() < 1e-12, "{chi2} {dof}: {p} vs {want}");
        }
        assert_eq!(super::p_value(1.0, 0), None);
    }

    /// Rows are listed ten at most, the rest counted.
    #[test]
    fn rows_are_listed_ten_at_most() {
        assert_eq!(super::list(&[3, 5]), "3, 5");
        assert_eq!(super::list(&(0..10).collect::<Vec<_>>()), "0, 1, 2, 3, 4, 5, 6, 7, 8, 9");
        assert_eq!(super::list(&(0..12).collect::<Vec<_>>()), "0, 1, 2, 3, 4, 5, 6, 7, 8, 9 and 2 more");
    }
}
