//! Force histories under a tangential oscillation: every spring is the stop
//! operator's steady state ([`crate::stop::solve`]) with the body's motion
//! `X = vhat tau + T sin(tau + phase)` in pre-slip lengths, its force read at
//! each sample from its phases ([`crate::stop::force_at`]). Units as the
//! seed's histories (module docs of [`super`]): the flat punch's force is in
//! `mu0 kz u0`; an MDR spring's per unit length in `mu0 E* u0` (the bound
//! `(1 - G(z) - amp cos tau)_+`), summed over both sides of the foundation.

use super::{Body, HistoryOptions, Sample};
use crate::combined::{report, Oscillation};
use crate::conditions::Conditions;
use crate::error::Result;
use crate::model::spring::EventKind;
use crate::stop::{solve, Bound, StopSpring};
use std::f64::consts::TAU;

/// A stop event's kind as a history's event (`forward` is the seed's `slip`).
pub(crate) fn event_kind(name: &str) -> Option<EventKind> {
    match name {
        "contact" => Some(EventKind::Contact),
        "loss_of_contact" => Some(EventKind::LossOfContact),
        "stick" => Some(EventKind::Stick),
        "forward" => Some(EventKind::Slip),
        "backward" => Some(EventKind::BackwardSlip),
        _ => None,
    }
}

/// The flat punch's samples at `taus`, with the events of every period added.
pub(super) fn flat_samples(c: &Conditions, periods: usize, mut taus: Vec<(f64, Option<EventKind>)>) -> Vec<Sample> {
    let o = Oscillation::of(c);
    let (b, d) = (Bound { c: 1.0, amp: o.amp }, o.drive());
    let sp = solve(b, d);
    let events = report(&sp, b).events;
    for p in 0..periods {
        for e in &events {
            taus.push((e.tau + TAU * p as f64, event_kind(e.kind)));
        }
    }
    taus.sort_by(|x, y| x.0.total_cmp(&y.0));
    taus.iter()
        .map(|&(tau, event)| {
            // The force on its bound is the bound, to the bit (the solver reads
            // the bound at tau reduced to the period, a rounding apart).
            let normal = (1.0 - o.amp * tau.cos()).max(0.0);
            let tangential = sp.force_at(b, d, tau).clamp(-normal, normal);
            Sample { tau, normal, tangential, transverse: None, event, springs: vec![], body: None }
        })
        .collect()
}

/// Every other contact through `opts.springs` springs at the midpoints of a
/// uniform grid on `0 <= z < reach(amp)`: the normal force exactly, the
/// tangential one as the grid's sum; the chosen springs one by one.
pub(super) fn foundation_samples(
    contact: &dyn crate::contact::Contact,
    c: &Conditions,
    opts: &HistoryOptions,
    taus: &[(f64, Option<EventKind>)],
) -> Result<Vec<Sample>> {
    let o = Oscillation::of(c);
    let d = o.drive();
    let bound = |g: f64| Bound { c: 1.0 - g, amp: o.amp };
    let dz = contact.reach(o.amp)? / opts.springs as f64;
    let springs: Vec<(Bound, StopSpring)> = crate::numerics::par::map(&(0..opts.springs).collect::<Vec<_>>(), |&i| {
        let b = bound(contact.equivalent_profile((i as f64 + 0.5) * dz));
        (b, solve(b, d))
    });
    let picked: Vec<(Bound, StopSpring)> = opts
        .spring_at
        .iter()
        .map(|&x| {
            let b = bound(contact.equivalent_profile(x));
            (b, solve(b, d))
        })
        .collect();
    // Both sides of the foundation, in units of F0 = F(1).
    let f0 = contact.static_force(1.0);
    let scale = 2.0 * dz / f0;
    let rows = crate::numerics::par::map(taus, |&(tau, _)| {
        let tangential = scale * springs.iter().map(|(b, s)| s.force_at(*b, d, tau)).sum::<f64>();
        let springs =
            picked.iter().map(|(b, s)| [(b.c - b.amp * tau.cos()).max(0.0), s.force_at(*b, d, tau)]).collect();
        Sample {
            tau,
            normal: contact.static_force(1.0 - o.amp * tau.cos()) / f0,
            tangential,
            transverse: None,
            event: None,
            springs,
            body: None,
        }
    });
    Ok(rows)
}

