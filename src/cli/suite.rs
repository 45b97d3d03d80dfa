//! `fricosc suite`: a versioned set of canonical cases another code should pass,
//! with every value's error bound, a manifest (the command that reproduces each
//! file, its SHA-256) and a README saying how to use it.
//!
//! Files (CSV with a header line, and the tables also as JSON; numbers in
//! shortest round-trip form):
//! - `tables/SHAPE.csv` and `.json`: `shape,vbar,amp,mu_ratio,reduction,error_bound` on one
//!   grid over every regime (`vbar` from 0 to 1.1 with points near 1; `amp`
//!   from 0.2 to 3: permanent contact, `amp = 1`, jumping slip-first and
//!   stick-first), for `flat`, `parabolic`, `cone` and a tabulated sphere;
//!   `error_bound` is the solver's error estimate (plus the table's
//!   interpolation estimate for the tabulated sphere, whose reference is the
//!   table itself, interpolated as documented).
//! - `limits.csv`: the limits `vbar -> 0+`, `vbar -> 1` (at `1 - 1e-3` and
//!   `1 - 1e-6`, where the reduction vanishes like `(1 - vbar)^2`) and
//!   `amp = 1` for each analytic shape.
//! - `histories/flat-*.csv`: force histories of the flat punch (permanent
//!   contact and jumping) over one period with every event time included, and
//!   `histories/flat-*-events.csv`: the exact events (phase, kind, forces).
//!
//! `fricosc suite --check DIR` recomputes every file and compares bytes and
//! hashes: a suite made by another version is reported file by file.

use crate::cmd::{emit, Outcome};
use crate::error::{Error, Result};
use crate::output::num;
use clap::Args;
use fricosc::Shape;
use sha2::{Digest, Sha256};
use std::path::Path;
/// The suite's version: changed whenever a case is added, a file's form changes,
/// or published digits move (within their bounds) with a faster or better form.
pub const SUITE_VERSION: u32 = 25;

/// Velocities of the tables: every regime, and close to the critical velocity.
const VBAR: [f64; 17] = [0.0, 0.01, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99, 0.999, 1.0, 1.1];
/// Amplitudes of the tables: permanent contact, `amp = 1`, jumping.
const AMP: [f64; 8] = [0.2, 0.5, 0.8, 1.0, 1.2, 1.5, 2.0, 3.0];
/// The tabulated shape of the suite (the sphere of `data/profiles`, R = 1 m, at u0 = 1e-6 m).
const TABULATED: &str = "profile:data/profiles/sphere.csv@1e-6";
/// `data/profiles/sphere.csv`, compiled in.
const SPHERE_TABLE: &str = include_str!("../../data/profiles/sphere.csv");
/// The histories: `(vbar, amp)`.
const HISTORIES: [(f64, f64); 2] = [(0.3, 0.5), (0.3, 1.5)];
/// Uniform samples of each history (event times are added).
const HISTORY_SAMPLES: usize = 64;

/// One file of the suite: its path in the suite, its content, and the command
/// that reproduces its values.
pub struct SuiteFile {
    /// Path relative to the suite directory.
    pub path: String,
    /// The file's bytes.
    pub text: String,
    /// The `fricosc` command that reproduces the values.
    pub command: String,
}

fn list(xs: &[f64]) -> String {
    xs.iter().map(|&x| num(x)).collect::<Vec<_>>().join(",")
}

fn value_row(shape: &Shape, spec: &str, vbar: f64, amp: f64) -> Result<Vec<String>> {
    let e = shape.evaluate(&fricosc::Conditions::vbar(vbar, amp)?)?;
    let bound = e.error_estimate + e.interpolation_error.unwrap_or(0.0);
    Ok(vec![spec.into(), num(vbar), num(amp), num(e.ratio.mu_ratio), num(e.ratio.reduction), num(bound)])
}

const VALUE_HEADER: [&str; 6] = ["shape", "vbar", "amp", "mu_ratio", "reduction", "error_bound"];

/// The same rows as JSON, as `fricosc table` prints it (one object with the
/// shape and a `rows` array, one row per line), with the error bound added.
fn json_rows(spec: &str, rows: &[Vec<String>]) -> Result<String> {
    let name = serde_json::to_string(spec).map_err(|e| Error::Internal { what: format!("JSON: {e}") })?;
    let lines: Vec<String> = rows
        .iter()
        .map(|r| {
            format!(
                "{{\"vbar\":{},\"amp\":{},\"mu_ratio\":{},\"reduction\":{},\"error_bound\":{}}}",
                r[1], r[2], r[3], r[4], r[5]
            )
        })
        .collect();
    Ok(format!("{{\"shape\":{name},\"rows\":[\n{}\n]}}\n", lines.join(",\n")))
}

