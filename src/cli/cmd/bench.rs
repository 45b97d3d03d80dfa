//! `fricosc bench`: the work-precision benchmark.

use super::emit;
use crate::error::{Error, Result};
use crate::export::{export_bytes, Format};
use clap::Args;

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
    let mut report = crate::bench::run(quick);
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
    for c in &report.instructions {
        o += &format!(
            "{}: {:.0} instructions per row (callgrind, {} rows)\n",
            c.workload, c.instructions_per_row, c.rows
        );
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

/// Per-row instruction counts of `batch` (JSON array, JSON Lines and CSV; flat
/// and parabolic rows) and `table`, where valgrind is installed (none
/// otherwise). Each is the count of a large run minus a one-row run (so that
/// start-up is not counted), over the rows' difference. Rayon runs one thread
/// (`RAYON_NUM_THREADS=1`): idle worker threads spin, and their instructions
/// would count as work.
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
        });
    }
    out.extend(table_counts());
    Ok(out)
}

/// Instructions per row of `table` (the seed's problem and oscillation in the
/// sliding direction), against a one-point table.
fn table_counts() -> Vec<crate::bench::InstructionCount> {
    let seed = |shape: &'static str, vbar: &'static str, amp: &'static str| {
        vec!["table", "--shape", shape, "--vbar", vbar, "--amp", amp, "--format", "csv"]
    };
    let oscillation = |shape: &'static str, vhat: &'static str, t: &'static str, phase: &'static str| {
        vec![
            "table",
            "--shape",
            shape,
            "--vhat",
            vhat,
            "--amp",
            "1.5",
            "--tangential-amp",
            t,
            "--phase",
            phase,
            "--format",
            "csv",
        ]
    };
    let tables: [(&str, Vec<&str>, Vec<&str>, usize); 4] = [
        ("table, 100 x 100 flat", seed("flat", "0:1.2:100", "0:3:100"), seed("flat", "0.6", "1.5"), 10_000),
        ("table, 10 x 100 parabolic", seed("parabolic", "0:1.2:100", "0:3:10"), seed("parabolic", "0.6", "1.5"), 1_000),
        (
            "table, oscillation in the sliding direction, flat: 10 vhat x 10 T x 10 phases at du/u0 = 1.5",
            oscillation("flat", "0.1:1.2:10", "0.1:4:10", "0:6:10"),
            oscillation("flat", "0.6", "2", "1"),
            1_000,
        ),
        (
            "table, oscillation in the sliding direction, parabolic: 5 vhat x 5 T x 4 phases at du/u0 = 1.5",
            oscillation("parabolic", "0.1:1.2:5", "0.1:4:5", "0:6:4"),
            oscillation("parabolic", "0.6", "2", "1"),
            100,
        ),
    ];
    let mut out = vec![];
    for (workload, args, single, rows) in tables {
        if let (Some(t), Some(s)) = (callgrind(&args), callgrind(&single)) {
            out.push(crate::bench::InstructionCount {
                workload: workload.into(),
                rows,
                instructions_per_row: (t - s) / (rows - 1) as f64,
                command: format!("valgrind --tool=callgrind fricosc {} (minus 1 point)", args.join(" ")),
            });
        }
    }
    out
}
