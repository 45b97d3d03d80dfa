//! `validate`: read another code's table and compare it with the exact solver
//! ([`crate::validation`]).
//!
//! Input is JSON (an array of row objects, or an object with a `rows` array and
//! optionally a `shape`, as `fricosc table` prints) or CSV with a header row.
//! Columns: `vbar` or `vhat` (eq. 15, `vbar = vhat / amp`), `amp`, and
//! `mu_ratio` or `mu` (then `mu_ratio = mu / mu0`, `--mu0` required);
//! optionally `shape` (a CSV column, a JSON row field or the JSON object's
//! field). Other CSV columns are listed as `ignored_columns`. The format is
//! recognised by the first non-blank character.

use crate::cli::error::{Error, Result};
use crate::cli::grid::parse_number;
use crate::cli::rows::{number, pick, raw_array, string};
use crate::validation::{
    rows_from_columns, AtRest, Convergence, HistoryValidation, RowRegime, SeriesRow, Summary, Validation,
};
use serde_json::value::RawValue;

/// Most rows one file may hold.
pub const MAX_ROWS: usize = crate::cli::grid::MAX_ROWS;

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
    /// CSV header columns that are not read.
    pub ignored_columns: Vec<String>,
}

/// One of two alternative columns, exactly one present: `(which, index)`.
fn one_of(names: [&str; 2], have: [bool; 2], what: &str, missing: &str) -> std::result::Result<bool, String> {
    match have {
        [true, false] => Ok(false),
        [false, true] => Ok(true),
        [true, true] => Err(format!("both '{}' and '{}' given: one {what} only", names[0], names[1])),
        [false, false] => Err(format!("{missing} '{}' (or '{}')", names[0], names[1])),
    }
}

