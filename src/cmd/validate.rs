//! `fricosc validate`: another code's table against the exact values, with
//! errors by regime and amplitude and findings that point at bugs.

use super::{io_err, read_input, Outcome};
use fricosc::error::{Error, Result};
use fricosc::grid::parse_number;
use fricosc::validate::{AtRest, Validation};
use std::io::{self, IsTerminal, Write};

/// The options of `validate` (see `main.rs` for their help).
pub(crate) struct ValidateArgs {
    pub(crate) shape: Option<String>,
    pub(crate) file: String,
    pub(crate) max_error: Option<String>,
    pub(crate) at_rest: String,
    pub(crate) mu0: Option<String>,
    pub(crate) tolerance: String,
    pub(crate) format: Option<String>,
}

/// Where the shape came from.
#[derive(serde::Serialize)]
#[serde(rename_all = "snake_case")]
enum ShapeSource {
    File,
    Option,
    Default,
}

#[derive(serde::Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    validation: &'a Validation,
    shape_source: ShapeSource,
    #[serde(skip_serializing_if = "<[String]>::is_empty")]
    ignored_columns: &'a [String],
}

/// Prints the comparison; [`Outcome::Negative`] when `--max-error` is exceeded.
pub(crate) fn run(a: ValidateArgs) -> Result<Outcome> {
    let max_error = match &a.max_error {
        Some(t) => Some(fricosc::error::check_nonneg("max-error", parse_number("--max-error", t)?)?),
        None => None,
    };
    let at_rest = match a.at_rest.as_str() {
        "sliding" => AtRest::Sliding,
        "relaxed" => AtRest::Relaxed,
        other => {
            return Err(Error::Parse {
                context: "--at-rest".into(),
                reason: format!("'{other}' is neither 'sliding' nor 'relaxed'"),
            })
        }
    };
    let mu0 = a.mu0.as_deref().map(|m| parse_number("--mu0", m)).transpose()?;
    let tolerance = fricosc::error::check_nonneg("tolerance", parse_number("--tolerance", &a.tolerance)?)?;
    let format = match a.format.as_deref() {
        Some(f @ ("summary" | "json" | "csv")) => f.to_string(),
        Some(other) => {
            return Err(Error::Parse {
                context: "--format".into(),
                reason: format!("'{other}' is not one of summary, json, csv"),
            })
        }
        // A person at a terminal reads the summary; a pipe gets JSON.
        None if io::stdout().is_terminal() => "summary".into(),
        None => "json".into(),
    };
    let (text, source) = read_input(Some(a.file))?;
    let table = fricosc::validate::read_table(&text, &source)?;
    drop(text);
    // The file's shape decides; --shape only where the file names none.
    let (shape, shape_source) = match (&table.shape, &a.shape) {
        (Some(f), Some(o)) => {
            let (fs, os) = (fricosc::input::parse_shape(f)?, fricosc::input::parse_shape(o)?);
            if fs.name() != os.name() {
                return Err(Error::Parse {
                    context: source,
                    reason: format!("the table is for shape '{f}', --shape says '{o}'"),
                });
            }
            (fs, ShapeSource::File)
        }
        (Some(f), None) => (fricosc::input::parse_shape(f)?, ShapeSource::File),
        (None, Some(o)) => (fricosc::input::parse_shape(o)?, ShapeSource::Option),
        (None, None) => (fricosc::shape::Shape::Flat, ShapeSource::Default),
    };
    let rows = fricosc::validate::normalise(&table, mu0, &source)?;
    let v = fricosc::validate::compare(&shape, &rows, at_rest, tolerance)?;
    let report = Report { validation: &v, shape_source, ignored_columns: &table.ignored_columns };
    let body = match format.as_str() {
        "json" => super::to_json(&report)? + "\n",
        "csv" => fricosc::validate::rows_csv(&v)?,
        _ => fricosc::validate::summary(&v, &report_source(&report), &table.ignored_columns),
    };
    let mut out = io::BufWriter::new(io::stdout().lock());
    out.write_all(body.as_bytes()).map_err(io_err)?;
    out.flush().map_err(io_err)?;
    Ok(if max_error.is_none_or(|e| v.max_abs_error <= e) { Outcome::Done } else { Outcome::Negative })
}

fn report_source(r: &Report) -> String {
    match r.shape_source {
        ShapeSource::File => "named by the table".into(),
        ShapeSource::Option => "from --shape".into(),
        ShapeSource::Default => "the default: the table names none and --shape is not given".into(),
    }
}
