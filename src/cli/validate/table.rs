//! `validate`: read another code's table or history and compare it with the
//! exact solver ([`fricosc::validation`]); the reports (summary, JSON, CSV).
//!
//! A table has the columns `vbar` or `vhat` (eq. 15, `vbar = vhat / amp`),
//! `amp`, and `mu_ratio` or `mu` (then `mu_ratio = mu / mu0`, `--mu0`
//! required), optionally `shape` (one for the whole table); any file
//! [`crate::tables`] reads (CSV as numpy, pandas or a spreadsheet writes
//! it, fricosc's or pandas' JSON, JSON Lines). Other columns are listed as not read.

use crate::error::{Error, Result};
use crate::tables::{read_columns, Kind};
use fricosc::validation::{rows_from_columns, AtRest, Finding, Summary, Validation};

/// Most rows one file may hold.
pub const MAX_ROWS: usize = crate::grid::MAX_ROWS;

/// One row as read: the velocity column (`vbar` or `vhat`) and the friction
/// column (`mu_ratio` or `mu`) as the file names them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RawRow {
    /// `vbar`, or `vhat` if [`RawTable::vhat`].
    pub velocity: f64,
    /// Amplitude `du/u0`.
    pub amp: f64,
    /// `mu_ratio`, or `mu` if [`RawTable::mu`].
    pub friction: f64,
}

/// A table as read.
#[derive(Debug, Clone, PartialEq)]
pub struct RawTable {
    /// The shape the file names (one for the whole table), if any.
    pub shape: Option<String>,
    /// True if the velocities are `vhat`.
    pub vhat: bool,
    /// True if the friction column is `mu` (not divided by `mu0`).
    pub mu: bool,
    /// The rows.
    pub rows: Vec<RawRow>,
    /// Columns that are not read.
    pub ignored_columns: Vec<String>,
    /// How the file was read ("CSV (',' delimited)", "pandas 'columns' JSON", ...).
    pub format: String,
    /// Under oscillation in the sliding direction: `(tangential_amp, phase)`
    /// of every row (a missing `phase` column is 0).
    pub tangential: Option<Vec<(f64, f64)>>,
}

const TABLE_COLUMNS: [(&str, Kind); 8] = [
    ("vbar", Kind::Number),
    ("vhat", Kind::Number),
    ("amp", Kind::Number),
    ("mu_ratio", Kind::Number),
    ("mu", Kind::Number),
    ("shape", Kind::Label),
    ("tangential_amp", Kind::Number),
    ("phase", Kind::Number),
];

/// Which of two alternative columns is present (exactly one must be): the second's?
fn one_of(c: &crate::tables::Columns, k: [usize; 2], what: &str) -> std::result::Result<bool, String> {
    let [a, b] = k.map(|k| TABLE_COLUMNS[k].0);
    match (c.has(k[0]), c.has(k[1])) {
        (true, false) => Ok(false),
        (false, true) => Ok(true),
        (true, true) => Err(format!("both '{a}' and '{b}' given: one {what} column only")),
        (false, false) => Err(format!(
            "no column '{a}' (or '{b}'): a table needs vbar (or vhat), amp and mu_ratio (or mu); this one \
             ({}) has {}",
            c.format,
            if c.names.is_empty() { "no names".to_string() } else { c.names.join(", ") }
        )),
    }
}

