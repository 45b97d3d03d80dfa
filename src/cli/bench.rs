//! `fricosc bench`: the work-precision comparison of the exact solver with the
//! seed's time-stepping scheme.
//!
//! Each point is (absolute error of `mu_ratio` against a 40-digit reference,
//! minimum over `k` samples of the wall time per evaluation after a warm-up);
//! a sample repeats the evaluation until it lasts a few milliseconds. Failures
//! (an error or a non-finite value) are kept and listed, never dropped.

use fricosc::stepper::Stepping;
use fricosc::Shape;
use serde::Serialize;
use std::time::Instant;

/// The reference values this benchmark uses: `data/reference-values.json`, the
/// project's public 40-digit values (independent evaluation, cross-checked by a
/// converged time stepper; `tests/reference.rs` reads and checks them).
const REFERENCES: &str = include_str!("../../data/reference-values.json");

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

/// Run the benchmark; `quick` finishes in seconds (for CI).
pub fn run(quick: bool) -> Report {
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
        cases.push(Case { name: name.into(), shape: shape_name.into(), vbar, amp, reference: reference.clone() });
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
        if let (Some((ee, et)), Some((se, st))) = (exact_best, stepping_best) {
            if ee <= se {
                ratios.push(Ratio {
                    case: name.into(),
                    exact_error: ee,
                    exact_time_s: et,
                    stepping_error: se,
                    stepping_time_s: st,
                    time_ratio: st / et,
                });
            }
        }
    }
    Report {
        version: env!("CARGO_PKG_VERSION").into(),
        machine: machine(),
        reference: "40-digit values of data/reference-values.json (independent high-precision evaluation of the \
                    exact periodic state, cross-checked by a converged time stepper), checked by tests/reference.rs"
            .into(),
        cases,
        points,
        ratios,
        failures,
        mode: if quick { "quick" } else { "full" }.into(),
        instructions: vec![],
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
    use crate::plot::{Axis, Chart, Dash, Key, Marker, Rgb, Series, Style, OKABE_ITO};
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
        rules: vec![crate::plot::Rule { horizontal: true, at: ERROR_FLOOR }],
    }
    .svg()
}
