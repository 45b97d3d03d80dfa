//! Force histories under a tangential oscillation: every spring is the stop
//! operator's steady state ([`crate::stop::solve`]) with the body's motion
//! `X = vhat tau + T sin(tau + phase)` in pre-slip lengths, its force read at
//! each sample from its phases ([`crate::stop::force_at`]). Units as the
//! seed's histories (module docs of [`super`]): the flat punch's force is in
//! `mu0 kz u0`; an MDR spring's per unit length in `mu0 E* u0` (the bound
//! `(1 - G(z) - amp cos tau)_+`), summed over both sides of the foundation.

use super::{HistoryOptions, Sample};
use crate::combined::{report, Oscillation};
use crate::conditions::Conditions;
use crate::error::Result;
use crate::model::spring::EventKind;
use crate::stop::{force_at, solve, Bound, StopSpring};
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
            let tangential = force_at(&sp, b, d, tau).clamp(-normal, normal);
            Sample { tau, normal, tangential, event, springs: vec![] }
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
        let tangential = scale * springs.iter().map(|(b, s)| force_at(s, *b, d, tau)).sum::<f64>();
        let springs =
            picked.iter().map(|(b, s)| [(b.c - b.amp * tau.cos()).max(0.0), force_at(s, *b, d, tau)]).collect();
        Sample { tau, normal: contact.static_force(1.0 - o.amp * tau.cos()) / f0, tangential, event: None, springs }
    });
    Ok(rows)
}
