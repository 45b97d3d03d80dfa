//! `fricosc bench`: the work-precision benchmark.

use super::{check_out_dir, emit};
use fricosc::error::{Error, Result};
use fricosc::export::{export, Format};

/// Run the benchmark and write its JSON, CSV and SVG into `out`.
pub(crate) fn run(out: &str, quick: bool) -> Result<()> {
    check_out_dir(out)?;
    let dir = std::path::Path::new(out);
    std::fs::create_dir_all(dir).map_err(|e| Error::write(out, e))?;
    let report = fricosc::bench::run(quick);
    for (ext, format) in [("json", Format::Json), ("csv", Format::Csv), ("svg", Format::Svg)] {
        std::fs::write(dir.join(format!("work-precision.{ext}")), export(&report, format)?)
            .map_err(|e| Error::write(out, e))?;
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
