//! Force histories against the exact steady state: the time origin and the
//! period found from the normal force, errors of both forces over the last
//! period, periodicity, and the events found from the force against its bound.
//!
//! # Units and phase
//! Forces are in units of the static force `F0`, the normal force at the mean
//! indentation `u0` without oscillation (`kz u0` for the flat punch, Hertz's
//! `(4/3) E* R^(1/2) u0^(3/2)` for the paraboloid; [`crate::contact::Contact::static_force`]
//! at depth 1 in general): normal `/ F0`, tangential `/ (mu0 F0)`. The seed's
//! phase is `tau = omega t` with the indentation `u0 - du cos tau` (the
//! shallowest point at `tau = 0`). A file written with another convention
//! (`u0 + du cos(omega t)`, a sine, a time origin elsewhere) differs by a
//! constant offset, which the normal force reveals ([`TimeOrigin`]): where the
//! file has a normal column, its phase is aligned to the seed's before
//! anything is compared.

use super::*;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

mod events;
mod exact;
mod plane;
mod series;
mod signal;
mod system;

pub use plane::TransverseComparison;
pub use series::{EventSeries, HistorySeries};
pub use system::BodyComparison;

use events::find_events;
use exact::Exact;
use signal::{origin_offset, period_from_normal, periodic_mean, Drifts, SNAP_SAMPLES};

/// The time column of a history.
#[derive(Debug, Clone, Copy)]
pub enum TimeAxis<'a> {
    /// The phase `omega t` itself (radians).
    Phase(&'a [f64]),
    /// Times, with the angular frequency `omega` (`tau = omega t`) or without
    /// it (then the period is found from the normal force).
    Time {
        /// The times.
        t: &'a [f64],
        /// The angular frequency, in radians per unit of `t`.
        omega: Option<f64>,
    },
}

/// A force history as a file gives it: forces in units of `F0` (module docs).
#[derive(Debug, Clone, Copy)]
pub struct HistoryData<'a> {
    /// The time column.
    pub time: TimeAxis<'a>,
    /// Tangential force, units `mu0 F0`.
    pub tangential: &'a [f64],
    /// Normal force, units `F0`, if the file has it.
    pub normal: Option<&'a [f64]>,
    /// In the plane (`Conditions::with_transverse`): the force across the
    /// sliding direction, units `mu0 F0`, if the file has it.
    pub transverse: Option<&'a [f64]>,
    /// On a system: the body's lag `X_d - x` and velocity `dx/dtau` (pre-slip
    /// lengths), if the file has them.
    pub body: Option<(&'a [f64], &'a [f64])>,
}

/// How the seed's phase of each sample was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum OriginSource {
    /// No normal column: the file's phase is taken as the seed's.
    Assumed,
    /// From the normal force's first harmonic over the last period.
    NormalForce,
}

/// The file's phase against the seed's: `tau_seed = tau_file + offset`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct TimeOrigin {
    /// How it was found.
    pub source: OriginSource,
    /// The offset added to the file's phase, in `(-pi, pi]` (0 when assumed).
    pub offset: f64,
    /// The offset in sample spacings of the last period.
    pub offset_samples: f64,
    /// The oscillation the file follows, where the offset is a multiple of
    /// `pi/2` within one sample spacing (it is then taken exactly):
    /// `u0 - du cos(omega t)` (the seed's), `u0 + du cos(omega t)`,
    /// `u0 + du sin(omega t)` or `u0 - du sin(omega t)`.
    pub convention: Option<&'static str>,
    /// The angular frequency found from the normal force (radians per unit of
    /// the file's `t`), where none was given.
    pub omega: Option<f64>,
}

/// The file's normal force against the exact one over the last period (after aligning).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct NormalComparison {
    /// Largest `|normal - exact|` (units `F0`).
    pub max_abs_error: f64,
    /// Root mean square of the same.
    pub rms_error: f64,
    /// The file's mean normal force over the period divided by the exact mean
    /// (the same quadrature on the same samples): 1 when the units agree.
    pub mean_ratio: f64,
}

