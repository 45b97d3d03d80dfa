//! Curved indenters by the method of dimensionality reduction (seed section 3).
//!
//! The contact is an elastic foundation of independent springs along `x`; with
//! `z = x/x_c` (`x_c` the contact radius at the mean indentation) and an
//! equivalent profile `g(z) = z^n` (normalised so that `g(1) = 1`), the spring
//! at `z` has `s(z) = (1 - z^n)/amp`, and all springs share `vbar`. Then
//! `mu_macro/mu0 = int <F>(s(z)) dz / int <B>(s(z)) dz`, and the reduction is
//! `int D(s(z)) dz / int <B>(s(z)) dz` with the per-spring deficit `D` of [`crate::spring`].
//!
//! # Bands
//! With `c = sqrt(1 - vbar^2)`, the single-spring regime changes at `s = 1`,
//! `s = +-c` and `s = -1`, and only `s > -1`, i.e. `z < (1 + amp)^(1/n)`, ever
//! touches. The bands (clipped to the springs present, `s <= 1/amp`):
//! - permanent contact `s >= 1`: normal force in closed form, deficit `D(vbar)`
//!   per spring, so its share is `D(vbar)` times the band length;
//! - slip first `c <= s < 1`: the same constant deficit, normal force by quadrature;
//! - stick first `|s| < c`: both by quadrature;
//! - slip only `-1 < s <= -c`: no deficit, normal force by quadrature.
//!
//! # Quadrature
//! The jumping springs are integrated in the angle `beta = arcsin s` in
//! `(-pi/2, pi/2)`: the per-spring means are analytic in `beta` (the square-root
//! behaviour of `<B>` at the contact-loss thresholds `s = +-1` disappears, and the
//! band edges `s = +-c` are `beta = +-arccos vbar`). The Jacobian is
//! `dz = (amp/n) y^(1/n - 1) cos(beta) dbeta` with `y = z^n = 1 - amp sin(beta)`,
//! singular only where `y = 0`, the centre of the contact:
//! - `amp > 1`: at `beta* = arcsin(1/amp)`, the top of the innermost band, like
//!   `(beta* - beta)^(1/n - 1)`: Gauss-Jacobi with that weight;
//! - `amp = 1`: at `pi/2`, like `(pi/2 - beta)^(2/n - 1)`: Gauss-Jacobi;
//! - `amp < 1`: off the real axis at `pi/2 +- i arccosh(1/amp)`.
//!
//! A band whose top is closer to that singularity than half its width (`amp`
//! near 1, or `amp c` near 1) is split geometrically towards its top, so that
//! every piece is at least its own width away from it (Gauss converges
//! geometrically on each). `y` is always evaluated in a cancellation-free form.
//! Each piece is integrated at orders 4, 8, 16, ...: it is accepted when the
//! difference of the first two orders is within the relative tolerance (that
//! difference is then the error estimate), or later when the error of the last
//! order predicted by geometric convergence from the last three, `100 d^3/d'^2`
//! (`d`, `d'` the last two differences, capped at `d`), is; the estimates of the
//! pieces add up to the reported one.

use crate::quad;
use crate::ratio::Ratio;
use crate::shape::DEFAULT_TOL;
use crate::spring::{mean_normal_sin_cos, Spring, Velocity};
use std::f64::consts::{FRAC_PI_2, PI};

/// Highest Gauss order tried per piece.
pub(crate) const MAX_ORDER: usize = 256;
/// First order tried per piece at the default tolerance; a tolerance of
/// `LOOSE_TOL` or looser starts at 2.
pub(crate) const MIN_ORDER: usize = 4;
/// Tolerances at or above this start the order ladder at 2.
pub(crate) const LOOSE_TOL: f64 = 1e-9;
/// Lowest Gauss order whose error is predicted by extrapolation: below it the
/// orders are pre-asymptotic (a 2-4-8 ladder was seen to predict 5e-11 for an
/// error of 1e-7), so the plain difference of the last two orders is both the
/// criterion and the estimate.
const PREDICT_MIN_ORDER: usize = 16;
/// Safety factor on the error predicted from geometric convergence
/// (`d^3/d'^2`, `d` and `d'` the last two differences): two decimal digits
/// for a convergence rate that is not yet constant.
const PREDICT_SAFETY: f64 = 100.0;
/// Above this `amp cos u`, `1/amp - cos u` (scaled `y`) loses more than one bit
/// to cancellation, and the product form `2 sin((u + u*)/2) sin((u - u*)/2)` is used.
const Y_PRODUCT_FORM: f64 = 0.5;
/// A singularity of the stick-first means closer to a band end than this
/// fraction of the band's width is graded.
const GRADE_RATIO: f64 = 0.0625;
/// The Jacobian's branch point is graded until this fraction of the width.
const JACOBIAN_GRADE_RATIO: f64 = 0.25;
/// Most pieces one band is split into (half from each end).
const MAX_PIECES: usize = 100;

