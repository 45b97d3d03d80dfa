//! `fricosc claims`: every quantitative statement of the seed, checked.

use super::emit;
use crate::error::Result;
use crate::export::{export, Format};
use clap::Args;

#[derive(Args)]
pub struct ClaimsArgs {
    /// markdown (default), json or csv.
    #[arg(long, default_value = "markdown")]
    pub format: String,
}

/// Print the claims as Markdown, JSON or CSV.
pub fn run(a: ClaimsArgs) -> Result<()> {
    let format = Format::parse(&a.format, &[Format::Markdown, Format::Json, Format::Csv])?;
    let claims = fricosc::seed::claims();
    let text = match format {
        Format::Markdown => crate::claims::markdown(&claims),
        f => export(&claims, f)?,
    };
    emit(if text.ends_with('\n') { text } else { text + "\n" }.as_str())
}
