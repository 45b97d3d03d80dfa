//! `validate --history`: a force history file as read, and the reports of its
//! comparison ([`fricosc::validation::compare_history`]).

use super::table::wrap;
use super::{count, csv_text, findings_text, json_name};
use crate::error::{Error, Result};
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
    /// How the file was read.
    pub format: String,
}

const HISTORY_COLUMNS: [(&str, Kind); 4] =
    [("tau", Kind::Number), ("t", Kind::Number), ("tangential", Kind::Number), ("normal", Kind::Number)];

/// Read a history (any format of [`crate::tables`]: columns `tau` or `t`,
/// `tangential`, optionally `normal`); forces in the file's units, divided by
/// `static_force` (`F0` in them) and `mu0` (the tangential one).
pub fn read_history(text: &str, source: &str, static_force: f64, mu0: f64) -> Result<HistoryColumns> {
    let err = |reason: String| Error::Parse { context: source.into(), reason };
    let mut c = read_columns(text, source, &HISTORY_COLUMNS, crate::grid::MAX_ROWS)?;
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
    fricosc::validation::to_static_units(&mut tangential, normal.as_deref_mut(), static_force, mu0)?;
    Ok(HistoryColumns { time, is_tau, tangential, normal, format: c.format })
}

/// Every sample of the last period as CSV: the seed's phase, the exact and the
/// file's tangential force and their difference, the same for the normal force.
pub fn history_csv(v: &HistoryValidation) -> Result<String> {
    let n = crate::output::num;
    let opt = |x: Option<f64>| x.map(n).unwrap_or_default();
    let header = ["index", "tau", "exact", "yours", "error", "normal_exact", "normal_yours", "normal_error"];
    let mut records = vec![header.map(String::from).to_vec()];
    for s in &v.last_period {
        records.push(vec![
            s.index.to_string(),
            n(s.tau),
            n(s.exact),
            n(s.yours),
            n(s.error),
            n(s.normal_exact),
            opt(s.normal_yours),
            opt(s.normal_error),
        ]);
    }
    csv_text(&records)
}

/// The time origin in words.
fn origin_text(v: &HistoryValidation) -> String {
    use fricosc::validation::OriginSource;
    let o = &v.time_origin;
    let omega = o
        .omega
        .map_or(String::new(), |w| format!(" Angular frequency found from the normal force: {w} rad per unit of t."));
    match o.source {
        OriginSource::Assumed => format!(
            "Time origin: assumed to be the seed's (no normal column to check it): tau = omega t with the \
             indentation u_z = u0 - du cos(omega t).{omega}"
        ),
        OriginSource::NormalForce if o.offset == 0.0 => {
            format!("Time origin: the seed's (from the normal force: u_z = u0 - du cos(omega t)).{omega}")
        }
        OriginSource::NormalForce => {
            let follows = o.convention.map_or(String::new(), |c| format!(" (the file follows u_z = {c})"));
            format!(
                "Time origin of your file: {:+.6} rad ({:+.2} samples) against the seed's u_z = u0 - du \
                 cos(omega t){follows}, found from the normal force; compared after aligning.{omega}",
                o.offset, o.offset_samples
            )
        }
    }
}

/// A history's comparison for a person.
pub fn history_summary(v: &HistoryValidation, format: &str) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let mut s = wrap(
        "",
        &format!(
            "fricosc validate --history: {} at vbar {}, amp {}; {}, {} in the last (read as {format}).",
            v.shape,
            v.vbar,
            v.amp,
            count(v.periods, "whole period"),
            count(v.samples, "sample")
        ),
        100,
    );
    s += &wrap("", &origin_text(v), 100);
    s += &wrap(
        "",
        &format!(
            "Tangential force over the last period: largest |error| {}, rms {} (units: {}).",
            e(v.max_abs_error),
            e(v.rms_error),
            v.units
        ),
        100,
    );
    if let Some(nc) = &v.normal {
        s += &wrap(
            "",
            &format!(
                "Normal force: largest |error| {}, rms {}; its mean over the period is {:.6} times the exact mean.",
                e(nc.max_abs_error),
                e(nc.rms_error),
                nc.mean_ratio
            ),
            100,
        );
    }
    s += &wrap(
        "",
        &match (v.period_drift, v.periodic) {
            (Some(d), Some(true)) => {
                format!("Periodic: the last period differs from the one before by {} at most.", e(d))
            }
            (Some(d), _) => format!("Not yet periodic: the last period differs from the one before by up to {}.", e(d)),
            _ => "One period only: periodicity cannot be judged (give two or more).".into(),
        },
        100,
    );
    if !v.exact_events.is_empty() || !v.events.is_empty() {
        s += &format!("\n{:<18}{:>12}{:>12}{:>14}\n", "event", "tau", "exact tau", "timing error");
        for f in &v.events {
            let o = |x: Option<f64>| x.map_or("-".into(), |y| format!("{y:.6}"));
            s += &format!(
                "{:<18}{:>12.6}{:>12}{:>14}\n",
                json_name(f.kind),
                f.tau,
                o(f.exact_tau),
                f.timing_error.map_or("-".into(), e)
            );
        }
    } else {
        s += &wrap("", "Events: not compared (a curved contact's total force has none).", 100);
    }
    s += &findings_text("Findings", &v.findings, "none", "sample");
    s
}
