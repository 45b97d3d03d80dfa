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

/// Numbers printed recently, by their bits: a table's grid values repeat row
/// after row (the amplitude on every row of its block, each velocity once per
/// amplitude), and `ryu` costs ~300 instructions a number, a copy ~10. A
/// direct-mapped cache of [`MEMO_SLOTS`] texts; a collision only reformats.
struct Memo {
    slots: Vec<(u64, u8, [u8; 24])>,
}

/// Slots of [`Memo`] (a power of two).
const MEMO_SLOTS: usize = 256;

impl Memo {
    fn new() -> Self {
        Memo { slots: vec![(0, 0, [0; 24]); MEMO_SLOTS] }
    }

    /// `x` as [`num`] prints it, through the cache.
    fn write(&mut self, out: &mut impl Write, x: f64) -> io::Result<()> {
        if !x.is_finite() {
            return out.write_all(b"null");
        }
        let bits = x.to_bits();
        let slot = &mut self.slots[(bits.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 56) as usize % MEMO_SLOTS];
        if slot.1 == 0 || slot.0 != bits {
            let mut b = ryu::Buffer::new();
            let text = b.format_finite(x).as_bytes();
            // ryu's longest text is 24 bytes; anything else is written as is.
            let Some(dst) = slot.2.get_mut(..text.len()) else { return out.write_all(text) };
            dst.copy_from_slice(text);
            *slot = (bits, text.len() as u8, slot.2);
        }
        out.write_all(&slot.2[..slot.1 as usize])
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

/// A row-streaming table writer: JSON `{"shape":..,"rows":[{..},..]}` or CSV.
pub struct TableWriter<W: Write> {
    out: W,
    format: Format,
    columns: Vec<&'static str>,
    rows: usize,
    /// The shape as a CSV field (quoted when it holds a comma or a quote).
    csv_shape: String,
    memo: Memo,
}

impl<W: Write> TableWriter<W> {
    /// Start a table with a `shape` label and named numeric columns.
    pub fn new(mut out: W, format: Format, shape: &str, columns: Vec<&'static str>) -> io::Result<Self> {
        match format {
            Format::Json => write!(out, "{{\"shape\":{},\"rows\":[", serde_json::to_string(shape)?)?,
            Format::Csv => writeln!(out, "shape,{}", columns.join(","))?,
        }
        Ok(TableWriter { out, format, columns, rows: 0, csv_shape: csv_field(shape), memo: Memo::new() })
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
                    self.out.write_all(b"\"")?;
                    self.out.write_all(c.as_bytes())?;
                    self.out.write_all(b"\":")?;
                    self.memo.write(&mut self.out, *v)?;
                }
                self.out.write_all(b"}")?;
            }
            Format::Csv => {
                self.out.write_all(self.csv_shape.as_bytes())?;
                for v in values {
                    self.out.write_all(b",")?;
                    self.memo.write(&mut self.out, *v)?;
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
