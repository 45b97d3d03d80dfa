//! The time a slip step's series run in: `tau`, or a logarithmic clock
//! towards a loss of contact or away from a contact regained.

use super::drive::Bound;
use super::series::{Series, INVERSE_FACTORIALS, ORDER, RECIPROCALS};
use std::f64::consts::TAU;

/// How close to a loss of contact, or to the contact regained (against the
/// contact's length), a slip's steps run in a log clock.
const LOG_REACH: f64 = 0.25;

/// The time a slip step's series run in: `tau`, or towards a loss of
/// contact at `loss` (a simple zero of `B`, `s = loss - tau` away) the log
/// clock `t` with `tau = loss - s e^(-t)`. There `dtau/dt = s e^(-t)` and
/// `B ~ beta s e^(-t)`: the slip's `y' = (dtau/dt) M y` has the bounded
/// coefficient `~ X'/(2 beta)`, and its series reach the zeros of `B`
/// behind (`behind` away in `tau`: `t = ln(s/behind)`) and ahead (`t =
/// ln(s/ahead) + i pi`), where in `tau` they reach only the loss itself: a
/// step covers a fixed fraction of `ln s`, not of `s`.
///
/// After a contact regained at `contact` (`s = tau - contact` ago), the
/// mirror image `Grow`: `tau = contact + s e^t`, whose series reach the loss
/// ahead (`window` away from the contact: `t = ln(window/s)`) and the loss
/// before the contact (`gap` before it: `t = ln(gap/s) + i pi`), not the
/// contact itself.
#[derive(Debug, Clone, Copy)]
pub(super) enum Clock {
    Tau,
    Log { loss: f64, s: f64, behind: f64, ahead: f64 },
    Grow { contact: f64, s: f64, gap: f64, window: f64 },
}

impl Clock {
    /// The clock of a slip step from `tau` under `bound` (`loss`, its next
    /// loss of contact, if any): within [`LOG_REACH`] of the contact's length
    /// before the loss, `Log`; as near after the contact regained last (at
    /// `2 pi k + t_c`), `Grow`; else `Tau`.
    pub(super) fn for_slip(bound: &Bound, tau: f64, loss: Option<f64>) -> Clock {
        let Some(e) = bound.edge else { return Clock::Tau };
        let (window, reach) = (TAU - 2.0 * e, LOG_REACH * (TAU - 2.0 * e));
        let contact = TAU * ((tau - e) / TAU).floor() + e;
        match loss {
            Some(l) if l - tau <= reach => Clock::Log { loss: l, s: l - tau, behind: window, ahead: 2.0 * e },
            _ if tau > contact && tau - contact <= reach => {
                Clock::Grow { contact, s: tau - contact, gap: 2.0 * e, window }
            }
            _ => Clock::Tau,
        }
    }

    /// `cos tau`, `sin tau` and `dtau/dt` (`None`: 1) as series in the clock's time.
    pub(super) fn trig(&self, tau: f64) -> (Series, Series, Option<Series>) {
        match *self {
            Clock::Tau => {
                let (c, s) = Series::trig(tau);
                (c, s, None)
            }
            Clock::Log { s, .. } => {
                let w = decaying(s);
                let (c, sn) = trig_along(tau, &w);
                (c, sn, Some(w))
            }
            Clock::Grow { s, .. } => {
                let w = Series(INVERSE_FACTORIALS) * s;
                let (c, sn) = trig_along(tau, &w);
                (c, sn, Some(w))
            }
        }
    }

    /// The distance from the step's start to the nearest singularity of its series.
    pub(super) fn radius(&self, bound: &Bound, tau: f64) -> f64 {
        match *self {
            Clock::Tau => bound.singularity_distance(tau),
            Clock::Log { s, behind, ahead, .. } => (behind / s).ln().min((ahead / s).ln().hypot(std::f64::consts::PI)),
            Clock::Grow { s, gap, window, .. } => (window / s).ln().min((gap / s).ln().hypot(std::f64::consts::PI)),
        }
    }

    /// The clock's time at which `tau` reaches `target` (never the loss itself).
    pub(super) fn horizon(&self, tau: f64, target: f64) -> f64 {
        match *self {
            Clock::Tau => target - tau,
            Clock::Log { loss, s, .. } if target < loss => (s / (loss - target)).ln(),
            Clock::Log { .. } => f64::INFINITY,
            Clock::Grow { contact, s, .. } => ((target - contact) / s).ln(),
        }
    }