/// Read a table (any format of [`crate::tables`]); `source` names it in
/// errors. Every row is read and checked before anything is compared.
pub fn read_table(text: &str, source: &str) -> Result<RawTable> {
    let err = |reason: String| Error::Parse { context: source.into(), reason };
    let mut c = read_columns(text, source, &TABLE_COLUMNS, MAX_ROWS)?;
    let vhat = one_of(&c, [0, 1], "velocity").map_err(err)?;
    let mu = one_of(&c, [3, 4], "friction").map_err(err)?;
    let amp = c.numbers[2]
        .take()
        .ok_or_else(|| err(format!("no column 'amp'; this table ({}) has {}", c.format, c.names.join(", "))))?;
    let velocity = c.numbers[usize::from(vhat)].take().unwrap_or_default();
    let friction = c.numbers[3 + usize::from(mu)].take().unwrap_or_default();
    let mut shapes = c.labels[5].take().unwrap_or_default();
    if shapes.len() > 1 {
        return Err(err(format!(
            "the table names more than one shape ({}): validate one shape at a time",
            shapes.iter().map(|s| format!("'{s}'")).collect::<Vec<_>>().join(", ")
        )));
    }
    let tangential = match (c.numbers[6].take(), c.numbers[7].take()) {
        (None, Some(_)) => return Err(err("a column 'phase' without 'tangential_amp'".into())),
        (None, None) => None,
        (Some(_), _) if !vhat => {
            return Err(err(
                "a table with 'tangential_amp' needs its velocities as 'vhat' (vbar = vhat/amp is undefined \
                 without normal oscillation)"
                    .into(),
            ))
        }
        (Some(t), p) => Some(t.iter().enumerate().map(|(i, &t)| (t, p.as_ref().map_or(0.0, |p| p[i]))).collect()),
    };
    let read = [
        if vhat { "vhat" } else { "vbar" },
        "amp",
        if mu { "mu" } else { "mu_ratio" },
        "shape",
        "tangential_amp",
        "phase",
    ];
    let ignored_columns = c.names.iter().filter(|h| !read.contains(&h.as_str())).cloned().collect();
    let rows = (0..c.rows).map(|i| RawRow { velocity: velocity[i], amp: amp[i], friction: friction[i] }).collect();
    Ok(RawTable { shape: shapes.pop(), vhat, mu, rows, ignored_columns, format: c.format, tangential })
}

/// `(vbar, amp, mu_ratio)` of every row ([`fricosc::validation::rows_from_columns`]).
pub fn normalise(table: &RawTable, mu0: Option<f64>, source: &str) -> Result<Vec<(f64, f64, f64)>> {
    if table.tangential.is_some() {
        return Err(Error::Parse {
            context: source.into(),
            reason: "a table under oscillation in the sliding direction (column 'tangential_amp'): only a \
                     single table's validate compares it"
                .into(),
        });
    }
    let v: Vec<f64> = table.rows.iter().map(|r| r.velocity).collect();
    let a: Vec<f64> = table.rows.iter().map(|r| r.amp).collect();
    let m: Vec<f64> = table.rows.iter().map(|r| r.friction).collect();
    rows_from_columns(&v, &a, &m, table.vhat, table.mu, mu0)
        .map_err(|e| Error::Parse { context: source.into(), reason: e.to_string() })
}

/// `[vhat, amp, tangential_amp, phase, mu_ratio]` of a table under
/// oscillation in the sliding direction (`mu / mu0` where the column is `mu`).
pub fn oscillation_rows(table: &RawTable, mu0: Option<f64>, source: &str) -> Result<Vec<[f64; 5]>> {
    let bad = |reason: &str| Error::Parse { context: source.into(), reason: reason.into() };
    let tangential = table.tangential.as_ref().ok_or_else(|| bad("no column 'tangential_amp'"))?;
    let scale = match (table.mu, mu0) {
        (true, Some(m)) => m,
        (true, None) => return Err(bad("the column 'mu' needs --mu0 (mu_ratio = mu / mu0)")),
        (false, Some(_)) => return Err(bad("--mu0 applies to a column 'mu'; this table has 'mu_ratio'")),
        (false, None) => 1.0,
    };
    Ok(table.rows.iter().zip(tangential).map(|(r, &(t, p))| [r.velocity, r.amp, t, p, r.friction / scale]).collect())
}

/// The summary of an oscillation table's comparison.
pub fn oscillation_summary(v: &fricosc::validation::OscillationValidation, source: &str) -> String {
    use std::fmt::Write;
    let s = &v.summary;
    let mut out = format!(
        "{source}: {} rows of {} under oscillation in the sliding direction\n\
         largest error {:.3e} (row {}), rms {:.3e}, largest relative {:.3e}\n",
        s.n, v.shape, s.max_abs_error, s.worst_row, s.rms_error, s.max_rel_error
    );
    if let Some(p) = &v.peer {
        let _ = writeln!(
            out,
            "stepping peer ({} steps a period, {} springs): largest error {:.3e}, rms {:.3e}",
            p.steps_per_period, p.springs, p.max_abs_error, p.rms_error
        );
    }
    out.push_str("by regime:\n");
    for r in &v.by_regime {
        let _ = writeln!(
            out,
            "  {:>5} rows  largest {:.3e}  rms {:.3e}  {}",
            r.summary.n, r.summary.max_abs_error, r.summary.rms_error, r.regime
        );
    }
    if v.findings.is_empty() {
        out.push_str("findings: none\n");
    }
    for f in &v.findings {
        let _ = writeln!(out, "finding: {} ({} rows, first {:?}): {}", json_name(f.kind), f.count, f.rows, f.hint);
    }
    out
}

