//! The subcommands (one module each, beside this file: its options and its
//! run) and what they share: the common options (typed by clap's value
//! parsers), the one checked path to stdout, bounded input, and the outcome
//! that `main` turns into an exit code.

use crate::error::{Error, Result};
use crate::{batch, bench, claims, figures, fit, history, plot, point, scene, suite, table, validate};
use clap::{Args, Subcommand};
use fricosc::stepper::Stepping;
use std::io::{self, Write};

/// What a command found: `main` maps `Negative` to exit code 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// Success (exit 0).
    Done,
    /// A negative answer: `validate` with findings or beyond `--max-error`, a
    /// stale suite (exit 1).
    Negative,
}

/// The subcommands.
#[derive(Subcommand)]
pub enum Command {
    /// One point, with regime and events: JSON.
    Point(point::PointArgs),
    /// A grid of amplitudes x velocities: JSON or CSV.
    Table(table::TableArgs),
    /// Draw mu/mu0 against vbar or vhat, one curve per amplitude, as SVG or PNG.
    Plot(plot::PlotArgs),
    /// Compare another code's table (vbar, amp, mu_ratio; CSV or JSON), force history or convergence
    /// series with the exact values. Exit 1 on a finding or an error above --max-error.
    Validate(validate::ValidateArgs),
    /// Fit the model to measured friction (v0, du, frequency or omega, mu, sigma): mu0, kx/kz and u0
    /// with standard errors, the covariance and chi-square.
    Fit(fit::FitArgs),
    /// The reference suite: canonical cases with error bounds, a manifest and a README (--out),
    /// or verify a copy of it (--check; exit 1 when a file differs).
    Suite(suite::SuiteArgs),
    /// Work-precision benchmark: exact solver vs time stepping; writes JSON, CSV, SVG and PNG to DIR.
    Bench(bench::BenchArgs),
    /// Every quantitative claim of the seed, checked against the exact solver.
    Claims(claims::ClaimsArgs),
    /// Normal and tangential force over time (the seed's Fig. 2), exact: JSON, CSV, SVG or PNG.
    History(history::HistoryArgs),
    /// The seed's Figs. 3, 4, 5 (+ inset), 7, 8: exact curves and the seed's approximations, as JSON, CSV, SVG
    /// and PNG.
    Figures(figures::FiguresArgs),
    /// Physical scenes (JSON, SI units): mu, forces and velocities in physical units.
    Scene(scene::SceneArgs),
    /// Rows of {shape, vbar, amp, ...} (a JSON array, JSON Lines or CSV) from FILE or stdin; the same rows with
    /// mu_ratio and reduction added.
    Batch(batch::BatchArgs),
}

impl Command {
    /// Run the command.
    pub fn run(self) -> Result<Outcome> {
        let done = |r: Result<()>| r.map(|()| Outcome::Done);
        match self {
            Command::Point(a) => done(point::run(a)),
            Command::Table(a) => done(table::run(a)),
            Command::Plot(a) => done(plot::run(a)),
            Command::Validate(a) => validate::run(a),
            Command::Fit(a) => fit::run(a),
            Command::Suite(a) => suite::run(a),
            Command::Bench(a) => done(bench::run(a)),
            Command::Claims(a) => done(claims::run(a)),
            Command::History(a) => done(history::run(a)),
            Command::Figures(a) => done(figures::run(a)),
            Command::Scene(a) => done(scene::run(a)),
            Command::Batch(a) => done(batch::run(a)),
        }
    }
}

/// clap's value parser of a number: finite (`-0` is 0).
pub fn number(text: &str) -> std::result::Result<f64, String> {
    crate::grid::number(text)
}

/// clap's value parser of a number `>= 0`.
pub fn nonneg(text: &str) -> std::result::Result<f64, String> {
    let x = number(text)?;
    if x < 0.0 {
        return Err(format!("{x:?} must be >= 0"));
    }
    Ok(x)
}

/// clap's value parser of a number `> 0`.
pub fn positive(text: &str) -> std::result::Result<f64, String> {
    let x = number(text)?;
    if x <= 0.0 {
        return Err(format!("{x:?} must be > 0"));
    }
    Ok(x)
}

