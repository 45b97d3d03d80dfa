//! `batch` in CSV (the `csv` crate reads and writes): every column kept,
//! `mu_ratio,reduction` appended, or filled where the header has them; with
//! a column `transverse_amp`, `transverse_ratio` too (0 on a row without a
//! transverse oscillation: no force across the sliding direction).

use super::{
    changed, digest, number, too_many, Answer, Inputs, Job, Method, Open, Read, Shapes, CHUNK, MAX_LINE,
    MAX_STREAM_ROWS,
};
use crate::error::{Error, Result};
use crate::output::io_of;
use std::io::{self, BufRead, Write};

/// A record as read: its shape's text and inputs, or why it is malformed.
type Record<'a> = std::result::Result<(&'a str, Inputs), String>;

/// A [`Record`] as [`Shapes::check`] takes it.
fn view<'r>(r: &'r Record<'_>) -> Read<'r> {
    r.as_ref().map(|(s, i)| (*s, i)).map_err(String::as_str)
}

/// The columns of a CSV batch.
struct Columns {
    shape: usize,
    /// The columns of [`Inputs::NAMES`] the header has.
    inputs: Vec<(&'static str, usize)>,
    /// The result columns, where the header has them.
    results: Option<(usize, usize)>,
    /// With a column `transverse_amp`: the column `transverse_ratio`, where
    /// the header has it (else appended).
    transverse: Option<Option<usize>>,
}

impl Columns {
    fn of(header: &csv::ByteRecord, source: &str) -> Result<Columns> {
        let bad = |reason: String| Error::Parse { context: source.into(), reason };
        let find = |name: &str| header.iter().position(|h| h.trim_ascii() == name.as_bytes());
        for (i, h) in header.iter().enumerate() {
            if let Some(g) = header.iter().take(i).find(|g| g.trim_ascii() == h.trim_ascii()) {
                let (g, h) = (String::from_utf8_lossy(g), String::from_utf8_lossy(h));
                let twice = if g == h { format!("'{h}'") } else { format!("'{g}' and '{h}'") };
                return Err(bad(format!("the header repeats the column {twice}")));
            }
        }
        let shape = find("shape").ok_or_else(|| bad("the header has no column 'shape'".into()))?;
        if find("amp").is_none() {
            return Err(bad("the header has no column 'amp'".into()));
        }
        if find("vbar").is_none() && find("vhat").is_none() {
            return Err(bad("the header has no column 'vbar' (or 'vhat')".into()));
        }
        let inputs = Inputs::NAMES.iter().filter_map(|&n| find(n).map(|c| (n, c))).collect();
        let results = match (find("mu_ratio"), find("reduction")) {
            (Some(m), Some(r)) => Some((m, r)),
            (None, None) => None,
            _ => return Err(bad("the header has only one of 'mu_ratio', 'reduction'".into())),
        };
        let transverse = find("transverse_amp").map(|_| find("transverse_ratio"));
        Ok(Columns { shape, inputs, results, transverse })
    }

    /// Record `r` of `chunk`: its shape and inputs; an empty cell of an
    /// optional column is absent.
    fn read<'a>(&self, chunk: &'a Chunk, r: usize) -> Record<'a> {
        let text = |col: usize, name: &str| {
            std::str::from_utf8(chunk.field(r, col)).map_err(|_| format!("'{name}' is not UTF-8"))
        };
        let mut inputs = Inputs::default();
        for &(name, col) in &self.inputs {
            let t = text(col, name)?.trim();
            if t.is_empty() && name != "amp" {
                continue;
            }
            if let Some(slot) = inputs.slot(name) {
                *slot = number(t, name)?;
            }
        }
        Ok((text(self.shape, "shape")?.trim(), inputs))
    }
}

/// A chunk of records: their fields one after another in `bytes`, where
/// each ends in `ends` (every record has `width` fields), and their lines.
/// Its buffers are reused chunk after chunk.
#[derive(Default)]
struct Chunk {
    bytes: Vec<u8>,
    ends: Vec<usize>,
    lines: Vec<u64>,
    width: usize,
}

impl Chunk {
    fn len(&self) -> usize {
        self.lines.len()
    }

    /// Field `f` of record `r`.
    fn field(&self, r: usize, f: usize) -> &[u8] {
        let i = r * self.width + f;
        let start = if i == 0 { 0 } else { self.ends[i - 1] };
        &self.bytes[start..self.ends[i]]
    }

