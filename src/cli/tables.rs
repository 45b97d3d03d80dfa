//! Reading the tables people write, for `validate` (tables and histories) and
//! `plot --overlay`: named columns, from
//! - CSV as spreadsheets, pandas and numpy write it: a header line, or numpy's
//!   commented header (`np.savetxt(..., header="vbar,amp,mu_ratio")` writes
//!   `# vbar,amp,mu_ratio`: the last comment line before the data names the
//!   columns when the first line is numbers); the delimiter found from the
//!   header (`,`, `;`, tab, else whitespace, numpy's default); other `#` lines
//!   are comments;
//! - JSON as fricosc writes it (`{"shape": ..., "rows": [...]}`) and as pandas
//!   does, in every orient that names the columns: `records` (an array of row
//!   objects), `columns` (pandas' default: `{column: {index: value}}`),
//!   `index` (`{index: {column: value}}`), `split` (`columns` and `data`) and
//!   `table` (`schema` and `data`); the `values` orient (no names) is refused
//!   with the orient to use;
//! - JSON Lines (one row object a line, pandas' `lines=True`).
//!
//! JSON is read as raw values ([`crate::json`]: no value trees, a column is
//! a vector of numbers, 8 bytes a row). Every refusal names the file, the row
//! and what was expected.

use crate::error::{Error, Result};
use crate::json;
use serde_json::value::RawValue;
use std::borrow::Cow;

/// What a wanted column holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Finite numbers.
    Number,
    /// A computed value: a number, or one that is not finite (`nan`, `inf`,
    /// a JSON null) where the computation diverged.
    Value,
    /// Text (a shape name): only its distinct values are kept.
    Label,
}

/// The wanted columns of a table as read.
#[derive(Debug, Clone, PartialEq)]
pub struct Columns {
    /// How the file was read (for messages): e.g. "CSV (';')", "pandas 'columns' JSON".
    pub format: String,
    /// Every column of the file, in its order.
    pub names: Vec<String>,
    /// Per wanted column: its numbers, if present (and a number column).
    pub numbers: Vec<Option<Vec<f64>>>,
    /// Per wanted column: its distinct values, if present (and a label column).
    pub labels: Vec<Option<Vec<String>>>,
    /// Rows read.
    pub rows: usize,
    /// Each row's line in the file, as an editor counts them (CSV; empty for JSON).
    pub lines: Vec<u64>,
}

impl Columns {
    fn new(format: &str, wanted: usize) -> Columns {
        Columns {
            format: format.into(),
            names: vec![],
            numbers: vec![None; wanted],
            labels: vec![None; wanted],
            rows: 0,
            lines: vec![],
        }
    }

    /// True if wanted column `k` is present.
    pub fn has(&self, k: usize) -> bool {
        self.numbers[k].is_some() || self.labels[k].is_some()
    }
}

/// The wanted columns of `text` (`source` names it in errors; `max_rows` caps the rows).
pub fn read_columns(text: &str, source: &str, wanted: &[(&str, Kind)], max_rows: usize) -> Result<Columns> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let err = |reason: String| Error::Parse { context: source.into(), reason };
    let mut cols = match text.trim_start().chars().next() {
        None => return Err(err("empty input".into())),
        Some('[' | '{') => Json { text, wanted, max_rows, source }.read()?,
        Some(_) => read_csv(text, source, wanted, max_rows)?,
    };
    if cols.rows == 0 {
        return Err(err(format!("the table has no rows ({}; nothing to compare)", cols.format)));
    }
    for (k, (name, _)) in wanted.iter().enumerate() {
        if let Some(v) = &cols.numbers[k] {
            if v.len() != cols.rows {
                return Err(err(format!("column '{name}' has {} values for {} rows", v.len(), cols.rows)));
            }
        }
    }
    cols.names.dedup();
    Ok(cols)
}

fn too_many(source: &str, limit: usize) -> Error {
    Error::TooLarge { what: format!("rows of {source}"), count: limit as u128 + 1, limit: limit as u128 }
}

