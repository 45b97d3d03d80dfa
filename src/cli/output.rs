//! Output formats at the edge: numbers print with round-trip precision.

use std::io::{self, Write};

/// Shortest text that reads back to the same `f64` (`1e-300`, `0.1`, `1.0`,
/// `1e+20`), by `zmij` (the formatter `serde_json` uses too, so `point`'s JSON,
/// tables and batches print one value alike). Non-finite values (never produced
/// by the solvers) print as `null`.
pub fn num(x: f64) -> String {
    let mut text = Vec::with_capacity(MEMO_TEXT);
    push_num(&mut text, &mut zmij::Buffer::new(), x);
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

/// Append the shortest text of `x` to `line` (`null` where not finite): the one
/// place a number's text is made ([`num`], [`Memo`] and table rows use it).
fn push_num(line: &mut Vec<u8>, fmt: &mut zmij::Buffer, x: f64) {
    if x.is_finite() {
        line.extend_from_slice(fmt.format_finite(x).as_bytes());
    } else {
        line.extend_from_slice(b"null");
    }
}

/// Numbers printed recently, by their bits: a table's grid values repeat row
/// after row (the amplitude on every row of its block, each velocity once per
/// amplitude), and formatting costs ~150 instructions a number, a copy ~10. A
/// direct-mapped cache of [`MEMO_SLOTS`] texts; a collision only reformats.
struct Memo {
    slots: Vec<(u64, u8, [u8; MEMO_TEXT])>,
}

/// Slots of [`Memo`] (a power of two).
const MEMO_SLOTS: usize = 256;
/// Bytes of a slot's text: the longest shortest text of an `f64` is 24 bytes
/// (`-2.2250738585072014e-308`).
const MEMO_TEXT: usize = 24;

impl Memo {
    fn new() -> Self {
        Memo { slots: vec![(0, 0, [0; MEMO_TEXT]); MEMO_SLOTS] }
    }

    /// Append `x` as [`num`] prints it to `line`, through the cache.
    fn push(&mut self, line: &mut Vec<u8>, fmt: &mut zmij::Buffer, x: f64) {
        let bits = x.to_bits();
        let slot = &mut self.slots[(bits.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 56) as usize % MEMO_SLOTS];
        let at = line.len();
        if slot.1 != 0 && slot.0 == bits {
            // A copy of the whole slot (a fixed size: no call), then cut to the text.
            line.extend_from_slice(&slot.2);
            line.truncate(at + slot.1 as usize);
            return;
        }
        push_num(line, fmt, x);
        let text = &line[at..];
        // Anything longer than a slot (never, see MEMO_TEXT) is not cached.
        if let Some(dst) = slot.2.get_mut(..text.len()) {
            dst.copy_from_slice(text);
            (slot.0, slot.1) = (bits, text.len() as u8);
        }
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
    /// The leading columns that repeat from row to row (the grid), printed through [`Memo`].
    grid: usize,
    rows: usize,
    /// The shape as a CSV field (quoted when it holds a comma or a quote).
    csv_shape: String,
    memo: Memo,
    fmt: zmij::Buffer,
    /// Rows not yet written: written in blocks of about [`BLOCK`] bytes (one
    /// write for hundreds of rows, large enough to bypass a `BufWriter`'s copy).
    line: Vec<u8>,
}

impl<W: Write> TableWriter<W> {
    /// Start a table with a `shape` label and named numeric columns, of which
    /// the first `grid` are the grid's (their values repeat, and are cached).
    pub fn new(mut out: W, format: Format, shape: &str, columns: Vec<&'static str>, grid: usize) -> io::Result<Self> {
        match format {
            Format::Json => write!(out, "{{\"shape\":{},\"rows\":[", serde_json::to_string(shape)?)?,
            Format::Csv => writeln!(out, "shape,{}", columns.join(","))?,
        }
        Ok(TableWriter {
            out,
            format,
            columns,
            grid,
            rows: 0,
            csv_shape: csv_field(shape),
            memo: Memo::new(),
            fmt: zmij::Buffer::new(),
            line: Vec::with_capacity(BLOCK + 1024),
        })
    }

    /// One row (values in column order); the shape is the one given to [`TableWriter::new`].
    pub fn row(&mut self, values: &[f64]) -> io::Result<()> {
        let line = &mut self.line;
        let json = self.format == Format::Json;
        if json {
            line.extend_from_slice(if self.rows > 0 { b",\n{" } else { b"\n{" });
        } else {
            line.extend_from_slice(self.csv_shape.as_bytes());
        }
        for (i, (c, &v)) in self.columns.iter().zip(values).enumerate() {
            if json {
                line.extend_from_slice(if i > 0 { b",\"" } else { b"\"" });
                line.extend_from_slice(c.as_bytes());
                line.extend_from_slice(b"\":");
            } else {
                line.push(b',');
            }
            if i < self.grid {
                self.memo.push(line, &mut self.fmt, v);
            } else {
                push_num(line, &mut self.fmt, v);
            }
        }
        line.extend_from_slice(if json { b"}" } else { b"\n" });
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
