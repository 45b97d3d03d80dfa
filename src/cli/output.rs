//! Output formats at the edge: numbers print with round-trip precision.

use std::io::{self, Write};

/// Shortest text that reads back to the same `f64` (`1e-300`, `0.1`, `1.0`,
/// `1e+20`), by `zmij` (the formatter `serde_json` uses too, so `point`'s JSON,
/// tables and batches print one value alike). A value that is not there (not
/// finite: a period where none was found) prints as `null`.
pub fn num(x: f64) -> String {
    let mut text = Vec::with_capacity(24);
    push_num(&mut text, &mut zmij::Buffer::new(), x, b"null");
    // zmij writes ASCII only.
    String::from_utf8_lossy(&text).into_owned()
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

/// A whole CSV document by the `csv` crate, a line per record (writing to
/// memory cannot fail).
pub fn csv_records<I, R, T>(records: I) -> String
where
    I: IntoIterator<Item = R>,
    R: IntoIterator<Item = T>,
    T: AsRef<[u8]>,
{
    csv_table(&[], records)
}

/// A whole CSV document: `header` (none if empty), then `rows`.
pub fn csv_table<I, R, T>(header: &[&str], rows: I) -> String
where
    I: IntoIterator<Item = R>,
    R: IntoIterator<Item = T>,
    T: AsRef<[u8]>,
{
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(vec![]);
    if !header.is_empty() {
        let _ = w.write_record(header);
    }
    for r in rows {
        let _ = w.write_record(r);
    }
    String::from_utf8_lossy(&w.into_inner().unwrap_or_default()).into_owned()
}

/// Append the shortest text of `x` to `line` (`missing` where not finite:
/// `null` in JSON, an empty CSV field): the one place a number's text is
/// made ([`num`] and table rows use it).
fn push_num(line: &mut Vec<u8>, fmt: &mut zmij::Buffer, x: f64, missing: &[u8]) {
    if x.is_finite() {
        line.extend_from_slice(fmt.format_finite(x).as_bytes());
    } else {
        line.extend_from_slice(missing);
    }
}

/// Append `x`, a whole number (a count, a period), without a fraction.
fn push_int(line: &mut Vec<u8>, fmt: &mut zmij::Buffer, x: f64, missing: &[u8]) {
    match x.is_finite() && x.fract() == 0.0 && x.abs() < 9e15 {
        true => line.extend_from_slice((x as i64).to_string().as_bytes()),
        false => push_num(line, fmt, x, missing),
    }
}

/// Output format of tabular commands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// One JSON document.
    Json,
    /// CSV with a header row.
    Csv,
}

/// Bytes of rows a [`TableWriter`] collects before it writes them.
const BLOCK: usize = 1 << 15;

/// A row-streaming table writer: JSON `{"shape":..,"rows":[{..},..]}` or CSV.
pub struct TableWriter<W: Write> {
    out: W,
    format: Format,
    columns: Vec<&'static str>,
    /// Which columns hold whole numbers ([`TableWriter::with_integers`]).
    integers: Vec<bool>,
    rows: usize,
    /// The shape as a CSV field (quoted when it holds a comma or a quote).
    csv_shape: String,
    fmt: zmij::Buffer,
    /// Rows not yet written: written in blocks of about [`BLOCK`] bytes (one
    /// write for hundreds of rows, large enough to bypass a `BufWriter`'s copy).
    line: Vec<u8>,
}

impl<W: Write> TableWriter<W> {
    /// Start a table with a `shape` label and named numeric columns.
    pub fn new(mut out: W, format: Format, shape: &str, columns: Vec<&'static str>) -> io::Result<Self> {
        match format {
            Format::Json => write!(out, "{{\"shape\":{},\"rows\":[", serde_json::to_string(shape)?)?,
            Format::Csv => writeln!(out, "shape,{}", columns.join(","))?,
        }
        Ok(TableWriter {
            out,
            format,
            integers: vec![false; columns.len()],
            columns,
            rows: 0,
            csv_shape: csv_field(shape),
            fmt: zmij::Buffer::new(),
            line: Vec::with_capacity(BLOCK + 1024),
        })
    }

    /// The columns named `names` hold whole numbers: printed `1`, not `1.0`.
    #[must_use]
    pub fn with_integers(mut self, names: &[&str]) -> Self {
        self.integers = self.columns.iter().map(|c| names.contains(c)).collect();
        self
    }

    /// One row (values in column order, each printed as [`num`] prints it, a
    /// whole-number column without a fraction; a value not there is `null` in
    /// JSON and an empty CSV field); the shape is the one given to
    /// [`TableWriter::new`].
    pub fn row(&mut self, cells: &[f64]) -> io::Result<()> {
        debug_assert_eq!(cells.len(), self.columns.len());
        let (line, fmt) = (&mut self.line, &mut self.fmt);
        let missing: &[u8] = if self.format == Format::Csv { b"" } else { b"null" };
        let cell = |line: &mut Vec<u8>, fmt: &mut zmij::Buffer, i: usize, x: f64| match self.integers[i] {
            true => push_int(line, fmt, x, missing),
            false => push_num(line, fmt, x, missing),
        };
        match self.format {
            Format::Csv => {
                line.extend_from_slice(self.csv_shape.as_bytes());
                for (i, x) in cells.iter().enumerate() {
                    line.push(b',');
                    cell(line, fmt, i, *x);
                }
                line.push(b'\n');
            }
            Format::Json => {
                line.extend_from_slice(if self.rows > 0 { b",\n{" } else { b"\n{" });
                for (i, (c, x)) in self.columns.iter().zip(cells).enumerate() {
                    line.extend_from_slice(if i > 0 { b",\"" } else { b"\"" });
                    line.extend_from_slice(c.as_bytes());
                    line.extend_from_slice(b"\":");
                    cell(line, fmt, i, *x);
                }
                line.push(b'}');
            }
        }
        self.rows += 1;
        if line.len() >= BLOCK {
            self.out.write_all(line)?;
            line.clear();
        }
        Ok(())
    }

    /// Close the document.
    pub fn finish(mut self) -> io::Result<()> {
        self.out.write_all(&self.line)?;
        if self.format == Format::Json {
            self.out.write_all(b"\n]}\n")?;
        }
        self.out.flush()
    }
}

/// A CSV writer's error as the I/O error it wraps, with its kind (a closed
/// pipe stays a closed pipe, which ends the program quietly).
pub fn io_of(e: csv::Error) -> io::Error {
    match e.into_kind() {
        csv::ErrorKind::Io(e) => e,
        other => io::Error::other(format!("{other:?}")),
    }
}
