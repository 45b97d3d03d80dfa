//! `batch`: a JSON array of `{shape, vbar, amp, ...}` objects in, the same array
//! with `mu_ratio` and `reduction` added out.
//!
//! Decision: one bad row rejects the whole batch (the error names the row), so
//! a caller never receives a partial array. Fields other than `shape`, `vbar`,
//! `amp` are kept as given and in order; `mu_ratio` and `reduction` present in
//! the input are replaced.

use crate::error::check_nonneg;
use crate::error::{Error, Result};
use crate::flat::Ratio;
use crate::shape::{evaluate, evaluate_stepping, Shape, Stepping};
use rayon::prelude::*;
use serde_json::{Map, Value};
use std::collections::HashMap;

/// Most rows one batch may hold.
pub const MAX_ROWS: usize = 10_000_000;

/// Evaluate every row of `text` (a JSON array); `source` names the input in errors.
pub fn run(text: &str, source: &str, stepping: Option<Stepping>) -> Result<Vec<Map<String, Value>>> {
    let parse_err = |reason: String| Error::Parse { context: source.into(), reason };
    if text.trim().is_empty() {
        return Err(parse_err("empty input (expected a JSON array)".into()));
    }
    let value: Value = serde_json::from_str(text).map_err(|e| parse_err(format!("malformed JSON: {e}")))?;
    let Value::Array(rows) = value else {
        return Err(parse_err("expected a JSON array of objects".into()));
    };
    if rows.len() > MAX_ROWS {
        return Err(Error::TooLarge {
            what: format!("rows of batch {source}"),
            count: rows.len() as u128,
            limit: MAX_ROWS as u128,
        });
    }
    // Validate every row first, then evaluate in parallel (rayon), in order.
    let mut shapes: HashMap<String, Shape> = HashMap::new();
    let mut jobs = Vec::with_capacity(rows.len());
    for (i, row) in rows.into_iter().enumerate() {
        let row_err = |reason: String| parse_err(format!("row {i}: {reason}"));
        let Value::Object(obj) = row else {
            return Err(row_err("expected an object".into()));
        };
        let spec = match obj.get("shape") {
            Some(Value::String(s)) => s.clone(),
            Some(_) => return Err(row_err("'shape' must be a string".into())),
            None => return Err(row_err("missing field 'shape'".into())),
        };
        let number = |name: &str| match obj.get(name) {
            Some(Value::Number(n)) => n.as_f64().ok_or_else(|| row_err(format!("'{name}' is not a finite number"))),
            Some(_) => Err(row_err(format!("'{name}' must be a number"))),
            None => Err(row_err(format!("missing field '{name}'"))),
        };
        let (vbar, amp) = (number("vbar")?, number("amp")?);
        check_nonneg("vbar", vbar).map_err(|e| row_err(e.to_string()))?;
        check_nonneg("amp", amp).map_err(|e| row_err(e.to_string()))?;
        if !shapes.contains_key(&spec) {
            let shape = Shape::parse(&spec).map_err(|e| row_err(e.to_string()))?;
            shapes.insert(spec.clone(), shape);
        }
        jobs.push((obj, spec, vbar, amp));
    }
    let results: Vec<Result<Ratio>> = jobs
        .par_iter()
        .map(|(_, spec, vbar, amp)| match stepping {
            Some(st) => evaluate_stepping(&shapes[spec], *vbar, *amp, st).map(|e| e.ratio),
            None => evaluate(&shapes[spec], *vbar, *amp).map(|e| e.ratio),
        })
        .collect();
    let mut out = Vec::with_capacity(jobs.len());
    for (i, ((mut obj, ..), eval)) in jobs.into_iter().zip(results).enumerate() {
        let r = eval.map_err(|e| parse_err(format!("row {i}: {e}")))?;
        obj.insert("mu_ratio".into(), Value::from(r.mu_ratio));
        obj.insert("reduction".into(), Value::from(r.reduction));
        out.push(obj);
    }
    Ok(out)
}
