//! `fricosc`: command-line interface, a thin layer over the library.
//!
//! Exit codes: 0 success (also when the reader closes the pipe), 1 a negative
//! answer (`validate`, `stress`), 2 bad input or a failed read/write (one line
//! on stderr, nothing on stdout), 3 an internal error (`Error::Internal`).

use clap::{Args, Parser, Subcommand};
use fricosc::batch;
use fricosc::error::{Error, Result};
use fricosc::grid::{parse_number, parse_values};
use fricosc::output::{Format, TableWriter};
use fricosc::shape::{check_tol, evaluate_stepping, evaluate_with, Shape, Stepping};
use rayon::prelude::*;
use std::io::{self, IsTerminal, Write};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "fricosc",
    version,
    about = "Exact friction under normal oscillation (Popov, Popov, Popov 2017)",
    arg_required_else_help = true
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// One point, with regime and events: JSON.
    Point(PointArgs),
    /// A grid of amplitudes x velocities: JSON or CSV.
    Table(TableArgs),
    /// Compare a table of (vbar, amp, mu_ratio) from another code (CSV or JSON) with the exact values.
    /// Exit 1 when the largest error exceeds --max-error.
    Validate {
        /// Shape of the table's contact.
        #[arg(long, default_value = "flat")]
        shape: String,
        /// Table file; stdin when '-'.
        file: String,
        /// Largest acceptable |mu_ratio - exact|.
        #[arg(long, allow_hyphen_values = true)]
        max_error: Option<String>,
    },
    /// Work-precision benchmark: exact solver vs time stepping; writes JSON, CSV and SVG to DIR.
    Bench {
        /// Output directory (created if missing).
        #[arg(long)]
        out: String,
        /// A few seconds, for CI.
        #[arg(long)]
        quick: bool,
    },
    /// Stress test: many random and edge points; exit 1 if any check fails.
    Stress {
        /// Points (rounded up to whole lines of 16).
        #[arg(long, default_value_t = 1_000_000)]
        points: usize,
        /// Seed of the point generator.
        #[arg(long, default_value_t = 1)]
        seed: u64,
    },
    /// Every quantitative claim of the seed, checked against the exact solver.
    Claims {
        /// markdown (default) or json.
        #[arg(long, default_value = "markdown")]
        format: String,
    },
    /// Normal and tangential force over time (the seed's Fig. 2), exact: JSON, CSV or SVG.
    History {
        /// Shape: flat or a power law.
        #[arg(long, default_value = "flat")]
        shape: String,
        #[command(flatten)]
        velocity: Velocity,
        /// Amplitude du/u0.
        #[arg(long, allow_hyphen_values = true)]
        amp: String,
        /// Periods to sample.
        #[arg(long, default_value_t = 1)]
        periods: usize,
        /// Uniform samples over all periods (event times are added).
        #[arg(long, default_value_t = 400)]
        samples: usize,
        /// Springs summed for MDR shapes.
        #[arg(long, default_value_t = 4000)]
        springs: usize,
        /// MDR shapes: report these springs too (positions x/x_c, comma list; JSON only).
        #[arg(long, allow_hyphen_values = true)]
        spring_at: Option<String>,
        /// json, csv or svg.
        #[arg(long, default_value = "json")]
        format: String,
    },
    /// The seed's Figs. 3, 4, 5 (+ inset), 7, 8: exact curves and the seed's approximations, as JSON, CSV, SVG.
    Figures {
        /// Output directory (created if missing).
        #[arg(long)]
        out: String,
    },
    /// Physical scenes (JSON, SI units): mu, forces and velocities in physical units.
    Scene {
        /// Scene files (run in parallel).
        files: Vec<String>,
        /// Print the JSON Schema of the scene file instead.
        #[arg(long)]
        schema: bool,
        /// Output format.
        #[arg(long, value_enum, default_value = "json")]
        format: Format,
    },
    /// A JSON array of {shape, vbar, amp, ...} from FILE or stdin; the same array with mu_ratio and reduction added.
    Batch {
        /// Input file; stdin when absent or '-'.
        file: Option<String>,
        #[command(flatten)]
        method: MethodArgs,
    },
}

