//! `fricosc fit`: the model fitted to measured friction (`fricosc::fit`).

use crate::cmd::{emit, positive, read_input, Outcome};
use crate::error::{Error, Result};
use crate::tables::{read_columns, Kind};
use clap::Args;
use fricosc::fit::{FitReport, Fixed, Measurement, Parameter, NAMES};
use std::io::IsTerminal;

#[derive(Args)]
pub struct FitArgs {
    /// Measurements (CSV or JSON, as validate reads tables; stdin when '-'): columns v0 (m/s),
    /// du (m), frequency (Hz) or omega (rad/s), mu, optionally sigma (its standard uncertainty).
    pub file: String,
    /// Indenter shape: flat, parabolic, cone, power:N, flat-tip:E, profile:FILE@U0, gx:FILE@U0.
    #[arg(long, default_value = "flat")]
    pub shape: String,
    /// Hold mu0 at this value (else fitted).
    #[arg(long, allow_hyphen_values = true, value_parser = positive)]
    pub mu0: Option<f64>,
    /// Hold kx/kz at this value (else fitted).
    #[arg(long, allow_hyphen_values = true, value_parser = positive)]
    pub stiffness_ratio: Option<f64>,
    /// Hold the mean indentation u0 (m) at this value (else fitted); one u0 for all rows (a fixed
    /// mean indentation, not a fixed mean load).
    #[arg(long, allow_hyphen_values = true, value_parser = positive)]
    pub u0: Option<f64>,
    /// The rig's system, held at these values (dimensionless, as for point): the model is the
    /// body's attractor there. --frequency-ratio holds at one frequency.
    #[command(flatten)]
    pub system: crate::cmd::SystemPoint,
    /// Fit the system's stiffness kappa = K/kx from --system-stiffness (--frequency-ratio and
    /// --damping held).
    #[arg(long, requires = "system_stiffness")]
    pub fit_system_stiffness: bool,
    /// Keep a fitted parameter within LO..HI (HI may be inf): NAME=LO:HI, NAME one of mu0,
    /// stiffness-ratio, u0, system-stiffness; repeatable. One that ends on its bound is named.
    #[arg(long = "bound", value_name = "NAME=LO:HI")]
    pub bounds: Vec<String>,
    /// summary or json (default: summary at a terminal, else json).
    #[arg(long)]
    pub format: Option<String>,
    /// Draw the data (sigma as error bars), the fitted curves and the residuals into this file
    /// (.svg or .png).
    #[arg(long)]
    pub plot: Option<String>,
}

/// Most rows a drawing shows (evenly spread; the outliers besides).
const MAX_DRAWN: usize = 4_000;

/// The columns `fit` reads, in order.
const WANTED: [(&str, Kind); 7] = [
    ("v0", Kind::Number),
    ("du", Kind::Number),
    ("frequency", Kind::Number),
    ("omega", Kind::Number),
    ("mu", Kind::Number),
    ("sigma", Kind::Number),
    ("load", Kind::Number),
];