/// Every file of the suite, computed now (paths relative to the repository for
/// the tabulated shape's table).
pub fn files() -> Result<Vec<SuiteFile>> {
    let mut out = vec![];
    for (name, spec) in
        [("flat", "flat"), ("parabolic", "parabolic"), ("cone", "cone"), ("tabulated-sphere", TABULATED)]
    {
        // The tabulated sphere's table is built in: the suite is the same from any directory.
        let shape = fricosc::Shape::parse_with(spec, &|_| Ok(SPHERE_TABLE.to_string()))?;
        let mut rows = vec![];
        for &a in &AMP {
            for &v in &VBAR {
                rows.push(value_row(&shape, spec, v, a)?);
            }
        }
        let command = format!("fricosc table --shape {spec} --amp {} --vbar {}", list(&AMP), list(&VBAR));
        out.push(SuiteFile {
            path: format!("tables/{name}.json"),
            text: json_rows(spec, &rows)?,
            command: command.clone(),
        });
        out.push(SuiteFile {
            path: format!("tables/{name}.csv"),
            text: crate::output::csv_table(&VALUE_HEADER, &rows),
            command: format!("{command} --format csv"),
        });
    }
    let mut rows = vec![];
    for spec in ["flat", "parabolic", "cone"] {
        let shape = fricosc::Shape::parse(spec)?;
        for (v, a) in [(0.0, 0.5), (0.0, 1.5), (1.0 - 1e-3, 0.5), (1.0 - 1e-6, 0.5), (1.0 - 1e-6, 1.5), (0.5, 1.0)] {
            rows.push(value_row(&shape, spec, v, a)?);
        }
    }
    out.push(SuiteFile {
        path: "limits.csv".into(),
        text: crate::output::csv_table(&VALUE_HEADER, &rows),
        command: "fricosc point --shape S --vbar V --amp A (each row)".into(),
    });
    for (v, a) in HISTORIES {
        let h = fricosc::history::history(
            &Shape::flat(),
            &fricosc::Conditions::vbar(v, a)?,
            &fricosc::history::HistoryOptions::default().with_samples(HISTORY_SAMPLES),
        )?;
        let event = |e: Option<fricosc::spring::EventKind>| {
            e.and_then(|k| serde_json::to_value(k).ok())
                .and_then(|k| k.as_str().map(str::to_string))
                .unwrap_or_default()
        };
        let stem = format!("histories/flat-vbar{}-amp{}", num(v), num(a));
        out.push(SuiteFile {
            path: format!("{stem}.csv"),
            // Exactly what the command writes (with its units line).
            text: crate::export::export(&h, crate::export::Format::Csv)?,
            command: format!(
                "fricosc history --shape flat --vbar {} --amp {} --samples {HISTORY_SAMPLES} --format csv",
                num(v),
                num(a)
            ),
        });
        let fricosc::Report::Flat(p) = Shape::flat().report(&fricosc::Conditions::vbar(v, a)?)? else {
            return Err(Error::Internal { what: "the flat punch's report without its events".into() });
        };
        let rows: Vec<Vec<String>> =
            p.events.iter().map(|e| vec![num(e.tau), event(Some(e.kind)), num(e.normal), num(e.tangential)]).collect();
        out.push(SuiteFile {
            path: format!("{stem}-events.csv"),
            text: crate::output::csv_table(&["tau", "kind", "normal", "tangential"], &rows),
            command: format!("fricosc point --shape flat --vbar {} --amp {} (events)", num(v), num(a)),
        });
    }
    Ok(out)
}

fn sha256(text: &str) -> String {
    Sha256::digest(text.as_bytes()).iter().map(|b| format!("{b:02x}")).collect()
}

/// The manifest: versions, and each file's command, rows and SHA-256.
pub fn manifest(files: &[SuiteFile]) -> Result<String> {
    let entries: Vec<serde_json::Value> = files
        .iter()
        .map(|f| {
            serde_json::json!({
                "path": f.path, "sha256": sha256(&f.text), "rows": f.text.lines().filter(|l| !l.starts_with('#')).count().saturating_sub(1),
                "command": f.command,
            })
        })
        .collect();
    let doc = serde_json::json!({
        "suite_version": SUITE_VERSION,
        "fricosc_version": env!("CARGO_PKG_VERSION"),
        "made_by": "fricosc suite --out DIR (the tabulated shape is data/profiles/sphere.csv, built into fricosc)",
        "units": "dimensionless: vbar (eq. 3), amp = du/u0, mu_ratio = mu_macro/mu0; histories in units of kz u0 (normal) and mu0 kz u0 (tangential), phase tau = omega t",
        "files": entries,
    });
    serde_json::to_string_pretty(&doc).map(|s| s + "\n").map_err(|e| Error::Internal { what: format!("manifest: {e}") })
}

