//! Force histories: the normal and tangential force over time (the seed's
//! Fig. 2), exact, sampled from the closed-form phases with every event time
//! included as a sample (`fricosc history`, the Python package's `history()`).
//!
//! Forces in units of the static force `F0`, the normal force at the mean
//! indentation `u0` without oscillation (normal `/ F0`, tangential
//! `/ (mu0 F0)`): `kz u0` for the flat punch, Hertz's `(4/3) E* R^(1/2) u0^(3/2)`
//! for the paraboloid, [`crate::contact::Contact::static_force`] at depth 1 in
//! general. For a curved contact the normal total is exact (the static force at
//! each phase's depth), the tangential total sums the exact forces of `springs`
//! springs at the midpoints of a uniform grid (second order in the spacing away
//! from the phase switches); chosen springs are reported per unit length of the
//! foundation, in units of `E* u0` (and `mu0 E* u0`).

mod combined;

pub(crate) use combined::{event_kind, system_at};

use crate::conditions::Conditions;
use crate::error::{check_nonneg, Error, Result};
use crate::model::spring::{EventKind, Spring};
use crate::shape::Shape;
use std::f64::consts::TAU;

/// One sample of the forces.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Sample {
    /// Phase `omega t` (from 0 to `2 pi periods`).
    pub tau: f64,
    /// Normal force.
    pub normal: f64,
    /// Tangential force (along the sliding direction).
    pub tangential: f64,
    /// The tangential force across the sliding direction, under a
    /// transverse oscillation ([`Conditions::with_transverse`]).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub transverse: Option<f64>,
    /// The event at this phase, if it is one (flat punch only).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub event: Option<EventKind>,
    /// For MDR shapes, the chosen springs' `[normal, tangential]` forces per unit
    /// length of the foundation, units `E* u0` (and `mu0 E* u0`), in the order of
    /// [`History::spring_positions`].
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Vec::is_empty"))]
    pub springs: Vec<[f64; 2]>,
    /// On a system, the body with mass: its place and velocity and the
    /// system spring's force.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub body: Option<Body>,
}

/// The body on a system at a sample: lengths in pre-slip lengths `l`, the
/// force in the units of the tangential force.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Body {
    /// The drive's lead on the body, `X_d - x`.
    pub body_lag: f64,
    /// The body's velocity `x'` (pre-slip lengths per radian of `omega t`).
    pub body_velocity: f64,
    /// The system's force on the body, `kappa (X_d - x) + 2 zeta sqrt(kappa)
    /// Omega (X_d' - x')` (with the contact's, it accelerates the body).
    pub system_force: f64,
}

/// A force history.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct History {
    /// Shape name.
    pub shape: String,
    /// The point: velocity and oscillation.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub point: HistoryPoint,
    /// Units of the forces.
    pub units: String,
    /// Positions `x/x_c` of the chosen springs (MDR shapes).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Vec::is_empty"))]
    pub spring_positions: Vec<f64>,
    /// The samples, in phase order.
    pub samples: Vec<Sample>,
}

/// The point a history is taken at: `vbar` and `amp`, or under a tangential
/// oscillation `vhat`, `amp`, `T` and the phase.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HistoryPoint {
    /// Dimensionless velocity `vbar` (eq. 3); `None` under a tangential
    /// oscillation, whose velocity is `vhat`.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub vbar: Option<f64>,
    /// `vhat` (eq. 15) under a tangential oscillation.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub vhat: Option<f64>,
    /// Amplitude `du/u0`.
    pub amp: f64,
    /// The oscillations in the plane, if any.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub in_plane: crate::InPlane,
}

impl HistoryPoint {
    /// The point of the conditions `c`.
    #[must_use]
    pub fn of(c: &Conditions) -> HistoryPoint {
        let in_plane = crate::InPlane::of(c);
        let by_vhat = in_plane.any();
        HistoryPoint {
            vbar: if by_vhat { None } else { c.as_vbar().ok() },
            vhat: by_vhat.then(|| c.as_vhat()),
            amp: c.amp(),
            in_plane,
        }
    }
}