/// One sample of the last period.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HistorySample {
    /// Index of the sample in the file (0-based, header not counted).
    pub index: usize,
    /// The seed's phase of the sample (the file's, aligned), in `[0, 2 pi)`.
    pub tau: f64,
    /// The exact tangential force (units `mu0 F0`).
    pub exact: f64,
    /// The file's.
    pub yours: f64,
    /// `yours - exact`.
    pub error: f64,
    /// The exact normal force (units `F0`).
    pub normal_exact: f64,
    /// The file's, if given.
    pub normal_yours: Option<f64>,
    /// `normal_yours - normal_exact`.
    pub normal_error: Option<f64>,
    /// In the plane: the exact force across the sliding direction (units `mu0 F0`).
    pub transverse_exact: Option<f64>,
    /// The file's, if given.
    pub transverse_yours: Option<f64>,
    /// On a system: the exact body's lag and velocity.
    pub body_exact: Option<[f64; 2]>,
    /// The file's, if given.
    pub body_yours: Option<[f64; 2]>,
}

/// An event found in a user's history, matched to the exact one of its kind.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FoundEvent {
    /// What happened.
    pub kind: crate::model::spring::EventKind,
    /// Its phase in the user's history (aligned), in `[0, 2 pi)`.
    pub tau: f64,
    /// The exact event's phase (absent if the exact solution has none of this kind).
    pub exact_tau: Option<f64>,
    /// `tau - exact_tau`, the shortest way round the period.
    pub timing_error: Option<f64>,
}

/// A user's force history against the exact steady state.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HistoryValidation {
    /// Shape name.
    pub shape: String,
    /// Units of the forces compared.
    pub units: String,
    /// The point: velocity and oscillation.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub point: crate::history::HistoryPoint,
    /// The file's phase against the seed's.
    pub time_origin: TimeOrigin,
    /// Whole periods in the history (counted from its span, one sample's
    /// spacing of slack).
    pub periods: usize,
    /// Samples in the last period (compared).
    pub samples: usize,
    /// Largest `|tangential - exact|` over the last period (units `mu0 F0`).
    pub max_abs_error: f64,
    /// Root mean square of the same.
    pub rms_error: f64,
    /// The normal force against the exact one, if the file gives it.
    pub normal: Option<NormalComparison>,
    /// In the plane, the force across against the exact one, if the file gives it.
    pub transverse: Option<TransverseComparison>,
    /// On a system, the body's columns against the exact body, if the file gives them.
    pub body: Option<BodyComparison>,
    /// Largest change of the tangential force from the previous period to the
    /// last at the same phase (linear interpolation), if there are two periods.
    pub period_drift: Option<f64>,
    /// The same between the two periods before, if there are three.
    pub previous_drift: Option<f64>,
    /// True where the drift is within the tolerance (times the peak force).
    pub periodic: Option<bool>,
    /// Periods still needed for the drift to fall below the tolerance, from the
    /// drift's decay between the last periods (absent if it does not decay).
    pub periods_needed: Option<f64>,
    /// The events found in the last period (stick, slip, contact, loss of
    /// contact: from the force against its Coulomb bound, in the plane its
    /// magnitude), with their timing errors (the flat punch; a curved
    /// contact's total has none; in the plane a file with the force across).
    pub events: Vec<FoundEvent>,
    /// Samples (seed's phases, at most 5) of the last period where the
    /// tangential force exceeds the Coulomb bound `mu0 N` (beyond the tolerance).
    pub above_bound: Vec<f64>,
    /// How many such samples.
    pub above_bound_count: usize,
    /// The exact events of the period.
    pub exact_events: Vec<crate::model::spring::Event>,
    /// What looks wrong, with hints (empty: nothing found).
    pub findings: Vec<Finding>,
    /// Every sample of the last period.
    pub last_period: Vec<HistorySample>,
}