/// Read a table (JSON or CSV); `source` names it in errors. Every row is read
/// and checked before anything is compared; a table without rows is an error.
pub fn read_table(text: &str, source: &str) -> Result<RawTable> {
    let err = |reason: String| Error::Parse { context: source.into(), reason };
    let mut shapes: Vec<String> = vec![];
    let mut ignored_columns = vec![];
    let (mut vhat, mut mu) = (None::<bool>, None::<bool>);
    // The same alternative for every row.
    let agree = |slot: &mut Option<bool>, value: bool, what: &str, i: usize| -> Result<()> {
        match *slot {
            Some(v) if v != value => Err(err(format!("row {i}: the {what} column changes from one row to the next"))),
            _ => {
                *slot = Some(value);
                Ok(())
            }
        }
    };
    let rows: Vec<RawRow> = match text.trim_start().chars().next() {
        None => return Err(err("empty input".into())),
        Some('[') | Some('{') => {
            let whole: &RawValue = serde_json::from_str(text).map_err(|e| err(format!("malformed JSON: {e}")))?;
            let array = if whole.get().starts_with('{') {
                let p = pick(whole, &["rows", "shape"]).map_err(err)?;
                if let Some(s) = p.0[1] {
                    shapes.push(string(s, "shape").map_err(err)?.into_owned());
                }
                p.0[0].ok_or_else(|| err("a JSON object needs a 'rows' array".into()))?
            } else {
                whole
            };
            let raw = raw_array(array.get()).map_err(|_| err("'rows' must be a JSON array".into()))?;
            let mut rows = Vec::with_capacity(raw.len());
            for (i, r) in raw.iter().enumerate() {
                let row_err = |reason: String| err(format!("row {i}: {reason}"));
                let p = pick(r, &["vbar", "vhat", "amp", "mu_ratio", "mu", "shape"]).map_err(row_err)?;
                let is_vhat =
                    one_of(["vbar", "vhat"], [p.0[0].is_some(), p.0[1].is_some()], "velocity", "missing field")
                        .map_err(row_err)?;
                let is_mu =
                    one_of(["mu_ratio", "mu"], [p.0[3].is_some(), p.0[4].is_some()], "friction value", "missing field")
                        .map_err(row_err)?;
                agree(&mut vhat, is_vhat, "velocity", i)?;
                agree(&mut mu, is_mu, "friction", i)?;
                let get = |k: usize, name: &str| {
                    number(p.0[k].ok_or_else(|| row_err(format!("missing field '{name}'")))?, name).map_err(row_err)
                };
                if let Some(s) = p.0[5] {
                    let s = string(s, "shape").map_err(row_err)?;
                    if !shapes.iter().any(|x| x == &*s) {
                        shapes.push(s.into_owned());
                    }
                }
                rows.push(RawRow {
                    velocity: get(if is_vhat { 1 } else { 0 }, if is_vhat { "vhat" } else { "vbar" })?,
                    amp: get(2, "amp")?,
                    friction: get(if is_mu { 4 } else { 3 }, if is_mu { "mu" } else { "mu_ratio" })?,
                });
            }
            rows
        }
        Some(_) => {
            let mut rd = csv::ReaderBuilder::new().trim(csv::Trim::All).from_reader(text.as_bytes());
            let header: Vec<String> =
                rd.headers().map_err(|e| err(format!("CSV header: {e}")))?.iter().map(str::to_string).collect();
            for (k, h) in header.iter().enumerate() {
                if header[..k].contains(h) {
                    return Err(err(format!("CSV header has column '{h}' twice")));
                }
            }
            let col = |name: &str| header.iter().position(|h| h == name);
            let lacks = "CSV header lacks column";
            let is_vhat = one_of(["vbar", "vhat"], [col("vbar").is_some(), col("vhat").is_some()], "velocity", lacks)
                .map_err(err)?;
            let is_mu =
                one_of(["mu_ratio", "mu"], [col("mu_ratio").is_some(), col("mu").is_some()], "friction value", lacks)
                    .map_err(err)?;
            let (vname, mname) = (if is_vhat { "vhat" } else { "vbar" }, if is_mu { "mu" } else { "mu_ratio" });
            let need = |name: &str| col(name).ok_or_else(|| err(format!("CSV header lacks column '{name}'")));
            let (cv, ca, cm, cs) = (need(vname)?, need("amp")?, need(mname)?, col("shape"));
            vhat = Some(is_vhat);
            mu = Some(is_mu);
            ignored_columns =
                header.iter().filter(|h| ![vname, "amp", mname, "shape"].contains(&h.as_str())).cloned().collect();
            let mut rows = vec![];
            for (i, rec) in rd.records().enumerate() {
                let rec = rec.map_err(|e| err(format!("row {i}: {e}")))?;
                let get = |c: usize, name: &str| {
                    let t = rec.get(c).ok_or_else(|| err(format!("row {i}: missing column '{name}'")))?;
                    parse_number(&format!("{source}: row {i}: {name}"), t)
                };
                if let Some(s) = cs.and_then(|c| rec.get(c)) {
                    if !shapes.iter().any(|x| x == s) {
                        shapes.push(s.to_string());
                    }
                }
                rows.push(RawRow { velocity: get(cv, vname)?, amp: get(ca, "amp")?, friction: get(cm, mname)? });
                if rows.len() > MAX_ROWS {
                    break;
                }
            }
            rows
        }
    };
    if rows.is_empty() {
        return Err(err("the table has no rows (nothing to validate)".into()));
    }
    if rows.len() > MAX_ROWS {
        return Err(Error::TooLarge {
            what: format!("rows of table {source}"),
            count: rows.len() as u128,
            limit: MAX_ROWS as u128,
        });
    }
    if shapes.len() > 1 {
        return Err(err(format!(
            "the table names more than one shape ({}): validate one shape at a time",
            shapes.iter().map(|s| format!("'{s}'")).collect::<Vec<_>>().join(", ")
        )));
    }
    Ok(RawTable { shape: shapes.pop(), vhat: vhat.unwrap_or(false), mu: mu.unwrap_or(false), rows, ignored_columns })
}

/// `(vbar, amp, mu_ratio)` of every row ([`crate::validation::rows_from_columns`]).
pub fn normalise(table: &RawTable, mu0: Option<f64>, source: &str) -> Result<Vec<(f64, f64, f64)>> {
    let v: Vec<f64> = table.rows.iter().map(|r| r.velocity).collect();
    let a: Vec<f64> = table.rows.iter().map(|r| r.amp).collect();
    let m: Vec<f64> = table.rows.iter().map(|r| r.friction).collect();
    rows_from_columns(&v, &a, &m, table.vhat, table.mu, mu0)
        .map_err(|e| Error::Parse { context: source.into(), reason: e.to_string() })
}

