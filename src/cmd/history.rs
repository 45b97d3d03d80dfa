//! `fricosc history`: exact force histories (the seed's Fig. 2).

use super::{emit, vbar_of, Velocity};
use fricosc::error::{Error, Result};
use fricosc::grid::{parse_number, parse_values};
use fricosc::shape::Shape;

pub(crate) fn run(
    shape: &str,
    velocity: &Velocity,
    amp: &str,
    (periods, samples, springs): (usize, usize, usize),
    spring_at: Option<&str>,
    format: &str,
) -> Result<()> {
    let chosen = match spring_at {
        Some(t) => parse_values("--spring-at", t)?,
        None => vec![],
    };
    let shape = Shape::parse(shape)?;
    let amp = parse_number("--amp", amp)?;
    let vbar = match (&velocity.vbar, &velocity.vhat) {
        (Some(v), _) => parse_number("--vbar", v)?,
        (None, Some(h)) => vbar_of(parse_number("--vhat", h)?, amp)?,
        (None, None) => unreachable!("clap requires one of --vbar, --vhat"),
    };
    if !matches!(format, "json" | "csv" | "svg") {
        return Err(Error::Parse { context: "--format".into(), reason: format!("'{format}' is not json, csv or svg") });
    }
    let h = fricosc::history::history(&shape, vbar, amp, periods, samples, springs, &chosen)?;
    let text = match format {
        "json" => serde_json::to_string_pretty(&h)
            .map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })?,
        "csv" => fricosc::history::to_csv(&h),
        _ => {
            let pts =
                |f: fn(&fricosc::history::Sample) -> f64| h.samples.iter().map(|x| (x.tau, f(x))).collect::<Vec<_>>();
            let ymax = h.samples.iter().map(|x| x.normal).fold(0.0, f64::max) * 1.05 + 1e-12;
            let series = [
                fricosc::plot::Series { label: "mu0 x normal force".into(), points: pts(|x| x.normal), dashed: false },
                fricosc::plot::Series {
                    label: "tangential force".into(),
                    points: pts(|x| x.tangential),
                    dashed: false,
                },
            ];
            let title = format!("{} vbar = {vbar}, du/u0 = {amp} ({})", h.shape, h.units);
            let tmax = h.samples.last().map_or(1.0, |x| x.tau);
            fricosc::plot::lines(&title, "omega t", "force", (0.0, tmax), (0.0, ymax), &series)
                .map_err(|e| Error::Internal { what: format!("drawing the plot: {e}") })?
        }
    };
    emit(&format!("{text}\n"))
}
