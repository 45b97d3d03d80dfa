//! Contacts: the flat punch (one spring), power-law profiles, a sphere worn
//! flat, and tabulated profiles by the method of dimensionality reduction.
//!
//! # Adding an indenter
//! A new indenter is one implementation of [`Contact`] (its MDR profile:
//! `equivalent_profile`, `reach`, `static_force`; and its solver `evaluate`)
//! and, to be named on the command line, one line in the registry of
//! [`crate::Shape::parse`]. A caller's own contact needs no registry:
//! [`crate::Shape::from_contact`]. [`FlatTip`] is the example: a sphere worn
//! flat at its tip.
use crate::error::Result;
use crate::ratio::Ratio;
use crate::shape::{Evaluation, Report};
use std::f64::consts::PI;

pub(crate) mod combined;
pub(crate) mod flat;
pub(crate) mod flat_tip;
pub(crate) mod history;
pub(crate) mod mdr;
pub(crate) mod profile;
pub(crate) mod regime;
pub(crate) mod shape;

pub use flat_tip::FlatTip;
pub use profile::{Table, Tabulated, MAX_TABLE_ROWS};
pub use shape::Reader;

/// A contact: its MDR geometry, and how `mu_macro/mu0` is solved for it.
///
/// A new shape describes its geometry ([`Contact::name`],
/// [`Contact::equivalent_profile`], [`Contact::reach`],
/// [`Contact::static_force`]; where `G` is not smooth,
/// [`Contact::breakpoints`]) and is solved by the banded integrator: every
/// spring's steady state in closed form, the bands between the regime
/// thresholds and the breakpoints by Gauss rules on the order ladder, with an
/// error estimate. Contacts with closed forms (the flat punch, power laws)
/// override the solving methods.
///
/// ```
/// use fricosc::contact::Contact;
/// use fricosc::{Conditions, Shape};
/// use std::sync::Arc;
///
/// /// The cone, described by its geometry alone: G(z) = z.
/// #[derive(Debug)]
/// struct MyCone;
/// impl Contact for MyCone {
///     fn name(&self) -> String {
///         "my-cone".into()
///     }
///     fn equivalent_profile(&self, z: f64) -> f64 {
///         z
///     }
///     fn reach(&self, amp: f64) -> fricosc::Result<f64> {
///         Ok(1.0 + amp)
///     }
///     /// 2 int_0^d (d - z) dz.
///     fn static_force(&self, depth: f64) -> f64 {
///         depth.max(0.0).powi(2)
///     }
/// }
///
/// let c = Conditions::vbar(0.3, 0.5)?;
/// let (mine, cone) = (Shape::from_contact(Arc::new(MyCone)).evaluate(&c)?, Shape::cone().evaluate(&c)?);
/// assert!((mine.ratio.mu_ratio - cone.ratio.mu_ratio).abs() <= mine.error_estimate + cone.error_estimate);
/// # Ok::<(), fricosc::Error>(())
/// ```
pub trait Contact: std::fmt::Debug + Send + Sync + std::panic::RefUnwindSafe {
    /// The canonical name, as it parses back (`flat-tip:0.5`).
    fn name(&self) -> String;

    /// The MDR equivalent profile in the contact's units, `G(z) = g(x_c z)/u0`
    /// (`G(1) = 1`, `x_c` the contact radius at the mean indentation `u0`),
    /// nondecreasing from `G(0) = 0`: the spring at `z` touches while the
    /// indentation exceeds `G(z) u0`. The flat punch is 0 on `z <= 1` and
    /// infinite beyond.
    fn equivalent_profile(&self, z: f64) -> f64;

    /// `z_max` with `G(z_max) = 1 + amp`: no spring beyond it ever touches (an
    /// error if the contact cannot reach that far, e.g. a table too short).
    ///
    /// # Errors
    /// The implementation's; the built-in contacts: [`crate::Error::InvalidParameter`]
    /// for an amplitude beyond a table's reach.
    fn reach(&self, amp: f64) -> Result<f64>;

