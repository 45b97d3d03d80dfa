//! `fricosc point`: one point with its regime, events and bands (JSON).

use super::{io_err, number, Common, TangentialPoint, VelocityPoint};
use crate::error::{Error, Result};
use clap::Args;
use fricosc::Shape;
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
    #[command(flatten)]
    pub tangential: TangentialPoint,
}

/// A point under oscillation in the sliding direction: the inputs, the answer
/// and the flat punch's spring (phases and events) or a curved contact's bands.
fn combined_point(shape: &Shape, o: &fricosc::combined::Oscillation, common: &Common) -> Result<serde_json::Value> {
    let mut v = serde_json::json!({"vhat": o.vhat, "amp": o.amp, "tangential_amp": o.tangential_amp, "phase": o.phase});
    let body = match common.method.stepping()? {
        Some(st) => {
            let e = fricosc::stepper::evaluate_oscillation(shape, o, st, fricosc::stepper::OSCILLATION_PERIODS)?;
            serde_json::json!({"mu_ratio": e.ratio.mu_ratio, "reduction": e.ratio.reduction, "method": "stepping",
                "steps": e.steps, "springs": e.springs, "period_change": e.period_change})
        }
        None => serde_json::to_value(fricosc::combined::evaluate(shape, o, common.options().tol)?)
            .map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })?,
    };
    if let (serde_json::Value::Object(m), serde_json::Value::Object(b)) = (&mut v, body) {
        m.extend(b);
    }
    Ok(v)
}

fn exact_point(shape: &Shape, vbar: f64, amp: f64, opts: &fricosc::Options) -> Result<serde_json::Value> {
    serde_json::to_value(shape.point(vbar, amp, opts)?)
        .map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })
}

pub fn run(a: PointArgs) -> Result<()> {
    let shape = crate::input::parse_shape(&a.common.shape)?;
    let amp = a.amp;
    let body = if let Some(o) = a.tangential.oscillation(&a.velocity, amp)? {
        combined_point(&shape, &o, &a.common)?
    } else {
        normal_point(&shape, &a, amp)?
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

/// The seed's problem: the solver's point, or the stepping peer's.
fn normal_point(shape: &Shape, a: &PointArgs, amp: f64) -> Result<serde_json::Value> {
    let vbar = a.velocity.vbar(amp)?;
    Ok(match a.common.method.stepping()? {
        Some(st) => {
            let e = fricosc::stepper::evaluate(shape, vbar, amp, st)?;
            serde_json::json!({"vbar": vbar, "amp": amp, "mu_ratio": e.ratio.mu_ratio, "reduction": e.ratio.reduction,
                "method": "stepping", "steps": e.steps, "springs": e.springs, "period_change": e.period_change})
        }
        None => exact_point(shape, vbar, amp, &a.common.options())?,
    })
}
