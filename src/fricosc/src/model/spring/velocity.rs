//! Velocity-dependent constants and the stick-first springs by stick length.

use super::stick::{stick_phase, tangent_length_guess, Start};
use super::{ROOT_RTOL_EVENTS, ROOT_RTOL_MEANS};
use crate::root;
use crate::special::{x_minus_sin as s_fn, x_minus_sin_with};
use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI, TAU};

/// Velocity-dependent constants shared by all springs of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Velocity {
    /// `vbar` (eq. 3), `< 1`.
    pub vbar: f64,
    /// `w = 1 - vbar`.
    pub w: f64,
    /// `alpha = arccos vbar`; springs with `|arcsin s| < alpha` stick from contact.
    pub alpha: f64,
    /// `delta = arcsin vbar = pi/2 - alpha`, the phase of a tangent start (eq. 4).
    pub delta: f64,
    /// Halley start for the stick length of a tangent start, and for its tail.
    pub(super) tangent_guess: (f64, f64),
}

impl Velocity {
    /// Constants for `0 <= vbar < 1`.
    pub fn new(vbar: f64) -> Self {
        let (w, alpha, delta) = velocity_angles(vbar);
        Velocity { vbar, w, alpha, delta, tangent_guess: tangent_length_guess(alpha, vbar) }
    }

    /// Half the stick length of a tangent start, `L_t/2`, to full precision:
    /// the top of the stick-first band in [`Velocity::stick_first_by_half_length`]
    /// (the spring at `beta = alpha` starts its stick at contact and at the
    /// tangent at once). The library takes it from the spring in permanent
    /// contact, whose stick this is ([`Spring::with_events`] at `s >= 1`: the
    /// same root), so that a point finds it once; the tests call this.
    #[cfg(test)]
    pub(crate) fn tangent_half_length(&self) -> f64 {
        0.5 * stick_phase(Start::Tangent, self, ROOT_RTOL_EVENTS).length
    }

    /// Half the stick length of the stick-first spring whose contact starts
    /// at phase `u` (`|pi/2 - u| < alpha`), to full precision (root-found).
    pub(crate) fn stick_half_length_at(&self, u: f64) -> f64 {
        let (sin_theta, cos_theta) = libm::sincos(u);
        let eps = self.alpha + (FRAC_PI_2 - u);
        let start = Start::Contact { theta: u, sin_theta, cos_theta, eps };
        0.5 * stick_phase(start, self, ROOT_RTOL_EVENTS).length
    }

    /// The branch point of [`Velocity::stick_first_by_half_length`] above the
    /// band: the `h` in `(0, pi)` where `g = vbar h/sin h` reaches 1, i.e.
    /// `w h - S(h) = 0` (in that form: no cancellation as `vbar -> 1`, where
    /// it is `sqrt(6 w)` to leading order). `sin phi` behaves like `sqrt(h_b -
    /// h)` there, so the band is integrated in `tau = sqrt(h_b - h)`.
    pub(crate) fn stick_branch_half_length(&self) -> f64 {
        let (vbar, w) = (self.vbar, self.w);
        let fdd = |h: f64| {
            let (sh, ch) = libm::sincos(h);
            (w * h - x_minus_sin_with(h, sh), ch - vbar, -sh)
        };
        // Within 1.3 % of the root (measured at 999 velocities; the old guesses
        // `pi w` and `sqrt(6 w)` were up to 17 % off; at vbar 0.3, 3 evaluations
        // a call where they took 4): from vbar -> 0, `pi - h_b
        // = k` with `sin k = vbar (pi - k)`, `k ~ vbar pi/(1 + vbar)` corrected
        // once by `k/sin k ~ 1 + k^2/6`; from vbar -> 1, `h_b^2 ~ 6 w (1 +
        // 3w/10)`.
        let guess = if vbar > 0.57 {
            (6.0 * w).sqrt() * (1.0 + 0.15 * w)
        } else {
            let k0 = vbar * PI / (1.0 + vbar);
            PI - vbar * (PI - k0) * (1.0 + k0 * k0 / 6.0)
        };
        // w h - S(h) > 0 just above 0 and = -vbar pi < 0 at pi.
        let lo = 1e-3 * guess.min(1.0);
        root::halley(fdd, lo, PI, guess.clamp(lo, PI), ROOT_RTOL_EVENTS, 0.0).x
    }

