//! The algebra of one slip step in the plane (`spring.rs`'s module docs):
//! the half-angle series, the force's quadratics, the slip rate and its
//! series, and what a force on its bound does next.

use super::series::{Series, LEN, ORDER, RECIPROCALS};

/// Whether a spring that regains contact at the rate `beta` (its bound's
/// level `level`) where the body moves at `xd` and accelerates at `xa` slips
/// at once. From `f = 0` a stick's force is `f =
/// X' t + X'' t^2/2 + ...` and its bound `B = beta t + B'' t^2/2 + ...`
/// (`beta = amp sin t_c`, `B'' = amp cos t_c = level`), so
///
/// `B^2 - |f|^2 = (beta^2 - |X'|^2) t^2 + (beta B'' - X'.X'') t^3 + ...`:
///
/// it sticks where the first term is positive; where it ties with `|X'|`
/// to rounding, the second decides (a stick of no length otherwise, whose
/// end no bisection could isolate).
pub(super) fn slips_on_contact(xd: [f64; 2], xa: [f64; 2], beta: f64, level: f64) -> bool {
    let speed = xd[0].hypot(xd[1]);
    if (speed - beta).abs() > 8.0 * f64::EPSILON * beta {
        return speed > beta;
    }
    beta * level < xd[0] * xa[0] + xd[1] * xa[1]
}

/// The half-angle series of a slip from `y0` (`|y0| = 1`), scaled by
/// `e^(-lam t)`: `z = e^(-lam t) y` with `y' = M y` (module docs) has `z' =
/// (M - lam) z`, `(k + 1) z_{k+1} = sum_j M_j z_{k-j} - lam z_k`, each
/// `z_k`'s terms added to the later sums as soon as it is known (rows the
/// compiler vectorises). With `lam` the growth of `|y|` at the start, `z`
/// keeps the size `y` would gain along a stiff slip, and the cancellation
/// that size brings to the force `B (c2, s2)/n`, out of the series.
pub(super) fn regular(b: &Series, xd: &[Series; 2], y0: [f64; 2], lam: f64) -> [Series; 2] {
    let half = *b * 2.0;
    let [ma, mb] = Series::div_pair(xd, &half);
    let (mut y1, mut y2) = (Series::constant(y0[0]), Series::constant(y0[1]));
    let (mut s1, mut s2) = ([0.0; ORDER], [0.0; ORDER]);
    for k in 0..ORDER {
        let (u, v) = (y1.0[k], y2.0[k]);
        for (((t1, t2), &a), &c) in s1[k..].iter_mut().zip(&mut s2[k..]).zip(&ma.0).zip(&mb.0) {
            *t1 += c * v - a * u;
            *t2 += c * u + a * v;
        }
        y1.0[k + 1] = (s1[k] - lam * u) * RECIPROCALS[k];
        y2.0[k + 1] = (s2[k] - lam * v) * RECIPROCALS[k];
    }
    [y1, y2]
}

/// The growth rate of `|y|` at the start of a slip from `y0` (`|y0| = 1`):
/// `y0^T M_0 y0 = (X'_0 . (y2^2 - y1^2, 2 y1 y2)) / (2 B_0)`.
pub(super) fn growth(b: &Series, xd: &[Series; 2], y0: [f64; 2]) -> f64 {
    let (u, v) = (y0[0], y0[1]);
    let lam = (xd[0].0[0] * (v * v - u * u) + xd[1].0[0] * 2.0 * u * v) / (2.0 * b.0[0]);
    if lam.is_finite() {
        lam
    } else {
        0.0
    }
}

/// `n = |y|^2`, `c2 = y2^2 - y1^2`, `s2 = 2 y1 y2`: `e = (c2, s2)/n`; and
/// `d2 = 2 y1^2 = n - c2`, so that `1 - e_x = d2/n` keeps its relative
/// accuracy where the force is nearly along `x` (the reduction's share).
pub(super) fn quadratics(y: &[Series; 2]) -> [Series; 4] {
    let [q0, q1, p] = Series::squares_and_product(y);
    [q0 + q1, q1 - q0, p * 2.0, q0 * 2.0]
}