/// Prints the fit; [`Outcome::Negative`] (exit 1) where it has a verdict.
pub fn run(a: FitArgs) -> Result<Outcome> {
    let json = match a.format.as_deref() {
        Some("json") => true,
        Some("summary") => false,
        Some(other) => return Err(Error::parse("--format", format!("'{other}' is not summary or json"))),
        None => !std::io::stdout().is_terminal(),
    };
    if let Some(path) = &a.plot {
        crate::cmd::drawing_kind("--plot", path)?;
    }
    let shape = crate::input::parse_shape(&a.shape)?;
    let (text, source) = read_input(Some(a.file.clone()))?;
    let (mut rows, lines) = measurements(&text, &source)?;
    if let Some(sys) = a.system.system(None)? {
        rows.iter_mut().for_each(|r| r.system = Some(sys));
    }
    let fixed = Fixed {
        mu0: a.mu0,
        stiffness_ratio: a.stiffness_ratio,
        u0: a.u0,
        fit_system_stiffness: a.fit_system_stiffness,
        bounds: bounds_of(&a.bounds)?,
    };
    let bar = std::sync::Arc::new(crate::progress::Bar::new(None, "fit: rows evaluated"));
    let seen = bar.clone();
    let r = fricosc::fit::fit_with_progress(&shape, &rows, &fixed, move |n| seen.inc(n as u64))?;
    drop(bar);
    // The result first: a drawing never holds it back.
    let out = if json { to_json(shape.name(), &rows, &r)? + "\n" } else { summary(shape.name(), &source, &r, &lines) };
    emit(&out)?;
    if let Some(path) = &a.plot {
        crate::cmd::write_drawing("--plot", path, &drawing(&shape, &rows, &r)?)?;
    }
    Ok(if r.verdicts.is_empty() { Outcome::Done } else { Outcome::Negative })
}

/// `--bound NAME=LO:HI` options as [`Fixed::bounds`] (a name given twice refused).
fn bounds_of(given: &[String]) -> Result<[Option<[f64; 2]>; 4]> {
    let mut out = [None; 4];
    for b in given {
        let bad = || Error::parse("--bound", format!("'{b}' is not NAME=LO:HI (NAME one of {})", NAMES.join(", ")));
        let (name, range) = b.split_once('=').ok_or_else(bad)?;
        let k = NAMES.iter().position(|n| *n == name.trim().replace('-', "_")).filter(|&k| out[k].is_none());
        let ((lo, hi), k) = (range.split_once(':').ok_or_else(bad)?, k.ok_or_else(bad)?);
        let num = |x: &str| x.trim().parse::<f64>().map_err(|_| bad());
        out[k] = Some([num(lo)?, num(hi)?]);
    }
    Ok(out)
}

/// The rows of a measurement file (named columns; a missing one named).
/// Also each row's line in the file (CSV; empty for JSON).
fn measurements(text: &str, source: &str) -> Result<(Vec<Measurement>, Vec<u64>)> {
    let c = read_columns(text, source, &WANTED, crate::validate::MAX_ROWS)?;
    let bad = |reason: String| Error::Parse { context: source.into(), reason };
    // A column fit does not read is refused, not ignored (a 'Sigma' would run unweighted).
    let known: Vec<&str> = WANTED.iter().map(|w| w.0).collect();
    if let Some(name) = c.names.iter().find(|n| !known.contains(&n.as_str())) {
        let like =
            known.iter().find(|k| k.eq_ignore_ascii_case(name.trim())).map(|k| format!(" (did you mean '{k}'?)"));
        return Err(bad(format!(
            "unknown column '{name}'{}: fit reads {}",
            like.unwrap_or_default(),
            known.join(", ")
        )));
    }
    let need = |k: usize| c.numbers[k].clone().ok_or_else(|| bad(format!("no column '{}'", WANTED[k].0)));
    let (v0, du, mu) = (need(0)?, need(1)?, need(4)?);
    let omega = match (&c.numbers[2], &c.numbers[3]) {
        (Some(f), None) => f.iter().map(|f| 2.0 * std::f64::consts::PI * f).collect(),
        (None, Some(w)) => w.clone(),
        (Some(_), Some(_)) => return Err(bad("give one of the columns 'frequency' and 'omega', not both".into())),
        (None, None) => return Err(bad("no column 'frequency' (Hz) or 'omega' (rad/s)".into())),
    };
    let (sigma, load) = (c.numbers[5].clone(), c.numbers[6].clone());
    let row = |i: usize| Measurement {
        v0: v0[i],
        du: du[i],
        omega: omega[i],
        mu: mu[i],
        sigma: sigma.as_ref().map(|s| s[i]),
        system: None,
        load: load.as_ref().map(|l| l[i]),
    };
    Ok(((0..c.rows).map(row).collect(), c.lines))
}