/// clap's value parser of a quadrature tolerance: finite, in `(0, 1)`.
pub fn tolerance(text: &str) -> std::result::Result<f64, String> {
    let tol = number(text)?;
    fricosc::Conditions::vbar(0.0, 0.0).and_then(|c| c.with_tol(tol)).map(|_| tol).map_err(|e| e.to_string())
}

/// A list of values: a comma list or `start:stop:count` ([`crate::grid::values`]).
#[derive(Debug, Clone, PartialEq)]
pub struct List(pub Vec<f64>);

/// clap's value parser of a [`List`].
pub fn list(text: &str) -> std::result::Result<List, String> {
    crate::grid::values(text).map(List)
}

/// The velocity of one point, as vbar (eq. 3) or vhat (eq. 15, vbar = vhat / amp).
#[derive(Args)]
#[group(required = true, multiple = false)]
pub struct VelocityPoint {
    /// Dimensionless velocity vbar = (kx/kz) v0 / (mu0 omega du) (eq. 3).
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub vbar: Option<f64>,
    /// Velocity vhat = (kx/kz) v0 / (mu0 omega u0) (eq. 15), vbar = vhat / amp.
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub vhat: Option<f64>,
}

impl VelocityPoint {
    /// The velocity as given.
    pub fn velocity(&self) -> Result<fricosc::Velocity> {
        match (self.vbar, self.vhat) {
            (Some(v), _) => Ok(fricosc::Velocity::Vbar(v)),
            (None, Some(h)) => Ok(fricosc::Velocity::Vhat(h)),
            (None, None) => Err(Error::Parse { context: "velocity".into(), reason: "give --vbar or --vhat".into() }),
        }
    }
}

/// The velocities of a table or plot: lists of vbar (eq. 3) or vhat (eq. 15).
#[derive(Args)]
#[group(required = true, multiple = false)]
pub struct VelocityList {
    /// Dimensionless velocities vbar = (kx/kz) v0 / (mu0 omega du) (eq. 3): a comma list or start:stop:count.
    #[arg(long, allow_hyphen_values = true, value_parser = list)]
    pub vbar: Option<List>,
    /// Velocities vhat = (kx/kz) v0 / (mu0 omega u0) (eq. 15), vbar = vhat / amp: a comma list or
    /// start:stop:count.
    #[arg(long, allow_hyphen_values = true, value_parser = list)]
    pub vhat: Option<List>,
    /// table: velocities as ratios vhat/T = v0/(omega dx) to the tangential amplitude, each row's
    /// vhat = this times its --tangential-amp (the rigid-body limit T -> infinity at fixed vhat/T).
    #[arg(long, allow_hyphen_values = true, value_parser = list, requires = "tangential_amp")]
    pub vhat_over_t: Option<List>,
}

impl VelocityList {
    /// The values and whether they are `vhat` (or `vhat/T`: [`VelocityList::over_t`]).
    pub fn values(&self) -> (&[f64], bool) {
        match (&self.vbar, &self.vhat, &self.vhat_over_t) {
            (Some(v), ..) => (&v.0, false),
            (None, Some(h), _) | (None, None, Some(h)) => (&h.0, true),
            (None, None, None) => (&[], false),
        }
    }

    /// Whether the values are `vhat/T`.
    pub fn over_t(&self) -> bool {
        self.vhat_over_t.is_some()
    }
}

/// Oscillation in the sliding direction for one point (`Conditions::with_tangential`).
#[derive(Args)]
pub struct TangentialPoint {
    /// Amplitude of an oscillation in the sliding direction, dx/l in pre-slip lengths l = mu0 u0 kz/kx
    /// (>= 0, at most 1e6; 0 is the seed's problem, bit for bit). Needs the velocity as --vhat.
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub tangential_amp: Option<f64>,
    /// Its phase against the normal oscillation, radians (default 0): the body moves as
    /// vhat tau + T sin(tau + phase) while the indentation is u0 - du cos tau.
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "tangential_amp")]
    pub phase: Option<f64>,
}