/// The regime of a band of springs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BandKind {
    /// `s >= 1`: springs never lose contact.
    PermanentContact,
    /// `sqrt(1 - vbar^2) <= s < 1`: contact lost; slip before the stick.
    SlipFirst,
    /// `|s| < sqrt(1 - vbar^2)`: stick from the moment of contact.
    StickFirst,
    /// `-1 < s <= -sqrt(1 - vbar^2)` (or any `|s| < 1` when `vbar >= 1`): no stick.
    SlipOnly,
}

/// One band: its extent and its share of the mean forces.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Band {
    /// Regime of the springs in the band.
    pub kind: BandKind,
    /// Extent in `x / x_c` (from the centre outwards).
    pub x_range: [f64; 2],
    /// Fraction of the mean normal force carried by the band.
    pub normal_share: f64,
    /// Fraction of the mean tangential force carried by the band.
    pub tangential_share: f64,
    /// Quadrature nodes spent on the band (0: closed form).
    pub nodes: usize,
}

/// Result of an MDR evaluation.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MdrResult {
    /// Ratio and reduction.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub ratio: Ratio,
    /// Estimated absolute error of `mu_ratio` (an upper bound in all tests).
    pub error_estimate: f64,
    /// Mean normal force of the whole contact over a period, units `E* x_c u0`
    /// (`x_c` the contact radius at the mean indentation `u0`; both sides of the
    /// MDR foundation, whose forces equal the 3D ones: Hertz is `4/3` at `amp = 0`).
    /// Absent when nothing needed it (`vbar >= 1` without bands, no closed form).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub mean_normal: Option<f64>,
    /// The bands, from the centre outwards (empty ones left out; none when the
    /// contact's extent `amp^(1/n)` in `x/x_c` overflows double precision).
    pub bands: Vec<Band>,
    /// Springs (quadrature nodes) evaluated in all.
    pub nodes: usize,
}

/// Integrals `(int amp <B> dz, int amp D dz)` with error estimates and node count.
#[derive(Debug, Clone, Copy, Default)]
struct Sums {
    normal: f64,
    deficit: f64,
    err_normal: f64,
    err_deficit: f64,
    nodes: usize,
}

impl std::ops::AddAssign for Sums {
    fn add_assign(&mut self, o: Sums) {
        self.normal += o.normal;
        self.deficit += o.deficit;
        self.err_normal += o.err_normal;
        self.err_deficit += o.err_deficit;
        self.nodes += o.nodes;
    }
}

/// How the Jacobian behaves at the top of a piece.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Top {
    /// Analytic at the top.
    Regular,
    /// `amp > 1`, top at `beta*`: weight `(beta* - beta)^(1/n - 1)`.
    Centre,
    /// `amp = 1`, top at `pi/2`: weight `(pi/2 - beta)^(2/n - 1)`.
    CentreCritical,
}

struct Foundation {
    n: f64,
    amp: f64,
    /// `1/n - 1`, the exponent of `y` in the Jacobian.
    gamma: f64,
    /// `u* = pi/2 - arcsin(1/amp)` for `amp > 1` (where `y = 0`), else 0.
    u_star: f64,
    /// Velocity constants when `vbar < 1`.
    vel: Option<Velocity>,
    tol: f64,
}

/// Nodes are placed in `u = pi/2 - beta`, the angular distance from the
/// contact centre's threshold `s = 1`: near the centre (`amp` near 1, or
/// `vbar` near 0) the distances that matter are tiny, and `u` resolves them
/// where `beta` near `pi/2` would round them away (`cos` of an angle near
/// `pi/2` keeps only the absolute accuracy of the angle).
impl Foundation {
    /// The foundation of `g = z^n` at amplitude `amp`: `u* = pi/2 - arcsin(1/amp)`
    /// for `amp > 1` (where `y = 0`), else 0.
    fn new(n: f64, amp: f64, vel: Option<Velocity>, tol: f64) -> Self {
        let u_star = if amp > 1.0 { 2.0 * (0.5 * (amp - 1.0) / amp).sqrt().asin() } else { 0.0 };
        Foundation { n, amp, gamma: 1.0 / n - 1.0, u_star, vel, tol }
    }