/// Add one raw cell to wanted column `k`.
fn push(cols: &mut Columns, k: usize, kind: Kind, value: Cell) -> std::result::Result<(), String> {
    match (kind, value) {
        (Kind::Number | Kind::Value, Cell::Number(x)) => cols.numbers[k].get_or_insert_with(Vec::new).push(x),
        (Kind::Label, Cell::Text(s)) => {
            let l = cols.labels[k].get_or_insert_with(Vec::new);
            if !l.iter().any(|x| *x == s) {
                l.push(s.into_owned());
            }
        }
        _ => return Err("internal: a cell of the wrong kind".into()),
    }
    Ok(())
}

enum Cell<'a> {
    Number(f64),
    Text(Cow<'a, str>),
}

// ----------------------------------------------------------------------------- CSV

/// The delimiter of a header line: the most frequent of `,`, `;` and tab
/// outside quotes; none (whitespace-separated) if it has none of them.
fn sniff(line: &str) -> Option<u8> {
    let (mut quoted, mut counts) = (false, [0usize; 3]);
    for b in line.bytes() {
        match b {
            b'"' => quoted = !quoted,
            b',' if !quoted => counts[0] += 1,
            b';' if !quoted => counts[1] += 1,
            b'\t' if !quoted => counts[2] += 1,
            _ => {}
        }
    }
    let (k, &n) = counts.iter().enumerate().max_by_key(|&(k, n)| (*n, std::cmp::Reverse(k)))?;
    (n > 0).then_some([b',', b';', b'\t'][k])
}

/// The fields of one line with `delimiter` (quotes as CSV has them), or split on whitespace.
fn fields(line: &str, delimiter: Option<u8>) -> std::result::Result<Vec<String>, String> {
    match delimiter {
        None => Ok(line.split_whitespace().map(str::to_string).collect()),
        Some(d) => {
            let mut rd = csv::ReaderBuilder::new()
                .delimiter(d)
                .has_headers(false)
                .trim(csv::Trim::All)
                .from_reader(line.as_bytes());
            match rd.records().next() {
                Some(Ok(r)) => Ok(r.iter().map(str::to_string).collect()),
                Some(Err(e)) => Err(e.to_string()),
                None => Ok(vec![]),
            }
        }
    }
}

fn delimiter_name(d: Option<u8>) -> &'static str {
    match d {
        Some(b',') => "','",
        Some(b';') => "';'",
        Some(b'\t') => "tab",
        _ => "whitespace",
    }
}

/// The first line of `text` that is neither blank nor a comment (trimmed,
/// with its byte offset), and the last comment before it.
fn first_line_of(text: &str) -> (Option<&str>, Option<(&str, usize)>) {
    let (mut offset, mut last_comment) = (0usize, None::<&str>);
    for line in text.split_inclusive('\n') {
        let t = line.trim();
        if t.starts_with('#') {
            last_comment = Some(t.trim_start_matches('#').trim());
        } else if !t.is_empty() {
            return (last_comment, Some((t, offset)));
        }
        offset += line.len();
    }
    (last_comment, None)
}

