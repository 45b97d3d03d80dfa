//! `fricosc bench`: the work-precision comparison of the exact solver with the
//! seed's time-stepping scheme.
//!
//! Each point is (absolute error of `mu_ratio` against a 40-digit reference,
//! minimum over `k` samples of the wall time per evaluation after a warm-up);
//! a sample repeats the evaluation until it lasts a few milliseconds. Failures
//! (an error or a non-finite value) are kept and listed, never dropped.

use crate::cmd::emit;
use crate::error::{Error, Result};
use crate::export::{export_bytes, Format};
use clap::Args;
use fricosc::stepper::Stepping;
use fricosc::Shape;
use serde::Serialize;
use std::time::Instant;

mod plane;
/// The reference values this benchmark uses: `data/reference-values.json`, the
/// project's public 40-digit values (independent evaluation, cross-checked by a
/// converged time stepper; `src/fricosc/tests/library/reference.rs` reads and checks them).
const REFERENCES: &str = include_str!("../../../data/reference-values.json");

/// One benchmarked case.
#[derive(Debug, Clone, Serialize)]
pub struct Case {
    /// Label.
    pub name: String,
    /// Shape name.
    pub shape: String,
    /// Dimensionless velocity.
    pub vbar: f64,
    /// Amplitude.
    pub amp: f64,
    /// The 40-digit reference, as text.
    pub reference: String,
    /// Across the sliding direction: `W` and `psi` (and `vbar` is `vhat/amp`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub transverse: Option<[f64; 2]>,
}

/// One (error, time) measurement.
#[derive(Debug, Clone, Serialize)]
pub struct Point {
    /// Case label.
    pub case: String,
    /// `exact` or `stepping`.
    pub method: String,
    /// The setting: `tol=...` or `M=...,N=...`.
    pub setting: String,
    /// `|mu_ratio - reference|` (0 means below f64 resolution of the reference).
    pub error: f64,
    /// Minimum wall time per evaluation, seconds.
    pub time_s: f64,
}

/// The ratio of stepping to exact time for one case.
#[derive(Debug, Clone, Serialize)]
pub struct Ratio {
    /// Case label.
    pub case: String,
    /// Exact solver at its default tolerance: error and time.
    pub exact_error: f64,
    /// Seconds per evaluation.
    pub exact_time_s: f64,
    /// The most accurate stepping run: error and time.
    pub stepping_error: f64,
    /// Seconds per evaluation.
    pub stepping_time_s: f64,
    /// `stepping_time_s / exact_time_s`, the exact solver being at least as accurate.
    pub time_ratio: f64,
}

/// Everything `bench` measured.
#[derive(Debug, Clone, Serialize)]
pub struct Report {
    /// fricosc version.
    pub version: String,
    /// Logical cores and CPU model.
    pub machine: Machine,
    /// How the reference values were obtained and verified.
    pub reference: String,
    /// The cases.
    pub cases: Vec<Case>,
    /// The measurements.
    pub points: Vec<Point>,
    /// Time ratios at matched (or better) error.
    pub ratios: Vec<Ratio>,
    /// Settings that failed, with the reason.
    pub failures: Vec<String>,
    /// `quick` or `full`.
    pub mode: String,
    /// Instructions per row of whole processes, from a deterministic counter
    /// (callgrind; full mode, where valgrind is installed).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub instructions: Vec<InstructionCount>,
    /// Points a second on one core, by kind.
    pub throughput: Vec<Throughput>,
}

/// The exact solver's speed on one core for one kind of point (one thread;
/// `fricosc table`, `batch` and Python's arrays use every core).
#[derive(Debug, Clone, Serialize)]
pub struct Throughput {
    /// The kind: stiff or on a system, flat or curved, and the point.
    pub kind: String,
    /// Points a second on one core (the best of a few samples).
    pub points_per_second_per_core: f64,
    /// The points a second on one core the kind should reach, where one is set.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target: Option<f64>,
}

