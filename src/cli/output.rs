//! Output formats at the edge: numbers print with round-trip precision.

use std::io::{self, Write};

/// Shortest text that reads back to the same `f64` (`1e-300`, `0.1`, `1.0`),
/// by `ryu` (the formatter `serde_json` uses too, so JSON and CSV agree).
/// Non-finite values (never produced by the solvers) print as `null`.
pub fn num(x: f64) -> String {
    let mut b = ryu::Buffer::new();
    if x.is_finite() {
        b.format_finite(x).to_string()
    } else {
        "null".into()
    }
}

/// One CSV field as the `csv` crate writes it (quoted only when needed), so that
/// a shape like `gx:a,b.csv@1` reads back as one field.
pub fn csv_field(s: &str) -> String {
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(vec![]);
    // Writing to a Vec cannot fail; an empty field is written as `""`.
    let _ = w.write_record([s]);
    let bytes = w.into_inner().unwrap_or_default();
    String::from_utf8_lossy(&bytes).trim_end_matches('\n').to_string()
}

/// A whole CSV document (header and rows) by the `csv` crate.
pub fn csv_table<I, R>(header: &[&str], rows: I) -> String
where
    I: IntoIterator<Item = R>,
    R: IntoIterator<Item = String>,
{
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(vec![]);
    let _ = w.write_record(header);
    for r in rows {
        let _ = w.write_record(r.into_iter().collect::<Vec<String>>());
    }
    String::from_utf8_lossy(&w.into_inner().unwrap_or_default()).into_owned()
}

fn write_num(out: &mut impl Write, x: f64) -> io::Result<()> {
    let mut b = ryu::Buffer::new();
    out.write_all(if x.is_finite() { b.format_finite(x) } else { "null" }.as_bytes())
}

/// Output format of tabular commands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// One JSON document.
    Json,
    /// CSV with a header row.
    Csv,
}

/// A row-streaming table writer: JSON `{"shape":..,"rows":[{..},..]}` or CSV.
pub struct TableWriter<W: Write> {
    out: W,
    format: Format,
    columns: Vec<&'static str>,
    rows: usize,
    /// The shape as a CSV field (quoted when it holds a comma or a quote).
    csv_shape: String,
}

impl<W: Write> TableWriter<W> {
    /// Start a table with a `shape` label and named numeric columns.
    pub fn new(mut out: W, format: Format, shape: &str, columns: Vec<&'static str>) -> io::Result<Self> {
        match format {
            Format::Json => write!(out, "{{\"shape\":{},\"rows\":[", serde_json::to_string(shape)?)?,
            Format::Csv => writeln!(out, "shape,{}", columns.join(","))?,
        }
        Ok(TableWriter { out, format, columns, rows: 0, csv_shape: csv_field(shape) })
    }

    /// One row (values in column order); the shape is the one given to [`TableWriter::new`].
    pub fn row(&mut self, values: &[f64]) -> io::Result<()> {
        match self.format {
            Format::Json => {
                if self.rows > 0 {
                    self.out.write_all(b",")?;
                }
                self.out.write_all(b"\n{")?;
                for (i, (c, v)) in self.columns.iter().zip(values).enumerate() {
                    if i > 0 {
                        self.out.write_all(b",")?;
                    }
                    write!(self.out, "\"{c}\":")?;
                    write_num(&mut self.out, *v)?;
                }
                self.out.write_all(b"}")?;
            }
            Format::Csv => {
                self.out.write_all(self.csv_shape.as_bytes())?;
                for v in values {
                    self.out.write_all(b",")?;
                    write_num(&mut self.out, *v)?;
                }
                self.out.write_all(b"\n")?;
            }
        }
        self.rows += 1;
        Ok(())
    }

    /// Close the document.
    pub fn finish(mut self) -> io::Result<()> {
        if self.format == Format::Json {
            self.out.write_all(b"\n]}\n")?;
        }
        self.out.flush()
    }
}
