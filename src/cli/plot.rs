//! `fricosc plot`: the user's own curves in the style of the seed's figures.

use crate::cmd::{drawing_kind, emit, list, write_drawing, List, VelocityList};
use crate::error::Result;
use clap::Args;
use fricosc::validation::OscillationInput;
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
    /// Its phase against the normal oscillation, radians (default 0). Several (a comma list or
    /// start:stop:count) at one --vhat: the curves are drawn against the phase.
    #[arg(long, allow_hyphen_values = true, value_parser = list, requires = "tangential_amp")]
    pub phase: Option<List>,
    /// The body on a system with mass and stiffness: the curves are its attractors'.
    /// Across the sliding direction (with --vhat): the curves are the plane's mu_ratio.
    #[command(flatten)]
    pub transverse: crate::cmd::TransversePoint,
    #[command(flatten)]
    pub system: crate::cmd::SystemPoint,
    /// With --system-stiffness, a curved body: its springs (32 to 16384, default 256).
    #[arg(long, requires = "system_stiffness")]
    pub springs: Option<usize>,
    /// With --overlay and a column mu: the Coulomb coefficient (mu_ratio = mu / mu0).
    #[arg(long, allow_hyphen_values = true, value_parser = crate::cmd::positive, requires = "overlay")]
    pub mu0: Option<f64>,
}

pub fn run(a: PlotArgs) -> Result<()> {
    if let Some(path) = &a.out {
        drawing_kind("--out", path)?;
    }
    let shape = crate::input::parse_shape(&a.shape)?;
    if a.velocity.over_t() {
        return Err(crate::error::Error::parse(
            "--vhat-over-t",
            "applies to table; plot draws against --vhat (or the phase)",
        ));
    }
    let (xs, vhat) = a.velocity.values();
    let phases = a.phase.as_ref().map_or(&[0.0][..], |p| &p.0[..]);
    crate::cmd::warn_degrees(phases);
    let system = a.system.system(a.springs)?;
    if system.is_some() && phases.len() > 1 {
        return Err(crate::error::Error::parse(
            "--system-stiffness",
            "a plot on a system draws against the velocity (one --phase)",
        ));
    }
    let transverse = a.transverse.oscillation()?;
    if transverse.is_some() && (system.is_some() || phases.len() > 1 || !vhat) {
        let reason = "a plot across the sliding direction draws against --vhat, stiff, at one --phase";
        return Err(crate::error::Error::parse("--transverse-amp", reason));
    }
    let (mut fig, fixed) = match (a.tangential_amp, phases, xs) {
        (Some(t), [_, _, ..], &[v]) if vhat => {
            (crate::figures::against_phase(&shape, &a.amp.0, v, t, phases)?, Fixed::Vhat(v))
        }
        (Some(_), [_, _, ..], _) => {
            return Err(crate::error::Error::parse(
                "--phase",
                "several phases are drawn against the phase at one --vhat",
            ))
        }
        (t, _, _) => {
            let tangential = t.map(|t| (t, phases[0]));
            (
                crate::figures::user_with(&shape, &a.amp.0, xs, vhat, (tangential, transverse), system.as_ref())?,
                Fixed::Phase(phases[0]),
            )
        }
    };
    if let Some(file) = &a.overlay {
        let (text, source) = crate::cmd::read_input(Some(file.clone()))?;
        let table = crate::validate::read_table(&text, &source)?;
        if let Some(named) = table.shape() {
            if crate::input::parse_shape(named)?.name() != shape.name() {
                return Err(crate::error::Error::parse(
                    source,
                    format!("its points are for shape '{named}', the plot is for '{}'", shape.name()),
                ));
            }
        }
        let name = std::path::Path::new(&source).file_name().map_or(source.clone(), |n| n.to_string_lossy().into());
        let across = transverse.map_or((0.0, 0.0), |w| (w.amp(), w.phase()));
        let (rows, x_as_is) = match (a.tangential_amp, transverse) {
            (None, None) if table.is_oscillation() => {
                return Err(crate::error::Error::parse(
                    source,
                    "its rows are under oscillation (column 'tangential_amp' or 'transverse_amp'): plot them with \
                     --vhat and --tangential-amp (--phase) or --transverse-amp (--transverse-phase)",
                ))
            }
            (None, None) => (table.rows(a.mu0, &source)?, false),
            (t, _) => {
                let rows = table.oscillation_rows(a.mu0, &source)?;
                (oscillation_points(&rows, (t.unwrap_or(0.0), across), fixed, &source)?, true)
            }
        };
        crate::figures::overlay(&mut fig, &rows, x_as_is, &name)?;
    }
    let svg = crate::figures::chart(&fig).svg();
    match &a.out {
        Some(path) => write_drawing("--out", path, &svg),
        None => emit(&svg),
    }
}

/// What a combined plot holds fixed besides `T`: the phase (curves against
/// `vhat`) or `vhat` (curves against the phase).
#[derive(Clone, Copy)]
enum Fixed {
    Phase(f64),
    Vhat(f64),
}

/// `(x, amp, mu_ratio)` of a table under oscillation on the plot's axis
/// (`vhat`, or the phase reduced to `[0, 2 pi)` as the solver reduces it),
/// every row at the plot's `T`, fixed value and `(W, psi)` across.
fn oscillation_points(
    rows: &[OscillationInput],
    (t, across): (f64, (f64, f64)),
    fixed: Fixed,
    source: &str,
) -> Result<Vec<(f64, f64, f64)>> {
    let reduce = |p: f64| {
        let c = fricosc::Conditions::vhat(0.0, 0.0).and_then(|c| c.with_tangential(1.0, p));
        c.ok().and_then(|c| c.tangential()).map_or(p, |x| x.1)
    };
    let (other, plot) = match fixed {
        Fixed::Phase(p) => ("phase", reduce(p)),
        Fixed::Vhat(v) => ("vhat", v),
    };
    let held = |r: &OscillationInput| match fixed {
        Fixed::Phase(_) => (reduce(r.phase), r.vhat),
        Fixed::Vhat(_) => (r.vhat, reduce(r.phase)),
    };
    let off = |r: &OscillationInput| (r.transverse_amp, r.transverse_phase) != across;
    match rows.iter().position(|r| r.tangential_amp != t || held(r).0 != plot || off(r)) {
        Some(i) => Err(crate::error::Error::parse(
            source,
            format!(
                "row {i} is at tangential_amp {}, {other} {}, across {:?}; the plot is at --tangential-amp {t}, \
                 --{other} {plot}, across {across:?} (overlay one oscillation at a time)",
                rows[i].tangential_amp,
                held(&rows[i]).0,
                (rows[i].transverse_amp, rows[i].transverse_phase)
            ),
        )),
        None => Ok(rows.iter().map(|r| (held(r).1, r.amp, r.mu_ratio)).collect()),
    }
}