/// The velocity, as vbar (eq. 3) or vhat (eq. 15, vbar = vhat / amp).
#[derive(Args)]
#[group(required = true, multiple = false)]
struct Velocity {
    /// Dimensionless velocity vbar = (kx/kz) v0 / (mu0 omega du) (eq. 3); for table a comma list
    /// or start:stop:count.
    #[arg(long, allow_hyphen_values = true)]
    vbar: Option<String>,
    /// Velocity vhat = (kx/kz) v0 / (mu0 omega u0) (eq. 15), vbar = vhat / amp; for table a comma
    /// list or start:stop:count.
    #[arg(long, allow_hyphen_values = true)]
    vhat: Option<String>,
}

// `--method`: the command-line face of `fricosc::shape::Method`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum MethodArg {
    /// The event-driven exact solver.
    Exact,
    /// The seed's time-stepping scheme.
    Stepping,
}

/// The solver: exact, or the seed's time stepping (for comparison and validation).
#[derive(Args)]
struct MethodArgs {
    /// exact (event-driven, default) or stepping (the seed's time-stepping scheme).
    #[arg(long, value_enum, default_value = "exact")]
    method: MethodArg,
    /// Time steps per period, 1 to 1e8 (only with --method stepping; default 1000).
    #[arg(long, allow_hyphen_values = true)]
    steps_per_period: Option<usize>,
    /// Springs of an MDR foundation, 1 to 1e8 (only with --method stepping; default 1000).
    #[arg(long, allow_hyphen_values = true)]
    springs: Option<usize>,
}

/// Default resolution of the stepping peer.
const DEFAULT_STEPPING: usize = 1000;

impl MethodArgs {
    /// The stepping resolution, or an error for stepping options without `--method stepping`.
    fn stepping(&self) -> Result<Option<Stepping>> {
        if self.method != MethodArg::Stepping {
            if let Some(name) = [("--steps-per-period", self.steps_per_period), ("--springs", self.springs)]
                .iter()
                .find(|(_, v)| v.is_some())
                .map(|(n, _)| *n)
            {
                return Err(Error::Parse {
                    context: name.into(),
                    reason: "applies only with --method stepping".into(),
                });
            }
            return Ok(None);
        }
        Ok(Some(Stepping {
            steps_per_period: self.steps_per_period.unwrap_or(DEFAULT_STEPPING),
            springs: self.springs.unwrap_or(DEFAULT_STEPPING),
        }))
    }
}

/// Options shared by `point` and `table`.
#[derive(Args)]
struct Common {
    /// Indenter shape: flat, parabolic, cone, power:N, profile:FILE@U0, gx:FILE@U0.
    #[arg(long, default_value = "flat")]
    shape: String,
    #[command(flatten)]
    velocity: Velocity,
    #[command(flatten)]
    method: MethodArgs,
    /// Relative quadrature tolerance for MDR shapes (default: as accurate as f64 allows).
    #[arg(long, allow_hyphen_values = true)]
    tol: Option<String>,
}

#[derive(Args)]
struct PointArgs {
    #[command(flatten)]
    common: Common,
    /// Amplitude du/u0 (>= 0).
    #[arg(long, allow_hyphen_values = true)]
    amp: String,
}

#[derive(Args)]
struct TableArgs {
    #[command(flatten)]
    common: Common,
    /// Amplitudes du/u0: a comma list or start:stop:count.
    #[arg(long, allow_hyphen_values = true)]
    amp: String,
    /// Output format.
    #[arg(long, value_enum, default_value = "json")]
    format: Format,
}

fn tol_of(t: &Option<String>) -> Result<f64> {
    match t {
        Some(t) => check_tol(parse_number("--tol", t)?),
        None => Ok(fricosc::mdr::DEFAULT_TOL),
    }
}

fn vbar_of(vhat: f64, amp: f64) -> Result<f64> {
    if amp > 0.0 {
        let vbar = vhat / amp;
        if vbar.is_finite() {
            Ok(vbar)
        } else {
            Err(Error::param("vbar", vbar, &format!("vhat / amp = {vhat:?} / {amp:?} overflows double precision")))
        }
    } else {
        Err(Error::param("amp", amp, "--vhat needs amp > 0 (vbar = vhat / amp)"))
    }
}

