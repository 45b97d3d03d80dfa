//! The band quadrature of an MDR power-law foundation: springs in the angle
//! `u = pi/2 - arcsin s`, Gauss(-Jacobi) pieces graded towards singularities,
//! orders raised until the truncation error predicted from the pass's own
//! coefficients is within the tolerance.

use crate::integrate::{self, Ladder, LOOSE_TOL, MIN_ORDER};
use crate::model::spring::{mean_normal_sin_cos, LengthNode, LengthTop, Velocity};
use crate::quad;
use std::f64::consts::FRAC_PI_2;

mod length;

/// What a band's nodes compute besides the normal force `<B>`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Means {
    /// Slip only (or no velocity): the tangential force is `<B>`, no deficit.
    Slip,
    /// Stick first: [`Velocity::stick_first_means`].
    StickFirst,
    /// Slip first (`cos u` between `sqrt(1 - vbar^2)` and 1, the contact
    /// phase `u` below `delta = arcsin vbar`): the deficit is the permanent
    /// spring's `D` (the caller's closed form), and the tangential force
    /// `<B> - D` is summed from non-negative parts ([`slip_first_tangential`]),
    /// with `excess` the permanent spring's tangent excess (`D = cos delta -
    /// excess`).
    SlipFirst {
        /// [`crate::model::spring::Spring::tangent_excess`] of a permanent spring.
        excess: f64,
    },
}

/// `<B> - D` of a slip-first spring at contact phase `u` (`s = cos u`), with
/// `D = cos delta - excess` the permanent spring's deficit. As `<B> = s (1 -
/// u/pi) + sin(u)/pi`, it is the sum of three non-negative terms (`u <= delta`):
/// `cos u - cos delta`, taken as `2 sin((delta + u)/2) sin((delta - u)/2)`;
/// `(sin u - u cos u)/pi`; and `excess`. As the difference of `<B>` (near 1)
/// and `D`, it kept only `eps` absolute where it is `O(vbar)`: the power law
/// with exponent 3.7 at amp 1, whose slip-first band is `vbar^(2/n)` wide,
/// lost `eps vbar^(2/n - 1)` relative (`mu/vbar` 3.18 for 2.71 at vbar 1e-30).
fn slip_first_tangential(u: f64, sin_u: f64, cos_u: f64, delta: f64, excess: f64) -> f64 {
    let gap = 2.0 * (0.5 * (delta + u)).sin() * (0.5 * (delta - u)).sin();
    // sin u - u cos u = u (1 - cos u) - (u - sin u), 1 - cos u = sin^2 u/(1 + cos u)
    // (u < pi/2): about u^3/2 - u^3/6.
    let lag = u * (sin_u * sin_u / (1.0 + cos_u)) - crate::special::x_minus_sin(u);
    // Each term >= 0 but for rounding; `nonneg` keeps a NaN for the checks downstream.
    crate::special::nonneg(gap) + crate::special::nonneg(lag) / std::f64::consts::PI + excess
}

