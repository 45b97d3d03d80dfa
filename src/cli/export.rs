//! One exporter for every report: a report names its columns and rows (CSV and
//! Markdown are drawn from them), serialises itself (JSON) and may draw itself
//! (SVG, and PNG from it). Output formats are a choice at the edge, never part of a computation.
//! (`table` streams its rows through [`crate::output::TableWriter`] instead: it
//! may hold 10^7 of them.)

use crate::error::{Error, Result};

/// Something a command prints or writes.
pub trait Report: serde::Serialize {
    /// Column names of the tabular form.
    fn columns(&self) -> Vec<String>;
    /// Rows of the tabular form, as text (numbers in round-trip precision).
    fn rows(&self) -> Vec<Vec<String>>;
    /// A line above the CSV table (written as a `#` comment: numpy reads past
    /// it, pandas with `comment="#"`, `fricosc validate` always), e.g. units.
    fn comment(&self) -> Option<String> {
        None
    }
    /// The report drawn as SVG, where it has a drawing.
    fn svg(&self) -> Option<Result<String>> {
        None
    }
}

/// An output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Pretty-printed JSON.
    Json,
    /// CSV with a header row (the `csv` crate).
    Csv,
    /// A Markdown table.
    Markdown,
    /// An SVG drawing.
    Svg,
    /// The SVG drawing rendered as PNG ([`crate::chart::png`]; bytes: see [`export_bytes`]).
    Png,
}

impl Format {
    /// Parse `text` as one of `allowed` (the names `json`, `csv`, `markdown`, `svg`).
    pub fn parse(text: &str, allowed: &[Format]) -> Result<Format> {
        let f = match text {
            "json" => Some(Format::Json),
            "csv" => Some(Format::Csv),
            "markdown" => Some(Format::Markdown),
            "svg" => Some(Format::Svg),
            "png" => Some(Format::Png),
            _ => None,
        };
        match f {
            Some(f) if allowed.contains(&f) => Ok(f),
            _ => Err(Error::Parse {
                context: "--format".into(),
                reason: format!(
                    "'{text}' is not one of {}",
                    allowed.iter().map(|f| f.name()).collect::<Vec<_>>().join(", ")
                ),
            }),
        }
    }

    /// The format's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Format::Json => "json",
            Format::Csv => "csv",
            Format::Markdown => "markdown",
            Format::Svg => "svg",
            Format::Png => "png",
        }
    }
}

/// The report in `format` (CSV and Markdown end with a newline, JSON and SVG do not).
pub fn export(report: &impl Report, format: Format) -> Result<String> {
    match format {
        Format::Json => serde_json::to_string_pretty(report)
            .map_err(|e| Error::Internal { what: format!("serialising the output: {e}") }),
        Format::Csv => {
            let table = crate::output::csv_table(
                &report.columns().iter().map(String::as_str).collect::<Vec<_>>(),
                report.rows(),
            );
            Ok(match report.comment() {
                Some(c) => format!("# {}\n{table}", crate::cmd::escape_controls(&c)),
                None => table,
            })
        }
        Format::Markdown => {
            let cell = |s: &str| s.replace('|', "/");
            let cols = report.columns();
            let mut s = format!("| {} |\n|{}\n", cols.join(" | "), "---|".repeat(cols.len()));
            for r in report.rows() {
                s += &format!("| {} |\n", r.iter().map(|c| cell(c)).collect::<Vec<_>>().join(" | "));
            }
            Ok(s)
        }
        Format::Svg => match report.svg() {
            Some(svg) => svg,
            None => Err(Error::Parse { context: "--format".into(), reason: "this report has no drawing".into() }),
        },
        Format::Png => Err(Error::Internal { what: "a PNG is bytes: export_bytes writes it".into() }),
    }
}

/// The report in `format` as bytes: [`export`]'s text, or for [`Format::Png`]
/// the SVG drawing rendered.
pub fn export_bytes(report: &impl Report, format: Format) -> Result<Vec<u8>> {
    match format {
        Format::Png => crate::chart::png(&export(report, Format::Svg)?)
            .map_err(|e| Error::Internal { what: format!("rendering the PNG: {e}") }),
        f => export(report, f).map(String::into_bytes),
    }
}
