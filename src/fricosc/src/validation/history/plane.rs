//! A history in the plane (`Conditions::with_transverse`) against the exact
//! orbit there ([`crate::history`]'s forces in the plane): the force along
//! the sliding direction and, where the file gives it, across it; the
//! events from the force's magnitude against its bound (a slip in the plane
//! has `|f| = B` in any direction).

use crate::error::{Error, Result};
use crate::model::spring::Event;
use crate::plane::Transverse;
use crate::shape::Shape;

/// Springs of a curved contact's reference history in the plane (the
/// midpoint grid of [`crate::history`]; second order in the spacing: a
/// cone's period means 9e-9 from the point's at this count).
pub(crate) const PLANE_REFERENCE_SPRINGS: usize = 4000;

/// The file's force across the sliding direction against the exact one over
/// the last period.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct TransverseComparison {
    /// Largest `|transverse - exact|` (units `mu0 F0`).
    pub max_abs_error: f64,
    /// Root mean square of the same.
    pub rms_error: f64,
}

/// The exact forces along and across at the seed's phases `taus` (in `[0,
/// 2 pi)`, any order) and the flat punch's events of one period (their
/// `tangential` the force along).
pub(super) fn exact(shape: &Shape, c: &crate::Conditions, w: Transverse, taus: &[f64]) -> Result<PlaneForces> {
    let mut order: Vec<usize> = (0..taus.len()).collect();
    order.sort_by(|&a, &b| taus[a].total_cmp(&taus[b]));
    let sorted: Vec<f64> = order.iter().map(|&i| taus[i]).collect();
    // One walk: the samples, and the flat punch's events of one period among them.
    let periods = usize::from(shape.is_flat());
    let samples = crate::plane::samples(shape, c, w, (periods, PLANE_REFERENCE_SPRINGS), sorted, |_| Ok(()))?;
    let (mut along, mut across) = (vec![0.0; taus.len()], vec![0.0; taus.len()]);
    let (at_taus, at_events): (Vec<_>, Vec<_>) = samples.iter().partition(|s| s.event.is_none());
    for (&i, s) in order.iter().zip(at_taus) {
        (along[i], across[i]) = (s.tangential, s.transverse.unwrap_or(0.0));
    }
    let events = at_events
        .iter()
        .filter_map(|s| Some(Event { kind: s.event?, tau: s.tau, normal: s.normal, tangential: s.tangential }))
        .collect();
    Ok(PlaneForces { along, across, events })
}

/// [`exact`]'s answer.
pub(super) struct PlaneForces {
    pub(super) along: Vec<f64>,
    pub(super) across: Vec<f64>,
    pub(super) events: Vec<Event>,
}

/// A file's column across the sliding direction is compared in the plane
/// only: refused with conditions along a line.
pub(super) fn check(c: &crate::Conditions, across: Option<&[f64]>) -> Result<()> {
    if across.is_some() && c.transverse().is_none() {
        let reason = "a force across the sliding direction is compared in the plane: give --transverse-amp (and \
                      --transverse-phase), or leave the column out";
        return Err(Error::Parse { context: "transverse".into(), reason: reason.into() });
    }
    Ok(())
}

/// The force whose magnitude meets the bound: `|(f_x, f_y)|` in the plane
/// (the file's across where given, else the exact one: a file without it
/// is judged on the force along alone), the signed force along a line.
pub(super) fn bounded(along: &[f64], across: Option<&[f64]>) -> Vec<f64> {
    match across {
        Some(y) => along.iter().zip(y).map(|(x, y)| x.hypot(*y)).collect(),
        None => along.to_vec(),
    }
}
