//! `fricosc claims`: the seed's claims checked by the library
//! ([`fricosc::seed::claims`]) as Markdown or a table.

use crate::cmd::emit;
use crate::error::Result;
use crate::export::{export, Format};
use clap::Args;
use fricosc::seed::Claim;
/// Width of the Markdown report's lines.
pub const WIDTH: usize = 100;

/// `text` in lines of at most `width` characters (words longer than a line
/// stand alone), the first line after `first`, the others after `indent`.
pub fn wrap(first: &str, text: &str, indent: &str, width: usize) -> String {
    let mut out = String::new();
    let mut line = first.to_string();
    let mut empty = first.trim().is_empty();
    for word in text.split_whitespace() {
        let len = line.chars().count();
        if !empty && len + 1 + word.chars().count() > width {
            out += line.trim_end();
            out.push('\n');
            line = indent.to_string();
            empty = true;
        }
        if !empty {
            line.push(' ');
        }
        line += word;
        empty = false;
    }
    out += line.trim_end();
    out.push('\n');
    out
}

/// The claims as Markdown in lines of at most [`WIDTH`] characters: a summary
/// table (claim, verdict, deviation), then each claim with the seed's
/// statement, the exact value, the deviation with its definition and unit, and
/// the criterion the verdict is computed by.
pub fn markdown(claims: &[Claim]) -> String {
    let mut s = String::from("| # | claim | verdict | deviation |\n|---|---|---|---|\n");
    for (i, c) in claims.iter().enumerate() {
        let dev = c.deviation.map_or("-".to_string(), |d| format!("{d:.3e}"));
        s += &format!("| {} | {} | {} | {dev} |\n", i + 1, c.claim, c.verdict.name());
    }
    for (i, c) in claims.iter().enumerate() {
        s += &format!("\n### {}. {}: {}\n\n", i + 1, c.claim, c.verdict.name());
        s += &wrap("- The seed says:", &c.seed_says, "  ", WIDTH);
        s += &wrap("- The exact solver gives:", &c.exact_gives, "  ", WIDTH);
        let dev = match c.deviation {
            Some(d) => format!("{d:.3e}, {} at {}.", c.deviation_is, c.location),
            None => format!("{} ({}).", c.deviation_is, c.location),
        };
        s += &wrap("- Deviation:", &dev, "  ", WIDTH);
        s += &wrap("- Verdict:", &format!("{}, by the criterion: {}.", c.verdict.name(), c.criterion), "  ", WIDTH);
    }
    s
}

impl crate::export::Report for Vec<Claim> {
    /// One row per claim, every field (the deviation as a number in round-trip precision).
    fn columns(&self) -> Vec<String> {
        ["claim", "seed_says", "exact_gives", "deviation", "deviation_is", "location", "criterion", "verdict"]
            .map(String::from)
            .to_vec()
    }

    fn rows(&self) -> Vec<Vec<String>> {
        self.iter()
            .map(|c| {
                vec![
                    c.claim.clone(),
                    c.seed_says.clone(),
                    c.exact_gives.clone(),
                    c.deviation.map_or(String::new(), crate::output::num),
                    c.deviation_is.clone(),
                    c.location.clone(),
                    c.criterion.clone(),
                    c.verdict.name().to_string(),
                ]
            })
            .collect()
    }
}

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
