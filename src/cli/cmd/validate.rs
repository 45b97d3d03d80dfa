//! `fricosc validate`: another code's table against the exact values, with
//! errors by regime and amplitude and findings that point at bugs.

use super::{io_err, nonneg, number, positive, read_input, Outcome};
use crate::cli::error::{Error, Result};
use crate::cli::grid::parse_number;
use crate::shape::Shape;
use crate::validation::{AtRest, Convergence, HistoryValidation, Validation};
use std::io::{self, IsTerminal, Write};

/// The options of `validate`.
#[derive(clap::Args)]
pub struct ValidateArgs {
    /// Shape of the table's contact, where the table names none (a JSON 'shape' field or a
    /// CSV 'shape' column decides; giving a different one is an error). Default: flat.
    #[arg(long)]
    pub shape: Option<String>,
    /// Table file (JSON or CSV; columns vbar or vhat, amp, mu_ratio or mu); stdin when '-'.
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
    /// With --series: draw the errors against the resolution into this file (SVG or PNG by its extension).
    #[arg(long, requires = "series")]
    pub plot: Option<String>,
    #[command(flatten)]
    pub history: HistoryArgs,
    /// Largest acceptable |mu_ratio - exact| (exit 1 beyond it).
    #[arg(long, allow_hyphen_values = true, value_parser = nonneg)]
    pub max_error: Option<f64>,
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
    /// summary (a short report; the default on a terminal), json (the default otherwise) or csv
    /// (one line per row).
    #[arg(long)]
    pub format: Option<String>,
}

/// The options of `validate --history`.
#[derive(clap::Args)]
pub struct HistoryArgs {
    /// The file is a force history (CSV: tau or t, tangential, optionally normal; forces in
    /// units of kz u0 and mu0 kz u0) at --vbar (or --vhat) and --amp: errors over the last period,
    /// periodicity, and the stick/slip/contact events with timing errors.
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
    /// With --history and a time column t: the angular frequency (tau = omega t); without it
    /// the period and phase are found from the normal force's maxima (at tau = pi).
    #[arg(long, allow_hyphen_values = true, value_parser = positive, requires = "on")]
    pub omega: Option<f64>,
    /// With --history: forces in your units, where the static normal force kz u0 is this value
    /// (normal / kz_u0; tangential / (mu0 kz_u0) with --mu0). Default: already normalised.
    #[arg(long, allow_hyphen_values = true, value_parser = positive, requires = "on")]
    pub kz_u0: Option<f64>,
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
    #[serde(skip_serializing_if = "<[String]>::is_empty")]
    ignored_columns: &'a [String],
}

