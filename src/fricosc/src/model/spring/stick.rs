//! The stick phase: its end root-found on an analytic bracket, its deficit in closed form.

use super::{accept_of, Velocity, ROOT_RTOL_EVENTS, ROOT_RTOL_MEANS};
use crate::root;
use crate::special::{half_sq_minus_versin as c_fn, half_sq_minus_versin_with, nonneg, x_minus_sin_with};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Where a stick starts (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Start {
    /// On the bound where its slope falls to `vbar`: `tau_s = delta = arcsin vbar`.
    Tangent,
    /// At the contact phase `theta = arccos s`, with zero force.
    Contact {
        /// The contact phase, in `(delta, pi)`.
        theta: f64,
        /// `sin theta`.
        sin_theta: f64,
        /// `cos theta = s`.
        cos_theta: f64,
        /// `alpha + beta = alpha + pi/2 - theta`, the start's distance from
        /// `-alpha` (where sticks vanish), with the best accuracy the caller has.
        eps: f64,
    },
}

/// The solved stick phase.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct StickSolution {
    pub(super) length: f64,
    pub(super) tail: f64,
    pub(super) deficit: f64,
    /// The sum of the magnitudes of the deficit's terms, over `2 pi` (the deficit's
    /// rounding is a few ulps of this).
    pub(super) magnitude: f64,
    /// `sin(tail/2)` and `cos(tail/2)` where the solver had them (a start at contact).
    pub(super) half_tail: Option<(f64, f64)>,
    pub(super) evaluations: u32,
}

/// Below this `vbar` the stick end is solved in the tail `e = x_max - L`
/// ([`stick_phase`]); above it in `L`, whose gap function is cancellation-free
/// as `vbar -> 1` but whose root loses `1e-16 / sqrt(vbar)` to rounding.
pub(super) const TAIL_FORM_VBAR: f64 = 0.5;

/// `2 pi` times the deficit of a stick of length `len` starting at `beta`, and
/// the sum of its terms' magnitudes (the bound of its rounding, in ulps):
/// `C(beta) - C(beta - len) - S(beta) len + w len^2/2`, with `sin beta`, `cos
/// beta` and `c_end = C(beta - len)` from the caller (no further trigonometry:
/// see [`stick_phase`]).
pub(super) fn deficit_2pi(beta: f64, (sin_b, cos_b): (f64, f64), w: f64, len: f64, c_end: f64) -> (f64, f64) {
    let terms =
        [half_sq_minus_versin_with(beta, cos_b), -c_end, -x_minus_sin_with(beta, sin_b) * len, 0.5 * w * len * len];
    (terms.iter().sum(), terms.iter().map(|t| t.abs()).sum())
}

/// Relative accuracy of [`tangent_length_guess`] over `vbar` in (0, 1):
/// `L` within 6.1e-10 on 2,000 velocities against 40-digit roots
/// (`data/scripts/tangent_guess.py`); `L` and the tail within 9.7e-10 on the
/// 1,013 of the test below (the tail `2 pi - L` at `vbar` just above the split);
/// so Halley's first step, below `ROOT_RTOL_MEANS`, is its last for the means
/// (two at `ROOT_RTOL_EVENTS`).
#[cfg(test)]
pub(super) const GUESS_ACCURACY: f64 = 2e-9;

/// `vbar` below which [`tangent_length_guess`] fits the tail `2 pi - L`.
pub(super) const GUESS_SPLIT: f64 = 0.35;
/// `g(t)`, `t = sqrt(vbar)`: the tail `2 pi - L = 2 sqrt(pi vbar) g(t)` for
/// `vbar <= GUESS_SPLIT` (highest power first; `g(0) = 1`, `g''(0)/2 = pi/6`).
pub(super) const GUESS_TAIL: [f64; 11] = [
    0.9565868058961245,
    -2.6570484842786324,
    3.733198796942937,
    -3.3806202452275564,
    2.4310968574811405,
    -1.4604759464633175,
    0.9888273462018545,
    -0.5908060981803004,
    0.52360097067532,
    -6.359491190067821e-08,
    1.0000000002178575,
];
/// `h(x)`, `x = alpha^2`: `L = alpha h(alpha^2)` for `vbar > GUESS_SPLIT`
/// (highest power first; `h(0) = 3`, the slope of `L` as `vbar -> 1`).
pub(super) const GUESS_RATIO: [f64; 11] = [
    9.014702697118404e-05,
    -0.0004904121679360048,
    0.0012668607111425523,
    -0.001745625294078046,
    0.0017203386528347213,
    -0.00041457324621635595,
    0.001781555417550693,
    0.005205381068098373,
    0.020719854721036088,
    0.09999978746358977,
    3.0000000013336545,
];

