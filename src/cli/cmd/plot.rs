//! `fricosc plot`: the user's own curves in the style of the seed's figures.

use super::{drawing_kind, emit, write_drawing, Velocity};
use crate::cli::error::Result;
use crate::cli::grid::parse_values;
use clap::Args;

#[derive(Args)]
pub struct PlotArgs {
    /// Indenter shape: flat, parabolic, cone, power:N, flat-tip:E, profile:FILE@U0, gx:FILE@U0.
    #[arg(long, default_value = "flat")]
    pub shape: String,
    #[command(flatten)]
    pub velocity: Velocity,
    /// Amplitudes du/u0, one curve each (at most 12): a comma list or start:stop:count.
    #[arg(long, allow_hyphen_values = true)]
    pub amp: String,
    /// Write the drawing to this file, SVG or PNG (300 dpi) by its extension (default: SVG on stdout).
    #[arg(long)]
    pub out: Option<String>,
}

pub fn run(a: PlotArgs) -> Result<()> {
    if let Some(path) = &a.out {
        drawing_kind("--out", path)?;
    }
    let shape = crate::cli::input::parse_shape(&a.shape)?;
    let amps = parse_values("--amp", &a.amp)?;
    let (xs, vhat) = match (&a.velocity.vbar, &a.velocity.vhat) {
        (Some(v), _) => (parse_values("--vbar", v)?, false),
        (None, Some(h)) => (parse_values("--vhat", h)?, true),
        (None, None) => unreachable!("clap requires one of --vbar, --vhat"),
    };
    let fig = crate::cli::figures::user(&shape, &amps, &xs, vhat)?;
    let svg = crate::cli::figures::chart(&fig).svg();
    match &a.out {
        Some(path) => write_drawing("--out", path, &svg),
        None => emit(&svg),
    }
}
