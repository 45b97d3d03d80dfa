//! `fricosc point`: one point with its regime, events and bands (JSON).

use crate::cmd::{io_err, Common, Drive};
use crate::error::{Error, Result};
use clap::Args;
use fricosc::{Conditions, Shape};
use std::io::{self, Write};
#[derive(Args)]
pub struct PointArgs {
    #[command(flatten)]
    pub common: Common,
    #[command(flatten)]
    pub drive: Drive,
}

pub fn run(a: PointArgs) -> Result<()> {
    let shape = crate::input::parse_shape(&a.common.shape)?;
    let c = a.drive.conditions()?.with_tol(a.common.tol())?;
    let system = &a.drive.system;
    let with_system = system.system_stiffness.is_some();
    let body = match (a.common.method.stepping_with(with_system)?, system.system(a.common.method.system_springs())?) {
        (_, Some(sys)) if c.transverse().is_some() => to_json(&shape.report(&c.with_system(sys))?)?,
        (Some(_), Some(_)) => {
            return Err(Error::Parse { context: "--system-stiffness".into(), reason: "is solved exactly only".into() })
        }
        (None, Some(sys)) => on_system(&shape, &c, sys)?,
        (_, None) if c.transverse().is_some() => in_plane(&shape, &c, a.common.method.stepping()?)?,
        (Some(st), None) => stepped(&shape, &c, st)?,
        (None, None) => to_json(&shape.report(&c)?)?,
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

/// The stepping peer's point: the inputs, its answer and its resolution.
fn stepped(shape: &Shape, c: &Conditions, st: fricosc::stepper::Stepping) -> Result<serde_json::Value> {
    let e = fricosc::stepper::evaluate(shape, c, st)?;
    let mut v = match c.tangential() {
        Some((t, phase)) => {
            serde_json::json!({"vhat": c.as_vhat(), "amp": c.amp(), "tangential_amp": t, "phase": phase})
        }
        None => serde_json::json!({"vbar": c.as_vbar()?, "amp": c.amp()}),
    };
    let body = serde_json::json!({"mu_ratio": e.ratio.mu_ratio, "reduction": e.ratio.reduction, "method": "stepping",
        "steps": e.steps, "springs": e.springs, "period_change": e.period_change});
    if let (serde_json::Value::Object(m), serde_json::Value::Object(b)) = (&mut v, body) {
        m.extend(b);
    }
    Ok(v)
}

/// Under an oscillation across the sliding direction: the inputs and the
/// plane's report (events, the period map's multiplier), or its stepper's answer.
fn in_plane(shape: &Shape, c: &Conditions, st: Option<fricosc::stepper::Stepping>) -> Result<serde_json::Value> {
    let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
    let w = c.transverse().map_or((0.0, 0.0), |w| (w.amp(), w.phase()));
    let mut v = serde_json::json!({"vhat": c.as_vhat(), "amp": c.amp(), "tangential_amp": t, "phase": phase,
        "transverse_amp": w.0, "transverse_phase": w.1});
    let body = match (st, c.transverse()) {
        (Some(st), Some(tw)) => {
            let e = fricosc::stepper::transverse(shape, c, tw, st, PLANE_STEPPED_PERIODS)?;
            serde_json::json!({"mu_ratio": e.mu_ratio, "transverse_ratio": e.transverse_ratio, "method": "stepping",
                "steps_per_period": st.steps_per_period, "springs": if shape.is_flat() { 1 } else { st.springs },
                "period_change": e.period_change})
        }
        _ => to_json(&shape.report(c)?)?,
    };
    if let (serde_json::Value::Object(m), serde_json::Value::Object(b)) = (&mut v, body) {
        m.extend(b);
    }
    Ok(v)
}

/// Periods the plane's stepper runs from its sliding start.
const PLANE_STEPPED_PERIODS: usize = 30;

/// A body on a system: the inputs and the attractor's report.
fn on_system(shape: &Shape, c: &Conditions, sys: fricosc::system::System) -> Result<serde_json::Value> {
    let r = crate::cmd::system_report(shape, &c.with_system(sys))?;
    let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
    // The velocity as given.
    let (name, given) = match c.velocity() {
        fricosc::Velocity::Vbar(v) => ("vbar", v),
        fricosc::Velocity::Vhat(v) => ("vhat", v),
    };
    let mut v = serde_json::json!({(name): given, "amp": c.amp(), "tangential_amp": t, "phase": phase,
        "system_stiffness": sys.stiffness(), "frequency_ratio": sys.frequency_ratio(), "damping": sys.damping(),
        "regime": r.regime(), "reduction": r.ratio().reduction});
    let body = to_json(&r)?;
    if let (serde_json::Value::Object(m), serde_json::Value::Object(b)) = (&mut v, body) {
        m.extend(b);
    }
    Ok(v)
}

fn to_json(v: &impl serde::Serialize) -> Result<serde_json::Value> {
    serde_json::to_value(v).map_err(|e| Error::Internal { what: format!("serialising the output: {e}") })
}
