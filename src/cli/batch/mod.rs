//! `batch`: rows of `{shape, vbar, amp, ...}` in, the same rows with
//! `mu_ratio` and `reduction` added out, as a JSON array, JSON Lines or CSV.
//!
//! Decisions:
//! - One bad row rejects the whole batch (the error names the row, or the line
//!   of JSON Lines and CSV), so a caller never receives a partial output: every
//!   row is checked (its numbers, its shape, that the shape reaches the
//!   amplitude) before the first byte is written. What can still fail after
//!   that is an internal error (exit code 3), never the input.
//! - A JSON array is read whole (at most 10^7 rows) and each row kept as its raw
//!   text, borrowed from the input; only the wanted fields are picked out, by
//!   one strict serial pass that finds and scans the rows at once
//!   ([`crate::scan::ArrayReader`], a chunk of 65,536 rows at a time, each
//!   chunk then checked in parallel). Each row is written back as given
//!   (other fields keep their order and bytes) with
//!   `"mu_ratio":..,"reduction":..` spliced in before its closing brace. A row
//!   that already has `mu_ratio` or `reduction` has them replaced (through a
//!   parsed map, for that row only). Memory: the input text plus 88 bytes per
//!   row (its text's place, its inputs, its results; up to twice that while
//!   the lists grow by doubling) and one chunk's scanned fields and numbers (13 MiB).
//! - JSON Lines and CSV stream in constant memory, in two passes over the
//!   input: the first checks every row, the second computes chunks of rows in
//!   parallel and writes them in order (the caller spools stdin to a temporary
//!   file to read it twice). An input of one chunk is read once: its rows are
//!   kept from the check, then computed and written. JSON Lines are read a
//!   chunk at a time (65,536 lines or 32 MiB; the first two at once while the
//!   first is kept) and scanned, checked and formatted in parallel too. Blank lines of JSON Lines are skipped. CSV keeps
//!   every column's value (fields are re-quoted only where CSV needs it) and
//!   appends `mu_ratio,reduction`, or fills those columns where they exist.
//! - Duplicate keys are refused. Each distinct shape string is parsed once.

use crate::error::{Error, Result};
use crate::scan::{self, string_of, RowsError};
use fricosc::error::check_nonneg;
use fricosc::stepper::Stepping;
use fricosc::Ratio;
use fricosc::Shape;
use rayon::prelude::*;
use std::collections::HashMap;
use std::io::{self, BufRead, Write};

mod csv_rows;
pub use csv_rows::io_of;
use csv_rows::stream_csv;

/// Most rows one JSON array may hold.
pub const MAX_ROWS: usize = crate::grid::MAX_ROWS;
/// Most rows of a streamed batch (JSON Lines, CSV).
pub const MAX_STREAM_ROWS: u64 = 1_000_000_000;
/// Longest line of JSON Lines or CSV, in bytes.
pub const MAX_LINE: usize = 1 << 20;
/// Rows computed at once when streaming.
const CHUNK: usize = 1 << 16;

/// The fields a row is read for.
const NAMES: [&str; FIELDS] = ["shape", "vbar", "amp", "mu_ratio", "reduction", "vhat", "tangential_amp", "phase"];

/// [`NAMES`] for the scanner.
const KEYS: scan::Keys<'static, FIELDS> = scan::Keys::new(&NAMES);

/// How many fields a row is read for.
const FIELDS: usize = 8;

/// The input (and output) format of a batch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// One JSON array of objects.
    Json,
    /// One JSON object per line.
    JsonLines,
    /// CSV with a header naming `shape`, `vbar`, `amp`.
    Csv,
}

impl Format {
    /// The format named `name` (`json`, `jsonl`, `csv`), or else the one the
    /// file's extension says (`.jsonl`/`.ndjson`, `.csv`; JSON otherwise).
    pub fn choose(name: Option<&str>, path: &str) -> Result<Format> {
        match name {
            Some("json") => Ok(Format::Json),
            Some("jsonl") => Ok(Format::JsonLines),
            Some("csv") => Ok(Format::Csv),
            Some(other) => Err(Error::Parse {
                context: "--format".into(),
                reason: format!("'{other}' is not one of json, jsonl, csv"),
            }),
            None => {
                let p = path.to_ascii_lowercase();
                Ok(if p.ends_with(".jsonl") || p.ends_with(".ndjson") {
                    Format::JsonLines
                } else if p.ends_with(".csv") {
                    Format::Csv
                } else {
                    Format::Json
                })
            }
        }
    }
}

/// One checked row: its shape (an index into [`Shapes`]), inputs, and whether
/// it already carried results to replace.
#[derive(Debug, Clone, Copy)]
struct Job {
    shape: u32,
    replace: bool,
    vbar: f64,
    amp: f64,
    /// Oscillation in the sliding direction: `(vhat, T, phase)`.
    tangential: Option<(f64, f64, f64)>,
}