/// Every compared row of an oscillation table as CSV.
pub fn oscillation_csv(v: &fricosc::validation::OscillationValidation) -> Result<String> {
    let n = crate::output::num;
    let header =
        ["row", "vhat", "amp", "tangential_amp", "phase", "mu_ratio", "exact", "error", "relative_error", "regime"];
    let rows = v.rows.iter().map(|r| {
        let cells = vec![
            r.row.to_string(),
            n(r.vhat),
            n(r.amp),
            n(r.tangential_amp),
            n(r.phase),
            n(r.mu_ratio),
            n(r.exact),
            n(r.error),
            r.relative_error.map(n).unwrap_or_default(),
            r.regime.clone(),
        ];
        (cells, r.peer_error)
    });
    compared_csv(&header, v.peer.is_some(), rows)
}

/// CSV of compared rows: `header`, then each row's cells, with a
/// `peer_error` column where the comparison ran the peer.
fn compared_csv(header: &[&str], peer: bool, rows: impl Iterator<Item = (Vec<String>, Option<f64>)>) -> Result<String> {
    let mut head: Vec<String> = header.iter().map(|h| h.to_string()).collect();
    if peer {
        head.push("peer_error".into());
    }
    let mut records = vec![head];
    for (mut cells, p) in rows {
        if peer {
            cells.push(p.map(crate::output::num).unwrap_or_default());
        }
        records.push(cells);
    }
    csv_text(&records)
}

/// A name as JSON writes it.
pub(crate) fn json_name<T: serde::Serialize>(x: T) -> String {
    serde_json::to_value(x).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
}

/// Text of a CSV writer's records (or an internal error).
pub(crate) fn csv_text(records: &[Vec<String>]) -> Result<String> {
    let fail = |e: String| Error::Internal { what: format!("writing CSV: {e}") };
    let mut w = csv::Writer::from_writer(vec![]);
    for r in records {
        w.write_record(r).map_err(|e| fail(e.to_string()))?;
    }
    let bytes = w.into_inner().map_err(|e| fail(e.to_string()))?;
    String::from_utf8(bytes).map_err(|e| fail(e.to_string()))
}

/// Every compared row as CSV (one header line).
pub fn rows_csv(v: &Validation) -> Result<String> {
    let n = crate::output::num;
    let header = ["row", "vbar", "amp", "mu_ratio", "exact", "error", "relative_error", "regime", "jumping_share"];
    let rows = v.rows.iter().map(|r| {
        let cells = vec![
            r.row.to_string(),
            n(r.vbar),
            n(r.amp),
            n(r.mu_ratio),
            n(r.exact),
            n(r.error),
            r.relative_error.map(n).unwrap_or_default(),
            json_name(r.regime),
            n(r.jumping_share),
        ];
        (cells, r.peer_error)
    });
    compared_csv(&header, v.peer.is_some(), rows)
}

