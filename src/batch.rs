//! `batch`: a JSON array of `{shape, vbar, amp, ...}` objects in, the same array
//! with `mu_ratio` and `reduction` added out.
//!
//! Decisions:
//! - One bad row rejects the whole batch (the error names the row), so a caller
//!   never receives a partial array: every row is checked and evaluated before
//!   the first byte is written.
//! - Rows are kept as their raw text, borrowed from the input; only `shape`,
//!   `vbar`, `amp` are read. Each row is written back as given (other fields
//!   keep their order and bytes) with `"mu_ratio":..,"reduction":..` spliced in
//!   before its closing brace. A row that already has `mu_ratio` or
//!   `reduction` has them replaced (through a parsed map, for that row only).
//! - Duplicate keys are refused. Each distinct shape string is parsed once.
//! - Memory: the input text plus 56 bytes per row (a raw-row reference, the
//!   checked inputs, the result); measured in README.

use crate::error::{check_nonneg, Error, Result};
use crate::ratio::Ratio;
use crate::rows::{number, pick, raw_array, string};
use crate::shape::{evaluate, evaluate_stepping, Shape, Stepping};
use rayon::prelude::*;
use serde_json::value::RawValue;
use std::collections::HashMap;
use std::io::{self, Write};

/// Most rows one batch may hold.
pub const MAX_ROWS: usize = crate::grid::MAX_ROWS;

/// One checked row: its shape (an index into [`Batch::shapes`]), inputs, and
/// whether it already carried results to replace.
#[derive(Debug, Clone, Copy)]
struct Job {
    shape: u32,
    replace: bool,
    vbar: f64,
    amp: f64,
}

/// An evaluated batch, borrowing its rows from the input text.
pub struct Batch<'a> {
    rows: Vec<&'a RawValue>,
    results: Vec<Ratio>,
    replace: Vec<usize>,
}

/// Check and evaluate every row of `text` (a JSON array); `source` names the input in errors.
pub fn run<'a>(text: &'a str, source: &str, stepping: Option<Stepping>) -> Result<Batch<'a>> {
    let parse_err = |reason: String| Error::Parse { context: source.into(), reason };
    let rows = raw_array(text).map_err(parse_err)?;
    if rows.len() > MAX_ROWS {
        return Err(Error::TooLarge {
            what: format!("rows of batch {source}"),
            count: rows.len() as u128,
            limit: MAX_ROWS as u128,
        });
    }
    let mut index: HashMap<String, u32> = HashMap::new();
    let mut shapes: Vec<Shape> = vec![];
    let mut jobs = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let row_err = |reason: String| parse_err(format!("row {i}: {reason}"));
        let p = pick(row, &["shape", "vbar", "amp", "mu_ratio", "reduction"]).map_err(row_err)?;
        let field = |k: usize, name: &str| p.0[k].ok_or_else(|| row_err(format!("missing field '{name}'")));
        let spec = string(field(0, "shape")?, "shape").map_err(row_err)?;
        let vbar = number(field(1, "vbar")?, "vbar").map_err(row_err)?;
        let amp = number(field(2, "amp")?, "amp").map_err(row_err)?;
        check_nonneg("vbar", vbar).map_err(|e| row_err(e.to_string()))?;
        check_nonneg("amp", amp).map_err(|e| row_err(e.to_string()))?;
        let shape = match index.get(spec.as_ref()) {
            Some(&k) => k,
            None => {
                let parsed = crate::input::parse_shape(&spec).map_err(|e| row_err(e.to_string()))?;
                if let Some(st) = stepping {
                    st.check(&parsed).map_err(|e| row_err(e.to_string()))?;
                }
                shapes.push(parsed);
                let k = (shapes.len() - 1) as u32;
                index.insert(spec.into_owned(), k);
                k
            }
        };
        jobs.push(Job { shape, replace: p.0[3].is_some() || p.0[4].is_some(), vbar, amp });
    }
    let results = jobs
        .par_iter()
        .enumerate()
        .map(|(i, j)| {
            let shape = &shapes[j.shape as usize];
            match stepping {
                Some(st) => evaluate_stepping(shape, j.vbar, j.amp, st).map(|e| e.ratio),
                None => evaluate(shape, j.vbar, j.amp).map(|e| e.ratio),
            }
            .map_err(|e| match e {
                Error::Internal { what } => Error::Internal { what: format!("{source} row {i}: {what}") },
                e => parse_err(format!("row {i}: {e}")),
            })
        })
        .collect::<Result<Vec<Ratio>>>()?;
    let replace = jobs.iter().enumerate().filter(|(_, j)| j.replace).map(|(i, _)| i).collect();
    Ok(Batch { rows, results, replace })
}

impl Batch<'_> {
    /// Number of rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// True for an empty array.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// `mu_macro/mu0` and the reduction of every row, in order.
    pub fn results(&self) -> &[Ratio] {
        &self.results
    }

    /// Write the array: `[`, one row per line, `]`.
    pub fn write(&self, out: &mut impl Write) -> io::Result<()> {
        let mut b1 = ryu::Buffer::new();
        let mut b2 = ryu::Buffer::new();
        let mut replace = self.replace.iter().peekable();
        out.write_all(b"[")?;
        for (i, (row, r)) in self.rows.iter().zip(&self.results).enumerate() {
            out.write_all(if i == 0 { b"\n" } else { b",\n" })?;
            if replace.peek() == Some(&&i) {
                replace.next();
                let mut map: serde_json::Map<String, serde_json::Value> =
                    serde_json::from_str(row.get()).map_err(io::Error::other)?;
                map.insert("mu_ratio".into(), r.mu_ratio.into());
                map.insert("reduction".into(), r.reduction.into());
                serde_json::to_writer(&mut *out, &map)?;
                continue;
            }
            let t = row.get();
            // Every row is an object with at least shape, vbar and amp: splice before '}'.
            out.write_all(&t.as_bytes()[..t.len() - 1])?;
            out.write_all(b",\"mu_ratio\":")?;
            out.write_all(b1.format_finite(r.mu_ratio).as_bytes())?;
            out.write_all(b",\"reduction\":")?;
            out.write_all(b2.format_finite(r.reduction).as_bytes())?;
            out.write_all(b"}")?;
        }
        out.write_all(b"\n]\n")
    }
}