/// A row's inputs, by name (`None` where absent), into a checked job: the
/// velocity as `vbar` or `vhat` (one of them; `vbar = vhat/amp`), and with
/// `tangential_amp` (which needs `vhat`) an optional `phase`.
fn inputs(
    shapes: &Shapes,
    shape: u32,
    get: &dyn Fn(&'static str) -> std::result::Result<Option<f64>, String>,
    replace: bool,
) -> std::result::Result<Job, String> {
    let amp = get("amp")?.ok_or("missing field 'amp'")?;
    let (vbar, vhat) = (get("vbar")?, get("vhat")?);
    let (t, phase) = (get("tangential_amp")?, get("phase")?);
    let err = |e: fricosc::Error| e.to_string();
    if phase.is_some() && t.is_none() {
        return Err("'phase' needs 'tangential_amp'".into());
    }
    let vbar = match (vbar, vhat, t) {
        (Some(_), Some(_), _) => return Err("give one of 'vbar' and 'vhat', not both".into()),
        (Some(_), None, Some(_)) => {
            return Err("'tangential_amp' needs the velocity as 'vhat' (vbar = vhat/amp is undefined at amp 0)".into())
        }
        (None, None, _) => return Err("missing field 'vbar' (or 'vhat')".into()),
        (Some(v), None, None) => v,
        (None, Some(h), None) => {
            check_nonneg("vhat", h).map_err(err)?;
            check_nonneg("amp", amp).map_err(err)?;
            fricosc::vbar_from_vhat(h, amp).map_err(err)?
        }
        (None, Some(h), Some(_)) => h,
    };
    let mut job = shapes.check(shape, vbar, amp, replace).map_err(|e| e.to_string())?;
    if let (Some(vhat), Some(t)) = (vhat, t) {
        let phase = phase.unwrap_or(0.0);
        fricosc::combined::Oscillation::new(vhat, amp, t, phase).map_err(err)?;
        job.tangential = Some((vhat, t, phase));
    }
    Ok(job)
}

/// The shapes of a batch, each distinct string parsed (and checked) once.
struct Shapes {
    index: HashMap<String, u32>,
    list: Vec<Shape>,
    stepping: Option<Stepping>,
    /// The last row's shape string and index (most batches use one shape).
    last: Option<(String, u32)>,
}

/// Most distinct shapes a streamed batch keeps parsed between chunks: beyond
/// it the cache is emptied at the next chunk (a chunk's rows refer to shapes
/// by index, so only between chunks), so that memory stays bounded whatever
/// the number of distinct shape strings.
pub const MAX_CACHED_SHAPES: usize = 4096;

impl Shapes {
    fn new(stepping: Option<Stepping>) -> Shapes {
        Shapes { index: HashMap::new(), list: vec![], stepping, last: None }
    }

    /// A new chunk of a streamed batch begins: the rows of the last one are done.
    fn new_chunk(&mut self) {
        if self.list.len() > MAX_CACHED_SHAPES {
            self.index.clear();
            self.list.clear();
            self.last = None;
        }
    }

    /// The index of the shape `spec`, parsed (and checked for the method) the first time.
    fn id(&mut self, spec: &str) -> Result<u32> {
        if let Some((last, k)) = &self.last {
            if last == spec {
                return Ok(*k);
            }
        }
        let k = match self.index.get(spec) {
            Some(&k) => k,
            None => {
                let parsed = crate::input::parse_shape(spec)?;
                if let Some(st) = self.stepping {
                    st.check(&parsed)?;
                }
                self.list.push(parsed);
                let k = (self.list.len() - 1) as u32;
                self.index.insert(spec.to_string(), k);
                k
            }
        };
        self.last = Some((spec.to_string(), k));
        Ok(k)
    }

    /// Check a row's numbers, and that its shape reaches the amplitude.
    fn check(&self, shape: u32, vbar: f64, amp: f64, replace: bool) -> Result<Job> {
        check_nonneg("vbar", vbar)?;
        check_nonneg("amp", amp)?;
        // A tabulated profile must reach the deepest indentation (else the
        // evaluation would refuse the row after output had begun).
        if !self.list[shape as usize].is_flat() {
            self.list[shape as usize].contact().reach(amp)?;
        }
        Ok(Job { shape, replace, vbar, amp, tangential: None })
    }

    fn evaluate(&self, j: &Job) -> fricosc::Result<Ratio> {
        let shape = &self.list[j.shape as usize];
        if let Some((vhat, t, phase)) = j.tangential {
            let o = fricosc::combined::Oscillation { vhat, amp: j.amp, tangential_amp: t, phase };
            return match self.stepping {
                Some(st) => {
                    fricosc::stepper::evaluate_oscillation(shape, &o, st, fricosc::stepper::OSCILLATION_PERIODS)
                        .map(|e| e.ratio)
                }
                None => fricosc::combined::evaluate(shape, &o, fricosc::DEFAULT_TOL).map(|e| e.ratio),
            };
        }
        match self.stepping {
            Some(st) => fricosc::stepper::evaluate(shape, j.vbar, j.amp, st).map(|e| e.ratio),
            // Inputs checked with the row (`Shapes::check`): the contact itself.
            None => shape.contact().ratio(j.vbar, j.amp, fricosc::DEFAULT_TOL),
        }
    }

    /// Evaluate `jobs` in parallel; `name(i)` names the row `i` of them in
    /// errors, and the first row at fault (in order) is the one reported.
    fn evaluate_all(&self, jobs: &[Job], source: &str, name: &(dyn Fn(usize) -> String + Sync)) -> Result<Vec<Ratio>> {
        let mut out = Vec::with_capacity(jobs.len());
        let filler = Ratio { mu_ratio: 0.0, reduction: 0.0 };
        map_into(jobs, filler, &|_, j| self.evaluate(j), &mut out).map_err(|(i, e)| match e {
            fricosc::Error::Internal { what } => Error::Internal { what: format!("{source} {}: {what}", name(i)) },
            e => Error::Parse { context: source.into(), reason: format!("{}: {e}", name(i)) },
        })?;
        Ok(out)
    }
}

/// `f(i, item)` over `items` in parallel, appended to `out` in order, or the
/// first item at fault (in order: its index, and why), with `out` as it was.
/// The results are written in place (rayon's indexed extend): no list of
/// `Result`s in between, no second copy into `out` (the check and the
/// evaluation together: 3,115 -> 3,078 instructions a JSON row, measured). `filler`
/// holds the place of a row at fault until the whole pass is done.
fn map_into<T: Sync, R: Copy + Send + Sync, E: Send>(
    items: &[T],
    filler: R,
    f: &(dyn Fn(usize, &T) -> std::result::Result<R, E> + Sync),
    out: &mut Vec<R>,
) -> std::result::Result<(), (usize, E)> {
    let first: std::sync::Mutex<Option<(usize, E)>> = std::sync::Mutex::new(None);
    let before = out.len();
    out.par_extend(items.par_iter().enumerate().map(|(i, item)| {
        f(i, item).unwrap_or_else(|e| {
            keep_first(&mut first.lock().unwrap_or_else(std::sync::PoisonError::into_inner), i, e);
            filler
        })
    }));
    match first.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner) {
        Some(fault) => {
            out.truncate(before);
            Err(fault)
        }
        None => Ok(()),
    }
}

