//! `batch`: rows of `{shape, vbar, amp, ...}` in, the same rows with
//! `mu_ratio` and `reduction` added out, as a JSON array, JSON Lines or CSV.
//!
//! Contracts (README, "Limits and promises"):
//! - One bad row rejects the whole batch, and the error names it (the row of
//!   a JSON array, counted from 0; the line of JSON Lines and CSV). Every row
//!   is checked (its numbers, its shape, that the shape reaches the
//!   amplitude) before the first byte is written; what can fail after that is
//!   an internal error (exit code 3), never the input.
//! - Every other field is written back exactly as given: a JSON row is its
//!   own text with `"mu_ratio":..,"reduction":..` spliced in before its closing
//!   brace, or, where the row has them, with their values' text replaced; a
//!   CSV record keeps every cell and gets two columns, or has those cells filled.
//! - A JSON array is read whole ([`MAX_ROWS`] rows). JSON Lines and CSV stream
//!   in constant memory: a first pass checks every row, a second reads them
//!   again, a chunk of 65,536 rows at a time, and computes and writes them
//!   ([`crate::twopass`]: the second pass reads exactly the bytes of the first,
//!   and each chunk's bytes must hash as they did, or the run stops with an
//!   error before that chunk is written). An input of one chunk is read once.
//!
//! The readers are `serde_json` (raw values borrowed from the input) and
//! `csv`; numbers are `str::parse`'s.

use crate::cmd::{io_err, read_input};
use crate::error::{Error, Result};
use fricosc::stepper::Stepping;
use fricosc::{Conditions, Ratio, Shape};
use rayon::prelude::*;
use std::collections::HashMap;
use std::io::{self, BufRead, Write};
mod csv_rows;
mod json_rows;

pub use json_rows::{evaluate, Batch};

/// Most rows one JSON array may hold.
pub const MAX_ROWS: usize = crate::grid::MAX_ROWS;
/// Most rows of a streamed batch (JSON Lines, CSV).
pub const MAX_STREAM_ROWS: u64 = 1_000_000_000;
/// Longest line of JSON Lines, or record of CSV, in bytes.
pub const MAX_LINE: usize = 1 << 20;
/// Rows checked, computed and written at once.
const CHUNK: usize = 1 << 16;
/// Most distinct shapes a streamed batch keeps parsed between chunks: beyond
/// it the cache is emptied at the next chunk, so that memory stays bounded
/// whatever the number of distinct shape strings.
pub const MAX_CACHED_SHAPES: usize = 4096;

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
            Some(other) => Err(Error::parse("--format", format!("'{other}' is not one of json, jsonl, csv"))),
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

/// The numeric inputs a row may give ([`Inputs::NAMES`]), each a finite
/// number or absent, held as NaN (a value no row can give: non-finite
/// numbers are refused where they are read). Eight bytes each, as rows are
/// moved by the million.
#[derive(Debug, Clone, Copy)]
struct Inputs([f64; 10]);

impl Default for Inputs {
    fn default() -> Self {
        Inputs([f64::NAN; 10])
    }
}

impl Inputs {
    /// The numeric fields a row is read for.
    const NAMES: [&'static str; 10] = [
        "vbar",
        "amp",
        "vhat",
        "tangential_amp",
        "phase",
        "system_stiffness",
        "frequency_ratio",
        "damping",
        "transverse_amp",
        "transverse_phase",
    ];

    /// The slot of the field `name`, if it is one of [`Inputs::NAMES`].
    fn slot(&mut self, name: &str) -> Option<&mut f64> {
        Inputs::NAMES.iter().position(|n| *n == name).map(|k| &mut self.0[k])
    }

    fn get(&self, k: usize) -> Option<f64> {
        Some(self.0[k]).filter(|x| !x.is_nan())
    }
}

/// A row as read: its shape's text and its inputs, or why it is malformed.
type Read<'a> = std::result::Result<(&'a str, &'a Inputs), &'a str>;

/// One checked row: its shape (an index into [`Shapes`]), conditions and system.
#[derive(Debug, Clone, Copy)]
struct Job {
    shape: u32,
    conditions: Conditions,
    system: Option<fricosc::system::System>,
}