/// The name of a regime (as JSON writes it).
fn regime_name(r: RowRegime) -> String {
    serde_json::to_value(r).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
}

/// Every compared row as CSV (one header line).
pub fn rows_csv(v: &Validation) -> Result<String> {
    let n = crate::cli::output::num;
    let mut w = csv::Writer::from_writer(vec![]);
    let header = ["row", "vbar", "amp", "mu_ratio", "exact", "error", "relative_error", "regime"];
    let fail = |e: csv::Error| Error::Internal { what: format!("writing CSV: {e}") };
    w.write_record(header).map_err(fail)?;
    for r in &v.rows {
        let rel = r.relative_error.map(n).unwrap_or_default();
        let rec =
            [r.row.to_string(), n(r.vbar), n(r.amp), n(r.mu_ratio), n(r.exact), n(r.error), rel, regime_name(r.regime)];
        w.write_record(rec).map_err(fail)?;
    }
    let bytes = w.into_inner().map_err(|e| Error::Internal { what: format!("writing CSV: {e}") })?;
    String::from_utf8(bytes).map_err(|e| Error::Internal { what: format!("writing CSV: {e}") })
}

/// Words wrapped to lines of at most `width` characters, the first prefixed by
/// `first` and the rest indented as deep.
fn wrap(first: &str, text: &str, width: usize) -> String {
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
pub fn summary(v: &Validation, shape_source: &str, ignored: &[String]) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let w = &v.worst;
    let at_rest = match v.at_rest {
        AtRest::Sliding => "the sliding limit vbar -> 0+ (mu_static; --at-rest relaxed for a relaxed start)",
        AtRest::Relaxed => "a relaxed start (0; --at-rest sliding for the limit vbar -> 0+)",
    };
    let mut s = String::new();
    s += &wrap("", &format!("fricosc validate: {} rows, shape {} ({shape_source}).", v.n, v.shape), 100);
    s += &wrap("", &format!("Rows at vbar = 0 are compared with {at_rest}."), 100);
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
    if !ignored.is_empty() {
        s += &wrap("", &format!("Columns not read: {}.", ignored.join(", ")), 100);
    }
    s += &summary_table("regime", v.by_regime.iter().map(|g| (regime_name(g.regime), &g.summary)));
    s += &summary_table("amp", v.by_amp.iter().map(|g| (g.amp.to_string(), &g.summary)));
    if v.findings.is_empty() {
        s += &format!("\nFindings: none (value checks to {:?}).\n", v.tolerance);
    } else {
        s += &format!("\nFindings (value checks to {:?}):\n", v.tolerance);
        for f in &v.findings {
            let kind =
                serde_json::to_value(f.kind).ok().and_then(|k| k.as_str().map(str::to_string)).unwrap_or_default();
            let rows = f.rows.iter().map(|r| r.to_string()).collect::<Vec<_>>().join(", ");
            let more = if f.count > f.rows.len() { ", ..." } else { "" };
            let noun = if f.count == 1 { "row" } else { "rows" };
            s += &wrap("- ", &format!("{kind}: {} {noun} ({rows}{more}): {}", f.count, f.hint), 100);
        }
    }
    s
}

/// A convergence study as CSV: one line per row, its order, constant,
/// Richardson error and needed resolution, then its error at each resolution.
pub fn series_csv(c: &Convergence) -> Result<String> {
    let n = crate::cli::output::num;
    let opt = |x: Option<f64>| x.map(n).unwrap_or_default();
    let fail = |e: csv::Error| Error::Internal { what: format!("writing CSV: {e}") };
    let mut w = csv::Writer::from_writer(vec![]);
    let mut header: Vec<String> =
        ["vbar", "amp", "regime", "exact", "order", "constant", "richardson_error", "needed_resolution"]
            .map(String::from)
            .to_vec();
    header.extend(c.resolutions.iter().map(|r| format!("error@{}", n(*r))));
    w.write_record(&header).map_err(fail)?;
    for r in &c.rows {
        let mut rec = vec![
            n(r.vbar),
            n(r.amp),
            regime_name(r.regime),
            n(r.exact),
            opt(r.order),
            opt(r.constant),
            opt(r.richardson_error),
            opt(r.needed_resolution),
        ];
        rec.extend(r.errors.iter().map(|e| n(*e)));
        w.write_record(&rec).map_err(fail)?;
    }
    let bytes = w.into_inner().map_err(|e| Error::Internal { what: format!("writing CSV: {e}") })?;
    String::from_utf8(bytes).map_err(|e| Error::Internal { what: format!("writing CSV: {e}") })
}