/// [`Throughput`] of the six kinds of point: the stiff flat punch and
/// paraboloid, both on a system (`kappa` 1, `Omega` 0.5, `zeta` 0.05; the
/// paraboloid at its default 256 springs), and both in the plane ([`plane`]'s
/// point, one thread: issue 62's targets, 50 us and 5 ms a point).
fn throughput(tm: Timing) -> fricosc::Result<Vec<Throughput>> {
    let sys = fricosc::system::System::new(1.0, 0.5, 0.05)?;
    let c = fricosc::Conditions::vhat(0.15, 0.5)?;
    let kinds = [
        ("stiff flat, vbar 0.3, amp 0.5", "flat", None),
        ("stiff parabolic, vbar 0.3, amp 0.5", "parabolic", None),
        ("flat on a system (kappa 1, Omega 0.5, zeta 0.05), vbar 0.3, amp 0.5", "flat", Some(sys)),
        ("parabolic on that system, 256 springs", "parabolic", Some(sys)),
    ];
    let mut out = vec![];
    for (kind, name, system) in kinds {
        let (shape, c) = (Shape::parse(name)?, system.map_or(c, |s| c.with_system(s)));
        shape.ratio(&c)?;
        let k = if system.is_some() { 2 } else { tm.k };
        let per = time_per_call(k, tm.sample, || shape.ratio(&c).map_or(f64::NAN, |r| r.mu_ratio));
        out.push(Throughput { kind: kind.into(), points_per_second_per_core: 1.0 / per, target: None });
    }
    out.extend(plane::throughput(tm)?);
    Ok(out)
}

/// Instructions per row of one workload, as a whole process: `(I(n) - I(1)) /
/// (n - 1)` with `I` callgrind's total over every thread, so that start-up and
/// reading are not counted per row.
#[derive(Debug, Clone, Serialize)]
pub struct InstructionCount {
    /// What ran.
    pub workload: String,
    /// Rows of the large run.
    pub rows: usize,
    /// Instructions per row.
    pub instructions_per_row: f64,
    /// The command (`FILE` a JSON array of random rows).
    pub command: String,
    /// The most instructions per row this workload is meant to take, where one is set.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target: Option<f64>,
}

/// The machine the numbers come from.
#[derive(Debug, Clone, Serialize)]
pub struct Machine {
    /// Logical cores.
    pub cores: usize,
    /// CPU model (from /proc/cpuinfo where available).
    pub cpu: String,
}

fn machine() -> Machine {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into());
    Machine { cores: std::thread::available_parallelism().map_or(1, |n| n.get()), cpu }
}

fn reference(shape: &str, vbar: f64, amp: f64) -> Option<String> {
    let v: serde_json::Value = serde_json::from_str(REFERENCES).ok()?;
    v["cases"].as_array()?.iter().find_map(|c| {
        (c["shape"] == shape && c["vbar"].as_f64() == Some(vbar) && c["amp"].as_f64() == Some(amp))
            .then(|| c["mu_ratio"].as_str().map(String::from))
            .flatten()
    })
}

/// Minimum over `k` samples of the time per call of `f` (after one warm-up sample).
fn time_per_call(k: usize, sample_s: f64, mut f: impl FnMut() -> f64) -> f64 {
    let mut reps = 1usize;
    let t0 = Instant::now();
    std::hint::black_box(f());
    let once = t0.elapsed().as_secs_f64().max(1e-9);
    if once < sample_s {
        reps = ((sample_s / once) as usize).clamp(1, 10_000_000);
    }
    let mut best = f64::INFINITY;
    for _ in 0..k {
        let t = Instant::now();
        for _ in 0..reps {
            std::hint::black_box(f());
        }
        best = best.min(t.elapsed().as_secs_f64() / reps as f64);
    }
    best
}

/// What the runs of one case collect: the measured points and the failures.
struct Collector<'a> {
    case: &'a str,
    reference: f64,
    points: &'a mut Vec<Point>,
    failures: &'a mut Vec<String>,
}

impl Collector<'_> {
    /// Record one run's value and time; its error if it gave a finite value.
    fn record(&mut self, method: &str, setting: String, value: fricosc::Result<f64>, time_s: f64) -> Option<f64> {
        let name = self.case;
        match value {
            Ok(m) if m.is_finite() => {
                let error = (m - self.reference).abs();
                self.points.push(Point { case: name.into(), method: method.into(), setting, error, time_s });
                Some(error)
            }
            Ok(m) => {
                self.failures.push(format!("{name} {method} {setting}: non-finite result {m}"));
                None
            }
            Err(e) => {
                self.failures.push(format!("{name} {method} {setting}: {e}"));
                None
            }
        }
    }
}