/// [`Foundation::band_centre_by_length`] splits a band without cuts towards
/// its top where the means' singularity below its bottom is closer than this
/// fraction of its width (fewest nodes on the parabolic table; from 0.3 of
/// the width on the split changes nothing).
const CENTRE_SPLIT_BELOW: f64 = 0.125;
/// First order of a stick-first band in the stick's half-length
/// ([`Foundation::band_by_length`]), in `tau = sqrt(h_b - h)`, which removes
/// the square-root branch point of `sin phi` just above the band's top: the
/// order at which most bands pass, so that few run a second pass (starting
/// lower made the estimate's single claim of the measured decay the
/// binding one, and it missed its bound when raised for these bands alone).
const LENGTH_FIRST_ORDER: usize = 20;
/// [`Foundation::band_centre_whole`] takes a band whose singularities lie at
/// least this fraction of its width (in `tau`) above its top.
const CENTRE_WHOLE_DISTANCE: f64 = 0.25;
/// The half-length forms take a spring's phase `u` from the band's top
/// ([`Foundation::pass_length`], [`Foundation::pass_centre_length`]) where
/// it is below this (and the spring in the top half): the addition formulas'
/// `sin u` is within `eps/u` relatively, 4 eps here.
const FROM_TOP_PHASE: f64 = 0.25;
/// Above this `amp cos u`, `1/amp - cos u` (scaled `y`) loses more than one bit
/// to cancellation, and the product form `2 sin((u + u*)/2) sin((u - u*)/2)` is used.
/// Beyond [`Y_PLAIN_MAX_AMP`] it is used everywhere: `cos u` of a node `u`
/// rounded to its ulp is off by up to an ulp absolute, which is `2 amp` ulps of
/// `y >= 1/(2 amp)` (the mean normal force of `power:3.7` at amp 1e9 was 1e-10 off).
const Y_PRODUCT_FORM: f64 = 0.5;
/// The largest `amp` whose plain `1/amp - cos u` keeps `y` within 4 ulps.
const Y_PLAIN_MAX_AMP: f64 = 2.0;
/// A singularity of the stick-first means closer to a band end than this
/// fraction of the band's width is graded.
const GRADE_RATIO: f64 = 0.25;
/// The Jacobian's branch point is graded until this fraction of the width.
const JACOBIAN_GRADE_RATIO: f64 = 0.25;
/// Most pieces one band is split into towards the stick-first means'
/// singularities (half from each end).
const MAX_PIECES: usize = 100;
/// Levels of the grading towards the Jacobian's branch point: a band's top can
/// lie within an ulp of it (where `amp sqrt(1 - vbar^2) = 1`, `u_sf = u*` up to
/// rounding: `amp = 5/3, vbar = 0.8`), and a piece that holds the branch point
/// within a fraction of its width converges only algebraically (see
/// [`Foundation::y_sc`] for the rest).
/// The distance `u_sf - u*` is at least an ulp of `u_sf`, so 2^-90 of the
/// width reaches it.
const JACOBIAN_LEVELS: i32 = 90;
/// Length in `t` of one segment of a mapped band ([`Foundation::pass_mapped`]).
/// The integrand is analytic in a strip about the real `t` axis (half-width
/// about `pi/2` where the Jacobian's complex zeros set it), so a segment's
/// convergence does not depend on how close the singularities lie; the length
/// is the cheapest of those tried from 2 to 7 with the predicted next order
/// (`fricosc bench` measures it; a few per cent either side of 5).
const SEGMENT: f64 = 5.0;
/// A side of a mapped band whose singularity lies beyond `GRADE_RATIO` of
/// the width is mapped as if it lay this many widths away (nearly linear there).
const FAR_SIDE: f64 = 64.0;

/// The three means integrated over the foundation, in this order: the normal
/// force `int amp <B> dz`, the deficit `int amp D dz` and the tangential force
/// `int amp <F> dz` (each computed from its own cancellation-free formula, so
/// that the smaller of `D` and `<F>` keeps its relative accuracy).
pub(super) const MEANS: usize = 3;
/// Index of the normal force, the deficit and the tangential force in [`Sums`].
pub(super) const NORMAL: usize = 0;
pub(super) const DEFICIT: usize = 1;
pub(super) const TANGENTIAL: usize = 2;

/// The sums of a band of the foundation: the [`MEANS`], and as the
/// magnitude the deficit's terms' sizes (its rounding is a few ulps of them).
pub(super) type Sums = integrate::Sums<MEANS>;
type Pass = integrate::Pass<MEANS>;
type Acc = integrate::Acc<MEANS>;

/// How the Jacobian behaves at the top of a piece.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Top {
    /// Analytic at the top.
    Regular,
    /// `amp > 1`, top at `beta*`: weight `(beta* - beta)^(1/n - 1)`.
    Centre,
    /// `amp = 1`, top at `pi/2`: weight `(pi/2 - beta)^(2/n - 1)`.
    CentreCritical,
}