/// A row's answer: `mu_ratio` and `reduction`, and under a transverse
/// oscillation the mean force across the sliding direction, `<f_y>/<B>`.
#[derive(Debug, Clone, Copy, Default)]
pub struct Answer {
    pub ratio: Ratio,
    pub transverse_ratio: Option<f64>,
}

/// How rows are solved: by the stepping peer, or exactly (on a system a curved body's `springs`).
#[derive(Debug, Clone, Copy, Default)]
pub struct Method {
    pub stepping: Option<Stepping>,
    pub springs: Option<usize>,
}

/// The shapes of a batch, each distinct string parsed (and checked) once.
struct Shapes {
    index: HashMap<String, u32>,
    list: Vec<Shape>,
    stepping: Option<Stepping>,
    springs: Option<usize>,
    /// Rows solved, on a terminal's stderr.
    bar: std::sync::Arc<crate::progress::Bar>,
}

impl Shapes {
    fn new(method: Method) -> Shapes {
        let bar = std::sync::Arc::new(crate::progress::Bar::new(None, "batch"));
        Shapes { index: HashMap::new(), list: vec![], stepping: method.stepping, springs: method.springs, bar }
    }

    /// The shapes as they are now, to evaluate rows already checked while
    /// more are read (which may add shapes).
    fn snapshot(&self) -> Shapes {
        let (list, bar) = (self.list.clone(), self.bar.clone());
        Shapes { index: HashMap::new(), list, stepping: self.stepping, springs: self.springs, bar }
    }

    /// A new chunk of a streamed batch begins: the rows of the last one are done.
    fn new_chunk(&mut self) {
        if self.list.len() > MAX_CACHED_SHAPES {
            self.index.clear();
            self.list.clear();
        }
    }

    /// The index of the shape `spec`, parsed (and checked for the method) the first time.
    fn id(&mut self, spec: &str) -> Result<u32> {
        if let Some(&k) = self.index.get(spec) {
            return Ok(k);
        }
        let parsed = crate::input::parse_shape(spec)?;
        if let Some(st) = self.stepping {
            st.check(&parsed)?;
        }
        self.list.push(parsed);
        let k = (self.list.len() - 1) as u32;
        self.index.insert(spec.to_string(), k);
        Ok(k)
    }