/// Keep in `slot` the fault of the lowest index: `(i, e)` where it comes
/// before the one there (the threads of a pass meet faults in any order).
fn keep_first<E>(slot: &mut Option<(usize, E)>, i: usize, e: E) {
    if slot.as_ref().is_none_or(|(j, _)| i < *j) {
        *slot = Some((i, e));
    }
}

/// The shape string of one JSON row (its raw fields).
fn json_spec<'a>(f: &[Option<&'a str>; FIELDS]) -> std::result::Result<std::borrow::Cow<'a, str>, String> {
    string_of(f[0].ok_or("missing field 'shape'")?, "shape")
}

/// The inputs of one JSON row whose shape has index `shape`.
fn json_numbers(shapes: &Shapes, shape: u32, r: &scan::Row<FIELDS>) -> std::result::Result<Job, String> {
    let f = &r.fields;
    let replace = f[3].is_some() || f[4].is_some();
    // The seed's row (vbar and amp only): straight to the check.
    if let ([_, Some(v), Some(a), ..], [None, None, None]) = (f, [f[5], f[6], f[7]]) {
        let (vbar, amp) = (r.number_in(1, v, "vbar")?, r.number_in(2, a, "amp")?);
        return shapes.check(shape, vbar, amp, replace).map_err(|e| e.to_string());
    }
    let get = |name: &'static str| -> std::result::Result<Option<f64>, String> {
        // The field's place in NAMES (a match, not a search: once per field of every row).
        let k = match name {
            "vbar" => 1,
            "amp" => 2,
            "vhat" => 5,
            "tangential_amp" => 6,
            _ => 7,
        };
        debug_assert_eq!(NAMES[k], name);
        r.number(k, name)
    };
    inputs(shapes, shape, &get, replace)
}

/// An evaluated JSON array, borrowing its rows from the input text.
pub struct Batch<'a> {
    rows: Vec<&'a str>,
    results: Vec<Ratio>,
    replace: Vec<usize>,
}

/// Most bytes of lines read into one chunk of a streamed batch.
const CHUNK_BYTES: usize = 32 << 20;

/// A row of a chunk as scanned: its fields, or why it is malformed.
type Scanned<'a> = std::result::Result<scan::Row<'a, FIELDS>, String>;

