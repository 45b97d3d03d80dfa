//! `fricosc validate`: another code's table against the exact values, with
//! errors by regime and amplitude and findings that point at bugs.

mod history;
mod series;
mod table;

pub use history::{history_csv, read_history, HistoryColumns};
pub use series::{series_csv, series_svg};
pub use table::{oscillation_csv, read_table, rows_csv, MAX_ROWS};

use crate::cmd::{io_err, nonneg, number, positive, read_input, Outcome};
use crate::error::{Error, Result};
use fricosc::stepper::Stepping;
use fricosc::validation::{
    AtRest, Check, Convergence, HistoryData, HistorySeries, HistoryValidation, OscillationValidation, TimeAxis,
    Validation,
};
use fricosc::Shape;
use std::io::{self, IsTerminal, Write};

/// The options of `validate`.
#[derive(clap::Args)]
pub struct ValidateArgs {
    /// Shape of the table's contact, where the table names none (a JSON 'shape' field or a
    /// CSV 'shape' column decides; giving a different one is an error). Default: flat.
    #[arg(long)]
    pub shape: Option<String>,
    /// Table file (JSON or CSV; columns vbar or vhat, amp, mu_ratio or mu; optionally
    /// tangential_amp and phase, transverse_amp, transverse_phase and transverse_ratio); stdin when '-'.
    /// With --series: several, each with its resolution (run@1000.csv, or run.csv@1000).
    #[arg(required = true)]
    pub files: Vec<String>,
    /// A convergence study: the same table at several resolutions (e.g. steps per period);
    /// reports the observed order per row and regime, the error constant, the Richardson value
    /// and the resolution needed for --target.
    #[arg(long)]
    pub series: bool,
    /// With --series: the target error for the needed resolution.
    #[arg(long, allow_hyphen_values = true, value_parser = positive, requires = "series")]
    pub target: Option<f64>,
    /// With --series: draw the errors against the resolution into this file (.svg or .png).
    #[arg(long, requires = "series")]
    pub plot: Option<String>,
    #[command(flatten)]
    pub history: HistoryArgs,
    /// A table on a system with mass and stiffness (one table: compared with the attractors).
    #[command(flatten)]
    pub system: crate::cmd::SystemPoint,
    /// With --system-stiffness, a curved body: its springs (32 to 16384, default 256).
    #[arg(long, requires = "system_stiffness")]
    pub springs: Option<usize>,
    /// Largest acceptable |mu_ratio - exact| (exit 1 beyond it).
    #[arg(long, allow_hyphen_values = true, value_parser = nonneg)]
    pub max_error: Option<f64>,
    /// Exit 0 whatever the findings and errors (the report is printed all the same).
    #[arg(long)]
    pub report_only: bool,
    /// Run fricosc's stepping peer (the seed's scheme) at M steps per period on every row
    /// and set its error beside yours (findings where yours is ten times its).
    #[arg(long, value_name = "M", value_parser = clap::value_parser!(u64).range(1..=100_000_000), conflicts_with_all = ["series", "on"])]
    pub peer: Option<u64>,
    /// With --peer and a curved shape: the peer's springs (default: M).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=100_000_000), requires = "peer")]
    pub peer_springs: Option<u64>,
    /// What a vbar = 0 row is compared with: 'sliding' (the limit vbar -> 0+, mu_static) or
    /// 'relaxed' (a stepper started from relaxed springs at exactly zero velocity: 0).
    #[arg(long, default_value = "sliding")]
    pub at_rest: String,
    /// Coulomb coefficient, for a table that gives 'mu' (mu_ratio = mu / mu0), or a history in
    /// your units (tangential / (mu0 F0)).
    #[arg(long, allow_hyphen_values = true, value_parser = positive)]
    pub mu0: Option<f64>,
    /// How far a value may leave [0, 1], differ from 1 above vbar = 1, or decrease in vbar
    /// before it is reported as a finding.
    #[arg(long, default_value = "1e-9", allow_hyphen_values = true, value_parser = nonneg)]
    pub tolerance: f64,
    /// summary (a short report; the default on a terminal), json (compact; the default
    /// otherwise) or csv (one line per row; with --history one per sample of the last period).
    #[arg(long)]
    pub format: Option<String>,
}