/// Forces in a file's units into those of [`HistoryData`]: the tangential
/// force divided by `mu0 F0`, the normal force by `F0` (`static_force`, the
/// normal force at depth `u0` without oscillation, in the file's units).
///
/// # Errors
/// [`Error::InvalidParameter`] unless `static_force` and `mu0` are finite and `> 0`.
pub fn to_static_units(tangential: &mut [f64], normal: Option<&mut [f64]>, static_force: f64, mu0: f64) -> Result<()> {
    for (name, x) in [("static-force", static_force), ("mu0", mu0)] {
        if !(x.is_finite() && x > 0.0) {
            return Err(Error::param(name, x, "must be finite and > 0"));
        }
    }
    tangential.iter_mut().for_each(|x| *x /= mu0 * static_force);
    if let Some(n) = normal {
        n.iter_mut().for_each(|x| *x /= static_force);
    }
    Ok(())
}

/// Fewest samples the last period of a history must hold to be compared.
pub(crate) const MIN_LAST_SAMPLES: usize = 4;

/// Springs of the reference tangential force of a curved contact's history
/// (the midpoint grid of the contact's grid; second order in the spacing).
pub(crate) const HISTORY_REFERENCE_SPRINGS: usize = 20_000;

/// How far the file's mean normal force may be from the exact mean (relative)
/// before it is a [`FindingKind::NormalScale`] finding. Both means use the
/// same quadrature on the same samples, so a stepper's own error in it is its
/// spring grid's (1e-5 with 250 springs on the paraboloid); wrong units are off
/// by tens of percent.
pub(crate) const NORMAL_MEAN_TOLERANCE: f64 = 1e-3;

/// How far (relative to the peak) the aligned normal force may differ from
/// the exact one before it is a [`FindingKind::NormalShape`] finding.
pub(crate) const NORMAL_SHAPE_TOLERANCE: f64 = 1e-2;

/// Check the columns: equal lengths, finite values, time not decreasing.
fn check_columns(time: &[f64], data: &HistoryData) -> Result<()> {
    let n = time.len();
    let other = [data.normal, data.transverse];
    if data.tangential.len() != n || other.iter().flatten().any(|x| x.len() != n) {
        return Err(Error::Parse { context: "history".into(), reason: "the columns differ in length".into() });
    }
    for i in 0..n {
        let bad = |what: &str| Error::Parse { context: format!("history sample {i}"), reason: what.into() };
        if !time[i].is_finite() || !data.tangential[i].is_finite() || other.iter().flatten().any(|x| !x[i].is_finite())
        {
            return Err(bad("values must be finite"));
        }
        if i > 0 && time[i] < time[i - 1] {
            return Err(bad("the phase (time) must not decrease"));
        }
    }
    Ok(())
}

/// The file's phases and, without `omega`, the angular frequency found.
fn file_phases(data: &HistoryData) -> Result<(Vec<f64>, Option<f64>)> {
    match data.time {
        TimeAxis::Phase(t) => Ok((t.to_vec(), None)),
        TimeAxis::Time { t, omega: Some(w) } => {
            if !(w.is_finite() && w > 0.0) {
                return Err(Error::param("omega", w, "must be finite and > 0"));
            }
            Ok((t.iter().map(|x| w * x).collect(), None))
        }
        TimeAxis::Time { t, omega: None } => {
            let n = data.normal.ok_or_else(|| Error::Parse {
                context: "history".into(),
                reason: "a time column t needs omega, or a normal column to find the period from".into(),
            })?;
            let w = TAU / period_from_normal(t, n)?;
            let t0 = t.first().copied().unwrap_or(0.0);
            Ok((t.iter().map(|x| w * (x - t0)).collect(), Some(w)))
        }
    }
}

/// The whole periods a history spans (with one sample's spacing of slack: a
/// run of two periods recorded from one step past a period's start spans
/// `2 pi - h`), and its last period: start, end and the samples in it.
fn last_period(taus: &[f64]) -> Result<(usize, f64, f64, Vec<usize>)> {
    let n = taus.len();
    let spacing_all = taus.windows(2).map(|w| w[1] - w[0]).fold(0.0f64, f64::max).min(PI);
    let span = if n > 1 { taus[n - 1] - taus[0] } else { 0.0 };
    let periods = ((span + spacing_all) / TAU * (1.0 + 1e-9)).floor() as usize;
    if periods < 1 {
        return Err(Error::Parse {
            context: "history".into(),
            reason: format!("it spans {:.3} periods: at least one whole period is needed", span / TAU),
        });
    }
    let end = taus[n - 1];
    let start = end - TAU;
    let last: Vec<usize> = (0..n).filter(|&i| taus[i] > start + 1e-12 * TAU).collect();
    if last.len() < MIN_LAST_SAMPLES {
        return Err(Error::Parse {
            context: "history".into(),
            reason: format!(
                "{} samples in the last period (from tau = {start:?} to {end:?}): at least {MIN_LAST_SAMPLES} are needed",
                last.len()
            ),
        });
    }
    Ok((periods, start, end, last))
}