    /// Static normal force at indentation `depth u0`,
    /// `2 int_0^inf (depth - G(z))_+ dz`, in units of `E* x_c u0` (both sides of
    /// the foundation; the flat punch's stiffness is `2 E* x_c`).
    fn static_force(&self, depth: f64) -> f64;

    /// `z` where `G(z) = level`, for a level the contact reaches: by default
    /// the root of `G(z) - level` bracketed by `0` and [`Contact::reach`].
    fn level(&self, level: f64) -> f64 {
        let hi = self.reach((level - 1.0).max(0.0)).unwrap_or(f64::NAN);
        crate::numerics::root::bracketed(|z| self.equivalent_profile(z) - level, 0.0, hi, 4.0 * f64::EPSILON).x
    }

    /// Where `G` is not smooth, or changes its scale (`z` values in `(0,
    /// reach)`): the bands are cut there. By default none.
    fn breakpoints(&self) -> Vec<f64> {
        vec![]
    }

    /// The largest amplitude the contact reaches ([`Contact::reach`] is an
    /// error beyond it): a table's deepest level less 1. By default unbounded.
    fn max_amp(&self) -> f64 {
        f64::INFINITY
    }

    /// The normal force averaged over a period at amplitude `amp`, in the units
    /// of [`Contact::static_force`]. By default the phase average
    /// `(1/pi) int_0^pi F(1 - amp cos tau) dtau` by Gauss-Legendre, on the part
    /// of the period in contact, graded at both ends (where `F` vanishes like a
    /// power of the depth); contacts with a closed form override it.
    ///
    /// # Errors
    /// The implementation's; the built-in contacts: [`crate::Error::InvalidParameter`]
    /// for an amplitude beyond a table's reach, [`crate::Error::Internal`] for a bug.
    fn mean_normal(&self, amp: f64) -> Result<f64> {
        crate::error::check_nonneg("amp", amp)?;
        let start = if amp > 1.0 { (1.0 / amp).acos() } else { 0.0 };
        let rule = crate::quad::rule(MEAN_NORMAL_ORDER, 0.0);
        let half = 0.5 * (PI - start);
        let mut sum = 0.0;
        for (&x, &w) in rule.nodes.iter().zip(&rule.weights) {
            let (st, ct) = (0.5 * PI * (1.0 + x)).sin_cos();
            let tau = start + half * (1.0 - ct);
            sum += w * half * st * 0.5 * PI * self.static_force(1.0 - amp * tau.cos());
        }
        Ok(sum / PI)
    }

    /// `mu_macro/mu0` with its error estimate; `vbar`, `amp` finite and `>= 0`,
    /// `tol` the relative quadrature tolerance. By default the banded
    /// integrator over the geometry, along `z`.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] for an amplitude beyond the contact's
    /// reach, [`crate::Error::Internal`] for a bug.
    fn evaluate(&self, vbar: f64, amp: f64, tol: f64) -> Result<Evaluation> {
        crate::error::check_nonneg("vbar", vbar)?;
        crate::error::check_nonneg("amp", amp)?;
        self.reach(amp)?;
        let (ratio, error_estimate) = crate::integrate::mdr::evaluate(&AlongZ(self), vbar, amp, tol, &self.name())?;
        Ok(Evaluation::of(ratio, error_estimate))
    }

    /// `mu_macro/mu0` alone (checked inputs): [`Contact::evaluate`]'s ratio, by
    /// default through it. A contact whose error estimate costs work of its own
    /// skips that work here (the flat punch: a batch of rows wants no estimate).
    ///
    /// # Errors
    /// As [`Contact::evaluate`].
    fn ratio(&self, vbar: f64, amp: f64, tol: f64) -> Result<crate::ratio::Ratio> {
        self.evaluate(vbar, amp, tol).map(|e| e.ratio)
    }