impl std::fmt::Display for HistoryPoint {
    /// `vbar 0.3, du/u0 0.5`, or `vhat 0.3, du/u0 0.5, T 1.5, phase 1.3`,
    /// and `W 1, psi 0.7` across the sliding direction.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let p = &self.in_plane;
        match (self.vbar, self.vhat, p.tangential_amp, p.phase) {
            (_, Some(v), Some(t), Some(p)) => write!(f, "vhat {v}, du/u0 {}, T {t}, phase {p}", self.amp)?,
            (_, Some(v), ..) => write!(f, "vhat {v}, du/u0 {}", self.amp)?,
            (Some(v), ..) => write!(f, "vbar {v}, du/u0 {}", self.amp)?,
            _ => write!(f, "du/u0 {}", self.amp)?,
        }
        match (p.transverse_amp, p.transverse_phase) {
            (Some(w), Some(psi)) => write!(f, ", W {w}, psi {psi}"),
            _ => Ok(()),
        }
    }
}

impl History {
    pub(crate) fn new(
        shape: &Shape,
        c: &Conditions,
        units: String,
        spring_positions: Vec<f64>,
        samples: Vec<Sample>,
    ) -> History {
        History { shape: shape.name().into(), point: HistoryPoint::of(c), units, spring_positions, samples }
    }
}

/// Tangential force of one spring at phase `tau`, units `mu0 kz du`, from its phases.
pub(crate) fn spring_force(sp: &Spring, tau: f64) -> f64 {
    let b = (sp.s - tau.cos()).max(0.0);
    if b == 0.0 {
        return 0.0;
    }
    if let Some(st) = sp.stick {
        let t0 = st.start;
        let x = (tau - t0).rem_euclid(TAU);
        if x < st.length {
            return (st.start_force + sp.vbar * x).min(b);
        }
    }
    b
}

/// Most springs summed for an MDR history.
pub const MAX_SPRINGS: usize = 1_000_000;

/// Most springs summed for a curved history in the plane (each an orbit
/// walked through the samples: about a minute on two cores).
pub const MAX_PLANE_SPRINGS: usize = 100_000;

/// Most spring-force evaluations one history may take (rows x springs: about a
/// minute on two cores).
pub const MAX_SPRING_WORK: u128 = 4_000_000_000;

/// Most rows one history may hold (and most chosen-spring values): the same
/// 10^7 as every other output of the command line (`grid::MAX_ROWS` there).
pub const MAX_SAMPLES: usize = 10_000_000;

/// What a [`history`] samples.
///
/// ```
/// use fricosc::history::{history, HistoryOptions};
/// let opts = HistoryOptions::default().with_samples(100);
/// let h = history(&fricosc::Shape::flat(), &fricosc::Conditions::vbar(0.3, 0.5)?, &opts)?;
/// assert_eq!(h.samples.len(), 101 + 2); // 100 intervals, and the stick and slip events
/// # Ok::<(), fricosc::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct HistoryOptions {
    /// Periods sampled (default 1).
    pub periods: usize,
    /// Uniform samples over all periods (default 400; the events are added).
    pub samples: usize,
    /// Springs summed for curved shapes (default 4000).
    pub springs: usize,
    /// Positions `x/x_c >= 0` of springs of a curved shape reported one by one.
    pub spring_at: Vec<f64>,
}

impl Default for HistoryOptions {
    fn default() -> Self {
        HistoryOptions { periods: 1, samples: 400, springs: 4000, spring_at: vec![] }
    }
}

impl HistoryOptions {
    /// With `periods` periods.
    #[must_use]
    pub fn with_periods(self, periods: usize) -> Self {
        HistoryOptions { periods, ..self }
    }
    /// With `samples` uniform samples.
    #[must_use]
    pub fn with_samples(self, samples: usize) -> Self {
        HistoryOptions { samples, ..self }
    }
    /// With `springs` springs summed (curved shapes).
    #[must_use]
    pub fn with_springs(self, springs: usize) -> Self {
        HistoryOptions { springs, ..self }
    }
    /// With these springs reported one by one (positions `x/x_c`, curved shapes).
    #[must_use]
    pub fn with_spring_at(self, spring_at: Vec<f64>) -> Self {
        HistoryOptions { spring_at, ..self }
    }
}

