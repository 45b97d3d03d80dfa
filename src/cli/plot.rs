//! `fricosc plot`: the user's own curves in the style of the seed's figures.

use crate::cmd::{drawing_kind, emit, list, write_drawing, List, VelocityList};
use crate::error::Result;
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
    /// Draw your own points over the curves: a table as `validate` reads it (vbar or vhat,
    /// amp, mu_ratio or mu), markers in the colour of their amplitude's curve (grey if the
    /// plot has none). At most 10^5 points.
    #[arg(long, value_name = "FILE")]
    pub overlay: Option<String>,
    /// Amplitude of an oscillation in the sliding direction, dx/l in pre-slip lengths (>= 0, at most 1e6;
    /// needs --vhat): the curves are the combined oscillation's.
    #[arg(long, allow_hyphen_values = true, value_parser = crate::cmd::nonneg)]
    pub tangential_amp: Option<f64>,
    /// Its phase against the normal oscillation, radians (default 0).
    #[arg(long, allow_hyphen_values = true, value_parser = crate::cmd::number, requires = "tangential_amp")]
    pub phase: Option<f64>,
    /// With --overlay and a column mu: the Coulomb coefficient (mu_ratio = mu / mu0).
    #[arg(long, allow_hyphen_values = true, value_parser = crate::cmd::positive, requires = "overlay")]
    pub mu0: Option<f64>,
}

pub fn run(a: PlotArgs) -> Result<()> {
    if let Some(path) = &a.out {
        drawing_kind("--out", path)?;
    }
    let shape = crate::input::parse_shape(&a.shape)?;
    let (xs, vhat) = a.velocity.values();
    let tangential = a.tangential_amp.map(|t| (t, a.phase.unwrap_or(0.0)));
    let mut fig = crate::figures::user_with(&shape, &a.amp.0, xs, vhat, tangential)?;
    if let Some(file) = &a.overlay {
        let (text, source) = crate::cmd::read_input(Some(file.clone()))?;
        let table = crate::validate::read_table(&text, &source)?;
        if let Some(named) = table.shape() {
            if crate::input::parse_shape(named)?.name() != shape.name() {
                return Err(crate::error::Error::Parse {
                    context: source,
                    reason: format!("its points are for shape '{named}', the plot is for '{}'", shape.name()),
                });
            }
        }
        let rows = table.rows(a.mu0, &source)?;
        let name = std::path::Path::new(&source).file_name().map_or(source.clone(), |n| n.to_string_lossy().into());
        crate::figures::overlay(&mut fig, &rows, &name)?;
    }
    let svg = crate::figures::chart(&fig).svg();
    match &a.out {
        Some(path) => write_drawing("--out", path, &svg),
        None => emit(&svg),
    }
}