fn io_err(e: io::Error) -> Error {
    Error::write("stdout", e)
}

/// The one path to stdout: the whole text at once, errors checked (a closed
/// pipe or a full disk is an `Error::Write`, never a panic).
fn emit(text: &str) -> Result<()> {
    let mut o = io::stdout().lock();
    o.write_all(text.as_bytes()).and_then(|()| o.flush()).map_err(io_err)
}

fn exact_point(shape: &Shape, vbar: f64, amp: f64, tol: f64) -> Result<serde_json::Value> {
    match shape {
        Shape::Flat => serde_json::to_value(fricosc::flat::point(vbar, amp)?),
        Shape::Power(n) => serde_json::to_value(fricosc::mdr::point(*n, vbar, amp, tol)?),
        Shape::Tabulated(..) | Shape::Registered(..) => {
            let e = evaluate_with(shape, vbar, amp, tol)?;
            // vbar and amp first, then the evaluation (interpolation_error only for tables).
            serde_json::to_value(e).map(|v| {
                let mut m = serde_json::Map::new();
                m.insert("vbar".into(), vbar.into());
                m.insert("amp".into(), amp.into());
                if let serde_json::Value::Object(o) = v {
                    m.extend(o);
                }
                serde_json::Value::Object(m)
            })
        }
    }
    .map_err(|e| Error::Parse { context: "output".into(), reason: e.to_string() })
}

fn point(a: PointArgs) -> Result<()> {
    let shape = Shape::parse(&a.common.shape)?;
    let amp = parse_number("--amp", &a.amp)?;
    let vbar = match (&a.common.velocity.vbar, &a.common.velocity.vhat) {
        (Some(v), _) => parse_number("--vbar", v)?,
        (None, Some(h)) => vbar_of(parse_number("--vhat", h)?, amp)?,
        (None, None) => unreachable!("clap requires one of --vbar, --vhat"),
    };
    let tol = tol_of(&a.common.tol)?;
    let body = match a.common.method.stepping()? {
        Some(st) => {
            let e = evaluate_stepping(&shape, vbar, amp, st)?;
            serde_json::json!({"vbar": vbar, "amp": amp, "mu_ratio": e.ratio.mu_ratio, "reduction": e.ratio.reduction,
                "method": "stepping", "steps": e.steps, "springs": e.springs, "period_change": e.period_change})
        }
        None => exact_point(&shape, vbar, amp, tol)?,
    };
    let mut obj = serde_json::Map::new();
    obj.insert("shape".into(), shape.name().into());
    if let serde_json::Value::Object(m) = body {
        obj.extend(m);
    }
    let json = serde_json::Value::Object(obj);
    let mut out = io::stdout().lock();
    serde_json::to_writer_pretty(&mut out, &json).map_err(|e| io_err(e.into()))?;
    writeln!(out).map_err(io_err)
}