/// The time origin of a history's last period: from its normal force where
/// given ([`TimeOrigin`]), else assumed the seed's.
fn find_origin(last_taus: &[f64], user_normal: Option<&[f64]>, found_omega: Option<f64>, spacing: f64) -> TimeOrigin {
    // A convention is recognised on the file's own time axis only (a found
    // frequency counts time from the first sample), to a hundredth of a sample:
    // the first harmonic finds the offset to rounding where the normal force
    // is smooth, and to a small fraction of a sample where it has kinks.
    let snap = if found_omega.is_some() { 0.0 } else { SNAP_SAMPLES * spacing };
    let (offset, convention, source) = match user_normal {
        Some(nl) => match origin_offset(last_taus, nl, snap) {
            Some((d, c)) => (d, c, OriginSource::NormalForce),
            None => (0.0, None, OriginSource::Assumed),
        },
        None => (0.0, None, OriginSource::Assumed),
    };
    TimeOrigin {
        source,
        offset,
        offset_samples: if spacing > 0.0 { offset / spacing } else { 0.0 },
        convention,
        omega: found_omega,
    }
}

/// Compare a force history ([`HistoryData`], forces in units of `F0`, module
/// docs) with the steady state of `shape` at `(vbar, amp)`: exact for the flat
/// punch; for other shapes the normal force is exact and the tangential force
/// the sum over 20,000 springs, and events are not
/// compared (the total has none). With a normal column the period (without
/// `omega`) and the time origin come from it ([`TimeOrigin`]). `tolerance`
/// decides "on the bound", "no contact" and "periodic" (relative to the peak
/// normal force).
///
/// # Errors
/// [`Error::Parse`] for columns of different lengths, too few samples or no whole
/// period; the solver's errors for bad `(vbar, amp)`.
pub fn compare_history(
    shape: &Shape,
    c: &crate::Conditions,
    data: &HistoryData,
    tolerance: f64,
) -> Result<HistoryValidation> {
    let amp = c.amp();
    crate::error::check_nonneg("tolerance", tolerance)?;
    if amp == 0.0 {
        return Err(Error::param("amp", amp, "a history without oscillation has no period"));
    }
    plane::check(c, data.transverse)?;
    let raw_time = match data.time {
        TimeAxis::Phase(t) | TimeAxis::Time { t, .. } => t,
    };
    check_columns(raw_time, data)?;
    let (taus, found_omega) = file_phases(data)?;
    let n = taus.len();
    let (periods, start, end, last) = last_period(&taus)?;
    let last_taus: Vec<f64> = last.iter().map(|&i| taus[i]).collect();
    let spacing = last_taus.windows(2).map(|w| w[1] - w[0]).fold(0.0f64, f64::max);
    let user_normal: Option<Vec<f64>> = data.normal.map(|x| last.iter().map(|&i| x[i]).collect());
    let time_origin = find_origin(&last_taus, user_normal.as_deref(), found_omega, spacing);
    let offset = time_origin.offset;
    let seed_tau = |i: usize| taus[i] + offset;
    let seed_taus: Vec<f64> = last.iter().map(|&i| seed_tau(i).rem_euclid(TAU)).collect();
    let (exact, forces) = exact_forces(shape, c, data, &seed_taus)?;
    let exact_n: Vec<f64> = last.iter().map(|&i| exact.normal(shape, seed_tau(i))).collect();
    let samples = last_samples(data, (&last, &seed_taus), (&forces, &exact_n));
    let normal = user_normal.as_ref().map(|nl| NormalComparison {
        max_abs_error: samples.iter().filter_map(|s| s.normal_error).fold(0.0f64, |m, e| m.max(e.abs())),
        rms_error: super::rms(samples.iter().filter_map(|s| s.normal_error)),
        mean_ratio: periodic_mean(&last_taus, nl) / periodic_mean(&last_taus, &exact_n),
    });
    let across_errors = || samples.iter().filter_map(|s| Some(s.transverse_yours? - s.transverse_exact?));
    let transverse = data.transverse.map(|_| TransverseComparison {
        max_abs_error: across_errors().fold(0.0f64, |m, e| m.max(e.abs())),
        rms_error: super::rms(across_errors()),
    });
    // The bound at each sample: the file's normal force where given.
    let bound = |i: usize| data.normal.map_or_else(|| exact.normal(shape, seed_tau(i)), |x| x[i]);
    let peak = (0..n).map(bound).fold(0.0f64, f64::max).max(f64::MIN_POSITIVE);
    let bar = tolerance * peak;
    let drifts = Drifts::of(&taus, data, (start, end), periods, bar);
    let body = data.body.is_some().then(|| {
        let yours: Vec<[f64; 2]> = samples.iter().filter_map(|s| s.body_yours).collect();
        system::compare_body(&yours, &forces.body)
    });
    // Out of contact (the bound at 0 or below) a force is the spring's not
    // relaxing, not a missed slip; a normal force below 0 is contact loss not modelled.
    let force = plane::bounded(data.tangential, data.transverse);
    let loose = |i: usize| bound(i) <= bar && force[i].abs() > bar;
    let out_of_contact: Vec<usize> = last.iter().copied().filter(|&i| loose(i)).collect();
    let above: Vec<usize> = last.iter().copied().filter(|&i| !loose(i) && force[i].abs() > bound(i) + bar).collect();
    let lowest = data.normal.map(|x| last.iter().map(|&i| x[i]).fold(f64::INFINITY, f64::min));
    let contact = Contact { out_of_contact, negative: lowest.filter(|&m| m < -bar) };
    // The flat punch's, in the plane where the file has the force across.
    let searched = exact.flat && (c.transverse().is_none() || data.transverse.is_some());
    let exact_events = if searched { forces.events } else { vec![] };
    let events = if searched { find_events(&last, &taus, offset, &force, &bound, bar, &exact_events) } else { vec![] };
    let mut v = HistoryValidation {
        shape: shape.name().to_string(),
        units: format!("normal: F0 (the static normal force at depth u0); tangential: mu0 F0{}", forces.units),
        point: crate::history::HistoryPoint::of(c),
        time_origin,
        periods,
        samples: last.len(),
        max_abs_error: samples.iter().fold(0.0f64, |m, s| m.max(s.error.abs())),
        rms_error: super::rms(samples.iter().map(|s| s.error)),
        normal,
        transverse,
        body,
        period_drift: drifts.last,
        previous_drift: drifts.previous,
        periodic: drifts.periodic,
        periods_needed: drifts.needed,
        events,
        above_bound_count: above.len(),
        above_bound: above.iter().take(FINDING_ROWS).map(|&i| seed_tau(i).rem_euclid(TAU)).collect(),
        exact_events,
        findings: vec![],
        last_period: samples,
    };
    v.findings = history_findings(&v, &above, &contact, tolerance);
    v.findings.extend(v.body.as_ref().and_then(|b| system::body_finding(b, &v.last_period)));
    large_error_findings(&mut v, shape, c, data, (&last, &seed_taus), peak);
    Ok(v)
}