    /// A row's inputs into a checked job: the velocity as `vbar` or `vhat`
    /// (one of them; `vbar = vhat/amp`), with `tangential_amp` (which needs
    /// `vhat`) an optional `phase`; the shape must reach the amplitude.
    fn job(&self, shape: u32, i: &Inputs) -> std::result::Result<Job, String> {
        let err = |e: fricosc::Error| e.to_string();
        // The seed's problem, `vbar` and `amp` only: most rows.
        if i.0[2..].iter().all(|x| x.is_nan()) && !i.0[0].is_nan() && !i.0[1].is_nan() {
            let conditions = Conditions::vbar(i.0[0], i.0[1]).map_err(err)?;
            self.list[shape as usize].check_amp(conditions.amp()).map_err(err)?;
            return Ok(Job { shape, conditions, system: None });
        }
        let [vbar, amp, vhat, tangential_amp, phase, kappa, omega, zeta, w, psi] = std::array::from_fn(|k| i.get(k));
        let amp = amp.ok_or("missing field 'amp'")?;
        if phase.is_some() && tangential_amp.is_none() {
            return Err("'phase' needs 'tangential_amp'".into());
        }
        if psi.is_some() && w.is_none() {
            return Err("'transverse_phase' needs 'transverse_amp'".into());
        }
        let conditions = match (vbar, vhat, tangential_amp) {
            (Some(_), Some(_), _) => return Err("give one of 'vbar' and 'vhat', not both".into()),
            (Some(_), None, Some(_)) => {
                return Err(
                    "'tangential_amp' needs the velocity as 'vhat' (vbar = vhat/amp is undefined at amp 0)".into()
                )
            }
            (None, None, _) => return Err("missing field 'vbar' (or 'vhat')".into()),
            (Some(v), None, None) => Conditions::vbar(v, amp).map_err(err)?,
            (None, Some(h), None) => {
                let c = Conditions::vhat(h, amp).map_err(err)?;
                // The plane asks for vhat only: amp = 0 is the transverse oscillation alone.
                if w.is_none() {
                    c.as_vbar().map_err(err)?;
                }
                c
            }
            (None, Some(h), Some(t)) => {
                Conditions::vhat(h, amp).and_then(|c| c.with_tangential(t, phase.unwrap_or(0.0))).map_err(err)?
            }
        };
        // A tabulated profile must reach the deepest indentation (else the
        // evaluation would refuse the row after output had begun).
        self.list[shape as usize].check_amp(amp).map_err(err)?;
        let system = match kappa {
            None if omega.is_some() || zeta.is_some() => {
                return Err("'frequency_ratio' and 'damping' need 'system_stiffness'".into())
            }
            None => None,
            Some(_) if self.stepping.is_some() => return Err("rows on a system are solved exactly only".into()),
            Some(k) => {
                let sys = fricosc::system::System::new(k, omega.unwrap_or(0.0), zeta.unwrap_or(0.0)).map_err(err)?;
                let sys = self.springs.map_or(Ok(sys), |n| sys.with_springs(n)).map_err(err)?;
                if sys.frequency_ratio() == 0.0 && !self.list[shape as usize].is_flat() {
                    return Err("a massless body (frequency_ratio 0) on a curved contact is not solved".into());
                }
                Some(sys)
            }
        };
        let Some(w) = w else { return Ok(Job { shape, conditions, system }) };
        if self.stepping.is_some() {
            return Err("rows in the plane ('transverse_amp') are solved exactly only".into());
        }
        let tw = fricosc::plane::Transverse::new(w, psi.unwrap_or(0.0)).map_err(err)?;
        let conditions = conditions.with_transverse(tw);
        let on = system.map_or(conditions, |sys| conditions.with_system(sys));
        fricosc::plane::check(&self.list[shape as usize], &on).map_err(err)?;
        Ok(Job { shape, conditions, system })
    }

    fn evaluate(&self, j: &Job) -> fricosc::Result<Answer> {
        let shape = &self.list[j.shape as usize];
        let ratio = |ratio| Answer { ratio, transverse_ratio: None };
        match (self.stepping, j.system) {
            (_, Some(sys)) => shape.ratio(&j.conditions.with_system(sys)).map(ratio),
            (None, None) if j.conditions.transverse().is_some() => {
                let e = shape.evaluate(&j.conditions)?;
                Ok(Answer { ratio: e.ratio, transverse_ratio: e.transverse_ratio })
            }
            (Some(st), None) => fricosc::stepper::evaluate(shape, &j.conditions, st).map(|e| ratio(e.ratio)),
            (None, None) => shape.ratio(&j.conditions).map(ratio),
        }
    }

    /// Evaluate `jobs` in parallel; `name(i)` names the row `i` of them in
    /// errors, and the first row at fault (in order) is the one reported.
    fn evaluate_all(&self, jobs: &[Job], source: &str, name: &(dyn Fn(usize) -> String + Sync)) -> Result<Vec<Answer>> {
        let mut out = Vec::with_capacity(jobs.len());
        let filler = Answer::default();
        let each = |_, j: &Job| {
            self.bar.inc(1);
            self.evaluate(j)
        };
        map_into(jobs, filler, &each, &mut out).map_err(|(i, e)| match e {
            fricosc::Error::Internal { what } => Error::Internal { what: format!("{source} {}: {what}", name(i)) },
            e => Error::Parse { context: source.into(), reason: format!("{}: {e}", name(i)) },
        })?;
        Ok(out)
    }