impl TangentialPoint {
    /// The tangential oscillation `(T, phase)`, if given; it needs the velocity as `--vhat`.
    pub fn oscillation(&self, velocity: &VelocityPoint) -> Result<Option<(f64, f64)>> {
        let Some(t) = self.tangential_amp else { return Ok(None) };
        vhat_for_tangential(velocity.vbar.is_some(), velocity.vhat)?;
        let phase = self.phase.unwrap_or(0.0);
        warn_degrees(&[phase]);
        Ok(Some((t, phase)))
    }
}

/// The system's mass and stiffness for one point (`fricosc::system`).
#[derive(Args)]
pub struct SystemPoint {
    /// The system's tangential stiffness over the contact's, kappa = K/kx (> 0; without it the
    /// system is stiff, the seed's problem).
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub system_stiffness: Option<f64>,
    /// With --system-stiffness: omega over the contact's natural frequency sqrt(kx/m) (default 0:
    /// a massless body).
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "system_stiffness")]
    pub frequency_ratio: Option<f64>,
    /// With --system-stiffness: the system's damping ratio zeta (default 0).
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "system_stiffness")]
    pub damping: Option<f64>,
}

impl SystemPoint {
    /// The system, if given, with a curved body's `springs` (by default
    /// [`fricosc::system::DEFAULT_SPRINGS`]).
    pub fn system(&self, springs: Option<usize>) -> Result<Option<fricosc::system::System>> {
        let Some(k) = self.system_stiffness else { return Ok(None) };
        let sys = fricosc::system::System::new(k, self.frequency_ratio.unwrap_or(0.0), self.damping.unwrap_or(0.0))?;
        Ok(Some(match springs {
            Some(n) => sys.with_springs(n)?,
            None => sys,
        }))
    }
}

/// One point's drive: its velocity, amplitude, tangential oscillation and system.
#[derive(Args)]
pub struct Drive {
    #[command(flatten)]
    pub velocity: VelocityPoint,
    /// Amplitude du/u0 (>= 0).
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub amp: f64,
    #[command(flatten)]
    pub tangential: TangentialPoint,
    #[command(flatten)]
    pub transverse: TransversePoint,
    #[command(flatten)]
    pub system: SystemPoint,
}

impl Drive {
    /// The conditions of the point at the default tolerance ([`conditions`]),
    /// with the oscillation across the sliding direction if given.
    pub fn conditions(&self) -> Result<fricosc::Conditions> {
        let tangential = self.tangential.oscillation(&self.velocity)?;
        match self.transverse.oscillation()? {
            // The plane asks for vhat only: amp = 0 is the transverse oscillation alone.
            Some(w) => Ok(match (self.velocity.velocity()?, tangential) {
                (v, Some((t, phase))) => conditions(v, self.amp, Some((t, phase)))?,
                (fricosc::Velocity::Vhat(v), None) => fricosc::Conditions::vhat(v, self.amp)?,
                (fricosc::Velocity::Vbar(v), None) => fricosc::Conditions::vbar(v, self.amp)?,
            }
            .with_transverse(w)),
            None => conditions(self.velocity.velocity()?, self.amp, tangential),
        }
    }
}

/// Oscillation across the sliding direction, in the plane (`Conditions::with_transverse`).
#[derive(Args)]
pub struct TransversePoint {
    /// Amplitude of an oscillation across the sliding direction, in the plane, dy/l in pre-slip
    /// lengths (>= 0, at most 1e6; 0 is the problem without it, bit for bit). A stiff system only.
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub transverse_amp: Option<f64>,
    /// Its phase against the normal oscillation, radians (default 0; |psi| <= 1e6): the body moves
    /// across as W sin(tau + psi).
    #[arg(long, allow_hyphen_values = true, value_parser = number, requires = "transverse_amp")]
    pub transverse_phase: Option<f64>,
}