/// The samples `last` of the last period (at the seed's phases `taus`) against
/// the exact forces and body there.
fn last_samples(
    data: &HistoryData,
    (last, taus): (&[usize], &[f64]),
    (exact, normal): (&Forces, &[f64]),
) -> Vec<HistorySample> {
    let sample = |(k, &i): (usize, &usize)| {
        let yours_n = data.normal.map(|x| x[i]);
        HistorySample {
            index: i,
            tau: taus[k],
            exact: exact.along[k],
            yours: data.tangential[i],
            error: data.tangential[i] - exact.along[k],
            normal_exact: normal[k],
            normal_yours: yours_n,
            normal_error: yours_n.map(|y| y - normal[k]),
            transverse_exact: exact.across.as_ref().map(|y| y[k]),
            transverse_yours: data.transverse.map(|y| y[i]),
            body_exact: exact.body.get(k).copied(),
            body_yours: data.body.map(|(l, v)| [l[i], v[i]]),
        }
    };
    last.iter().enumerate().map(sample).collect()
}

/// The exact forces at the seed's phases of the last period.
struct Forces {
    along: Vec<f64>,
    /// In the plane.
    across: Option<Vec<f64>>,
    /// On a system with mass.
    body: Vec<[f64; 2]>,
    events: Vec<crate::model::spring::Event>,
    /// What the units say besides the line's.
    units: &'static str,
}

