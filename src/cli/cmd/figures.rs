//! `fricosc figures`: the seed's figures, exact, with its approximations.

use super::{check_out_dir, emit};
use crate::cli::error::Result;
use clap::Args;

#[derive(Args)]
pub struct FiguresArgs {
    /// Output directory (created if missing).
    #[arg(long)]
    pub out: String,
}

/// Write every figure into `--out`.
pub fn run(a: FiguresArgs) -> Result<()> {
    let out = a.out.as_str();
    check_out_dir(out)?;
    let names = crate::cli::figures::write_all(std::path::Path::new(out))?;
    emit(&format!("wrote {} figures to {out}: {}\n", names.len(), names.join(", ")))
}