/// The slip rate `lambda = X'.e - B'` times `n` (of any scale of `y`),
/// `X'_x c2 + X'_y s2 - B' n`, from `X'`, `B'` and [`quadratics`]: its
/// first two coefficients (its value and slope at the start), with the
/// rounding of its constant term, within which a rate is taken as 0: 16
/// ulp of `(|X'_x| + |X'_y| + |B'|) n`, as `c2` and `s2` carry an ulp of `n`
/// each (a direction along an axis has a component of rounding size) and
/// each component of `X'` an ulp of `|X'|` (a drive rotated or composed).
pub(super) fn slip_rate(xd: &[Series; 2], bdot: &Series, [n, c2, s2, _]: &[Series; 4]) -> ([f64; 2], f64) {
    let sizes = (xd[0].0[0].abs() + xd[1].0[0].abs() + bdot.0[0].abs()) * n.0[0];
    let low = |a: &Series, b: &Series| [a.0[0] * b.0[0], a.0[0] * b.0[1] + a.0[1] * b.0[0]];
    let (x, y, z) = (low(&xd[0], c2), low(&xd[1], s2), low(bdot, n));
    ([x[0] + y[0] - z[0], x[1] + y[1] - z[1]], 16.0 * f64::EPSILON * sizes)
}

/// A positive multiple of the slip rate along a slip, `w lambda / n`, from
/// `q = B/n` (`n = |z|^2` of the scaled half-angle series [`regular`] with
/// its `lam`, `w = dtau/dt` of the clock, `q` in the clock's time): as
/// `|y|^2' = 2 y.My = (X'_x c2 + X'_y s2)/B = |y|^2 (lambda + B')/B`,
/// `(B/|y|^2)' = -lambda/|y|^2`, and with `n = e^(-2 lam t) |y|^2`,
/// `2 lam q - q' = w lambda / n`. No product: `q` is the force's own factor.
/// Its last order needs `q`'s next, and is left out.
pub(super) fn rate_series(q: &Series, lam: f64) -> Series {
    let mut r = [0.0; LEN];
    for (k, (rk, w)) in r.iter_mut().zip(q.0.windows(2)).enumerate() {
        *rk = 2.0 * lam * w[0] - (k + 1) as f64 * w[1];
    }
    Series(r)
}

/// The leading zeros of `B^2 - |f|^2` in a stick from a force on its
/// bound: its value, and its slope `-2 B lambda` where the rate `lambda n`
/// is 0 to its rounding `tol` (a touch).
pub(super) fn zeros(rate: f64, tol: f64) -> usize {
    if rate < -tol {
        1
    } else {
        2
    }
}

/// Whether a force on its bound slips, from the slip rate `rate` (within
/// `tol` of 0 where it rides on the bound) and its slope: a rate that is
/// positive, or 0 and rising (a stick would leave the disc at once).
pub(super) fn slips(rate: f64, tol: f64, slope: f64) -> bool {
    rate > tol || (rate >= -tol && slope > 0.0)
}

/// `int_0^t B e_perp (d th/d th_0) dtau` over a slip step from `|y0| = 1`:
/// how the step's force integral moves with the angle it starts at. With
/// `f = B e`, `d f/d th = B e_perp = B (-s2, c2)/n`, and `d th/d th_0 =
/// 1/|y|^2 = e^(-2 lam t)/n` (`n = |z|^2` of [`regular`]'s scaled series,
/// `|y0| = 1`), the integrand is `(-f_y, f_x) e^(-2 lam t)/n`, `f = (f_x,
/// f_y)` in the clock's time as the step books it.
pub(super) fn turning(f: [&Series; 2], n: &Series, lam: f64, t: f64) -> [f64; 2] {
    let mut decay = [0.0; LEN];
    let mut term = 1.0;
    for (k, c) in decay.iter_mut().enumerate() {
        *c = term;
        term *= -2.0 * lam * RECIPROCALS[k];
    }
    let g = Series(decay).div(n);
    let [gy, gx] = g.mul_each([f[1], f[0]]);
    [-gy.integral(t), gx.integral(t)]
}