    /// Everything the solver reports about one point (checked inputs). By
    /// default the evaluation alone; the flat punch adds its events, power laws
    /// their bands.
    ///
    /// # Errors
    /// As [`Contact::evaluate`].
    fn point(&self, vbar: f64, amp: f64, tol: f64) -> Result<Report> {
        Ok(Report::Other { vbar, amp, evaluation: self.evaluate(vbar, amp, tol)? })
    }

    /// `mu_static/mu0`, the limit `vbar -> 0+` (the minimum normal force over
    /// its mean, seed section 4). By default the solver at `vbar = 0`.
    ///
    /// # Errors
    /// As [`Contact::evaluate`].
    fn mu_static(&self, amp: f64, tol: f64) -> Result<f64> {
        if amp >= 1.0 {
            // Every spring loses contact (G >= 0 puts every level at or below 1
            // <= amp) and sticks from contact to loss: exactly 0.
            crate::error::check_nonneg("amp", amp)?;
            return Ok(0.0);
        }
        Ok(self.evaluate(0.0, amp, tol)?.ratio.mu_ratio)
    }

    /// True if one spring represents the contact exactly (the flat punch): the
    /// time-stepping peer and histories then use one spring.
    fn single_spring(&self) -> bool {
        false
    }
}

/// A contact's profile along `z` itself, as the banded integrator takes it.
struct AlongZ<'a, C: ?Sized>(&'a C);

impl<C: Contact + ?Sized> crate::integrate::mdr::Profile for AlongZ<'_, C> {
    fn at(&self, z: f64) -> (f64, f64) {
        (self.0.equivalent_profile(z), 1.0)
    }
    fn level(&self, level: f64) -> f64 {
        self.0.level(level)
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.0.breakpoints()
    }
}

/// Gauss-Legendre order of the default [`Contact::mean_normal`]: the graded
/// integrand is smooth (a depth `c^(3/2)` becomes `theta^3`), and 64 points
/// reproduce the paraboloid's closed form to 2e-15 (`src/fricosc/tests/library/contact.rs`).
const MEAN_NORMAL_ORDER: usize = 64;

/// The foundation of `contact` discretised for the time-stepping peer and force
/// histories: `count` springs at the midpoints of a uniform grid on the part
/// that ever touches, `0 <= z < reach(amp)` (one spring for the flat punch).
/// Returns the spacing `dz` and `s(i) = (1 - G(z_i))/amp` (`amp > 0`).
pub(crate) fn grid(contact: &dyn Contact, amp: f64, count: usize) -> Result<(f64, impl Fn(usize) -> f64 + Sync + '_)> {
    let count = if contact.single_spring() { 1 } else { count.max(1) };
    let dz = contact.reach(amp)? / count as f64;
    // s = 1/amp overflows for a subnormal amp: the largest finite s is as good
    // (the spring never loses contact), as in `flat::spring_s`.
    Ok((dz, move |i: usize| ((1.0 - contact.equivalent_profile((i as f64 + 0.5) * dz)) / amp).min(f64::MAX)))
}

/// Below this amplitude an MDR contact's spring coordinate `s = (1 - G)/amp`
/// could overflow. The reduction is linear in `amp` there: every spring inside
/// the contact is in permanent contact, with a deficit (in units of `amp`) that
/// does not depend on `s`, and the jumping springs at the edge, a band of width
/// `O(amp)`, add `O(amp^2)`. So the tabulated and flat-tip contacts compute it
/// at this amplitude and scale it ([`crate::ratio::Ratio::scaled`]), with a
/// relative error of order `AMP_LINEAR` itself.
pub(crate) const AMP_LINEAR: f64 = 1e-300;

