//! The normal force of a power-law foundation in closed form: one side at a
//! given depth, and the period mean for the cone and the paraboloid.

use std::f64::consts::PI;

/// Complete elliptic integrals `(K(m), E(m))` by the arithmetic-geometric mean,
/// given the parameter `m` in `[0, 1)` and its complement `m1 = 1 - m` (passed
/// separately so that `m -> 1` keeps its accuracy).
pub(super) fn elliptic_ke(m: f64, m1: f64) -> (f64, f64) {
    let (mut a, mut b) = (1.0f64, m1.sqrt());
    let mut sum = 0.5 * m; // 2^(n-1) c_n^2 at n = 0, c_0^2 = m
    let mut pow = 0.5;
    for _ in 0..40 {
        let c = 0.5 * (a - b);
        if c.abs() <= f64::EPSILON * a {
            break;
        }
        let (an, bn) = (0.5 * (a + b), (a * b).sqrt());
        pow *= 2.0;
        sum += pow * c * c;
        a = an;
        b = bn;
    }
    let k = std::f64::consts::FRAC_PI_2 / a;
    (k, k * (1.0 - sum))
}

/// Force of one side of the elastic foundation of `g = z^n` pressed to depth
/// `c` (units `E* x_c u0`): `int_0^(c^(1/n)) (c - z^n) dz = (n/(n+1)) c^(1 + 1/n)`;
/// 0 for `c <= 0`. The one place this formula lives.
pub(crate) fn foundation_force(n: f64, c: f64) -> f64 {
    if c <= 0.0 {
        0.0
    } else {
        n / (n + 1.0) * c.powf(1.0 + 1.0 / n)
    }
}

/// Total mean normal force `int amp <B> dz` in closed form where one exists:
/// `(n/(n+1)) (1/pi) int_0^pi (1 - amp cos t)_+^(1 + 1/n) dt` (the foundation's
/// force at indentation `c` is `c^(1+1/n) n/(n+1)`), elementary for the cone and
/// complete elliptic integrals for the paraboloid (with `m = 2 amp/(1 + amp)`:
/// `int_0^(pi/2) (1 - m sin^2)^(3/2) = (2(2 - m)E - (1 - m)K)/3`, and for `m > 1`
/// the reciprocal-modulus form `int cos^4 / sqrt(1 - sin^2/m)`). For `amp > 1`
/// the value is divided by `amp^(1 + 1/n)`, as everything in `power_law`.
pub(super) fn total_normal(n: f64, amp: f64) -> Option<f64> {
    let a = amp;
    if n == 1.0 {
        let i = if a <= 1.0 {
            PI * (1.0 + 0.5 * a * a)
        } else {
            // Scaled by 1/amp^2 (see `power_law`).
            let t0 = (1.0 / a).acos();
            let r = PI - t0;
            r / (a * a) + 2.0 * t0.sin() / a + (0.5 * r - 0.25 * (2.0 * t0).sin())
        };
        Some(0.5 * i / PI)
    } else if n == 2.0 {
        let i = if a < 1.0 {
            let (m, m1) = (2.0 * a / (1.0 + a), (1.0 - a) / (1.0 + a));
            let (k, e) = elliptic_ke(m, m1);
            2.0 * (1.0 + a).powf(1.5) * (2.0 * (2.0 - m) * e - m1 * k) / 3.0
        } else if a == 1.0 {
            // (1 + a)^(3/2) = 2^(3/2), and the bracket is 2 E(1) = 2.
            2.0 * 2f64.powf(1.5) * 2.0 / 3.0
        } else {
            // Written without 2a, which overflows for amp above 9e307.
            let (mp, mp1) = (0.5 + 0.5 / a, 0.5 * ((a - 1.0) / a));
            let (k, e) = elliptic_ke(mp, mp1);
            // int_0^(pi/2) cos^4/sqrt(1 - mp sin^2) = ((3mp - 2)(mp - 1) K + (4mp - 2) E)/(3 mp^2).
            let j = ((3.0 * mp - 2.0) * (-mp1) * k + (4.0 * mp - 2.0) * e) / (3.0 * mp * mp);
            // Scaled by 1/amp^(3/2) (see `power_law`).
            2.0 * (1.0 + 1.0 / a).powf(1.5) * j * mp.sqrt()
        };
        Some(2.0 / 3.0 * i / PI)
    } else {
        None
    }
}