/// Check one chunk of rows, `items`, each scanned (`row(item)`: its fields, or
/// why it is malformed): their shapes looked up serially (each distinct string
/// parsed once), their numbers checked in parallel. Appends the rows' raw text
/// to `raws` and their jobs to `jobs` (nothing where a row is at fault), or
/// returns the first row at fault (its index in the chunk, and why), as a
/// serial reading finds it.
fn check_chunk<'a, T: Sync>(
    items: &[T],
    row: &(dyn Fn(&T) -> std::result::Result<&scan::Row<'a, FIELDS>, &String> + Sync),
    shapes: &mut Shapes,
    raws: &mut Vec<&'a str>,
    jobs: &mut Vec<Job>,
) -> std::result::Result<(), (usize, String)> {
    // Serially: the first malformed row, and every shape up to it.
    let mut ids = Vec::with_capacity(items.len());
    let mut first: Option<(usize, String)> = None;
    // The last row's raw shape value and its index: the same text is the same
    // shape (most batches use one), with no decoding or lookup.
    let mut last: Option<(&'a str, u32)> = None;
    for (j, item) in items.iter().enumerate() {
        let id = match row(item) {
            Ok(r) => match (r.fields[0], last) {
                (Some(raw), Some((l, k))) if raw == l => Ok(k),
                (raw, _) => json_spec(&r.fields).and_then(|spec| {
                    let k = shapes.id(&spec).map_err(|e| e.to_string())?;
                    last = raw.map(|raw| (raw, k));
                    Ok(k)
                }),
            },
            Err(e) => Err(e.clone()),
        };
        match id {
            Ok(k) => ids.push(k),
            Err(reason) => {
                first = Some((j, reason));
                break;
            }
        }
    }
    // In parallel: the numbers of the rows before it (all scanned well),
    // their jobs appended in place; a fault among them comes first.
    let shapes = &*shapes;
    let checked = &items[..ids.len()];
    let filler = Job { shape: 0, replace: false, vbar: 0.0, amp: 0.0, tangential: None };
    let numbers = |j: usize, item: &T| match row(item) {
        Ok(r) => json_numbers(shapes, ids[j], r),
        Err(e) => Err(e.clone()),
    };
    map_into(checked, filler, &numbers, jobs)?;
    if let Some(fault) = first {
        jobs.truncate(jobs.len() - checked.len());
        return Err(fault);
    }
    raws.extend(checked.iter().filter_map(|item| row(item).ok().map(|r| r.raw)));
    Ok(())
}

/// Check and evaluate every row of `text` (a JSON array); `source` names the input in errors.
///
/// The rows are read serially, a chunk at a time, by one strict pass
/// ([`scan::ArrayReader`]); each chunk's rows are then checked by
/// `check_chunk`, and the first fault (a row's check, or else the reader's)
/// reported, as a serial reading finds it.
pub fn run<'a>(text: &'a str, source: &str, stepping: Option<Stepping>) -> Result<Batch<'a>> {
    let parse_err = |reason: String| Error::Parse { context: source.into(), reason };
    let mut reader = scan::ArrayReader::new(text, &NAMES);
    let mut shapes = Shapes::new(stepping);
    let (mut rows, mut jobs) = (vec![], vec![]);
    let mut chunk = Vec::with_capacity(CHUNK);
    while !reader.is_done() {
        let first = reader.rows_read();
        let fault = reader.chunk(CHUNK, &mut chunk).err();
        if first + chunk.len() > MAX_ROWS {
            // Count the rest (a strict scan, nothing kept) for the message.
            let mut count = first + chunk.len();
            while !reader.is_done() && reader.chunk(CHUNK, &mut chunk).is_ok() {
                count = reader.rows_read();
            }
            return Err(Error::TooLarge {
                what: format!("rows of batch {source}"),
                count: count.max(reader.rows_read()) as u128,
                limit: MAX_ROWS as u128,
            });
        }
        check_chunk(&chunk, &|r| Ok(r), &mut shapes, &mut rows, &mut jobs)
            .map_err(|(j, reason)| parse_err(format!("row {}: {reason}", first + j)))?;
        match fault {
            None => {}
            Some(RowsError::Row { row, reason }) => return Err(parse_err(format!("row {row}: {reason}"))),
            Some(RowsError::Syntax { row: Some(row), error }) => {
                return Err(parse_err(format!("row {row}: {}", error.describe(text))))
            }
            // Nothing but whitespace before it (an empty input, not an array): the reason alone.
            Some(RowsError::Syntax { row: None, error })
                if text.as_bytes()[..error.at.min(text.len())].iter().all(u8::is_ascii_whitespace) =>
            {
                return Err(parse_err(error.what))
            }
            Some(RowsError::Syntax { row: None, error }) => return Err(parse_err(error.describe(text))),
        }
    }
    let results = shapes.evaluate_all(&jobs, source, &|i| format!("row {i}"))?;
    let replace = jobs.iter().enumerate().filter(|(_, j)| j.replace).map(|(i, _)| i).collect();
    Ok(Batch { rows, results, replace })
}