/// Below this velocity a curved contact at `amp >= 1` (where `mu -> 0` like
/// `vbar`) is solved at `vbar` scaled by a power of two to about
/// `[VBAR_LINEAR/2, VBAR_LINEAR)` and its `mu` scaled back ([`VelocityScale`]):
/// solved directly, its springs' forces of order `vbar` would go subnormal,
/// and `mu` lost its relative accuracy beyond what its estimate covered (the
/// paraboloid at `amp = 2, vbar = 1e-320`: 2.4056e-320 for 2.4079e-320,
/// estimate 0); at `amp = 1` the slip-first band's width (`vbar^2` in `y`)
/// underflows first: the paraboloid's `mu/vbar` was 2.5685834705770345 down
/// to vbar 1e-155, 2.5685883889 at 1e-160 and 3.45 at 1e-200, each with an
/// estimate of 1.7e-14 relative. `2^-400`, about `3.9e-121`: far above that,
/// and far below where `mu/vbar` still moves (its relative change is about
/// `15 vbar`).
pub(crate) const VBAR_LINEAR: f64 = f64::from_bits((1023 - 400) << 52);

/// How a curved contact treats a velocity below [`VBAR_LINEAR`] at `amp >= 1`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct VelocityScale {
    /// The velocity to solve at.
    pub(crate) vbar: f64,
    /// The power of two `vbar` was multiplied by (1: not scaled).
    factor: f64,
}

impl VelocityScale {
    /// The velocity to solve `(vbar, amp)` at.
    pub(crate) fn of(vbar: f64, amp: f64) -> VelocityScale {
        if amp >= 1.0 && vbar > 0.0 && vbar < VBAR_LINEAR {
            // 2^k with vbar 2^k in [VBAR_LINEAR/2, VBAR_LINEAR), up to the
            // rounding of log2 (a factor 2 either way changes nothing: `mu` is
            // linear there): k <= 675, so 2^k is finite and the product exact.
            let k = (VBAR_LINEAR.log2() - vbar.log2()).floor() as i32;
            let factor = 2f64.powi(k);
            VelocityScale { vbar: vbar * factor, factor }
        } else {
            VelocityScale { vbar, factor: 1.0 }
        }
    }

    /// The ratio and an error (estimate or interpolation) at the velocity
    /// asked for, from those at [`VelocityScale::vbar`]: `mu` divided by the
    /// factor (exact, but for the one rounding of a subnormal result), and
    /// the error likewise plus that rounding (at most half the smallest
    /// subnormal, which is added: its half rounds to 0) and the linearisation
    /// (`mu` times `1e3` times the scaled velocity, far above the observed
    /// `15 vbar`).
    pub(crate) fn back(self, ratio: Ratio, error: f64) -> (Ratio, f64) {
        if self.factor == 1.0 {
            return (ratio, error);
        }
        let mu = ratio.mu_ratio / self.factor;
        let error = error / self.factor + f64::from_bits(1) + 1e3 * self.vbar * mu;
        (Ratio { mu_ratio: mu, reduction: 1.0 - mu }, error)
    }
}

/// The flat cylindrical punch: one spring (seed section 2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FlatPunch;

impl Contact for FlatPunch {
    fn name(&self) -> String {
        "flat".into()
    }
    fn evaluate(&self, vbar: f64, amp: f64, _tol: f64) -> Result<Evaluation> {
        let ratio = flat::ratio(vbar, amp)?;
        Ok(Evaluation::of(ratio, shape::flat_error_estimate(&ratio)))
    }
    fn ratio(&self, vbar: f64, amp: f64, _tol: f64) -> Result<crate::ratio::Ratio> {
        flat::ratio(vbar, amp)
    }
    fn point(&self, vbar: f64, amp: f64, _tol: f64) -> Result<Report> {
        Ok(Report::Flat(flat::point(vbar, amp)?))
    }
    fn mu_static(&self, amp: f64, _tol: f64) -> Result<f64> {
        Ok(flat::mu_static_ratio(amp))
    }
    fn equivalent_profile(&self, z: f64) -> f64 {
        if z <= 1.0 {
            0.0
        } else {
            f64::INFINITY
        }
    }
    fn reach(&self, _amp: f64) -> Result<f64> {
        Ok(1.0)
    }
    fn static_force(&self, depth: f64) -> f64 {
        2.0 * depth.max(0.0)
    }
    fn mean_normal(&self, amp: f64) -> Result<f64> {
        crate::error::check_nonneg("amp", amp)?;
        Ok(2.0 * flat::mean_normal(amp))
    }
    fn single_spring(&self) -> bool {
        true
    }
}