/// The options of `validate --history`.
#[derive(clap::Args)]
pub struct HistoryArgs {
    /// The file is a force history (columns tau or t, tangential, optionally normal, transverse; forces in
    /// units of the static force F0 and mu0 F0, or yours with --static-force and --mu0) at --vbar
    /// (or --vhat) and --amp: the time origin from the normal force, errors of both forces over the
    /// last period, periodicity, and the stick/slip/contact events with timing errors.
    #[arg(long = "history", requires = "amp")]
    pub on: bool,
    /// With --history: the velocity vbar (eq. 3).
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "on", conflicts_with = "vhat")]
    pub vbar: Option<f64>,
    /// With --history: the velocity vhat (eq. 15), instead of --vbar.
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "on")]
    pub vhat: Option<f64>,
    /// With --history: the amplitude du/u0.
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "on")]
    pub amp: Option<f64>,
    /// With --history and --vhat: the amplitude of an oscillation in the sliding direction,
    /// dx/l (as `point --tangential-amp`).
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "vhat")]
    pub tangential_amp: Option<f64>,
    /// With --history and --tangential-amp: its phase, radians (default 0).
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "tangential_amp")]
    pub phase: Option<f64>,
    /// With --history and a time column t: the angular frequency (tau = omega t); without it
    /// the period is found from the normal force.
    #[arg(long, allow_hyphen_values = true, value_parser = positive, requires = "on")]
    pub omega: Option<f64>,
    /// With --history: forces in your units, where F0, the normal force at the mean
    /// indentation u0 without oscillation, is this value (normal / F0; tangential / (mu0 F0)
    /// with --mu0): kz u0 for the flat punch, (4/3) E* R^1/2 u0^3/2 for the paraboloid (Hertz).
    /// Default: already normalised.
    #[arg(long, visible_alias = "kz-u0", allow_hyphen_values = true, value_parser = positive, requires = "on")]
    pub static_force: Option<f64>,
    /// With --history: a history in the plane (its column transverse compared where given).
    #[command(flatten)]
    pub transverse: crate::cmd::TransversePoint,
}

/// Where the shape came from.
#[derive(serde::Serialize)]
#[serde(rename_all = "snake_case")]
enum ShapeSource {
    File,
    Option,
    Default,
}

#[derive(serde::Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    validation: &'a Validation,
    shape_source: ShapeSource,
    format: &'a str,
    #[serde(skip_serializing_if = "<[String]>::is_empty")]
    ignored_columns: &'a [String],
}

/// Compact JSON (one line) of a report, newline-terminated.
fn compact<T: serde::Serialize>(value: &T) -> Result<String> {
    serde_json::to_string(value)
        .map(|s| s + "\n")
        .map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })
}

/// Write a report to stdout.
fn print(body: &str) -> Result<()> {
    let mut out = io::BufWriter::new(io::stdout().lock());
    out.write_all(body.as_bytes()).map_err(io_err)?;
    out.flush().map_err(io_err)
}

/// The exit: [`Outcome::Negative`] on findings or an error beyond `--max-error`,
/// unless `--report-only`.
fn outcome(a: &ValidateArgs, findings: bool, max_abs_error: f64) -> Outcome {
    // A NaN error is beyond any bound.
    let beyond = a.max_error.is_some_and(|e| max_abs_error.is_nan() || max_abs_error > e);
    if !a.report_only && (findings || beyond) {
        Outcome::Negative
    } else {
        Outcome::Done
    }
}