/// Halley start for the stick length `L` of a tangent start and its tail
/// `2 pi - L`, which depend on `vbar` alone: polynomial fits of degree 10
/// ([`GUESS_TAIL`], [`GUESS_RATIO`], from `data/scripts/tangent_guess.py`),
/// both within `GUESS_ACCURACY` relative (tested; the tail from its own fit
/// where it is small, not as a difference).
pub(super) fn tangent_length_guess(alpha: f64, vbar: f64) -> (f64, f64) {
    let horner = |c: &[f64], x: f64| c.iter().fold(0.0, |acc, &k| acc * x + k);
    if vbar <= GUESS_SPLIT {
        let t = vbar.sqrt();
        let tail = 2.0 * PI.sqrt() * t * horner(&GUESS_TAIL, t);
        (TAU - tail, tail)
    } else {
        let length = alpha * horner(&GUESS_RATIO, alpha * alpha);
        (length, TAU - length)
    }
}

/// Solve the stick phase from `start`: the root of the gap
/// `H(x) = S(beta - x) - S(beta) + w x`, and the deficit.
///
/// The root lies in `[alpha + beta, x_max]`, where `H` falls from its maximum.
/// Halley's method ([`root::halley`]) starts from [`tangent_length_guess`]
/// after a tangent start. After a start at contact it starts, in the tail form,
/// from the root of `H`'s quadratic model (below), and otherwise from the
/// tangent guess scaled by the ratio `L / (alpha + beta)`, which runs from 2
/// (`beta -> -alpha`, where `H ~ eps x - |s| x^2/2`) to the tangent value.
///
/// # The tail form (`vbar <` [`TAIL_FORM_VBAR`])
/// As `vbar -> 0` the root approaches `x_max` and the slope of `H` there falls
/// like `2 sqrt(pi vbar)`, while `H` is a sum of order-one terms: the rounding of
/// those terms moves the root by `1e-16 / sqrt(vbar)`. In the tail
/// `e = x_max - x` the gap is a product of small factors. With the stick end at
/// phase `T - e` (`T = 2 pi + delta` after a tangent start, `T = 2 pi - theta`,
/// the loss of contact, after a start at contact) and `q = -delta` resp.
/// `q = theta`, `B(T - e) - B(tau_s) = cos q - cos(q + e)`, so
/// `H(e) = 2 sin(e/2) sin(q + e/2) - vbar (x_max - e)`, `H'(e) = sin(q + e) + vbar`,
/// and `e` is found with full relative accuracy. `sin q` and `cos q` are known
/// without a sine (`-vbar` and `sqrt(1 - vbar^2)`, resp. `sin theta` and `s`),
/// so an evaluation takes one `sin_cos`, of `e/2`.
pub(super) fn stick_phase(start: Start, vel: &Velocity, rtol: f64) -> StickSolution {
    let (alpha, w, vbar) = (vel.alpha, vel.w, vel.vbar);
    let (beta, x_max) = match start {
        Start::Tangent => (alpha, TAU),
        Start::Contact { theta, .. } => (FRAC_PI_2 - theta, TAU - 2.0 * theta),
    };
    let lo = match start {
        Start::Tangent => alpha + beta,
        Start::Contact { eps, .. } if eps < SHORT_STICK * alpha => return short_stick(eps, vel, rtol),
        Start::Contact { eps, .. } => eps,
    };
    let (_, tail_t) = vel.tangent_guess;
    // sin q and cos q, known without a sine: (-vbar, sqrt(1 - vbar^2)) after
    // a tangent start, (sin theta, s) after a start at contact; and sin beta,
    // cos beta: (cos q, vbar) resp. (cos q, sin q).
    let (sq, cq) = match start {
        Start::Tangent => (-vbar, (w * (1.0 + vbar)).sqrt()),
        Start::Contact { sin_theta, cos_theta, .. } => (sin_theta, cos_theta),
    };
    let beta_sc = (cq, if start == Start::Tangent { vbar } else { sq });
    let (length, tail, evaluations) = if vbar < TAIL_FORM_VBAR {
        // H, H' = sin(q + e) + vbar and H'' = cos(q + e), from one sin_cos: the
        // angle q + e/2 by the addition formulas, whose absolute error is that
        // of its terms (sin(q + e/2) keeps more digits as q + e/2 -> pi than a
        // sine of the rounded sum would).
        let fdd = |e: f64| {
            let (s1, c1) = libm::sincos(0.5 * e);
            let (s2, c2) = (sq * c1 + cq * s1, cq * c1 - sq * s1);
            (2.0 * s1 * s2 - vbar * (x_max - e), s2 * c1 + c2 * s1 + vbar, c2 * c1 - s2 * s1)
        };
        let e_hi = (x_max - lo).max(0.0);
        let tail_guess = match start {
            Start::Tangent => tail_t,
            // The root of H's quadratic model, (cos q / 2) e^2 + (sin q + vbar) e
            // - vbar x_max = 0 (q = theta; relative error 1e-6 at vbar 1e-3, 2e-2
            // at 0.05, 0.2 at 0.49), then one Newton step on its quartic model:
            // 2.0 evaluations a stick-first spring (99 x 99 springs, s in (-1, 1),
            // vbar < 0.5) where the length form's interpolation (up to 9x off in
            // the tail at vbar 1e-3) took 2.9.
            Start::Contact { sin_theta, cos_theta, .. } => {
                let b = sin_theta + vbar;
                let e = 2.0 * vbar * x_max / (b + (b * b + 2.0 * cos_theta * vbar * x_max).max(0.0).sqrt());
                // One Newton step on the quartic model.
                let e2 = e * e;
                let p = sin_theta * e * (1.0 - e2 / 6.0) + cos_theta * e2 * (0.5 - e2 / 24.0) - vbar * (x_max - e);
                let dp = sin_theta * (1.0 - 0.5 * e2) + cos_theta * e * (1.0 - e2 / 6.0) + vbar;
                if dp > 0.0 {
                    e - p / dp
                } else {
                    e
                }
            }
        };
        let e0 = tail_guess.clamp(0.0, e_hi);
        // The acceptance is relative to the tail e; the means need the length
        // L = x_max - e to it relative, so it is scaled by L/e where L is the shorter.
        let accept = accept_of(rtol) * ((x_max - e0) / e0).min(1.0);
        let r = root::halley(fdd, 0.0, e_hi, e0, rtol, accept);
        (x_max - r.x, r.x, r.evaluations)
    } else {
        length_form(beta, beta_sc.0, lo, x_max, start, vel, rtol)
    };
    // After a start at contact the means need sin(e/2) of the tail e anyway
    // (`Velocity::stick_first_means`): from its sin_cos, also cos(beta - L) =
    // -sin(q + e) = -(sin q cos e + cos q sin e) (beta - L = q + e - 3 pi/2),
    // one call for what took up to four (cos(beta - L), sin(e/2), sin e).
    let (c_end, half_tail) = match start {
        Start::Tangent => (c_fn(beta - length), None),
        Start::Contact { .. } => {
            let (h, hc) = libm::sincos(0.5 * tail);
            let cos_end = -(sq * (1.0 - 2.0 * h * h) + cq * (2.0 * h * hc));
            (half_sq_minus_versin_with(beta - length, cos_end), Some((h, hc)))
        }
    };
    let (d, m) = deficit_2pi(beta, beta_sc, w, length, c_end);
    // The deficit is a mean of a non-negative gap; rounding must not flip it.
    StickSolution { length, tail, deficit: nonneg(d / TAU), magnitude: m / TAU, half_tail, evaluations }
}

