//! `fricosc claims`: every quantitative statement of the seed, checked.

use super::{emit, to_json};
use fricosc::error::{Error, Result};

/// Print the claims as Markdown or JSON.
pub(crate) fn run(format: &str) -> Result<()> {
    let claims = fricosc::claims::check();
    match format {
        "markdown" => emit(&fricosc::claims::to_markdown(&claims)),
        "json" => emit(&format!("{}\n", to_json(&claims)?)),
        other => {
            Err(Error::Parse { context: "--format".into(), reason: format!("'{other}' is neither markdown nor json") })
        }
    }
}