/// Write one JSON row with its results: spliced before its closing brace, or
/// (where it carried results) through a parsed map that replaces them.
fn write_json_row<W: Write + ?Sized>(
    out: &mut W,
    row: &str,
    r: &Ratio,
    replace: bool,
    buf: &mut zmij::Buffer,
) -> io::Result<()> {
    if replace {
        let mut map: serde_json::Map<String, serde_json::Value> =
            serde_json::from_str(row).map_err(io::Error::other)?;
        map.insert("mu_ratio".into(), r.mu_ratio.into());
        map.insert("reduction".into(), r.reduction.into());
        return serde_json::to_writer(&mut *out, &map).map_err(io::Error::other);
    }
    // Every row is an object with at least shape, vbar and amp: splice before '}'.
    out.write_all(&row.as_bytes()[..row.len() - 1])?;
    out.write_all(b",\"mu_ratio\":")?;
    out.write_all(buf.format_finite(r.mu_ratio).as_bytes())?;
    out.write_all(b",\"reduction\":")?;
    out.write_all(buf.format_finite(r.reduction).as_bytes())?;
    out.write_all(b"}")
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

    /// Write the array: `[`, one row per line, `]`. Chunks of rows are
    /// formatted in parallel and written in order.
    pub fn write(&self, out: &mut impl Write) -> io::Result<()> {
        out.write_all(b"[")?;
        let n = self.rows.len();
        for c in (0..n).step_by(CHUNK) {
            let end = (c + CHUNK).min(n);
            let pieces: Vec<io::Result<Vec<u8>>> = (c..end)
                .into_par_iter()
                .chunks(4096)
                .map(|idx| {
                    let mut buf = Vec::with_capacity(idx.len() * 128);
                    let mut fmt = zmij::Buffer::new();
                    for i in idx {
                        buf.extend_from_slice(if i == 0 { b"\n" } else { b",\n" });
                        let rep = self.replace.binary_search(&i).is_ok();
                        write_json_row(&mut buf, self.rows[i], &self.results[i], rep, &mut fmt)?;
                    }
                    Ok(buf)
                })
                .collect();
            for p in pieces {
                out.write_all(&p?)?;
            }
        }
        out.write_all(b"\n]\n")
    }
}

/// Stream a JSON Lines or CSV batch: `open()` gives the input (called twice:
/// once to check every row, once to compute and write; once only when the
/// input is one chunk, computed from its check); `source` names it.
/// Returns the number of rows.
pub fn stream(
    format: Format,
    open: &dyn Fn() -> Result<Box<dyn BufRead>>,
    source: &str,
    stepping: Option<Stepping>,
    out: &mut dyn Write,
) -> Result<u64> {
    match format {
        Format::JsonLines => stream_lines(open, source, stepping, out),
        Format::Csv => stream_csv(open, source, stepping, out),
        Format::Json => Err(Error::Internal { what: "a JSON array is not streamed".into() }),
    }
}

fn too_many(source: &str, n: u64) -> Error {
    Error::TooLarge { what: format!("rows of batch {source}"), count: n as u128, limit: MAX_STREAM_ROWS as u128 }
}

/// `read_until(b'\n')` of at most `limit` bytes (as through `Read::take`):
/// the bytes up to and including the next line break, or up to `limit` of
/// them, or to the end, appended to `buf`; their count. The line break is
/// found by `memchr` in the reader's buffer (~80 instructions a 68-byte line,
/// the call included, where the standard library's search took ~160; and no
/// `Take` adapter a line).
fn read_line_capped(input: &mut dyn BufRead, buf: &mut Vec<u8>, limit: usize) -> io::Result<usize> {
    let mut read = 0;
    while read < limit {
        let avail = match input.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if avail.is_empty() {
            break;
        }
        let avail = &avail[..avail.len().min(limit - read)];
        let (used, done) = match memchr::memchr(b'\n', avail) {
            Some(i) => (i + 1, true),
            None => (avail.len(), false),
        };
        buf.extend_from_slice(&avail[..used]);
        input.consume(used);
        read += used;
        if done {
            break;
        }
    }
    Ok(read)
}

/// The next chunk of non-blank lines of JSON Lines (at most [`CHUNK`] lines
/// and about [`CHUNK_BYTES`] bytes), read into one buffer: each line's span
/// (without its line break) and number; no spans at the end.
fn line_chunk(
    input: &mut dyn BufRead,
    source: &str,
    line: &mut u64,
    buf: &mut Vec<u8>,
    spans: &mut Vec<(usize, usize)>,
    numbers: &mut Vec<u64>,
) -> Result<()> {
    buf.clear();
    spans.clear();
    numbers.clear();
    while spans.len() < CHUNK && buf.len() < CHUNK_BYTES {
        let start = buf.len();
        let n = read_line_capped(input, buf, MAX_LINE + 2)
            .map_err(|e| Error::Parse { context: source.into(), reason: format!("cannot read: {e}") })?;
        if n == 0 {
            break;
        }
        *line += 1;
        // A UTF-8 byte-order mark (spreadsheets write one) is not part of the first line.
        if *line == 1 && buf[start..].starts_with(b"\xEF\xBB\xBF") {
            buf.drain(start..start + 3);
        }
        let mut end = buf.len();
        if end == start {
            continue;
        }
        if buf[end - 1] == b'\n' {
            end -= 1;
            if end > start && buf[end - 1] == b'\r' {
                end -= 1;
            }
        }
        if end - start > MAX_LINE {
            return Err(Error::TooLarge {
                what: format!("bytes of line {line} of {source}"),
                count: n as u128,
                limit: MAX_LINE as u128,
            });
        }
        if buf[start..end].iter().all(|b| b.is_ascii_whitespace()) {
            buf.truncate(start);
            continue;
        }
        spans.push((start, end));
        numbers.push(*line);
    }
    Ok(())
}