/// Every limit of a history, checked before anything is allocated; the rows
/// (uniform samples, their end point, and up to 4 events a period of the flat punch).
fn check_history(shape: &Shape, vbar: f64, amp: f64, o: &HistoryOptions) -> Result<u128> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    for &x in &o.spring_at {
        check_nonneg("spring position", x)?;
    }
    if !o.spring_at.is_empty() && shape.is_flat() {
        return Err(Error::InvalidShape {
            spec: shape.name().into(),
            reason: "chosen springs need an MDR shape".into(),
        });
    }
    for (name, v) in [("periods", o.periods), ("samples", o.samples), ("springs", o.springs)] {
        if v == 0 {
            return Err(Error::param(name, 0.0, "must be >= 1"));
        }
    }
    let too_large = |what: &str, count: u128, limit: u128| {
        if count > limit {
            Err(Error::TooLarge { what: what.into(), count, limit })
        } else {
            Ok(())
        }
    };
    too_large("history springs", o.springs as u128, MAX_SPRINGS as u128)?;
    let events = if shape.is_flat() { 4 * o.periods as u128 } else { 0 };
    let rows = o.samples as u128 + 1 + events;
    too_large("history rows (samples + 1 + events)", rows, MAX_SAMPLES as u128)?;
    let values = rows * o.spring_at.len() as u128;
    too_large("history chosen-spring values (rows x --spring-at positions)", values, MAX_SAMPLES as u128)?;
    let work = rows * if shape.is_flat() { 1 } else { o.springs as u128 };
    too_large("history spring evaluations (rows x springs)", work, MAX_SPRING_WORK)?;
    if !shape.is_flat() && amp > 0.0 {
        // The springs' s = (1 - G)/amp, and the largest force, must be numbers.
        if amp < MIN_CURVED_AMP {
            return Err(Error::param("amp", amp, "a curved shape's history needs amp >= 1e-300 (or amp = 0)"));
        }
        let c = shape.contact();
        if !(c.static_force(1.0 + amp).is_finite() && c.reach(amp)?.is_finite()) {
            return Err(Error::param(
                "amp",
                amp,
                &format!("the normal force of {} at this amplitude overflows double precision", shape.name()),
            ));
        }
    }
    Ok(rows)
}

/// The units of every history's forces (module docs).
pub(crate) const UNITS: &str = "normal: F0 (the static normal force at depth u0); tangential: mu0 F0";

/// Smallest nonzero amplitude of a curved shape's history: below it the
/// springs' coordinate `s = (1 - G)/amp` overflows.
pub const MIN_CURVED_AMP: f64 = 1e-300;

/// The force history of `shape` under the conditions `c` (their tolerance is
/// not used): `opts.periods` periods with `opts.samples` uniform samples, plus
/// the flat punch's events. Under a tangential oscillation every spring is the
/// stop operator's ([`crate::spring::solve`]), with `vhat`, `T` and the phase of `c`.
/// On a system ([`Conditions::with_system`]): one period of the attractor,
/// with the body (a curved body as the system's springs).
///
/// ```
/// use fricosc::history::{history, HistoryOptions};
/// use fricosc::{Conditions, Shape};
/// let c = Conditions::vhat(0.2, 0.5)?.with_tangential(1.5, 1.3)?;
/// let h = history(&Shape::flat(), &c, &HistoryOptions::default().with_samples(100))?;
/// // The force slips both ways: it reaches -B where the body moves back.
/// assert!(h.samples.iter().any(|s| s.tangential < 0.0 && s.tangential == -s.normal));
/// # Ok::<(), fricosc::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for bad inputs (`vhat` without a tangential
/// oscillation at `amp = 0`), [`Error::TooLarge`] beyond the
/// limits ([`MAX_SAMPLES`] rows, [`MAX_SPRINGS`] springs, [`MAX_SPRING_WORK`]).
pub fn history(shape: &Shape, c: &Conditions, opts: &HistoryOptions) -> Result<History> {
    if let Some(w) = c.transverse() {
        return in_plane(shape, c, w, opts);
    }
    if let Some(sys) = c.system() {
        return combined::on_system(shape, c, sys, opts);
    }
    let amp = c.amp();
    let vbar = if c.tangential().is_some() { 0.0 } else { c.as_vbar()? };
    check_history(shape, vbar, amp, opts)?;
    let total = TAU * opts.periods as f64;
    let samples = opts.samples;
    let mut taus: Vec<(f64, Option<EventKind>)> =
        (0..=samples).map(|j| (total * j as f64 / samples as f64, None)).collect();
    let (units, out) = match (shape.is_flat(), c.tangential().is_some()) {
        (true, false) => (UNITS.to_string(), flat_samples(vbar, amp, opts.periods, taus)),
        (true, true) => (UNITS.to_string(), combined::flat_samples(c, opts.periods, taus)),
        (false, tangential) => {
            taus.sort_by(|a, b| a.0.total_cmp(&b.0));
            let units = format!("{UNITS}; chosen springs per unit length: E* u0 and mu0 E* u0");
            let out = if tangential {
                combined::foundation_samples(shape.contact(), c, opts, &taus)?
            } else {
                foundation_samples(shape.contact(), vbar, amp, opts, &taus)?
            };
            (units, out)
        }
    };
    // Every force is a number: never NaN or inf as an answer.
    let finite = |s: &Sample| {
        s.tau.is_finite()
            && s.normal.is_finite()
            && s.tangential.is_finite()
            && s.springs.iter().flatten().all(|x| x.is_finite())
    };
    if let Some(s) = out.iter().find(|s| !finite(s)) {
        return Err(Error::param(
            "amp",
            amp,
            &format!("the forces of {} overflow double precision at tau = {:?}", shape.name(), s.tau),
        ));
    }
    Ok(History::new(shape, c, units, opts.spring_at.clone(), out))
}

