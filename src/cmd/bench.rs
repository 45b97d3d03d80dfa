//! `fricosc bench`: the work-precision benchmark.

use super::{check_out_dir, emit};
use fricosc::error::{Error, Result};
use std::io;

pub(crate) fn run(out: &str, quick: bool) -> Result<()> {
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