/// Timing repetitions and the shortest time sampled per repetition.
#[derive(Clone, Copy)]
struct Timing {
    k: usize,
    sample: f64,
}

/// The exact solver at several tolerances (the flat punch has no tolerance to
/// set): `(error, time)` of the last (most accurate) one.
fn exact_runs(c: &mut Collector, shape: &Shape, vbar: f64, amp: f64, tm: Timing) -> Option<(f64, f64)> {
    let tols: &[f64] =
        if shape.is_flat() { &[fricosc::DEFAULT_TOL] } else { &[1e-4, 1e-6, 1e-8, 1e-11, fricosc::DEFAULT_TOL] };
    let mut best = None;
    for &tol in tols {
        let run =
            || fricosc::Conditions::vbar(vbar, amp).and_then(|c| c.with_tol(tol)).and_then(|c| shape.evaluate(&c));
        let value = run().map(|e| e.ratio.mu_ratio);
        let t = time_per_call(tm.k, tm.sample, || run().map_or(f64::NAN, |e| e.ratio.mu_ratio));
        if let Some(err) = c.record("exact", format!("tol={tol:e}"), value, t) {
            best = Some((err, t));
        }
    }
    best
}

/// Time stepping at several resolutions: `(error, time)` of the most accurate run.
fn stepping_runs(c: &mut Collector, shape: &Shape, vbar: f64, amp: f64, tm: Timing, quick: bool) -> Option<(f64, f64)> {
    let steps: Vec<(usize, usize)> = match (shape.is_flat(), quick) {
        (true, true) => vec![(100, 1), (1000, 1), (10_000, 1)],
        (true, false) => vec![(100, 1), (1000, 1), (10_000, 1), (100_000, 1), (1_000_000, 1), (10_000_000, 1)],
        (false, true) => vec![(50, 50), (100, 100), (200, 200)],
        (false, false) => vec![(100, 100), (300, 300), (1000, 1000), (3000, 3000), (10_000, 10_000)],
    };
    let mut best: Option<(f64, f64)> = None;
    for (m, n) in steps {
        let st = Stepping { steps_per_period: m, springs: n };
        let run = || fricosc::Conditions::vbar(vbar, amp).and_then(|c| fricosc::stepper::evaluate(shape, &c, st));
        let value = run().map(|e| e.ratio.mu_ratio);
        let t = time_per_call(tm.k.min(3), tm.sample, || run().map_or(f64::NAN, |e| e.ratio.mu_ratio));
        if let Some(err) = c.record("stepping", format!("M={m},N={n}"), value, t) {
            if best.is_none_or(|(e, _)| err < e) {
                best = Some((err, t));
            }
        }
    }
    best
}

impl Ratio {
    /// The case's `(error, time)` of the exact solver and of the stepper.
    fn of(case: &str, (exact_error, exact_time_s): (f64, f64), (stepping_error, stepping_time_s): (f64, f64)) -> Ratio {
        let time_ratio = stepping_time_s / exact_time_s;
        Ratio { case: case.into(), exact_error, exact_time_s, stepping_error, stepping_time_s, time_ratio }
    }
}