    /// The hash of its fields (their bytes and where each ends).
    fn digest(&self) -> u64 {
        let ends: Vec<u8> = self.ends.iter().flat_map(|e| e.to_le_bytes()).collect();
        digest(&self.bytes) ^ digest(&ends).rotate_left(1)
    }
}

/// What [`Lines`] has seen of the input: where each line ends (a `\n`, a
/// `\r\n` or a lone `\r`), and the bytes since the last record.
#[derive(Default)]
struct Seen {
    /// Bytes passed on.
    offset: u64,
    /// Line ends (where, and 1 or 2 bytes) not yet behind the last record asked about.
    ends: std::collections::VecDeque<(u64, u64)>,
    /// Line ends behind it.
    behind: u64,
    /// Whether the last byte passed on was a `\r`.
    cr: bool,
    /// Bytes passed on since the last record was read.
    since: u64,
}

impl Seen {
    /// The line (from 1) of a record the reader says starts at byte `at`: after
    /// blank lines (or within a `\r\n`) that is a line end, and no record
    /// starts with one, so the line ends from there on are passed over too.
    fn line(&mut self, at: u64) -> u64 {
        let mut at = at;
        while let Some(&(e, len)) = self.ends.front() {
            if e > at {
                break;
            }
            // A line end the reader stopped in or at: the record is after it.
            at = at.max(e + len);
            self.ends.pop_front();
            self.behind += 1;
        }
        self.behind + 1
    }
}

/// The input as the CSV reader sees it: its line ends counted (the `csv`
/// crate's own count misses blank lines and lone `\r`), and at most
/// [`MAX_LINE`] bytes (and the reader's buffer) between two records, so that
/// a record too long is refused before it is in memory.
struct Lines {
    inner: Box<dyn BufRead>,
    seen: std::rc::Rc<std::cell::RefCell<Seen>>,
}

/// The CSV reader's own buffer: what it may have read beyond a record.
const READ_AHEAD: usize = 1 << 13;

impl io::Read for Lines {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let mut seen = self.seen.borrow_mut();
        if seen.since > (MAX_LINE + 2 * READ_AHEAD) as u64 {
            return Err(io::Error::other(format!("a record of more than {MAX_LINE} bytes")));
        }
        let n = self.inner.read(buf)?;
        // Line ends only (memchr); a `\n` right after a `\r` (also across two
        // reads) makes that `\r` a two-byte end.
        for i in memchr::memchr2_iter(b'\n', b'\r', &buf[..n]) {
            let cr_before = if i > 0 { buf[i - 1] == b'\r' } else { seen.cr };
            let at = seen.offset + i as u64;
            match seen.ends.back_mut() {
                Some(last) if buf[i] == b'\n' && cr_before => last.1 = 2,
                _ => seen.ends.push_back((at, 1)),
            }
        }
        if n > 0 {
            seen.cr = buf[n - 1] == b'\r';
        }
        seen.offset += n as u64;
        seen.since += n as u64;
        Ok(n)
    }
}

/// The records of one pass, a chunk at a time.
struct Records {
    reader: csv::Reader<Lines>,
    seen: std::rc::Rc<std::cell::RefCell<Seen>>,
    source: String,
    header: csv::ByteRecord,
    columns: Columns,
    record: csv::ByteRecord,
}

impl Records {
    fn new(input: Box<dyn BufRead>, source: &str) -> Result<Records> {
        let seen = std::rc::Rc::new(std::cell::RefCell::new(Seen::default()));
        let lines = Lines { inner: input, seen: seen.clone() };
        let mut reader = csv::ReaderBuilder::new().has_headers(true).buffer_capacity(READ_AHEAD).from_reader(lines);
        let header = reader
            .byte_headers()
            .map_err(|e| Error::Parse { context: source.into(), reason: format!("line 1: {e}") })?
            .clone();
        if header.iter().all(<[u8]>::is_empty) {
            return Err(Error::Parse { context: source.into(), reason: "the input is empty: no header".into() });
        }
        let columns = Columns::of(&header, source)?;
        Ok(Records { reader, seen, source: source.into(), header, columns, record: csv::ByteRecord::new() })
    }

    /// The line of the record that starts at `pos`.
    fn line(&self, pos: Option<&csv::Position>) -> u64 {
        let at = pos.map_or_else(|| self.reader.position().byte(), csv::Position::byte);
        self.seen.borrow_mut().line(at)
    }