/// The history under a transverse oscillation `w` ([`crate::plane`]): the
/// forces along and across the sliding direction at the samples, the flat
/// punch's orbit's events among them, a curved contact's springs summed as
/// under the other oscillations; what the plane does not solve (a system,
/// chosen springs) refused before any work.
fn in_plane(shape: &Shape, c: &Conditions, w: crate::plane::Transverse, opts: &HistoryOptions) -> Result<History> {
    crate::plane::check(shape, c)?;
    check_history(shape, 0.0, c.amp(), opts)?;
    if !opts.spring_at.is_empty() {
        let reason = "chosen springs are not reported in the plane (the contact's total forces are)";
        return Err(Error::Parse { context: "spring-at".into(), reason: reason.into() });
    }
    if !shape.is_flat() && opts.springs > MAX_PLANE_SPRINGS {
        let (what, count, limit) =
            ("history springs in the plane".into(), opts.springs as u128, MAX_PLANE_SPRINGS as u128);
        return Err(Error::TooLarge { what, count, limit });
    }
    let total = TAU * opts.periods as f64;
    let taus = (0..=opts.samples).map(|j| total * j as f64 / opts.samples as f64).collect();
    let rows = |n: usize| {
        let (count, limit) = (n as u128, MAX_SAMPLES as u128);
        let what = "history rows (samples + 1 + events)".into();
        if count > limit {
            Err(Error::TooLarge { what, count, limit })
        } else {
            Ok(())
        }
    };
    let samples = crate::plane::samples(shape, c, w, (opts.periods, opts.springs), taus, rows)?;
    let units = format!("{UNITS} (along and across the sliding direction)");
    Ok(History::new(shape, c, units, vec![], samples))
}

/// The flat punch's samples at `taus`, with its events added.
fn flat_samples(vbar: f64, amp: f64, periods: usize, mut taus: Vec<(f64, Option<EventKind>)>) -> Vec<Sample> {
    let sp = crate::flat::spring(vbar, amp, crate::model::spring::Precision::Events);
    for p in 0..periods {
        for e in sp.events() {
            taus.push((e.tau + TAU * p as f64, Some(e.kind)));
        }
    }
    taus.sort_by(|a, b| a.0.total_cmp(&b.0));
    taus.iter()
        .map(|&(tau, event)| {
            let (normal, tangential) = crate::flat::forces_at(&sp, amp, tau);
            Sample { tau, normal, tangential, transverse: None, event, springs: vec![], body: None }
        })
        .collect()
}

