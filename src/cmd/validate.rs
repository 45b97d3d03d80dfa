//! `fricosc validate`: another code's table against the exact values.

use super::{io_err, read_input, Outcome};
use fricosc::error::Result;
use fricosc::grid::parse_number;
use std::io::{self, Write};

/// Prints the comparison; [`Outcome::Negative`] when `--max-error` is exceeded.
pub(crate) fn run(shape: &str, file: String, max_error: Option<String>) -> Result<Outcome> {
    let shape = fricosc::input::parse_shape(shape)?;
    let max_error = match max_error {
        Some(t) => Some(fricosc::error::check_nonneg("max-error", parse_number("--max-error", &t)?)?),
        None => None,
    };
    let (text, source) = read_input(Some(file))?;
    let table = fricosc::validate::read_table(&text, &source)?;
    drop(text);
    let mut v = fricosc::validate::validate(&shape, &table.rows)?;
    v.ignored_columns = table.ignored_columns;
    let mut out = io::BufWriter::new(io::stdout().lock());
    serde_json::to_writer_pretty(&mut out, &v).map_err(|e| io_err(e.into()))?;
    writeln!(out).map_err(io_err)?;
    out.flush().map_err(io_err)?;
    Ok(if max_error.is_none_or(|e| v.max_abs_error <= e) { Outcome::Done } else { Outcome::Negative })
}