    /// The stick-first spring whose stick lasts `L = 2h`, `0 < h <=`
    /// `Velocity::tangent_half_length`, in closed form: no root to find.
    ///
    /// The stick from contact at `beta` ends where the gap `H(x) = sin beta -
    /// sin(beta - x) - vbar x = 2 cos(beta - x/2) sin(x/2) - vbar x` returns to
    /// 0, so a stick of length `2h` starts at `beta = h - phi` with `cos phi =
    /// g = vbar h/sin h` (`phi` in `[0, pi/2]`; `beta = -alpha` at `h = 0`, and
    /// `beta` rises with `h`): the band of springs is swept by `h` explicitly.
    /// With `psi = beta - h = -phi` the deficit `(1/2pi) int_0^L H` is
    /// `(1/2pi) [L sin beta + cos beta - cos(beta - L) - vbar L^2/2]
    /// = sin(phi) (sin h - h cos h)/pi` (using `vbar h = cos(psi) sin h`): a
    /// product of non-negative factors. The tail after the stick is `e =
    /// x_max - L = pi - 2 phi = 2 arcsin g`, so `sin(e/2) = g`, `cos(e/2) =
    /// sin phi`; the contact phase is `u = pi/2 - beta`, with `sin u = cos
    /// beta` and `cos u = sin beta` by the addition formulas; and
    /// `|du/dh| = 1 + vbar (sin h - h cos h)/(sin^2 h sin phi)` (from `dg/dh =
    /// vbar (sin h - h cos h)/sin^2 h`). `1 - g = (w h - S(h))/sin h` keeps
    /// `sin phi`'s digits as `g -> 1`. One `sin_cos`, one square root and one
    /// arcsine.
    pub(crate) fn stick_first_by_half_length(&self, h: f64) -> LengthNode {
        self.stick_first_by_half_length_with(h, true)
    }

    /// [`Velocity::stick_first_by_half_length`], the mean tangential force
    /// only where `tangential` asks for it (else 0: a series of `S(e)` and a
    /// division less, for a caller whose `mu` comes from the deficit).
    pub(crate) fn stick_first_by_half_length_with(&self, h: f64, tangential: bool) -> LengthNode {
        let vbar = self.vbar;
        let (sh, ch) = libm::sincos(h);
        let s_h = x_minus_sin_with(h, sh);
        let t3 = sin_minus_x_cos(h, sh, ch, s_h);
        let g = vbar * h / sh;
        let wh = self.w * h;
        let sin_phi = ((wh - s_h) / sh * (1.0 + g)).sqrt();
        // phi = arccos g and a = arcsin g = pi/2 - phi, the smaller directly.
        let (phi, a) = if g <= FRAC_1_SQRT_2 {
            let a = g.asin();
            (FRAC_PI_2 - a, a)
        } else {
            let phi = sin_phi.asin();
            (phi, FRAC_PI_2 - phi)
        };
        let beta = h - phi;
        let (sin_b, cos_b) = (sh * g - ch * sin_phi, ch * g + sh * sin_phi);
        let deficit = sin_phi * t3 / PI;
        // <F> = (vbar L^2/2 + s S(e) + 2 sin(u) sin^2(e/2))/2pi, e = 2a.
        let e = 2.0 * a;
        let tangential = if tangential {
            (2.0 * vbar * h * h + sin_b * x_minus_sin_with(e, 2.0 * g * sin_phi) + 2.0 * cos_b * g * g) / TAU
        } else {
            0.0
        };
        // Rounding: sin phi carries the cancellation of w h - S(h).
        let magnitude = deficit * (2.0 + (wh + s_h) / (wh - s_h));
        LengthNode {
            beta,
            sin_u: cos_b,
            cos_u: sin_b,
            du_dh: 1.0 + vbar * t3 / (sh * sh * sin_phi),
            means: StickMeans { deficit, tangential, magnitude },
            sin_h: sh,
            g,
            sin_phi,
        }
    }

    /// The top `h*` of a band in the half-length, as
    /// [`Velocity::phase_below_top`] needs it.
    pub(crate) fn length_top(&self, h: f64) -> LengthTop {
        let (sh, ch) = libm::sincos(h);
        let node = self.stick_first_by_half_length(h);
        let t3 = sin_minus_x_cos(h, sh, ch, x_minus_sin_with(h, sh));
        LengthTop { h, cos_h: ch, t3, node }
    }

    /// `u(h* - rho) - u(h*)` of [`Velocity::stick_first_by_half_length`]'s
    /// springs, to full relative accuracy as `rho -> 0` (`node` is the spring
    /// at `h = h* - rho`, `u_top` the phase the band's top stands for).
    ///
    /// With `u = pi/2 - h + phi`, it is `rho + (phi - phi*)`, two non-negative
    /// terms (`g = vbar h/sin h` rises with `h`, so `phi = arccos g` falls).
    /// `sin(phi - phi*) = sin phi g* - g sin phi* = dg (g (g + g*)/(sin phi +
    /// sin phi*) + sin phi)` with `dg = g* - g = vbar N/(sin h sin h*)` and `N
    /// = h* sin h - h sin h* = rho (sin h* - h* cos h*) + h* cos h* S(rho) - 2
    /// h* sin h* sin^2(rho/2)` (from `sin(h* - rho)` by the addition formula,
    /// in `h*` and `rho` alone, so that the top is exactly `rho` away). That
    /// form loses a few digits at most while `rho <= h*/2` (a factor 5 at `h*
    /// -> 0`); beyond, `u - u*` is at least `rho` (`|du/dh| >= 1`) and the
    /// plain difference `(pi/2 - beta) - u_top` keeps its relative accuracy.
    pub(crate) fn phase_below_top(&self, top: &LengthTop, rho: f64, node: &LengthNode, u_top: f64) -> f64 {
        if rho > 0.5 * top.h {
            return (FRAC_PI_2 - node.beta) - u_top;
        }
        // rho <= h*/2 < 2: S(rho) by its series, sin(rho/2) by its own where small.
        let s2 = crate::special::sin_cos_small(0.5 * rho).0;
        let sin_top = top.node.sin_h;
        let n = rho * top.t3 + top.h * top.cos_h * s_fn(rho) - 2.0 * top.h * sin_top * s2 * s2;
        let dg = self.vbar * n.max(0.0) / (node.sin_h * sin_top);
        let (g, gt) = (node.g, top.node.g);
        let sin_diff = dg * (g * (g + gt) / (node.sin_phi + top.node.sin_phi) + node.sin_phi);
        rho + sin_diff.min(1.0).asin()
    }

