//! `fricosc`: command-line interface, a thin layer over the library: the
//! options (clap) and the dispatch to one file per subcommand in `cmd/`.
//!
//! Exit codes: 0 success (also when the reader closes the pipe), 1 a negative
//! answer (`validate`, `stress`), 2 bad input or a failed read/write (one line
//! on stderr, nothing on stdout), 3 an internal error (`Error::Internal`).

use clap::{Parser, Subcommand};
use fricosc::cli::cmd::{self, emit, MethodArgs, Outcome, Velocity};
use fricosc::cli::error::{Error, Result};
use fricosc::cli::output::Format;
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
    Point(cmd::point::PointArgs),
    /// A grid of amplitudes x velocities: JSON or CSV.
    Table(cmd::table::TableArgs),
    /// Draw mu/mu0 against vbar or vhat, one curve per amplitude, as SVG or PNG.
    Plot(cmd::plot::PlotArgs),
    /// Compare a table of (vbar, amp, mu_ratio) from another code (CSV or JSON) with the exact values.
    /// Exit 1 when the largest error exceeds --max-error.
    Validate {
        /// Shape of the table's contact, where the table names none (a JSON 'shape' field or a
        /// CSV 'shape' column decides; giving a different one is an error). Default: flat.
        #[arg(long)]
        shape: Option<String>,
        /// Table file (JSON or CSV; columns vbar or vhat, amp, mu_ratio or mu); stdin when '-'.
        /// With --series: several, each with its resolution (run@1000.csv, or run.csv@1000).
        #[arg(required = true)]
        files: Vec<String>,
        /// A convergence study: the same table at several resolutions (e.g. steps per period);
        /// reports the observed order per row and regime, the error constant, the Richardson value
        /// and the resolution needed for --target.
        #[arg(long)]
        series: bool,
        /// With --series: the target error for the needed resolution.
        #[arg(long, allow_hyphen_values = true)]
        target: Option<String>,
        /// With --series: draw the errors against the resolution (SVG) into this file.
        #[arg(long)]
        plot: Option<String>,
        /// The file is a force history (CSV: tau or t, tangential, optionally normal; forces in
        /// units of kz u0 and mu0 kz u0) of the flat punch at --vbar (or --vhat) and --amp: errors
        /// over the last period, periodicity, and the stick/slip/contact events with timing errors.
        #[arg(long)]
        history: bool,
        /// With --history: the velocity vbar (eq. 3).
        #[arg(long, allow_hyphen_values = true)]
        vbar: Option<String>,
        /// With --history: the velocity vhat (eq. 15), instead of --vbar.
        #[arg(long, allow_hyphen_values = true)]
        vhat: Option<String>,
        /// With --history: the amplitude du/u0.
        #[arg(long, allow_hyphen_values = true)]
        amp: Option<String>,
        /// With --history and a time column t: the angular frequency (tau = omega t); without it
        /// the period and phase are found from the normal force's maxima (at tau = pi).
        #[arg(long, allow_hyphen_values = true)]
        omega: Option<String>,
        /// With --history: forces in your units, where the static normal force kz u0 is this value
        /// (normal / kz_u0; tangential / (mu0 kz_u0) with --mu0). Default: already normalised.
        #[arg(long, allow_hyphen_values = true)]
        kz_u0: Option<String>,
        /// Largest acceptable |mu_ratio - exact| (exit 1 beyond it).
        #[arg(long, allow_hyphen_values = true)]
        max_error: Option<String>,
        /// What a vbar = 0 row is compared with: 'sliding' (the limit vbar -> 0+, mu_static) or
        /// 'relaxed' (a stepper started from relaxed springs at exactly zero velocity: 0).
        #[arg(long, default_value = "sliding")]
        at_rest: String,
        /// Coulomb coefficient, for a table that gives 'mu' (mu_ratio = mu / mu0).
        #[arg(long, allow_hyphen_values = true)]
        mu0: Option<String>,
        /// How far a value may leave [0, 1], differ from 1 above vbar = 1, or decrease in vbar
        /// before it is reported as a finding.
        #[arg(long, default_value = "1e-9", allow_hyphen_values = true)]
        tolerance: String,
        /// summary (a short report; the default on a terminal), json (the default otherwise) or csv
        /// (one line per row).
        #[arg(long)]
        format: Option<String>,
    },
    /// The reference suite: canonical cases with error bounds, a manifest and a README (--out),
    /// or verify a copy of it (--check; exit 1 when a file differs).
    Suite {
        /// Write the suite into this directory (created if missing).
        #[arg(long)]
        out: Option<String>,
        /// Check the suite in this directory against the current solver.
        #[arg(long)]
        check: Option<String>,
    },
    /// Work-precision benchmark: exact solver vs time stepping; writes JSON, CSV, SVG and PNG to DIR.
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
        /// markdown (default), json or csv.
        #[arg(long, default_value = "markdown")]
        format: String,
    },
    /// Normal and tangential force over time (the seed's Fig. 2), exact: JSON, CSV, SVG or PNG.
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
        /// json, csv, svg or png (the seed's Fig. 2, 300 dpi).
        #[arg(long, default_value = "json")]
        format: String,
        /// exact (default) or stepping: the seed's time-stepping scheme (flat punch), one row per
        /// step, the same columns (for comparing with validate --history).
        #[arg(long, value_enum, default_value = "exact")]
        method: cmd::MethodArg,
        /// Time steps per period with --method stepping (default 1000).
        #[arg(long, allow_hyphen_values = true)]
        steps_per_period: Option<usize>,
    },
    /// The seed's Figs. 3, 4, 5 (+ inset), 7, 8: exact curves and the seed's approximations, as JSON, CSV, SVG and PNG.
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
        /// Also draw mu_macro against the velocity, one curve per amplitude (the seed's Fig. 9
        /// layout), to this file: SVG or PNG by its extension.
        #[arg(long)]
        plot: Option<String>,
    },
    /// Rows of {shape, vbar, amp, ...} (a JSON array, JSON Lines or CSV) from FILE or stdin; the same rows with mu_ratio and reduction added.
    Batch {
        /// Input file; stdin when absent or '-'.
        file: Option<String>,
        /// Input and output format: json (an array), jsonl (one object per line, streamed) or csv
        /// (streamed); default: by the file's extension (.jsonl, .ndjson, .csv), else json.
        #[arg(long)]
        format: Option<String>,
        #[command(flatten)]
        method: MethodArgs,
    },
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
    let done = |r: Result<()>| r.map(|()| Outcome::Done);
    let result = match cli.command {
        Command::Point(a) => done(cmd::point::run(a)),
        Command::Table(a) => done(cmd::table::run(a)),
        Command::Plot(a) => done(cmd::plot::run(a)),
        Command::Bench { out, quick } => done(cmd::bench::run(&out, quick)),
        Command::Scene { files, schema, format, plot } => done(cmd::scene::run(files, schema, format, plot)),
        Command::Figures { out } => done(cmd::figures::run(&out)),
        Command::History {
            shape,
            velocity,
            amp,
            periods,
            samples,
            springs,
            spring_at,
            format,
            method,
            steps_per_period,
        } => {
            let stepping = match (method, steps_per_period) {
                (cmd::MethodArg::Stepping, m) => Ok(Some(m.unwrap_or(cmd::DEFAULT_STEPPING))),
                (_, Some(_)) => Err(Error::Parse {
                    context: "--steps-per-period".into(),
                    reason: "applies only with --method stepping".into(),
                }),
                (_, None) => Ok(None),
            };
            done(stepping.and_then(|st| {
                cmd::history::run(
                    &shape,
                    &velocity,
                    &amp,
                    (periods, samples, springs),
                    spring_at.as_deref(),
                    &format,
                    st,
                )
            }))
        }
        Command::Claims { format } => done(cmd::claims::run(&format)),
        Command::Suite { out, check } => cmd::suite::run(out, check),
        Command::Stress { points, seed } => cmd::stress::run(points, seed),
        Command::Batch { file, format, method } => {
            done(method.stepping().and_then(|st| cmd::batch::run(file, format, st)))
        }
        Command::Validate {
            shape,
            files,
            series,
            target,
            plot,
            history,
            vbar,
            vhat,
            amp,
            omega,
            kz_u0,
            max_error,
            at_rest,
            mu0,
            tolerance,
            format,
        } => cmd::validate::run(cmd::validate::ValidateArgs {
            shape,
            files,
            series,
            target,
            plot,
            history: history.then_some(cmd::validate::HistoryArgs { vbar, vhat, amp, omega, kz_u0 }),
            max_error,
            at_rest,
            mu0,
            tolerance,
            format,
        }),
    };
    // Every exit code is decided here.
    match result {
        Ok(Outcome::Done) => ExitCode::SUCCESS,
        Ok(Outcome::Negative) => ExitCode::from(1),
        // The reader went away (`| head`): end quietly, as ripgrep does.
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
