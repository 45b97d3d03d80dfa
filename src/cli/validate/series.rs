//! The reports of a convergence study (`validate --series`).

use crate::error::{Error, Result};
use crate::output::csv_records;
use fricosc::validation::{Convergence, Needed, SeriesRow};

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
            r.regime.name().into(),
            n(r.jumping_share),
            r.status.name().into(),
            n(r.exact),
            opt(r.order),
            opt(r.constant),
            opt(r.richardson_error),
            match r.needed_resolution {
                None => String::new(),
                Some(Needed::Resolution(m)) => n(m),
                Some(Needed::Unreachable) => "unreachable".into(),
            },
        ];
        rec.extend(r.errors.iter().map(|e| n(*e)));
        records.push(rec);
    }
    Ok(csv_records(&records))
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
            label: g.regime.label(c.jumping_share(g.regime)),
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
