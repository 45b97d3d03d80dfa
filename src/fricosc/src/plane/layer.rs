//! The thin layer where the bound nearly vanishes (`amp` near 1: a touch of
//! zero, or a contact window that barely closes) and a slip is stiff: its
//! direction relaxes to the body's velocity at the rate `|X'|/B`.
//!
//! **The slow manifold.** With `alpha` the direction of `X'`, the slip law
//! `B th' = |X'| sin(alpha - th)` has the solution that follows `alpha`: put
//! `th = alpha - eps`, so `|X'| eps = B (alpha' - eps')` to first order in
//! `eps`, and iterate once from `eps = B alpha'/|X'|`:
//!
//! `eps = (B alpha'/|X'|) (1 - B'/|X'|)`
//!
//! (`alpha' = X' x X''/|X'|^2`; in the layer `B' ~ sqrt(2 amp B)` is the
//! larger of the two small parameters), and it attracts every other slip at
//! the rate `|X'|/B`. Inside the layer, where `B <= b_layer`, a slip within
//! [`ON_MANIFOLD`] of it (or of the neglected part, `(B kappa)^2 + B kappa
//! (B'/|X'|)^2`, `kappa = (|alpha'| + |X''|/|X'|)/|X'|`, times 16) is taken
//! to be on it and its force `B e(th_m)` integrated by Gauss-Legendre
//! quadrature; the neglected part costs at most `int B` times it, which
//! `b_layer = 1e-5 min(1, |X'|^2)` keeps near `1e-17` (the estimate books
//! it), with `|X'|` where the layer is: at `tau = 0` for a bound that stays
//! in contact, at the edges of contact (the smaller) for one that loses it
//! ([`thickness`]). Off the manifold the Taylor steps go on until the
//! transient has decayed.

use super::drive::{Bound, Drive};
use std::f64::consts::TAU;

/// `|th - th_m|` below which a slip in the layer is on the manifold: the
/// transient left, `B phi B/|X'|`, is below `1e-25`.
pub(crate) const ON_MANIFOLD: f64 = 1e-12;
/// `B` at the layer's edges, for `|X'(0)| = 1`.
const LAYER_B: f64 = 1e-5;

/// The layers `[2 pi k - w, 2 pi k + w]` of one spring.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Layer {
    half_width: f64,
}

impl Layer {
    /// The layer of `bound` under `drive`, if its minimum `level - amp` is
    /// below the layer's `B`: `1 - cos w = (b_layer - (level - amp))/amp`.
    pub(crate) fn of(drive: &Drive, bound: &Bound) -> Option<Layer> {
        let b = thickness(drive, bound);
        let gap = bound.level - bound.amp;
        // A bound whose peak is below `b` is in the layer all period (`w = pi`).
        let s = ((b - gap) / (2.0 * bound.amp)).sqrt().min(1.0);
        (bound.amp > 0.0 && gap < b).then(|| Layer { half_width: 2.0 * s.asin() })
    }

    /// The layer's end if `tau` is in one (before its end).
    pub(crate) fn exit_if_inside(&self, tau: f64) -> Option<f64> {
        let center = TAU * (tau / TAU).round();
        let (entry, exit) = (center - self.half_width, center + self.half_width);
        (entry <= tau && tau < exit).then_some(exit)
    }

    /// The next layer's start after `tau` (outside a layer).
    pub(crate) fn next_entry(&self, tau: f64) -> f64 {
        TAU * (tau / TAU).ceil() - self.half_width
    }
}

/// `B` at the layer's edges (module docs): `1e-5 min(1, |X'|^2)`, `|X'|` at
/// `tau = 0`, or the smaller at the edges of contact `+-edge` where the
/// bound loses it (there, not at `tau = 0` out of contact, a slip is stiff).
pub(crate) fn thickness(drive: &Drive, bound: &Bound) -> f64 {
    let speed = |tau: f64| {
        let v = drive.velocity_at(tau);
        v[0].hypot(v[1])
    };
    let v = bound.edge.map_or_else(|| speed(0.0), |e| speed(e).min(speed(-e)));
    LAYER_B * v.min(1.0).powi(2)
}

/// The slow manifold's direction `e(th_m)` at `tau`, and the bound on the
/// angle's neglected part (module docs).
pub(crate) fn manifold(drive: &Drive, bound: &Bound, tau: f64) -> ([f64; 2], f64) {
    let (v, a) = (drive.velocity_at(tau), drive.acceleration_at(tau));
    let speed = v[0].hypot(v[1]);
    let turn = (v[0] * a[1] - v[1] * a[0]) / (speed * speed);
    let (b, rate) = (bound.at(tau), bound.amp * tau.sin() / speed);
    let eps = b * turn / speed * (1.0 - rate);
    let kappa = (turn.abs() + a[0].hypot(a[1]) / speed) / speed;
    let neglected = (b * kappa).powi(2) + b * kappa * rate * rate;
    let (se, ce) = eps.sin_cos();
    let e = [v[0] / speed, v[1] / speed];
    // e(alpha - eps): e rotated by -eps.
    let m = [e[0] * ce + e[1] * se, e[1] * ce - e[0] * se];
    (m, neglected)
}

/// `int_a^b B e(th_m) dtau`, `int_a^b B dtau` and the bound on the former's
/// neglected part (module docs), by the 16-point Gauss-Legendre rule (the
/// integrand is analytic on a scale of 1, the interval at most the layer's
/// width).
pub(crate) fn integral(drive: &Drive, bound: &Bound, a: f64, b: f64) -> ([f64; 3], f64) {
    let rule = crate::quad::rule(16, 0.0);
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let (mut f, mut err) = ([0.0; 3], 0.0);
    for (x, w) in rule.nodes.iter().zip(&rule.weights) {
        let tau = mid + half * x;
        let bt = bound.at(tau);
        let (m, neglected) = manifold(drive, bound, tau);
        f[0] += w * bt * m[0];
        f[1] += w * bt * m[1];
        f[2] += w * bt;
        err += w * bt * neglected;
    }
    (f.map(|v| v * half), err * half)
}
