//! `fricosc figures`: the seed's figures, exact, with its approximations.

use super::emit;
use crate::error::Result;
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
    let dir = crate::outdir::OutDir::open("--out", out)?;
    let names = crate::figures::write_all(&dir)?;
    emit(&format!("wrote {} figures to {out}: {}\n", names.len(), names.join(", ")))
}
