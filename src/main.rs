//! `fricosc`: command-line interface, a thin layer over the library.
//!
//! Exit codes: 0 success, 2 error (one line on stderr, nothing on stdout).

use clap::{Args, Parser, Subcommand};
use fricosc::batch;
use fricosc::error::{Error, Result};
use fricosc::grid::{parse_number, parse_values};
use fricosc::output::{Format, TableWriter};
use fricosc::shape::{check_tol, evaluate_with, Shape};
use rayon::prelude::*;
use std::io::{self, Read, Write};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "fricosc",
    version,
    about = "Exact friction under normal oscillation (Popov, Popov, Popov 2017)"
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
    /// A JSON array of {shape, vbar, amp, ...} from FILE or stdin; the same array with mu_ratio and reduction added.
    Batch {
        /// Input file; stdin when absent or '-'.
        file: Option<String>,
    },
}

/// The velocity, as vbar (eq. 3) or vhat (eq. 15, vbar = vhat / amp).
#[derive(Args)]
#[group(required = true, multiple = false)]
struct Velocity {
    /// Dimensionless velocity vbar = (kx/kz) v0 / (mu0 omega du) (eq. 3).
    #[arg(long, allow_hyphen_values = true)]
    vbar: Option<String>,
    /// Velocity vhat = (kx/kz) v0 / (mu0 omega u0) (eq. 15); vbar = vhat / amp.
    #[arg(long, allow_hyphen_values = true)]
    vhat: Option<String>,
}

/// Options shared by `point` and `table`.
#[derive(Args)]
struct Common {
    /// Indenter shape: flat, parabolic, cone, power:N.
    #[arg(long, default_value = "flat")]
    shape: String,
    #[command(flatten)]
    velocity: Velocity,
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
        Ok(vhat / amp)
    } else {
        Err(Error::param("amp", amp, "--vhat needs amp > 0 (vbar = vhat / amp)"))
    }
}

fn io_err(e: io::Error) -> Error {
    Error::Io {
        path: "stdout".into(),
        reason: e.to_string(),
    }
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
    let body = match shape {
        Shape::Flat => serde_json::to_value(fricosc::flat::point(vbar, amp)?),
        Shape::Power(n) => serde_json::to_value(fricosc::mdr::point(n, vbar, amp, tol)?),
    }
    .map_err(|e| Error::Parse {
        context: "output".into(),
        reason: e.to_string(),
    })?;
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
            what: "table".into(),
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
    let mut w = TableWriter::new(io::BufWriter::new(io::stdout().lock()), a.format, &name, cols).map_err(io_err)?;
    // Rows in parallel (rayon), written in order, a bounded chunk at a time.
    let pairs: Vec<(f64, f64)> = amps
        .iter()
        .flat_map(|&amp| vels.iter().map(move |&v| (amp, v)))
        .collect();
    for chunk in pairs.chunks(1 << 15) {
        let rows: Vec<Result<[f64; 5]>> = chunk
            .par_iter()
            .map(|&(amp, v)| {
                let vbar = if is_vhat { vbar_of(v, amp)? } else { v };
                let e = evaluate_with(&shape, vbar, amp, tol)?;
                Ok([v, vbar, amp, e.ratio.mu_ratio, e.ratio.reduction])
            })
            .collect();
        for row in rows {
            let r = row?;
            if is_vhat {
                w.row(&name, &r)
            } else {
                w.row(&name, &r[1..])
            }
            .map_err(io_err)?;
        }
    }
    w.finish().map_err(io_err)
}

fn read_input(file: Option<String>) -> Result<(String, String)> {
    match file.as_deref() {
        None | Some("-") => {
            let mut s = String::new();
            io::stdin().read_to_string(&mut s).map_err(|e| Error::Io {
                path: "stdin".into(),
                reason: e.to_string(),
            })?;
            Ok((s, "stdin".into()))
        }
        Some(p) => {
            let s = std::fs::read_to_string(p).map_err(|e| Error::Io {
                path: p.into(),
                reason: e.to_string(),
            })?;
            Ok((s, p.into()))
        }
    }
}

fn run_batch(file: Option<String>) -> Result<()> {
    let (text, source) = read_input(file)?;
    let rows = batch::run(&text, &source)?;
    let mut out = io::BufWriter::new(io::stdout().lock());
    out.write_all(b"[").map_err(io_err)?;
    for (i, r) in rows.iter().enumerate() {
        out.write_all(if i == 0 { b"\n" } else { b",\n" }).map_err(io_err)?;
        serde_json::to_writer(&mut out, r).map_err(|e| io_err(e.into()))?;
    }
    out.write_all(b"\n]\n").map_err(io_err)?;
    out.flush().map_err(io_err)
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            if code == 0 {
                let _ = e.print();
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
        Command::Batch { file } => run_batch(file),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
