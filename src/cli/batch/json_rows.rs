//! `batch` in JSON: an array read whole, or JSON Lines streamed. Each row is
//! read once by `serde_json`: its text borrowed from the input, its wanted
//! fields converted, every other one checked and skipped.

use super::{changed, digest, too_many, Answer, Inputs, Job, Method, Open, Read, Shapes};
use super::{CHUNK, MAX_LINE, MAX_ROWS, MAX_STREAM_ROWS};
use crate::error::{Error, Result};
use crate::json::{NumberOf, StringOf};
use rayon::prelude::*;
use serde::de::{self, Deserializer, MapAccess, Visitor};
use serde_json::value::RawValue;
use std::borrow::Cow;
use std::fmt;
use std::io::{self, BufRead, Write};
use std::ops::Range;

/// Most bytes of lines read into one chunk of JSON Lines.
const CHUNK_BYTES: usize = 32 << 20;

/// One JSON row: its text (from `{` to `}`), its shape and inputs, and the
/// byte ranges (in the text) of the values of `mu_ratio` and `reduction`
/// where it gives them.
struct Row<'a> {
    raw: &'a str,
    shape: Cow<'a, str>,
    inputs: Inputs,
    /// Where the row gives results (boxed: rarely there, and rows are moved by the million).
    results: Option<Box<Given>>,
}

/// Where a row's values of [`RESULTS`] are, if it gives them.
type Given = [Option<Range<usize>>; 3];

/// The fields of a row's answer: `transverse_ratio` where it has a
/// transverse oscillation (or gives the field).
const RESULTS: [&str; 3] = ["mu_ratio", "reduction", "transverse_ratio"];

/// A row as read, or why it is malformed.
type Parsed<'a> = std::result::Result<Row<'a>, String>;

/// A row that gives results: its index and where their values are.
type Replace = (usize, Box<Given>);

impl<'a> Row<'a> {
    /// The row whose text is `raw`, from its fields as read.
    fn of(raw: &'a str, p: Picked<'a>) -> std::result::Result<Row<'a>, String> {
        let shape = p.shape.ok_or("missing field 'shape'")?;
        let inputs = p.inputs;
        let offset = |v: &str| v.as_ptr() as usize - raw.as_ptr() as usize;
        let at = |v: Option<&str>| v.map(|v| offset(v)..offset(v) + v.len());
        let results = p.results.iter().any(Option::is_some).then(|| Box::new(p.results.map(at)));
        Ok(Row { raw, shape, inputs, results })
    }
}

/// Read one row from its text: an object, and nothing else but JSON's
/// whitespace around it (which is not part of the row's text).
fn row(text: &str) -> std::result::Result<Row<'_>, String> {
    let raw = text.trim_matches(|c| matches!(c, ' ' | '\t' | '\n' | '\r'));
    if !raw.starts_with('{') {
        return Err("malformed JSON: expected an object".into());
    }
    let mut de = serde_json::Deserializer::from_str(raw);
    let p = <Picked as serde::Deserialize>::deserialize(&mut de)
        .and_then(|p| de.end().map(|()| p))
        .map_err(|e| crate::json::message(&e))?;
    Row::of(raw, p)
}

/// What a row's fields give: the shape, the inputs, and the text of the
/// values of `mu_ratio` and `reduction` (borrowed from the row).
struct Picked<'a> {
    shape: Option<Cow<'a, str>>,
    inputs: Inputs,
    results: [Option<&'a str>; 3],
}

impl<'de> serde::Deserialize<'de> for Picked<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        d.deserialize_map(Fields)
    }
}

/// The visitor of a row's fields: only the wanted ones are converted, and
/// only the results' values kept as text. A wanted field may not come twice
/// (which value would be meant?); other fields are the row's own business,
/// passed through as written.
struct Fields;