/// A convergence study for a person: orders per regime, then every row.
pub fn series_summary(c: &Convergence) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let opt = |x: Option<f64>, f: &dyn Fn(f64) -> String| x.map(f).unwrap_or_else(|| "-".into());
    let res: Vec<String> = c.resolutions.iter().map(|r| r.to_string()).collect();
    let mut s = wrap(
        "",
        &format!("fricosc validate --series: {} rows of {} at resolutions {}.", c.rows.len(), c.shape, res.join(", ")),
        100,
    );
    s += &wrap(
        "",
        "Observed order: the least-squares slope of log |error| against log resolution (errors at rounding left out).",
        100,
    );
    s += &format!("\n{:<22}{:>6}{:>14}{:>8}{:>8}\n", "regime", "rows", "median order", "min", "max");
    for g in &c.by_regime {
        s += &format!(
            "{:<22}{:>6}{:>14.2}{:>8.2}{:>8.2}\n",
            regime_name(g.regime),
            g.n,
            g.median_order,
            g.min_order,
            g.max_order
        );
    }
    let needed = if c.target.is_some() { "needed" } else { "" };
    s += &format!(
        "\n{:>8}{:>6}  {:<20}{:>7}{:>11}{:>13}{:>13}{:>12}\n",
        "vbar", "amp", "regime", "order", "constant", "last error", "richardson", needed
    );
    for r in &c.rows {
        s += &format!(
            "{:>8}{:>6}  {:<20}{:>7}{:>11}{:>13}{:>13}{:>12}\n",
            r.vbar,
            r.amp,
            regime_name(r.regime),
            opt(r.order, &|p| format!("{p:.2}")),
            opt(r.constant, &e),
            e(*r.errors.last().unwrap_or(&0.0)),
            opt(r.richardson_error, &e),
            opt(r.needed_resolution, &|m| format!("{m:.3e}"))
        );
    }
    s
}

