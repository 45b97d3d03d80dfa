//! `fricosc claims`: every quantitative statement of the seed, checked.

use super::emit;
use fricosc::error::Result;
use fricosc::export::{export, Format};

/// Print the claims as Markdown, JSON or CSV.
pub(crate) fn run(format: &str) -> Result<()> {
    let format = Format::parse(format, &[Format::Markdown, Format::Json, Format::Csv])?;
    let claims = fricosc::claims::check();
    let text = match format {
        Format::Markdown => fricosc::claims::markdown(&claims),
        f => export(&claims, f)?,
    };
    emit(if text.ends_with('\n') { text } else { text + "\n" }.as_str())
}