/// Every other contact through its MDR foundation ([`crate::contact::grid`]):
/// the normal force exactly, the tangential one as the grid's sum.
fn foundation_samples(
    c: &dyn crate::contact::Contact,
    vbar: f64,
    amp: f64,
    opts: &HistoryOptions,
    taus: &[(f64, Option<EventKind>)],
) -> Result<Vec<Sample>> {
    let (dz, sp): (f64, Vec<Spring>) = if amp > 0.0 {
        let (dz, s_of) = crate::contact::grid(c, amp, opts.springs)?;
        (dz, (0..opts.springs).map(|i| Spring::with_events(s_of(i), vbar)).collect())
    } else {
        (0.0, vec![])
    };
    let picked: Vec<(f64, Option<Spring>)> = opts
        .spring_at
        .iter()
        .map(|&x| {
            let g = c.equivalent_profile(x);
            (g, (amp > 0.0).then(|| Spring::with_events((1.0 - g) / amp, vbar)))
        })
        .collect();
    // Both sides of the foundation, in units of F0 = F(1).
    let f0 = c.static_force(1.0);
    Ok(taus
        .iter()
        .map(|&(tau, _)| {
            let normal = c.static_force(1.0 - amp * tau.cos()) / f0;
            let tangential = if amp > 0.0 {
                2.0 * amp * dz / f0 * sp.iter().map(|s| spring_force(s, tau)).sum::<f64>()
            } else {
                normal
            };
            let springs = picked
                .iter()
                .map(|(g, sp)| {
                    let nrm = (1.0 - g - amp * tau.cos()).max(0.0);
                    [nrm, sp.as_ref().map_or(nrm, |s| amp * spring_force(s, tau))]
                })
                .collect();
            Sample { tau, normal, tangential, transverse: None, event: None, springs, body: None }
        })
        .collect())
}

/// The flat punch's history by time stepping (the peer): the seed's scheme,
/// or under a tangential oscillation the stop operator's
/// ([`crate::stepper`]), every step of `periods` periods at `steps_per_period`
/// steps, in the units of [`history`]: the same columns as the exact history,
/// so that a stepper's output can be checked against it (`validate
/// --history`). The spring starts sliding (on its bound), as the peer does.
///
/// # Errors
/// [`Error::InvalidParameter`] for bad inputs or no oscillation at all,
/// [`Error::TooLarge`] beyond [`MAX_SAMPLES`] rows.
pub fn stepped_history(c: &Conditions, periods: usize, steps_per_period: usize) -> Result<History> {
    if let Some(w) = c.transverse() {
        let reason =
            "is not stepped as a history (the exact history in the plane is `history`'s; the 2-D peer answers points)";
        return Err(Error::param("transverse-amp", w.amp(), reason));
    }
    let amp = c.amp();
    for (name, v) in [("periods", periods), ("steps-per-period", steps_per_period)] {
        if v == 0 {
            return Err(Error::param(name, 0.0, "must be >= 1"));
        }
    }
    let rows = periods as u128 * steps_per_period as u128 + 1;
    if rows > MAX_SAMPLES as u128 {
        return Err(Error::TooLarge {
            what: "history rows (periods x steps + 1)".into(),
            count: rows,
            limit: MAX_SAMPLES as u128,
        });
    }
    if amp == 0.0 && c.tangential().is_none() {
        return Err(Error::param("amp", amp, "a stepped history needs an oscillation (amp > 0 or a tangential one)"));
    }
    // In units of kz u0 (the bound (1 - amp cos tau)_+, the drive's step
    // X(tau_k) - X(tau_k-1) in mu0 kz u0), so that no 1/amp overflows at tiny
    // amplitudes: the seed's drive is amp vbar h a step.
    let h = TAU / steps_per_period as f64;
    let drive = c.tangential().map(|(t, phase)| crate::stop::Drive { vhat: c.as_vhat(), t, phase });
    let df = if drive.is_none() { amp * c.as_vbar()? * h } else { 0.0 };
    let mut f = (1.0 - amp).max(0.0);
    let mut samples = Vec::with_capacity(rows as usize);
    for k in 0..rows as usize {
        let tau = h * k as f64;
        let b = (1.0 - amp * tau.cos()).max(0.0);
        if k > 0 {
            f = match drive {
                Some(d) => crate::stepper::update_two_way(f, b, d.dx(h * (k - 1) as f64, tau)),
                None => crate::stepper::update(f, b, df),
            };
        }
        samples.push(Sample {
            tau,
            normal: b,
            tangential: f,
            transverse: None,
            event: None,
            springs: vec![],
            body: None,
        });
    }
    let units = format!("{UNITS} (time stepping)");
    Ok(History::new(&Shape::flat(), c, units, vec![], samples))
}
