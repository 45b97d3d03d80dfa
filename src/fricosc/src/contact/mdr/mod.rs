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
//! Each piece is integrated at increasing orders from 16 (a mapped segment from
//! 32; 8 and 16 at loose tolerances), each next one chosen from the measured
//! decay and at most a doubling: it is accepted when the truncation error
//! predicted from the decay of the integrand's discrete orthogonal-polynomial
//! coefficients at the same nodes (`quad::Rule::truncation`; after a doubling,
//! at most the difference of the two passes) is within the relative tolerance;
//! the estimates of the pieces add up to the reported one.
//!
//! # The stick-first band in the stick's half-length
//! From vbar 1e-3 on, the stick-first band is integrated in its springs'
//! stick half-length `h` instead of the phase: the spring whose stick lasts
//! `2h` starts it at `beta = h - arccos(vbar h/sin h)` and loses `sin(phi)(sin
//! h - h cos h)/pi` ([`crate::spring`]'s closed form), so a node needs no
//! root; in `tau = sqrt(h_b - h)`, `h_b` the square-root branch point where
//! `vbar h = sin h`, the integrand is analytic up to the band's top. Below the
//! contact centre's threshold `u*` the whole band is one Gauss-Jacobi piece
//! in `tau`, its weight `(tau - tau*)^(1/n - 1)` from the top (`u - u*` from
//! the top to full relative accuracy: [`crate::spring`]'s `phase_below_top`),
//! where the singularities above the top lie far enough (else the phase
//! grades towards `u*`, and the half-length takes the band's lowest piece).
//! Springs with a small phase near the top take it from the top too.

mod foundation;
mod normal;

use crate::model::spring::{Spring, Velocity};
use crate::ratio::Ratio;
use crate::special::{one_minus_a_cos_asin, powf};
use crate::DEFAULT_TOL;
use foundation::{Foundation, Means, Sums, Top, DEFICIT, MEANS, NORMAL, TANGENTIAL};
pub(crate) use normal::foundation_force;
use normal::total_normal;
use std::f64::consts::{FRAC_PI_2, PI};

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

/// Below this `vbar` the stick-first band is integrated in the contact phase
/// `u`, not in the stick's half-length ([`Foundation::band_by_length`]). As
/// `vbar -> 0` the band's top `h_t` nears `pi`, where `g = vbar h/sin h` has
/// its pole, about `(pi vbar)^(1/4)` away in `tau`: the coefficients' decay
/// turns irregular, and the estimate of the first, loose orders with it.
/// Measured on the 42,000 checks' grid (tolerances 1e-3 to 1e-11 against the
/// default, 60 velocities a decade): the largest error was 0.05 of its
/// estimate from 1e-3 to 0.1 (0.27 over the whole grid), 0.08 at 5e-4, 0.37 at
/// 2.5e-4, 0.88 at 1.5e-4, and below 1.3e-4 estimates failed. Down to here
/// the half-length takes far fewer nodes than the phase (the paraboloid at
/// vbar 0.003, amp 2: 40 for 160). Its small top phase `arcsin vbar` is taken
/// from the top ([`Foundation::pass_length`]).
const BY_LENGTH_MIN_VBAR: f64 = 1e-3;
/// [`solve`] skips the stick-first band's tangential force where its bound on
/// the reduction ([`deficit_only`]) is below this: `mu` comes from the
/// deficit up to a reduction of 1/2, and the margin keeps the choice the one
/// that the computed reduction makes.
const DEFICIT_ONLY_BELOW: f64 = 0.45;
/// Nor where the Jacobian's branch point `u*` lies above the band's top
/// closer than this fraction of the band's width (`amp` or `amp sqrt(1 -
/// vbar^2)` near 1): the phase's grading and mapping resolve it, and `u -
/// u*` keeps its digits there as `(top - u*) + d`.
const BY_LENGTH_JACOBIAN_DISTANCE: f64 = 0.25;