/// Prints the comparison; [`Outcome::Negative`] when `--max-error` is exceeded.
pub fn run(a: ValidateArgs) -> Result<Outcome> {
    let max_error = a.max_error;
    let at_rest = match a.at_rest.as_str() {
        "sliding" => AtRest::Sliding,
        "relaxed" => AtRest::Relaxed,
        other => {
            return Err(Error::Parse {
                context: "--at-rest".into(),
                reason: format!("'{other}' is neither 'sliding' nor 'relaxed'"),
            })
        }
    };
    let (mu0, tolerance) = (a.mu0, a.tolerance);
    let format = match a.format.as_deref() {
        Some(f @ ("summary" | "json" | "csv")) => f.to_string(),
        Some(other) => {
            return Err(Error::Parse {
                context: "--format".into(),
                reason: format!("'{other}' is not one of summary, json, csv"),
            })
        }
        // A person at a terminal reads the summary; a pipe gets JSON.
        None if io::stdout().is_terminal() => "summary".into(),
        None => "json".into(),
    };
    let h = &a.history;
    if a.series {
        if h.on {
            return run_history_series(&a, h, mu0, tolerance, &format);
        }
        return run_series(&a, at_rest, mu0, &format);
    }
    if h.on {
        return run_history(&a, h, mu0, tolerance, &format, max_error);
    }
    if a.files.len() != 1 || a.target.is_some() || a.plot.is_some() {
        return Err(Error::Parse {
            context: "validate".into(),
            reason: "several files, --target and --plot need --series".into(),
        });
    }
    let (text, source) = read_input(Some(a.files[0].clone()))?;
    let table = crate::cli::validate::read_table(&text, &source)?;
    drop(text);
    let (shape, shape_source) = choose_shape(table.shape.as_deref(), a.shape.as_deref(), &source)?;
    let rows = crate::cli::validate::normalise(&table, mu0, &source)?;
    let v = crate::validation::compare(&shape, &rows, at_rest, tolerance)?;
    let report = Report { validation: &v, shape_source, ignored_columns: &table.ignored_columns };
    let body = match format.as_str() {
        "json" => super::to_json(&report)? + "\n",
        "csv" => crate::cli::validate::rows_csv(&v)?,
        _ => crate::cli::validate::summary(&v, &report_source(&report), &table.ignored_columns),
    };
    let mut out = io::BufWriter::new(io::stdout().lock());
    out.write_all(body.as_bytes()).map_err(io_err)?;
    out.flush().map_err(io_err)?;
    Ok(if max_error.is_none_or(|e| v.max_abs_error <= e) { Outcome::Done } else { Outcome::Negative })
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
            let (fs, os) = (crate::cli::input::parse_shape(f)?, crate::cli::input::parse_shape(o)?);
            if fs.name() != os.name() {
                return Err(Error::Parse {
                    context: source.into(),
                    reason: format!("the table is for shape '{f}', --shape says '{o}'"),
                });
            }
            (fs, ShapeSource::File)
        }
        (Some(f), None) => (crate::cli::input::parse_shape(f)?, ShapeSource::File),
        (None, Some(o)) => (crate::cli::input::parse_shape(o)?, ShapeSource::Option),
        (None, None) => (Shape::flat(), ShapeSource::Default),
    })
}

