//! `fricosc scene`: physical scenes in SI units.

use super::emit;
use fricosc::error::{Error, Result};
use fricosc::output::Format;
use rayon::prelude::*;
use std::io::IsTerminal;

pub(crate) fn run(files: Vec<String>, schema: bool, format: Format) -> Result<()> {
    if schema {
        return emit(&format!("{}\n", fricosc::scene::schema()));
    }
    if files.is_empty() {
        return Err(Error::Parse { context: "scene".into(), reason: "give a scene file (or --schema)".into() });
    }
    // Read and solve everything before the first byte is written.
    let scenes: Vec<Result<fricosc::scene::Scene>> = files
        .iter()
        .map(|f| {
            let text = fricosc::input::read_capped(f, fricosc::input::MAX_SMALL_BYTES)?;
            fricosc::scene::parse(&text, f)
        })
        .collect();
    let scenes = scenes.into_iter().collect::<Result<Vec<_>>>()?;
    // A progress bar on stderr only when it is a terminal and the work is long.
    let total: usize = scenes.iter().map(fricosc::scene::velocity_count).sum();
    let bar = (std::io::stderr().is_terminal() && total >= 2000).then(|| indicatif::ProgressBar::new(total as u64));
    let tick = |k: u64| {
        if let Some(b) = &bar {
            b.inc(k);
        }
    };
    let results: Vec<Result<fricosc::scene::SceneResult>> =
        scenes.par_iter().zip(&files).map(|(s, f)| fricosc::scene::solve_with_progress(s, f, &tick)).collect();
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let results = results.into_iter().collect::<Result<Vec<_>>>()?;
    for (r, f) in results.iter().zip(&files) {
        for w in &r.warnings {
            eprintln!("warning: {f}: {w}");
        }
    }
    let text = match format {
        Format::Csv => results
            .iter()
            .map(|r| fricosc::export::export(r, fricosc::export::Format::Csv))
            .collect::<Result<Vec<_>>>()?
            .join("\n"),
        Format::Json => {
            let v = if results.len() == 1 { serde_json::to_value(&results[0]) } else { serde_json::to_value(&results) };
            v.and_then(|v| serde_json::to_string_pretty(&v))
                .map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })?
        }
    };
    emit(&format!("{}\n", text.trim_end()))
}