impl<'de> Visitor<'de> for Fields {
    type Value = Picked<'de>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an object")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> std::result::Result<Self::Value, A::Error> {
        let mut out = Picked { shape: None, inputs: Inputs::default(), results: [None; 3] };
        // A field read twice would be ambiguous: refused (a field already set).
        let twice = |key: &str| de::Error::custom(format!("duplicate key '{key}'"));
        while let Some(key) = map.next_key::<Key>()? {
            match key {
                Key::Shape if out.shape.is_none() => out.shape = Some(map.next_value_seed(StringOf("shape"))?),
                Key::Input(k) if out.inputs.0[k].is_nan() => {
                    out.inputs.0[k] = map.next_value_seed(NumberOf(Inputs::NAMES[k]))?;
                }
                Key::Result(r) if out.results[r].is_none() => {
                    out.results[r] = Some(map.next_value::<&'de RawValue>()?.get());
                }
                Key::Other => map.next_value::<de::IgnoredAny>().map(drop)?,
                _ => return Err(twice(key.name())),
            }
        }
        Ok(out)
    }
}

/// A row's field, by its key: the fields rows give most often first, one
/// comparison of the key's text each.
#[derive(Clone, Copy)]
enum Key {
    Shape,
    /// One of [`Inputs::NAMES`].
    Input(usize),
    /// One of [`RESULTS`].
    Result(usize),
    Other,
}

impl Key {
    fn name(self) -> &'static str {
        match self {
            Key::Shape => "shape",
            Key::Input(k) => Inputs::NAMES[k],
            Key::Result(r) => RESULTS[r],
            Key::Other => "",
        }
    }
}

impl<'de> serde::Deserialize<'de> for Key {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Key;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a field name")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> std::result::Result<Key, E> {
                Ok(match s {
                    "shape" => Key::Shape,
                    "vbar" => Key::Input(0),
                    "amp" => Key::Input(1),
                    "mu_ratio" => Key::Result(0),
                    "reduction" => Key::Result(1),
                    "transverse_ratio" => Key::Result(2),
                    _ => Inputs::NAMES.iter().position(|n| *n == s).map_or(Key::Other, Key::Input),
                })
            }
        }
        d.deserialize_str(V)
    }
}

/// The rows of a JSON array, one at a time: each read once, by a stream
/// deserializer from where it starts (which says where it ends); between
/// them only whitespace and commas, checked here.
struct ArrayRows<'a> {
    text: &'a str,
    at: usize,
    first: bool,
    done: bool,
}

impl<'a> ArrayRows<'a> {
    fn new(text: &'a str) -> std::result::Result<ArrayRows<'a>, String> {
        let mut rows = ArrayRows { text, at: 0, first: true, done: false };
        match rows.peek() {
            None => Err("empty input (expected a JSON array)".into()),
            Some(b'[') => {
                rows.at += 1;
                Ok(rows)
            }
            Some(_) => Err("expected a JSON array of objects".into()),
        }
    }

    /// The next byte that is not JSON whitespace (`at` moved to it).
    fn peek(&mut self) -> Option<u8> {
        let b = self.text.as_bytes();
        while self.at < b.len() && matches!(b[self.at], b' ' | b'\t' | b'\n' | b'\r') {
            self.at += 1;
        }
        b.get(self.at).copied()
    }

    /// The array's end: nothing but whitespace may follow.
    fn end(&mut self) -> Option<std::result::Result<Row<'a>, String>> {
        self.done = true;
        self.at += 1;
        self.peek().map(|_| Err("malformed JSON: trailing characters".into()))
    }

    /// The next row (`None` after the last), or why the array is malformed there.
    fn next(&mut self) -> Option<std::result::Result<Row<'a>, String>> {
        if self.done {
            return None;
        }
        match (self.peek(), std::mem::take(&mut self.first)) {
            (Some(b']'), _) => return self.end(),
            (Some(b','), false) => self.at += 1,
            (Some(_), true) => {}
            (found, _) => {
                self.done = true;
                let what = if found.is_some() { "expected `,` or `]`" } else { "EOF while parsing a list" };
                return Some(Err(format!("malformed JSON: {what}")));
            }
        }
        if self.peek().is_some_and(|b| b != b'{') {
            self.done = true;
            return Some(Err("malformed JSON: expected an object".into()));
        }
        let start = self.at;
        let mut stream = serde_json::Deserializer::from_str(&self.text[start..]).into_iter::<Picked>();
        let result = match stream.next() {
            Some(Ok(p)) => Row::of(&self.text[start..start + stream.byte_offset()], p),
            Some(Err(e)) => {
                self.done = true;
                Err(crate::json::message(&e))
            }
            None => {
                self.done = true;
                Err("malformed JSON: EOF while parsing a list".into())
            }
        };
        self.at = start + stream.byte_offset();
        Some(result)
    }
}

