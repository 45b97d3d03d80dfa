//! `validate --history`: a force history file as read, and the CSV of its
//! comparison ([`fricosc::validation::compare_history`]).

use crate::error::{Error, Result};
use crate::output::csv_records;
use crate::tables::{read_columns, Kind};
use fricosc::validation::HistoryValidation;

/// The columns of a history file, forces already divided by the units given.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryColumns {
    /// The time column (`tau`, or `t` if not [`HistoryColumns::is_tau`]).
    pub time: Vec<f64>,
    /// True if the time column is the phase `tau`.
    pub is_tau: bool,
    /// Tangential force, units `mu0 F0`.
    pub tangential: Vec<f64>,
    /// Normal force, units `F0`, if given.
    pub normal: Option<Vec<f64>>,
    /// In the plane: the force across the sliding direction, units `mu0 F0`, if given.
    pub transverse: Option<Vec<f64>>,
    /// On a system: the body's lag and velocity (pre-slip lengths), if given.
    pub body: Option<(Vec<f64>, Vec<f64>)>,
    /// How the file was read.
    pub format: String,
}

const HISTORY_COLUMNS: [&str; 7] = ["tau", "t", "tangential", "normal", "body_lag", "body_velocity", "transverse"];
const NUM: Kind = Kind::Number;

/// Read a history (any format of [`crate::tables`]: columns `tau` or `t`,
/// `tangential`, optionally `normal`, in the plane `transverse`, and on a
/// system `body_lag` with `body_velocity`, as `fricosc history` writes them); forces in the file's units, divided by
/// `static_force` (`F0` in them) and `mu0` (the tangential one).
pub fn read_history(text: &str, source: &str, static_force: f64, mu0: f64) -> Result<HistoryColumns> {
    let err = |reason: String| Error::Parse { context: source.into(), reason };
    let mut c = read_columns(text, source, &HISTORY_COLUMNS.map(|n| (n, NUM)), crate::grid::MAX_ROWS)?;
    let names = || format!("this one ({}) has {}", c.format, c.names.join(", "));
    let is_tau = match (c.has(0), c.has(1)) {
        (true, false) => true,
        (false, true) => false,
        (true, true) => return Err(err("both 'tau' and 't' given: one time column only".into())),
        (false, false) => {
            return Err(err(format!("no time column 'tau' (the phase omega t) or 't' (time); {}", names())))
        }
    };
    let time = c.numbers[if is_tau { 0 } else { 1 }].take().unwrap_or_default();
    let mut tangential = c.numbers[2]
        .take()
        .ok_or_else(|| err(format!("no column 'tangential' (the tangential force); {}", names())))?;
    let mut normal = c.numbers[3].take();
    let mut transverse = c.numbers[6].take();
    let body = match (c.numbers[4].take(), c.numbers[5].take()) {
        (Some(lag), Some(velocity)) => Some((lag, velocity)),
        (None, None) => None,
        _ => return Err(err("'body_lag' and 'body_velocity' are given together or not at all".into())),
    };
    fricosc::validation::to_static_units(&mut tangential, normal.as_deref_mut(), static_force, mu0)?;
    if let Some(y) = transverse.as_deref_mut() {
        fricosc::validation::to_static_units(y, None, static_force, mu0)?;
    }
    Ok(HistoryColumns { time, is_tau, tangential, normal, transverse, body, format: c.format })
}

/// Every sample of the last period as CSV: the seed's phase, the exact and the
/// file's tangential force and their difference, the same for the normal force;
/// in the plane the force across, exact and the file's; on a system with the
/// file's body, its lag and velocity, exact and the file's.
pub fn history_csv(v: &HistoryValidation) -> Result<String> {
    let across = v.last_period.first().is_some_and(|s| s.transverse_exact.is_some());
    let mut header = vec!["index", "tau", "exact", "yours", "error", "normal_exact", "normal_yours", "normal_error"];
    header.extend(if across { &["transverse_exact", "transverse_yours"][..] } else { &[] });
    header.extend(if v.body.is_some() {
        &["lag_exact", "lag_yours", "velocity_exact", "velocity_yours"][..]
    } else {
        &[]
    });
    let mut records = vec![header.into_iter().map(String::from).collect::<Vec<_>>()];
    for s in &v.last_period {
        let mut cells = vec![Some(s.tau), Some(s.exact), Some(s.yours), Some(s.error), Some(s.normal_exact)];
        cells.extend([s.normal_yours, s.normal_error]);
        if across {
            cells.extend([s.transverse_exact, s.transverse_yours]);
        }
        if let Some((e, y)) = s.body_exact.zip(s.body_yours) {
            cells.extend([e[0], y[0], e[1], y[1]].map(Some));
        }
        let mut row = vec![s.index.to_string()];
        row.extend(cells.into_iter().map(|x| x.map(crate::output::num).unwrap_or_default()));
        records.push(row);
    }
    Ok(csv_records(&records))
}
