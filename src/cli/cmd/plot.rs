//! `fricosc plot`: the user's own curves in the style of the seed's figures.

use super::{drawing_kind, emit, list, write_drawing, List, VelocityList};
use crate::cli::error::Result;
use clap::Args;

#[derive(Args)]
pub struct PlotArgs {
    /// Indenter shape: flat, parabolic, cone, power:N, flat-tip:E, profile:FILE@U0, gx:FILE@U0.
    #[arg(long, default_value = "flat")]
    pub shape: String,
    #[command(flatten)]
    pub velocity: VelocityList,
    /// Amplitudes du/u0, one curve each (at most 12): a comma list or start:stop:count.
    #[arg(long, allow_hyphen_values = true, value_parser = list)]
    pub amp: List,
    /// Write the drawing to this file, SVG or PNG (300 dpi) by its extension (default: SVG on stdout).
    #[arg(long)]
    pub out: Option<String>,
}

pub fn run(a: PlotArgs) -> Result<()> {
    if let Some(path) = &a.out {
        drawing_kind("--out", path)?;
    }
    let shape = crate::cli::input::parse_shape(&a.shape)?;
    let (xs, vhat) = a.velocity.values();
    let fig = crate::cli::figures::user(&shape, &a.amp.0, xs, vhat)?;
    let svg = crate::cli::figures::chart(&fig).svg();
    match &a.out {
        Some(path) => write_drawing("--out", path, &svg),
        None => emit(&svg),
    }
}