/// [`stick_phase`]'s root in the length `L` (`vbar >=` [`TAIL_FORM_VBAR`]),
/// in `[lo, x_max]`: `(L, x_max - L, evaluations)`.
pub(super) fn length_form(
    beta: f64,
    sin_beta: f64,
    lo: f64,
    x_max: f64,
    start: Start,
    vel: &Velocity,
    rtol: f64,
) -> (f64, f64, u32) {
    let (alpha, w, vbar) = (vel.alpha, vel.w, vel.vbar);
    let (lt, _) = vel.tangent_guess;
    let guess = if start == Start::Tangent {
        lt
    } else {
        let ratio_t = lt / (2.0 * alpha);
        lo * (2.0 + (ratio_t - 2.0) * lo / (2.0 * alpha))
    };
    let s_beta = x_minus_sin_with(beta, sin_beta);
    // H, H' = cos(beta - x) - vbar and H'' = sin(beta - x) share one sin_cos.
    let fdd = |x: f64| {
        let y = beta - x;
        let (sn, cs) = libm::sincos(y);
        (x_minus_sin_with(y, sn) - s_beta + w * x, cs - vbar, sn)
    };
    let r = root::halley(fdd, lo, x_max, guess, rtol, accept_of(rtol));
    (r.x, x_max - r.x, r.evaluations)
}