/// The suite's README.
pub fn readme() -> String {
    format!(
        "# fricosc reference suite, version {SUITE_VERSION}\n\n\
Canonical cases for codes that compute friction under normal oscillation (Popov, Popov, Popov,\n\
Friction 2017): the exact values of fricosc {} with an error bound on each.\n\n\
- `tables/*.csv` (the same as `tables/*.json`): `mu_ratio = mu_macro/mu0` and `reduction = 1 - mu_ratio` (computed on its own, with\n\
  full relative accuracy) on one grid of `vbar` (eq. 3) and `amp = du/u0` covering every regime, for\n\
  the flat punch, the paraboloid (`parabolic`), the cone and a tabulated sphere. `error_bound` bounds\n\
  `|mu_ratio - exact|`. At `vbar = 0` the value is the limit `vbar -> 0+` of a sliding contact\n\
  (a stepper started from relaxed springs gives 0 there instead).\n\
- `limits.csv`: `vbar -> 0+`, `vbar -> 1` (`1 - 1e-3`, `1 - 1e-6`) and `amp = 1`.\n\
- `histories/flat-*.csv`: normal and tangential force of the flat punch over one period (phase\n\
  `tau = omega t`, forces in units of `kz u0` and `mu0 kz u0`, stated on a first `#` line), with\n\
  every event's phase among the samples; `*-events.csv`: the exact events (contact, loss of contact, stick, slip).\n\
- `manifest.json`: the command that reproduces each file's values, its rows and its SHA-256.\n\n\
How to use it: run your code at the same inputs and compare, e.g. with `fricosc validate\n\
your-table.csv` (errors by regime and amplitude, findings with hints). A converged time stepper\n\
should agree to its own discretisation error; `error_bound` is far below that. `fricosc suite\n\
--check DIR` verifies a copy of this suite against the installed fricosc.\n",
        env!("CARGO_PKG_VERSION")
    )
}

/// Write the suite into the folder `out`.
pub fn write(out: &crate::outdir::OutDir) -> Result<Vec<String>> {
    let files = files()?;
    let mut written = vec![];
    let mut put = |rel: &str, text: &str| -> Result<()> {
        out.write(rel, text.as_bytes())?;
        written.push(rel.to_string());
        Ok(())
    };
    for f in &files {
        put(&f.path, &f.text)?;
    }
    put("manifest.json", &manifest(&files)?)?;
    put("README.md", &readme())?;
    Ok(written)
}

/// Compare the suite in `dir` with the one computed now: the files that differ
/// or are missing (empty: the suite is current).
pub fn check(dir: &Path) -> Result<Vec<String>> {
    let name = dir.display().to_string();
    if name.trim().is_empty() {
        return Err(Error::Parse { context: "--check".into(), reason: "the suite's folder is empty".into() });
    }
    match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => return Err(Error::Parse { context: "--check".into(), reason: format!("'{name}' is not a folder") }),
        Err(e) => return Err(Error::read(&name, e)),
    }
    let files = files()?;
    let mut expected: Vec<(String, String)> = files.iter().map(|f| (f.path.clone(), f.text.clone())).collect();
    expected.push(("manifest.json".into(), manifest(&files)?));
    expected.push(("README.md".into(), readme()));
    let mut bad = vec![];
    for (rel, text) in expected {
        let p = dir.join(&rel);
        // Only regular files are read (a link to /dev/zero or a FIFO is a
        // difference, not a read), and no more of each than the expected size.
        match std::fs::symlink_metadata(&p) {
            Ok(m) if !m.is_file() => bad.push(format!("{rel} is not a regular file")),
            Ok(m) if m.len() != text.len() as u64 => bad.push(format!("{rel} differs")),
            Ok(_) => match fricosc::io::read_capped(&p.display().to_string(), text.len() as u64) {
                Ok(found) if found == text => {}
                Ok(_) => bad.push(format!("{rel} differs")),
                Err(e) => return Err(Error::read(&p.display().to_string(), e)),
            },
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => bad.push(format!("{rel} is missing")),
            Err(e) => return Err(Error::read(&p.display().to_string(), e)),
        }
    }
    Ok(bad)
}

#[derive(Args)]
pub struct SuiteArgs {
    /// Write the suite into this directory (created if missing).
    #[arg(long)]
    pub out: Option<String>,
    /// Check the suite in this directory against the current solver.
    #[arg(long)]
    pub check: Option<String>,
}

/// `--out DIR` writes the suite; `--check DIR` compares it with the current
/// solver ([`Outcome::Negative`] when a file differs or is missing).
pub fn run(a: SuiteArgs) -> Result<Outcome> {
    match (a.out, a.check) {
        (Some(dir), None) => {
            let out = crate::outdir::OutDir::open("--out", &dir)?;
            let files = crate::suite::write(&out)?;
            emit(&format!(
                "wrote the reference suite (version {}) to {dir}: {} files\n",
                crate::suite::SUITE_VERSION,
                files.len()
            ))?;
            Ok(Outcome::Done)
        }
        (None, Some(dir)) => {
            let bad = crate::suite::check(std::path::Path::new(&dir))?;
            if bad.is_empty() {
                emit(&format!("{dir}: the reference suite (version {}) is current\n", crate::suite::SUITE_VERSION))?;
                Ok(Outcome::Done)
            } else {
                emit(&format!("{dir}: {}\n", bad.join("; ")))?;
                Ok(Outcome::Negative)
            }
        }
        _ => Err(crate::error::Error::parse("suite", "give exactly one of --out DIR (write) and --check DIR (verify)")),
    }
}