/// The exact forces at the seed's phases `taus` of the last period: the
/// stiff problem's (a massless body's: the stiff one at the drive scaled,
/// `crate::system::massless`) one by one, a body with mass's attractor once
/// ([`system::exact`], its body too), the plane's orbit once
/// ([`plane::exact`]); with [`Exact`] for the normal force (and, stiff along
/// a line, the forces under other conventions).
fn exact_forces(shape: &Shape, c: &crate::Conditions, data: &HistoryData, taus: &[f64]) -> Result<(Exact, Forces)> {
    let with_mass = c.system().filter(|s| s.frequency_ratio() > 0.0);
    if data.body.is_some() && with_mass.is_none() {
        let reason = "body columns compare a body with mass on a system: give --system-stiffness and \
                      --frequency-ratio, or leave the columns out";
        return Err(Error::Parse { context: "body_lag".into(), reason: reason.into() });
    }
    if let Some(w) = c.transverse() {
        let f = plane::exact(shape, c, w, taus)?;
        let units = " (along and across the sliding direction)";
        let forces = Forces { along: f.along, across: Some(f.across), body: vec![], events: f.events, units };
        return Ok((Exact::normal_only(shape, c.amp()), forces));
    }
    let stiff = match c.system() {
        Some(s) if with_mass.is_none() => crate::system::massless(c, s)?,
        _ => c.stiff(),
    };
    let exact = Exact::new(shape, &stiff)?;
    let (along, body, events) = match with_mass {
        Some(sys) => system::exact(shape, c, sys, taus)?,
        None => (crate::numerics::par::map(taus, |&t| exact.tangential(t)), vec![], exact.events(&stiff)?),
    };
    Ok((exact, Forces { along, across: None, body, events, units: "" }))
}

/// Errors of order one in a history: beyond `LARGE_ERROR` of the `peak` and
/// beyond what a step's timing could explain (four of the file's largest
/// steps in force): the convention that explains them, or `large_errors`
/// where nothing else is named.
fn large_error_findings(
    v: &mut HistoryValidation,
    shape: &Shape,
    c: &crate::Conditions,
    data: &HistoryData,
    (last, seed_taus): (&[usize], &[f64]),
    peak: f64,
) {
    let steps = |f: &[f64]| last.windows(2).map(|w| (f[w[1]] - f[w[0]]).abs()).fold(0.0, f64::max);
    let step = steps(data.tangential).max(data.transverse.map_or(0.0, steps));
    let large = (super::convention::LARGE_ERROR * peak).max(4.0 * step);
    // In the plane the force across counts as the force along does.
    let error = |s: &HistorySample| {
        s.error.abs().max(s.transverse_yours.zip(s.transverse_exact).map_or(0.0, |(y, e)| (y - e).abs()))
    };
    let bad: Vec<usize> =
        v.last_period.iter().filter(|s| s.error.is_nan() || error(s) > large).map(|s| s.index).collect();
    if bad.is_empty() {
        return;
    }
    let yours: Vec<f64> = last.iter().map(|&i| data.tangential[i]).collect();
    let named = match c.system().filter(|s| s.frequency_ratio() > 0.0) {
        // The conventions are a line's (the plane's are a table's: `validate`).
        _ if c.transverse().is_some() => None,
        Some(sys) => system::mistake(shape, (c, sys), seed_taus, (&yours, bad.clone()), v.max_abs_error),
        None => {
            let under = |other: &crate::Conditions| -> Option<f64> {
                let e = Exact::new(shape, other).ok()?;
                Some(yours.iter().zip(seed_taus).map(|(y, &t)| (y - e.tangential(t)).abs()).fold(0.0, f64::max))
            };
            super::convention::history_finding(c, &bad, v.max_abs_error, &under)
        }
    };
    match named {
        Some(f) => v.findings.push(f),
        None if v.findings.is_empty() => v.findings.extend(super::convention::large_errors(bad, v.max_abs_error)),
        None => {}
    }
}