    /// The next chunk of records (at most [`CHUNK`]).
    fn chunk(&mut self, chunk: &mut Chunk) -> Result<()> {
        chunk.bytes.clear();
        chunk.ends.clear();
        chunk.lines.clear();
        chunk.width = self.header.len();
        while chunk.len() < CHUNK {
            let more = self.reader.read_byte_record(&mut self.record).map_err(|e| self.fault(&e))?;
            if !more {
                break;
            }
            self.seen.borrow_mut().since = 0;
            let line = self.line(self.record.position());
            if self.record.as_slice().len() > MAX_LINE {
                return Err(Error::parse(
                    self.source.clone(),
                    format!("line {line}: a record of more than {MAX_LINE} bytes"),
                ));
            }
            for f in &self.record {
                chunk.bytes.extend_from_slice(f);
                chunk.ends.push(chunk.bytes.len());
            }
            chunk.lines.push(line);
        }
        Ok(())
    }

    fn fault(&self, e: &csv::Error) -> Error {
        let reason = match e.kind() {
            csv::ErrorKind::UnequalLengths { pos, expected_len, len } => {
                format!("line {}: {len} fields where the header has {expected_len}", self.line(pos.as_ref()))
            }
            csv::ErrorKind::Io(io) if io.get_ref().is_some_and(|x| x.is::<crate::twopass::SpoolFull>()) => {
                let full = io.get_ref().map(ToString::to_string).unwrap_or_default();
                return Error::Write { path: "a copy of the input".into(), source: io::Error::new(io.kind(), full) };
            }
            _ => format!("line {}: {e}", self.line(e.position())),
        };
        Error::Parse { context: self.source.clone(), reason }
    }

    /// Check a chunk: its jobs, or the first line at fault.
    fn check(&self, chunk: &Chunk, shapes: &mut Shapes) -> Result<Vec<Job>> {
        let mut jobs = Vec::with_capacity(chunk.len());
        let read: Vec<Record> = (0..chunk.len()).map(|r| self.columns.read(chunk, r)).collect();
        shapes
            .check(&read, &view, &mut jobs)
            .map_err(|(j, reason)| Error::parse(self.source.clone(), format!("line {}: {reason}", chunk.lines[j])))?;
        Ok(jobs)
    }

    /// A writer of the output, its header written.
    fn writer<'w>(&self, out: &'w mut dyn Write) -> io::Result<csv::Writer<&'w mut dyn Write>> {
        let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(out);
        let mut h = self.header.clone();
        if self.columns.results.is_none() {
            h.push_field(b"mu_ratio");
            h.push_field(b"reduction");
        }
        if self.columns.transverse == Some(None) {
            h.push_field(b"transverse_ratio");
        }
        w.write_byte_record(&h).map_err(io_of)?;
        Ok(w)
    }

    /// Write a chunk of records with their results, field by field.
    fn write(&self, w: &mut csv::Writer<&mut dyn Write>, chunk: &Chunk, results: &[Answer]) -> io::Result<()> {
        let mut fmt = zmij::Buffer::new();
        for (i, a) in results.iter().enumerate() {
            let (r, t) = (&a.ratio, a.transverse_ratio.unwrap_or(0.0));
            for f in 0..chunk.width {
                match (self.columns.results, self.columns.transverse) {
                    (Some((m, _)), _) if f == m => w.write_field(fmt.format_finite(r.mu_ratio)),
                    (Some((_, d)), _) if f == d => w.write_field(fmt.format_finite(r.reduction)),
                    (_, Some(Some(c))) if f == c => w.write_field(fmt.format_finite(t)),
                    _ => w.write_field(chunk.field(i, f)),
                }
                .map_err(io_of)?;
            }
            if self.columns.results.is_none() {
                w.write_field(fmt.format_finite(r.mu_ratio)).map_err(io_of)?;
                w.write_field(fmt.format_finite(r.reduction)).map_err(io_of)?;
            }
            if self.columns.transverse == Some(None) {
                w.write_field(fmt.format_finite(t)).map_err(io_of)?;
            }
            w.write_record(None::<&[u8]>).map_err(io_of)?;
        }
        Ok(())
    }
}

