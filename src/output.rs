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
}

impl<W: Write> TableWriter<W> {
    /// Start a table with a `shape` label and named numeric columns.
    pub fn new(mut out: W, format: Format, shape: &str, columns: Vec<&'static str>) -> io::Result<Self> {
        match format {
            Format::Json => write!(out, "{{\"shape\":{},\"rows\":[", serde_json::to_string(shape)?)?,
            Format::Csv => writeln!(out, "shape,{}", columns.join(","))?,
        }
        Ok(TableWriter { out, format, columns, rows: 0 })
    }

    /// One row (values in column order).
    pub fn row(&mut self, shape: &str, values: &[f64]) -> io::Result<()> {
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
                write!(self.out, "{shape}")?;
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