    /// How the Jacobian behaves at `u*`, the top of the innermost band.
    fn top_kind(&self) -> Top {
        if self.amp > 1.0 {
            Top::Centre
        } else if self.amp == 1.0 {
            Top::CentreCritical
        } else {
            Top::Regular
        }
    }

    /// `y = 1 - amp sin(beta) = 1 - amp cos(u)` without cancellation; for
    /// `amp > 1` scaled by `1/amp`: `cos(u*) - cos(u) = 2 sin((u + u*)/2) sin((u - u*)/2)`.
    fn y(&self, u: f64) -> f64 {
        if self.amp > 1.0 {
            2.0 * (0.5 * (u + self.u_star)).sin() * (0.5 * (u - self.u_star)).sin()
        } else {
            let h = (0.5 * u).sin();
            (1.0 - self.amp) + 2.0 * self.amp * h * h
        }
    }

    /// [`Contact::y`] given `sin(u)`, `cos(u)` (no further trigonometry where it
    /// does not cancel): `amp <= 1`: `1 - cos u = sin^2 u / (1 + cos u)`;
    /// `amp > 1` away from `u*`: `1/amp - cos u`.
    fn y_sc(&self, u: f64, sin_u: f64, cos_u: f64) -> f64 {
        if self.amp <= 1.0 {
            let one_minus_c = if cos_u > 0.0 { sin_u * sin_u / (1.0 + cos_u) } else { 1.0 - cos_u };
            (1.0 - self.amp) + self.amp * one_minus_c
        } else if self.amp * cos_u > Y_PRODUCT_FORM {
            self.y(u)
        } else {
            1.0 / self.amp - cos_u
        }
    }

    /// `y^gamma`, with the common exponents without `powf`.
    fn y_pow(&self, y: f64) -> f64 {
        if self.gamma == 0.0 {
            1.0
        } else if self.gamma == -0.5 {
            1.0 / y.sqrt()
        } else {
            y.powf(self.gamma)
        }
    }

    /// The Jacobian `|dz/du| = (amp/n) y^gamma sin(u)` (for `amp > 1` in scaled
    /// units, see `power_law`), divided by the weight of `top`; `d` is the
    /// distance of `u` from the top of the piece.
    fn jacobian(&self, u: f64, sin_u: f64, cos_u: f64, d: f64, top: Top) -> f64 {
        let k = if self.amp > 1.0 { 1.0 / self.n } else { self.amp / self.n };
        match top {
            Top::Regular => k * self.y_pow(self.y_sc(u, sin_u, cos_u)) * sin_u,
            Top::Centre => {
                // Top at u*: y / d = 2 sin((u + u*)/2) sin(d/2)/d.
                let ratio = 2.0 * (0.5 * (u + self.u_star)).sin() * (0.5 * d).sin() / d;
                k * ratio.powf(self.gamma) * sin_u
            }
            Top::CentreCritical => {
                // amp = 1, top at u = 0 (u = d): y/u^2 = 2 (sin(u/2)/u)^2, sin(u)/u.
                let q = (0.5 * d).sin() / d;
                k * (2.0 * q * q).powf(self.gamma) * (d.sin() / d)
            }
        }
    }

    /// Exponent of the weight `(u - top)^e` of `top`.
    fn weight_exponent(&self, top: Top) -> f64 {
        match top {
            Top::Regular => 0.0,
            Top::Centre => self.gamma,
            Top::CentreCritical => 2.0 * self.gamma + 1.0,
        }
    }