/// Prints the comparison; [`Outcome::Negative`] on findings or beyond `--max-error`.
pub fn run(a: ValidateArgs) -> Result<Outcome> {
    let max_error = a.max_error;
    let at_rest = match a.at_rest.as_str() {
        "sliding" => AtRest::Sliding,
        "relaxed" => AtRest::Relaxed,
        other => return Err(Error::parse("--at-rest", format!("'{other}' is neither 'sliding' nor 'relaxed'"))),
    };
    let (mu0, tolerance) = (a.mu0, a.tolerance);
    let format = match a.format.as_deref() {
        Some(f @ ("summary" | "json" | "csv")) => f.to_string(),
        Some(other) => return Err(Error::parse("--format", format!("'{other}' is not one of summary, json, csv"))),
        // A person at a terminal reads the summary; a pipe gets JSON.
        None if io::stdout().is_terminal() => "summary".into(),
        None => "json".into(),
    };
    let h = &a.history;
    let system = a.system.system(a.springs)?;
    let check =
        Check::default().with_at_rest(at_rest).with_tolerance(tolerance).with_system(system).with_max_error(max_error);
    if a.series {
        if h.on {
            return run_history_series(&a, h, mu0, tolerance, &format);
        }
        return run_series(&a, &check, mu0, &format);
    }
    if h.on {
        return run_history(&a, h, mu0, tolerance, &format);
    }
    if h.transverse.transverse_amp.is_some() {
        return Err(Error::parse("--transverse-amp", "goes with --history (a table's rows give theirs)"));
    }
    if a.files.len() != 1 || a.target.is_some() || a.plot.is_some() {
        return Err(Error::parse("validate", "several files, --target and --plot need --series"));
    }
    let (text, source) = read_input(Some(a.files[0].clone()))?;
    let table = read_table(&text, &source)?;
    drop(text);
    let (shape, shape_source) = choose_shape(table.shape(), a.shape.as_deref(), &source)?;
    let peer = a.peer.map(|m| Stepping { steps_per_period: m as usize, springs: a.peer_springs.unwrap_or(m) as usize });
    if table.is_oscillation() {
        let rows = table.oscillation_rows(mu0, &source)?;
        let v = fricosc::validation::compare_oscillation(&shape, &rows, &check.with_peer(peer))?;
        #[derive(serde::Serialize)]
        struct OscillationReport<'a> {
            #[serde(flatten)]
            validation: &'a OscillationValidation,
            shape_source: ShapeSource,
            format: &'a str,
            #[serde(skip_serializing_if = "<[String]>::is_empty")]
            ignored_columns: &'a [String],
        }
        let report = OscillationReport {
            validation: &v,
            shape_source,
            format: table.format(),
            ignored_columns: table.ignored_columns(),
        };
        let body = match format.as_str() {
            "json" => compact(&report)?,
            "csv" => oscillation_csv(&v)?,
            _ => v.summary(&source),
        };
        print(&body)?;
        // `--max-error` is a finding of its own (beyond the exact values' estimates).
        return Ok(outcome(&a, !v.findings.is_empty(), 0.0));
    }
    let rows = table.rows(mu0, &source)?;
    let mut v = fricosc::validation::compare(&shape, &rows, &check.with_peer(peer))?;
    v.key_by(&table);
    let report =
        Report { validation: &v, shape_source, format: table.format(), ignored_columns: table.ignored_columns() };
    let body = match format.as_str() {
        "json" => compact(&report)?,
        "csv" => rows_csv(&v)?,
        _ => v.summary(&table, &report_source(&report)),
    };
    print(&body)?;
    Ok(outcome(&a, !v.findings.is_empty(), 0.0))
}

fn report_source(r: &Report) -> String {
    match r.shape_source {
        ShapeSource::File => "named by the table".into(),
        ShapeSource::Option => "from --shape".into(),
        ShapeSource::Default => "the default: the table names none and --shape is not given".into(),
    }
}

