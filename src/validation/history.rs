//! Force histories against the exact steady state: errors over the last
//! period, periodicity, and the events found from the force against its bound.

use super::*;

/// An event found in a user's history, matched to the exact one of its kind.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FoundEvent {
    /// What happened.
    pub kind: crate::spring::EventKind,
    /// Its phase in the user's history, in `[0, 2 pi)`.
    pub tau: f64,
    /// The exact event's phase (absent if the exact solution has none of this kind).
    pub exact_tau: Option<f64>,
    /// `tau - exact_tau`, the shortest way round the period.
    pub timing_error: Option<f64>,
}

/// A user's force history against the exact steady state (the flat punch).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HistoryValidation {
    /// Shape name.
    pub shape: String,
    /// Units of the forces compared.
    pub units: String,
    /// Dimensionless velocity.
    pub vbar: f64,
    /// Amplitude.
    pub amp: f64,
    /// Whole periods in the history.
    pub periods: usize,
    /// Samples in the last period (compared).
    pub samples: usize,
    /// Largest `|tangential - exact|` over the last period (units `mu0 kz u0`).
    pub max_abs_error: f64,
    /// Root mean square of the same.
    pub rms_error: f64,
    /// `(tau, tangential - exact)` at every sample of the last period.
    pub sample_errors: Vec<(f64, f64)>,
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
    /// contact: from the force against its Coulomb bound), with their timing errors.
    pub events: Vec<FoundEvent>,
    /// Samples (phases, at most 5) of the last period where the tangential force
    /// exceeds the Coulomb bound `mu0 N` (beyond the tolerance): the switch from
    /// stick to slip (eq. 8) is missed there.
    pub above_bound: Vec<f64>,
    /// How many such samples.
    pub above_bound_count: usize,
    /// The exact events of the period.
    pub exact_events: Vec<crate::spring::Event>,
}

/// Phases of a history's samples from its time column `t`: `t` itself if it is
/// the phase (`is_tau`), else `omega t`, else (without `omega`) the period and
/// phase found from the normal force's maxima, where `tau = pi`
/// (`N ~ 1 - amp cos tau`): the mean spacing of the first and last maxima.
///
/// # Errors
/// [`Error::Parse`] when the time column is not increasing or the period cannot
/// be found.
pub fn phases(t: &[f64], is_tau: bool, omega: Option<f64>, normal: Option<&[f64]>) -> Result<Vec<f64>> {
    if is_tau {
        return Ok(t.to_vec());
    }
    if let Some(w) = omega {
        if !(w.is_finite() && w > 0.0) {
            return Err(Error::param("omega", w, "must be finite and > 0"));
        }
        return Ok(t.iter().map(|x| w * x).collect());
    }
    let bad = |reason: &str| Error::Parse { context: "history".into(), reason: reason.into() };
    let n = normal.ok_or_else(|| bad("a time column t needs omega, or a normal column to find the period from"))?;
    let peaks: Vec<f64> =
        (1..n.len().saturating_sub(1)).filter(|&i| n[i] > n[i - 1] && n[i] >= n[i + 1]).map(|i| t[i]).collect();
    if peaks.len() < 2 {
        return Err(bad("fewer than two maxima of the normal force: give omega"));
    }
    let period = (peaks[peaks.len() - 1] - peaks[0]) / (peaks.len() - 1) as f64;
    let w = std::f64::consts::TAU / period;
    Ok(t.iter().map(|x| std::f64::consts::PI + w * (x - peaks[0])).collect())
}

/// Largest `|F(tau) - F(tau - 2 pi)|` over samples in `[from, to]`, the earlier
/// value interpolated linearly between the user's samples.
fn drift(taus: &[f64], f: &[f64], from: f64, to: f64) -> Option<f64> {
    let at = |t: f64| -> Option<f64> {
        let j = taus.partition_point(|&x| x < t);
        if j == 0 || j >= taus.len() {
            return (j < taus.len() && taus[j] == t).then(|| f[j]);
        }
        let (t0, t1) = (taus[j - 1], taus[j]);
        if t1 == t0 {
            return Some(f[j]);
        }
        Some(f[j - 1] + (f[j] - f[j - 1]) * (t - t0) / (t1 - t0))
    };
    let mut worst: Option<f64> = None;
    for (i, &t) in taus.iter().enumerate() {
        if t > from && t <= to {
            if let Some(prev) = at(t - std::f64::consts::TAU) {
                worst = Some(worst.unwrap_or(0.0).max((f[i] - prev).abs()));
            }
        }
    }
    worst
}