    /// Order-`m` Gauss(-Jacobi) sums `(int amp <B> dz, int amp D dz)` over
    /// `u` in `[top, bottom]` with the weight of `kind` at the top. (Starting
    /// Newton from the neighbouring node's stick length was tried: it costs 10 %
    /// more instructions than the fitted guess, the nodes of a low order being
    /// far apart.)
    fn pass(&self, top: f64, bottom: f64, kind: Top, stick: bool, m: usize) -> (f64, f64) {
        let e = self.weight_exponent(kind);
        let r = quad::rule(m, e);
        let h = 0.5 * (bottom - top);
        let (mut sn, mut sd) = (0.0, 0.0);
        for (&x, &w) in r.nodes.iter().zip(&r.weights) {
            // x = -1 at the top.
            let d = h * (1.0 + x);
            let u = top + d;
            let beta = FRAC_PI_2 - u;
            let (su, cu) = u.sin_cos();
            let jac = w * self.jacobian(u, su, cu, d, kind);
            // sin(beta) = cos(u), cos(beta) = sin(u).
            let b = mean_normal_sin_cos(beta, cu, su);
            let dd = match (stick, &self.vel) {
                (true, Some(vel)) => vel.stick_first_deficit(u),
                _ => 0.0,
            };
            sn += jac * b;
            sd += jac * dd;
        }
        let width = if e == 0.0 { h } else { h.powf(e + 1.0) };
        let scale = if self.amp > 1.0 { width } else { self.amp * width };
        (scale * sn, scale * sd)
    }

    /// One piece at increasing orders, until the predicted error is within the
    /// tolerance relative to the piece plus `scale` (the band's sums so far).
    fn piece(&self, top: f64, bottom: f64, kind: Top, stick: bool, scale: (f64, f64)) -> Sums {
        let mut m = if self.tol >= LOOSE_TOL { 2 } else { MIN_ORDER };
        let q0 = self.pass(top, bottom, kind, stick, m);
        let q1 = self.pass(top, bottom, kind, stick, 2 * m);
        let mut nodes = 3 * m;
        let (mut prev_d, mut cur) = (((q1.0 - q0.0).abs(), (q1.1 - q0.1).abs()), q1);
        let within = |en: f64, ed: f64, q: (f64, f64)| {
            en <= self.tol * (q.0.abs() + scale.0) && ed <= self.tol * (q.1.abs() + scale.1)
        };
        // At least three orders: two that agree by accident prove nothing.
        loop {
            m *= 2;
            let next = self.pass(top, bottom, kind, stick, 2 * m);
            nodes += 2 * m;
            let d = ((next.0 - cur.0).abs(), (next.1 - cur.1).abs());
            // Geometric convergence e_k = C r^k: the error of `next` is d^3 / d_prev^2
            // (times a safety factor 100), once the orders are asymptotic.
            let predict = |dc: f64, dp: f64| {
                if 2 * m < PREDICT_MIN_ORDER {
                    dc
                } else if dc == 0.0 {
                    0.0
                } else if dc < dp {
                    (PREDICT_SAFETY * dc * dc * dc / (dp * dp)).min(dc)
                } else {
                    dc
                }
            };
            let (en, ed) = (predict(d.0, prev_d.0), predict(d.1, prev_d.1));
            cur = next;
            if within(en, ed, cur) {
                return Sums { normal: cur.0, deficit: cur.1, err_normal: en, err_deficit: ed, nodes };
            }
            if 2 * m >= MAX_ORDER {
                // Not converged: report the plain last difference, not a prediction.
                return Sums {
                    normal: cur.0,
                    deficit: cur.1,
                    err_normal: d.0.max(en),
                    err_deficit: d.1.max(ed),
                    nodes,
                };
            }
            prev_d = d;
        }
    }

    /// Distance from a band's top `top` (in `u`) to the nearest singularity of
    /// the Jacobian above it (`inf` if none).
    fn singular_distance(&self, top: f64, kind: Top) -> f64 {
        // gamma = 0 (cone): no singularity; amp = 1 with gamma = -1/2 (paraboloid):
        // y^(-1/2) sin(u) = sqrt(2) cos(u/2) is analytic at u = 0.
        if self.gamma == 0.0 || (self.amp == 1.0 && self.gamma == -0.5) {
            return f64::INFINITY;
        }
        match kind {
            // The other zero of y, at u = -u*.
            Top::Centre => 2.0 * self.u_star,
            Top::CentreCritical => f64::INFINITY,
            Top::Regular if self.amp >= 1.0 => top - self.u_star,
            Top::Regular => top.hypot((1.0 / self.amp).acosh()),
        }
    }