/// The permanent-contact band `0 <= z <= z1 = (1 - amp)^(1/n)` (`amp < 1`), in
/// closed form: every spring there has the same deficit `D(vbar)` and the same
/// stick excess `X = <F> - F(tau_s)` ([`Spring::tangent_excess`]), so
/// `N = z1 - z1^(n+1)/(n+1)`, `D = amp D(vbar) z1` and, since each spring's
/// `amp <F> = (1 - z^n - amp sqrt(1 - vbar^2)) + amp X`,
/// `T = z1 ((1 - amp sqrt(1 - vbar^2)) - (1 - amp)/(n + 1) + amp X)`, every
/// part cancellation-free (`z1^n = 1 - amp`).
struct Permanent {
    sums: Sums,
    /// `D(vbar)` of one spring in permanent contact (0 at `vbar >= 1`).
    deficit_per_spring: f64,
    /// The magnitude of that deficit's terms, times the band's `amp z1`.
    deficit_magnitude: f64,
    /// The tangent excess of one spring in permanent contact (0 at `vbar >= 1`,
    /// and where the tangential force is not integrated).
    excess: f64,
    /// Whether the bands integrate the tangential force: not where `mu` will
    /// come from the deficit ([`deficit_only`]); the band's own tangential
    /// force is then 0 (it is never used), and so is the excess.
    tangential: bool,
    /// Half the stick of a spring in permanent contact (NaN at `vbar >= 1`):
    /// the stick from the tangent, `Velocity::tangent_half_length` (a test's),
    /// which is the top of the stick-first band in the half-length. The spring
    /// is solved to full precision for it, so that the band's top needs no
    /// root of its own.
    tangent_half_length: f64,
}

/// The permanent band, with `closed` the closed-form total normal force where
/// one replaces the bands' (which decides [`Permanent::tangential`]).
fn permanent_band(n: f64, vbar: f64, amp: f64, z1: f64, closed: Option<f64>) -> Permanent {
    let normal = z1 - z1 * powf(z1, n) / (n + 1.0);
    let mut sums = Sums { value: [normal, 0.0, normal], ..Default::default() };
    if vbar >= 1.0 {
        let (deficit_per_spring, deficit_magnitude, excess, tangent_half_length) = (0.0, 0.0, 0.0, f64::NAN);
        return Permanent {
            sums,
            deficit_per_spring,
            deficit_magnitude,
            excess,
            tangential: true,
            tangent_half_length,
        };
    }
    let sp = Spring::with_events(f64::MAX, vbar);
    sums.value[DEFICIT] = sp.deficit * (amp * z1);
    let tangential = !deficit_only(closed, &sums);
    // The excess (a sine and a series) only where the tangential force is integrated.
    let x = if tangential { sp.tangent_excess().unwrap_or(0.0) } else { 0.0 };
    sums.value[TANGENTIAL] = if tangential && z1 > 0.0 {
        z1 * (one_minus_a_cos_asin(amp, vbar) - (1.0 - amp) / (n + 1.0) + amp * x)
    } else {
        0.0
    };
    Permanent {
        sums,
        deficit_per_spring: sp.deficit,
        deficit_magnitude: sp.deficit_magnitude * (amp * z1),
        excess: x,
        tangential,
        tangent_half_length: sp.stick.map_or(f64::NAN, |st| 0.5 * st.length),
    }
}

/// `mu_macro/mu0` of the power-law profile `g = z^n` at `(vbar, amp)`.
///
/// ```
/// use fricosc::{Conditions, Shape};
/// // The cone (n = 1) at vbar = 0.3, du/u0 = 0.5.
/// let r = Shape::cone().evaluate(&Conditions::vbar(0.3, 0.5)?)?;
/// assert!((r.ratio.mu_ratio - 0.6635626779221783).abs() < 1e-14);
/// assert!(r.error_estimate < 1e-14);
/// # Ok::<(), fricosc::Error>(())
/// ```
///
/// # Errors
/// [`crate::Error::InvalidParameter`] for a negative or non-finite `vbar` or
/// `amp`, `n` outside [[`crate::MIN_EXPONENT`], [`crate::MAX_EXPONENT`]];
/// [`crate::Error::Internal`] for a bug.
pub(crate) fn power_law(n: f64, vbar: f64, amp: f64, tol: f64) -> crate::Result<MdrResult> {
    check(n, vbar, amp)?;
    let at = crate::contact::VelocityScale::of(vbar, amp);
    let r = solve(n, at.vbar, amp, tol, Report::Ratio)?;
    let (ratio, error_estimate) = at.back(r.ratio, r.error_estimate);
    Ok(MdrResult { ratio, error_estimate, ..r })
}

