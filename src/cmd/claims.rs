//! `fricosc claims`: every quantitative statement of the seed, checked.

use super::emit;
use fricosc::error::Result;
use fricosc::export::{export, Format};

/// Print the claims as Markdown, JSON or CSV.
pub(crate) fn run(format: &str) -> Result<()> {
    let format = Format::parse(format, &[Format::Markdown, Format::Json, Format::Csv])?;
    let text = export(&fricosc::claims::check(), format)?;
    emit(if text.ends_with('\n') { text } else { text + "\n" }.as_str())
}