    /// `tau` after the time `t` from `tau`.
    pub(super) fn time(&self, tau: f64, t: f64) -> f64 {
        match *self {
            Clock::Tau => tau + t,
            Clock::Log { loss, s, .. } => loss - s * (-t).exp(),
            Clock::Grow { contact, s, .. } => contact + s * t.exp(),
        }
    }
}

/// `c e^(-t)`.
fn decaying(c: f64) -> Series {
    let mut a = INVERSE_FACTORIALS;
    for (k, x) in a.iter_mut().enumerate() {
        *x *= if k % 2 == 0 { c } else { -c };
    }
    Series(a)
}

/// `(cos u, sin u)` of the series `u` with `u(0) = tau0` and `u' = w`:
/// `cos' = -sin w`, `sin' = cos w`, each order's terms added to the later
/// sums as soon as it is known.
fn trig_along(tau0: f64, w: &Series) -> (Series, Series) {
    let (s0, c0) = tau0.sin_cos();
    let (mut c, mut s) = (Series::constant(c0), Series::constant(s0));
    let (mut pc, mut ps) = ([0.0; ORDER], [0.0; ORDER]);
    for k in 0..ORDER {
        let (ck, sk) = (c.0[k], s.0[k]);
        for ((a, b), &wj) in pc[k..].iter_mut().zip(&mut ps[k..]).zip(&w.0) {
            *a -= sk * wj;
            *b += ck * wj;
        }
        c.0[k + 1] = pc[k] * RECIPROCALS[k];
        s.0[k + 1] = ps[k] * RECIPROCALS[k];
    }
    (c, s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plane::series::LEN;

    /// `cos` and `sin` along `u' = 1` are [`Series::trig`]; along `u = l - s
    /// e^(-t)` they are `cos(l - s e^(-t))` (the log clock towards a loss),
    /// and along `u = l + s e^t` (away from a contact) `cos(l + s e^t)`,
    /// within the steps they take (at `t = 1` the truncation is 1e-12).
    #[test]
    fn trig_along_a_series_by_its_values() {
        let (c, s) = Series::trig(0.9);
        let (ca, sa) = trig_along(0.9, &Series::constant(1.0));
        let near = |a: f64, b: f64, k: usize| (a - b).abs() <= 8.0 * f64::EPSILON * INVERSE_FACTORIALS[k];
        assert!((0..LEN).all(|k| near(c.0[k], ca.0[k], k) && near(s.0[k], sa.0[k], k)));
        let (l, d) = (5.2, 0.3);
        let (ca, sa) = trig_along(l - d, &decaying(d));
        for t in [0.1f64, 0.3, 0.5] {
            let u = l - d * (-t).exp();
            assert!(
                (ca.eval(t) - u.cos()).abs() < 4e-16 && (sa.eval(t) - u.sin()).abs() < 4e-16,
                "{t} {:e} {:e}",
                ca.eval(t) - u.cos(),
                sa.eval(t) - u.sin()
            );
        }
        assert_eq!(decaying(2.0).0[..3], [2.0, -2.0, 1.0]);
        // Away from a contact at `l`, `u = l + s e^t`: `Clock::Grow`'s series.
        let s = 0.02;
        let grow = Clock::Grow { contact: l, s, gap: 10.0, window: 4.0 };
        let (cg, sg, w) = grow.trig(l + s);
        let w = w.unwrap();
        for t in [0.25f64, 0.5, 1.0] {
            let u = l + s * t.exp();
            // To the rounding of the argument `u` (about 5) itself.
            let (ec, es) = (cg.eval(t) - u.cos(), sg.eval(t) - u.sin());
            assert!(ec.abs().max(es.abs()) < 2.0 * f64::EPSILON * u, "{t}: {ec:e} {es:e}");
            assert!((w.eval(t) - s * t.exp()).abs() < 4e-16 * u, "{t}");
            assert!((grow.time(l + s, t) - u).abs() <= 4.0 * f64::EPSILON * u);
        }
        // Its horizon reaches a target in its time; its radius is the loss
        // ahead (`ln(4/s)`) where the loss behind the contact (`|ln(10/s) +
        // i pi|`) is farther, that loss where it is nearer.
        assert!((grow.time(l + s, grow.horizon(l + s, l + 0.5)) - (l + 0.5)).abs() < 1e-15);
        let bound = Bound::new(1.0, 2.0);
        assert_eq!(grow.radius(&bound, l + s), (4.0f64 / s).ln());
        let near = Clock::Grow { contact: l, s, gap: 0.01, window: 4.0 };
        assert!((near.radius(&bound, l + s) - (0.5f64).ln().hypot(std::f64::consts::PI)).abs() < 1e-15);
    }
}