fn read_csv(text: &str, source: &str, wanted: &[(&str, Kind)], max_rows: usize) -> Result<Columns> {
    let err = |reason: String| Error::Parse { context: source.into(), reason };
    let (last_comment, first) = first_line_of(text);
    let (first, first_at) = first.ok_or_else(|| err("the table has no rows (only comments or blank lines)".into()))?;
    let numeric = |line: &str, d: Option<u8>| {
        fields(line, d).is_ok_and(|f| !f.is_empty() && f.iter().all(|x| crate::grid::number(x).is_ok()))
    };
    // numpy's header is a comment above rows of numbers.
    let (header_line, data_at) = match last_comment {
        Some(c) if numeric(first, sniff(first)) && !c.is_empty() => (c, first_at),
        _ if numeric(first, sniff(first)) => {
            let names: Vec<&str> = wanted.iter().map(|w| w.0).collect();
            return Err(err(format!(
                "no header line: the first line is numbers; name the columns ({}) in a first line, or as numpy \
                 writes them: np.savetxt(file, rows, header='{}', delimiter=',')",
                names.join(", "),
                names.join(",")
            )));
        }
        _ => (first, first_at + text[first_at..].find('\n').map_or(text.len() - first_at, |n| n + 1)),
    };
    let delimiter = sniff(header_line);
    let header = fields(header_line, delimiter).map_err(|e| err(format!("CSV header: {e}")))?;
    for (k, h) in header.iter().enumerate() {
        if header[..k].contains(h) {
            return Err(err(format!("the header has column '{h}' twice")));
        }
    }
    let mut cols = Columns::new(&format!("CSV ({} delimited)", delimiter_name(delimiter)), wanted.len());
    cols.names = header.clone();
    let at: Vec<Option<usize>> = wanted.iter().map(|(w, _)| header.iter().position(|h| h == w)).collect();
    let body = &text[data_at.min(text.len())..];
    // The line of the body's first character (1-based).
    let first_line = 1 + text[..data_at.min(text.len())].matches('\n').count() as u64;
    let mut each = |i: usize, rec: &[&str], line: u64| -> Result<()> {
        cols.lines.push(line);
        if rec.len() != header.len() {
            return Err(err(format!(
                "row {i}: {} fields, the header has {} ({}; read as {} delimited)",
                rec.len(),
                header.len(),
                header.join(", "),
                delimiter_name(delimiter)
            )));
        }
        for (k, (name, kind)) in wanted.iter().enumerate() {
            let Some(c) = at[k] else { continue };
            let cell = match kind {
                Kind::Number => Cell::Number(crate::grid::number(rec[c]).map_err(|e| {
                    let hint = if rec[c].contains(',') && delimiter != Some(b',') {
                        " (decimal commas are not read: write numbers with '.')"
                    } else {
                        ""
                    };
                    err(format!("row {i}: {name}: {e}{hint}"))
                })?),
                Kind::Value => Cell::Number(json::computed(rec[c]).map_err(|e| err(format!("row {i}: {name}: {e}")))?),
                Kind::Label => Cell::Text(Cow::Borrowed(rec[c])),
            };
            push(&mut cols, k, *kind, cell).map_err(|e| Error::Internal { what: e })?;
        }
        cols.rows += 1;
        if cols.rows > max_rows {
            return Err(too_many(source, max_rows));
        }
        Ok(())
    };
    match delimiter {
        None => {
            let lines = body.lines().map(str::trim).zip(first_line..);
            for (i, (line, at)) in lines.filter(|(l, _)| !l.is_empty() && !l.starts_with('#')).enumerate() {
                each(i, &line.split_whitespace().collect::<Vec<_>>(), at)?;
            }
        }
        Some(d) => {
            let mut rd = csv::ReaderBuilder::new()
                .delimiter(d)
                .has_headers(false)
                .flexible(true)
                .comment(Some(b'#'))
                .trim(csv::Trim::All)
                .from_reader(body.as_bytes());
            for (i, rec) in rd.records().enumerate() {
                let rec = rec.map_err(|e| err(format!("row {i}: {e}")))?;
                let at = first_line + rec.position().map_or(0, |p| p.line() - 1);
                each(i, &rec.iter().collect::<Vec<_>>(), at)?;
            }
        }
    }
    Ok(cols)
}

// ---------------------------------------------------------------------------- JSON

struct Json<'a, 'w> {
    text: &'a str,
    wanted: &'w [(&'w str, Kind)],
    max_rows: usize,
    source: &'a str,
}

const ORIENTS: &str = "a JSON table is an array of row objects, an object with a 'rows' array (as fricosc writes \
                       it), JSON Lines, or pandas' to_json in an orient that names the columns: 'columns' (the \
                       default), 'records', 'index', 'split' or 'table'";