/// Words wrapped to lines of at most `width` characters, the first prefixed by
/// `first` and the rest indented as deep.
pub(super) fn wrap(first: &str, text: &str, width: usize) -> String {
    let indent = " ".repeat(first.chars().count());
    let mut out = String::new();
    let mut line = first.to_string();
    for word in text.split_whitespace() {
        if line.chars().count() + 1 + word.chars().count() > width && !line.trim().is_empty() && line != first {
            out.push_str(line.trim_end());
            out.push('\n');
            line = indent.clone();
        } else if !line.ends_with(' ') && !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    out.push_str(line.trim_end());
    out.push('\n');
    out
}

/// `n noun`, with the plural where `n != 1`.
pub(crate) fn count(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

/// A regime's label: its name, and for a curved contact the share of the load
/// on springs that lose contact ("mixed: 38 % jumping", or a range).
pub(crate) fn regime_label(regime: fricosc::report::ContactRegime, share: [f64; 2]) -> String {
    use fricosc::report::ContactRegime::{Jumping, Mixed};
    let pct = |x: f64| format!("{:.0}", 100.0 * x);
    match regime {
        Mixed if pct(share[0]) == pct(share[1]) => format!("mixed: {} % jumping", pct(share[0])),
        Mixed => format!("mixed: {}-{} % jumping", pct(share[0]), pct(share[1])),
        Jumping => "jumping: 100 %".into(),
        r => r.name().into(),
    }
}

/// Findings as a list for a person, after a blank line: none, or each with its rows and hint.
pub(crate) fn findings_text(title: &str, findings: &[Finding], none: &str, row_noun: &str) -> String {
    if findings.is_empty() {
        return format!("\n{title}: {none}.\n");
    }
    let mut s = format!("\n{title}:\n");
    for f in findings {
        let rows = f.rows.iter().map(|r| r.to_string()).collect::<Vec<_>>().join(", ");
        let more = if f.count > f.rows.len() { ", ..." } else { "" };
        let which =
            if f.rows.is_empty() { String::new() } else { format!("{} ({rows}{more}): ", count(f.count, row_noun)) };
        s += &wrap("- ", &format!("{}: {which}{}", json_name(f.kind), f.hint), 100);
    }
    s
}

/// A table of error summaries, one line per group, after a blank line.
fn summary_table<'a>(title: &str, groups: impl Iterator<Item = (String, &'a Summary)>) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let mut s = format!(
        "\n{:<22}{:>8}{:>14}{:>12}{:>16}{:>11}\n",
        title, "rows", "max |error|", "rms error", "max rel error", "worst row"
    );
    for (name, m) in groups {
        s += &format!(
            "{:<22}{:>8}{:>14}{:>12}{:>16}{:>11}\n",
            name,
            m.n,
            e(m.max_abs_error),
            e(m.rms_error),
            e(m.max_rel_error),
            m.worst_row
        );
    }
    s
}

/// A short report for a person (lines of at most 100 characters).
pub fn summary(v: &Validation, shape_source: &str, table: &RawTable) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let w = &v.worst;
    let at_rest = match v.at_rest {
        AtRest::Sliding => "the sliding limit vbar -> 0+ (mu_static; --at-rest relaxed for a relaxed start)",
        AtRest::Relaxed => "a relaxed start (0; --at-rest sliding for the limit vbar -> 0+)",
    };
    let mut s = String::new();
    s += &wrap(
        "",
        &format!(
            "fricosc validate: {} of shape {} ({shape_source}), read as {}.",
            count(v.n, "row"),
            v.shape,
            table.format
        ),
        100,
    );
    if v.rows.iter().any(|r| r.vbar == 0.0) {
        s += &wrap("", &format!("Rows at vbar = 0 are compared with {at_rest}."), 100);
    }
    s += &wrap(
        "",
        &format!(
            "Largest |error| {} at row {} (vbar {}, amp {}: {} against the exact {}); rms {}.",
            e(v.max_abs_error),
            w.row,
            w.vbar,
            w.amp,
            w.mu_ratio,
            w.exact,
            e(v.rms_error)
        ),
        100,
    );
    if let Some(p) = &v.peer {
        s += &wrap(
            "",
            &format!(
                "fricosc's stepping peer (the seed's scheme) at {} steps per period{}: largest |error| {}, rms {} \
                 (each row's in the JSON and CSV as peer_error).",
                p.steps_per_period,
                if p.springs > 1 { format!(" and {} springs", p.springs) } else { String::new() },
                e(p.max_abs_error),
                e(p.rms_error)
            ),
            100,
        );
    }
    if !table.ignored_columns.is_empty() {
        s += &wrap("", &format!("Columns not read: {}.", table.ignored_columns.join(", ")), 100);
    }
    s += &summary_table("regime", v.by_regime.iter().map(|g| (regime_label(g.regime, g.jumping_share), &g.summary)));
    s += &summary_table("amp", v.by_amp.iter().map(|g| (g.amp.to_string(), &g.summary)));
    s += &findings_text(&format!("Findings (value checks to {:?})", v.tolerance), &v.findings, "none", "row");
    s
}