impl TransversePoint {
    /// The transverse oscillation, if given.
    pub fn oscillation(&self) -> Result<Option<fricosc::plane::Transverse>> {
        let Some(w) = self.transverse_amp else { return Ok(None) };
        let psi = self.transverse_phase.unwrap_or(0.0);
        let t = fricosc::plane::Transverse::new(w, psi)?;
        warn_degrees_of("--transverse-phase", &[psi]);
        Ok(Some(t))
    }
}

/// `--tangential-amp` needs `--vhat`: `vbar = vhat/amp` is not defined without normal oscillation.
fn vhat_for_tangential(has_vbar: bool, vhat: Option<f64>) -> Result<f64> {
    match (has_vbar, vhat) {
        (false, Some(v)) => Ok(v),
        _ => Err(Error::parse(
            "--tangential-amp",
            "give the velocity as --vhat (vbar = vhat/amp is undefined without normal oscillation)",
        )),
    }
}

/// Oscillation in the sliding direction for a table: lists swept like `--amp`.
#[derive(Args)]
pub struct TangentialList {
    /// Amplitudes of an oscillation in the sliding direction, dx/l in pre-slip lengths
    /// l = mu0 u0 kz/kx (each >= 0, at most 1e6): a comma list or start:stop:count. Needs --vhat;
    /// adds the columns tangential_amp and phase.
    #[arg(long, allow_hyphen_values = true, value_parser = list)]
    pub tangential_amp: Option<List>,
    /// Phases against the normal oscillation, radians (default 0): a comma list or start:stop:count.
    #[arg(long, allow_hyphen_values = true, value_parser = list, requires = "tangential_amp")]
    pub phase: Option<List>,
}

impl TangentialList {
    /// `(tangential amplitudes, phases)` if given; checks that the velocities are `vhat`.
    pub fn values(&self, is_vhat: bool) -> Result<Option<(Vec<f64>, Vec<f64>)>> {
        let Some(t) = &self.tangential_amp else { return Ok(None) };
        if !is_vhat {
            vhat_for_tangential(true, None)?;
        }
        let phases = self.phase.as_ref().map_or(vec![0.0], |p| p.0.clone());
        warn_degrees(&phases);
        Ok(Some((t.0.clone(), phases)))
    }
}

/// A warning on stderr (the work goes on) where a phase is beyond `2 pi` in
/// size: phases are radians, and 90 is more likely meant as degrees.
pub fn warn_degrees(phases: &[f64]) {
    warn_degrees_of("--phase", phases);
}

/// [`warn_degrees`] for the phases of the flag `flag`.
pub fn warn_degrees_of(flag: &str, phases: &[f64]) {
    if let Some(p) = phases.iter().find(|p| p.abs() > std::f64::consts::TAU) {
        let turns = p / std::f64::consts::TAU;
        say(&format!(
            "warning: {flag} {p} is radians ({turns:.2} periods); if degrees were meant, give {}",
            crate::output::num(p.to_radians())
        ));
    }
}

// `--method`: the command-line face of the exact solver and the stepping peer.
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
    /// Springs of an MDR foundation: with --method stepping 1 to 1e8 (default 1000); on a system
    /// (--system-stiffness, or batch rows with system_stiffness) 32 to 16384 (default 256;
    /// compared with N/8, N/4 and N/2 for the error estimate).
    #[arg(long, allow_hyphen_values = true)]
    pub springs: Option<usize>,
}

/// Default resolution of the stepping peer.
pub const DEFAULT_STEPPING: usize = 1000;

impl MethodArgs {
    /// The stepping resolution, or an error for stepping options without `--method stepping`.
    pub fn stepping(&self) -> Result<Option<Stepping>> {
        self.stepping_with(false)
    }

    /// The springs of a curved body on a system (`--springs` with the exact method).
    pub fn system_springs(&self) -> Option<usize> {
        self.springs.filter(|_| self.method == MethodArg::Exact)
    }