/// The file's shape decides; `--shape` only where the file names none (an
/// error where the two disagree); the flat punch where neither does.
fn choose_shape(file: Option<&str>, option: Option<&str>, source: &str) -> Result<(Shape, ShapeSource)> {
    Ok(match (file, option) {
        (Some(f), Some(o)) => {
            let (fs, os) = (crate::input::parse_shape(f)?, crate::input::parse_shape(o)?);
            if fs.name() != os.name() {
                return Err(Error::parse(source, format!("the table is for shape '{f}', --shape says '{o}'")));
            }
            (fs, ShapeSource::File)
        }
        (Some(f), None) => (crate::input::parse_shape(f)?, ShapeSource::File),
        (None, Some(o)) => (crate::input::parse_shape(o)?, ShapeSource::Option),
        (None, None) => (Shape::flat(), ShapeSource::Default),
    })
}

/// `FILE@N` (the resolution after the last `@`), or a file named like
/// `run@1000.csv` (the digits after the last `@` of its name).
fn file_and_resolution(arg: &str) -> Result<(String, f64)> {
    let bad = || Error::parse(arg, "a series file needs its resolution: run@1000.csv or run.csv@1000");
    let (head, tail) = arg.rsplit_once('@').ok_or_else(bad)?;
    let checked = |n: f64| {
        if n.is_finite() && n > 0.0 {
            Ok(n)
        } else {
            Err(Error::parse(arg, format!("the resolution {n:?} must be a finite number > 0")))
        }
    };
    if let Ok(n) = tail.trim().parse::<f64>() {
        return Ok((head.to_string(), checked(n)?));
    }
    let digits: String = tail.chars().take_while(|c| c.is_ascii_digit() || *c == '.' || *c == 'e').collect();
    let n = digits.trim_end_matches('.').parse::<f64>().map_err(|_| bad())?;
    Ok((arg.to_string(), checked(n)?))
}

#[derive(serde::Serialize)]
struct SeriesReport<'a> {
    #[serde(flatten)]
    convergence: &'a Convergence,
    shape_source: ShapeSource,
}

fn run_series(a: &ValidateArgs, check: &Check, mu0: Option<f64>, format: &str) -> Result<Outcome> {
    let target = a.target;
    if let Some(path) = &a.plot {
        crate::cmd::drawing_kind("--plot", path)?;
    }
    if a.files.len() < 2 {
        return Err(Error::Parse { context: "--series".into(), reason: "needs two files or more".into() });
    }
    let mut resolutions = vec![];
    let mut tables = vec![];
    let mut chosen: Option<(Shape, ShapeSource)> = None;
    for arg in &a.files {
        let (file, n) = file_and_resolution(arg)?;
        let (text, source) = read_input(Some(file))?;
        let table = read_table(&text, &source)?;
        let (shape, src) = choose_shape(table.shape(), a.shape.as_deref(), &source)?;
        if let Some((s, _)) = &chosen {
            if s.name() != shape.name() {
                return Err(Error::parse(
                    source,
                    format!("its shape '{}' differs from the series' '{}'", shape.name(), s.name()),
                ));
            }
        }
        chosen = Some((shape, src));
        tables.push(table.rows(mu0, &source)?);
        resolutions.push(n);
    }
    let (shape, shape_source) = chosen.ok_or_else(|| Error::Internal { what: "an empty series".into() })?;
    let c = fricosc::validation::convergence(&shape, &resolutions, &tables, check, target)?;
    if let Some(path) = &a.plot {
        let svg = series_svg(&c)?;
        crate::cmd::write_drawing("--plot", path, &svg)?;
    }
    let body = match format {
        "json" => compact(&SeriesReport { convergence: &c, shape_source })?,
        "csv" => series_csv(&c)?,
        _ => c.summary(),
    };
    print(&body)?;
    let worst = c.rows.iter().filter_map(|r| r.errors.last()).fold(0.0f64, |m, e| m.max(e.abs()));
    Ok(outcome(a, !c.findings.is_empty(), if a.max_error.is_some() { worst } else { 0.0 }))
}