fn table(a: TableArgs) -> Result<()> {
    let shape = Shape::parse(&a.common.shape)?;
    let tol = tol_of(&a.common.tol)?;
    let amps = parse_values("--amp", &a.amp)?;
    let (vels, is_vhat) = match (&a.common.velocity.vbar, &a.common.velocity.vhat) {
        (Some(v), _) => (parse_values("--vbar", v)?, false),
        (None, Some(h)) => (parse_values("--vhat", h)?, true),
        (None, None) => unreachable!("clap requires one of --vbar, --vhat"),
    };
    let total = amps.len() as u128 * vels.len() as u128;
    if total > fricosc::grid::MAX_LIST {
        return Err(Error::TooLarge {
            what: "table rows (amplitudes x velocities)".into(),
            count: total,
            limit: fricosc::grid::MAX_LIST,
        });
    }
    // Validate every input before the first byte is written.
    for &amp in &amps {
        fricosc::error::check_nonneg("amp", amp)?;
        for &v in &vels {
            let vbar = if is_vhat { vbar_of(v, amp)? } else { v };
            fricosc::error::check_nonneg(if is_vhat { "vhat" } else { "vbar" }, vbar)?;
        }
    }
    let mut cols = vec!["vbar", "amp", "mu_ratio", "reduction"];
    if is_vhat {
        cols.insert(0, "vhat");
    }
    let name = shape.name();
    let stepping = a.common.method.stepping()?;
    if let Some(st) = stepping {
        st.check(&shape)?;
    }
    // Every row is computed (in parallel, rayon) before the first byte is
    // written: an error in any row (a tabulated shape's range, an internal
    // error) leaves stdout empty. 40 bytes per row: 400 MB at the 10^7 limit.
    let pairs: Vec<(f64, f64)> = amps.iter().flat_map(|&amp| vels.iter().map(move |&v| (amp, v))).collect();
    let rows: Vec<[f64; 5]> = pairs
        .par_iter()
        .map(|&(amp, v)| {
            let vbar = if is_vhat { vbar_of(v, amp)? } else { v };
            let r = match stepping {
                Some(st) => evaluate_stepping(&shape, vbar, amp, st)?.ratio,
                None => evaluate_with(&shape, vbar, amp, tol)?.ratio,
            };
            Ok([v, vbar, amp, r.mu_ratio, r.reduction])
        })
        .collect::<Result<Vec<_>>>()?;
    drop(pairs);
    let mut w = TableWriter::new(io::BufWriter::new(io::stdout().lock()), a.format, &name, cols).map_err(io_err)?;
    for r in &rows {
        if is_vhat { w.row(r) } else { w.row(&r[1..]) }.map_err(io_err)?;
    }
    w.finish().map_err(io_err)
}

fn read_input(file: Option<String>) -> Result<(String, String)> {
    let path = file.unwrap_or_else(|| "-".into());
    let text = fricosc::input::read_capped(&path, fricosc::input::MAX_TABLE_BYTES)?;
    Ok((text, if path == "-" { "stdin".into() } else { path }))
}

fn run_batch(file: Option<String>, stepping: Option<Stepping>) -> Result<()> {
    let (text, source) = read_input(file)?;
    let rows = batch::run(&text, &source, stepping)?;
    let mut out = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
    rows.write(&mut out).and_then(|()| out.flush()).map_err(io_err)
}

fn run_history(
    shape: &str,
    velocity: &Velocity,
    amp: &str,
    (periods, samples, springs): (usize, usize, usize),
    spring_at: Option<&str>,
    format: &str,
) -> Result<()> {
    let chosen = match spring_at {
        Some(t) => parse_values("--spring-at", t)?,
        None => vec![],
    };
    let shape = Shape::parse(shape)?;
    let amp = parse_number("--amp", amp)?;
    let vbar = match (&velocity.vbar, &velocity.vhat) {
        (Some(v), _) => parse_number("--vbar", v)?,
        (None, Some(h)) => vbar_of(parse_number("--vhat", h)?, amp)?,
        (None, None) => unreachable!("clap requires one of --vbar, --vhat"),
    };
    if !matches!(format, "json" | "csv" | "svg") {
        return Err(Error::Parse { context: "--format".into(), reason: format!("'{format}' is not json, csv or svg") });
    }
    let h = fricosc::history::history(&shape, vbar, amp, periods, samples, springs, &chosen)?;
    let text = match format {
        "json" => serde_json::to_string_pretty(&h)
            .map_err(|e| Error::Parse { context: "output".into(), reason: e.to_string() })?,
        "csv" => fricosc::history::to_csv(&h),
        _ => {
            let pts =
                |f: fn(&fricosc::history::Sample) -> f64| h.samples.iter().map(|x| (x.tau, f(x))).collect::<Vec<_>>();
            let ymax = h.samples.iter().map(|x| x.normal).fold(0.0, f64::max) * 1.05 + 1e-12;
            let series = [
                fricosc::plot::Series { label: "mu0 x normal force".into(), points: pts(|x| x.normal), dashed: false },
                fricosc::plot::Series {
                    label: "tangential force".into(),
                    points: pts(|x| x.tangential),
                    dashed: false,
                },
            ];
            let title = format!("{} vbar = {vbar}, du/u0 = {amp} ({})", h.shape, h.units);
            let tmax = h.samples.last().map_or(1.0, |x| x.tau);
            fricosc::plot::lines(&title, "omega t", "force", (0.0, tmax), (0.0, ymax), &series)
                .map_err(|e| Error::Parse { context: "plot".into(), reason: e })?
        }
    };
    emit(&format!("{text}\n"))
}