    /// Integrate the band `u` in `[top, bottom]`, split geometrically towards
    /// close singularities: one `near.0` (or the Jacobian's) above the top and
    /// one `near.1` below the bottom. Cuts at `top + d 2^k` and `bottom - d 2^k`
    /// keep every piece at least its own width away from both.
    fn band(&self, top: f64, bottom: f64, kind: Top, stick: bool, near: (f64, f64), scale: (f64, f64)) -> Sums {
        let mut total = Sums::default();
        // An empty band, or one whose half-width underflows to 0 (vbar = 5e-324
        // makes a band [0, 5e-324]): its share is below anything representable.
        if bottom <= top || 0.5 * (bottom - top) == 0.0 {
            return total;
        }
        let width = bottom - top;
        let floor = width * 2f64.powi(-(MAX_PIECES as i32 / 2 - 2));
        let mut cuts = vec![top, bottom];
        // The Jacobian's branch point (y = 0, a power singularity) is graded
        // until every piece is at least half its width away from it; the milder
        // singularities of the stick-first means' continuation only until a
        // sixteenth of the width (Gauss copes beyond). Gradings stay within a
        // half resp. a sixteenth of the width from their end, so they never cross
        // from opposite ends.
        let jac = self.singular_distance(top, kind).max(floor);
        for (start, ratio, sign, from) in [
            (jac, JACOBIAN_GRADE_RATIO, 1.0, top),
            (near.0.max(floor), GRADE_RATIO, 1.0, top),
            (near.1.max(floor), GRADE_RATIO, -1.0, bottom),
        ] {
            let mut d = start;
            while d < ratio * width {
                cuts.push(from + sign * d);
                d *= 2.0;
            }
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        // Widest pieces first: their sum sets the absolute scale that the tiny
        // pieces near a singularity need only match (a relative tolerance on a
        // piece worth 1e-17 of the band would chase rounding noise).
        let mut pieces: Vec<(f64, f64)> = cuts.windows(2).map(|w| (w[0], w[1])).collect();
        pieces.sort_by(|a, b| (b.1 - b.0).total_cmp(&(a.1 - a.0)));
        for (a, b) in pieces {
            let k = if a == top { kind } else { Top::Regular };
            let pc = self.piece(a, b, k, stick, (scale.0 + total.normal.abs(), scale.1 + total.deficit.abs()));
            total += pc;
        }
        total
    }
}

/// Complete elliptic integrals `(K(m), E(m))` by the arithmetic-geometric mean,
/// given the parameter `m` in `[0, 1)` and its complement `m1 = 1 - m` (passed
/// separately so that `m -> 1` keeps its accuracy).
fn elliptic_ke(m: f64, m1: f64) -> (f64, f64) {
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
fn total_normal(n: f64, amp: f64) -> Option<f64> {
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

/// `mu_macro/mu0` of the power-law profile `g = z^n` at `(vbar, amp)`.
///
/// ```
/// // The cone (n = 1) at vbar = 0.3, du/u0 = 0.5.
/// let r = fricosc::mdr::power_law(1.0, 0.3, 0.5, &fricosc::Options::default())?;
/// assert!((r.ratio.mu_ratio - 0.6635626779221783).abs() < 1e-14);
/// assert!(r.error_estimate < 1e-14);
/// # Ok::<(), fricosc::Error>(())
/// ```
///
/// # Errors
/// [`crate::Error::InvalidParameter`] for a negative or non-finite `vbar` or
/// `amp`, `n` outside [[`crate::MIN_EXPONENT`], [`crate::MAX_EXPONENT`]], or bad
/// options; [`crate::Error::Internal`] for a bug.
pub fn power_law(n: f64, vbar: f64, amp: f64, opts: &crate::Options) -> crate::Result<MdrResult> {
    check(n, vbar, amp, opts)?;
    solve(n, vbar, amp, opts.tol, Report::Ratio)
}

/// Check the inputs of [`power_law`] and [`point`].
fn check(n: f64, vbar: f64, amp: f64, opts: &crate::Options) -> crate::Result<()> {
    if !(crate::MIN_EXPONENT..=crate::MAX_EXPONENT).contains(&n) {
        return Err(crate::Error::param("n", n, "the exponent must be within [0.05, 1e6]"));
    }
    crate::error::check_nonneg("vbar", vbar)?;
    crate::error::check_nonneg("amp", amp)?;
    opts.check()
}

/// What [`solve`] reports besides the ratio.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Report {
    /// The ratio and its error estimate only (the normal force from its closed
    /// form where one exists).
    Ratio,
    /// Also the bands (every band's normal force by quadrature).
    Bands,
}

/// [`power_law`] on checked inputs: `n > 0`, `vbar, amp` finite and `>= 0`,
/// `tol` the relative quadrature tolerance. All integrals are scaled by `amp`
/// (units `kz u0` rather than `kz du`), so that `amp -> 0` stays finite.
pub(crate) fn solve(n: f64, vbar: f64, amp: f64, tol: f64, report: Report) -> crate::Result<MdrResult> {
    let bands = report == Report::Bands;
    let tol = tol.max(DEFAULT_TOL);
    // For amp > 1 every integral is computed divided by amp^(1 + 1/n) (in
    // `y/amp`), so that huge amplitudes and small exponents cannot overflow; the
    // ratio is unaffected, and the reported normal force is scaled back.
    let big = amp > 1.0;
    let unscale = |x: f64| if big { x * amp.powf(1.0 + 1.0 / n) } else { x };
    // Both sides of the foundation (z < 0 mirrors z > 0): twice the half-line integral.
    let unit = |half: Option<f64>| MdrResult {
        ratio: Ratio { mu_ratio: 1.0, reduction: 0.0 },
        error_estimate: 0.0,
        mean_normal: half.map(|x| 2.0 * x),
        bands: vec![],
        nodes: 0,
    };
    if amp == 0.0 {
        return Ok(unit(Some(foundation_force(n, 1.0))));
    }
    if vbar >= 1.0 && !bands {
        return Ok(unit(total_normal(n, amp).map(unscale).filter(|x| x.is_finite())));
    }
    let vel = (vbar < 1.0).then(|| Velocity::new(vbar));
    let alpha = vel.map_or(0.0, |v| v.alpha);
    // In u = pi/2 - beta: the centre threshold y = 0 at u* (amp > 1), the
    // stick-first band's upper edge beta = alpha at u_alpha = arcsin(vbar).
    let u_alpha = if vel.is_some() { vbar.asin() } else { FRAC_PI_2 };
    let contact = Foundation::new(n, amp, vel, tol);
    let (u_star, top_kind) = (contact.u_star, contact.top_kind());
    let top_of = |u: f64| if u == u_star { top_kind } else { Top::Regular };
    let d_perm = vel.map_or(0.0, |_| Spring::new(f64::MAX, vbar).deficit);
    let z_of_s = |s: f64| (1.0 - amp * s).clamp(0.0, 1.0 + amp).powf(1.0 / n);
    // Band edges from u: y(u) is cancellation-free where 1 - amp sqrt(1 - vbar^2) is not.
    let z_scale = if big { amp.powf(1.0 / n) } else { 1.0 };
    let z_of_u = |u: f64| z_scale * contact.y(u).max(0.0).powf(1.0 / n);

    // Permanent contact (amp < 1): int_0^{z1} amp s dz = z1 - z1^(n+1)/(n+1).
    let z1 = z_of_s(1.0);
    let perm = Sums { normal: z1 - z1 * z1.powf(n) / (n + 1.0), deficit: d_perm * (amp * z1), ..Default::default() };
    // The stick-first band is u in [u_sf, pi/2 + alpha], u_sf = max(u_alpha, u*);
    // slip first is [u*, u_sf]; slip only [pi/2 + alpha, pi].
    let u_sf = u_alpha.max(u_star);
    // Clipped to the springs present: at vbar >= 1 (alpha = 0) and a huge amp,
    // u* rounds to just above pi/2, and no band may start before the centre.
    let u_low = (FRAC_PI_2 + alpha).max(u_star);
    let inf = f64::INFINITY;
    // The largest parts first: their sums are the absolute scale for the thin bands.
    // The stick-first means, continued beyond the band, are singular at s = +-1
    // (u = 0 and u = pi): u_sf above the band, arcsin(vbar) below it. At
    // vbar = 0 they are the mean normal force itself (everything sticks):
    // analytic, nothing to grade for.
    let near = if vbar == 0.0 { (inf, inf) } else { (u_sf, u_alpha) };
    let scale0 = (perm.normal, perm.deficit);
    let stick_first = contact.band(u_sf, u_low, top_of(u_sf), vel.is_some(), near, scale0);
    let scale1 = (scale0.0 + stick_first.normal, scale0.1 + stick_first.deficit);
    // Without the band report, a closed-form total normal force (cone, paraboloid)
    // makes the normal force of the two slip bands unnecessary: only the stick
    // band needs springs solved.
    let closed = if bands { None } else { total_normal(n, amp) };
    // Slip first: its deficit is D(vbar) per spring.
    let mut slip_first = match closed {
        Some(_) => Sums::default(),
        None => contact.band(u_star, u_sf, top_of(u_star), false, (inf, inf), scale1),
    };
    slip_first.deficit =
        if big { d_perm * contact.y(u_sf).max(0.0).powf(1.0 / n) } else { amp * d_perm * (z_of_u(u_sf) - z1) };
    let scale2 = (scale1.0 + slip_first.normal, scale1.1 + slip_first.deficit);
    let slip_only = match closed {
        Some(_) => Sums::default(),
        None => contact.band(u_low, PI, top_of(u_low), false, (inf, inf), scale2),
    };

    let first_kind = if vel.is_some() { BandKind::SlipFirst } else { BandKind::SlipOnly };
    let parts = [
        (BandKind::PermanentContact, [0.0, z1], perm),
        (first_kind, [z1, z_of_u(u_sf)], slip_first),
        (BandKind::StickFirst, [z_of_u(u_sf), z_of_u(u_low)], stick_first),
        (BandKind::SlipOnly, [z_of_u(u_low), (1.0 + amp).powf(1.0 / n)], slip_only),
    ];
    let mut total = Sums::default();
    for p in &parts {
        total += p.2;
    }
    if let Some(nc) = closed {
        // The closed form replaces the quadrature of the normal force (and its error).
        total.normal = nc;
        total.err_normal = 0.0;
    }
    let (nn, dd) = (total.normal, total.deficit);
    // Truncation (the pieces' estimates, propagated through dd/nn) plus rounding.
    let reduction = if nn > 0.0 { dd / nn } else { 0.0 };
    let rounding = crate::ratio::rounding_estimate(reduction, total.nodes);
    let truncation = crate::ratio::quotient_error(nn, dd, total.err_normal, total.err_deficit);
    let error_estimate = truncation + rounding;
    let ratio = Ratio::from_deficit_within(dd, nn, error_estimate, "power-law contact")?;
    let tangential = nn - dd;
    let band_list = if bands {
        parts
            .iter()
            .filter(|p| p.1[1] > p.1[0])
            .map(|&(kind, x_range, s)| Band {
                kind,
                x_range,
                normal_share: if nn > 0.0 { s.normal / nn } else { 0.0 },
                tangential_share: if tangential > 0.0 { (s.normal - s.deficit) / tangential } else { 0.0 },
                nodes: s.nodes,
            })
            .collect()
    } else {
        vec![]
    };
    let mean_normal = Some(2.0 * unscale(nn)).filter(|x| x.is_finite());
    // At vbar = 0 a small mu_ratio comes from its closed form (the minimum
    // normal force over the mean: exactly 0 when the body jumps) instead of
    // 1 - reduction, which is only absolutely accurate (4e-16 at amp >= 1);
    // the reduction, above 0.5 there, is then 1 - mu to rounding.
    let ratio = if vbar == 0.0 && ratio.mu_ratio < 0.5 {
        let mu = mu_static_ratio(n, amp, tol);
        Ratio { mu_ratio: mu, reduction: 1.0 - mu }
    } else {
        ratio
    };
    Ok(MdrResult { ratio, error_estimate, mean_normal, bands: band_list, nodes: total.nodes })
}

/// A full MDR point: the result plus the static limit, for `fricosc point`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MdrPoint {
    /// Dimensionless velocity (eq. 3).
    pub vbar: f64,
    /// Amplitude `du/u0`.
    pub amp: f64,
    /// Result at `(vbar, amp)` with bands.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub result: MdrResult,
    /// `mu_static/mu0`, the limit `vbar -> 0+`: minimum over mean normal force.
    pub mu_static_ratio: f64,
}

/// Mean normal force of the whole contact over a period (both sides of the
/// foundation), units `E* x_c u0`; `None` where it overflows f64.
///
/// It does not depend on `vbar`: the closed form for the cone and the
/// paraboloid, otherwise the band quadrature of the normal force alone (the
/// solver asked at `vbar = 1`, where no spring sticks and no deficit is computed).
/// The one place the contact's mean normal force is obtained.
pub(crate) fn mean_normal_force(n: f64, amp: f64, tol: f64) -> crate::Result<Option<f64>> {
    crate::error::check_nonneg("amp", amp)?;
    if amp == 0.0 {
        return Ok(Some(2.0 * foundation_force(n, 1.0)));
    }
    match total_normal(n, amp) {
        // total_normal is scaled by amp^(1 + 1/n) for amp > 1 (see power_law).
        Some(half) => {
            let scale = if amp > 1.0 { amp.powf(1.0 + 1.0 / n) } else { 1.0 };
            Ok(Some(2.0 * half * scale).filter(|x| x.is_finite()))
        }
        None => Ok(solve(n, 1.0, amp, tol, Report::Bands)?.mean_normal),
    }
}

/// `mu_static/mu0`, the limit `vbar -> 0+`: every jumping spring sticks from
/// contact to loss of contact (losing all its friction) and every permanent one
/// loses `D(0) = 1`, so what remains is the minimum normal force over its mean,
/// `int_0^{z1} (1 - amp - z^n) dz / N = (n/(n+1)) (1 - amp)_+^(1 + 1/n) / N`
/// (the seed's section 4). `tests/mdr.rs` checks it against `power_law` at `vbar = 0`.
pub(crate) fn mu_static_ratio(n: f64, amp: f64, tol: f64) -> f64 {
    if amp == 0.0 {
        return 1.0;
    }
    if amp >= 1.0 {
        return 0.0;
    }
    // Both sides of the foundation: the minimum force is twice one side's.
    let nn = mean_normal_force(n, amp, tol).ok().flatten().unwrap_or(f64::NAN);
    (2.0 * foundation_force(n, 1.0 - amp) / nn).min(1.0)
}

/// [`power_law`] with the bands and the static limit.
///
/// ```
/// // The cone (n = 1) at vbar = 0.3, du/u0 = 0.5: its bands carry the whole force.
/// let p = fricosc::mdr::point(1.0, 0.3, 0.5, &fricosc::Options::default())?;
/// let shares: f64 = p.result.bands.iter().map(|b| b.normal_share).sum();
/// assert!((shares - 1.0).abs() < 1e-14);
/// # Ok::<(), fricosc::Error>(())
/// ```
///
/// # Errors
/// As [`power_law`].
pub fn point(n: f64, vbar: f64, amp: f64, opts: &crate::Options) -> crate::Result<MdrPoint> {
    check(n, vbar, amp, opts)?;
    let tol = opts.tol;
    // mu_ratio and its estimate from the same call as every other command (one
    // value per input); the bands, normal force and node count from the banded run.
    let plain = solve(n, vbar, amp, tol, Report::Ratio)?;
    let mut result = solve(n, vbar, amp, tol, Report::Bands)?;
    result.ratio = plain.ratio;
    result.error_estimate = plain.error_estimate;
    let mu_static_ratio = mu_static_ratio(n, amp, tol);
    Ok(MdrPoint { vbar, amp, result, mu_static_ratio })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_form_normal_force_equals_the_band_quadrature() {
        for n in [1.0, 2.0] {
            for a in [1e-6, 0.1, 0.5, 0.9, 0.999999, 1.0, 1.000001, 1.5, 3.0, 10.0, 1e4] {
                let closed = total_normal(n, a).unwrap();
                let r = solve(n, 0.3, a, DEFAULT_TOL, Report::Bands).unwrap();
                let shares: f64 = r.bands.iter().map(|b| b.normal_share).sum();
                assert!((shares - 1.0).abs() < 1e-14);
                // The quadrature's total, rebuilt from the bands of the report.
                let quad_total = {
                    let c = Foundation::new(n, a, None, DEFAULT_TOL);
                    let (u_star, top) = (c.u_star, c.top_kind());
                    let z1 = (1.0 - a).max(0.0).powf(1.0 / n);
                    let perm = z1 - z1 * z1.powf(n) / (n + 1.0);
                    let inf = f64::INFINITY;
                    let jumping = c.band(u_star, PI, top, false, (inf, inf), (perm, 0.0)).normal;
                    // amp > 1: scaled by amp^(1 + 1/n), as total_normal.
                    perm + jumping
                };
                assert!((closed / quad_total - 1.0).abs() < 1e-14, "n={n} a={a}: {closed} vs {quad_total}");
            }
        }
    }

    #[test]
    fn elliptic_integrals_match_known_values() {
        // K(1/2) and E(1/2) (parameter m = k^2), 20 digits from the literature (mpmath).
        let (k, e) = elliptic_ke(0.5, 0.5);
        assert!((k - 1.854_074_677_301_371_9).abs() < 4e-16, "{k}");
        assert!((e - 1.350_643_881_047_675_5).abs() < 4e-16, "{e}");
        let (k0, e0) = elliptic_ke(0.0, 1.0);
        assert_eq!((k0, e0), (FRAC_PI_2, FRAC_PI_2));
    }
}
