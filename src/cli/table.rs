//! `fricosc table`: a grid of amplitudes x velocities (JSON or CSV).

use crate::cmd::{io_err, list, Common, List, SystemPoint, TangentialList, VelocityList};
use crate::error::{Error, Result};
use crate::output::{Format, TableWriter};
use clap::Args;
use rayon::prelude::*;
use std::io;
#[derive(Args)]
pub struct TableArgs {
    #[command(flatten)]
    pub common: Common,
    #[command(flatten)]
    pub velocity: VelocityList,
    /// Amplitudes du/u0: a comma list or start:stop:count.
    #[arg(long, allow_hyphen_values = true, value_parser = list)]
    pub amp: List,
    #[command(flatten)]
    pub tangential: TangentialList,
    #[command(flatten)]
    pub transverse: crate::table_plane::TransverseList,
    #[command(flatten)]
    pub system: SystemPoint,
    /// Output format.
    #[arg(long, value_enum, default_value = "json")]
    pub format: Format,
}

/// A table of a general point (oscillation in the sliding direction, or a
/// body on a system: [`general_table`]): its conditions and columns.
struct Grid {
    points: Vec<fricosc::Conditions>,
    /// Each point's velocity as given (`vbar` or `vhat`; `vhat/T` where given so).
    given: Vec<f64>,
    over_t: bool,
    columns: Vec<&'static str>,
}

/// Every (amp, T, phase, velocity) of a table in the sliding direction, or
/// on a system (`on_system`), checked before any work: the velocity is
/// `vhat` under a tangential oscillation, either on a system without one.
fn grid(a: &TableArgs, on_system: bool) -> Result<Grid> {
    let (vels, is_vhat) = a.velocity.values();
    let (ts, phases) = a.tangential.values(is_vhat)?.unwrap_or((vec![0.0], vec![0.0]));
    let amps = &a.amp.0;
    let total = [amps.len(), ts.len(), phases.len(), vels.len()].iter().map(|&n| n as u128).product::<u128>();
    let (limit, what) = match on_system {
        true => (MAX_SYSTEM_ROWS, "table rows on a system"),
        false => (crate::grid::MAX_LIST, "table rows (amplitudes x tangential amplitudes x phases x velocities)"),
    };
    if total > limit {
        return Err(Error::TooLarge { what: what.into(), count: total, limit });
    }
    let over_t = a.velocity.over_t();
    let mut g = Grid { points: Vec::with_capacity(total as usize), given: vec![], over_t, columns: vec![] };
    for &amp in amps {
        for &t in &ts {
            for &phase in &phases {
                for &v in vels {
                    let vhat = if over_t { v * t } else { v };
                    let c = if on_system {
                        let velocity = if is_vhat { fricosc::Velocity::Vhat(v) } else { fricosc::Velocity::Vbar(v) };
                        let c = a.common.conditions(velocity, amp, None)?;
                        fricosc::Conditions::vhat(c.as_vhat(), amp)?.with_tangential(t, phase)?
                    } else {
                        a.common.conditions(fricosc::Velocity::Vhat(vhat), amp, Some((t, phase)))?
                    };
                    g.points.push(c);
                    g.given.push(v);
                }
            }
        }
    }
    // The velocity as given: vbar or vhat on a system, vhat (or vhat/T, and
    // the vhat it makes) under a tangential oscillation.
    g.columns = match (over_t, on_system && !is_vhat) {
        (true, _) => vec!["vhat_over_t", "vhat"],
        (false, true) => vec!["vbar"],
        (false, false) => vec!["vhat"],
    };
    g.columns.extend(["amp", "tangential_amp", "phase", "mu_ratio", "reduction"]);
    if on_system {
        g.columns.extend(["period", "standard_error", "error_estimate"]);
    }
    Ok(g)
}