/// A row as [`Shapes::check`] takes it.
fn read<'r>(r: &'r std::result::Result<Row<'_>, String>) -> Read<'r> {
    match r {
        Ok(r) => Ok((r.shape.as_ref(), &r.inputs)),
        Err(e) => Err(e),
    }
}

/// Write one row with its results: its text with the values of the results
/// it gives replaced, or with them spliced in before its closing brace
/// (`transverse_ratio` where the row has a transverse oscillation or gives
/// the field; 0 without one: no force across the sliding direction).
fn write_row(out: &mut Vec<u8>, raw: &str, given: Option<&Given>, a: &Answer, fmt: &mut zmij::Buffer) {
    let values = [a.ratio.mu_ratio, a.ratio.reduction, a.transverse_ratio.unwrap_or(0.0)];
    let none: Given = [None, None, None];
    let given = given.unwrap_or(&none);
    let wanted = [true, true, a.transverse_ratio.is_some() || given[2].is_some()];
    // The values the row gives are replaced where they stand; the others
    // are spliced in before its brace.
    let mut spans: Vec<(Range<usize>, f64)> =
        given.iter().zip(values).filter_map(|(g, x)| g.clone().map(|g| (g, x))).collect();
    spans.sort_by_key(|(g, _)| g.start);
    let mut at = 0;
    for (g, x) in spans {
        out.extend_from_slice(&raw.as_bytes()[at..g.start]);
        out.extend_from_slice(fmt.format_finite(x).as_bytes());
        at = g.end;
    }
    out.extend_from_slice(&raw.as_bytes()[at..raw.len() - 1]);
    for k in (0..RESULTS.len()).filter(|&k| wanted[k] && given[k].is_none()) {
        out.extend_from_slice(format!(",\"{}\":", RESULTS[k]).as_bytes());
        out.extend_from_slice(fmt.format_finite(values[k]).as_bytes());
    }
    out.push(b'}');
}

/// An evaluated JSON array, borrowing its rows from the input text.
pub struct Batch<'a> {
    rows: Vec<&'a str>,
    results: Vec<Answer>,
    /// The rows that give results (sorted by index).
    replace: Vec<Replace>,
}

/// Check and evaluate every row of `text` (a JSON array); `source` names the
/// input in errors. The rows are read and checked one after another (the
/// first at fault is the one named, before any fault of an evaluation); each
/// chunk of them is evaluated in parallel while the next is read.
pub fn evaluate<'a>(text: &'a str, source: &str, method: Method) -> Result<Batch<'a>> {
    let mut array = ArrayRows::new(text).map_err(|reason| Error::Parse { context: source.into(), reason })?;
    let mut shapes = Shapes::new(method);
    let mut batch = Batch { rows: vec![], results: vec![], replace: vec![] };
    let (mut pending, mut failed) = (vec![], None);
    loop {
        let (evaluating, first) = (shapes.snapshot(), batch.results.len());
        let (read, evaluated) = rayon::join(
            || read_chunk(&mut array, &mut shapes, &mut batch, source),
            || evaluating.evaluate_all(&pending, source, &|i| format!("row {}", first + i)),
        );
        match evaluated {
            Ok(r) => batch.results.extend(r),
            Err(e) => failed = failed.or(Some(e)),
        }
        pending = read?;
        if pending.is_empty() {
            return failed.map_or(Ok(batch), Err);
        }
    }
}