fn run_scene(files: Vec<String>, schema: bool, format: Format) -> Result<()> {
    if schema {
        return emit(&format!("{}\n", fricosc::scene::schema()));
    }
    if files.is_empty() {
        return Err(Error::Parse { context: "scene".into(), reason: "give a scene file (or --schema)".into() });
    }
    // Read and solve everything before the first byte is written.
    let scenes: Vec<Result<fricosc::scene::Scene>> = files
        .iter()
        .map(|f| {
            let text = fricosc::input::read_capped(f, fricosc::input::MAX_SMALL_BYTES)?;
            fricosc::scene::parse(&text, f)
        })
        .collect();
    let scenes = scenes.into_iter().collect::<Result<Vec<_>>>()?;
    // A progress bar on stderr only when it is a terminal and the work is long.
    let total: usize = scenes.iter().map(fricosc::scene::velocity_count).sum();
    let bar = (std::io::stderr().is_terminal() && total >= 2000).then(|| indicatif::ProgressBar::new(total as u64));
    let tick = |k: u64| {
        if let Some(b) = &bar {
            b.inc(k);
        }
    };
    let results: Vec<Result<fricosc::scene::SceneResult>> =
        scenes.par_iter().zip(&files).map(|(s, f)| fricosc::scene::solve_with_progress(s, f, &tick)).collect();
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let results = results.into_iter().collect::<Result<Vec<_>>>()?;
    for (r, f) in results.iter().zip(&files) {
        for w in &r.warnings {
            eprintln!("warning: {f}: {w}");
        }
    }
    let text = match format {
        Format::Csv => results.iter().map(fricosc::scene::to_csv).collect::<Vec<_>>().join("\n"),
        Format::Json => {
            let v = if results.len() == 1 { serde_json::to_value(&results[0]) } else { serde_json::to_value(&results) };
            v.and_then(|v| serde_json::to_string_pretty(&v))
                .map_err(|e| Error::Parse { context: "output".into(), reason: e.to_string() })?
        }
    };
    emit(&format!("{}\n", text.trim_end()))
}

/// An output directory must be named: `--out ""` would write into the current one.
fn check_out_dir(out: &str) -> Result<()> {
    if out.trim().is_empty() {
        return Err(Error::Parse { context: "--out".into(), reason: "the output directory is empty".into() });
    }
    if std::path::Path::new(out).exists() && !std::path::Path::new(out).is_dir() {
        return Err(Error::Parse { context: "--out".into(), reason: format!("'{out}' exists and is not a directory") });
    }
    Ok(())
}

fn run_bench(out: &str, quick: bool) -> Result<()> {
    check_out_dir(out)?;
    let dir = std::path::Path::new(out);
    let werr = |e: String| Error::write(out, io::Error::other(e));
    std::fs::create_dir_all(dir).map_err(|e| Error::write(out, e))?;
    let report = fricosc::bench::run(quick);
    let json = serde_json::to_string_pretty(&report).map_err(|e| werr(e.to_string()))?;
    let svg = fricosc::bench::to_svg(&report).map_err(werr)?;
    for (name, text) in [
        ("work-precision.json", json),
        ("work-precision.csv", fricosc::bench::to_csv(&report)),
        ("work-precision.svg", svg),
    ] {
        std::fs::write(dir.join(name), text).map_err(|e| Error::write(out, e))?;
    }
    let mut o = String::new();
    for r in &report.ratios {
        o += &format!(
            "{}: exact {:.1e} s at error {:.1e}; stepping {:.1e} s at error {:.1e}; time ratio {:.2e}\n",
            r.case, r.exact_time_s, r.exact_error, r.stepping_time_s, r.stepping_error, r.time_ratio
        );
    }
    for f in &report.failures {
        o += &format!("failure: {f}\n");
    }
    emit(&format!("{o}wrote {out}/work-precision.{{json,csv,svg}}\n"))
}

