//! `fricosc point`: one point with its regime, events and bands (JSON).

use super::{io_err, number, Common, VelocityPoint};
use crate::cli::error::{Error, Result};
use crate::shape::Shape;
use clap::Args;
use std::io::{self, Write};

#[derive(Args)]
pub struct PointArgs {
    #[command(flatten)]
    pub common: Common,
    #[command(flatten)]
    pub velocity: VelocityPoint,
    /// Amplitude du/u0 (>= 0).
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub amp: f64,
}

fn exact_point(shape: &Shape, vbar: f64, amp: f64, opts: &crate::Options) -> Result<serde_json::Value> {
    serde_json::to_value(shape.point(vbar, amp, opts)?)
        .map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })
}

pub fn run(a: PointArgs) -> Result<()> {
    let shape = crate::cli::input::parse_shape(&a.common.shape)?;
    let amp = a.amp;
    let vbar = a.velocity.vbar(amp)?;
    let body = match a.common.method.stepping()? {
        Some(st) => {
            let e = crate::stepper::evaluate(&shape, vbar, amp, st)?;
            serde_json::json!({"vbar": vbar, "amp": amp, "mu_ratio": e.ratio.mu_ratio, "reduction": e.ratio.reduction,
                "method": "stepping", "steps": e.steps, "springs": e.springs, "period_change": e.period_change})
        }
        None => exact_point(&shape, vbar, amp, &a.common.options())?,
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