/// The next [`CHUNK`] rows of `array`, read and checked: their text (and
/// where they give results) appended to `batch`, their jobs returned (none
/// at the end).
fn read_chunk<'a>(
    array: &mut ArrayRows<'a>,
    shapes: &mut Shapes,
    batch: &mut Batch<'a>,
    source: &str,
) -> Result<Vec<Job>> {
    let bad = |reason: String| Error::Parse { context: source.into(), reason };
    let mut jobs = Vec::with_capacity(CHUNK.min(MAX_ROWS));
    let mut last: Option<(Cow<str>, u32)> = None;
    while jobs.len() < CHUNK {
        let Some(row) = array.next() else { break };
        let k = batch.rows.len();
        if k == MAX_ROWS {
            let count = (k + 1 + std::iter::from_fn(|| array.next()).count()) as u128;
            return Err(Error::TooLarge { what: format!("rows of batch {source}"), count, limit: MAX_ROWS as u128 });
        }
        let at = |reason: String| bad(format!("row {k}: {reason}"));
        let row = row.map_err(at)?;
        let id = match &last {
            Some((l, id)) if *l == row.shape => *id,
            _ => {
                let id = shapes.id(&row.shape).map_err(|e| at(e.to_string()))?;
                last = Some((row.shape.clone(), id));
                id
            }
        };
        jobs.push(shapes.job(id, &row.inputs).map_err(at)?);
        batch.rows.push(row.raw);
        if let Some(given) = row.results {
            batch.replace.push((k, given));
        }
    }
    Ok(jobs)
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

    /// The answer of every row, in order.
    pub fn results(&self) -> &[Answer] {
        &self.results
    }

    /// Write the array: `[`, one row per line, `]`. Chunks of rows are
    /// formatted in parallel and written in order.
    pub fn write(&self, out: &mut impl Write) -> io::Result<()> {
        out.write_all(b"[")?;
        const PIECE: usize = 4096;
        for (c, (rows, results)) in self.rows.chunks(CHUNK).zip(self.results.chunks(CHUNK)).enumerate() {
            let pieces: Vec<Vec<u8>> = rows
                .par_chunks(PIECE)
                .zip(results.par_chunks(PIECE))
                .enumerate()
                .map(|(p, (rows, results))| {
                    let first = c * CHUNK + p * PIECE;
                    let mut buf = Vec::with_capacity(rows.len() * 128);
                    let mut fmt = zmij::Buffer::new();
                    for (j, (raw, r)) in rows.iter().zip(results).enumerate() {
                        let i = first + j;
                        buf.extend_from_slice(if i == 0 { b"\n" } else { b",\n" });
                        let given = self.replace.binary_search_by_key(&i, |(k, _)| *k).ok();
                        write_row(&mut buf, raw, given.map(|k| &*self.replace[k].1), r, &mut fmt);
                    }
                    buf
                })
                .collect();
            for p in pieces {
                out.write_all(&p)?;
            }
        }
        out.write_all(b"\n]\n")
    }
}

/// The next chunk of non-blank lines of JSON Lines (at most [`CHUNK`] lines
/// and about [`CHUNK_BYTES`] bytes), read into one buffer: each line's span
/// (without its line break) and number; no spans at the end.
struct Lines {
    buf: Vec<u8>,
    spans: Vec<(usize, usize)>,
    numbers: Vec<u64>,
}

impl Lines {
    fn new() -> Lines {
        Lines { buf: vec![], spans: vec![], numbers: vec![] }
    }

