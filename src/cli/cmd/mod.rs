//! The subcommands, one file each, and what they share: the common options,
//! the one checked path to stdout, bounded input, and the outcome that `main`
//! turns into an exit code.

use crate::cli::error::{Error, Result};
use crate::cli::grid::parse_number;
use crate::shape::check_tol;
use crate::stepper::Stepping;
use clap::Args;
use std::io::{self, Write};

pub mod batch;
pub mod bench;
pub mod claims;
pub mod figures;
pub mod history;
pub mod plot;
pub mod point;
pub mod scene;
pub mod stress;
pub mod suite;
pub mod table;
pub mod validate;

/// What a command found: `main` maps `Negative` to exit code 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// Success (exit 0).
    Done,
    /// A negative answer: `validate` beyond `--max-error`, a failed `stress` check (exit 1).
    Negative,
}

/// The velocity, as vbar (eq. 3) or vhat (eq. 15, vbar = vhat / amp).
#[derive(Args)]
#[group(required = true, multiple = false)]
pub struct Velocity {
    /// Dimensionless velocity vbar = (kx/kz) v0 / (mu0 omega du) (eq. 3); for table and plot a comma list
    /// or start:stop:count.
    #[arg(long, allow_hyphen_values = true)]
    pub vbar: Option<String>,
    /// Velocity vhat = (kx/kz) v0 / (mu0 omega u0) (eq. 15), vbar = vhat / amp; for table and plot a comma
    /// list or start:stop:count.
    #[arg(long, allow_hyphen_values = true)]
    pub vhat: Option<String>,
}

// `--method`: the command-line face of `crate::shape::Method`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MethodArg {
    /// The event-driven exact solver.
    Exact,
    /// The seed's time-stepping scheme.
    Stepping,
}

/// The solver: exact, or the seed's time stepping (for comparison and validation).
#[derive(Args)]
pub struct MethodArgs {
    /// exact (event-driven, default) or stepping (the seed's time-stepping scheme).
    #[arg(long, value_enum, default_value = "exact")]
    pub method: MethodArg,
    /// Time steps per period, 1 to 1e8 (only with --method stepping; default 1000).
    #[arg(long, allow_hyphen_values = true)]
    pub steps_per_period: Option<usize>,
    /// Springs of an MDR foundation, 1 to 1e8 (only with --method stepping; default 1000).
    #[arg(long, allow_hyphen_values = true)]
    pub springs: Option<usize>,
}

/// Default resolution of the stepping peer.
pub const DEFAULT_STEPPING: usize = 1000;

impl MethodArgs {
    /// The stepping resolution, or an error for stepping options without `--method stepping`.
    pub fn stepping(&self) -> Result<Option<Stepping>> {
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
pub struct Common {
    /// Indenter shape: flat, parabolic, cone, power:N, profile:FILE@U0, gx:FILE@U0.
    #[arg(long, default_value = "flat")]
    pub shape: String,
    #[command(flatten)]
    pub velocity: Velocity,
    #[command(flatten)]
    pub method: MethodArgs,
    /// Relative quadrature tolerance for MDR shapes (default: as accurate as f64 allows).
    #[arg(long, allow_hyphen_values = true)]
    pub tol: Option<String>,
}

pub fn tol_of(t: &Option<String>) -> Result<f64> {
    match t {
        Some(t) => Ok(check_tol(parse_number("--tol", t)?)?),
        None => Ok(crate::DEFAULT_TOL),
    }
}

pub fn vbar_of(vhat: f64, amp: f64) -> Result<f64> {
    Ok(crate::vbar_from_vhat(vhat, amp)?)
}

pub fn io_err(e: io::Error) -> Error {
    Error::write("stdout", e)
}

/// The one path to stdout: the whole text at once, errors checked (a closed
/// pipe or a full disk is an `Error::Write`, never a panic).
pub fn emit(text: &str) -> Result<()> {
    emit_bytes(text.as_bytes())
}

/// [`emit`] for bytes (a PNG).
pub fn emit_bytes(bytes: &[u8]) -> Result<()> {
    let mut o = io::stdout().lock();
    o.write_all(bytes).and_then(|()| o.flush()).map_err(io_err)
}

/// An SVG document rendered as PNG (an internal error if our own SVG does not render).
pub fn png_of(svg: &str) -> Result<Vec<u8>> {
    crate::cli::plot::png(svg).map_err(|e| Error::Internal { what: format!("rendering the PNG: {e}") })
}

/// Whether a drawing's file name asks for a PNG (`.png`) or an SVG (`.svg`);
/// any other name is refused before any work is done.
pub fn drawing_kind(option: &str, path: &str) -> Result<bool> {
    let lower = path.to_ascii_lowercase();
    if lower.ends_with(".png") {
        Ok(true)
    } else if lower.ends_with(".svg") {
        Ok(false)
    } else {
        Err(Error::Parse { context: option.into(), reason: format!("'{path}' must end in .svg or .png") })
    }
}

/// Write a drawing to `path` as SVG or PNG, by its extension ([`drawing_kind`]).
pub fn write_drawing(option: &str, path: &str, svg: &str) -> Result<()> {
    if drawing_kind(option, path)? {
        let png = png_of(svg)?;
        std::fs::write(path, png).map_err(|e| Error::write(path, e))
    } else {
        write_file(option, path, svg)
    }
}

pub fn read_input(file: Option<String>) -> Result<(String, String)> {
    let path = file.unwrap_or_else(|| "-".into());
    let text = crate::cli::input::read_capped(&path, crate::cli::input::MAX_TABLE_BYTES)?;
    Ok((text, if path == "-" { "stdin".into() } else { path }))
}

/// An output directory must be named: `--out ""` would write into the current one.
pub fn check_out_dir(out: &str) -> Result<()> {
    if out.trim().is_empty() {
        return Err(Error::Parse { context: "--out".into(), reason: "the output directory is empty".into() });
    }
    if std::path::Path::new(out).exists() && !std::path::Path::new(out).is_dir() {
        return Err(Error::Parse { context: "--out".into(), reason: format!("'{out}' exists and is not a directory") });
    }
    Ok(())
}

/// JSON text of a result; our own types always serialise, so a failure is internal.
pub fn to_json<T: serde::Serialize>(value: &T) -> Result<String> {
    serde_json::to_string_pretty(value).map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })
}

/// Write `text` to the file `path` (an empty path is refused; a failed write is
/// an error naming the path).
pub fn write_file(option: &str, path: &str, text: &str) -> Result<()> {
    if path.trim().is_empty() {
        return Err(Error::Parse { context: option.into(), reason: "the file name is empty".into() });
    }
    std::fs::write(path, text).map_err(|e| Error::write(path, e))
}
