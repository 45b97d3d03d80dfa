//! `validate`: compare another code's table of `(vbar, amp, mu_ratio)` with the
//! exact solver.
//!
//! Input is JSON (an array of row objects, or an object with a `rows` array, as
//! `fricosc table` prints) or CSV with a header row naming at least `vbar`,
//! `amp` and `mu_ratio` (other columns are ignored; `--shape` decides the
//! geometry). The format is recognised by the first non-blank character.

use crate::error::{check_nonneg, Error, Result};
use crate::grid::parse_number;
use crate::shape::{evaluate, Shape};
use rayon::prelude::*;
use serde::Serialize;
use serde_json::Value;

/// Most rows one file may hold.
pub const MAX_ROWS: usize = 10_000_000;

/// One compared row.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Row {
    /// Index of the row in the input (0-based, header not counted).
    pub row: usize,
    /// Dimensionless velocity.
    pub vbar: f64,
    /// Amplitude `du/u0`.
    pub amp: f64,
    /// The value under test.
    pub mu_ratio: f64,
    /// The exact value.
    pub exact: f64,
    /// `mu_ratio - exact`.
    pub error: f64,
}

/// The comparison of a whole table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Validation {
    /// Shape name.
    pub shape: String,
    /// Number of rows.
    pub n: usize,
    /// Largest `|error|`.
    pub max_abs_error: f64,
    /// Root mean square of the errors.
    pub rms_error: f64,
    /// The row with the largest `|error|` (absent for an empty table).
    pub worst: Option<Row>,
    /// Every row.
    pub rows: Vec<Row>,
}

/// Read `(vbar, amp, mu_ratio)` rows from JSON or CSV text; `source` names it in errors.
pub fn read_rows(text: &str, source: &str) -> Result<Vec<(f64, f64, f64)>> {
    let err = |reason: String| Error::Parse { context: source.into(), reason };
    let rows = match text.trim_start().chars().next() {
        None => return Err(err("empty input".into())),
        Some('[') | Some('{') => {
            let v: Value = serde_json::from_str(text).map_err(|e| err(format!("malformed JSON: {e}")))?;
            let arr = match v {
                Value::Array(a) => a,
                Value::Object(mut o) => match o.remove("rows") {
                    Some(Value::Array(a)) => a,
                    _ => return Err(err("a JSON object needs a 'rows' array".into())),
                },
                _ => return Err(err("expected a JSON array or an object with 'rows'".into())),
            };
            arr.iter()
                .enumerate()
                .map(|(i, r)| {
                    let num = |k: &str| match r.get(k) {
                        Some(Value::Number(n)) => {
                            n.as_f64().ok_or_else(|| err(format!("row {i}: '{k}' is not finite")))
                        }
                        Some(_) => Err(err(format!("row {i}: '{k}' must be a number"))),
                        None => Err(err(format!("row {i}: missing field '{k}'"))),
                    };
                    Ok((num("vbar")?, num("amp")?, num("mu_ratio")?))
                })
                .collect::<Result<Vec<_>>>()?
        }
        Some(_) => {
            let mut lines = text.lines().filter(|l| !l.trim().is_empty());
            let header: Vec<&str> = lines.next().unwrap_or("").split(',').map(str::trim).collect();
            let col = |name: &str| {
                header.iter().position(|h| *h == name).ok_or_else(|| err(format!("CSV header lacks column '{name}'")))
            };
            let (cv, ca, cm) = (col("vbar")?, col("amp")?, col("mu_ratio")?);
            lines
                .enumerate()
                .map(|(i, l)| {
                    let f: Vec<&str> = l.split(',').collect();
                    let get = |c: usize, name: &str| {
                        let t = f.get(c).ok_or_else(|| err(format!("row {i}: missing column '{name}'")))?;
                        parse_number(&format!("{source}: row {i}: {name}"), t)
                    };
                    Ok((get(cv, "vbar")?, get(ca, "amp")?, get(cm, "mu_ratio")?))
                })
                .collect::<Result<Vec<_>>>()?
        }
    };
    if rows.len() > MAX_ROWS {
        return Err(Error::TooLarge {
            what: format!("rows of table {source}"),
            count: rows.len() as u128,
            limit: MAX_ROWS as u128,
        });
    }
    for (i, &(v, a, m)) in rows.iter().enumerate() {
        let at = |e: Error| err(format!("row {i}: {e}"));
        check_nonneg("vbar", v).map_err(at)?;
        check_nonneg("amp", a).map_err(at)?;
        if !m.is_finite() {
            return Err(err(format!("row {i}: mu_ratio is not finite")));
        }
    }
    Ok(rows)
}

/// Compare `rows` with the exact solver for `shape`.
pub fn validate(shape: &Shape, rows: &[(f64, f64, f64)]) -> Result<Validation> {
    let exact: Vec<Result<f64>> =
        rows.par_iter().map(|&(v, a, _)| evaluate(shape, v, a).map(|e| e.ratio.mu_ratio)).collect();
    let mut out = Vec::with_capacity(rows.len());
    for (i, (&(vbar, amp, mu_ratio), e)) in rows.iter().zip(exact).enumerate() {
        let exact = e?;
        out.push(Row { row: i, vbar, amp, mu_ratio, exact, error: mu_ratio - exact });
    }
    let n = out.len();
    let worst = out.iter().copied().max_by(|a, b| a.error.abs().total_cmp(&b.error.abs()));
    let max_abs_error = worst.map_or(0.0, |w| w.error.abs());
    let rms_error = if n > 0 { (out.iter().map(|r| r.error * r.error).sum::<f64>() / n as f64).sqrt() } else { 0.0 };
    Ok(Validation { shape: shape.name(), n, max_abs_error, rms_error, worst, rows: out })
}