    fn read(&mut self, input: &mut dyn BufRead, source: &str, line: &mut u64) -> Result<()> {
        self.buf.clear();
        self.spans.clear();
        self.numbers.clear();
        while self.spans.len() < CHUNK && self.buf.len() < CHUNK_BYTES {
            let start = self.buf.len();
            let limit = (MAX_LINE + 2) as u64;
            let n = io::Read::take(&mut *input, limit)
                .read_until(b'\n', &mut self.buf)
                .map_err(|e| Error::read(source, e))?;
            if n == 0 {
                break;
            }
            *line += 1;
            // A UTF-8 byte-order mark (spreadsheets write one) is not part of the first line.
            if *line == 1 && self.buf[start..].starts_with(b"\xEF\xBB\xBF") {
                self.buf.drain(start..start + 3);
            }
            let mut end = self.buf.len();
            if end > start && self.buf[end - 1] == b'\n' {
                end -= 1;
                if end > start && self.buf[end - 1] == b'\r' {
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
            if self.buf[start..end].iter().all(u8::is_ascii_whitespace) {
                self.buf.truncate(start);
                continue;
            }
            self.spans.push((start, end));
            self.numbers.push(*line);
        }
        Ok(())
    }

    /// The lines read, each parsed (in parallel). The chunk is checked as
    /// UTF-8 at once (its lines begin and end at line breaks, so on character
    /// boundaries); where it is not, line by line, to name the line.
    fn rows(&self) -> Vec<std::result::Result<Row<'_>, String>> {
        let whole = std::str::from_utf8(&self.buf).ok();
        self.spans
            .par_iter()
            .map(|&(a, b)| match whole {
                Some(text) => row(&text[a..b]),
                None => row(std::str::from_utf8(&self.buf[a..b]).map_err(|_| "not UTF-8".to_string())?),
            })
            .collect()
    }
}

/// Check a chunk of lines: their rows and jobs, or the first line at fault.
fn check_lines<'a>(lines: &'a Lines, shapes: &mut Shapes, source: &str) -> Result<(Vec<Parsed<'a>>, Vec<Job>)> {
    let rows = lines.rows();
    let mut jobs = Vec::with_capacity(rows.len());
    shapes
        .check(&rows, &read, &mut jobs)
        .map_err(|(j, reason)| Error::parse(source, format!("line {}: {reason}", lines.numbers[j])))?;
    Ok((rows, jobs))
}

/// Compute a checked chunk's rows in parallel and write them in order.
fn emit(
    shapes: &Shapes,
    lines: &Lines,
    rows: &[std::result::Result<Row, String>],
    jobs: &[Job],
    source: &str,
    out: &mut dyn Write,
) -> Result<()> {
    let results = shapes.evaluate_all(jobs, source, &|i| format!("line {}", lines.numbers[i]))?;
    let pieces: Vec<Vec<u8>> = rows
        .par_chunks(4096)
        .zip(results.par_chunks(4096))
        .map(|(rows, rs)| {
            let mut buf = Vec::with_capacity(rows.len() * 128);
            let mut fmt = zmij::Buffer::new();
            for (row, r) in rows.iter().flatten().zip(rs) {
                write_row(&mut buf, row.raw, row.results.as_deref(), r, &mut fmt);
                buf.push(b'\n');
            }
            buf
        })
        .collect();
    for p in pieces {
        out.write_all(&p).map_err(|e| Error::write("stdout", e))?;
    }
    Ok(())
}