/// A table under oscillation in the sliding direction, or on a system: the velocity as given,
/// amp, tangential_amp, phase, mu_ratio, reduction, and on a system period (a whole number;
/// missing where none was found), standard_error (where none) and error_estimate.
fn general_table(a: &TableArgs, shape: &fricosc::Shape, system: Option<fricosc::system::System>) -> Result<()> {
    if system.is_some() && (a.common.method.stepping_with(true)?.is_some() || a.velocity.over_t()) {
        return Err(Error::parse("--system-stiffness", "is solved exactly, at --vbar or --vhat"));
    }
    let g = grid(a, system.is_some())?;
    let stepping = if system.is_some() { None } else { a.common.method.stepping()? };
    if let Some(st) = stepping {
        st.check(shape)?;
    }
    let or_nan = |x: Option<f64>| x.unwrap_or(f64::NAN);
    // Each row's values after its inputs: mu, reduction, and on a system the
    // period, standard error and estimate.
    let bar = crate::progress::Bar::new(Some(g.points.len() as u64), "table");
    let rows = g
        .points
        .par_iter()
        .map(|c| {
            bar.inc(1);
            Ok(match (system, stepping) {
                (Some(sys), _) => {
                    let r = crate::cmd::system_report(shape, &c.with_system(sys))?;
                    let period = r.period.map(|k| k as f64);
                    [r.mu_ratio, r.ratio().reduction, or_nan(period), or_nan(r.standard_error), r.error_estimate]
                }
                (None, stepping) => {
                    let r = match stepping {
                        Some(st) => fricosc::stepper::evaluate(shape, c, st)?.ratio,
                        None => shape.ratio(c)?,
                    };
                    [r.mu_ratio, r.reduction, f64::NAN, f64::NAN, f64::NAN]
                }
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let width = g.columns.len();
    let mut w = TableWriter::new(io::BufWriter::new(io::stdout().lock()), a.format, shape.name(), g.columns)
        .map_err(io_err)?
        .with_integers(&["period"]);
    for ((c, r), &v) in g.points.iter().zip(&rows).zip(&g.given) {
        let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
        let row = [v, c.as_vhat(), c.amp(), t, phase, r[0], r[1], r[2], r[3], r[4]];
        // Without vhat/T the given velocity is the only velocity column.
        let cells = if g.over_t { &row[..width] } else { &[&row[..1], &row[2..=width]].concat()[..] };
        w.row(cells).map_err(io_err)?;
    }
    w.finish().map_err(io_err)
}

/// Rows a rayon task computes in a row: enough that rayon's bookkeeping is
/// small beside a flat row, few enough that a table of slow curved rows
/// still splits over every thread.
const ROWS_PER_TASK: usize = 64;

pub fn run(a: TableArgs) -> Result<()> {
    let shape = crate::input::parse_shape(&a.common.shape)?;
    let tol = a.common.tol();
    let amps = &a.amp.0;
    let (vels, is_vhat) = a.velocity.values();
    if let Some(ws) = &a.transverse.transverse_amp {
        return crate::table_plane::plane_table(&a, &shape, ws);
    }
    let system = a.system.system(a.common.method.system_springs())?;
    if system.is_some() || a.tangential.tangential_amp.is_some() {
        return general_table(&a, &shape, system);
    }
    let total = amps.len() as u128 * vels.len() as u128;
    if total > crate::grid::MAX_LIST {
        return Err(Error::TooLarge {
            what: "table rows (amplitudes x velocities)".into(),
            count: total,
            limit: crate::grid::MAX_LIST,
        });
    }
    // Validate every input before the first byte is written.
    let velocity = |v: f64| if is_vhat { fricosc::Velocity::Vhat(v) } else { fricosc::Velocity::Vbar(v) };
    for &amp in amps {
        for &v in vels {
            a.common.conditions(velocity(v), amp, None)?;
        }
    }
    let mut cols = vec!["vbar", "amp", "mu_ratio", "reduction"];
    if is_vhat {
        cols.insert(0, "vhat");
    }
    let name = shape.name();
    let stepping = a.common.method.stepping()?;
    if let Some(st) = stepping {
        st.check(&shape)?;
    }
    // Every row is computed (in parallel, rayon) before the first byte is
    // written: an error in any row (a tabulated shape's range, an internal
    // error) leaves stdout empty. 24 bytes per row (vbar, mu_ratio, reduction):
    // 240 MB at the 10^7 limit.
    // Rows are filled in place, a chunk of ROWS_PER_TASK at a time (row i is
    // amplitude i / vels.len(), velocity i % vels.len()): no list of pairs, no
    // collection of rayon's pieces into one vector afterwards.
    let contact = shape.contact();
    let mut rows = vec![[0.0; 3]; total as usize];
    rows.par_chunks_mut(ROWS_PER_TASK).enumerate().try_for_each(|(c, chunk)| {
        let first = c * ROWS_PER_TASK;
        let (mut a_i, mut v_i) = (first / vels.len(), first % vels.len());
        for row in chunk {
            let (amp, v) = (amps[a_i], vels[v_i]);
            (a_i, v_i) = if v_i + 1 == vels.len() { (a_i + 1, 0) } else { (a_i, v_i + 1) };
            let vbar = if is_vhat { fricosc::Conditions::vhat(v, amp)?.as_vbar()? } else { v };
            let r = match stepping {
                Some(st) => fricosc::stepper::evaluate(&shape, &fricosc::Conditions::vbar(vbar, amp)?, st)?.ratio,
                // Inputs and options checked above, once: the contact itself.
                None => contact.ratio(vbar, amp, tol)?,
            };
            *row = [vbar, r.mu_ratio, r.reduction];
        }
        Ok::<(), Error>(())
    })?;
    let mut w = TableWriter::new(io::BufWriter::new(io::stdout().lock()), a.format, name, cols).map_err(io_err)?;
    for (block, &amp) in rows.chunks(vels.len().max(1)).zip(amps) {
        for (r, &v) in block.iter().zip(vels) {
            if is_vhat { w.row(&[v, r[0], amp, r[1], r[2]]) } else { w.row(&[v, amp, r[1], r[2]]) }.map_err(io_err)?;
        }
    }
    w.finish().map_err(io_err)
}

/// Most rows of a table on a system (each up to about two seconds).
const MAX_SYSTEM_ROWS: u128 = 100_000;