/// Errors against resolution on log axes, per regime (one colour each): the
/// geometric mean of its rows' errors (solid, circles) and the slope of its
/// median order through the last point (dashed).
pub fn series_svg(c: &Convergence) -> Result<String> {
    use crate::cli::plot::{Axis, Chart, Dash, Marker, Series, Style, OKABE_ITO};
    let mut series = vec![];
    let (mut ylo, mut yhi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (i, g) in c.by_regime.iter().enumerate() {
        let rows: Vec<&SeriesRow> = c.rows.iter().filter(|r| r.regime == g.regime).collect();
        let mut pts = vec![];
        for (k, &m) in c.resolutions.iter().enumerate() {
            let logs: Vec<f64> = rows.iter().map(|r| r.errors[k].abs()).filter(|x| *x > 0.0).map(f64::log10).collect();
            if !logs.is_empty() {
                pts.push((m, 10f64.powf(logs.iter().sum::<f64>() / logs.len() as f64)));
            }
        }
        let Some(&(ml, el)) = pts.last() else { continue };
        let m0 = c.resolutions[0];
        let fitted = vec![(m0, el * (ml / m0).powf(g.median_order)), (ml, el)];
        for &(_, y) in pts.iter().chain(&fitted) {
            ylo = ylo.min(y);
            yhi = yhi.max(y);
        }
        let color = OKABE_ITO[(i + 1) % OKABE_ITO.len()];
        series.push(Series {
            label: regime_name(g.regime),
            points: pts,
            style: Style::line(color).marker(Marker::Circle),
            legend: true,
        });
        series.push(Series {
            label: format!("order {:.2}", g.median_order),
            points: fitted,
            style: Style::dashed(color, Dash::Dashed),
            legend: true,
        });
    }
    let (x0, x1) = (c.resolutions[0], c.resolutions[c.resolutions.len() - 1]);
    if !(ylo.is_finite() && yhi.is_finite()) {
        return Err(Error::Parse { context: "--plot".into(), reason: "no errors above zero to draw".into() });
    }
    Ok(Chart {
        title: format!("{}: error against resolution", c.shape),
        x: Axis::log("resolution (e.g. steps per period)", (x0 / 1.2, x1 * 1.2)),
        y: Axis::log("|μ/μ_{0} − exact| (geometric mean per regime)", (ylo / 3.0, yhi * 3.0)),
        series,
        key: vec![],
        rules: vec![],
    }
    .svg())
}

fn event_name(k: crate::spring::EventKind) -> String {
    serde_json::to_value(k).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
}

/// The events found in a history, as CSV.
pub fn events_csv(v: &HistoryValidation) -> Result<String> {
    let n = crate::cli::output::num;
    let opt = |x: Option<f64>| x.map(n).unwrap_or_default();
    let fail = |e: csv::Error| Error::Internal { what: format!("writing CSV: {e}") };
    let mut w = csv::Writer::from_writer(vec![]);
    w.write_record(["kind", "tau", "exact_tau", "timing_error"]).map_err(fail)?;
    for e in &v.events {
        w.write_record([event_name(e.kind), n(e.tau), opt(e.exact_tau), opt(e.timing_error)]).map_err(fail)?;
    }
    let bytes = w.into_inner().map_err(|e| Error::Internal { what: format!("writing CSV: {e}") })?;
    String::from_utf8(bytes).map_err(|e| Error::Internal { what: format!("writing CSV: {e}") })
}

/// A history's comparison for a person.
pub fn history_summary(v: &HistoryValidation) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let mut s = wrap(
        "",
        &format!(
            "fricosc validate --history: {} at vbar {}, amp {}; {} whole periods, {} samples in the last.",
            v.shape, v.vbar, v.amp, v.periods, v.samples
        ),
        100,
    );
    s += &wrap(
        "",
        &format!(
            "Tangential force over the last period: largest |error| {}, rms {} ({}).",
            e(v.max_abs_error),
            e(v.rms_error),
            v.units
        ),
        100,
    );
    s += &wrap(
        "",
        &match (v.period_drift, v.periodic, v.periods_needed) {
            (Some(d), Some(true), _) => {
                format!("Periodic: the last period differs from the one before by {} at most.", e(d))
            }
            (Some(d), _, Some(k)) => format!(
                "Not yet periodic: the last period differs from the one before by up to {}; about {k} more periods \
                 would bring that below the tolerance.",
                e(d)
            ),
            (Some(d), _, None) => format!(
                "Not yet periodic: the last period differs from the one before by up to {} (and the drift does not \
                 decay from period to period: run more periods, or check the start).",
                e(d)
            ),
            _ => "One period only: periodicity cannot be judged (give two or more).".into(),
        },
        100,
    );
    s += &format!("\n{:<18}{:>12}{:>12}{:>14}\n", "event", "tau", "exact tau", "timing error");
    for f in &v.events {
        let o = |x: Option<f64>| x.map_or("-".into(), |y| format!("{y:.6}"));
        s += &format!(
            "{:<18}{:>12.6}{:>12}{:>14}\n",
            event_name(f.kind),
            f.tau,
            o(f.exact_tau),
            f.timing_error.map_or("-".into(), e)
        );
    }
    if v.above_bound_count > 0 {
        let first: Vec<String> = v.above_bound.iter().map(|t| format!("{t:.4}")).collect();
        s += &wrap(
            "",
            &format!(
                "Above the Coulomb bound at {} samples (tau = {}{}): the tangential force exceeds mu0 times the \
                 normal force, so the switch from stick to slip is missed (check the stick end, eq. 8, and its sign).",
                v.above_bound_count,
                first.join(", "),
                if v.above_bound_count > first.len() { ", ..." } else { "" }
            ),
            100,
        );
    }
    let found: Vec<_> = v.events.iter().map(|f| f.kind).collect();
    for x in &v.exact_events {
        if !found.contains(&x.kind) {
            s += &wrap(
                "",
                &format!(
                    "Missing: the exact {} at tau = {:.6} has no counterpart in the history.",
                    event_name(x.kind),
                    x.tau
                ),
                100,
            );
        }
    }
    s
}