/// Check the inputs of [`power_law`] and [`point`].
fn check(n: f64, vbar: f64, amp: f64) -> crate::Result<()> {
    if !(crate::MIN_EXPONENT..=crate::MAX_EXPONENT).contains(&n) {
        return Err(crate::Error::param("n", n, "the exponent must be within [0.05, 1e6]"));
    }
    crate::error::check_nonneg("vbar", vbar)?;
    crate::error::check_nonneg("amp", amp)?;
    Ok(())
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

/// No reduction (no oscillation, or no spring sticks): `mu = mu0`, with the
/// mean normal force of one side of the foundation (`half`) doubled (z < 0
/// mirrors z > 0).
fn sliding(half: Option<f64>) -> MdrResult {
    MdrResult {
        ratio: Ratio { mu_ratio: 1.0, reduction: 0.0 },
        error_estimate: 0.0,
        mean_normal: half.map(|x| 2.0 * x),
        bands: vec![],
        nodes: 0,
    }
}

/// The slip-first band's width in z: for amp < 1 from z1 = y(0)^(1/n) to
/// y(u_sf)^(1/n), as z1 ((1 + dy/y(0))^(1/n) - 1) with dy = y(u_sf) - y(0) =
/// 2 amp sin^2(u_sf/2): the plain difference of the two powers would keep only
/// their absolute accuracy, and the band is as thin as vbar^2 near vbar = 0.
/// (For amp > 1, in the scaled units of the integrals: y/amp from 0.)
/// `z_sf` is `z(u_sf)`, the plain form where `z1 = 0`.
fn slip_first_width(contact: &Foundation, n: f64, amp: f64, z1: f64, u_sf: f64, z_sf: impl Fn() -> f64) -> f64 {
    if amp > 1.0 {
        powf(contact.y(u_sf).max(0.0), 1.0 / n)
    } else if z1 == 0.0 {
        z_sf()
    } else {
        let h = (0.5 * u_sf).sin();
        let (dy, y0) = (2.0 * amp * h * h, 1.0 - amp);
        let growth = (dy / y0).ln_1p() / n;
        // Where e^growth overflows (z1 subnormal: amp an ulp below 1 and n
        // small) the band is z_sf itself to far beyond double precision.
        if growth > 700.0 {
            z_sf() - z1
        } else {
            z1 * growth.exp_m1()
        }
    }
}

/// Whether `mu` will come from the deficit, known before the bands: then the
/// stick-first band need not integrate the tangential force. With the
/// closed-form normal force `N` (`closed`), the reduction is at most `(D_perm +
/// N - N_perm)/N`, every spring's deficit outside the permanent band being at
/// most its normal force; the deficit is used where that bound is below
/// [`DEFICIT_ONLY_BELOW`] (the cone and the paraboloid at `amp < 1`, where the
/// permanent band holds most of the force: at `vbar 0.3, amp 0.4` 90 %).
fn deficit_only(closed: Option<f64>, perm: &Sums) -> bool {
    closed.is_some_and(|nc| {
        let rest = (nc - perm.value[NORMAL]).max(0.0);
        perm.value[DEFICIT] + rest < DEFICIT_ONLY_BELOW * nc
    })
}

/// The ratio and its error estimate from the totals: `mu` from the tangential
/// force's own integral where it is the small one (`small_mu`), else from the
/// deficit; truncation (the pieces' estimates through the quotient) plus rounding.
fn ratio_of(total: &Sums, perm_deficit_magnitude: f64, small_mu: bool) -> crate::Result<(Ratio, f64)> {
    let (nn, dd) = (total.value[NORMAL], total.value[DEFICIT]);
    let reduction = if nn > 0.0 { dd / nn } else { 0.0 };
    let eps = f64::EPSILON;
    Ok(if small_mu {
        let tt = total.value[TANGENTIAL];
        let mu = tt / nn;
        let truncation = crate::ratio::quotient_error(nn, tt, total.error[NORMAL], total.error[TANGENTIAL]);
        // Each spring's <F> is a sum of non-negative terms (16 eps each), the
        // slip-first band's too (`foundation::Means::SlipFirst`).
        let rounding = crate::ratio::quotient_rounding(mu, total.nodes);
        let estimate = truncation + rounding;
        (Ratio::from_mu_within(mu, estimate, "power-law contact")?, estimate)
    } else {
        // Truncation (the pieces' estimates, propagated through dd/nn) plus
        // rounding: of the sums, and of each spring's deficit (a few ulps of
        // its terms, which exceed it where the stick is long).
        let rounding = crate::ratio::rounding_estimate(reduction, total.nodes)
            + 4.0 * eps * (total.magnitude + perm_deficit_magnitude) / nn;
        let truncation = crate::ratio::quotient_error(nn, dd, total.error[NORMAL], total.error[DEFICIT]);
        let estimate = truncation + rounding;
        (Ratio::from_deficit_within(dd, nn, estimate, "power-law contact")?, estimate)
    })
}

/// The bands of a report: extent and shares of the non-empty ones.
fn band_report(parts: &[(BandKind, [f64; 2], Sums)], nn: f64, tangential: f64) -> Vec<Band> {
    parts
        .iter()
        .filter(|p| p.1[1] > p.1[0])
        .map(|&(kind, x_range, s)| Band {
            kind,
            x_range,
            normal_share: if nn > 0.0 { s.value[NORMAL] / nn } else { 0.0 },
            tangential_share: if tangential > 0.0 { s.value[TANGENTIAL] / tangential } else { 0.0 },
            nodes: s.nodes,
        })
        .collect()
}

/// The stick-first band: in its springs' stick half-length where that variable
/// serves (`by_length`); below the centre's threshold, its part away from it
/// (`centre_by_length`); else in the contact phase, from `u_sf` to `u_low`.
fn stick_first_band(
    contact: &Foundation,
    vel: Option<Velocity>,
    perm: &Permanent,
    (u_sf, u_low): (f64, f64),
    near: (f64, f64),
    means: Means,
) -> Sums {
    let top = if u_sf == contact.u_star { contact.top_kind() } else { Top::Regular };
    let by_length = vel.filter(|v| {
        top == Top::Regular
            && v.vbar >= BY_LENGTH_MIN_VBAR
            && contact.singular_distance(u_sf, Top::Regular) >= BY_LENGTH_JACOBIAN_DISTANCE * (u_low - u_sf)
    });
    let centre_by_length = vel.filter(|v| top == Top::Centre && v.vbar >= BY_LENGTH_MIN_VBAR);
    match (by_length, centre_by_length) {
        (Some(v), _) => contact.band_by_length(&v, perm.tangent_half_length, v.delta, perm.sums.value),
        (None, Some(v)) => contact.band_centre_by_length(&v, u_sf, u_low, near, perm.sums.value),
        (None, None) => contact.band(u_sf, u_low, top, means, near, perm.sums.value),
    }
}

/// The total of the four bands, the closed-form normal force (`closed`)
/// replacing the quadrature's (and its error) where there is one.
fn total_of(parts: [&Sums; 4], closed: Option<f64>) -> Sums {
    let mut total = Sums::default();
    for p in parts {
        total += *p;
    }
    if let Some(nc) = closed {
        total.value[NORMAL] = nc;
        total.error[NORMAL] = 0.0;
    }
    total
}

/// The z of the stick-first band's top (`u_sf`), of its bottom (`u_low`) and of
/// the contact's edge; the slip-only band is empty where nothing slips only
/// (`u_low = pi` at vbar = 0), not an ulp wide from two roundings of the edge.
fn outer_edges(n: f64, amp: f64, u_sf: f64, u_low: f64, z_of_u: impl Fn(f64) -> f64) -> [f64; 3] {
    let z_outer = powf(1.0 + amp, 1.0 / n);
    let z_low = if u_low >= PI { z_outer } else { z_of_u(u_low) };
    [z_of_u(u_sf), z_low, z_outer]
}

/// Whether `mu` is the small one (reduction above 1/2: `vbar -> 0` with `amp`
/// near or above 1); then it comes from the tangential force's own integral:
/// `1 - dd/nn` would keep only the absolute accuracy of `dd`, whose terms are
/// far larger than `mu`. An internal error where the tangential force was not
/// integrated (`deficit_only`'s bound said the reduction is below
/// [`DEFICIT_ONLY_BELOW`]).
fn small_mu(total: &Sums, tangential: bool, (n, vbar, amp): (f64, f64, f64)) -> crate::Result<bool> {
    let reduction = if total.value[NORMAL] > 0.0 { total.value[DEFICIT] / total.value[NORMAL] } else { 0.0 };
    if reduction > 0.5 && !tangential {
        let what = format!("power law n = {n}, vbar = {vbar}, amp = {amp}: reduction {reduction} above its bound");
        return Err(crate::Error::Internal { what });
    }
    Ok(reduction > 0.5)
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
    if amp == 0.0 {
        return Ok(sliding(Some(foundation_force(n, 1.0))));
    }
    if vbar >= 1.0 && !bands {
        return Ok(sliding(total_normal(n, amp).map(unscale).filter(|x| x.is_finite())));
    }
    let vel = (vbar < 1.0).then(|| Velocity::new(vbar));
    let alpha = vel.map_or(0.0, |v| v.alpha);
    // In u = pi/2 - beta: the centre threshold y = 0 at u* (amp > 1), the
    // stick-first band's upper edge beta = alpha at u_alpha = arcsin(vbar).
    let u_alpha = vel.map_or(FRAC_PI_2, |v| v.delta);
    // Without the band report, a closed-form total normal force (cone, paraboloid)
    // replaces the bands' normal force (see `sum` below).
    let closed = if bands { None } else { total_normal(n, amp) };
    let mut contact = Foundation::new(n, amp, vel, tol);
    contact.normal = closed.is_none();
    let (u_star, top_kind) = (contact.u_star, contact.top_kind());
    let top_of = |u: f64| if u == u_star { top_kind } else { Top::Regular };
    let z_of_s = |s: f64| powf((1.0 - amp * s).clamp(0.0, 1.0 + amp), 1.0 / n);
    let z1 = z_of_s(1.0);
    let perm = permanent_band(n, vbar, amp, z1, closed);
    contact.tangential = perm.tangential;
    // Band edges from u: y(u) is cancellation-free where 1 - amp sqrt(1 - vbar^2) is not.
    let z_scale = if big { powf(amp, 1.0 / n) } else { 1.0 };
    let z_of_u = |u: f64| z_scale * powf(contact.y(u).max(0.0), 1.0 / n);
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
    let stick_means = if vel.is_some() { Means::StickFirst } else { Means::Slip };
    let stick_first = stick_first_band(&contact, vel, &perm, (u_sf, u_low), near, stick_means);
    let plus = |a: [f64; MEANS], b: &Sums| std::array::from_fn(|k| a[k] + b.value[k]);
    // Slip first: its deficit is D(vbar) per spring, in closed form.
    let d_perm = perm.deficit_per_spring;
    let slip_first_width = slip_first_width(&contact, n, amp, z1, u_sf, || z_of_u(u_sf));
    let slip_first_deficit = if big { d_perm * slip_first_width } else { amp * d_perm * slip_first_width };
    let slip_bands = |scale: [f64; MEANS]| {
        let means = Means::SlipFirst { excess: perm.excess };
        let mut first = contact.band(u_star, u_sf, top_of(u_star), means, (inf, inf), scale);
        first.value[DEFICIT] = slip_first_deficit;
        let only = contact.band(u_low, PI, top_of(u_low), Means::Slip, (inf, inf), plus(scale, &first));
        (first, only)
    };
    // With the closed form, the two slip bands are unnecessary where the
    // reduction is the small one: only the stick band needs springs solved.
    let scale1 = plus(perm.sums.value, &stick_first);
    let (mut slip_first, mut slip_only) = match closed {
        Some(_) => {
            let mut first = Sums::default();
            first.value[DEFICIT] = slip_first_deficit;
            (first, Sums::default())
        }
        None => slip_bands(scale1),
    };
    let sum = |parts: [&Sums; 4]| total_of(parts, closed);
    let mut total = sum([&perm.sums, &slip_first, &stick_first, &slip_only]);
    let small_mu = vel.is_some() && small_mu(&total, contact.tangential, (n, vbar, amp))?;
    if small_mu && closed.is_some() {
        (slip_first, slip_only) = slip_bands(scale1);
        total = sum([&perm.sums, &slip_first, &stick_first, &slip_only]);
    }
    let (ratio, error_estimate) = ratio_of(&total, perm.deficit_magnitude, small_mu)?;
    let nn = total.value[NORMAL];
    // The bands' edges only where they are reported (four powers a point).
    let band_list = if bands {
        let [z_sf, z_low, z_outer] = outer_edges(n, amp, u_sf, u_low, z_of_u);
        let parts = [
            (BandKind::PermanentContact, [0.0, z1], perm.sums),
            (if vel.is_some() { BandKind::SlipFirst } else { BandKind::SlipOnly }, [z1, z_sf], slip_first),
            (BandKind::StickFirst, [z_sf, z_low], stick_first),
            (BandKind::SlipOnly, [z_low, z_outer], slip_only),
        ];
        // Shares of the tangential force from its own (cancellation-free) sum: as
        // `nn - dd` they lost their relative accuracy with `mu` (the paraboloid's
        // one band at amp 2 held 0.62 of it at vbar 1e-16, and none at 1e-20).
        band_report(&parts, nn, total.value[TANGENTIAL])
    } else {
        vec![]
    };
    let mean_normal = Some(2.0 * unscale(nn)).filter(|x| x.is_finite());
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
/// (the seed's section 4). `src/fricosc/tests/library/mdr.rs` checks it against `power_law` at `vbar = 0`.
///
/// A failed or non-finite mean normal force is an error, never a value.
pub(crate) fn mu_static_ratio(n: f64, amp: f64, tol: f64) -> crate::Result<f64> {
    if amp == 0.0 {
        return Ok(1.0);
    }
    if amp >= 1.0 {
        return Ok(0.0);
    }
    // Both sides of the foundation: the minimum force is twice one side's.
    let nn = mean_normal_force(n, amp, tol)?.ok_or_else(|| crate::Error::Internal {
        what: format!("mean normal force of power:{n} at amp {amp} overflows"),
    })?;
    let mu = 2.0 * foundation_force(n, 1.0 - amp) / nn;
    Ok(Ratio::from_mu(mu, "static friction of a power-law contact")?.mu_ratio)
}

/// [`power_law`] with the bands and the static limit.
///
/// ```
/// use fricosc::{Conditions, Report, Shape};
/// // The cone (n = 1) at vbar = 0.3, du/u0 = 0.5: its bands carry the whole force.
/// let Report::Power(p) = Shape::cone().report(&Conditions::vbar(0.3, 0.5)?)? else { panic!() };
/// let shares: f64 = p.result.bands.iter().map(|b| b.normal_share).sum();
/// assert!((shares - 1.0).abs() < 1e-14);
/// # Ok::<(), fricosc::Error>(())
/// ```
///
/// # Errors
/// As [`power_law`].
pub(crate) fn point(n: f64, vbar: f64, amp: f64, tol: f64) -> crate::Result<MdrPoint> {
    check(n, vbar, amp)?;
    // mu_ratio and its estimate from the same call as every other command (one
    // value per input); the bands, normal force and node count from the banded run.
    let plain = power_law(n, vbar, amp, tol)?;
    // The bands at the velocity `power_law` solved at: below `VBAR_LINEAR` the
    // forces of a direct solve would be subnormal, and the shares are ratios
    // (independent of the scaling, `mu` being linear in `vbar` there).
    let at = crate::contact::VelocityScale::of(vbar, amp);
    let mut result = solve(n, at.vbar, amp, tol, Report::Bands)?;
    result.ratio = plain.ratio;
    result.error_estimate = plain.error_estimate;
    let mu_static_ratio = mu_static_ratio(n, amp, tol)?;
    Ok(MdrPoint { vbar, amp, result, mu_static_ratio })
}

#[cfg(test)]
mod tests;