/// The MDR power-law profile `g ~ |x|^n`, solved in analytic bands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLaw {
    /// The exponent `n` (1: cone, 2: paraboloid).
    pub n: f64,
}

impl Contact for PowerLaw {
    fn name(&self) -> String {
        if self.n == 2.0 {
            "parabolic".into()
        } else if self.n == 1.0 {
            "cone".into()
        } else {
            format!("power:{:?}", self.n)
        }
    }
    fn evaluate(&self, vbar: f64, amp: f64, tol: f64) -> Result<Evaluation> {
        let r = mdr::power_law(self.n, vbar, amp, tol)?;
        Ok(Evaluation::of(r.ratio, r.error_estimate))
    }
    fn point(&self, vbar: f64, amp: f64, tol: f64) -> Result<Report> {
        Ok(Report::Power(mdr::point(self.n, vbar, amp, tol)?))
    }
    fn mu_static(&self, amp: f64, tol: f64) -> Result<f64> {
        mdr::mu_static_ratio(self.n, amp, tol)
    }
    fn equivalent_profile(&self, z: f64) -> f64 {
        z.powf(self.n)
    }
    fn reach(&self, amp: f64) -> Result<f64> {
        Ok((1.0 + amp).powf(1.0 / self.n))
    }
    fn static_force(&self, depth: f64) -> f64 {
        2.0 * mdr::foundation_force(self.n, depth)
    }
    fn mean_normal(&self, amp: f64) -> Result<f64> {
        mdr::mean_normal_force(self.n, amp, crate::DEFAULT_TOL)?
            .ok_or_else(|| crate::Error::param("amp", amp, "the mean normal force overflows double precision"))
    }
}

impl Contact for profile::Tabulated {
    fn name(&self) -> String {
        self.name().to_string()
    }
    fn evaluate(&self, vbar: f64, amp: f64, tol: f64) -> Result<Evaluation> {
        let r = profile::evaluate(self, vbar, amp, tol)?;
        Ok(Evaluation { interpolation_error: Some(r.interpolation_error), ..Evaluation::of(r.ratio, r.error_estimate) })
    }
    fn equivalent_profile(&self, z: f64) -> f64 {
        profile::equivalent_profile(self, z)
    }
    fn reach(&self, amp: f64) -> Result<f64> {
        profile::reach(self, amp)
    }
    /// The interpolant's own inverse.
    fn level(&self, level: f64) -> f64 {
        profile::level(self, level)
    }
    fn max_amp(&self) -> f64 {
        profile::max_amp(self)
    }
    fn static_force(&self, depth: f64) -> f64 {
        profile::static_force(self, depth)
    }
    fn mean_normal(&self, amp: f64) -> Result<f64> {
        profile::mean_normal(self, amp)
    }

    /// The table's knots.
    fn breakpoints(&self) -> Vec<f64> {
        profile::knots(self)
    }
}

impl PowerLaw {
    /// The power law of `power:N`: `N` finite within [[`shape::MIN_EXPONENT`], [`shape::MAX_EXPONENT`]].
    pub(crate) fn parse(rest: &str, spec: &str) -> Result<PowerLaw> {
        let bad = |reason: &str| crate::Error::InvalidShape { spec: spec.into(), reason: reason.into() };
        let n: f64 = rest.trim().parse().map_err(|_| bad("the exponent is not a number"))?;
        if !n.is_finite() || n <= 0.0 {
            Err(bad("the exponent must be finite and > 0"))
        } else if !(shape::MIN_EXPONENT..=shape::MAX_EXPONENT).contains(&n) {
            Err(bad("the exponent must be within [0.05, 1e6] (power:N tends to flat as N grows)"))
        } else {
            Ok(PowerLaw { n })
        }
    }
}