    /// Check one chunk of rows as read (`read(row)`: its shape's text and
    /// inputs, or why it is malformed): their shapes looked up serially (each
    /// distinct string parsed once), their numbers checked in parallel. The
    /// jobs are appended to `jobs`, or the first row at fault (as a serial
    /// reading finds it: its index in the chunk, and why) is returned and
    /// nothing appended.
    fn check<T: Sync>(
        &mut self,
        rows: &[T],
        read: &(dyn Fn(&T) -> Read + Sync),
        jobs: &mut Vec<Job>,
    ) -> std::result::Result<(), (usize, String)> {
        let mut ids = Vec::with_capacity(rows.len());
        let mut fault = None;
        let mut last: Option<(&str, u32)> = None;
        for (j, row) in rows.iter().enumerate() {
            let id = match read(row) {
                Ok((spec, _)) => match last {
                    Some((l, k)) if l == spec => Ok(k),
                    _ => self.id(spec).inspect(|&k| last = Some((spec, k))).map_err(|e| e.to_string()),
                },
                Err(e) => Err(e.to_string()),
            };
            match id {
                Ok(k) => ids.push(k),
                Err(reason) => {
                    fault = Some((j, reason));
                    break;
                }
            }
        }
        let this = &*self;
        let filler =
            Job { shape: 0, conditions: Conditions::vbar(0.0, 0.0).map_err(|e| (0, e.to_string()))?, system: None };
        let job = |j: usize, row: &T| match read(row) {
            Ok((_, inputs)) => this.job(ids[j], inputs),
            Err(e) => Err(e.to_string()),
        };
        map_into(&rows[..ids.len()], filler, &job, jobs)?;
        if let Some(f) = fault {
            jobs.truncate(jobs.len() - ids.len());
            return Err(f);
        }
        Ok(())
    }
}