fn parameter(p: &Parameter) -> serde_json::Value {
    // The bounds as set ([0, null]: none; JSON has no infinity).
    serde_json::json!({"value": p.value, "stderr": p.stderr, "fixed": p.fixed, "profile": p.profile, "bounds": p.bounds})
}

/// Every row of the JSON report, each made as it is written (a million rows
/// never exist as JSON values at once).
struct RowsOut<'a>(&'a [Measurement], &'a FitReport);

impl serde::Serialize for RowsOut<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let (rows, r) = (self.0, self.1);
        s.collect_seq(rows.iter().enumerate().map(|(i, m)| {
            let (res, p) = (r.residuals[i], r.points[i]);
            serde_json::json!({"v0": m.v0, "du": m.du, "omega": m.omega, "mu": m.mu, "sigma": m.sigma,
                "model": m.mu - res, "residual": res, "normalised_residual": r.normalised_residuals[i],
                "vbar": p[0], "amp": p[1], "load": m.load})
        }))
    }
}

/// The report as JSON: parameters, covariance, correlation, chi-square, and every row.
fn to_json(shape: &str, rows: &[Measurement], r: &FitReport) -> Result<String> {
    let head = serde_json::json!({
        "shape": shape,
        "parameters": r.parameters.iter().map(|p| (p.name.to_string(), parameter(p))).collect::<serde_json::Map<_, _>>(),
        "order": r.parameters.iter().map(|p| p.name).collect::<Vec<_>>(),
        "covariance": r.covariance, "correlation": r.correlation,
        "chi2": r.chi2, "dof": r.dof, "reduced_chi2": r.reduced_chi2, "weighted": r.weighted,
        "p_value": r.p_value, "verdicts": r.verdicts, "notes": r.notes, "outliers": r.outliers,
        "outlier_threshold": r.outlier_threshold,
        "iterations": r.iterations, "converged": r.converged, "reference_load": r.reference_load,
    });
    #[derive(serde::Serialize)]
    struct Out<'a> {
        #[serde(flatten)]
        head: serde_json::Value,
        rows: RowsOut<'a>,
    }
    serde_json::to_string_pretty(&Out { head, rows: RowsOut(rows, r) })
        .map_err(|e| Error::Internal { what: format!("fit report: {e}") })
}

/// The report for a person: each value rounded to its standard error's
/// second significant digit.
fn summary(shape: &str, source: &str, r: &FitReport, lines: &[u64]) -> String {
    let line = |name: &str, p: &Parameter| match (p.fixed, p.stderr) {
        (true, _) => format!("  {name:<16} {} (fixed)\n", crate::output::num(p.value)),
        (false, Some(se)) => {
            let profile = p.profile.map(|[a, b]| format!(" (profile interval {a:.3e} to {b:.3e})"));
            format!("  {name:<16} {}{}\n", rounded(p.value, se), profile.unwrap_or_default())
        }
        (false, None) if p.bounds.contains(&p.value) => format!("  {name:<16} {} (on its bound)\n", p.value),
        (false, None) => format!("  {name:<16} {} (not determined)\n", crate::output::num(p.value)),
    };
    let mut out = format!("{source}: {} rows fitted with the {shape} model\n", r.residuals.len());
    for p in &r.parameters {
        let name = match p.name {
            "stiffness_ratio" => "kx/kz".into(),
            "u0" => r.reference_load.map_or("u0 (m)".into(), |l| format!("u0 (m) at {l} N")),
            "system_stiffness" => "K/kx".into(),
            other => other.to_string(),
        };
        out += &line(&name, p);
    }
    let kind = if r.weighted { "weighted by sigma" } else { "unweighted: errors scaled by the residuals" };
    let p =
        r.p_value.map(|p| if p >= 0.01 { format!(", p {p:.2}") } else { format!(", p {p:.1e}") }).unwrap_or_default();
    out += &format!("chi2 {:.4}, dof {}, reduced chi2 {:.3}{p} ({kind})\n", r.chi2, r.dof, r.reduced_chi2);
    for v in &r.verdicts {
        out += &format!("verdict: {v}\n");
    }
    for n in &r.notes {
        out += &format!("note: {n}\n");
    }
    // The outliers (rows counted from 0) by their lines in the file.
    let named: Vec<String> = r
        .outliers
        .iter()
        .take(10)
        .map(|&i| match lines.get(i) {
            Some(l) => format!("row {i} (line {l})"),
            None => format!("row {i}"),
        })
        .collect();
    if !named.is_empty() {
        let beyond = r.outlier_threshold;
        out += &format!("outliers beyond {beyond:.2} standard uncertainties: {}\n", named.join(", "));
    }
    out
}