/// JSON Lines: chunks of lines read serially, checked, evaluated and
/// formatted in parallel; blank lines skipped.
pub(super) fn stream_lines(open: &Open, source: &str, method: Method, out: &mut dyn Write) -> Result<u64> {
    let mut shapes = Shapes::new(method);
    let flush = |out: &mut dyn Write| out.flush().map_err(|e| Error::write("stdout", e));
    // Pass 1: every chunk checked, its bytes' hash kept. An input of one
    // chunk is read once: computed and written from what was checked.
    let mut input = open()?;
    let (mut line, mut total) = (0u64, 0u64);
    let mut hashes = vec![];
    let mut lines = Lines::new();
    loop {
        shapes.new_chunk();
        lines.read(&mut *input, source, &mut line)?;
        if lines.spans.is_empty() {
            break;
        }
        let (rows, jobs) = check_lines(&lines, &mut shapes, source)?;
        total += jobs.len() as u64;
        if total > MAX_STREAM_ROWS {
            return Err(too_many(source, total));
        }
        hashes.push(digest(&lines.buf));
        if hashes.len() == 1 && input.fill_buf().is_ok_and(<[u8]>::is_empty) {
            emit(&shapes, &lines, &rows, &jobs, source, out)?;
            return flush(out).map(|()| total);
        }
    }
    // Pass 2: every chunk read again, compared, computed and written.
    let mut input = open()?;
    line = 0;
    for (k, hash) in hashes.iter().enumerate() {
        shapes.new_chunk();
        lines.read(&mut *input, source, &mut line)?;
        if digest(&lines.buf) != *hash {
            return Err(changed(source, &format!("chunk {} of {} differs from what was checked", k + 1, hashes.len())));
        }
        let (rows, jobs) = check_lines(&lines, &mut shapes, source)?;
        emit(&shapes, &lines, &rows, &jobs, source, out)?;
    }
    flush(out).map(|()| total)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row's text and values: the fields it is read for, wherever they
    /// are, escaped names and strings, `-0`, other fields left alone; the
    /// faults named.
    #[test]
    fn rows_are_read_by_name() {
        let r = row(r#"{"x":[1,{"vbar":2}],"sh\u0061pe":"fl\u0061t","amp":-0,"vbar":0.5,"mu_ratio":7}"#).unwrap();
        assert_eq!(r.shape, "flat");
        assert_eq!((r.inputs.get(0), r.inputs.get(1).map(f64::to_bits)), (Some(0.5), Some(0)));
        assert_eq!(r.results.and_then(|g| g[0].clone()).map(|g| &r.raw[g]), Some("7"));
        for (text, fault) in [
            (r#"[1]"#, "expected an object"),
            (r#"{"vbar":1,"amp":1}"#, "missing field 'shape'"),
            (r#"{"shape":1,"vbar":1,"amp":1}"#, "'shape' must be a string"),
            (r#"{"shape":"flat","vbar":"1","amp":1}"#, "'vbar' must be a number"),
            (r#"{"shape":"flat","vbar":1e999,"amp":1}"#, "'vbar' is not a finite number"),
            (r#"{"shape":"flat","vbar":1,"v\u0062ar":1}"#, "duplicate key 'vbar'"),
        ] {
            let e = row(text).err().unwrap_or_default();
            assert!(e.contains(fault), "{text}: {e}");
        }
    }

    /// Results given are replaced in place, one given gets the other spliced
    /// in, none given gets both; every other byte stays.
    #[test]
    fn results_are_spliced_or_replaced_in_place() {
        // The flat punch at vbar = 0, amp = 0.75: mu = 1 - amp = 0.25 exactly.
        let r = fricosc::Shape::flat().ratio(&fricosc::Conditions::vbar(0.0, 0.75).unwrap()).unwrap();
        assert_eq!((r.mu_ratio, r.reduction), (0.25, 0.75));
        let mut fmt = zmij::Buffer::new();
        for (text, want) in [
            (r#"{"a": 1e400, "b":"\ud800"}"#, r#"{"a": 1e400, "b":"\ud800","mu_ratio":0.25,"reduction":0.75}"#),
            (r#"{"reduction" : 9, "x":-0,"mu_ratio":[1]}"#, r#"{"reduction" : 0.75, "x":-0,"mu_ratio":0.25}"#),
            (r#"{"mu_ratio":1.0000000000000000001 }"#, r#"{"mu_ratio":0.25 ,"reduction":0.75}"#),
        ] {
            let mut given = [None, None, None];
            for (k, name) in ["\"mu_ratio\"", "\"reduction\""].iter().enumerate() {
                if let Some(i) = text.find(name) {
                    let start = i + name.len() + text[i + name.len()..].find(':').unwrap() + 1;
                    let start = start + text[start..].len() - text[start..].trim_start().len();
                    let len = text[start..].find([',', '}']).unwrap();
                    given[k] = Some(start..start + text[start..start + len].trim_end().len());
                }
            }
            let mut out = vec![];
            let given = given.iter().any(Option::is_some).then_some(&given);
            write_row(&mut out, text, given, &Answer { ratio: r, transverse_ratio: None }, &mut fmt);
            assert_eq!(String::from_utf8(out).unwrap(), want);
        }
    }
}