/// What a history shows of contact loss: samples with a tangential force
/// where the normal force is 0 (or below), and the lowest normal force where
/// it goes below 0.
struct Contact {
    out_of_contact: Vec<usize>,
    negative: Option<f64>,
}

fn history_findings(v: &HistoryValidation, above: &[usize], contact: &Contact, tolerance: f64) -> Vec<Finding> {
    let mut out = vec![];
    let e = |x: f64| format!("{x:.3e}");
    if let Some(low) = contact.negative {
        out.push(general(
            FindingKind::NegativeNormal,
            format!(
                "the normal force goes below 0 (down to {}): contact loss is not modelled; a spring pulled \
                 out of contact carries no force (neither normal nor tangential) and enters contact again \
                 relaxed",
                e(low)
            ),
        ));
    }
    out.extend(finding(
        FindingKind::ForceOutOfContact,
        contact.out_of_contact.clone(),
        "a tangential force while the normal force is 0: the spring is not relaxed when it loses contact \
         (out of contact it carries no force, and it enters contact again at 0)",
    ));
    if let Some(nc) = v.normal.as_ref().filter(|_| contact.negative.is_none()) {
        let peak = v.last_period.iter().filter_map(|s| s.normal_yours).fold(0.0f64, f64::max);
        if (nc.mean_ratio - 1.0).abs() > NORMAL_MEAN_TOLERANCE || !nc.mean_ratio.is_finite() {
            out.push(general(
                FindingKind::NormalScale,
                format!(
                    "the normal column's mean over the last period is {} times the exact mean: the forces are \
                     not in units of the static force F0 (give --static-force: the normal force at depth u0 \
                     without oscillation, in the file's units: kz u0 for the flat punch, (4/3) E* R^1/2 u0^3/2 \
                     for the paraboloid), or the amplitude or shape differ",
                    nc.mean_ratio
                ),
            ));
        } else if nc.max_abs_error > NORMAL_SHAPE_TOLERANCE * peak {
            out.push(general(
                FindingKind::NormalShape,
                format!(
                    "the normal column differs from the exact normal force by up to {} of its peak (after \
                     aligning the time origin): check the amplitude (--amp), the shape and the time axis (omega)",
                    e(nc.max_abs_error / peak.max(f64::MIN_POSITIVE))
                ),
            ));
        }
    }
    if v.periodic == Some(false) {
        let more = v
            .periods_needed
            .map_or("the drift does not decay from period to period: check the start".to_string(), |k| {
                format!("about {k} more periods would bring it below the tolerance")
            });
        out.push(general(
            FindingKind::NotPeriodic,
            format!(
                "the last period differs from the one before by up to {} (tolerance {tolerance:e} of the peak): \
                 not yet in steady state; {more}",
                e(v.period_drift.unwrap_or(f64::NAN))
            ),
        ));
    }
    out.extend(finding(
        FindingKind::AboveBound,
        above.to_vec(),
        "the tangential force exceeds mu0 times the normal force at these samples: the switch from stick to \
         slip is missed (check the stick end, eq. 8, and its sign)",
    ));
    let found: Vec<_> = v.events.iter().map(|f| f.kind).collect();
    let missing: Vec<String> = v
        .exact_events
        .iter()
        .filter(|x| !found.contains(&x.kind))
        .map(|x| format!("{} at tau = {:.6}", x.kind.name(), x.tau))
        .collect();
    if !missing.is_empty() {
        out.push(general(
            FindingKind::MissingEvent,
            format!("the exact {} have no counterpart in the history", missing.join(", ")),
        ));
    }
    out
}
