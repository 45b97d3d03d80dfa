//! `fricosc suite`: write the reference suite, or check a copy of it.

use super::{emit, Outcome};
use crate::error::Result;
use clap::Args;

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
        _ => Err(crate::error::Error::Parse {
            context: "suite".into(),
            reason: "give exactly one of --out DIR (write) and --check DIR (verify)".into(),
        }),
    }
}