/// Read and compare one history file; also how it was read.
fn history_of(
    a: &ValidateArgs,
    h: &HistoryArgs,
    file: &str,
    mu0: Option<f64>,
    tolerance: f64,
) -> Result<(HistoryValidation, String)> {
    let shape = match &a.shape {
        Some(spec) => crate::input::parse_shape(spec)?,
        None => Shape::flat(),
    };
    let velocity = match (h.vbar, h.vhat) {
        (Some(v), None) => fricosc::Velocity::Vbar(v),
        (None, Some(v)) => fricosc::Velocity::Vhat(v),
        _ => return Err(Error::Parse { context: "--history".into(), reason: "needs one of --vbar and --vhat".into() }),
    };
    let tangential = h.tangential_amp.map(|t| (t, h.phase.unwrap_or(0.0)));
    if let Some((_, phase)) = tangential {
        crate::cmd::warn_degrees(&[phase]);
    }
    let mut conditions = crate::cmd::conditions(velocity, h.amp.unwrap_or(0.0), tangential)?;
    conditions = a.system.system(a.springs)?.map_or(conditions, |s| conditions.with_system(s));
    conditions = h.transverse.oscillation()?.map_or(conditions, |w| conditions.with_transverse(w));
    let (text, source) = read_input(Some(file.to_string()))?;
    let c = read_history(&text, &source, h.static_force.unwrap_or(1.0), mu0.unwrap_or(1.0))?;
    drop(text);
    let time = if c.is_tau { TimeAxis::Phase(&c.time) } else { TimeAxis::Time { t: &c.time, omega: h.omega } };
    if c.is_tau && h.omega.is_some() {
        return Err(Error::parse(source, "--omega is given, but the time column is the phase tau"));
    }
    let body = c.body.as_ref().map(|(l, v)| (&l[..], &v[..]));
    let data = HistoryData {
        time,
        tangential: &c.tangential,
        normal: c.normal.as_deref(),
        transverse: c.transverse.as_deref(),
        body,
    };
    let v = fricosc::validation::compare_history(&shape, &conditions, &data, tolerance).map_err(|e| match e {
        fricosc::Error::Parse { context, reason } => Error::Parse { context: format!("{source}: {context}"), reason },
        e => Error::Core(e),
    })?;
    Ok((v, c.format))
}

fn run_history(a: &ValidateArgs, h: &HistoryArgs, mu0: Option<f64>, tolerance: f64, format: &str) -> Result<Outcome> {
    if a.files.len() != 1 {
        return Err(Error::parse("--history", "takes one file (several with --series)"));
    }
    let (v, read_as) = history_of(a, h, &a.files[0], mu0, tolerance)?;
    let body = match format {
        "json" => compact(&v)?,
        "csv" => history_csv(&v)?,
        _ => v.summary(&read_as),
    };
    print(&body)?;
    Ok(outcome(a, !v.findings.is_empty(), v.max_abs_error))
}

fn run_history_series(
    a: &ValidateArgs,
    h: &HistoryArgs,
    mu0: Option<f64>,
    tolerance: f64,
    format: &str,
) -> Result<Outcome> {
    if a.files.len() < 2 {
        return Err(Error::Parse { context: "--series".into(), reason: "needs two files or more".into() });
    }
    let mut runs = vec![];
    for arg in &a.files {
        let (file, n) = file_and_resolution(arg)?;
        runs.push((n, history_of(a, h, &file, mu0, tolerance)?.0));
    }
    let report = HistorySeries::new(runs);
    let body = match format {
        "csv" => {
            let mut t = String::from("resolution,max_abs_error\n");
            for (r, e) in report.resolutions.iter().zip(&report.max_abs_errors) {
                t += &format!("{},{}\n", crate::output::num(*r), crate::output::num(*e));
            }
            t
        }
        "json" => compact(&report)?,
        _ => report.summary(),
    };
    print(&body)?;
    let worst = report.max_abs_errors.last().copied().unwrap_or(0.0);
    Ok(outcome(a, !report.findings.is_empty(), worst))
}
