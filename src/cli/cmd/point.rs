//! `fricosc point`: one point with its regime, events and bands (JSON).

use super::{io_err, tol_of, vbar_of, Common};
use crate::cli::error::{Error, Result};
use crate::cli::grid::parse_number;
use crate::shape::Shape;
use clap::Args;
use std::io::{self, Write};

#[derive(Args)]
pub struct PointArgs {
    #[command(flatten)]
    pub common: Common,
    /// Amplitude du/u0 (>= 0).
    #[arg(long, allow_hyphen_values = true)]
    pub amp: String,
}

fn exact_point(shape: &Shape, vbar: f64, amp: f64, tol: f64) -> Result<serde_json::Value> {
    serde_json::to_value(shape.point(vbar, amp, &crate::Options::default().with_tol(tol))?)
        .map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })
}

pub fn run(a: PointArgs) -> Result<()> {
    let shape = crate::cli::input::parse_shape(&a.common.shape)?;
    let amp = parse_number("--amp", &a.amp)?;
    let vbar = match (&a.common.velocity.vbar, &a.common.velocity.vhat) {
        (Some(v), _) => parse_number("--vbar", v)?,
        (None, Some(h)) => vbar_of(parse_number("--vhat", h)?, amp)?,
        (None, None) => unreachable!("clap requires one of --vbar, --vhat"),
    };
    let tol = tol_of(&a.common.tol)?;
    let body = match a.common.method.stepping()? {
        Some(st) => {
            let e = crate::stepper::evaluate(&shape, vbar, amp, st)?;
            serde_json::json!({"vbar": vbar, "amp": amp, "mu_ratio": e.ratio.mu_ratio, "reduction": e.ratio.reduction,
                "method": "stepping", "steps": e.steps, "springs": e.springs, "period_change": e.period_change})
        }
        None => exact_point(&shape, vbar, amp, tol)?,
    };
    let mut obj = serde_json::Map::new();
    obj.insert("shape".into(), shape.name().into());
    if let serde_json::Value::Object(m) = body {
        obj.extend(m);
    }
    let json = serde_json::Value::Object(obj);
    let mut out = io::stdout().lock();
    serde_json::to_writer_pretty(&mut out, &json).map_err(|e| io_err(e.into()))?;
    writeln!(out).map_err(io_err)
}
