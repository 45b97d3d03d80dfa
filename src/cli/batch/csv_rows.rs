//! `batch` in CSV: records read and checked one at a time, evaluated in
//! parallel chunks; every column kept, `mu_ratio,reduction` appended or filled.

use super::{changed, inputs, too_many, Job, Shapes, CHUNK, MAX_LINE, MAX_STREAM_ROWS};
use crate::error::{Error, Result};
use fricosc::stepper::Stepping;
use fricosc::Ratio;
use std::io::{self, BufRead, Write};

/// CSV: records read and checked one at a time, evaluated in parallel chunks.
pub(super) fn stream_csv(
    open: &dyn Fn() -> Result<Box<dyn BufRead>>,
    source: &str,
    stepping: Option<Stepping>,
    out: &mut dyn Write,
) -> Result<u64> {
    let mut shapes = Shapes::new(stepping);
    let werr = |e: io::Error| Error::write("stdout", e);
    // Pass 1: check every row. The first chunk's rows are kept as they are
    // checked: a batch of at most one chunk is read once, computed and written.
    let mut rows = Csv::new(open()?, source)?;
    let (mut jobs, mut lines) = (Vec::new(), Vec::new());
    let mut n = 0u64;
    loop {
        if n > 0 && n.is_multiple_of(CHUNK as u64) {
            shapes.new_chunk();
        }
        let keep = n < CHUNK as u64;
        let Some((line, job)) = rows.next(&mut shapes, keep)? else { break };
        if keep {
            jobs.push(job);
            lines.push(line);
        }
        n += 1;
        if n > MAX_STREAM_ROWS {
            return Err(too_many(source, n));
        }
    }
    if n <= CHUNK as u64 {
        let results = shapes.evaluate_all(&jobs, source, &|i| format!("line {}", lines[i]))?;
        rows.header(out).map_err(werr)?;
        rows.write_kept(out, &results).map_err(werr)?;
        out.flush().map_err(werr)?;
        return Ok(n);
    }
    // Pass 2 (more than a chunk): compute chunks in parallel, write them in order.
    let mut rows = Csv::new(open()?, source)?;
    rows.header(out).map_err(werr)?;
    let mut again = 0u64;
    loop {
        shapes.new_chunk();
        jobs.clear();
        lines.clear();
        while jobs.len() < CHUNK {
            let Some((line, job)) = rows.next(&mut shapes, true)? else { break };
            jobs.push(job);
            lines.push(line);
        }
        if jobs.is_empty() {
            break;
        }
        again += jobs.len() as u64;
        if again > n {
            return Err(changed(source, n, again));
        }
        let results = shapes.evaluate_all(&jobs, source, &|i| format!("line {}", lines[i]))?;
        rows.write_kept(out, &results).map_err(werr)?;
    }
    if again != n {
        return Err(changed(source, n, again));
    }
    out.flush().map_err(werr)?;
    Ok(n)
}

/// A CSV writer's error as the I/O error it wraps, with its kind (a closed
/// pipe stays a closed pipe, which ends the program quietly).
pub fn io_of(e: csv::Error) -> io::Error {
    match e.into_kind() {
        csv::ErrorKind::Io(e) => e,
        other => io::Error::other(format!("{other:?}")),
    }
}

