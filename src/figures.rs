//! `fricosc figures`: the seed's Figs. 3, 4, 5 (with its inset), 7 and 8, exact,
//! with the seed's approximations on each (dashed), as JSON, CSV and SVG.
//! Every exact point is the solver's value ([`crate::shape::evaluate`]).

use crate::error::{Error, Result};
use crate::plot::{lines, Series};
use crate::seed;
use crate::shape::{evaluate, Shape};
use serde::Serialize;

/// One curve of a figure.
#[derive(Debug, Clone, Serialize)]
pub struct Curve {
    /// Legend label.
    pub label: String,
    /// `exact` or `approximation`.
    pub kind: String,
    /// Amplitude `du/u0`, where the curve has one.
    pub amp: Option<f64>,
    /// `(x, y)` points.
    pub points: Vec<[f64; 2]>,
}

/// One figure.
#[derive(Debug, Clone, Serialize)]
pub struct Figure {
    /// File stem (`fig3`, `fig5-inset`, ...).
    pub name: String,
    /// Title, as in the seed.
    pub title: String,
    /// Axis labels.
    pub x_label: String,
    /// Axis label.
    pub y_label: String,
    /// Axis ranges `[x0, x1, y0, y1]`.
    pub range: [f64; 4],
    /// Curves.
    pub curves: Vec<Curve>,
}

/// A figure of `mu/mu0` against `vbar` on the seed's axes.
fn against_vbar(name: &str, title: &str, curves: Vec<Curve>) -> Figure {
    Figure {
        name: name.into(),
        title: title.into(),
        x_label: "vbar (eq. 3)".into(),
        y_label: "mu_macro / mu0".into(),
        range: [0.0, 1.2, 0.0, 1.05],
        curves,
    }
}

fn grid(x0: f64, x1: f64, n: usize) -> Vec<f64> {
    (0..n).map(|k| x0 + (x1 - x0) * k as f64 / (n - 1) as f64).collect()
}

fn exact(shape: &Shape, label: String, amp: f64, xs: &[f64], vbar_of: impl Fn(f64) -> f64) -> Result<Curve> {
    let points = xs
        .iter()
        .map(|&x| evaluate(shape, vbar_of(x), amp).map(|e| [x, e.ratio.mu_ratio]))
        .collect::<Result<Vec<_>>>()?;
    Ok(Curve { label, kind: "exact".into(), amp: Some(amp), points })
}

fn approx(label: String, amp: Option<f64>, xs: &[f64], f: impl Fn(f64) -> f64) -> Curve {
    Curve { label, kind: "approximation".into(), amp, points: xs.iter().map(|&x| [x, f(x)]).collect() }
}

