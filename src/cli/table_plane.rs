//! `fricosc table --transverse-amp`: a grid in the plane (a contact under
//! an oscillation across the sliding direction, `fricosc::plane`).

use crate::cmd::{io_err, list, List};
use crate::error::{Error, Result};
use crate::output::TableWriter;
use crate::table::TableArgs;
use clap::Args;
use fricosc::plane::Transverse;
use rayon::prelude::*;
use std::io;

/// Oscillation across the sliding direction for a table: lists swept like `--amp`.
#[derive(Args)]
pub struct TransverseList {
    /// Amplitudes of an oscillation across the sliding direction, dy/l in pre-slip lengths (each at
    /// least 0, at most 1e6; a stiff system only): a comma list or start:stop:count. Adds the
    /// columns transverse_amp, transverse_phase, transverse_ratio and error_estimate; 1e5 rows at most.
    #[arg(long, allow_hyphen_values = true, value_parser = list)]
    pub transverse_amp: Option<List>,
    /// Their phases against the normal oscillation, radians (default 0): a comma list or start:stop:count.
    #[arg(long, allow_hyphen_values = true, value_parser = list, requires = "transverse_amp")]
    pub transverse_phase: Option<List>,
}

/// Rows of a table in the plane at most (a point takes about a millisecond).
pub const MAX_PLANE_ROWS: u128 = 100_000;

/// The table in the plane: every (amp, T, phase, W, psi, velocity), checked
/// before any work, solved in parallel, written with the velocity as given.
pub fn plane_table(a: &TableArgs, shape: &fricosc::Shape, ws: &List) -> Result<()> {
    if a.system.system_stiffness.is_some() || a.common.method.stepping()?.is_some() || a.velocity.over_t() {
        return Err(Error::parse("--transverse-amp", "is solved exactly on a stiff system, at --vbar or --vhat"));
    }
    let (vels, is_vhat) = a.velocity.values();
    let (ts, phases) = a.tangential.values(is_vhat)?.unwrap_or((vec![0.0], vec![0.0]));
    let psis = a.transverse.transverse_phase.as_ref().map_or(vec![0.0], |p| p.0.clone());
    let sizes = [a.amp.0.len(), ts.len(), phases.len(), ws.0.len(), psis.len(), vels.len()];
    let total = sizes.iter().map(|&n| n as u128).product::<u128>();
    if total > MAX_PLANE_ROWS {
        return Err(Error::TooLarge { what: "table rows in the plane".into(), count: total, limit: MAX_PLANE_ROWS });
    }
    let tangential = a.tangential.tangential_amp.is_some();
    let mut points = Vec::with_capacity(total as usize);
    for &amp in &a.amp.0 {
        for (&t, &phase) in ts.iter().flat_map(|t| phases.iter().map(move |p| (t, p))) {
            for (&w, &psi) in ws.0.iter().flat_map(|w| psis.iter().map(move |p| (w, p))) {
                let tw = Transverse::new(w, psi)?;
                for &v in vels {
                    let velocity = if is_vhat { fricosc::Velocity::Vhat(v) } else { fricosc::Velocity::Vbar(v) };
                    let c = match velocity {
                        fricosc::Velocity::Vbar(v) => fricosc::Conditions::vbar(v, amp)?,
                        fricosc::Velocity::Vhat(v) => fricosc::Conditions::vhat(v, amp)?,
                    };
                    let c = if tangential { c.with_tangential(t, phase)? } else { c };
                    points.push((v, c.with_transverse(tw), tw));
                }
            }
        }
    }
    crate::cmd::warn_degrees_of("--transverse-phase", &psis);
    let bar = crate::progress::Bar::new(Some(total as u64), "table");
    let rows = points
        .par_iter()
        .map(|(_, c, _)| {
            bar.inc(1);
            shape.evaluate(c)
        })
        .collect::<fricosc::Result<Vec<_>>>()?;
    let velocity = if is_vhat { "vhat" } else { "vbar" };
    let columns = vec![
        velocity,
        "amp",
        "tangential_amp",
        "phase",
        "transverse_amp",
        "transverse_phase",
        "mu_ratio",
        "reduction",
        "transverse_ratio",
        "error_estimate",
    ];
    let mut out =
        TableWriter::new(io::BufWriter::new(io::stdout().lock()), a.format, shape.name(), columns).map_err(io_err)?;
    for ((v, c, tw), e) in points.iter().zip(&rows) {
        let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
        // W = 0 asks the question without it: no transverse ratio, the force across is 0.
        let across = e.transverse_ratio.unwrap_or(0.0);
        let row = [
            *v,
            c.amp(),
            t,
            phase,
            tw.amp(),
            tw.phase(),
            e.ratio.mu_ratio,
            e.ratio.reduction,
            across,
            e.error_estimate,
        ];
        out.row(&row).map_err(io_err)?;
    }
    out.finish().map_err(io_err)
}