/// CSV: every record checked in a first pass (an input of one chunk is then
/// computed and written from it), then read again a chunk at a time,
/// compared with the first pass, evaluated in parallel and written.
pub(super) fn stream_csv(open: &Open, source: &str, method: Method, out: &mut dyn Write) -> Result<u64> {
    let mut shapes = Shapes::new(method);
    let werr = |e: io::Error| Error::write("stdout", e);
    let mut records = Records::new(open()?, source)?;
    let mut chunk = Chunk::default();
    let (mut hashes, mut total) = (vec![], 0u64);
    let mut single = None;
    loop {
        shapes.new_chunk();
        records.chunk(&mut chunk)?;
        // A short chunk is the last: the reader is at the end.
        let last = chunk.len() < CHUNK;
        if chunk.len() > 0 {
            let jobs = records.check(&chunk, &mut shapes)?;
            total += jobs.len() as u64;
            if total > MAX_STREAM_ROWS {
                return Err(too_many(source, total));
            }
            hashes.push(chunk.digest());
            if last && hashes.len() == 1 {
                single = Some(jobs);
            }
        }
        if last {
            break;
        }
    }
    let name = |chunk: &Chunk, i: usize| format!("line {}", chunk.lines[i]);
    if hashes.is_empty() || single.is_some() {
        // At most one chunk: its records are still in `chunk`.
        let jobs = single.unwrap_or_default();
        let results = shapes.evaluate_all(&jobs, source, &|i| name(&chunk, i))?;
        let mut w = records.writer(out).map_err(werr)?;
        records.write(&mut w, &chunk, &results).map_err(werr)?;
        return w.flush().map_err(werr).map(|()| total);
    }
    let mut records = Records::new(open()?, source)?;
    let mut w = records.writer(out).map_err(werr)?;
    for (k, hash) in hashes.iter().enumerate() {
        shapes.new_chunk();
        records.chunk(&mut chunk)?;
        if chunk.digest() != *hash {
            return Err(changed(source, &format!("chunk {} of {} differs from what was checked", k + 1, hashes.len())));
        }
        let jobs = records.check(&chunk, &mut shapes)?;
        let results = shapes.evaluate_all(&jobs, source, &|i| name(&chunk, i))?;
        records.write(&mut w, &chunk, &results).map_err(werr)?;
    }
    w.flush().map_err(werr).map(|()| total)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An input whose second reading differs from the first (a file edited
    /// between the passes: `0.1` became `0.125` in its second chunk) is
    /// refused before that chunk is written; the same input read twice alike
    /// gives its rows.
    #[test]
    fn an_input_changed_between_the_passes_is_refused() {
        let text = |last: &str| {
            let mut t = String::from("shape,vbar,amp\n");
            for _ in 0..CHUNK + 10 {
                t.push_str("flat,0.3,0.5\n");
            }
            t + &format!("flat,{last},0.5\n")
        };
        for edited in [true, false] {
            let passes = std::cell::Cell::new(0);
            let open = || -> Result<Box<dyn BufRead>> {
                passes.set(passes.get() + 1);
                let t = if edited && passes.get() > 1 { text("0.125") } else { text("0.1") };
                Ok(Box::new(io::Cursor::new(t.into_bytes())))
            };
            let mut out = vec![];
            let r = stream_csv(&open, "f.csv", Method::default(), &mut out);
            let lines = out.iter().filter(|&&b| b == b'\n').count();
            if edited {
                let e = r.unwrap_err().to_string();
                assert!(e.contains("the input changed while it was read: chunk 2 of 2"), "{e}");
                assert_eq!(lines, CHUNK + 1, "only the first chunk written");
            } else {
                assert_eq!(r.unwrap(), CHUNK as u64 + 11);
                assert_eq!(lines, CHUNK + 12);
            }
        }
    }

    /// Line ends split over two reads (`\r` in one, `\n` in the next: a
    /// reader that brings one byte at a time) are counted once.
    #[test]
    fn line_ends_split_between_reads_count_once() {
        let text = "shape,vbar,amp\r\n\r\nflat,0.3,0.5\r\nflat,0.3,0.5\r\rflat,x,0.5\r\n";
        let open = || -> Result<Box<dyn BufRead>> { Ok(Box::new(io::BufReader::with_capacity(1, text.as_bytes()))) };
        let e = stream_csv(&open, "t.csv", Method::default(), &mut vec![]).unwrap_err().to_string();
        assert!(e.contains("line 6: 'vbar' is not a finite number"), "{e}");
    }
}
