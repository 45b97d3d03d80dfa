//! `fricosc history`: exact force histories (the seed's Fig. 2).

use super::{emit_bytes, list, number, List, MethodArg, VelocityPoint, DEFAULT_STEPPING};
use crate::error::{Error, Result};
use crate::export::{export_bytes, Format};
use clap::Args;

#[derive(Args)]
pub struct HistoryArgs {
    /// Shape: flat, a power law, flat-tip:E or a tabulated profile.
    #[arg(long, default_value = "flat")]
    pub shape: String,
    #[command(flatten)]
    pub velocity: VelocityPoint,
    /// Amplitude du/u0.
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub amp: f64,
    /// Periods to sample.
    #[arg(long, default_value_t = 1)]
    pub periods: usize,
    /// Uniform samples over all periods (event times are added).
    #[arg(long, default_value_t = 400)]
    pub samples: usize,
    /// Springs summed for curved shapes.
    #[arg(long, default_value_t = 4000)]
    pub springs: usize,
    /// Curved shapes: report these springs too (positions x/x_c, comma list; JSON only).
    #[arg(long, allow_hyphen_values = true, value_parser = list)]
    pub spring_at: Option<List>,
    /// json, csv, svg or png (the seed's Fig. 2, 300 dpi).
    #[arg(long, default_value = "json")]
    pub format: String,
    /// exact (default) or stepping: the seed's time-stepping scheme (flat punch), one row per
    /// step, the same columns (for comparing with validate --history).
    #[arg(long, value_enum, default_value = "exact")]
    pub method: MethodArg,
    /// Time steps per period with --method stepping (default 1000).
    #[arg(long, allow_hyphen_values = true)]
    pub steps_per_period: Option<usize>,
}

pub fn run(a: HistoryArgs) -> Result<()> {
    let stepping = match (a.method, a.steps_per_period) {
        (MethodArg::Stepping, m) => Some(m.unwrap_or(DEFAULT_STEPPING)),
        (_, Some(_)) => {
            return Err(Error::Parse {
                context: "--steps-per-period".into(),
                reason: "applies only with --method stepping".into(),
            })
        }
        (_, None) => None,
    };
    let chosen = a.spring_at.map(|l| l.0).unwrap_or_default();
    let shape = crate::input::parse_shape(&a.shape)?;
    let amp = a.amp;
    let vbar = match a.velocity.velocity()? {
        fricosc::Velocity::Vbar(v) => fricosc::Conditions::vbar(v, amp)?,
        fricosc::Velocity::Vhat(v) => fricosc::Conditions::vhat(v, amp)?,
    }
    .as_vbar()?;
    let format = Format::parse(&a.format, &[Format::Json, Format::Csv, Format::Svg, Format::Png])?;
    // A drawing holds at most as many points as a plot (checked before any work).
    let drawn = match stepping {
        Some(m) => a.periods as u128 * m as u128 + 1,
        None => a.samples as u128 + 1,
    };
    let limit = crate::figures::MAX_POINTS as u128;
    if matches!(format, Format::Svg | Format::Png) && drawn > limit {
        return Err(Error::TooLarge {
            what: "samples of a history drawn as SVG or PNG (use csv or json for more)".into(),
            count: drawn,
            limit,
        });
    }
    let h = match stepping {
        None => {
            let opts = fricosc::history::HistoryOptions::default()
                .with_periods(a.periods)
                .with_samples(a.samples)
                .with_springs(a.springs)
                .with_spring_at(chosen);
            fricosc::history::history(&shape, vbar, amp, &opts)?
        }
        Some(m) => {
            if !shape.is_flat() || !chosen.is_empty() {
                return Err(fricosc::Error::InvalidShape {
                    spec: shape.name().into(),
                    reason: "history --method stepping steps the flat punch (without --spring-at)".into(),
                }
                .into());
            }
            fricosc::history::stepped_history(vbar, amp, a.periods, m)?
        }
    };
    let mut bytes = export_bytes(&h, format)?;
    if format != Format::Png && bytes.last() != Some(&b'\n') {
        bytes.push(b'\n');
    }
    emit_bytes(&bytes)
}