impl<'a> Json<'a, '_> {
    fn err(&self, reason: String) -> Error {
        Error::Parse { context: self.source.into(), reason }
    }

    fn cell(&self, raw: &'a RawValue, name: &str, kind: Kind) -> std::result::Result<Cell<'a>, String> {
        Ok(match kind {
            Kind::Number => Cell::Number(json::number(raw, name)?),
            Kind::Value if raw.get() == "null" => Cell::Number(f64::NAN),
            Kind::Value => Cell::Number(json::computed(raw.get()).map_err(|e| format!("'{name}': {e}"))?),
            Kind::Label => Cell::Text(json::string(raw, name)?),
        })
    }

    fn read(&self) -> Result<Columns> {
        let t = self.text;
        let top = match json::value(t) {
            Ok(v) => v.get(),
            // More than one value: JSON Lines, one row object a line.
            Err(e) if e.is_syntax() && e.to_string().starts_with("trailing characters") => return self.lines(),
            Err(e) => return Err(self.err(json::message(&e))),
        };
        if top.starts_with('[') {
            return self.array(top, "JSON array of rows");
        }
        let top = json::members(top).map_err(|e| self.err(e))?;
        let key = |k: &str| top.iter().find(|(x, _)| x == k).map(|(_, v)| *v);
        let is_wanted = |k: &str| self.wanted.iter().any(|(w, _)| *w == k);
        if let Some(rows) = key("rows") {
            let mut cols = self.array(rows.get(), "fricosc JSON ('rows')")?;
            if let (Some(v), Some(k)) = (key("shape"), self.wanted.iter().position(|(w, _)| *w == "shape")) {
                let s = json::string(v, "shape").map_err(|e| self.err(e))?;
                push(&mut cols, k, Kind::Label, Cell::Text(s)).map_err(|e| Error::Internal { what: e })?;
            }
            return Ok(cols);
        }
        if let (Some(columns), Some(data)) = (key("columns"), key("data")) {
            return self.split(columns, data);
        }
        if let (Some(_), Some(data)) = (key("schema"), key("data")) {
            return self.array(data.get(), "pandas 'table' JSON");
        }
        if !top.is_empty() && top.iter().all(|(_, v)| v.get().starts_with('{')) {
            if top.iter().any(|(k, _)| is_wanted(k)) {
                return self.columns(&top);
            }
            return self.index(&top);
        }
        let keys: Vec<&str> = top.iter().map(|(k, _)| k.as_ref()).take(8).collect();
        Err(self.err(format!("{ORIENTS}; this object has the keys {}", keys.join(", "))))
    }

    /// Rows from one row object (its wanted fields; `k` its index).
    fn record(&self, cols: &mut Columns, k: usize, fields: &[Option<&'a RawValue>]) -> std::result::Result<(), String> {
        for (j, (name, kind)) in self.wanted.iter().enumerate() {
            match fields[j] {
                Some(raw) => {
                    if k > 0 && !cols.has(j) {
                        return Err(format!("field '{name}' is not in the rows before"));
                    }
                    let c = self.cell(raw, name, *kind)?;
                    push(cols, j, *kind, c)?;
                }
                None if cols.has(j) => return Err(format!("missing field '{name}'")),
                None => {}
            }
        }
        cols.rows += 1;
        Ok(())
    }

    /// [`Error::TooLarge`] once `rows` reach the cap (checked before each row).
    fn full(&self, rows: usize) -> Result<()> {
        if rows >= self.max_rows {
            return Err(too_many(self.source, self.max_rows));
        }
        Ok(())
    }

    /// The wanted fields of the members of a row object.
    fn fields(&self, members: &json::Members<'a>) -> Vec<Option<&'a RawValue>> {
        self.wanted.iter().map(|(w, _)| members.iter().find(|(k, _)| k == w).map(|(_, v)| *v)).collect()
    }

    /// One row object of an array, `k` its index.
    fn row(&self, cols: &mut Columns, k: usize, v: &'a RawValue) -> std::result::Result<(), String> {
        match v.get().as_bytes()[0] {
            b'{' => {
                let members = json::members(v.get())?;
                if k == 0 {
                    cols.names = members.iter().map(|(k, _)| k.to_string()).collect();
                }
                self.record(cols, k, &self.fields(&members))
            }
            b'[' => Err("an array of arrays has no column names (pandas' orient 'values'): write \
                         to_json(orient='records') or orient='split'"
                .into()),
            _ => Err("expected a row object".into()),
        }
    }

    /// An array of row objects, `text` its JSON.
    fn array(&self, text: &'a str, format: &str) -> Result<Columns> {
        let mut cols = Columns::new(format, self.wanted.len());
        let rows = json::elements(text).map_err(|e| self.err(e))?;
        for (k, v) in rows.into_iter().enumerate() {
            self.full(cols.rows)?;
            self.row(&mut cols, k, v).map_err(|e| self.err(format!("row {k}: {e}")))?;
        }
        Ok(cols)
    }

    /// JSON Lines: one row object a line (blank lines skipped).
    fn lines(&self) -> Result<Columns> {
        let mut cols = Columns::new("JSON Lines", self.wanted.len());
        let mut k = 0usize;
        for (n, line) in self.text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let at = |e: String| self.err(format!("line {}: {e}", n + 1));
            let v = json::value(line).map_err(|e| {
                if e.to_string().starts_with("trailing characters") {
                    at("one row object a line (JSON Lines): trailing characters".into())
                } else {
                    at(json::message(&e))
                }
            })?;
            if !v.get().starts_with('{') {
                return Err(at("expected a row object (JSON Lines: one object a line)".into()));
            }
            self.full(cols.rows)?;
            self.row(&mut cols, k, v).map_err(at)?;
            k += 1;
        }
        Ok(cols)
    }

    /// pandas' `columns` orient: `{column: {index: value}}`, every column with
    /// the same index labels in the same order.
    fn columns(&self, top: &json::Members<'a>) -> Result<Columns> {
        let mut cols = Columns::new("pandas 'columns' JSON", self.wanted.len());
        cols.names = top.iter().map(|(k, _)| k.to_string()).collect();
        let mut index: Option<Vec<Cow<str>>> = None;
        for (j, (name, kind)) in self.wanted.iter().enumerate() {
            let Some((_, column)) = top.iter().find(|(k, _)| k == name) else { continue };
            let members = json::members(column.get()).map_err(|e| self.err(format!("column '{name}': {e}")))?;
            for (n, (label, v)) in members.iter().enumerate() {
                self.full(n)?;
                self.cell(v, name, *kind)
                    .and_then(|c| push(&mut cols, j, *kind, c))
                    .map_err(|e| self.err(format!("column '{name}', index '{label}': {e}")))?;
                if index.as_ref().is_some_and(|x| x.get(n) != Some(label)) {
                    return Err(self.err(format!("column '{name}': its index labels differ from the columns before")));
                }
            }
            match &index {
                None => index = Some(members.into_iter().map(|(l, _)| l).collect()),
                Some(x) if x.len() != members.len() => {
                    return Err(self.err(format!(
                        "column '{name}' has {} values, the columns before {}",
                        members.len(),
                        x.len()
                    )))
                }
                Some(_) => {}
            }
        }
        cols.rows = index.map_or(0, |x| x.len());
        Ok(cols)
    }

    /// pandas' `index` orient: `{index: {column: value}}`.
    fn index(&self, top: &json::Members<'a>) -> Result<Columns> {
        let mut cols = Columns::new("pandas 'index' JSON", self.wanted.len());
        for (k, (label, v)) in top.iter().enumerate() {
            self.full(cols.rows)?;
            self.row(&mut cols, k, v).map_err(|e| self.err(format!("index '{label}': {e}")))?;
        }
        if self.wanted.iter().enumerate().all(|(j, _)| !cols.has(j)) {
            let names: Vec<&str> = top.iter().map(|(k, _)| k.as_ref()).take(8).collect();
            return Err(self.err(format!(
                "{ORIENTS}; this object's keys ({}) are neither wanted columns nor index labels of rows that have them",
                names.join(", ")
            )));
        }
        Ok(cols)
    }

    /// pandas' `split` orient: `{"columns": [...], "index": [...], "data": [[...], ...]}`.
    fn split(&self, columns: &'a RawValue, data: &'a RawValue) -> Result<Columns> {
        let mut cols = Columns::new("pandas 'split' JSON", self.wanted.len());
        let names = json::elements(columns.get())
            .and_then(|v| v.iter().map(|n| json::string(n, "columns").map(Cow::into_owned)).collect())
            .map_err(|e: String| self.err(e))?;
        cols.names = names;
        let at: Vec<Option<usize>> = self.wanted.iter().map(|(w, _)| cols.names.iter().position(|n| n == w)).collect();
        let rows = json::elements(data.get()).map_err(|e| self.err(e))?;
        for (k, row) in rows.into_iter().enumerate() {
            self.full(cols.rows)?;
            let cells = json::elements(row.get()).map_err(|e| self.err(format!("row {k}: {e}")))?;
            let fields: Vec<Option<&RawValue>> = at.iter().map(|c| c.and_then(|c| cells.get(c)).copied()).collect();
            let r = if cells.len() != cols.names.len() {
                Err(format!("{} values, the columns are {}", cells.len(), cols.names.len()))
            } else {
                self.record(&mut cols, k, &fields)
            };
            r.map_err(|e| self.err(format!("row {k}: {e}")))?;
        }
        Ok(cols)
    }
}