/// CSV rows.
struct Csv {
    reader: csv::Reader<Box<dyn BufRead>>,
    source: String,
    /// Columns of shape and amp; of vbar, vhat, tangential_amp and phase where present.
    cols: [usize; 2],
    optional: [(&'static str, Option<usize>); 4],
    results: Option<(usize, usize)>,
    header: csv::ByteRecord,
    record: csv::ByteRecord,
    /// Records kept for [`Csv::write_kept`], their fields one after another
    /// (no allocation a record; the buffers are reused chunk after chunk), and
    /// where each field ends in `kept` (every record has the header's fields).
    kept: Vec<u8>,
    ends: Vec<usize>,
    /// The output rows of a chunk, written at once.
    line: Vec<u8>,
}

impl Csv {
    fn new(input: Box<dyn BufRead>, source: &str) -> Result<Csv> {
        let bad = |reason: String| Error::Parse { context: source.into(), reason };
        let mut reader = csv::ReaderBuilder::new().has_headers(true).from_reader(input);
        let header = reader.byte_headers().map_err(|e| bad(format!("header: {e}")))?.clone();
        let find = |name: &str| header.iter().position(|h| h.trim_ascii() == name.as_bytes());
        let col = |name: &str| find(name).ok_or_else(|| bad(format!("the header has no column '{name}'")));
        for (i, h) in header.iter().enumerate() {
            if header.iter().take(i).any(|g| g == h) {
                return Err(bad(format!("the header repeats the column '{}'", String::from_utf8_lossy(h))));
            }
        }
        let cols = [col("shape")?, col("amp")?];
        let optional = ["vbar", "vhat", "tangential_amp", "phase"].map(|n| (n, find(n)));
        if optional[0].1.is_none() && optional[1].1.is_none() {
            return Err(bad("the header has no column 'vbar' (or 'vhat')".into()));
        }
        let results = match (find("mu_ratio"), find("reduction")) {
            (Some(m), Some(r)) => Some((m, r)),
            (None, None) => None,
            _ => return Err(bad("the header has only one of 'mu_ratio', 'reduction'".into())),
        };
        let record = csv::ByteRecord::new();
        let (kept, ends, line) = (vec![], vec![], vec![]);
        Ok(Csv { reader, source: source.into(), cols, optional, results, header, record, kept, ends, line })
    }
}

impl Csv {
    /// Write the output's header: the input's, with the result columns appended where it has none.
    fn header(&mut self, out: &mut dyn Write) -> io::Result<()> {
        let mut h = self.header.clone();
        if self.results.is_none() {
            h.push_field(b"mu_ratio");
            h.push_field(b"reduction");
        }
        let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(&mut *out);
        w.write_byte_record(&h).map_err(io_of)?;
        w.flush()
    }

    /// The next record's line number and job; `None` at the end. With `keep`,
    /// the record is kept to be written by [`Csv::write_kept`].
    fn next(&mut self, shapes: &mut Shapes, keep: bool) -> Result<Option<(u64, Job)>> {
        let more = self.reader.read_byte_record(&mut self.record).map_err(|e| {
            let reason = match e.kind() {
                csv::ErrorKind::UnequalLengths { pos, expected_len, len } => format!(
                    "line {}: {len} fields where the header has {expected_len}",
                    pos.as_ref().map_or(self.reader.position().line(), |p| p.line())
                ),
                _ => format!("line {}: {e}", self.reader.position().line()),
            };
            Error::Parse { context: self.source.clone(), reason }
        })?;
        if !more {
            return Ok(None);
        }
        let line = self.record.position().map_or(0, |p| p.line());
        let bad =
            |reason: String| Error::Parse { context: self.source.clone(), reason: format!("line {line}: {reason}") };
        if self.record.as_slice().len() > MAX_LINE {
            return Err(bad(format!("a record of more than {MAX_LINE} bytes")));
        }
        let text = |col: usize, name: &str| {
            std::str::from_utf8(&self.record[col]).map_err(|_| format!("'{name}' is not UTF-8"))
        };
        // A column's number; an empty cell of an optional column is absent.
        let get = |name: &'static str| -> std::result::Result<Option<f64>, String> {
            let col = if name == "amp" {
                Some(self.cols[1])
            } else {
                self.optional.iter().find(|(n, _)| *n == name).and_then(|(_, c)| *c)
            };
            let Some(col) = col else { return Ok(None) };
            let t = text(col, name)?.trim();
            if t.is_empty() && name != "amp" {
                return Ok(None);
            }
            match crate::float::f64_of(t) {
                Ok(x) if x.is_finite() => Ok(Some(x + 0.0)),
                _ => Err(format!("'{name}' is not a finite number: '{t}'")),
            }
        };
        let spec = text(self.cols[0], "shape").map_err(bad)?.trim();
        let k = shapes.id(spec).map_err(|e| bad(e.to_string()))?;
        // The seed's columns (vbar and amp only, both plain numbers): straight
        // to the check; anything else (an error included) through `inputs`.
        // (A cell the fast path does not read gives None: `inputs` then reads it, or words why not.)
        let plain = |col: usize| text(col, "").ok().and_then(|t| crate::float::parse(t.trim()));
        let job = match self.optional {
            [(_, Some(v)), (_, None), (_, None), (_, None)] => match (plain(v), plain(self.cols[1])) {
                (Some(vbar), Some(amp)) => {
                    shapes.check(k, vbar + 0.0, amp + 0.0, self.results.is_some()).map_err(|e| bad(e.to_string()))?
                }
                _ => inputs(shapes, k, &get, self.results.is_some()).map_err(bad)?,
            },
            _ => inputs(shapes, k, &get, self.results.is_some()).map_err(bad)?,
        };
        if keep {
            for f in &self.record {
                self.kept.extend_from_slice(f);
                self.ends.push(self.kept.len());
            }
        }
        Ok(Some((line, job)))
    }

    /// Write the kept records with their results (in order), and forget them.
    /// Each field is written as the `csv` crate writes it (see [`push_field`]).
    fn write_kept(&mut self, out: &mut dyn Write, results: &[Ratio]) -> io::Result<()> {
        let mut buf = zmij::Buffer::new();
        let line = &mut self.line;
        line.clear();
        let mut start = 0;
        for (row, r) in self.ends.chunks(self.header.len().max(1)).zip(results) {
            for (i, &end) in row.iter().enumerate() {
                let f = &self.kept[start..end];
                start = end;
                if i > 0 {
                    line.push(b',');
                }
                match self.results {
                    Some((m, _)) if i == m => line.extend_from_slice(buf.format_finite(r.mu_ratio).as_bytes()),
                    Some((_, d)) if i == d => line.extend_from_slice(buf.format_finite(r.reduction).as_bytes()),
                    _ => push_field(line, f),
                }
            }
            if self.results.is_none() {
                line.push(b',');
                line.extend_from_slice(buf.format_finite(r.mu_ratio).as_bytes());
                line.push(b',');
                line.extend_from_slice(buf.format_finite(r.reduction).as_bytes());
            }
            line.push(b'\n');
        }
        self.kept.clear();
        self.ends.clear();
        out.write_all(line)
    }
}

/// Append one field of a record of several fields as the `csv` crate's
/// writer does (`QuoteStyle::Necessary`, `,` and `\n`): quoted when it holds
/// a comma, a quote, `\r` or `\n`, a quote inside doubled; an empty field as
/// nothing. Tested against the crate's writer.
fn push_field(line: &mut Vec<u8>, f: &[u8]) {
    if !f.iter().any(|&b| matches!(b, b',' | b'"' | b'\r' | b'\n')) {
        line.extend_from_slice(f);
        return;
    }
    line.push(b'"');
    for &b in f {
        if b == b'"' {
            line.push(b'"');
        }
        line.push(b);
    }
    line.push(b'"');
}

#[cfg(test)]
mod tests {
    use super::push_field;

    /// Records written field by field as the `csv` crate writes them.
    #[test]
    fn fields_are_written_as_the_csv_crate_writes_them() {
        let fields: [&[u8]; 12] =
            [b"", b"a", b"1e-5", b"a,b", b"\"", b"say \"hi\"", b"x\ny", b"x\ry", b" sp ", b"#c", b"\xff\xfe", b"\t"];
        for a in fields {
            for b in fields {
                let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(vec![]);
                w.write_byte_record(&csv::ByteRecord::from(vec![a, b, b"0.5"])).unwrap();
                let want = w.into_inner().unwrap();
                let mut got = vec![];
                push_field(&mut got, a);
                got.push(b',');
                push_field(&mut got, b);
                got.extend_from_slice(b",0.5\n");
                assert_eq!(got, want, "{a:?} {b:?}");
            }
        }
    }
}