pub(super) struct Foundation {
    pub(super) n: f64,
    pub(super) amp: f64,
    /// `1/n - 1`, the exponent of `y` in the Jacobian.
    pub(super) gamma: f64,
    /// `u* = pi/2 - arcsin(1/amp)` for `amp > 1` (where `y = 0`), else 0.
    pub(super) u_star: f64,
    /// `sin u*` and `cos u*` (of `u*` as rounded: `y` vanishes there exactly).
    star_sin_cos: (f64, f64),
    /// Velocity constants when `vbar < 1`.
    pub(super) vel: Option<Velocity>,
    pub(super) tol: f64,
    /// Whether the bands integrate the normal force. Without a band report,
    /// the cone's and the paraboloid's total normal force has a closed form
    /// that replaces the bands' (`mdr::solve`): a stick-first node then skips
    /// its `<B>` (a series and two divisions), and every band's normal slot
    /// holds 0, whose truncation estimate is 0, so that it decides no order
    /// (the slip bands of a small `mu` would otherwise chase a normal force
    /// that is thrown away, against a scale without the stick band's).
    pub(super) normal: bool,
    /// Whether the stick-first bands integrate the tangential force (where
    /// `mu` will come from the deficit, `mdr::solve` knows so before the band:
    /// `S(e)`, a division and a third mean's sums less a node). Its slot holds
    /// 0 otherwise, as the normal force's.
    pub(super) tangential: bool,
}

/// Nodes are placed in `u = pi/2 - beta`, the angular distance from the
/// contact centre's threshold `s = 1`: near the centre (`amp` near 1, or
/// `vbar` near 0) the distances that matter are tiny, and `u` resolves them
/// where `beta` near `pi/2` would round them away (`cos` of an angle near
/// `pi/2` keeps only the absolute accuracy of the angle).
impl Foundation {
    /// The foundation of `g = z^n` at amplitude `amp`: `u* = pi/2 - arcsin(1/amp)`
    /// for `amp > 1` (where `y = 0`), else 0.
    pub(super) fn new(n: f64, amp: f64, vel: Option<Velocity>, tol: f64) -> Self {
        let u_star = if amp > 1.0 { 2.0 * (0.5 * (amp - 1.0) / amp).sqrt().asin() } else { 0.0 };
        let star_sin_cos = libm::sincos(u_star);
        Foundation { n, amp, gamma: 1.0 / n - 1.0, u_star, star_sin_cos, vel, tol, normal: true, tangential: true }
    }

    /// The means that a band of `means` integrates: the normal force where no
    /// closed form replaces it ([`Foundation::normal`]), the deficit, and the
    /// tangential force unless a stick-first band may skip it
    /// ([`Foundation::tangential`]).
    fn active(&self, means: Means) -> [bool; MEANS] {
        let mut a = [true; MEANS];
        a[NORMAL] = self.normal;
        a[TANGENTIAL] = self.tangential || means != Means::StickFirst;
        a
    }