/// Prints the comparison; `Ok(false)` when `--max-error` is exceeded.
fn run_validate(shape: &str, file: String, max_error: Option<String>) -> Result<bool> {
    let shape = Shape::parse(shape)?;
    let max_error = match max_error {
        Some(t) => Some(fricosc::error::check_nonneg("max-error", parse_number("--max-error", &t)?)?),
        None => None,
    };
    let (text, source) = read_input(Some(file))?;
    let table = fricosc::validate::read_table(&text, &source)?;
    drop(text);
    let mut v = fricosc::validate::validate(&shape, &table.rows)?;
    v.ignored_columns = table.ignored_columns;
    let mut out = io::BufWriter::new(io::stdout().lock());
    serde_json::to_writer_pretty(&mut out, &v).map_err(|e| io_err(e.into()))?;
    writeln!(out).map_err(io_err)?;
    out.flush().map_err(io_err)?;
    Ok(max_error.is_none_or(|e| v.max_abs_error <= e))
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            // No command at all: the full help, on stderr (it is a usage error, exit 2).
            if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                eprint!("{}", e.render());
                return ExitCode::from(2);
            }
            let code = if e.use_stderr() { 2 } else { 0 };
            if code == 0 {
                // --help and --version: printed through the checked path too.
                return match emit(&e.render().to_string()) {
                    Ok(()) => ExitCode::SUCCESS,
                    Err(err) if err.is_broken_pipe() => ExitCode::SUCCESS,
                    Err(err) => {
                        eprintln!("error: {err}");
                        ExitCode::from(2)
                    }
                };
            } else {
                // One line: clap's message up to its usage block, joined.
                let msg = e.to_string();
                let text: Vec<&str> = msg
                    .lines()
                    .map(str::trim)
                    .take_while(|l| !l.starts_with("Usage:"))
                    .filter(|l| !l.is_empty())
                    .collect();
                eprintln!("{}", text.join(" "));
            }
            return ExitCode::from(code);
        }
    };
    let result = match cli.command {
        Command::Point(a) => point(a),
        Command::Table(a) => table(a),
        Command::Bench { out, quick } => run_bench(&out, quick),
        Command::Scene { files, schema, format } => run_scene(files, schema, format),
        Command::Figures { out } => check_out_dir(&out)
            .and_then(|()| fricosc::figures::write_all(std::path::Path::new(&out)))
            .and_then(|names| emit(&format!("wrote {} figures to {out}: {}\n", names.len(), names.join(", ")))),
        Command::History { shape, velocity, amp, periods, samples, springs, spring_at, format } => {
            run_history(&shape, &velocity, &amp, (periods, samples, springs), spring_at.as_deref(), &format)
        }
        Command::Claims { format } => {
            let claims = fricosc::claims::check();
            match format.as_str() {
                "markdown" => emit(&fricosc::claims::to_markdown(&claims)),
                "json" => serde_json::to_string_pretty(&claims)
                    .map_err(|e| Error::Parse { context: "output".into(), reason: e.to_string() })
                    .and_then(|t| emit(&format!("{t}\n"))),
                other => Err(Error::Parse {
                    context: "--format".into(),
                    reason: format!("'{other}' is neither markdown nor json"),
                }),
            }
        }
        Command::Stress { points, seed } => {
            if points > 100_000_000 {
                Err(Error::TooLarge { what: "stress points".into(), count: points as u128, limit: 100_000_000 })
            } else {
                let r = fricosc::stress::run(points, seed, &fricosc::stress::default_shapes());
                let ok = r.failure_count == 0;
                let printed = serde_json::to_string_pretty(&r)
                    .map_err(|e| Error::Parse { context: "output".into(), reason: e.to_string() })
                    .and_then(|t| emit(&format!("{t}\n")));
                match printed {
                    Ok(()) if !ok => return ExitCode::from(1),
                    other => other,
                }
            }
        }
        Command::Batch { file, method } => method.stepping().and_then(|st| run_batch(file, st)),
        Command::Validate { shape, file, max_error } => match run_validate(&shape, file, max_error) {
            Ok(true) => Ok(()),
            Ok(false) => return ExitCode::from(1),
            Err(e) => Err(e),
        },
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader went away (`| head`): end quietly, as ripgrep does.
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e @ Error::Internal { .. }) => {
            eprintln!("error: {e}");
            ExitCode::from(3)
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