/// `f(i, item)` over `items` in parallel, appended to `out` in order, or the
/// first item at fault (in order: its index, and why), with `out` as it was.
/// `filler` holds the place of an item at fault until the pass is done.
fn map_into<T: Sync, R: Copy + Send + Sync, E: Send>(
    items: &[T],
    filler: R,
    f: &(impl Fn(usize, &T) -> std::result::Result<R, E> + Sync),
    out: &mut Vec<R>,
) -> std::result::Result<(), (usize, E)> {
    let first: std::sync::Mutex<Option<(usize, E)>> = std::sync::Mutex::new(None);
    let before = out.len();
    out.par_extend(items.par_iter().enumerate().map(|(i, item)| {
        f(i, item).unwrap_or_else(|e| {
            let mut slot = first.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
            if slot.as_ref().is_none_or(|(j, _)| i < *j) {
                *slot = Some((i, e));
            }
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

/// A number of a row's field: `str::parse`'s value of its text, `+ 0.0`
/// (`-0` is 0); anything that is not a number is an error naming the field.
fn number(text: &str, name: &str) -> std::result::Result<f64, String> {
    let t = text.trim();
    // JSON's and CSV's numbers only: `str::parse` also takes "inf" and "NaN".
    let numeric = t.bytes().next().is_some_and(|b| b == b'-' || b == b'+' || b == b'.' || b.is_ascii_digit());
    match t.parse::<f64>() {
        Ok(x) if numeric && x.is_finite() => Ok(x + 0.0),
        _ => Err(format!("'{name}' is not a finite number: '{t}'")),
    }
}

/// Stream a JSON Lines or CSV batch read twice from `input`; `source` names
/// it. Returns the number of rows.
pub fn stream(format: Format, input: &crate::twopass::TwoPass, method: Method, out: &mut dyn Write) -> Result<u64> {
    let open = || input.next_pass();
    match format {
        Format::JsonLines => json_rows::stream_lines(&open, input.source(), method, out),
        Format::Csv => csv_rows::stream_csv(&open, input.source(), method, out),
        Format::Json => Err(Error::Internal { what: "a JSON array is not streamed".into() }),
    }
}

/// A reader of one pass of a streamed input.
type Open<'a> = dyn Fn() -> Result<Box<dyn BufRead>> + 'a;

fn too_many(source: &str, n: u64) -> Error {
    Error::TooLarge { what: format!("rows of batch {source}"), count: n as u128, limit: MAX_STREAM_ROWS as u128 }
}

/// The input's second reading differs from the first (the file was changed).
fn changed(source: &str, what: &str) -> Error {
    Error::Parse { context: source.into(), reason: format!("the input changed while it was read: {what}") }
}

/// The hash of a chunk's bytes, for the second pass's comparison (foldhash:
/// a change of the input between the passes is not adversarial).
fn digest(bytes: &[u8]) -> u64 {
    use std::hash::BuildHasher;
    foldhash::fast::FixedState::with_seed(0).hash_one(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Numbers as JSON and CSV write them, and what `str::parse` would take
    /// that is not a number there.
    #[test]
    fn numbers_are_those_of_json_and_csv() {
        for (t, x) in [("0.5", 0.5f64), ("-0", 0.0), ("1e-5", 1e-5), (" 2 ", 2.0), ("+1", 1.0), (".5", 0.5)] {
            assert_eq!(number(t, "x").map(f64::to_bits), Ok(x.to_bits()), "{t}");
        }
        for t in ["inf", "NaN", "infinity", "1e400", "", "x", "0x10"] {
            assert!(number(t, "vbar").is_err_and(|e| e.contains("'vbar' is not a finite number")), "{t}");
        }
    }

    /// `map_into` appends in order, or reports the first item at fault (of
    /// many, spread over the threads) and leaves `out` as it was.
    #[test]
    fn map_into_keeps_order_and_the_first_fault() {
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

    /// A chunk with a row at fault (its shape, found serially; or its numbers,
    /// found in parallel) is reported at that row and appends nothing.
    #[test]
    fn a_chunk_at_fault_appends_nothing() {
        type Row = std::result::Result<(&'static str, Inputs), &'static str>;
        let row = |shape: &'static str, vbar: f64| -> Row {
            let mut inputs = Inputs::default();
            (inputs.0[0], inputs.0[1]) = (vbar, 1.0);
            Ok((shape, inputs))
        };
        let mut shapes = Shapes::new(Method::default());
        let mut jobs = vec![];
        fn read<'r>(r: &'r Row) -> Read<'r> {
            r.as_ref().map(|(s, i)| (*s, i)).map_err(|e| *e)
        }
        shapes.check(&[row("flat", 0.5), row("flat", 0.2)], &read, &mut jobs).unwrap();
        assert_eq!(jobs.len(), 2);
        for (rows, at) in [
            (vec![row("flat", 0.5), row("flat", 0.5), row("nope", 0.5)], 2),
            (vec![row("flat", 0.5), row("flat", -1.0), row("nope", 0.5)], 1),
            (vec![row("flat", 0.5), Err("malformed"), row("flat", -1.0)], 1),
        ] {
            let fault = shapes.check(&rows, &read, &mut jobs).unwrap_err();
            assert_eq!(fault.0, at, "{fault:?}");
            assert_eq!(jobs.len(), 2);
        }
    }
}

#[derive(clap::Args)]
pub struct BatchArgs {
    /// Input file; stdin when absent or '-'.
    pub file: Option<String>,
    /// Input and output format: json (an array), jsonl (one object per line, streamed) or csv
    /// (streamed); default: by the file's extension (.jsonl, .ndjson, .csv), else json.
    #[arg(long)]
    pub format: Option<String>,
    #[command(flatten)]
    pub method: crate::cmd::MethodArgs,
}

pub fn run(a: BatchArgs) -> Result<()> {
    // --springs serves the rows on a system with the exact method.
    let method = Method { stepping: a.method.stepping_with(true)?, springs: a.method.system_springs() };
    let (file, format) = (a.file, a.format);
    let path = file.clone().unwrap_or_else(|| "-".into());
    match Format::choose(format.as_deref(), &path)? {
        Format::Json => {
            let (text, source) = read_input(file)?;
            let rows = evaluate(&text, &source, method)?;
            let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
            rows.write(&mut out).and_then(|()| out.flush()).map_err(io_err)
        }
        streamed => {
            // Streaming reads its input twice (check, then compute and write),
            // the second time exactly the bytes the first one checked; an input
            // of one chunk (65,536 rows) once.
            let input = crate::twopass::TwoPass::open(&path)?;
            let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
            stream(streamed, &input, method, &mut out).map(|_| ())
        }
    }
}
