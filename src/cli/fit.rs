//! `fricosc fit`: the model fitted to measured friction (`fricosc::fit`).

use crate::cmd::{emit, positive, read_input};
use crate::error::{Error, Result};
use crate::tables::{read_columns, Kind};
use clap::Args;
use fricosc::fit::{FitReport, Fixed, Measurement, Parameter};
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
    /// Hold the mean indentation u0 (m) at this value (else fitted).
    #[arg(long, allow_hyphen_values = true, value_parser = positive)]
    pub u0: Option<f64>,
    /// summary or json (default: summary at a terminal, else json).
    #[arg(long)]
    pub format: Option<String>,
}

/// The columns `fit` reads, in order.
const WANTED: [(&str, Kind); 6] = [
    ("v0", Kind::Number),
    ("du", Kind::Number),
    ("frequency", Kind::Number),
    ("omega", Kind::Number),
    ("mu", Kind::Number),
    ("sigma", Kind::Number),
];

pub fn run(a: FitArgs) -> Result<()> {
    let json = match a.format.as_deref() {
        Some("json") => true,
        Some("summary") => false,
        Some(other) => {
            return Err(Error::Parse {
                context: "--format".into(),
                reason: format!("'{other}' is not summary or json"),
            })
        }
        None => !std::io::stdout().is_terminal(),
    };
    let shape = crate::input::parse_shape(&a.shape)?;
    let (text, source) = read_input(Some(a.file.clone()))?;
    let rows = measurements(&text, &source)?;
    let fixed = Fixed { mu0: a.mu0, stiffness_ratio: a.stiffness_ratio, u0: a.u0 };
    let r = fricosc::fit::fit(&shape, &rows, &fixed)?;
    let out = if json { to_json(shape.name(), &rows, &r)? + "\n" } else { summary(shape.name(), &source, &r) };
    emit(&out)
}

/// The rows of a measurement file (named columns; a missing one named).
fn measurements(text: &str, source: &str) -> Result<Vec<Measurement>> {
    let c = read_columns(text, source, &WANTED, crate::validate::MAX_ROWS)?;
    let bad = |reason: String| Error::Parse { context: source.into(), reason };
    let need = |k: usize| c.numbers[k].clone().ok_or_else(|| bad(format!("no column '{}'", WANTED[k].0)));
    let (v0, du, mu) = (need(0)?, need(1)?, need(4)?);
    let omega = match (&c.numbers[2], &c.numbers[3]) {
        (Some(f), None) => f.iter().map(|f| 2.0 * std::f64::consts::PI * f).collect(),
        (None, Some(w)) => w.clone(),
        (Some(_), Some(_)) => return Err(bad("give one of the columns 'frequency' and 'omega', not both".into())),
        (None, None) => return Err(bad("no column 'frequency' (Hz) or 'omega' (rad/s)".into())),
    };
    let sigma = c.numbers[5].clone();
    Ok((0..c.rows)
        .map(|i| Measurement { v0: v0[i], du: du[i], omega: omega[i], mu: mu[i], sigma: sigma.as_ref().map(|s| s[i]) })
        .collect())
}

fn parameter(p: &Parameter) -> serde_json::Value {
    serde_json::json!({"value": p.value, "stderr": p.stderr, "fixed": p.fixed})
}

/// The report as JSON: parameters, covariance, correlation, chi-square, and every row.
fn to_json(shape: &str, rows: &[Measurement], r: &FitReport) -> Result<String> {
    let per_row: Vec<serde_json::Value> = rows
        .iter()
        .zip(&r.residuals)
        .zip(&r.points)
        .map(|((m, res), p)| {
            serde_json::json!({"v0": m.v0, "du": m.du, "omega": m.omega, "mu": m.mu, "sigma": m.sigma,
                "model": m.mu - res, "residual": res, "vbar": p[0], "amp": p[1]})
        })
        .collect();
    let v = serde_json::json!({
        "shape": shape,
        "parameters": {"mu0": parameter(&r.mu0), "stiffness_ratio": parameter(&r.stiffness_ratio),
            "u0": parameter(&r.u0)},
        "order": ["mu0", "stiffness_ratio", "u0"],
        "covariance": r.covariance, "correlation": r.correlation,
        "chi2": r.chi2, "dof": r.dof, "reduced_chi2": r.reduced_chi2, "weighted": r.weighted,
        "verdicts": r.verdicts, "iterations": r.iterations, "rows": per_row,
    });
    serde_json::to_string_pretty(&v).map_err(|e| Error::Internal { what: format!("fit report: {e}") })
}

/// The report for a person.
fn summary(shape: &str, source: &str, r: &FitReport) -> String {
    let line = |name: &str, p: &Parameter| {
        let v = crate::output::num(p.value);
        match (p.fixed, p.stderr) {
            (true, _) => format!("  {name:<16} {v} (fixed)\n"),
            (false, Some(se)) => format!("  {name:<16} {v} +- {se:.3e}\n"),
            (false, None) => format!("  {name:<16} {v} (not determined)\n"),
        }
    };
    let mut out = format!("{source}: {} rows fitted with the {shape} model\n", r.residuals.len());
    out += &line("mu0", &r.mu0);
    out += &line("kx/kz", &r.stiffness_ratio);
    out += &line("u0 (m)", &r.u0);
    let kind = if r.weighted { "weighted by sigma" } else { "unweighted: errors scaled by the residuals" };
    out += &format!("chi2 {:.4e}, dof {}, reduced chi2 {:.4e} ({kind})\n", r.chi2, r.dof, r.reduced_chi2);
    for v in &r.verdicts {
        out += &format!("not determined: {v}\n");
    }
    out
}
