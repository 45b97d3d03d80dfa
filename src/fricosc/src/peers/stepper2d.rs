//! The stop operator in the plane by time stepping: the peer of oscillation
//! across the sliding direction (`MODEL-transverse.md`). Each spring's
//! tangential force `f` is a vector bounded by the circle of radius
//! `B = (1 - G(z) - amp cos tau)_+`; each step moves it with the body by
//! `dX` and projects it back onto the disc (the return mapping: slip along the
//! force, Coulomb's law with an isotropic coefficient, maximal dissipation);
//! out of contact it is 0. The body moves as
//!
//! `X(tau) = (vhat tau + T sin(tau + phase), W sin(tau + psi))`,
//!
//! `W = dy/l` the transverse amplitude over the pre-slip length and `psi` its
//! phase against the normal oscillation. Along one line (`W = 0`) the
//! projection is the clamp of [`super::stepper`]'s oscillation peer, bit for
//! bit: `g/|g|` is exactly `+-1` there.
//!
//! The rigid limit (pre-slip lengths to 0: `vhat`, `W` large at fixed
//! `W/vhat`, `amp = 0`, `T = 0`): every spring slips along the velocity
//! `(vhat, W cos(tau + psi))`, so
//!
//! `mu = <vhat / |X'|> = (1/2 pi) int dtau / sqrt(1 + k^2 cos^2 tau) = (2/pi) K(-k^2)`,
//!
//! `k = W/vhat`, `K(m)` the complete elliptic integral of the first kind; by
//! Gauss's arithmetic-geometric mean, `K(m) = pi / (2 AGM(1, sqrt(1 - m)))`,
//! so `mu = 1 / AGM(1, sqrt(1 + k^2))` ([`rigid_limit`]).

use super::stepper::Stepping;
use crate::error::{Error, Result};
use crate::plane::Transverse;
use crate::shape::Shape;
use crate::special::Kahan;
use std::f64::consts::TAU;

/// The means of the last period of a run in the plane.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct TransverseStepping {
    /// `<f_x> / <B>`, along the sliding direction.
    pub mu_ratio: f64,
    /// `<f_y> / <B>`, the mean force across it.
    pub transverse_ratio: f64,
    /// The largest change of either from the period before.
    pub period_change: f64,
}

/// `mu_macro/mu0` and the transverse ratio of `shape` under the conditions
/// `c` (sliding, normal and tangential oscillation) and the transverse
/// oscillation `w` by time stepping (module docs): `st.springs` springs at the
/// midpoints of the part that ever touches (one for the flat punch), started
/// sliding along `x` (`f = (B, 0)` at `tau = 0`), `periods` periods, the
/// means of the last (rectangle rule on the periodic state).
///
/// # Errors
/// [`Error::InvalidParameter`] for bad inputs, a resolution beyond the
/// limits, conditions on a system; [`Error::Internal`] for a non-finite result.
pub fn transverse(
    shape: &Shape,
    c: &crate::Conditions,
    w: Transverse,
    st: Stepping,
    periods: usize,
) -> Result<TransverseStepping> {
    if c.system().is_some() {
        return Err(Error::param("system-stiffness", 0.0, "the plane's peer steps a stiff system only"));
    }
    if periods == 0 || periods > 1000 {
        return Err(Error::param("periods", periods as f64, "must be between 1 and 1000"));
    }
    let o = crate::combined::Oscillation::of(c);
    let levels = super::stepper::levels(shape, o.amp, st)?;
    let m = st.steps_per_period;
    let h = TAU / m as f64;
    // X(tau_k) - X(tau_{k-1}) without cancellation: 2 sin(h/2) cos(mid + phase).
    let step = |k: usize, amp: f64, phase: f64| {
        let mid = h * (k as f64 - 0.5);
        2.0 * amp * (mid + phase).cos() * (0.5 * h).sin()
    };
    let mut f: Vec<[f64; 2]> = levels.iter().map(|&ci| [(ci - o.amp).max(0.0), 0.0]).collect();
    let mut means = [[0.0; 2]; 2];
    for p in 0..periods {
        let (mut fx, mut fy, mut nb) = (Kahan::default(), Kahan::default(), Kahan::default());
        for k in 1..=m {
            let ct = (h * k as f64).cos();
            let dx = [o.vhat * h + step(k, o.tangential_amp, o.phase), step(k, w.amp(), w.phase())];
            for (fi, &ci) in f.iter_mut().zip(&levels) {
                let b = ci - o.amp * ct;
                *fi = project([fi[0] + dx[0], fi[1] + dx[1]], b);
                fx.add(fi[0]);
                fy.add(fi[1]);
                nb.add(b.max(0.0));
            }
        }
        let ratio = |s: f64| if nb.sum > 0.0 { s / nb.sum } else { 0.0 };
        means = [means[1], [ratio(fx.sum), ratio(fy.sum)]];
        if p == 0 {
            means[0] = [f64::NAN; 2];
        }
    }
    let [last, before] = [means[1], means[0]];
    if !(last[0].is_finite() && last[1].is_finite()) {
        return Err(Error::Internal { what: format!("time stepping in the plane gave {last:?}") });
    }
    let change = (last[0] - before[0]).abs().max((last[1] - before[1]).abs());
    Ok(TransverseStepping { mu_ratio: last[0], transverse_ratio: last[1], period_change: change })
}

/// The return mapping: `g` projected onto the disc of radius `b` (0 out of
/// contact). `g/|g|` first, then times `b`: along an axis exactly `+-b`.
#[inline]
fn project(g: [f64; 2], b: f64) -> [f64; 2] {
    if b <= 0.0 {
        return [0.0, 0.0];
    }
    let r = g[0].hypot(g[1]);
    if r <= b {
        g
    } else {
        [g[0] / r * b, g[1] / r * b]
    }
}

/// `mu` of the rigid limit at `k = W/vhat` (module docs): `1/AGM(1, sqrt(1 + k^2))`.
#[must_use]
pub fn rigid_limit(k: f64) -> f64 {
    let (mut a, mut g) = (1.0f64, (1.0 + k * k).sqrt());
    for _ in 0..64 {
        if (a - g).abs() <= 4.0 * f64::EPSILON * a {
            break;
        }
        (a, g) = (0.5 * (a + g), (a * g).sqrt());
    }
    1.0 / (0.5 * (a + g))
}