/// A stick from contact whose start `beta` lies within this fraction of `alpha`
/// of `-alpha` (where sticks vanish, `s -> -sqrt(1 - vbar^2)`) is solved by
/// [`short_stick`].
pub(super) const SHORT_STICK: f64 = 0.25;
/// [`short_stick`]'s last Halley step for the means, relative to `h` (the
/// deficit evaluated before it is then within `3e-16` relatively).
pub(super) const SHORT_STICK_MEANS_STEP: f64 = 1e-8;
/// Halley steps [`short_stick`] takes before a bracketed search takes over.
pub(super) const SHORT_STICK_MAX_STEPS: u32 = 12;

/// The stick phase of a stick from contact near `beta = -alpha`, with
/// `eps = alpha + beta < SHORT_STICK alpha`, where the stick is short
/// (`L ~ 2 eps`) and its deficit tiny (`~ (2/3) sin(alpha) eps^3 / 2 pi`): the
/// general form sums terms of order `alpha^2` (or 1) and kept only
/// `1e-16 (alpha/eps)^3` of it relatively (relative error 0.3 at
/// `s = -c + 1e-6`, `vbar = 0.3`; 6.6e5 at `s = -c + 1e-8`, `vbar = 0.6`).
///
/// With the stick's half-length `h`, `d = eps - h` and the middle phase
/// `phi = beta - h = d - alpha`, the gap is
/// `H(2h) = sin beta - sin(beta - 2h) - 2 vbar h = 2h G(h)` with
/// `G = cos(phi) sinc(h) - vbar`, written without cancellation as
/// `G = (cos(alpha - d) - cos alpha) - cos(alpha - d) S(h)/h`, where
/// `cos(alpha - d) - cos alpha = c sin d - vbar sin^2 d/(1 + cos d)`
/// (`c = sin alpha`; `d <= eps/24` is small): from the sines and cosines of
/// `h` and `d` alone (those of `d <= eps/2 < pi/16` by their series). The
/// root lies in `[eps/2, eps]` (for `eps < alpha/4`, `G(eps/2) > 0` and
/// `G(eps) < 0`); Halley's method starts from its series
/// `d = t eps^2/6 - t^2 eps^3/18 + (t^3/27 + 7t/360) eps^4` (`t = cot alpha`).
///
/// The deficit `(1/2pi) int_0^L H = (1/2pi) [L sin beta + cos beta -
/// cos(beta - L) - vbar L^2/2]` is, with `vbar` eliminated through
/// `H = 2h G`, `(1/pi) [sin(alpha - d) (sin h - h cos h) + h^2 G(h)]`:
/// products of small factors (`sin h - h cos h = h (1 - cos h) - S(h)`, about
/// `h^3/3`), and still stationary in `h` (an error `e` in `h` moves it by
/// `3 (e/h)^2` relatively): the means stop at a step of `1e-8 h`, event times
/// at [`ROOT_RTOL_EVENTS`]. Only `alpha` and `eps` enter: the deficit is as
/// accurate as `eps` relatively, 3 times over. The magnitude returned (the
/// deficit's rounding is a few ulps of it) is `D (2 + 3 alpha/eps)`, for an
/// `eps` within `1.5 ulp(alpha)` where it is `alpha + beta` rounded.
pub(super) fn short_stick(eps: f64, vel: &Velocity, rtol: f64) -> StickSolution {
    let (alpha, vbar) = (vel.alpha, vel.vbar);
    if eps.is_nan() || eps <= 0.0 {
        // At the end of the sticks to rounding (the regime's sign test said
        // stick-first): a stick of no length, slip for the whole contact of 2 delta.
        let tail = 2.0 * vel.delta;
        return StickSolution { length: 0.0, tail, deficit: 0.0, magnitude: 0.0, half_tail: None, evaluations: 0 };
    }
    let c = (vel.w * (1.0 + vbar)).sqrt();
    // sin h - h cos h = h (1 - cos h) - S(h), about h^3/3 (no cancellation;
    // 1 - cos h = sin^2 h/(1 + cos h), h <= eps < pi/8).
    let third = |h: f64, sh: f64, ch: f64| h * sh * sh / (1.0 + ch) - x_minus_sin_with(h, sh);
    // G, G', G'' (sinc'' = -sinc - 2 sinc'/h; sin phi = -sin(alpha - d)), and
    // the deficit at h (stationary there).
    let eval = |h: f64| {
        let (sh, ch) = libm::sincos(h);
        let d = eps - h;
        let (sd, cd) = crate::special::sin_cos_small(d);
        let (sa, ca) = (c * cd - vbar * sd, vbar * cd + c * sd);
        let t3 = third(h, sh, ch);
        let g = (c * sd - vbar * sd * sd / (1.0 + cd)) - ca * x_minus_sin_with(h, sh) / h;
        let sinc = sh / h;
        let dsinc = -t3 / (h * h);
        let ddsinc = -sinc - 2.0 * dsinc / h;
        let derivs = (-sa * sinc + ca * dsinc, -ca * sinc - 2.0 * sa * dsinc + ca * ddsinc);
        (g, derivs, nonneg((sa * t3 + h * h * g) / PI))
    };
    let step_tol = if rtol == ROOT_RTOL_MEANS { SHORT_STICK_MEANS_STEP } else { rtol };
    let (mut h, mut evaluations) = if vbar == 0.0 {
        // The stick lasts until the contact is lost: G(eps) = 0.
        (eps, 0)
    } else {
        let t = vbar / c;
        let e2 = eps * eps;
        let d = t * e2 / 6.0 - t * t * e2 * eps / 18.0 + (t * t * t / 27.0 + 7.0 * t / 360.0) * e2 * e2;
        ((eps - d).clamp(0.5 * eps, eps), 0)
    };
    let mut deficit;
    loop {
        let (g, (g1, g2), dh) = eval(h);
        evaluations += 1;
        deficit = dh;
        if vbar == 0.0 || g == 0.0 {
            break;
        }
        let newton = g / g1;
        let denom = 1.0 - 0.5 * newton * g2 / g1;
        let step = if (0.5..=2.0).contains(&denom) { newton / denom } else { newton };
        let next = h - step;
        if !(0.5 * eps..=eps).contains(&next) || evaluations >= SHORT_STICK_MAX_STEPS {
            // Not finite, out of the bracket, or too slow: bracketed search, and
            // the deficit at its root.
            let r = root::bracketed(|x| eval(x).0, 0.5 * eps, eps, ROOT_RTOL_EVENTS);
            evaluations += r.evaluations;
            h = r.x;
            deficit = eval(h).2;
            break;
        }
        h = next;
        if step.abs() <= step_tol * h {
            break;
        }
    }
    let d = eps - h;
    // The contact lasts 2 (pi - theta) = 2 (eps + delta): the tail after the
    // stick, 2 (delta + d), is a sum of non-negative terms (0 at vbar = 0).
    // Its half's sine and cosine by the addition formulas, with sin delta =
    // vbar and cos delta = c (no library call: a short stick took four).
    let half = vel.delta + d;
    let (sd, cd) = crate::special::sin_cos_small(d);
    StickSolution {
        length: 2.0 * h,
        tail: 2.0 * half,
        deficit,
        magnitude: deficit * (2.0 + 3.0 * alpha / eps),
        half_tail: Some((vbar * cd + c * sd, c * cd - vbar * sd)),
        evaluations,
    }
}