/// A body on a system with mass and stiffness: one period of the attractor.
/// The flat punch's exactly (the attractor's phases sampled), its events among
/// the samples, a massless body the stiff problem at the drive scaled by
/// `kappa/(1 + kappa)`; a curved body's as its springs
/// ([`crate::system::System::springs`]), every spring's events exact (not
/// listed), the forces over the normal force at the mean indentation.
pub(super) fn on_system(
    shape: &crate::shape::Shape,
    c: &Conditions,
    sys: &crate::system::System,
    opts: &HistoryOptions,
) -> Result<super::History> {
    use crate::error::Error;
    // The option named as the user gives it, not the shape.
    if opts.periods != 1 {
        let reason = "a history on a system is one period of its attractor";
        return Err(Error::param("periods", opts.periods as f64, reason));
    }
    if !opts.spring_at.is_empty() {
        let reason = "a history on a system is the contact's total force: no chosen springs";
        return Err(Error::Parse { context: "spring-at".into(), reason: reason.into() });
    }
    let units = format!(
        "{}; on a system: K/kx {}, omega/omega_c {}, zeta {}",
        super::UNITS,
        sys.stiffness(),
        sys.frequency_ratio(),
        sys.damping()
    );
    if !shape.is_flat() {
        super::check_history(shape, 0.0, c.amp(), opts)?;
        let taus: Vec<f64> = (0..opts.samples).map(|j| TAU * j as f64 / opts.samples as f64).collect();
        let (_, forces) = crate::system::curved_history(shape, c, sys, &taus)?;
        let samples = taus
            .iter()
            .zip(forces)
            .map(|(&tau, [normal, f, x, v, norm])| {
                let (lag, force) = sys.body(c, tau, x, v);
                let body = Some(Body { body_lag: lag, body_velocity: v, system_force: force / norm });
                Sample { tau, normal, tangential: f, transverse: None, event: None, springs: vec![], body }
            })
            .collect();
        return Ok(super::History::new(shape, c, units, vec![], samples));
    }
    if sys.frequency_ratio() == 0.0 {
        return super::history(shape, &crate::system::massless(c, sys)?, opts);
    }
    super::check_history(shape, 0.0, c.amp(), opts)?;
    // The attractor once: its events among the samples, then its forces.
    let (report, orbit) = crate::system::attractor(c, sys)?;
    let orbit = orbit.ok_or_else(|| Error::Internal { what: "a body with mass has an orbit".into() })?;
    let mut taus: Vec<(f64, Option<EventKind>)> =
        (0..opts.samples).map(|j| (TAU * j as f64 / opts.samples as f64, None)).collect();
    taus.extend(report.events.iter().map(|e| (e.tau.rem_euclid(TAU), Some(system_event(e.kind)))));
    taus.sort_by(|x, y| x.0.total_cmp(&y.0));
    let at: Vec<f64> = taus.iter().map(|x| x.0).collect();
    let forces = crate::system::sample(&orbit, &at);
    let samples = taus
        .iter()
        .zip(forces)
        .map(|(&(tau, event), [f, x, v])| {
            let normal = (1.0 - c.amp() * tau.cos()).max(0.0);
            let (lag, force) = sys.body(c, tau, x, v);
            let body = Some(Body { body_lag: lag, body_velocity: v, system_force: force });
            Sample { tau, normal, tangential: f.clamp(-normal, normal), transverse: None, event, springs: vec![], body }
        })
        .collect();
    Ok(super::History::new(shape, c, units, vec![], samples))
}

/// A system's phase that starts at an event as a history's event.
fn system_event(kind: crate::system::Kind) -> EventKind {
    use crate::system::Kind;
    match kind {
        Kind::Stick => EventKind::Stick,
        Kind::Forward => EventKind::Slip,
        Kind::Backward => EventKind::BackwardSlip,
        Kind::Free => EventKind::LossOfContact,
    }
}

/// A body with mass on a system (`Omega > 0`) at the phases `taus` (in `[0,
/// 2 pi)`, any order): the tangential force (the history's units), the
/// body's lag `X_d - x` and velocity at each, and the attractor's events
/// (the flat punch's; units of [`Event`]: `kz du`). One period of the drive
/// is one of the attractor only where it has period 1: any other is refused.
///
/// # Errors
/// As [`super::history`]; [`crate::Error::InvalidParameter`] (`frequency-ratio`)
/// where the attractor has another period or none.
pub(crate) fn system_at(
    shape: &crate::shape::Shape,
    c: &Conditions,
    sys: &crate::system::System,
    taus: &[f64],
) -> Result<(Vec<[f64; 3]>, Vec<crate::model::spring::Event>)> {
    let mut order: Vec<usize> = (0..taus.len()).collect();
    order.sort_by(|&a, &b| taus[a].total_cmp(&taus[b]));
    let sorted: Vec<f64> = order.iter().map(|&i| taus[i]).collect();
    let amp = c.amp();
    let (report, rows) = if shape.is_flat() {
        let (report, orbit) = crate::system::attractor(c, sys)?;
        let orbit = orbit.ok_or_else(|| crate::Error::Internal { what: "a body with mass has an orbit".into() })?;
        (report, crate::system::sample(&orbit, &sorted))
    } else {
        let (report, rows) = crate::system::curved_history(shape, c, sys, &sorted)?;
        (report, rows.into_iter().map(|[_, f, x, v, _]| [f, x, v]).collect())
    };
    if report.period != Some(1) {
        let what = report.period.map_or("no period".to_string(), |k| format!("period {k}"));
        let reason = format!(
            "the attractor here has {what}: a history's last period of the drive is compared with a period-1 \
             attractor only (validate a table of mu instead)"
        );
        return Err(crate::Error::param("frequency-ratio", sys.frequency_ratio(), &reason));
    }
    let mut out = vec![[0.0; 3]; taus.len()];
    for (&i, (&tau, [f, x, v])) in order.iter().zip(sorted.iter().zip(rows)) {
        out[i] = [f, sys.body(c, tau, x, v).0, v];
    }
    let events = report
        .events
        .iter()
        .map(|e| crate::model::spring::Event {
            kind: system_event(e.kind),
            tau: e.tau.rem_euclid(TAU),
            normal: (1.0 / amp - e.tau.cos()).max(0.0),
            tangential: e.force / amp,
        })
        .collect();
    Ok((out, events))
}