/// Run the benchmark; `quick` finishes in seconds (for CI).
pub fn measure(quick: bool) -> Report {
    let tm = if quick { Timing { k: 3, sample: 2e-4 } } else { Timing { k: 7, sample: 5e-3 } };
    let specs =
        [("flat amp<=1", "flat", 0.5, 0.5), ("flat amp>1", "flat", 0.5, 1.5), ("parabolic", "parabolic", 0.3, 0.4)];
    let (mut cases, mut points, mut failures, mut ratios) = (vec![], vec![], vec![], vec![]);
    for (name, shape_name, vbar, amp) in specs {
        let Some(reference) = reference(shape_name, vbar, amp) else {
            failures.push(format!("{name}: no reference value"));
            continue;
        };
        let refv: f64 = reference.parse().unwrap_or(f64::NAN);
        cases.push(Case {
            name: name.into(),
            shape: shape_name.into(),
            vbar,
            amp,
            reference: reference.clone(),
            transverse: None,
        });
        let shape = match Shape::parse(shape_name) {
            Ok(s) => s,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        let mut c = Collector { case: name, reference: refv, points: &mut points, failures: &mut failures };
        let exact_best = exact_runs(&mut c, &shape, vbar, amp, tm);
        let stepping_best = stepping_runs(&mut c, &shape, vbar, amp, tm, quick);
        if let (Some(exact), Some(stepping)) = (exact_best, stepping_best) {
            if exact.0 <= stepping.0 {
                ratios.push(Ratio::of(name, exact, stepping));
            }
        }
    }
    let mut out = plane::Out { cases: &mut cases, points: &mut points, failures: &mut failures, ratios: &mut ratios };
    plane::flat(&mut out, tm, quick);
    plane::parabolic(&mut out, tm, quick);
    let throughput = throughput(tm).unwrap_or_else(|e| {
        failures.push(format!("throughput: {e}"));
        vec![]
    });
    Report {
        version: env!("CARGO_PKG_VERSION").into(),
        machine: machine(),
        reference: "40-digit values of data/reference-values.json (independent high-precision evaluation of the \
                    exact periodic state, cross-checked by a converged time stepper), checked by src/fricosc/tests/library/reference.rs"
            .into(),
        cases,
        points,
        ratios,
        failures,
        mode: if quick { "quick" } else { "full" }.into(),
        instructions: vec![],
        throughput,
    }
}

impl crate::export::Report for Report {
    /// The points: `case,method,setting,error,time_s`.
    fn columns(&self) -> Vec<String> {
        ["case", "method", "setting", "error", "time_s"].map(String::from).to_vec()
    }

    fn rows(&self) -> Vec<Vec<String>> {
        self.points
            .iter()
            .map(|p| {
                vec![
                    p.case.to_string(),
                    p.method.to_string(),
                    p.setting.clone(),
                    format!("{:?}", p.error),
                    format!("{:?}", p.time_s),
                ]
            })
            .collect()
    }

    fn svg(&self) -> Option<crate::error::Result<String>> {
        Some(Ok(to_svg(self)))
    }
}

/// Errors at or below this are drawn at it (the reference has 40 digits; an
/// error of 0 means the f64 result is the reference rounded).
const ERROR_FLOOR: f64 = 1e-17;

/// Log-log SVG of error against time per evaluation: one colour per case, the
/// exact solver solid with circles, time stepping dashed with triangles.
fn to_svg(r: &Report) -> String {
    use crate::chart::{Axis, Chart, Dash, Key, Marker, Rgb, Series, Style, OKABE_ITO};
    let (tmin, tmax) = r.points.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| (a.min(p.time_s), b.max(p.time_s)));
    let (tmin, tmax) = if tmax > 0.0 { (tmin / 3.0, tmax * 3.0) } else { (1e-9, 1.0) };
    let mut cases: Vec<&str> = vec![];
    for p in &r.points {
        if !cases.contains(&p.case.as_str()) {
            cases.push(&p.case);
        }
    }
    let color = |case: &str| OKABE_ITO[cases.iter().position(|c| *c == case).unwrap_or(0) % OKABE_ITO.len()];
    let style = |case: &str, method: &str| {
        if method == "exact" {
            Style::line(color(case)).marker(Marker::Circle)
        } else {
            Style::dashed(color(case), Dash::Dashed).marker(Marker::Triangle)
        }
    };
    let mut series: Vec<Series> = vec![];
    for p in &r.points {
        let label = format!("{} / {}", p.case, p.method);
        let xy = (p.time_s, p.error.max(ERROR_FLOOR));
        match series.iter_mut().find(|s| s.label == label) {
            Some(s) => s.points.push(xy),
            None => series.push(Series { label, points: vec![xy], style: style(&p.case, &p.method), legend: false }),
        }
    }
    for s in &mut series {
        s.points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    let grey = Rgb(0x55, 0x55, 0x55);
    let mut key = vec![Key::Heading("case".into())];
    let pretty = |c: &str| c.replace("amp<=", "Δu_{z}/u_{z0} ≤ ").replace("amp>", "Δu_{z}/u_{z0} > ");
    key.extend(cases.iter().map(|c| Key::Entry(Style::line(color(c)), pretty(c))));
    key.push(Key::Heading(String::new()));
    key.push(Key::Entry(Style::line(grey).marker(Marker::Circle), "exact".into()));
    key.push(Key::Entry(Style::dashed(grey, Dash::Dashed).marker(Marker::Triangle), "stepping".into()));
    key.push(Key::Heading("errors ≤ 10^{−17} drawn on the grey line".into()));
    Chart {
        title: "fricosc work-precision: the exact solver against time stepping".into(),
        x: Axis::log("time per evaluation (s)", (tmin, tmax)),
        y: Axis::log("error |μ/μ_{0} − reference|", (ERROR_FLOOR / 10.0, 1.0)),
        series,
        key,
        rules: vec![crate::chart::Rule { horizontal: true, at: ERROR_FLOOR }],
    }
    .svg()
}

#[derive(Args)]
pub struct BenchArgs {
    /// Output directory (created if missing).
    #[arg(long)]
    pub out: String,
    /// A few seconds, for CI.
    #[arg(long)]
    pub quick: bool,
}

/// Run the benchmark and write its JSON, CSV, SVG and PNG into `--out`.
pub fn run(a: BenchArgs) -> Result<()> {
    let (out, quick) = (a.out.as_str(), a.quick);
    let dir = crate::outdir::OutDir::open("--out", out)?;
    let mut report = measure(quick);
    if !quick {
        report.instructions = instruction_counts()?;
    }
    for (ext, format) in [("json", Format::Json), ("csv", Format::Csv), ("svg", Format::Svg), ("png", Format::Png)] {
        dir.write(&format!("work-precision.{ext}"), &export_bytes(&report, format)?)?;
    }
    let mut o = String::new();
    for r in &report.ratios {
        o += &format!(
            "{}: exact {:.1e} s at error {:.1e}; stepping {:.1e} s at error {:.1e}; time ratio {:.2e}\n",
            r.case, r.exact_time_s, r.exact_error, r.stepping_time_s, r.stepping_error, r.time_ratio
        );
    }
    for t in &report.throughput {
        let target = t.target.map_or(String::new(), |g| format!("; target at least {g:.0}"));
        o += &format!("{}: {:.3e} points a second on one core{target}\n", t.kind, t.points_per_second_per_core);
    }
    for c in &report.instructions {
        let (target, n, what) =
            (c.target.map_or(String::new(), |t| format!("; target at most {t:.0}")), c.rows, &c.workload);
        o += &format!("{what}: {:.0} instructions per row (callgrind, {n} rows){target}\n", c.instructions_per_row);
    }
    for f in &report.failures {
        o += &format!("failure: {f}\n");
    }
    emit(&format!("{o}wrote {out}/work-precision.{{json,csv,svg,png}}\n"))
}

/// Total instructions of `fricosc ARGS` under callgrind, or `None` without valgrind.
fn callgrind(args: &[&str]) -> Option<f64> {
    let exe = std::env::current_exe().ok()?;
    let out = std::process::Command::new("valgrind")
        .env("RAYON_NUM_THREADS", "1")
        .args(["--tool=callgrind", "--callgrind-out-file=/dev/null"])
        .arg(exe)
        .args(args)
        .stdout(std::process::Stdio::null())
        .output()
        .ok()?;
    let err = String::from_utf8_lossy(&out.stderr);
    let line = err.lines().find(|l| l.contains("Collected :"))?;
    line.rsplit(':').next()?.trim().parse().ok()
}

/// Per-row instruction counts of `batch` (JSON array, JSON Lines and CSV; flat and parabolic rows) and `table`, where
/// valgrind is installed (none otherwise). Each is the count of a large run minus a one-row run (so that start-up is
/// not counted), over the rows' difference. Rayon runs one thread (`RAYON_NUM_THREADS=1`): idle worker threads spin,
/// and their instructions would count as work.
fn instruction_counts() -> Result<Vec<crate::bench::InstructionCount>> {
    // The workloads' input files go in a scratch folder of our own, removed after.
    let scratch = std::env::temp_dir().join(format!("fricosc-bench-{}", std::process::id()));
    std::fs::create_dir(&scratch).map_err(|e| Error::write(&scratch.display().to_string(), e))?;
    let counts = instruction_counts_in(&scratch);
    let _ = std::fs::remove_dir_all(&scratch);
    counts
}

fn instruction_counts_in(dir: &std::path::Path) -> Result<Vec<crate::bench::InstructionCount>> {
    // A fixed pseudo-random row set: vbar in [0, 1.2], amp in [0, 3].
    let mut seed = 0x9E3779B97F4A7C15u64;
    let mut rand = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let random = |n: usize, rand: &mut dyn FnMut() -> f64| -> Vec<(f64, f64)> {
        (0..n).map(|_| (1.2 * rand(), 3.0 * rand())).collect()
    };
    // The parabolic table's own grid, for batch against table on the same points.
    let grid: Vec<(f64, f64)> =
        (0..10).flat_map(|a| (0..100).map(move |v| (1.2 * v as f64 / 99.0, 3.0 * a as f64 / 9.0))).collect();
    let json = |shape: &str, pts: &[(f64, f64)]| {
        let r: Vec<String> =
            pts.iter().map(|(v, a)| format!("{{\"shape\":\"{shape}\",\"vbar\":{v:?},\"amp\":{a:?}}}")).collect();
        format!("[{}]", r.join(",\n"))
    };
    let lines = |shape: &str, pts: &[(f64, f64)]| -> String {
        pts.iter().map(|(v, a)| format!("{{\"shape\":\"{shape}\",\"vbar\":{v:?},\"amp\":{a:?}}}\n")).collect()
    };
    let csv = |shape: &str, pts: &[(f64, f64)]| -> String {
        "shape,vbar,amp\n".to_string() + &pts.iter().map(|(v, a)| format!("{shape},{v:?},{a:?}\n")).collect::<String>()
    };
    let flat = random(10_000, &mut rand);
    let parabolic = random(1_000, &mut rand);
    type Make<'a> = &'a dyn Fn(&str, &[(f64, f64)]) -> String;
    type Workload<'a> = (&'a str, &'a str, Make<'a>, &'a [(f64, f64)], &'a str);
    let files: [Workload; 5] = [
        ("batch, random flat rows (JSON array)", "flat", &json, &flat, "json"),
        ("batch, random flat rows (JSON Lines)", "flat", &lines, &flat, "jsonl"),
        ("batch, random flat rows (CSV)", "flat", &csv, &flat, "csv"),
        ("batch, random parabolic rows (JSON array)", "parabolic", &json, &parabolic, "json"),
        ("batch, the parabolic table's 10 x 100 points (JSON array)", "parabolic", &json, &grid, "json"),
    ];
    let mut out = vec![];
    for (workload, shape, make, pts, ext) in files {
        let (big, one) = (dir.join(format!("rows.{ext}")), dir.join(format!("row.{ext}")));
        let werr = |p: &std::path::Path, e| Error::write(&p.display().to_string(), e);
        std::fs::write(&big, make(shape, pts)).map_err(|e| werr(&big, e))?;
        std::fs::write(&one, make(shape, &pts[..1])).map_err(|e| werr(&one, e))?;
        let counts =
            (callgrind(&["batch", &big.display().to_string()]), callgrind(&["batch", &one.display().to_string()]));
        let _ = (std::fs::remove_file(&big), std::fs::remove_file(&one));
        let (Some(i_n), Some(i_1)) = counts else { return Ok(vec![]) };
        out.push(crate::bench::InstructionCount {
            workload: workload.into(),
            rows: pts.len(),
            instructions_per_row: (i_n - i_1) / (pts.len() - 1) as f64,
            command: format!("valgrind --tool=callgrind fricosc batch FILE.{ext} ({} rows minus 1 row)", pts.len()),
            target: None,
        });
    }
    out.extend(table_counts());
    Ok(out)
}

