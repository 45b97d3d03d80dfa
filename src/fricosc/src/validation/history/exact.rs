//! The exact forces a history is compared with.

use super::HISTORY_REFERENCE_SPRINGS;
use crate::error::Result;
use crate::model::spring::{Event, Spring};
use crate::shape::Shape;
use crate::stop::{solve, Bound, Drive, StopSpring};

/// The exact forces of `shape` under `c` in units of `F0` (module docs), from
/// [`crate::history::history`]'s springs: the flat punch's in closed form; a
/// curved contact's normal force from the static force at each depth, its
/// tangential force summed over [`HISTORY_REFERENCE_SPRINGS`] springs.
pub(super) struct Exact {
    pub(super) flat: bool,
    amp: f64,
    springs: Springs,
    /// A spring's force (units `mu0 E* du` a unit length, or `mu0 E* u0`
    /// under a tangential oscillation) to `mu0 F0`.
    scale: f64,
    f0: f64,
}

/// The springs of [`Exact`]: the seed's, or the stop operator's with their bounds and drive.
enum Springs {
    Seed(Vec<Spring>),
    Stop(Vec<(Bound, StopSpring)>, Drive),
}

impl Exact {
    pub(super) fn new(shape: &Shape, c: &crate::Conditions) -> Result<Exact> {
        let (flat, amp) = (shape.is_flat(), c.amp());
        let count = if flat { 1 } else { HISTORY_REFERENCE_SPRINGS };
        let (dz, s_of) = crate::contact::grid(shape.contact(), amp, count)?;
        let f0 = if flat { 1.0 } else { shape.contact().static_force(1.0) };
        let (springs, scale) = match c.tangential() {
            None => {
                let vbar = c.as_vbar()?;
                let springs = if flat {
                    vec![crate::flat::spring(vbar, amp, crate::model::spring::Precision::Events)]
                } else {
                    (0..count).map(|i| Spring::with_events(s_of(i), vbar)).collect()
                };
                (Springs::Seed(springs), if flat { 1.0 } else { 2.0 * amp * dz / f0 })
            }
            Some(_) => {
                let d = crate::combined::Oscillation::of(c).drive();
                let level =
                    |i: usize| if flat { 1.0 } else { 1.0 - shape.contact().equivalent_profile((i as f64 + 0.5) * dz) };
                let springs = (0..count)
                    .map(|i| {
                        let b = Bound { c: level(i), amp };
                        (b, solve(b, d))
                    })
                    .collect();
                (Springs::Stop(springs, d), if flat { 1.0 } else { 2.0 * dz / f0 })
            }
        };
        Ok(Exact { flat, amp, springs, scale, f0 })
    }

    /// The normal force only (a history in the plane has its forces from
    /// [`super::plane`]).
    pub(super) fn normal_only(shape: &Shape, amp: f64) -> Exact {
        let flat = shape.is_flat();
        let f0 = if flat { 1.0 } else { shape.contact().static_force(1.0) };
        Exact { flat, amp, springs: Springs::Seed(vec![]), scale: 0.0, f0 }
    }

    pub(super) fn normal(&self, shape: &Shape, tau: f64) -> f64 {
        if self.flat {
            (1.0 - self.amp * tau.cos()).max(0.0)
        } else {
            shape.contact().static_force(1.0 - self.amp * tau.cos()) / self.f0
        }
    }

    pub(super) fn tangential(&self, tau: f64) -> f64 {
        match &self.springs {
            Springs::Seed(sp) if self.flat => crate::flat::forces_at(&sp[0], self.amp, tau).1,
            Springs::Seed(sp) => {
                self.scale * sp.iter().map(|s| crate::contact::history::spring_force(s, tau)).sum::<f64>()
            }
            Springs::Stop(sp, d) => self.scale * sp.iter().map(|(b, s)| s.force_at(*b, *d, tau)).sum::<f64>(),
        }
    }

    /// The exact events of the period (the flat punch; a curved contact's total has none).
    pub(super) fn events(&self, c: &crate::Conditions) -> Result<Vec<Event>> {
        match &self.springs {
            _ if !self.flat => Ok(vec![]),
            Springs::Seed(_) => Ok(crate::flat::point(c.as_vbar()?, self.amp)?.events),
            Springs::Stop(sp, _) => Ok(crate::combined::report(&sp[0].1, sp[0].0)
                .events
                .iter()
                .filter_map(|e| {
                    let kind = crate::contact::history::event_kind(e.kind)?;
                    Some(Event { kind, tau: e.tau, normal: e.normal, tangential: e.tangential })
                })
                .collect()),
        }
    }
}