    /// The means of the stick-first spring whose contact starts at phase
    /// `theta = arccos s` (`beta = pi/2 - theta`, `|beta| < alpha`), given
    /// `sin theta` and `cos theta = s`: the deficit `D`, the mean tangential
    /// force `<F>` with full relative accuracy where it is small (as
    /// [`Spring::mean_tangential`]: `(vbar L^2/2 + s S(e) + 2 sin(theta)
    /// sin^2(e/2))/2pi`), and the magnitude of the terms `D` is summed from (its
    /// rounding is a few ulps of that, not of `D`). Units `mu0 kz du`.
    pub(crate) fn stick_first_means(&self, theta: f64, sin_theta: f64, cos_theta: f64) -> StickMeans {
        // The node's phase u = theta is exact: eps = alpha + pi/2 - theta as
        // accurate as alpha.
        let eps = self.alpha + (FRAC_PI_2 - theta);
        let sol = stick_phase(Start::Contact { theta, sin_theta, cos_theta, eps }, self, ROOT_RTOL_MEANS);
        let (l, e) = (sol.length, sol.tail);
        // sin(e/2) and sin e = 2 sin(e/2) cos(e/2) from the solution's one sin_cos.
        let (h, hc) = sol.half_tail.unwrap_or_else(|| libm::sincos(0.5 * e));
        let tangential =
            (0.5 * self.vbar * l * l + cos_theta * x_minus_sin_with(e, 2.0 * h * hc) + 2.0 * sin_theta * h * h) / TAU;
        StickMeans { deficit: sol.deficit, tangential, magnitude: sol.magnitude }
    }
}

/// A stick-first spring given by its stick's half-length
/// ([`Velocity::stick_first_by_half_length`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LengthNode {
    /// The stick's start `beta`; the contact phase is `u = pi/2 - beta`.
    pub(crate) beta: f64,
    /// `sin u = cos beta` and `cos u = sin beta` (`s`).
    pub(crate) sin_u: f64,
    pub(crate) cos_u: f64,
    /// `|du/dh|`.
    pub(crate) du_dh: f64,
    pub(crate) means: StickMeans,
    /// `sin h`, `g = vbar h/sin h = cos phi` and `sin phi`.
    pub(crate) sin_h: f64,
    pub(crate) g: f64,
    pub(crate) sin_phi: f64,
}

/// `sin h - h cos h` given `sin h`, `cos h` and `S(h) = h - sin h`: `h (1 -
/// cos h) - S(h)` below `pi/2` (about `h^3/3`), a sum of non-negative terms
/// above.
fn sin_minus_x_cos(h: f64, sh: f64, ch: f64, s_h: f64) -> f64 {
    if ch > 0.0 {
        h * sh * sh / (1.0 + ch) - s_h
    } else {
        sh - h * ch
    }
}

/// The top of a band in the stick's half-length ([`Velocity::length_top`]):
/// `h*`, `cos h*`, `sin h* - h* cos h*` and its spring (`sin h*` is the spring's).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LengthTop {
    pub(crate) h: f64,
    cos_h: f64,
    t3: f64,
    pub(crate) node: LengthNode,
}

/// The means of a stick-first spring ([`Velocity::stick_first_means`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct StickMeans {
    pub(crate) deficit: f64,
    pub(crate) tangential: f64,
    pub(crate) magnitude: f64,
}

/// Critical velocity parameters `(w, alpha, delta) = (1 - vbar, arccos vbar,
/// arcsin vbar)` from one arcsine: the smaller angle directly (`delta = arcsin
/// vbar` for `vbar <= 1/sqrt 2`, else `alpha = 2 arcsin(sqrt(w/2))`, accurate as
/// `vbar -> 1`), the other, at least `pi/4`, as `pi/2` minus it with `pi/2` in
/// two parts (each within an ulp of the library's `acos` and `asin`).
pub(super) fn velocity_angles(vbar: f64) -> (f64, f64, f64) {
    // pi/2 - FRAC_PI_2.
    const FRAC_PI_2_LO: f64 = 6.123233995736766e-17;
    let w = 1.0 - vbar;
    if vbar <= FRAC_1_SQRT_2 {
        let delta = vbar.asin();
        (w, (FRAC_PI_2 - delta) + FRAC_PI_2_LO, delta)
    } else {
        let alpha = 2.0 * (0.5 * w).sqrt().asin();
        (w, alpha, (FRAC_PI_2 - alpha) + FRAC_PI_2_LO)
    }
}