/// One line of JSON Lines, scanned (tried first with the layout of the line
/// before it in `layouts`).
fn scan_line<'a>(text: &'a str, layouts: &mut scan::Layouts<'a, FIELDS>) -> Scanned<'a> {
    scan::line_row_with(text, &KEYS, layouts).map_err(|e| e.describe(text))
}

/// Lines a task of [`scan_lines`] scans, one line's layout tried on the next.
const LINES_PER_TASK: usize = 1024;

/// The lines `spans` of a chunk `buf`, scanned in parallel: the chunk checked
/// as UTF-8 at once (~0.5 instructions a byte where a check a line took ~140
/// a line), else line by line, so that the line at fault is the one named.
fn scan_lines<'a>(buf: &'a [u8], spans: &[(usize, usize)]) -> Vec<Scanned<'a>> {
    // Each span starts after a line break (or at the start) and ends before
    // one (or at the end): on character boundaries of a valid text.
    match std::str::from_utf8(buf) {
        Ok(text) => {
            // Tasks of consecutive lines, each scanned into its place.
            let mut out: Vec<Scanned<'a>> = Vec::new();
            out.resize_with(spans.len(), || Err(String::new()));
            out.par_chunks_mut(LINES_PER_TASK).zip(spans.par_chunks(LINES_PER_TASK)).for_each(|(out, spans)| {
                let mut layouts = scan::Layouts::default();
                for (slot, &(a, b)) in out.iter_mut().zip(spans) {
                    *slot = scan_line(&text[a..b], &mut layouts);
                }
            });
            out
        }
        Err(_) => spans
            .par_iter()
            .map(|&(a, b)| {
                std::str::from_utf8(&buf[a..b])
                    .map_err(|_| "not UTF-8".to_string())
                    .and_then(|line| scan_line(line, &mut scan::Layouts::default()))
            })
            .collect(),
    }
}

/// JSON Lines: chunks of lines read serially, checked ([`check_chunk`]),
/// evaluated and formatted in parallel; blank lines skipped.
fn stream_lines(
    open: &dyn Fn() -> Result<Box<dyn BufRead>>,
    source: &str,
    stepping: Option<Stepping>,
    out: &mut dyn Write,
) -> Result<u64> {
    let mut shapes = Shapes::new(stepping);
    let fault = |numbers: &[u64], (j, reason): (usize, String)| Error::Parse {
        context: source.into(),
        reason: format!("line {}: {reason}", numbers[j]),
    };
    let werr = |e: io::Error| Error::write("stdout", e);
    // Compute a checked chunk's rows in parallel and write them in order.
    let emit = |shapes: &Shapes, raws: &[&str], jobs: &[Job], numbers: &[u64], out: &mut dyn Write| -> Result<()> {
        let results = shapes.evaluate_all(jobs, source, &|i| format!("line {}", numbers[i]))?;
        let pieces: Vec<io::Result<Vec<u8>>> = raws
            .par_chunks(4096)
            .zip(jobs.par_chunks(4096))
            .zip(results.par_chunks(4096))
            .map(|((raws, jobs), rs)| {
                let mut buf = Vec::with_capacity(raws.len() * 128);
                let mut fmt = zmij::Buffer::new();
                for ((raw, job), r) in raws.iter().zip(jobs).zip(rs) {
                    write_json_row(&mut buf, raw, r, job.replace, &mut fmt)?;
                    buf.push(b'\n');
                }
                Ok(buf)
            })
            .collect();
        for p in pieces {
            out.write_all(&p.map_err(werr)?).map_err(werr)?;
        }
        Ok(())
    };
    // Pass 1, its first chunk: checked and kept while the next is read. An
    // input of one chunk is read once: computed and written from what was checked.
    let mut input = open()?;
    let mut line = 0u64;
    let (mut buf, mut spans, mut numbers) = (vec![], vec![], vec![]);
    line_chunk(&mut *input, source, &mut line, &mut buf, &mut spans, &mut numbers)?;
    let scanned = scan_lines(&buf, &spans);
    let (mut raws, mut jobs) = (vec![], vec![]);
    check_chunk(&scanned, &|r| r.as_ref(), &mut shapes, &mut raws, &mut jobs).map_err(|f| fault(&numbers, f))?;
    let mut total = jobs.len() as u64;
    let (mut buf2, mut spans2, mut numbers2) = (vec![], vec![], vec![]);
    line_chunk(&mut *input, source, &mut line, &mut buf2, &mut spans2, &mut numbers2)?;
    if spans2.is_empty() {
        emit(&shapes, &raws, &jobs, &numbers, out)?;
        out.flush().map_err(werr)?;
        return Ok(total);
    }
    drop((raws, jobs, scanned));
    (buf, spans, numbers) = (buf2, spans2, numbers2);
    // Pass 1, the other chunks (the second already read); then pass 2: every
    // chunk computed and written.
    let (mut again, mut pending) = (0u64, true);
    for pass in [1, 2] {
        if pass == 2 {
            input = open()?;
            line = 0;
        }
        loop {
            shapes.new_chunk();
            if !std::mem::take(&mut pending) {
                line_chunk(&mut *input, source, &mut line, &mut buf, &mut spans, &mut numbers)?;
            }
            if spans.is_empty() {
                break;
            }
            let scanned = scan_lines(&buf, &spans);
            let (mut raws, mut jobs) = (vec![], vec![]);
            check_chunk(&scanned, &|r| r.as_ref(), &mut shapes, &mut raws, &mut jobs)
                .map_err(|f| fault(&numbers, f))?;
            if pass == 1 {
                total += jobs.len() as u64;
                if total > MAX_STREAM_ROWS {
                    return Err(too_many(source, total));
                }
                continue;
            }
            again += jobs.len() as u64;
            if again > total {
                return Err(changed(source, total, again));
            }
            emit(&shapes, &raws, &jobs, &numbers, out)?;
        }
    }
    if again != total {
        return Err(changed(source, total, again));
    }
    out.flush().map_err(werr)?;
    Ok(total)
}

