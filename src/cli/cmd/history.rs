//! `fricosc history`: exact force histories (the seed's Fig. 2).

use super::{emit_bytes, vbar_of, Velocity};
use crate::cli::error::Result;
use crate::cli::export::{export_bytes, Format};
use crate::cli::grid::{parse_number, parse_values};

pub fn run(
    shape: &str,
    velocity: &Velocity,
    amp: &str,
    (periods, samples, springs): (usize, usize, usize),
    spring_at: Option<&str>,
    format: &str,
    stepping: Option<usize>,
) -> Result<()> {
    let chosen = match spring_at {
        Some(t) => parse_values("--spring-at", t)?,
        None => vec![],
    };
    let shape = crate::cli::input::parse_shape(shape)?;
    let amp = parse_number("--amp", amp)?;
    let vbar = match (&velocity.vbar, &velocity.vhat) {
        (Some(v), _) => parse_number("--vbar", v)?,
        (None, Some(h)) => vbar_of(parse_number("--vhat", h)?, amp)?,
        (None, None) => unreachable!("clap requires one of --vbar, --vhat"),
    };
    let format = Format::parse(format, &[Format::Json, Format::Csv, Format::Svg, Format::Png])?;
    let h = match stepping {
        None => {
            let opts = crate::history::HistoryOptions::default()
                .with_periods(periods)
                .with_samples(samples)
                .with_springs(springs)
                .with_spring_at(chosen);
            crate::history::history(&shape, vbar, amp, &opts)?
        }
        Some(m) => {
            if !shape.is_flat() || !chosen.is_empty() {
                return Err(crate::Error::InvalidShape {
                    spec: shape.name().into(),
                    reason: "history --method stepping steps the flat punch (without --spring-at)".into(),
                }
                .into());
            }
            crate::history::stepped_history(vbar, amp, periods, m)?
        }
    };
    let mut bytes = export_bytes(&h, format)?;
    if format != Format::Png && bytes.last() != Some(&b'\n') {
        bytes.push(b'\n');
    }
    emit_bytes(&bytes)
}