/// `value +- error`, the error to two significant digits and the value to
/// the same decimal place (`0.3487 +- 0.0010`; in exponent form beyond 1e4
/// or below 1e-3: `(9.72 +- 0.14)e-7`).
fn rounded(value: f64, error: f64) -> String {
    if !(error.is_finite() && error > 0.0) {
        return format!("{} +- {}", crate::output::num(value), crate::output::num(error));
    }
    let place = error.log10().floor() as i32 - 1;
    let exp = if value != 0.0 { value.abs().log10().floor() as i32 } else { place + 1 };
    if (-3..4).contains(&exp) {
        let digits = (-place).max(0) as usize;
        format!("{value:.digits$} +- {error:.digits$}")
    } else {
        let scale = 10f64.powi(exp);
        let digits = (exp - place).max(0) as usize;
        format!("({:.digits$} +- {:.digits$})e{exp}", value / scale, error / scale)
    }
}

/// The fit's drawing: the data (with their `sigma` as error bars) and the
/// fitted curve of each amplitude and frequency against `v0`, the residuals
/// below; one SVG of the two charts.
fn drawing(shape: &fricosc::Shape, rows: &[Measurement], r: &FitReport) -> Result<String> {
    use crate::chart::{viridis, Axis, Chart, Key, Marker, Rule, Series, Style};
    // A curve for each amplitude, frequency and (under load control) load.
    let mut groups: Vec<(f64, f64, f64)> = rows.iter().map(|m| (m.du, m.omega, m.load.unwrap_or(0.0))).collect();
    groups.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)).then(a.2.total_cmp(&b.2)));
    groups.dedup();
    let vmax = rows.iter().map(|m| m.v0).fold(0.0, f64::max) * 1.05;
    let colour = |k: usize| viridis(if groups.len() > 1 { k as f64 / (groups.len() - 1) as f64 } else { 0.0 });
    let (mut top, mut bottom, mut ymax, mut rmax) = (vec![], vec![], 0.0f64, 0.0f64);
    for (k, &(du, omega, load)) in groups.iter().enumerate() {
        let load = (load > 0.0).then_some(load);
        let style = Style::line(colour(k));
        let curve = (0..=200)
            .map(|i| {
                let v0 = vmax * i as f64 / 200.0;
                Ok((v0, r.predict(shape, (v0, du, omega), rows[0].system, load)?))
            })
            .collect::<Result<Vec<_>>>()?;
        let f = omega / std::f64::consts::TAU;
        let freq = if f >= 1e3 { format!("{} kHz", f / 1e3) } else { format!("{f} Hz") };
        let label = format!("Δu = {du:e} m, f = {freq}{}", load.map(|l| format!(", {l} N")).unwrap_or_default());
        ymax = curve.iter().fold(ymax, |m, p| m.max(p.1));
        top.push(Series { label: label.clone(), points: curve, style, legend: true });
        // At most about MAX_DRAWN rows drawn, evenly spread, and every outlier.
        let every = rows.len().div_ceil(MAX_DRAWN);
        let mine: Vec<(&Measurement, f64)> = rows
            .iter()
            .zip(&r.residuals)
            .enumerate()
            .filter(|(i, (m, _))| {
                (m.du, m.omega, m.load) == (du, omega, load) && (i % every == 0 || r.outliers.contains(i))
            })
            .map(|(_, (m, e))| (m, *e))
            .collect();
        let bars = |centre: &dyn Fn(&Measurement, f64) -> f64| {
            let mut pts = vec![];
            for (m, e) in &mine {
                let s = m.sigma.unwrap_or(0.0);
                pts.extend([(m.v0, centre(m, *e) - s), (m.v0, centre(m, *e) + s), (f64::NAN, f64::NAN)]);
            }
            pts
        };
        let dots = Style { dash: None, ..style }.marker(Marker::Circle);
        for (charts, centre) in [
            (&mut top, &(|m: &Measurement, _| m.mu) as &dyn Fn(&Measurement, f64) -> f64),
            (&mut bottom, &|_: &Measurement, e: f64| e),
        ] {
            // The error bars drawn over the markers (which would hide them).
            let points = mine.iter().map(|(m, e)| (m.v0, centre(m, *e))).collect();
            charts.push(Series { label: format!("{label}, measured"), points, style: dots, legend: false });
            charts.push(Series {
                label: format!("{label}, sigma"),
                points: bars(centre),
                style: style.width(0.8),
                legend: false,
            });
        }
        for (m, e) in &mine {
            ymax = ymax.max(m.mu + m.sigma.unwrap_or(0.0));
            rmax = rmax.max(e.abs() + m.sigma.unwrap_or(0.0));
        }
    }
    let x = Axis::linear("sliding velocity v_{0} (m/s)", (0.0, vmax));
    let fit = Chart {
        title: format!(
            "{}: mu against v0, fitted (mu0 {}, kx/kz {}, u0 {} m{})",
            shape.name(),
            value(r, "mu0"),
            value(r, "stiffness_ratio"),
            value(r, "u0"),
            r.parameter("system_stiffness")
                .map_or(String::new(), |p| format!(", K/kx {}", crate::output::num(p.value)))
        ),
        x: x.clone(),
        y: Axis::linear("friction coefficient μ", (0.0, 1.05 * ymax)),
        series: top,
        key: vec![Key::Heading("fitted model, measured ± σ".into())],
        rules: vec![],
    };
    let residuals = Chart {
        title: "residuals".into(),
        x,
        y: Axis::linear("residual μ - model", (-1.1 * rmax.max(1e-300), 1.1 * rmax.max(1e-300))),
        series: bottom,
        key: vec![],
        rules: vec![Rule { horizontal: true, at: 0.0 }],
    };
    Ok(stack(&fit.svg(), &residuals.svg()))
}

/// The value of the parameter `name` as printed (`-` where the fit has none).
fn value(r: &FitReport, name: &str) -> String {
    r.parameter(name).map_or("-".into(), |p| crate::output::num(p.value))
}

/// Two SVG drawings of the chart module, the second below the first.
fn stack(upper: &str, lower: &str) -> String {
    let height = |svg: &str| crate::chart::parse_size(svg).map_or(0.0, |s| s.1);
    let inner = |svg: &str| {
        let start = svg.find('>').map_or(0, |i| i + 1);
        let end = svg.rfind("</svg>").unwrap_or(svg.len());
        svg[start..end].to_string()
    };
    let (h1, h2) = (height(upper), height(lower));
    let width = crate::chart::WIDTH;
    let lower = inner(lower).replace("id=\"plot\"", "id=\"plot2\"").replace("url(#plot)", "url(#plot2)");
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}pt" height="{h}pt" viewBox="0 0 {width} {h}" font-family="DejaVu Sans, Verdana, sans-serif">{}<g transform="translate(0 {h1})">{lower}</g></svg>
"#,
        inner(upper),
        h = h1 + h2
    )
}
