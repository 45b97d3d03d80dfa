//! `fricosc table`: a grid of amplitudes x velocities (JSON or CSV).

use crate::cmd::{io_err, list, Common, List, SystemPoint, TangentialList, VelocityList};
use crate::error::{Error, Result};
use crate::output::{Cell, Format, TableWriter, Text};
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
    pub system: SystemPoint,
    /// Output format.
    #[arg(long, value_enum, default_value = "json")]
    pub format: Format,
}

/// A table under oscillation in the sliding direction: every (amp, T, phase,
/// vhat), columns vhat, amp, tangential_amp, phase, mu_ratio, reduction.
fn combined_table(a: &TableArgs, shape: &fricosc::Shape, ts: &[f64], phases: &[f64]) -> Result<()> {
    let (vels, _) = a.velocity.values();
    let over_t = a.velocity.over_t();
    let amps = &a.amp.0;
    let total = [amps.len(), ts.len(), phases.len(), vels.len()].iter().map(|&n| n as u128).product::<u128>();
    if total > crate::grid::MAX_LIST {
        return Err(Error::TooLarge {
            what: "table rows (amplitudes x tangential amplitudes x phases x velocities)".into(),
            count: total,
            limit: crate::grid::MAX_LIST,
        });
    }
    let mut points = Vec::with_capacity(total as usize);
    for &amp in amps {
        for &t in ts {
            for &phase in phases {
                for &v in vels {
                    // Checked before any work (and the phase printed as given).
                    let vhat = if over_t { v * t } else { v };
                    points.push(a.common.conditions(fricosc::Velocity::Vhat(vhat), amp, Some((t, phase)))?);
                }
            }
        }
    }
    let stepping = a.common.method.stepping()?;
    if let Some(st) = stepping {
        st.check(shape)?;
    }
    let rows: Vec<[f64; 3]> = points
        .par_iter()
        .map(|c| {
            let r = match stepping {
                Some(st) => fricosc::stepper::evaluate(shape, c, st)?.ratio,
                None => shape.ratio(c)?,
            };
            Ok([c.as_vhat(), r.mu_ratio, r.reduction])
        })
        .collect::<Result<Vec<_>>>()?;
    let mut cols = vec!["vhat", "amp", "tangential_amp", "phase", "mu_ratio", "reduction"];
    if over_t {
        cols.insert(0, "vhat_over_t");
    }
    let mut w =
        TableWriter::new(io::BufWriter::new(io::stdout().lock()), a.format, shape.name(), cols).map_err(io_err)?;
    // The grid's values printed once each, in the order the rows were made.
    let texts = |xs: &[f64]| xs.iter().map(|&x| Text::of(x)).collect::<Vec<_>>();
    let (amp_t, t_t, phase_t, vel_t) = (texts(amps), texts(ts), texts(phases), texts(vels));
    let mut rows = rows.iter();
    for amp in &amp_t {
        for t in &t_t {
            for phase in &phase_t {
                for (v, r) in vel_t.iter().zip(rows.by_ref()) {
                    let (mu, reduction) = (Cell::Num(r[1]), Cell::Num(r[2]));
                    let rest = [Cell::Text(amp), Cell::Text(t), Cell::Text(phase), mu, reduction];
                    match over_t {
                        true => w.row(&[&[Cell::Text(v), Cell::Num(r[0])][..], &rest].concat()),
                        false => w.row(&[&[Cell::Text(v)][..], &rest].concat()),
                    }
                    .map_err(io_err)?;
                }
            }
        }
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
    if let Some(sys) = a.system.system(a.common.method.system_springs())? {
        return system_table(&a, &shape, &sys);
    }
    if let Some((ts, phases)) = a.tangential.values(is_vhat)? {
        return combined_table(&a, &shape, &ts, &phases);
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
    // The grid's values printed once each (a vhat table's vbar is a row's own).
    let amp_texts: Vec<Text> = amps.iter().map(|&x| Text::of(x)).collect();
    let vel_texts: Vec<Text> = vels.iter().map(|&x| Text::of(x)).collect();
    let mut w = TableWriter::new(io::BufWriter::new(io::stdout().lock()), a.format, name, cols).map_err(io_err)?;
    for (block, amp) in rows.chunks(vels.len().max(1)).zip(&amp_texts) {
        for (r, v) in block.iter().zip(&vel_texts) {
            let (amp, v, mu, reduction) = (Cell::Text(amp), Cell::Text(v), Cell::Num(r[1]), Cell::Num(r[2]));
            if is_vhat { w.row(&[v, Cell::Num(r[0]), amp, mu, reduction]) } else { w.row(&[v, amp, mu, reduction]) }
                .map_err(io_err)?;
        }
    }
    w.finish().map_err(io_err)
}

/// A table of a body on a system (`fricosc::system`): every (amp, T, phase,
/// velocity), columns vhat, amp, tangential_amp, phase, mu_ratio, period
/// (empty where none was found), standard_error (where none), error_estimate
/// (a curved body's).
fn system_table(a: &TableArgs, shape: &fricosc::Shape, sys: &fricosc::system::System) -> Result<()> {
    if a.common.method.stepping_with(true)?.is_some() || a.velocity.over_t() {
        return Err(Error::Parse {
            context: "--system-stiffness".into(),
            reason: "is solved exactly, at --vbar or --vhat".into(),
        });
    }
    let (vels, is_vhat) = a.velocity.values();
    let (ts, phases) = a.tangential.values(is_vhat)?.unwrap_or((vec![0.0], vec![0.0]));
    let amps = &a.amp.0;
    let total = [amps.len(), ts.len(), phases.len(), vels.len()].iter().map(|&n| n as u128).product::<u128>();
    if total > MAX_SYSTEM_ROWS {
        return Err(Error::TooLarge { what: "table rows on a system".into(), count: total, limit: MAX_SYSTEM_ROWS });
    }
    let mut points = vec![];
    for &amp in amps {
        for &t in &ts {
            for &phase in &phases {
                for &v in vels {
                    let velocity = if is_vhat { fricosc::Velocity::Vhat(v) } else { fricosc::Velocity::Vbar(v) };
                    let c = a.common.conditions(velocity, amp, None)?;
                    points.push(fricosc::Conditions::vhat(c.as_vhat(), amp)?.with_tangential(t, phase)?);
                }
            }
        }
    }
    let rows = points.par_iter().map(|c| Ok(fricosc::system::solve(shape, c, sys)?)).collect::<Result<Vec<_>>>()?;
    let cols = vec!["vhat", "amp", "tangential_amp", "phase", "mu_ratio", "period", "standard_error", "error_estimate"];
    let mut w =
        TableWriter::new(io::BufWriter::new(io::stdout().lock()), a.format, shape.name(), cols).map_err(io_err)?;
    for (c, r) in points.iter().zip(&rows) {
        let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
        let period = r.period.map_or(Cell::Num(f64::NAN), |k| Cell::Num(k as f64));
        let se = Cell::Num(r.standard_error.unwrap_or(f64::NAN));
        let est = Cell::Num(r.error_estimate.unwrap_or(f64::NAN));
        let row = [Cell::Num(c.as_vhat()), Cell::Num(c.amp()), Cell::Num(t), Cell::Num(phase), Cell::Num(r.mu_ratio)];
        w.row(&[&row[..], &[period, se, est]].concat()).map_err(io_err)?;
    }
    w.finish().map_err(io_err)
}

/// Most rows of a table on a system (each up to about two seconds).
const MAX_SYSTEM_ROWS: u128 = 100_000;
