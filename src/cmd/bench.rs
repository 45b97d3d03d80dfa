//! `fricosc bench`: the work-precision benchmark.

use super::{check_out_dir, emit};
use fricosc::error::{Error, Result};
use fricosc::export::{export_bytes, Format};

/// Run the benchmark and write its JSON, CSV, SVG and PNG into `out`.
pub(crate) fn run(out: &str, quick: bool) -> Result<()> {
    check_out_dir(out)?;
    let dir = std::path::Path::new(out);
    std::fs::create_dir_all(dir).map_err(|e| Error::write(out, e))?;
    let mut report = fricosc::bench::run(quick);
    if !quick {
        report.instructions = instruction_counts(dir)?;
    }
    for (ext, format) in [("json", Format::Json), ("csv", Format::Csv), ("svg", Format::Svg), ("png", Format::Png)] {
        std::fs::write(dir.join(format!("work-precision.{ext}")), export_bytes(&report, format)?)
            .map_err(|e| Error::write(out, e))?;
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

/// Per-row instruction counts of `batch` (flat and parabolic rows) and `table`,
/// where valgrind is installed (none otherwise).
fn instruction_counts(dir: &std::path::Path) -> Result<Vec<fricosc::bench::InstructionCount>> {
    let mut out = vec![];
    // A fixed pseudo-random row set: vbar in [0, 1.2], amp in [0, 3].
    let mut seed = 0x9E3779B97F4A7C15u64;
    let mut rand = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut rows = |shape: &str, n: usize| -> String {
        let r: Vec<String> = (0..n)
            .map(|_| format!("{{\"shape\":\"{shape}\",\"vbar\":{:?},\"amp\":{:?}}}", 1.2 * rand(), 3.0 * rand()))
            .collect();
        format!("[{}]", r.join(",\n"))
    };
    for (shape, n) in [("flat", 10_000usize), ("parabolic", 1_000)] {
        let (big, one) = (dir.join(format!("rows-{shape}.json")), dir.join(format!("row-{shape}.json")));
        std::fs::write(&big, rows(shape, n)).map_err(|e| Error::write(&big.display().to_string(), e))?;
        std::fs::write(&one, rows(shape, 1)).map_err(|e| Error::write(&one.display().to_string(), e))?;
        let (Some(i_n), Some(i_1)) =
            (callgrind(&["batch", &big.display().to_string()]), callgrind(&["batch", &one.display().to_string()]))
        else {
            return Ok(vec![]);
        };
        let _ = (std::fs::remove_file(&big), std::fs::remove_file(&one));
        out.push(fricosc::bench::InstructionCount {
            workload: format!("batch, random {shape} rows"),
            rows: n,
            instructions_per_row: (i_n - i_1) / (n - 1) as f64,
            command: format!("valgrind --tool=callgrind fricosc batch FILE ({n} rows minus 1 row)"),
        });
    }
    let table = callgrind(&["table", "--shape", "flat", "--vbar", "0:1.2:100", "--amp", "0:3:100"]);
    let single = callgrind(&["table", "--shape", "flat", "--vbar", "0.6", "--amp", "1.5"]);
    if let (Some(t), Some(s)) = (table, single) {
        out.push(fricosc::bench::InstructionCount {
            workload: "table, 100 x 100 flat".into(),
            rows: 10_000,
            instructions_per_row: (t - s) / 9_999.0,
            command:
                "valgrind --tool=callgrind fricosc table --shape flat --vbar 0:1.2:100 --amp 0:3:100 (minus 1 point)"
                    .into(),
        });
    }
    Ok(out)
}
