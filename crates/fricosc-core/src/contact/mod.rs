//! Contacts: the flat punch (one spring), power-law profiles and tabulated
//! profiles by the method of dimensionality reduction, and [`shape::Shape`].
//!
//! # Adding an indenter
//! A new analytic indenter is one file implementing [`Contact`] and one line in
//! [`REGISTRY`] (its name prefix and its parser); [`shape::Shape::parse`] then
//! accepts it everywhere a shape is named (`point`, `table`, `batch`,
//! `validate`). [`flat_tip`] is the example: a sphere worn flat at its tip.
use crate::error::Result;
use crate::shape::Evaluation;
use std::sync::Arc;

pub mod flat;
pub mod flat_tip;
pub mod mdr;
pub mod profile;
pub mod shape;

/// A contact geometry: `mu_macro/mu0` as a function of `vbar` (eq. 3) and
/// `amp = du/u0`.
pub trait Contact: std::fmt::Debug + Send + Sync + std::panic::RefUnwindSafe {
    /// The canonical name, as it parses back (`flat-tip:0.5`).
    fn name(&self) -> String;

    /// `mu_macro/mu0` with its error estimate; `vbar`, `amp` finite and `>= 0`,
    /// `tol` the relative quadrature tolerance.
    fn evaluate(&self, vbar: f64, amp: f64, tol: f64) -> Result<Evaluation>;

    /// `mu_static/mu0`, the limit `vbar -> 0+` (the minimum normal force over
    /// its mean, seed section 4). By default the solver at `vbar = 0`.
    fn mu_static(&self, amp: f64, tol: f64) -> Result<f64> {
        Ok(self.evaluate(0.0, amp, tol)?.ratio.mu_ratio)
    }
}

/// `(int <B> w dx, int D w dx)` over `x` in `[p, q]` of the springs `s(x)`
/// (`spring(x) = (s, w)`, `w` a Jacobian), times `unit`, by Gauss-Legendre of
/// order `m` in `theta` with `x = p + (q - p)(1 - cos theta)/2`: the substitution
/// absorbs the square-root behaviour of the means where a band ends at a
/// contact-loss threshold (`s = +-1`). Shared by the tabulated and flat-tip contacts.
pub(crate) fn cosine_band(
    p: f64,
    q: f64,
    m: usize,
    vbar: f64,
    unit: f64,
    spring: &dyn Fn(f64) -> (f64, f64),
) -> (f64, f64) {
    let rule = crate::quad::rule(m, 0.0);
    let half = 0.5 * (q - p);
    let (mut sn, mut sd) = (0.0, 0.0);
    for (&x, &w) in rule.nodes.iter().zip(&rule.weights) {
        let (st, ct) = (0.5 * std::f64::consts::PI * (1.0 + x)).sin_cos();
        let (s, jac) = spring(p + half * (1.0 - ct));
        let sp = crate::spring::Spring::new(s, vbar);
        let weight = w * half * st * jac;
        sn += weight * unit * sp.mean_normal;
        sd += weight * unit * sp.deficit;
    }
    (0.5 * std::f64::consts::PI * sn, 0.5 * std::f64::consts::PI * sd)
}

/// Below this amplitude an MDR contact's spring coordinate `s = (1 - G)/amp`
/// could overflow. The reduction is linear in `amp` there: every spring inside
/// the contact is in permanent contact, with a deficit (in units of `amp`) that
/// does not depend on `s`, and the jumping springs at the edge, a band of width
/// `O(amp)`, add `O(amp^2)`. So the tabulated and flat-tip contacts compute it
/// at this amplitude and scale it ([`crate::ratio::Ratio::scaled`]), with a
/// relative error of order `AMP_LINEAR` itself.
pub const AMP_LINEAR: f64 = 1e-300;

/// A parser of the part of a shape specification after its prefix.
pub type Parser = fn(&str) -> Result<Arc<dyn Contact>>;

/// The flat cylindrical punch: one spring (seed section 2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FlatPunch;

impl Contact for FlatPunch {
    fn name(&self) -> String {
        "flat".into()
    }
    fn evaluate(&self, vbar: f64, amp: f64, _tol: f64) -> Result<Evaluation> {
        let ratio = flat::ratio(vbar, amp)?;
        Ok(Evaluation { ratio, error_estimate: shape::flat_error_estimate(&ratio), interpolation_error: None })
    }
    fn mu_static(&self, amp: f64, _tol: f64) -> Result<f64> {
        Ok(flat::mu_static_ratio(amp))
    }
}

/// The MDR power-law profile `g ~ |x|^n` ([`mdr`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLaw {
    /// The exponent `n` (1: cone, 2: paraboloid).
    pub n: f64,
}

impl Contact for PowerLaw {
    fn name(&self) -> String {
        shape::Shape::Power(self.n).name()
    }
    fn evaluate(&self, vbar: f64, amp: f64, tol: f64) -> Result<Evaluation> {
        let r = mdr::power_law(self.n, vbar, amp, tol, false)?;
        Ok(Evaluation { ratio: r.ratio, error_estimate: r.error_estimate, interpolation_error: None })
    }
    fn mu_static(&self, amp: f64, tol: f64) -> Result<f64> {
        Ok(mdr::mu_static_ratio(self.n, amp, tol))
    }
}

impl Contact for profile::Tabulated {
    fn name(&self) -> String {
        "tabulated".into()
    }
    fn evaluate(&self, vbar: f64, amp: f64, _tol: f64) -> Result<Evaluation> {
        let r = profile::evaluate(self, vbar, amp)?;
        Ok(Evaluation {
            ratio: r.ratio,
            error_estimate: r.error_estimate,
            interpolation_error: Some(r.interpolation_error),
        })
    }
}

/// Shapes implemented through [`Contact`]: name prefix and parser.
pub const REGISTRY: &[(&str, Parser)] = &[("flat-tip:", flat_tip::parse)];