/// Fewest samples the last period of a history must hold to be compared.
pub const MIN_LAST_SAMPLES: usize = 4;

/// Springs of the reference tangential force of a curved contact's history
/// (the midpoint grid of the contact's grid; second order in the spacing).
pub const HISTORY_REFERENCE_SPRINGS: usize = 20_000;

/// Compare a force history (phases `taus`, nondecreasing; the tangential force
/// in units of `mu0 kz u0` for the flat punch, `mu0 E* x_c u0` for other
/// shapes; the normal force in units of `kz u0` or `E* x_c u0` if known, else
/// the exact one is used for the Coulomb bound) with the steady state of
/// `shape` at `(vbar, amp)`: exact for the flat punch; for other shapes the
/// normal force is exact and the tangential force the sum over
/// [`HISTORY_REFERENCE_SPRINGS`] springs, and events are not compared (the
/// total has none). `tolerance` decides "on the bound", "no contact" and
/// "periodic" (relative to the peak normal force).
///
/// # Errors
/// [`Error::Parse`] for columns of different lengths, too few samples or no whole
/// period; the solver's errors for bad `(vbar, amp)`.
pub fn compare_history(
    shape: &Shape,
    vbar: f64,
    amp: f64,
    taus: &[f64],
    tangential: &[f64],
    normal: Option<&[f64]>,
    tolerance: f64,
) -> Result<HistoryValidation> {
    use crate::spring::EventKind;
    use std::f64::consts::TAU;
    crate::error::check_nonneg("vbar", vbar)?;
    crate::error::check_nonneg("amp", amp)?;
    crate::error::check_nonneg("tolerance", tolerance)?;
    if amp == 0.0 {
        return Err(Error::param("amp", amp, "a history without oscillation has no period"));
    }
    let n = taus.len();
    if tangential.len() != n || normal.is_some_and(|x| x.len() != n) {
        return Err(Error::Parse { context: "history".into(), reason: "the columns differ in length".into() });
    }
    for i in 0..n {
        let bad = |what: &str| Error::Parse { context: format!("history sample {i}"), reason: what.into() };
        if !taus[i].is_finite() || !tangential[i].is_finite() || normal.is_some_and(|x| !x[i].is_finite()) {
            return Err(bad("values must be finite"));
        }
        if i > 0 && taus[i] < taus[i - 1] {
            return Err(bad("the phase (time) must not decrease"));
        }
    }
    let span = if n > 1 { taus[n - 1] - taus[0] } else { 0.0 };
    let periods = (span / TAU + 1e-9).floor() as usize;
    if periods < 1 {
        return Err(Error::Parse {
            context: "history".into(),
            reason: format!("it spans {:.3} periods: at least one whole period is needed", span / TAU),
        });
    }
    let flat = shape.is_flat();
    let sp = crate::flat::spring(vbar, amp, crate::spring::Precision::Events);
    // Curved contacts: the reference springs, and the static force at each depth.
    let (dz, springs) = if flat {
        (0.0, vec![])
    } else {
        let (dz, s_of) = crate::contact::grid(shape.contact(), amp, HISTORY_REFERENCE_SPRINGS)?;
        (dz, (0..HISTORY_REFERENCE_SPRINGS).map(|i| Spring::with_events(s_of(i), vbar)).collect())
    };
    let exact_normal = |t: f64| {
        if flat {
            crate::flat::forces_at(&sp, amp, t).0
        } else {
            shape.contact().static_force(1.0 - amp * t.cos())
        }
    };
    let exact_tangential = |t: f64| {
        if flat {
            crate::flat::forces_at(&sp, amp, t).1
        } else {
            2.0 * amp * dz * springs.iter().map(|s| crate::history::spring_force(s, t)).sum::<f64>()
        }
    };
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
    let mut max_abs = 0.0f64;
    let mut sample_errors = Vec::with_capacity(last.len());
    let exact_last: Vec<f64> = crate::numerics::par::map(&last, |&i| exact_tangential(taus[i]));
    for (&i, &x) in last.iter().zip(&exact_last) {
        let e = tangential[i] - x;
        max_abs = max_abs.max(e.abs());
        sample_errors.push((taus[i], e));
    }
    let peak =
        (0..n).map(|i| normal.map_or(exact_normal(taus[i]), |x| x[i])).fold(0.0f64, f64::max).max(f64::MIN_POSITIVE);
    let period_drift = (periods >= 2).then(|| drift(taus, tangential, start, end)).flatten();
    let previous_drift = (periods >= 3).then(|| drift(taus, tangential, start - TAU, start)).flatten();
    let bar = tolerance * peak;
    let periodic = period_drift.map(|d| d <= bar);
    let periods_needed = match (period_drift, previous_drift) {
        (Some(d), _) if d <= bar => Some(0.0),
        (Some(d), Some(p)) if d < p && d > 0.0 => Some(((bar / d).ln() / (d / p).ln()).ceil()),
        _ => None,
    };
    // States along the last period: 0 no contact, 1 on the bound (slip), 2 below (stick).
    let state = |i: usize| {
        let b = normal.map_or(exact_normal(taus[i]), |x| x[i]);
        if b <= bar {
            0
        } else if (tangential[i] - b).abs() <= bar {
            1
        } else {
            2
        }
    };
    let exact_events = if flat { crate::flat::point(vbar, amp)?.events } else { vec![] };
    let above: Vec<f64> = last
        .iter()
        .filter(|&&i| tangential[i] > normal.map_or(exact_normal(taus[i]), |x| x[i]) + bar)
        .map(|&i| taus[i].rem_euclid(TAU))
        .collect();
    let mut found = vec![];
    let mut prev = last.first().map(|&i| state(i));
    for &i in last.iter().skip(1).filter(|_| flat) {
        let s = state(i);
        let kinds: &[EventKind] = match (prev, s) {
            (Some(0), 1) => &[EventKind::Contact],
            (Some(0), 2) => &[EventKind::Contact, EventKind::Stick],
            (Some(1 | 2), 0) => &[EventKind::LossOfContact],
            (Some(1), 2) => &[EventKind::Stick],
            (Some(2), 1) => &[EventKind::Slip],
            _ => &[],
        };
        // The event lies between the two samples: their midpoint.
        let tau = (0.5 * (taus[i - 1] + taus[i])).rem_euclid(TAU);
        for &kind in kinds {
            let exact = exact_events
                .iter()
                .filter(|e| e.kind == kind)
                .map(|e| {
                    let d = (tau - e.tau + 0.5 * TAU).rem_euclid(TAU) - 0.5 * TAU;
                    (e.tau, d)
                })
                .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()));
            found.push(FoundEvent { kind, tau, exact_tau: exact.map(|x| x.0), timing_error: exact.map(|x| x.1) });
        }
        prev = Some(s);
    }
    let units =
        if flat { "normal: kz u0; tangential: mu0 kz u0" } else { "normal: E* x_c u0; tangential: mu0 E* x_c u0" };
    Ok(HistoryValidation {
        shape: shape.name().to_string(),
        units: units.into(),
        vbar,
        amp,
        periods,
        samples: last.len(),
        max_abs_error: max_abs,
        rms_error: super::rms(sample_errors.iter().map(|s| s.1)),
        sample_errors,
        period_drift,
        previous_drift,
        periodic,
        periods_needed,
        events: found,
        above_bound_count: above.len(),
        above_bound: above.into_iter().take(FINDING_ROWS).collect(),
        exact_events,
    })
}