/// The `table` workloads: what runs, the table's options and those of its one-point counterpart, its rows, and the
/// instructions per row it is meant to take (a flat point on a system: 1.5 M, issue 59's target).
const TABLES: [(&str, &str, &str, usize, Option<f64>); 8] = [
    (
        "table, 100 x 100 flat",
        "--shape flat --vbar 0:1.2:100 --amp 0:3:100",
        "--shape flat --vbar 0.6 --amp 1.5",
        10_000,
        None,
    ),
    (
        "table, 10 x 100 parabolic",
        "--shape parabolic --vbar 0:1.2:100 --amp 0:3:10",
        "--shape parabolic --vbar 0.6 --amp 1.5",
        1_000,
        None,
    ),
    (
        "table, oscillation in the sliding direction, flat: 10 vhat x 10 T x 10 phases at du/u0 = 1.5",
        "--shape flat --vhat 0.1:1.2:10 --amp 1.5 --tangential-amp 0.1:4:10 --phase 0:6:10",
        "--shape flat --vhat 0.6 --amp 1.5 --tangential-amp 2 --phase 1",
        1_000,
        None,
    ),
    (
        "table, oscillation in the sliding direction, parabolic: 5 vhat x 5 T x 4 phases at du/u0 = 1.5",
        "--shape parabolic --vhat 0.1:1.2:5 --amp 1.5 --tangential-amp 0.1:4:5 --phase 0:6:4",
        "--shape parabolic --vhat 0.6 --amp 1.5 --tangential-amp 2 --phase 1",
        100,
        None,
    ),
    (
        "table on a system (K/kx 1, Omega 0.5, zeta 0.05), flat: 50 vbar at du/u0 = 0.5",
        "--shape flat --vbar 0.02:1:50 --amp 0.5 --system-stiffness 1 --frequency-ratio 0.5 --damping 0.05",
        "--shape flat --vbar 0.6 --amp 0.5 --system-stiffness 1 --frequency-ratio 0.5 --damping 0.05",
        50,
        Some(1.5e6),
    ),
    (
        "table on a system (K/kx 1, Omega 0.5, zeta 0.05), parabolic, 64 springs: 4 vbar at du/u0 = 0.5",
        "--shape parabolic --vbar 0.1:1:4 --amp 0.5 --system-stiffness 1 --frequency-ratio 0.5 --damping 0.05 \
         --springs 64",
        "--shape parabolic --vbar 0.6 --amp 0.5 --system-stiffness 1 --frequency-ratio 0.5 --damping 0.05 --springs 64",
        4,
        None,
    ),
    (
        "table in the plane, flat: 20 vhat at du/u0 = 0.5, W 1.2, psi 0.7",
        "--shape flat --vhat 0.1:1.2:20 --amp 0.5 --transverse-amp 1.2 --transverse-phase 0.7",
        "--shape flat --vhat 0.3 --amp 0.5 --transverse-amp 1.2 --transverse-phase 0.7",
        20,
        None,
    ),
    (
        "table in the plane, parabolic: 2 vhat at du/u0 = 0.5, W 1.2, psi 0.7",
        "--shape parabolic --vhat 0.3:0.6:2 --amp 0.5 --transverse-amp 1.2 --transverse-phase 0.7",
        "--shape parabolic --vhat 0.3 --amp 0.5 --transverse-amp 1.2 --transverse-phase 0.7",
        2,
        None,
    ),
];

/// Instructions per row of `table` ([`TABLES`]), against a one-point table.
fn table_counts() -> Vec<crate::bench::InstructionCount> {
    let args = |options: &str| format!("table {options} --format csv");
    let count = |options: &str| callgrind(&args(options).split_whitespace().collect::<Vec<_>>());
    let of = |(workload, table, single, rows, target): (&str, &str, &str, usize, Option<f64>)| {
        Some(crate::bench::InstructionCount {
            workload: workload.into(),
            rows,
            instructions_per_row: (count(table)? - count(single)?) / (rows - 1) as f64,
            command: format!("valgrind --tool=callgrind fricosc {} (minus 1 point)", args(table)),
            target,
        })
    };
    TABLES.into_iter().filter_map(of).collect()
}
