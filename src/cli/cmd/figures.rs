//! `fricosc figures`: the seed's figures, exact, with its approximations.

use super::{check_out_dir, emit};
use crate::cli::error::Result;

/// Write every figure into `out`.
pub fn run(out: &str) -> Result<()> {
    check_out_dir(out)?;
    let names = crate::cli::figures::write_all(std::path::Path::new(out))?;
    emit(&format!("wrote {} figures to {out}: {}\n", names.len(), names.join(", ")))
}
