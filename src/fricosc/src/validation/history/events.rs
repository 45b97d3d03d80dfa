//! The events of a history's last period, from the force against its bound.

use super::FoundEvent;
use std::f64::consts::TAU;

/// The events between consecutive samples of the last period: the state (0 no
/// contact, 1 on the bound, 2 below it) of `force` (the force along a line,
/// signed; in the plane its magnitude) changes; each matched to the nearest
/// exact event of its kind.
pub(super) fn find_events(
    last: &[usize],
    taus: &[f64],
    offset: f64,
    force: &[f64],
    bound: &dyn Fn(usize) -> f64,
    bar: f64,
    exact_events: &[crate::model::spring::Event],
) -> Vec<FoundEvent> {
    use crate::model::spring::EventKind;
    // 0 no contact, 1 on the bound, 2 below it, 3 on the bound's negative (a backward slip).
    let state = |i: usize| {
        let b = bound(i);
        if b <= bar {
            0
        } else if (force[i] - b).abs() <= bar {
            1
        } else if (force[i] + b).abs() <= bar {
            3
        } else {
            2
        }
    };
    let mut found = vec![];
    let mut prev = last.first().map(|&i| state(i));
    for &i in last.iter().skip(1) {
        let s = state(i);
        let kinds: &[EventKind] = match (prev, s) {
            (Some(0), 1) => &[EventKind::Contact],
            (Some(0), 2) => &[EventKind::Contact, EventKind::Stick],
            (Some(0), 3) => &[EventKind::Contact, EventKind::BackwardSlip],
            (Some(1..=3), 0) => &[EventKind::LossOfContact],
            (Some(1 | 3), 2) => &[EventKind::Stick],
            (Some(2 | 3), 1) => &[EventKind::Slip],
            (Some(1 | 2), 3) => &[EventKind::BackwardSlip],
            _ => &[],
        };
        // The event lies between the two samples: their midpoint.
        let tau = (0.5 * (taus[i - 1] + taus[i]) + offset).rem_euclid(TAU);
        for &kind in kinds {
            let exact = exact_events
                .iter()
                .filter(|e| e.kind == kind)
                .map(|e| (e.tau, (tau - e.tau + 0.5 * TAU).rem_euclid(TAU) - 0.5 * TAU))
                .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()));
            found.push(FoundEvent { kind, tau, exact_tau: exact.map(|x| x.0), timing_error: exact.map(|x| x.1) });
        }
        prev = Some(s);
    }
    found
}
