//! The reports of a convergence study (`validate --series`).

use super::table::wrap;
use super::{count, csv_text, findings_text, json_name, regime_label};
use crate::error::{Error, Result};
use fricosc::validation::{Convergence, Needed, SeriesRow};

fn needed_text(n: Option<Needed>, f: &dyn Fn(f64) -> String) -> String {
    match n {
        None => String::new(),
        Some(Needed::Resolution(m)) => f(m),
        Some(Needed::Unreachable) => "unreachable".into(),
    }
}

/// A convergence study as CSV: one line per row, its status, order, constant,
/// Richardson error and needed resolution, then its error at each resolution.
pub fn series_csv(c: &Convergence) -> Result<String> {
    let n = crate::output::num;
    let opt = |x: Option<f64>| x.map(n).unwrap_or_default();
    let mut header: Vec<String> = [
        "vbar",
        "amp",
        "regime",
        "jumping_share",
        "status",
        "exact",
        "order",
        "constant",
        "richardson_error",
        "needed_resolution",
    ]
    .map(String::from)
    .to_vec();
    header.extend(c.resolutions.iter().map(|r| format!("error@{}", n(*r))));
    let mut records = vec![header];
    for r in &c.rows {
        let mut rec = vec![
            n(r.vbar),
            n(r.amp),
            json_name(r.regime),
            n(r.jumping_share),
            json_name(r.status),
            n(r.exact),
            opt(r.order),
            opt(r.constant),
            opt(r.richardson_error),
            needed_text(r.needed_resolution, &n),
        ];
        rec.extend(r.errors.iter().map(|e| n(*e)));
        records.push(rec);
    }
    csv_text(&records)
}

/// A convergence study for a person: orders per regime, every row, findings and cautions.
pub fn series_summary(c: &Convergence) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let opt = |x: Option<f64>, f: &dyn Fn(f64) -> String| x.map(f).unwrap_or_else(|| "-".into());
    let res: Vec<String> = c.resolutions.iter().map(|r| r.to_string()).collect();
    let mut s = wrap(
        "",
        &format!(
            "fricosc validate --series: {} of {} at resolutions {}.",
            count(c.rows.len(), "row"),
            c.shape,
            res.join(", ")
        ),
        100,
    );
    s += &wrap(
        "",
        "Observed order: the least-squares slope of log |error| against log resolution (errors at rounding left \
         out). Status: converging (order >= 0.5), not_converging, resolution_independent (the same error at \
         every resolution), exact (at rounding).",
        100,
    );
    s += &format!("\n{:<26}{:>6}{:>14}{:>8}{:>8}\n", "regime", "rows", "median order", "min", "max");
    for g in &c.by_regime {
        s += &format!(
            "{:<26}{:>6}{:>14.2}{:>8.2}{:>8.2}\n",
            regime_label(g.regime, share_range(c, g.regime)),
            g.n,
            g.median_order,
            g.min_order,
            g.max_order
        );
    }
    let with_needed = c.target.is_some();
    s += &format!(
        "\n{:>8}{:>6}  {:<22}{:>7}{:>11}{:>13}{:>13}  {:<22}{}\n",
        "vbar",
        "amp",
        "regime",
        "order",
        "constant",
        "last error",
        "richardson",
        "status",
        if with_needed { format!("{:>12}", "needed") } else { String::new() }
    );
    for r in &c.rows {
        s += &format!(
            "{:>8}{:>6}  {:<22}{:>7}{:>11}{:>13}{:>13}  {:<22}{}\n",
            r.vbar,
            r.amp,
            regime_label(r.regime, [r.jumping_share; 2]),
            opt(r.order, &|p| format!("{p:.2}")),
            opt(r.constant, &e),
            e(*r.errors.last().unwrap_or(&0.0)),
            opt(r.richardson_error, &e),
            json_name(r.status),
            if with_needed {
                format!("{:>12}", needed_text(r.needed_resolution, &|m| format!("{m:.3e}")))
            } else {
                String::new()
            }
        );
    }
    s += &findings_text("Findings", &c.findings, "none", "row");
    if !c.cautions.is_empty() {
        s += &findings_text("Cautions (not findings)", &c.cautions, "none", "row");
    }
    s
}

/// Errors against resolution on log axes, per regime (one colour each): the
/// geometric mean of its rows' errors (solid, circles) and the slope of its
/// median order through the last point (dashed).
pub fn series_svg(c: &Convergence) -> Result<String> {
    use crate::chart::{Axis, Chart, Dash, Marker, Series, Style, OKABE_ITO};
    let mut series = vec![];
    let (mut ylo, mut yhi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (i, g) in c.by_regime.iter().enumerate() {
        let rows: Vec<&SeriesRow> = c.rows.iter().filter(|r| r.regime == g.regime).collect();
        let mut pts = vec![];
        for (k, &m) in c.resolutions.iter().enumerate() {
            let logs: Vec<f64> = rows.iter().map(|r| r.errors[k].abs()).filter(|x| *x > 0.0).map(f64::log10).collect();
            if !logs.is_empty() {
                pts.push((m, 10f64.powf(logs.iter().sum::<f64>() / logs.len() as f64)));
            }
        }
        let Some(&(ml, el)) = pts.last() else { continue };
        let m0 = c.resolutions[0];
        let fitted = vec![(m0, el * (ml / m0).powf(g.median_order)), (ml, el)];
        for &(_, y) in pts.iter().chain(&fitted) {
            ylo = ylo.min(y);
            yhi = yhi.max(y);
        }
        let color = OKABE_ITO[(i + 1) % OKABE_ITO.len()];
        series.push(Series {
            label: regime_label(g.regime, share_range(c, g.regime)),
            points: pts,
            style: Style::line(color).marker(Marker::Circle),
            legend: true,
        });
        series.push(Series {
            label: format!("order {:.2}", g.median_order),
            points: fitted,
            style: Style::dashed(color, Dash::Dashed),
            legend: true,
        });
    }
    let (x0, x1) = (c.resolutions[0], c.resolutions[c.resolutions.len() - 1]);
    if !(ylo.is_finite() && yhi.is_finite()) {
        return Err(Error::Parse { context: "--plot".into(), reason: "no errors above zero to draw".into() });
    }
    Ok(Chart {
        title: format!("{}: error against resolution", c.shape),
        x: Axis::log("resolution (e.g. steps per period)", (x0 / 1.2, x1 * 1.2)),
        y: Axis::log("|μ/μ_{0} − exact| (geometric mean)", (ylo / 3.0, yhi * 3.0)),
        series,
        key: vec![],
        rules: vec![],
    }
    .svg())
}

/// The smallest and largest jumping share of a regime's rows.
fn share_range(c: &Convergence, g: fricosc::report::ContactRegime) -> [f64; 2] {
    let share = c.rows.iter().filter(|r| r.regime == g).map(|r| r.jumping_share);
    [share.clone().fold(f64::INFINITY, f64::min), share.fold(f64::NEG_INFINITY, f64::max)]
}
