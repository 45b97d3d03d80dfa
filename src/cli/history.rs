//! `fricosc history`: the force histories of [`fricosc::history`] as a
//! report (CSV, JSON, the seed's Fig. 2 as SVG).

use crate::cmd::{emit_bytes, list, Drive, List, MethodArg, DEFAULT_STEPPING};
use crate::error::{Error, Result};
use crate::export::{export_bytes, Format};
use clap::Args;
use fricosc::history::{History, Sample};
impl crate::export::Report for History {
    /// On a system also the body's lag behind the drive, velocity and the system's force.
    fn columns(&self) -> Vec<String> {
        let first = self.samples.first();
        let body = first.is_some_and(|x| x.body.is_some());
        let extra: &[&str] = if body { &["body_lag", "body_velocity", "system_force"] } else { &[] };
        let across: &[&str] = if first.is_some_and(|x| x.transverse.is_some()) { &["transverse"] } else { &[] };
        ["tau", "normal", "tangential"]
            .iter()
            .chain(across)
            .chain(&["event"])
            .chain(extra)
            .map(|c| c.to_string())
            .collect()
    }

    fn comment(&self) -> Option<String> {
        Some(format!(
            "fricosc history of {} at {}: tau = omega t with the indentation u0 - du cos(tau); {}",
            self.shape, self.point, self.units
        ))
    }

    fn rows(&self) -> Vec<Vec<String>> {
        let n = crate::output::num;
        self.samples
            .iter()
            .map(|x| {
                let ev = x.event.map(|e| {
                    serde_json::to_value(e).ok().and_then(|v| v.as_str().map(String::from)).unwrap_or_default()
                });
                let body = x.body.iter().flat_map(|b| [n(b.body_lag), n(b.body_velocity), n(b.system_force)]);
                let across = x.transverse.map(n);
                [n(x.tau), n(x.normal), n(x.tangential)]
                    .into_iter()
                    .chain(across)
                    .chain([ev.unwrap_or_default()])
                    .chain(body)
                    .collect()
            })
            .collect()
    }

    /// Both forces over the phase (the seed's Fig. 2).
    fn svg(&self) -> Option<Result<String>> {
        use crate::chart::{Axis, Chart, Series, Style, OKABE_ITO};
        let pts = |f: fn(&Sample) -> f64| self.samples.iter().map(|x| (x.tau, f(x))).collect::<Vec<_>>();
        let ymax = self.samples.iter().map(|x| x.normal).fold(0.0, f64::max) * 1.05 + 1e-12;
        // A backward slip (a tangential oscillation) takes the force below 0.
        let lowest =
            |x: &Sample| x.tangential.min(x.body.map_or(0.0, |b| b.system_force)).min(x.transverse.unwrap_or(0.0));
        let ymin = self.samples.iter().map(lowest).fold(0.0, f64::min) * 1.05;
        let line = |label: &str, f: fn(&Sample) -> f64, style| Series {
            label: label.into(),
            points: pts(f),
            style,
            legend: true,
        };
        let mut series = vec![
            line("μ_{0} × normal force", |x| x.normal, Style::line(OKABE_ITO[4])),
            line("tangential force", |x| x.tangential, Style::line(OKABE_ITO[5]).width(1.5)),
        ];
        if self.samples.first().is_some_and(|x| x.transverse.is_some()) {
            let across = |x: &Sample| x.transverse.unwrap_or(f64::NAN);
            series.push(line("force across the sliding direction", across, Style::line(OKABE_ITO[1])));
        }
        // On a system, the system spring's force on the body beside the contact's.
        if self.samples.first().is_some_and(|x| x.body.is_some()) {
            let system = |x: &Sample| x.body.map_or(f64::NAN, |b| b.system_force);
            series.push(line("system force", system, Style::line(OKABE_ITO[2])));
        }
        let tmax = self.samples.last().map_or(1.0, |x| x.tau);
        let unit = "force / (μ_{0} F_{0})";
        Some(Ok(Chart {
            title: format!("{}: forces at {} ({})", self.shape, self.point, self.units),
            x: Axis::linear("phase ωt (rad)", (0.0, tmax)),
            y: Axis::linear(unit, (ymin, ymax)),
            series,
            key: vec![],
            rules: vec![],
        }
        .svg()))
    }
}

#[derive(Args)]
pub struct HistoryArgs {
    /// Shape: flat, a power law, flat-tip:E or a tabulated profile.
    #[arg(long, default_value = "flat")]
    pub shape: String,
    #[command(flatten)]
    pub drive: Drive,
    /// Periods to sample.
    #[arg(long, default_value_t = 1)]
    pub periods: usize,
    /// Uniform samples over all periods (event times are added).
    #[arg(long, default_value_t = 400)]
    pub samples: usize,
    /// Springs summed for curved shapes (default 4000; on a system 256, 32 to 16384).
    #[arg(long)]
    pub springs: Option<usize>,
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

/// Springs a stiff curved history sums by default.
const DEFAULT_HISTORY_SPRINGS: usize = 4000;

pub fn run(a: HistoryArgs) -> Result<()> {
    let stepping = match (a.method, a.steps_per_period) {
        (MethodArg::Stepping, m) => Some(m.unwrap_or(DEFAULT_STEPPING)),
        (_, Some(_)) => return Err(Error::parse("--steps-per-period", "applies only with --method stepping")),
        (_, None) => None,
    };
    let chosen = a.spring_at.map(|l| l.0).unwrap_or_default();
    let shape = crate::input::parse_shape(&a.shape)?;
    let c = a.drive.conditions()?;
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
                .with_springs(a.springs.unwrap_or(DEFAULT_HISTORY_SPRINGS))
                .with_spring_at(chosen);
            let c = a.drive.system.system(a.springs)?.map_or(c, |sys| c.with_system(sys));
            fricosc::history::history(&shape, &c, &opts)?
        }
        Some(m) => {
            if !shape.is_flat() || !chosen.is_empty() {
                return Err(fricosc::Error::InvalidShape {
                    spec: shape.name().into(),
                    reason: "history --method stepping steps the flat punch (without --spring-at)".into(),
                }
                .into());
            }
            fricosc::history::stepped_history(&c, a.periods, m)?
        }
    };
    let mut bytes = export_bytes(&h, format)?;
    if format != Format::Png && bytes.last() != Some(&b'\n') {
        bytes.push(b'\n');
    }
    emit_bytes(&bytes)
}