/// Build all figures.
pub fn build() -> Result<Vec<Figure>> {
    let flat = Shape::Flat;
    let parabolic = Shape::Power(2.0);
    let vb = grid(0.0, 1.2, 241);
    let small = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0];
    let jumping = [1.2, 1.4, 1.6, 1.8, 2.0];
    let mut figs = vec![];

    // Fig. 3: flat punch, no jumping, and eq. 11.
    let mut c = vec![];
    for &a in &small {
        c.push(exact(&flat, format!("du/u0 = {a}"), a, &vb, |v| v)?);
        c.push(approx(format!("eq. 11, du/u0 = {a}"), Some(a), &vb, |v| seed::eq11(v, a)));
    }
    figs.push(against_vbar("fig3", "Fig. 3: flat punch, mu/mu0 vs vbar (solid exact, dashed eq. 11)", c));

    // Fig. 3 inset: amp = 1 at low velocity, eq. 12.
    let vs = grid(0.0, 0.1, 201);
    figs.push(Figure {
        name: "fig3-inset".into(),
        title: "Fig. 3 inset: du/u0 = 1, low velocity (solid exact, dashed eq. 12)".into(),
        x_label: "vbar".into(),
        y_label: "mu_macro / mu0".into(),
        range: [0.0, 0.1, 0.0, 0.3],
        curves: vec![
            exact(&flat, "exact".into(), 1.0, &vs, |v| v)?,
            approx("eq. 12".into(), Some(1.0), &vs, |v| seed::eq12(v, 1.0)),
        ],
    });

    // Fig. 4: flat punch against vhat = vbar amp, and eq. 16.
    let vh = grid(0.0, 2.0, 201);
    let mut c = vec![];
    for &a in small.iter().skip(1).chain(&jumping) {
        c.push(exact(&flat, format!("du/u0 = {a}"), a, &vh, |x| x / a)?);
        c.push(approx(format!("eq. 16, du/u0 = {a}"), Some(a), &vh, |x| seed::eq16(x, a)));
    }
    figs.push(Figure {
        name: "fig4".into(),
        title: "Fig. 4: flat punch, mu/mu0 vs vhat (solid exact, dashed eq. 16)".into(),
        x_label: "vhat (eq. 15)".into(),
        y_label: "mu_macro / mu0".into(),
        range: [0.0, 2.0, 0.0, 1.05],
        curves: c,
    });

    // Fig. 5: jumping, and eq. 17.
    let mut c = vec![];
    for k in 0..=10 {
        let a = 1.0 + 0.1 * k as f64;
        c.push(exact(&flat, format!("du/u0 = {a:.1}"), a, &vb, |v| v)?);
    }
    c.push(approx("eq. 17".into(), None, &vb, seed::eq17));
    figs.push(against_vbar("fig5", "Fig. 5: flat punch, jumping, du/u0 = 1 ... 2 (solid exact, dashed eq. 17)", c));

    // Fig. 5 inset: the low-velocity slope against the amplitude.
    let aa = grid(1.0, 5.0, 161);
    let slope_exact: Vec<[f64; 2]> = aa.iter().map(|&a| [a, crate::claims::exact_slope(a)]).collect();
    figs.push(Figure {
        name: "fig5-inset".into(),
        title: "Fig. 5 inset: low-velocity slope mu/(mu0 vbar) vs du/u0".into(),
        x_label: "du/u0".into(),
        y_label: "slope".into(),
        range: [1.0, 5.0, 0.0, 3.5],
        curves: vec![
            Curve {
                label: "exact (solver at vbar = 1e-9)".into(),
                kind: "exact".into(),
                amp: None,
                points: slope_exact,
            },
            approx("eq. 21 corrected".into(), None, &aa, seed::eq21_slope),
            approx("eq. 21 as printed (pi too small)".into(), None, &aa, seed::eq21_slope_printed),
            approx("eq. 22 corrected, pi^2/4".into(), None, &aa, |_| seed::EQ22_CORRECTED),
            approx("eq. 22 as printed, pi/4".into(), None, &aa, |_| seed::EQ22_PRINTED),
        ],
    });

    // Figs. 7 and 8: paraboloid, with eqs. 27 and 28.
    let mut c = vec![];
    for &a in &small {
        let ms = crate::mdr::mu_static_ratio(2.0, a, crate::mdr::DEFAULT_TOL);
        c.push(exact(&parabolic, format!("du/u0 = {a}"), a, &vb, |v| v)?);
        c.push(approx(format!("eq. 27, du/u0 = {a}"), Some(a), &vb, |v| seed::eq27(v, ms)));
        c.push(approx(format!("eq. 28, du/u0 = {a}"), Some(a), &vb, |v| seed::eq28(v, ms)));
    }
    figs.push(against_vbar("fig7", "Fig. 7: parabolic, mu/mu0 vs vbar (solid exact, dashed eqs. 27, 28)", c));
    let mut c = vec![];
    for &a in small.iter().skip(1).chain(&jumping) {
        let ms = crate::mdr::mu_static_ratio(2.0, a, crate::mdr::DEFAULT_TOL);
        c.push(exact(&parabolic, format!("du/u0 = {a}"), a, &vh, |x| x / a)?);
        c.push(approx(format!("eq. 27, du/u0 = {a}"), Some(a), &vh, |x| seed::eq27(x / a, ms)));
    }
    figs.push(Figure {
        name: "fig8".into(),
        title: "Fig. 8: parabolic, mu/mu0 vs vhat (solid exact, dashed eq. 27)".into(),
        x_label: "vhat (eq. 15)".into(),
        y_label: "mu_macro / mu0".into(),
        range: [0.0, 2.0, 0.0, 1.05],
        curves: c,
    });
    Ok(figs)
}

impl crate::export::Report for Figure {
    /// Long format: `curve,kind,amp,x,y`.
    fn columns(&self) -> Vec<String> {
        ["curve", "kind", "amp", "x", "y"].map(String::from).to_vec()
    }

    fn rows(&self) -> Vec<Vec<String>> {
        let n = crate::output::num;
        self.curves
            .iter()
            .flat_map(|c| {
                c.points.iter().map(move |p| {
                    vec![c.label.clone(), c.kind.to_string(), c.amp.map_or(String::new(), n), n(p[0]), n(p[1])]
                })
            })
            .collect()
    }

    fn svg(&self) -> Option<Result<String>> {
        let series: Vec<Series> = self
            .curves
            .iter()
            .map(|c| Series {
                label: c.label.clone(),
                points: c.points.iter().map(|p| (p[0], p[1])).collect(),
                dashed: c.kind == "approximation",
            })
            .collect();
        let (x, y) = ((self.range[0], self.range[1]), (self.range[2], self.range[3]));
        Some(
            lines(&self.title, &self.x_label, &self.y_label, x, y, &series)
                .map_err(|e| Error::Internal { what: format!("drawing the plot: {e}") }),
        )
    }
}

/// Write every figure as `name.json`, `name.csv`, `name.svg` into `dir`.
pub fn write_all(dir: &std::path::Path) -> Result<Vec<String>> {
    let werr = |e: std::io::Error| Error::write(&dir.display().to_string(), e);
    std::fs::create_dir_all(dir).map_err(werr)?;
    let mut names = vec![];
    for f in build()? {
        use crate::export::{export, Format};
        for (ext, format) in [("json", Format::Json), ("csv", Format::Csv), ("svg", Format::Svg)] {
            std::fs::write(dir.join(format!("{}.{ext}", f.name)), export(&f, format)?).map_err(werr)?;
        }
        names.push(f.name);
    }
    Ok(names)
}