    /// How the Jacobian behaves at `u*`, the top of the innermost band.
    pub(super) fn top_kind(&self) -> Top {
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
    pub(super) fn y(&self, u: f64) -> f64 {
        if self.amp > 1.0 {
            self.y_product(u - self.u_star)
        } else {
            let h = (0.5 * u).sin();
            (1.0 - self.amp) + 2.0 * self.amp * h * h
        }
    }

    /// [`Foundation::y`] given `sin(u)`, `cos(u)` and `u - u*` (no further
    /// trigonometry where it does not cancel): `amp <= 1`: `1 - cos u = sin^2 u /
    /// (1 + cos u)`; `1 < amp <= 2` away from `u*`: `1/amp - cos u`; near it,
    /// and everywhere beyond (see [`Y_PLAIN_MAX_AMP`]), the product form with
    /// `u - u*` as given. A node is `top + d`, rounded to an ulp of `u`; `u - u*`
    /// must come from `(top - u*) + d` instead, or a piece within 1e-10 of `u*`
    /// sees its Jacobian `y^gamma` jitter by 1e-6 (at `amp sqrt(1 - vbar^2) = 1`
    /// the stick-first band starts there; the test
    /// `the_stick_first_band_starting_at_the_centre_threshold` holds it).
    pub(super) fn y_sc(&self, sin_u: f64, cos_u: f64, from_star: f64) -> f64 {
        if self.amp <= 1.0 {
            let one_minus_c = if cos_u > 0.0 { sin_u * sin_u / (1.0 + cos_u) } else { 1.0 - cos_u };
            (1.0 - self.amp) + self.amp * one_minus_c
        } else if self.amp * cos_u > Y_PRODUCT_FORM || self.amp > Y_PLAIN_MAX_AMP {
            self.y_product(from_star)
        } else {
            1.0 / self.amp - cos_u
        }
    }

    /// `y` of `amp > 1` (scaled by `1/amp`) as `cos u* - cos u = 2 sin((u + u*)/2)
    /// sin((u - u*)/2)`, with `u - u*` given by the caller (`u` itself is not needed).
    fn y_product(&self, from_star: f64) -> f64 {
        let (sum, s, _) = self.half_angles(from_star);
        2.0 * sum * s
    }

    /// `sin((u + u*)/2) = sin u* cos(d/2) + cos u* sin(d/2)` and `sin(d/2)`,
    /// `d = u - u*` in `[0, pi - u*]`, and `cos(d/2)`, from one `sin_cos` (by
    /// its series for small `d`, [`crate::special::sin_cos_small`]): two
    /// non-negative terms (both angles in `[0, pi/2]`), so no cancellation
    /// (one shared range reduction instead of two sines).
    fn half_angles(&self, d: f64) -> (f64, f64, f64) {
        let (sin_star, cos_star) = self.star_sin_cos;
        let (s, c) = crate::special::sin_cos_small(0.5 * d);
        (sin_star * c + cos_star * s, s, c)
    }

    /// `y / (u - u*) = 2 sin((u + u*)/2) sin(d/2)/d` for `amp > 1`, `d = u - u*`
    /// ([`Foundation::half_angles`]).
    fn centre_ratio(&self, d: f64) -> f64 {
        let (sum, s, _) = self.half_angles(d);
        2.0 * sum * s / d
    }

    /// `y^gamma` (or of any positive ratio: the Centre tops take it of `y/d`),
    /// with the common exponents without `powf`.
    pub(super) fn y_pow(&self, y: f64) -> f64 {
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
    /// distance of `u` from the top of the piece, `from_star` that of `u` from `u*`.
    pub(super) fn jacobian(&self, sin_u: f64, cos_u: f64, d: f64, from_star: f64, top: Top) -> f64 {
        let k = if self.amp > 1.0 { 1.0 / self.n } else { self.amp / self.n };
        match top {
            Top::Regular => k * self.y_pow(self.y_sc(sin_u, cos_u, from_star)) * sin_u,
            Top::Centre => k * self.y_pow(self.centre_ratio(d)) * sin_u,
            Top::CentreCritical => {
                // amp = 1, top at u = 0 (u = d): y/u^2 = 2 (sin(u/2)/u)^2, sin(u)/u.
                let q = (0.5 * d).sin() / d;
                k * self.y_pow(2.0 * q * q) * (d.sin() / d)
            }
        }
    }

    /// Exponent of the weight `(u - top)^e` of `top`.
    pub(super) fn weight_exponent(&self, top: Top) -> f64 {
        match top {
            Top::Regular => 0.0,
            Top::Centre => self.gamma,
            Top::CentreCritical => 2.0 * self.gamma + 1.0,
        }
    }

    /// Order-`m` Gauss(-Jacobi) sums `(int amp <B> dz, int amp D dz)` over
    /// `u` in `[top, bottom]` with the weight of `kind` at the top. Each
    /// node's stick starts Halley from the fitted guess, not from the
    /// neighbouring node's length: a low order's nodes lie far apart.
    pub(super) fn pass(&self, top: f64, bottom: f64, kind: Top, means: Means, m: usize) -> Pass {
        let e = self.weight_exponent(kind);
        let r = quad::rule(m, e);
        let h = 0.5 * (bottom - top);
        // Exact where it matters (Sterbenz: a top near u*).
        let top_from_star = top - self.u_star;
        let mut acc = Acc::new(&r, self.active(means));
        for &x in &r.nodes {
            // x = -1 at the top.
            let d = h * (1.0 + x);
            let (f, mag) = self.node(top + d, d, top_from_star + d, kind, 1.0, means);
            acc.add(f, mag);
        }
        let width = if e == 0.0 { h } else { h.powf(e + 1.0) };
        acc.finish(&r, if self.amp > 1.0 { width } else { self.amp * width })
    }

    /// One node's integrand: `factor` times the Jacobian and the means at `u`
    /// (`d` from the piece's top, `from_star` from `u*`), and the deficit's magnitude
    /// likewise.
    fn node(&self, u: f64, d: f64, from_star: f64, kind: Top, factor: f64, means: Means) -> ([f64; MEANS], f64) {
        let beta = FRAC_PI_2 - u;
        let (su, cu) = libm::sincos(u);
        let jac = factor * self.jacobian(su, cu, d, from_star, kind);
        // sin(beta) = cos(u), cos(beta) = sin(u); the contact phase is u.
        // <B> is the tangential force of a spring that only slips.
        let b = if self.normal || means == Means::Slip { mean_normal_sin_cos(beta, cu, su) } else { 0.0 };
        let (dd, tt, mm) = match (means, &self.vel) {
            (Means::StickFirst, Some(vel)) => {
                let m = vel.stick_first_means(u, su, cu);
                (m.deficit, if self.tangential { m.tangential } else { 0.0 }, m.magnitude)
            }
            (Means::SlipFirst { excess }, Some(vel)) => (0.0, slip_first_tangential(u, su, cu, vel.delta, excess), 0.0),
            _ => (0.0, b, 0.0),
        };
        let mut f = [0.0; MEANS];
        f[NORMAL] = if self.normal { jac * b } else { 0.0 };
        f[DEFICIT] = jac * dd;
        f[TANGENTIAL] = jac * tt;
        (f, jac.abs() * mm)
    }

    /// Order-`m` Gauss-Legendre sums over the segment `[t0, t1]` of a band
    /// `u` in `[top, bottom]` (analytic at the top) in the variable
    /// `t = ln((u - top + d0)/(bottom + d1 - u))`, which sends singularities at
    /// `top - d0` and `bottom + d1` to `t = -inf` and `+inf`: the integrand is
    /// analytic in a strip about the real `t` axis, so segments of a fixed
    /// length ([`SEGMENT`]) converge alike however close the singularities lie,
    /// where graded pieces took one piece per factor 2 of distance. With
    /// `W = bottom - top`, `t_top = ln(d0/(W + d1))`, `tau = t - t_top` and
    /// `E = e^t`: `u - top = d0 expm1(tau)/(1 + E)` (exact near the top) and
    /// `du/dt = (u - top + d0)(bottom + d1 - u)/(W + d0 + d1)`.
    pub(super) fn pass_mapped(&self, top: f64, bottom: f64, ends: (f64, f64), seg: (f64, f64), m: usize) -> Pass {
        let (d0, d1) = ends;
        let r = quad::rule(m, 0.0);
        let width = bottom - top;
        let e_top = d0 / (width + d1);
        let t_top = e_top.ln();
        let h = 0.5 * (seg.1 - seg.0);
        let top_from_star = top - self.u_star;
        let mut acc = Acc::new(&r, self.active(Means::StickFirst));
        for &x in &r.nodes {
            let tau = (seg.0 - t_top) + h * (1.0 + x);
            // E = e^(t_top + tau) from the expm1 already at hand (one exp a node less).
            let em1 = tau.exp_m1();
            let d = (d0 * em1 / (1.0 + e_top * (1.0 + em1))).min(width);
            let dudt = (d + d0) * ((width - d) + d1) / (width + d0 + d1);
            let (f, mag) = self.node(top + d, d, top_from_star + d, Top::Regular, dudt, Means::StickFirst);
            acc.add(f, mag);
        }
        acc.finish(&r, if self.amp > 1.0 { h } else { self.amp * h })
    }

    /// A stick-first band analytic at its top, singular near an end (a
    /// distance below `GRADE_RATIO` of its width: `near.0` or the Jacobian's
    /// branch point above the top, `near.1` below the bottom), in the mapped
    /// variable of [`Foundation::pass_mapped`], cut into segments of length
    /// [`SEGMENT`] in `t`; a far side is mapped as if [`FAR_SIDE`] widths away.
    /// Fewer nodes than graded pieces for such bands, many fewer where the
    /// singularity is close (the boundary `amp sqrt(1 - vbar^2) = 1`). Bands
    /// with the Jacobian's weight at the top (`amp > 1` from `u*`) stay
    /// graded: mapped with the Jacobi weight in `tau` they cost more.
    fn band_mapped(&self, top: f64, bottom: f64, ends: (f64, f64), scale: [f64; MEANS]) -> Sums {
        let (d0, d1) = ends;
        let width = bottom - top;
        let t_top = (d0 / (width + d1)).ln();
        let t_bottom = ((width + d0) / d1).ln();
        let k = ((t_bottom - t_top) / SEGMENT).ceil().max(1.0) as usize;
        let at = |i: usize| if i == k { t_bottom } else { t_top + (t_bottom - t_top) * i as f64 / k as f64 };
        // Middle segments first (the widest in u): their sums set the scale.
        let mut order: Vec<usize> = (0..k).collect();
        order.sort_by_key(|&i| (2 * i + 1).abs_diff(k));
        let mut total = Sums::default();
        for i in order {
            let sc = std::array::from_fn(|j| scale[j] + total.value[j].abs());
            let pass = |m| self.pass_mapped(top, bottom, ends, (at(i), at(i + 1)), m);
            total += self.ladder().run(self.mapped_first_order(), pass, sc);
        }
        total
    }

    /// The order ladder of the foundation's pieces, to its tolerance.
    fn ladder(&self) -> Ladder {
        Ladder::new(self.tol)
    }

    /// One piece at increasing orders, until the predicted error of every mean
    /// is within the tolerance relative to the piece plus `scale` (the band's
    /// sums so far).
    pub(super) fn piece(&self, top: f64, bottom: f64, kind: Top, means: Means, scale: [f64; MEANS]) -> Sums {
        self.ladder().run(self.ladder().first_order(), |m| self.pass(top, bottom, kind, means, m), scale)
    }

    /// The first order of a band in the stick's half-length:
    /// [`LENGTH_FIRST_ORDER`], or [`MIN_ORDER`] at a tolerance of
    /// [`LOOSE_TOL`] or looser.
    fn length_first_order(&self) -> usize {
        if self.tol >= LOOSE_TOL {
            MIN_ORDER
        } else {
            LENGTH_FIRST_ORDER
        }
    }

    /// The first order of a mapped segment: one doubling above
    /// [`Ladder::first_order`] (see [`SEGMENT`]: at order 16 nearly every
    /// segment of the parabolic table failed; from 32, 34.5 nodes a point
    /// became 29.8, and 51.1 -> 46.2 and 55.8 -> 52.3 for the exponents 3 and
    /// 0.5; with [`Foundation::next_order`] too, 29.1, 44.8 and 49.3, and 32.8
    /// -> 28.6 for the cone).
    fn mapped_first_order(&self) -> usize {
        2 * self.ladder().first_order()
    }

    /// Distance from a band's top `top` (in `u`) to the nearest singularity of
    /// the Jacobian above it (`inf` if none).
    pub(super) fn singular_distance(&self, top: f64, kind: Top) -> f64 {
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

    /// The distances of a band's singularities that [`Foundation::band`] and
    /// [`Foundation::band_centre_by_length`] grade towards: the Jacobian's
    /// branch point above `top`, and `near` above and below, floored.
    /// Singularities closer than these are treated as at them (as graded
    /// pieces stop there): what lies between is at most 2^-48 of the band's
    /// width (2^-90 towards the Jacobian's branch point). At amp = 1 (u* = 0)
    /// a regular top's distance to the branch point is the top itself, exact,
    /// however small (the stick-first band's top is arcsin(vbar)): floored,
    /// the mapping put the branch point at 2^-90 of the width, and `power:20`
    /// at vbar 1e-40 lost 2.5e-5 of mu, with an estimate of 6.9e-6.
    fn floored_distances(&self, top: f64, width: f64, kind: Top, near: (f64, f64)) -> (f64, f64, f64) {
        let floor = width * 2f64.powi(-(MAX_PIECES as i32 / 2 - 2));
        let distance = self.singular_distance(top, kind);
        let jac = if self.amp == 1.0 && kind == Top::Regular {
            distance.max(f64::MIN_POSITIVE)
        } else {
            distance.max(width * 2f64.powi(-JACOBIAN_LEVELS))
        };
        (jac, near.0.max(floor), near.1.max(floor))
    }

    /// Integrate the band `u` in `[top, bottom]` with close singularities:
    /// one `near.0` (or the Jacobian's) above the top and one `near.1` below
    /// the bottom. A stick-first band analytic at its top is integrated in
    /// segments of a mapped variable ([`Foundation::band_mapped`]); any other
    /// is split geometrically: cuts at `top + d 2^k` and `bottom - d 2^k` keep
    /// every piece at least its own width away from both.
    pub(super) fn band(
        &self,
        top: f64,
        bottom: f64,
        kind: Top,
        means: Means,
        near: (f64, f64),
        scale: [f64; MEANS],
    ) -> Sums {
        let mut total = Sums::default();
        // An empty band, or one whose half-width underflows to 0 (vbar = 5e-324
        // makes a band [0, 5e-324]): its share is below anything representable.
        if bottom <= top || 0.5 * (bottom - top) == 0.0 {
            return total;
        }
        let width = bottom - top;
        let (jac, near_above, below) = self.floored_distances(top, width, kind, near);
        let above = jac.min(near_above);
        let close = |d: f64| d < GRADE_RATIO * width;
        if means == Means::StickFirst && kind == Top::Regular && (close(above) || close(below)) {
            let side = |d: f64| if close(d) { d } else { FAR_SIDE * width };
            return self.band_mapped(top, bottom, (side(above), side(below)), scale);
        }
        let mut cuts = vec![top, bottom];
        // The Jacobian's branch point (y = 0, a power singularity) and the
        // singularities of the stick-first means' continuation are graded until
        // every piece is at least its own width away from them, up to a quarter
        // of the band's width (Gauss copes beyond), so that the gradings from
        // opposite ends never cross.
        grade(&mut cuts, jac, JACOBIAN_GRADE_RATIO * width, top, 1.0);
        grade(&mut cuts, near_above, GRADE_RATIO * width, top, 1.0);
        grade(&mut cuts, below, GRADE_RATIO * width, bottom, -1.0);
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        // Widest pieces first: their sum sets the absolute scale that the tiny
        // pieces near a singularity need only match (a relative tolerance on a
        // piece worth 1e-17 of the band would chase rounding noise).
        let mut pieces: Vec<(f64, f64)> = cuts.windows(2).map(|w| (w[0], w[1])).collect();
        pieces.sort_by(|a, b| (b.1 - b.0).total_cmp(&(a.1 - a.0)));
        for (a, b) in pieces {
            let k = if a == top { kind } else { Top::Regular };
            let sc = std::array::from_fn(|i| scale[i] + total.value[i].abs());
            let pc = self.piece(a, b, k, means, sc);
            total += pc;
        }
        total
    }
}

/// Cuts at `from + sign d 2^k` for `k = 0, 1, ...` while `d 2^k < until`:
/// every piece at least its own width away from a singularity at distance
/// `d` beyond `from`.
fn grade(cuts: &mut Vec<f64>, d: f64, until: f64, from: f64, sign: f64) {
    let mut d = d;
    while d < until {
        cuts.push(from + sign * d);
        d *= 2.0;
    }
}