    /// [`MethodArgs::stepping`], where `--springs` also serves a system's curved body (`on_system`).
    pub fn stepping_with(&self, on_system: bool) -> Result<Option<Stepping>> {
        if self.method != MethodArg::Stepping {
            let springs = self.springs.filter(|_| !on_system);
            if let Some(name) = [("--steps-per-period", self.steps_per_period), ("--springs", springs)]
                .iter()
                .find(|(_, v)| v.is_some())
                .map(|(n, _)| *n)
            {
                return Err(Error::parse(name, "applies only with --method stepping"));
            }
            return Ok(None);
        }
        Ok(Some(Stepping {
            steps_per_period: self.steps_per_period.unwrap_or(DEFAULT_STEPPING),
            springs: self.springs.unwrap_or(DEFAULT_STEPPING),
        }))
    }
}

/// The shape, method and tolerance shared by `point` and `table`.
#[derive(Args)]
pub struct Common {
    /// Indenter shape: flat, parabolic, cone, power:N, flat-tip:E, profile:FILE@U0, gx:FILE@U0.
    #[arg(long, default_value = "flat")]
    pub shape: String,
    #[command(flatten)]
    pub method: MethodArgs,
    /// Relative quadrature tolerance for curved shapes, in (0, 1) (default: as accurate as f64 allows, 4e-15).
    #[arg(long, allow_hyphen_values = true, value_parser = tolerance)]
    pub tol: Option<f64>,
}

impl Common {
    /// The quadrature tolerance.
    pub fn tol(&self) -> f64 {
        self.tol.unwrap_or(fricosc::DEFAULT_TOL)
    }

    /// The conditions of one point: `velocity` and `amp`, with a tangential
    /// oscillation `(T, phase)` if given, and this tolerance.
    pub fn conditions(
        &self,
        velocity: fricosc::Velocity,
        amp: f64,
        tangential: Option<(f64, f64)>,
    ) -> Result<fricosc::Conditions> {
        Ok(conditions(velocity, amp, tangential)?.with_tol(self.tol())?)
    }
}

/// The conditions of one point: `velocity` and `amp`, with a tangential
/// oscillation `(T, phase)` if given (the default tolerance); `vbar` must be
/// defined without one.
pub fn conditions(
    velocity: fricosc::Velocity,
    amp: f64,
    tangential: Option<(f64, f64)>,
) -> Result<fricosc::Conditions> {
    let c = match velocity {
        fricosc::Velocity::Vbar(v) => fricosc::Conditions::vbar(v, amp)?,
        fricosc::Velocity::Vhat(v) => fricosc::Conditions::vhat(v, amp)?,
    };
    match tangential {
        Some((t, phase)) => Ok(c.with_tangential(t, phase)?),
        None => {
            c.as_vbar()?;
            Ok(c)
        }
    }
}

/// `text` with its control characters escaped (`\u{1b}` for an escape), so
/// that the bytes of an input quoted in a message never reach a terminal raw.
pub fn escape_controls(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { c.escape_default().to_string() } else { c.to_string() }).collect()
}

/// One line on stderr (control characters escaped), or nothing if stderr
/// cannot take it (a full disk, a closed stderr): a message never panics and
/// never costs the answer.
pub fn say(line: &str) {
    let mut e = io::stderr().lock();
    let _ = writeln!(e, "{}", escape_controls(line)).and_then(|()| e.flush());
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
    crate::chart::png(svg).map_err(|e| Error::Internal { what: format!("rendering the PNG: {e}") })
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
        crate::outdir::write_atomic(std::path::Path::new(path), &png)
    } else {
        write_file(option, path, svg)
    }
}

pub fn read_input(file: Option<String>) -> Result<(String, String)> {
    let path = file.unwrap_or_else(|| "-".into());
    let text = crate::input::read_capped(&path, crate::input::MAX_TABLE_BYTES)?;
    Ok((text, if path == "-" { "stdin".into() } else { path }))
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
    crate::outdir::write_atomic(std::path::Path::new(path), text.as_bytes())
}

/// The attractor of `shape` under `c`, conditions with a system ([`fricosc::Conditions::with_system`]).
pub fn system_report(shape: &fricosc::Shape, c: &fricosc::Conditions) -> Result<fricosc::system::SystemReport> {
    let fricosc::Report::System(r) = shape.report(c)? else { return Err(Error::Internal { what: "no system".into() }) };
    Ok(r)
}
