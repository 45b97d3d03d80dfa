//! One spring of the model built from the seed's description, independently of
//! the library: the stick starts where the bound's slope falls to vbar (or at
//! the contact, with zero force), ends at the root of the plain gap
//! `B(t0 + x) - F0 - vbar x` (bisection), and the means are elementary
//! integrals over those phases (the seed's eq. 9, eq. 20 for the normal force).
#![allow(dead_code)]
use std::f64::consts::{PI, TAU};

/// Mean normal force of a spring, eq. 20 form: `(s (pi - th) + sin th)/pi`.
pub fn mean_b(s: f64) -> f64 {
    if s >= 1.0 {
        s
    } else if s <= -1.0 {
        0.0
    } else {
        let th = s.acos();
        (s * (PI - th) + th.sin()) / PI
    }
}

/// Period-mean stick deficit of a spring, from the seed's construction.
pub fn deficit(s: f64, v: f64) -> f64 {
    if v >= 1.0 || s <= -1.0 {
        return 0.0;
    }
    let delta = v.asin();
    let c = (1.0 - v * v).sqrt();
    let (t0, f0, x_max) = if s >= c {
        let x_max = if s >= 1.0 { TAU } else { TAU - s.acos() - delta };
        (delta, s - c, x_max)
    } else if s > -c {
        let th = s.acos();
        (th, 0.0, TAU - 2.0 * th)
    } else {
        return 0.0;
    };
    let gap = |x: f64| (s - (t0 + x).cos()) - f0 - v * x;
    // The gap peaks where the bound's slope is vbar again (t0 + x = pi - delta).
    let (mut lo, mut hi) = ((PI - delta - t0).max(0.0), x_max);
    if gap(lo) <= 0.0 {
        return 0.0;
    }
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if gap(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let l = 0.5 * (lo + hi);
    ((s - f0) * l - ((t0 + l).sin() - t0.sin()) - 0.5 * v * l * l) / TAU
}

/// `mu_macro/mu0` of the flat punch (`s = 1/amp`) by this construction.
pub fn flat_mu(v: f64, amp: f64) -> f64 {
    if amp == 0.0 || v >= 1.0 {
        return 1.0;
    }
    let s = 1.0 / amp;
    let b = mean_b(s);
    (b - deficit(s, v)) / b
}