/// The input's second reading differs from the first (the file was changed).
fn changed(source: &str, checked: u64, again: u64) -> Error {
    Error::Parse {
        context: source.into(),
        reason: format!("the input changed while it was read: {checked} rows were checked, {again} came back"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Read;

    /// JSON Lines are scanned in tasks of consecutive lines, each line tried
    /// with the last line's layout: every line reads as it reads alone (rows,
    /// numbers to the bit, and faults), across tasks and changing layouts.
    #[test]
    fn lines_scan_as_each_line_alone() {
        let kinds = [
            |i: usize| format!(r#"{{"shape":"flat","vbar":0.{i},"amp":{i}e-2}}"#),
            |i: usize| format!(r#"  {{"vbar":{i},"shape":"parabolic","amp":1}} "#),
            |i: usize| format!(r#"{{"shape":"flat","vbar":0.{i},"amp":{i},"id":"r{i}"}}"#),
            |i: usize| format!(r#"{{"shape":"flat","vbar":0.{i},"amp":{i}}} x"#),
            |i: usize| format!(r#"{{"shape":"flat","vbar":0.{i},"amp":{i},"vbar":1}}"#),
            |i: usize| format!(r#"{{"shape":"fl\u0061t","vbar":{i},"amp":1}}"#),
        ];
        for period in [1, 3, 700] {
            let lines: Vec<String> = (0..2500).map(|i| kinds[(i / period) % kinds.len()](i)).collect();
            let buf = lines.join("\n");
            let mut spans = vec![];
            let mut at = 0;
            for l in &lines {
                spans.push((at, at + l.len()));
                at += l.len() + 1;
            }
            let got = scan_lines(buf.as_bytes(), &spans);
            assert_eq!(got.len(), lines.len());
            for (g, l) in got.iter().zip(&lines) {
                let alone = scan::line_row(l, &KEYS).map_err(|e| e.describe(l));
                type Bits<'a> = (&'a str, [Option<&'a str>; 8], [u64; 8]);
                fn bits<'a>(r: &Scanned<'a>) -> std::result::Result<Bits<'a>, String> {
                    r.as_ref().map(|r| (r.raw, r.fields, r.numbers.map(f64::to_bits))).map_err(Clone::clone)
                }
                assert_eq!(bits(g), bits(&alone), "period {period}: {l}");
            }
        }
    }

    /// A chunk with a row at fault (its shape, found serially; or its numbers,
    /// found in parallel) is reported at that row and appends nothing.
    #[test]
    fn a_chunk_at_fault_appends_nothing() {
        let good = [r#"{"shape":"flat","vbar":0.5,"amp":1}"#, r#"{"shape":"flat","vbar":0.2,"amp":0.5}"#];
        let scanned = |lines: &[&'static str]| -> Vec<Scanned<'static>> {
            lines.iter().map(|l| scan::line_row(l, &KEYS).map_err(|e| e.what)).collect()
        };
        let mut shapes = Shapes::new(None);
        let (mut raws, mut jobs) = (vec![], vec![]);
        check_chunk(&scanned(&good), &|r| r.as_ref(), &mut shapes, &mut raws, &mut jobs).unwrap();
        assert_eq!((raws.len(), jobs.len()), (2, 2));
        for (bad, at) in [
            ([good[0], good[1], r#"{"shape":"nope","vbar":0.5,"amp":1}"#], 2),
            ([good[0], r#"{"shape":"flat","vbar":-1,"amp":1}"#, good[1]], 1),
        ] {
            let fault = check_chunk(&scanned(&bad), &|r| r.as_ref(), &mut shapes, &mut raws, &mut jobs).unwrap_err();
            assert_eq!(fault.0, at, "{fault:?}");
            assert_eq!((raws.len(), jobs.len()), (2, 2), "{bad:?}");
        }
    }

    /// `map_into` appends `f`'s values in order, or reports the first item at
    /// fault (of many, spread over the threads) and leaves `out` as it was.
    #[test]
    fn map_into_keeps_order_and_the_first_fault() {
        // The slot keeps the lowest index, whatever the order faults come in.
        let mut slot = None;
        for (i, e) in [(50, "b"), (70, "c"), (20, "a"), (30, "d"), (20, "e")] {
            keep_first(&mut slot, i, e);
        }
        assert_eq!(slot, Some((20, "a")));
        let items: Vec<u64> = (0..100_000).collect();
        let square = |_: usize, &x: &u64| -> std::result::Result<u64, String> { Ok(x * x) };
        let mut out = vec![7];
        assert_eq!(map_into(&items, 0, &square, &mut out), Ok(()));
        assert!(out.len() == 100_001 && out[0] == 7 && out.iter().skip(1).zip(&items).all(|(y, x)| *y == x * x));
        let faulty = |i: usize, &x: &u64| if i > 20_000 && i % 7 == 3 { Err(format!("item {x}")) } else { Ok(x) };
        for _ in 0..20 {
            let mut out = vec![1, 2];
            assert_eq!(map_into(&items, 0, &faulty, &mut out), Err((20_002, "item 20002".to_string())));
            assert_eq!(out, [1, 2]);
        }
    }

    /// A reader that hands out its bytes `step` at a time and is interrupted
    /// once before each piece: lines cut anywhere by the buffer, as `read_until`
    /// through `Read::take` would read them.
    struct Pieces {
        data: Vec<u8>,
        at: usize,
        step: usize,
        interrupt: bool,
    }

    impl Read for Pieces {
        fn read(&mut self, out: &mut [u8]) -> io::Result<usize> {
            self.interrupt = !self.interrupt;
            if self.interrupt {
                return Err(io::Error::from(io::ErrorKind::Interrupted));
            }
            let n = self.step.min(out.len()).min(self.data.len() - self.at);
            out[..n].copy_from_slice(&self.data[self.at..self.at + n]);
            self.at += n;
            Ok(n)
        }
    }

    #[test]
    fn lines_are_read_as_read_until_through_take_reads_them() {
        let data = b"ab\n\ncdefghij\r\nklmnopqrstuvwxyz\nlast".to_vec();
        for (step, cap, limit) in [(1, 1, 100), (3, 2, 100), (5, 64, 100), (64, 64, 4), (2, 3, 7), (7, 5, 1)] {
            let pieces = Pieces { data: data.clone(), at: 0, step, interrupt: false };
            let mut ours = io::BufReader::with_capacity(cap, pieces);
            let mut theirs = io::BufReader::with_capacity(cap, &data[..]);
            loop {
                let (mut a, mut b) = (vec![], vec![]);
                let n = read_line_capped(&mut ours, &mut a, limit).unwrap();
                let m = Read::take(&mut theirs, limit as u64).read_until(b'\n', &mut b).unwrap();
                assert_eq!((n, &a), (m, &b), "step {step} cap {cap} limit {limit}");
                if n == 0 {
                    break;
                }
            }
        }
    }

    /// A chunk whose text is valid UTF-8 is checked at once; one that is not,
    /// line by line: only the line at fault is refused, and named as such.
    #[test]
    fn lines_of_a_chunk_are_checked_as_utf8_at_once_or_line_by_line() {
        let row = |v: &str| format!("{{\"shape\":\"flat\",\"vbar\":{v},\"amp\":1}}");
        let good = format!("{}\n{}\r\n", row("0.5"), row("0.25"));
        let spans = |buf: &[u8]| {
            let mut s = vec![];
            let mut a = 0;
            for (i, &c) in buf.iter().enumerate() {
                if c == b'\n' {
                    let b = if i > a && buf[i - 1] == b'\r' { i - 1 } else { i };
                    s.push((a, b));
                    a = i + 1;
                }
            }
            s
        };
        let buf = good.as_bytes();
        let scanned = scan_lines(buf, &spans(buf));
        let vbars: Vec<_> = scanned.iter().map(|r| r.as_ref().unwrap().numbers[1]).collect();
        assert_eq!(vbars, [0.5, 0.25]);
        let mut bad = good.clone().into_bytes();
        bad.extend_from_slice(b"{\"shape\":\"fl\xFFat\"}\n");
        bad.extend_from_slice(format!("{}\n", row("0.125")).as_bytes());
        let scanned = scan_lines(&bad, &spans(&bad));
        assert_eq!(scanned.len(), 4);
        assert!(scanned[0].is_ok() && scanned[1].is_ok() && scanned[3].is_ok());
        assert_eq!(scanned[2].as_ref().err().map(String::as_str), Some("not UTF-8"));
    }
}
