//! The flat punch's forces along its orbit in the plane, at chosen phases.
//!
//! The orbit is periodic, so every period's samples are the first period's:
//! each phase is reduced to `[0, 2 pi]` and one walk from the orbit's start
//! goes through them in order, each sample's force the end of the walk so
//! far, resumed from where it stopped ([`Start::Resume`]: the same phases
//! and events as the one walk of the period, its steps only split).

use super::spring::Start;
use super::{centre, orbit, Transverse};
use crate::contact::history::Sample;
use crate::error::Result;
use crate::shape::Shape;
use crate::spring::EventKind;
use crate::Conditions;
use std::f64::consts::TAU;

/// The samples of the flat punch's orbit under `c` and `w` at the
/// phases of `taus` (each in `[0, 2 pi periods]`, ascending) with the
/// orbit's events of each of `periods` periods among them: the normal
/// force `B`, the tangential force along the sliding direction
/// (`tangential`) and across it (`transverse`), in the units of `B`.
/// `rows` is called with the number of rows before the samples are taken.
///
/// # Errors
/// A curved shape, what [`super::check`] refuses; [`crate::Error::Internal`] where no
/// attracting orbit is found; `rows`'s error.
pub(crate) fn samples(
    shape: &Shape,
    c: &Conditions,
    w: Transverse,
    periods: usize,
    taus: Vec<f64>,
    rows: impl FnOnce(usize) -> Result<()>,
) -> Result<Vec<Sample>> {
    if !shape.contact().single_spring() {
        let reason = "a history in the plane is the flat punch's only so far (a curved contact's point is answered)";
        return Err(crate::Error::param("transverse-amp", w.amp(), reason));
    }
    let sp = centre(c, w)?;
    let (eval, start) = orbit(&sp)?;
    // Each sample's phase, and its phase in one period (an event's exactly
    // the orbit's, so that the walk stops where the orbit's events are).
    let reduced = |tau: f64| if tau >= TAU { tau - TAU * ((tau / TAU).ceil() - 1.0) } else { tau };
    let mut at: Vec<(f64, f64, Option<EventKind>)> = taus.into_iter().map(|t| (t, reduced(t), None)).collect();
    for p in 0..periods {
        at.extend(eval.events.iter().map(|e| (e.tau + TAU * p as f64, e.tau, Some(e.kind))));
    }
    rows(at.len())?;
    at.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut order: Vec<(f64, usize)> = at.iter().enumerate().map(|(i, &(_, r, _))| (r, i)).collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut force = vec![[0.0; 2]; at.len()];
    let (mut from, mut now, mut f) = (start, 0.0, start_force(start));
    for (tau, i) in order {
        if tau > now {
            let walk = sp.walk(from, tau)?;
            (from, now, f) = (Start::Resume(walk.resume), tau, walk.end);
        }
        force[i] = f;
    }
    Ok(at
        .iter()
        .zip(force)
        .map(|(&(tau, _, event), [fx, fy])| Sample {
            tau,
            normal: sp.bound.at(tau).max(0.0),
            tangential: fx,
            transverse: Some(fy),
            event,
            springs: vec![],
            body: None,
        })
        .collect())
}

/// The force at the start of a walk from `start` at `tau = 0`.
fn start_force(start: Start) -> [f64; 2] {
    match start {
        Start::Force(_, f) => f,
        Start::Contact(_) | Start::Resume(_) => [0.0; 2],
    }
}
