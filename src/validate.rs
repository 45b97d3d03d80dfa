//! `validate`: compare another code's table of `(vbar, amp, mu_ratio)` with the
//! exact solver.
//!
//! Input is JSON (an array of row objects, or an object with a `rows` array, as
//! `fricosc table` prints) or CSV with a header row naming at least `vbar`,
//! `amp` and `mu_ratio` (other columns are listed as `ignored_columns` in the
//! report; `--shape` decides the geometry). The format is recognised by the first non-blank character.

use crate::error::{check_nonneg, Error, Result};
use crate::grid::parse_number;
use crate::rows::{number, pick, raw_array};
use crate::shape::{evaluate, Shape};
use rayon::prelude::*;
use serde::Serialize;
use serde_json::value::RawValue;

/// Most rows one file may hold.
pub const MAX_ROWS: usize = crate::grid::MAX_ROWS;

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
    /// CSV columns that were read but not compared (absent when none).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub ignored_columns: Vec<String>,
    /// Every row.
    pub rows: Vec<Row>,
}

/// Read `(vbar, amp, mu_ratio)` rows from JSON or CSV text; `source` names it in errors.
///
/// JSON rows are read from their raw text (no value trees; duplicate keys are
/// refused). CSV is read with a real CSV reader (quoted fields, a byte-order
/// mark tolerated by [`crate::input`]); a duplicated column is refused, and a
/// table without data rows is an error, never a pass.
pub fn read_rows(text: &str, source: &str) -> Result<Vec<(f64, f64, f64)>> {
    Ok(read_table(text, source)?.rows)
}

/// The rows of a table and the CSV columns that were not used.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// `(vbar, amp, mu_ratio)` per row.
    pub rows: Vec<(f64, f64, f64)>,
    /// CSV header columns other than `vbar`, `amp`, `mu_ratio` (not compared).
    pub ignored_columns: Vec<String>,
}

/// As [`read_rows`], with the ignored CSV columns.
pub fn read_table(text: &str, source: &str) -> Result<Table> {
    let err = |reason: String| Error::Parse { context: source.into(), reason };
    let mut ignored_columns = vec![];
    let rows = match text.trim_start().chars().next() {
        None => return Err(err("empty input".into())),
        Some('[') | Some('{') => {
            let whole: &RawValue = serde_json::from_str(text).map_err(|e| err(format!("malformed JSON: {e}")))?;
            let array = if whole.get().starts_with('{') {
                let p = pick(whole, &["rows"]).map_err(err)?;
                p.0[0].ok_or_else(|| err("a JSON object needs a 'rows' array".into()))?
            } else {
                whole
            };
            let rows = raw_array(array.get()).map_err(|_| err("'rows' must be a JSON array".into()))?;
            rows.iter()
                .enumerate()
                .map(|(i, r)| {
                    let row_err = |reason: String| err(format!("row {i}: {reason}"));
                    let p = pick(r, &["vbar", "amp", "mu_ratio"]).map_err(row_err)?;
                    let get = |k: usize, name: &str| {
                        let raw = p.0[k].ok_or_else(|| row_err(format!("missing field '{name}'")))?;
                        number(raw, name).map_err(row_err)
                    };
                    Ok((get(0, "vbar")?, get(1, "amp")?, get(2, "mu_ratio")?))
                })
                .collect::<Result<Vec<_>>>()?
        }
        Some(_) => {
            let mut rd = csv::ReaderBuilder::new().trim(csv::Trim::All).from_reader(text.as_bytes());
            let header: Vec<String> =
                rd.headers().map_err(|e| err(format!("CSV header: {e}")))?.iter().map(str::to_string).collect();
            for (k, h) in header.iter().enumerate() {
                if header[..k].contains(h) {
                    return Err(err(format!("CSV header has column '{h}' twice")));
                }
            }
            let col = |name: &str| {
                header.iter().position(|h| h == name).ok_or_else(|| err(format!("CSV header lacks column '{name}'")))
            };
            let (cv, ca, cm) = (col("vbar")?, col("amp")?, col("mu_ratio")?);
            ignored_columns =
                header.iter().filter(|h| !["vbar", "amp", "mu_ratio"].contains(&h.as_str())).cloned().collect();
            rd.records()
                .enumerate()
                .map(|(i, rec)| {
                    let rec = rec.map_err(|e| err(format!("row {i}: {e}")))?;
                    let get = |c: usize, name: &str| {
                        let t = rec.get(c).ok_or_else(|| err(format!("row {i}: missing column '{name}'")))?;
                        parse_number(&format!("{source}: row {i}: {name}"), t)
                    };
                    Ok((get(cv, "vbar")?, get(ca, "amp")?, get(cm, "mu_ratio")?))
                })
                .collect::<Result<Vec<_>>>()?
        }
    };
    if rows.is_empty() {
        return Err(err("the table has no rows (nothing to validate)".into()));
    }
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
    Ok(Table { rows, ignored_columns })
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
    Ok(Validation { shape: shape.name(), n, max_abs_error, rms_error, worst, ignored_columns: vec![], rows: out })
}