/// `FILE@N` (the resolution after the last `@`), or a file named like
/// `run@1000.csv` (the digits after the last `@` of its name).
fn file_and_resolution(arg: &str) -> Result<(String, f64)> {
    let bad = || Error::Parse {
        context: arg.into(),
        reason: "a series file needs its resolution: run@1000.csv or run.csv@1000".into(),
    };
    let (head, tail) = arg.rsplit_once('@').ok_or_else(bad)?;
    let checked = |n: f64| {
        if n.is_finite() && n > 0.0 {
            Ok(n)
        } else {
            Err(Error::Parse {
                context: arg.into(),
                reason: format!("the resolution {n:?} must be a finite number > 0"),
            })
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

fn run_series(a: &ValidateArgs, at_rest: AtRest, mu0: Option<f64>, format: &str) -> Result<Outcome> {
    let target = a.target;
    if let Some(path) = &a.plot {
        super::drawing_kind("--plot", path)?;
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
        let table = crate::cli::validate::read_table(&text, &source)?;
        let (shape, src) = choose_shape(table.shape.as_deref(), a.shape.as_deref(), &source)?;
        if let Some((s, _)) = &chosen {
            if s.name() != shape.name() {
                return Err(Error::Parse {
                    context: source,
                    reason: format!("its shape '{}' differs from the series' '{}'", shape.name(), s.name()),
                });
            }
        }
        chosen = Some((shape, src));
        tables.push(crate::cli::validate::normalise(&table, mu0, &source)?);
        resolutions.push(n);
    }
    let (shape, shape_source) = chosen.ok_or_else(|| Error::Internal { what: "an empty series".into() })?;
    let c = crate::validation::convergence(&shape, &resolutions, &tables, at_rest, target)?;
    if let Some(path) = &a.plot {
        let svg = crate::cli::validate::series_svg(&c)?;
        super::write_drawing("--plot", path, &svg)?;
    }
    let body = match format {
        "json" => super::to_json(&SeriesReport { convergence: &c, shape_source })? + "\n",
        "csv" => crate::cli::validate::series_csv(&c)?,
        _ => crate::cli::validate::series_summary(&c),
    };
    let mut out = io::BufWriter::new(io::stdout().lock());
    out.write_all(body.as_bytes()).map_err(io_err)?;
    out.flush().map_err(io_err)?;
    Ok(Outcome::Done)
}

/// Read and compare one history file.
fn history_of(
    a: &ValidateArgs,
    h: &HistoryArgs,
    file: &str,
    mu0: Option<f64>,
    tolerance: f64,
) -> Result<HistoryValidation> {
    let shape = match &a.shape {
        Some(spec) => crate::cli::input::parse_shape(spec)?,
        None => Shape::flat(),
    };
    let amp = h.amp.unwrap_or(0.0);
    let vbar = match (h.vbar, h.vhat) {
        (Some(v), None) => v,
        (None, Some(v)) => super::vbar_of(v, amp)?,
        _ => return Err(Error::Parse { context: "--history".into(), reason: "needs one of --vbar and --vhat".into() }),
    };
    let omega = h.omega;
    let (text, source) = read_input(Some(file.to_string()))?;
    let err = |reason: String| Error::Parse { context: source.clone(), reason };
    let mut rd = csv::ReaderBuilder::new().trim(csv::Trim::All).from_reader(text.as_bytes());
    let header: Vec<String> =
        rd.headers().map_err(|e| err(format!("CSV header: {e}")))?.iter().map(str::to_string).collect();
    let col = |name: &str| header.iter().position(|h| h == name);
    let (time, is_tau) = match (col("tau"), col("t")) {
        (Some(c), None) => (c, true),
        (None, Some(c)) => (c, false),
        (Some(_), Some(_)) => return Err(err("both 'tau' and 't' given: one time column only".into())),
        (None, None) => return Err(err("CSV header lacks column 'tau' (or 't')".into())),
    };
    let tangential = col("tangential").ok_or_else(|| err("CSV header lacks column 'tangential'".into()))?;
    let normal_col = col("normal");
    let (mut t, mut ft, mut fnorm) = (vec![], vec![], vec![]);
    for (i, rec) in rd.records().enumerate() {
        let rec = rec.map_err(|e| err(format!("row {i}: {e}")))?;
        let get = |c: usize, name: &str| parse_number(&format!("{source}: row {i}: {name}"), rec.get(c).unwrap_or(""));
        t.push(get(time, "time")?);
        ft.push(get(tangential, "tangential")?);
        if let Some(c) = normal_col {
            fnorm.push(get(c, "normal")?);
        }
        if t.len() > crate::cli::grid::MAX_ROWS {
            return Err(Error::TooLarge {
                what: format!("rows of {source}"),
                count: t.len() as u128,
                limit: crate::cli::grid::MAX_ROWS as u128,
            });
        }
    }
    // Forces in the user's units: normal / (kz u0), tangential / (mu0 kz u0).
    let unit = h.kz_u0.unwrap_or(1.0);
    let mu0 = mu0.unwrap_or(1.0);
    for (name, x) in [("kz-u0", unit), ("mu0", mu0)] {
        if !(x.is_finite() && x > 0.0) {
            return Err(Error::param(name, x, "must be finite and > 0"));
        }
    }
    fnorm.iter_mut().for_each(|x| *x /= unit);
    ft.iter_mut().for_each(|x| *x /= mu0 * unit);
    let normal = normal_col.map(|_| fnorm.as_slice());
    let taus = crate::validation::phases(&t, is_tau, omega, normal)
        .map_err(|e| Error::Parse { context: source.clone(), reason: e.to_string() })?;
    Ok(crate::validation::compare_history(&shape, vbar, amp, &taus, &ft, normal, tolerance)?)
}

fn run_history(
    a: &ValidateArgs,
    h: &HistoryArgs,
    mu0: Option<f64>,
    tolerance: f64,
    format: &str,
    max_error: Option<f64>,
) -> Result<Outcome> {
    if a.files.len() != 1 {
        return Err(Error::Parse {
            context: "--history".into(),
            reason: "takes one file (several with --series)".into(),
        });
    }
    let v = history_of(a, h, &a.files[0], mu0, tolerance)?;
    let body = match format {
        "json" => super::to_json(&v)? + "\n",
        "csv" => crate::cli::validate::events_csv(&v)?,
        _ => crate::cli::validate::history_summary(&v),
    };
    let mut out = io::BufWriter::new(io::stdout().lock());
    out.write_all(body.as_bytes()).map_err(io_err)?;
    out.flush().map_err(io_err)?;
    Ok(if max_error.is_none_or(|e| v.max_abs_error <= e) { Outcome::Done } else { Outcome::Negative })
}

/// The convergence of a series of histories: per resolution the largest error
/// over the last period and each event's timing error, with their observed orders.
#[derive(serde::Serialize)]
struct HistorySeries {
    resolutions: Vec<f64>,
    max_abs_errors: Vec<f64>,
    order: Option<f64>,
    constant: Option<f64>,
    /// Per event kind: the timing errors (one per resolution) and their order.
    events: Vec<EventSeries>,
}

#[derive(serde::Serialize)]
struct EventSeries {
    kind: String,
    timing_errors: Vec<Option<f64>>,
    order: Option<f64>,
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
        runs.push((n, history_of(a, h, &file, mu0, tolerance)?));
    }
    runs.sort_by(|x, y| x.0.total_cmp(&y.0));
    let resolutions: Vec<f64> = runs.iter().map(|r| r.0).collect();
    let max_abs_errors: Vec<f64> = runs.iter().map(|r| r.1.max_abs_error).collect();
    let (order, constant) = crate::validation::observed_order(&resolutions, &max_abs_errors);
    let mut kinds: Vec<crate::spring::EventKind> = runs[0].1.exact_events.iter().map(|e| e.kind).collect();
    kinds.dedup();
    let events = kinds
        .iter()
        .map(|&k| {
            let timing_errors: Vec<Option<f64>> =
                runs.iter().map(|r| r.1.events.iter().find(|e| e.kind == k).and_then(|e| e.timing_error)).collect();
            let (res, errs): (Vec<f64>, Vec<f64>) =
                resolutions.iter().zip(&timing_errors).filter_map(|(r, e)| e.map(|e| (*r, e))).unzip();
            let name = serde_json::to_value(k).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default();
            EventSeries { kind: name, timing_errors, order: crate::validation::observed_order(&res, &errs).0 }
        })
        .collect();
    let report = HistorySeries { resolutions, max_abs_errors, order, constant, events };
    let body = match format {
        "csv" => {
            let mut t = String::from("resolution,max_abs_error\n");
            for (r, e) in report.resolutions.iter().zip(&report.max_abs_errors) {
                t += &format!("{},{}\n", crate::cli::output::num(*r), crate::cli::output::num(*e));
            }
            t
        }
        "json" => super::to_json(&report)? + "\n",
        _ => {
            let o = |p: Option<f64>| p.map_or("-".into(), |p| format!("{p:.2}"));
            let mut t = format!(
                "fricosc validate --series --history: {} histories; the largest error over the last period has \
                 order {}.\n",
                report.resolutions.len(),
                o(report.order)
            );
            for (r, e) in report.resolutions.iter().zip(&report.max_abs_errors) {
                t += &format!("  resolution {r:>10}: largest |error| {e:.2e}\n");
            }
            for ev in &report.events {
                t += &format!("  event {:<16} timing order {}\n", ev.kind, o(ev.order));
            }
            t
        }
    };
    let mut out = io::BufWriter::new(io::stdout().lock());
    out.write_all(body.as_bytes()).map_err(io_err)?;
    out.flush().map_err(io_err)?;
    Ok(Outcome::Done)
}
