//! Indenter shapes: one [`Shape`] type for every contact, built from a name as
//! the command line writes it, or from a [`Contact`] of the caller's own.

use super::{Contact, FlatPunch, PowerLaw};
use crate::conditions::Conditions;
use crate::error::{Error, Result};
use crate::ratio::Ratio;
use std::sync::Arc;

/// Smallest accepted power-law exponent: below it the weights `y^(1/n - 1)` are so
/// concentrated at the contact edge that neither this solver nor the independent
/// reference quadrature of the tests agree for `amp > 1` (checked down to 0.03).
pub const MIN_EXPONENT: f64 = 0.05;
/// Largest accepted power-law exponent: beyond it `1/n - 1` rounds towards -1 and
/// the centre's weight stops being integrable in f64; such a profile is the flat
/// punch to within `O(1/N)`.
pub const MAX_EXPONENT: f64 = 1e6;

/// The reader of the files a shape or scene names (`profile:FILE@U0`): the
/// library reads no files itself. [`crate::io::read_capped`] is one.
pub type Reader<'a> = &'a dyn Fn(&str) -> std::io::Result<String>;

/// A contact geometry: the flat punch, a power law, a worn tip, a tabulated
/// profile, or any [`Contact`] of the caller's. Two shapes are equal when their
/// names are.
///
/// ```
/// use fricosc::{Conditions, Shape};
/// let hertz = Shape::parse("parabolic")?;
/// assert_eq!(hertz, Shape::parabolic());
/// let e = hertz.evaluate(&Conditions::vbar(0.3, 0.4)?)?;
/// assert!((e.ratio.mu_ratio - 0.7661542311590507).abs() < 1e-15);
/// # Ok::<(), fricosc::Error>(())
/// ```
#[derive(Clone)]
pub struct Shape {
    contact: Arc<dyn Contact>,
    name: String,
}

impl std::fmt::Debug for Shape {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Shape({})", self.name)
    }
}

impl PartialEq for Shape {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

/// A parser of a shape's name after its prefix (`2.5` of `power:2.5`).
type Parser = fn(rest: &str, spec: &str, read: Reader) -> Result<Arc<dyn Contact>>;

/// Every shape name: an exact name or a prefix, and its parser. The one place
/// a shape is added (with its [`Contact`] implementation).
const REGISTRY: &[(&str, Parser)] = &[
    ("flat", |_, _, _| Ok(Arc::new(FlatPunch))),
    ("parabolic", |_, _, _| Ok(Arc::new(PowerLaw { n: 2.0 }))),
    ("cone", |_, _, _| Ok(Arc::new(PowerLaw { n: 1.0 }))),
    ("power:", |rest, spec, _| PowerLaw::parse(rest, spec).map(|p| Arc::new(p) as Arc<dyn Contact>)),
    ("flat-tip:", |rest, _, _| super::flat_tip::parse(rest)),
    ("profile:", |rest, spec, read| super::profile::parse_shape(rest, spec, true, read)),
    ("gx:", |rest, spec, read| super::profile::parse_shape(rest, spec, false, read)),
];

impl Shape {
    /// The flat cylindrical punch (one spring; seed section 2).
    #[must_use]
    pub fn flat() -> Shape {
        Shape::from_contact(Arc::new(FlatPunch))
    }

    /// The paraboloid (Hertz; MDR profile `g ~ x^2`).
    #[must_use]
    pub fn parabolic() -> Shape {
        Shape::from_contact(Arc::new(PowerLaw { n: 2.0 }))
    }

    /// The cone (MDR profile `g ~ |x|`).
    #[must_use]
    pub fn cone() -> Shape {
        Shape::from_contact(Arc::new(PowerLaw { n: 1.0 }))
    }

    /// The power law `g ~ |x|^n`.
    ///
    /// # Errors
    /// [`Error::InvalidShape`] for `n` outside [[`MIN_EXPONENT`], [`MAX_EXPONENT`]].
    pub fn power(n: f64) -> Result<Shape> {
        let spec = format!("power:{n:?}");
        Ok(Shape::from_contact(Arc::new(PowerLaw::parse(&format!("{n:?}"), &spec)?)))
    }

    /// A shape from a contact of the caller's, named by [`Contact::name`].
    pub fn from_contact(contact: Arc<dyn Contact>) -> Shape {
        let name = contact.name();
        Shape { contact, name }
    }

    /// Parse `flat`, `parabolic`, `cone`, `power:N` or `flat-tip:E`. Tabulated
    /// shapes name a file: they need [`Shape::parse_with`].
    ///
    /// # Errors
    /// [`Error::InvalidShape`] for an unknown or malformed name.
    pub fn parse(spec: &str) -> Result<Shape> {
        Self::parse_with(spec, &|path: &str| {
            Err(std::io::Error::new(
                std::io::ErrorKind::Unsupported,
                format!("{path:?}: tabulated shapes need a reader (Shape::parse_with)"),
            ))
        })
    }

    /// Parse any shape: those of [`Shape::parse`], and a tabulated
    /// `profile:FILE@U0` (an axisymmetric profile `f(r)`) or `gx:FILE@U0` (an
    /// MDR profile `g(x)`), whose file's text `read(FILE)` supplies.
    ///
    /// ```
    /// use fricosc::Shape;
    /// let text = "r,f\n0,0\n0.5,0.125\n1,0.5\n"; // f = r^2/2
    /// let s = Shape::parse_with("profile:table@0.3", &|_| Ok(text.to_string()))?;
    /// assert_eq!(s.name(), "profile:table@0.3");
    /// # Ok::<(), fricosc::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidShape`] for an unknown or malformed name, [`Error::File`]
    /// when the reader fails, [`Error::Parse`] for a malformed table.
    pub fn parse_with(spec: &str, read: Reader) -> Result<Shape> {
        let spec = spec.trim();
        let entry =
            REGISTRY.iter().find(|(key, _)| if key.ends_with(':') { spec.starts_with(key) } else { spec == *key });
        let Some((key, parse)) = entry else {
            return Err(Error::InvalidShape {
                spec: spec.into(),
                reason:
                    "unknown shape (known: flat, parabolic, cone, power:N, flat-tip:E, profile:FILE@U0, gx:FILE@U0)"
                        .into(),
            });
        };
        Ok(Shape::from_contact(parse(&spec[key.len()..], spec, read)?))
    }

    /// The canonical name, as it parses back (`parabolic`, `power:2.5`).
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The shape's contact.
    #[must_use]
    pub fn contact(&self) -> &dyn Contact {
        self.contact.as_ref()
    }

    /// True for the flat punch (one spring represents the contact exactly).
    #[must_use]
    pub fn is_flat(&self) -> bool {
        self.contact.single_spring()
    }

    /// `mu_macro/mu0` under the conditions `c`, with an error estimate:
    /// the one way in. Without a tangential oscillation the seed's problem
    /// at `vbar`; with one, the stop operator of every spring; with the body
    /// on a system ([`Conditions::with_system`]), its attractor.
    ///
    /// ```
    /// use fricosc::{Conditions, Shape};
    /// let e = Shape::cone().evaluate(&Conditions::vbar(0.3, 0.5)?.with_tol(1e-9)?)?;
    /// assert!(e.error_estimate < 1e-9 && e.ratio.mu_ratio > 0.5);
    /// # Ok::<(), fricosc::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an amplitude beyond a tabulated
    /// profile, or `vbar = vhat/amp` undefined (`amp = 0` without a
    /// tangential oscillation); [`Error::Internal`] for a bug.
    pub fn evaluate(&self, c: &Conditions) -> Result<Evaluation> {
        if let Some(w) = c.transverse() {
            let r = crate::plane::solve(self, c, w, false)?;
            return Ok(Evaluation {
                transverse_ratio: Some(r.transverse_ratio),
                ..Evaluation::of(r.ratio, r.error_estimate)
            });
        }
        if let Some(sys) = c.system() {
            let r = crate::system::solve(self, c, sys)?;
            return Ok(Evaluation::of(r.ratio(), r.error_estimate));
        }
        match c.tangential() {
            Some(_) => {
                let r = super::combined::evaluate(self, c)?;
                Ok(Evaluation::of(r.ratio, r.error_estimate))
            }
            None => self.contact.evaluate(c.as_vbar()?, c.amp(), c.tol()),
        }
    }

    /// [`Shape::evaluate`]'s ratio without its error estimate: the same
    /// numbers, less work where the estimate costs any (a batch of rows).
    ///
    /// # Errors
    /// As [`Shape::evaluate`].
    pub fn ratio(&self, c: &Conditions) -> Result<Ratio> {
        if c.transverse().is_some() {
            return Ok(self.evaluate(c)?.ratio);
        }
        if let Some(sys) = c.system() {
            return Ok(crate::system::solve(self, c, sys)?.ratio());
        }
        match c.tangential() {
            Some(_) => Ok(super::combined::evaluate(self, c)?.ratio),
            None => self.contact.ratio(c.as_vbar()?, c.amp(), c.tol()),
        }
    }

    /// Everything the solver reports about one point: the flat punch's regime
    /// and events, a power law's bands, under a tangential oscillation the
    /// flat punch's phases or a curved contact's bands; on a system the
    /// attractor ([`crate::system::SystemReport`]); else the evaluation.
    ///
    /// # Errors
    /// As [`Shape::evaluate`].
    pub fn report(&self, c: &Conditions) -> Result<Report> {
        if let Some(w) = c.transverse() {
            return Ok(Report::Plane(crate::plane::solve(self, c, w, true)?));
        }
        if let Some(sys) = c.system() {
            return Ok(Report::System(crate::system::solve(self, c, sys)?));
        }
        match c.tangential() {
            Some((t, phase)) => Ok(Report::Tangential(crate::report::Tangential {
                vhat: c.as_vhat(),
                amp: c.amp(),
                tangential_amp: t,
                phase,
                result: super::combined::evaluate(self, c)?,
            })),
            None => self.contact.point(c.as_vbar()?, c.amp(), c.tol()),
        }
    }

    /// Whether the shape reaches the amplitude `amp` (a tabulated profile
    /// must reach the contact's edge, `G = 1 + amp`): the check a batch makes
    /// of each row before it writes anything.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an amplitude beyond a tabulated profile.
    pub fn check_amp(&self, amp: f64) -> Result<()> {
        if amp > self.contact.max_amp() {
            self.contact.reach(amp)?;
        }
        Ok(())
    }

    /// `mu_static/mu0`, the limit `vbar -> 0+` (the minimum normal force over
    /// its mean), at amplitude `amp` and quadrature tolerance `tol`.
    ///
    /// # Errors
    /// As [`Shape::evaluate`], and for a bad `amp` or `tol`.
    pub fn mu_static(&self, amp: f64, tol: f64) -> Result<f64> {
        let c = Conditions::vbar(0.0, amp)?.with_tol(tol)?;
        self.contact.mu_static(c.amp(), c.tol())
    }
}

/// `mu_macro/mu0` of a shape with an error estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct Evaluation {
    /// Ratio and reduction.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub ratio: Ratio,
    /// Estimated absolute error of `mu_ratio` (a bound in every test).
    pub error_estimate: f64,
    /// For tabulated shapes: the estimated error that interpolating the table adds.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub interpolation_error: Option<f64>,
    /// Under an oscillation across the sliding direction: `<f_y>/<B>`, the
    /// mean force across it (the same error estimate).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub transverse_ratio: Option<f64>,
}

impl Evaluation {
    /// A ratio with its estimate and nothing else.
    pub(crate) fn of(ratio: Ratio, error_estimate: f64) -> Evaluation {
        Evaluation { ratio, error_estimate, interpolation_error: None, transverse_ratio: None }
    }
}

/// Everything the solver reports about one point ([`Shape::report`]): the
/// flat punch's regime and events, a power law's bands, under a tangential
/// oscillation the spring's phases or the bands, or, for other shapes, the
/// evaluation with its error estimates. Serialised (feature `serde`) as one
/// flat object: `fricosc point`'s output.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(untagged))]
#[non_exhaustive]
pub enum Report {
    /// The flat punch.
    Flat(crate::report::FlatPoint),
    /// A power-law profile.
    Power(crate::report::MdrPoint),
    /// Any shape under an oscillation in the sliding direction.
    Tangential(crate::report::Tangential),
    /// Any shape with the body on a system ([`Conditions::with_system`]): its attractor.
    System(crate::system::SystemReport),
    /// The flat punch under an oscillation across the sliding direction
    /// ([`Conditions::with_transverse`]).
    Plane(crate::plane::PlaneEvaluation),
    /// Any other shape.
    Other {
        /// Dimensionless velocity.
        vbar: f64,
        /// Amplitude `du/u0`.
        amp: f64,
        /// The evaluation.
        #[cfg_attr(feature = "serde", serde(flatten))]
        evaluation: Evaluation,
    },
}

impl Report {
    /// `mu_macro/mu0` and the reduction.
    #[must_use]
    pub fn ratio(&self) -> Ratio {
        match self {
            Report::Flat(p) => p.ratio,
            Report::Power(p) => p.result.ratio,
            Report::Tangential(t) => t.result.ratio,
            Report::System(r) => r.ratio(),
            Report::Plane(p) => p.ratio,
            Report::Other { evaluation, .. } => evaluation.ratio,
        }
    }
}

/// Absolute error estimate of the flat punch's `mu_ratio`: the smaller of
/// `mu_ratio` and the reduction is computed directly with relative error at
/// most [`crate::ratio::ROUNDING_PER_TERM`] eps (measured: 3.3 eps,
/// `src/fricosc/tests/library/flat_events.rs`), the other as its complement. So where `mu_ratio` is
/// the small one its error is `16 eps mu_ratio` (relative, down to the smallest
/// subnormals, whose own spacing is added), else `eps (16 reduction + 1/2)`
/// (the complement adds half an ulp of 1).
pub(crate) fn flat_error_estimate(r: &Ratio) -> f64 {
    let per_term = crate::ratio::ROUNDING_PER_TERM;
    if r.mu_ratio < 0.5 {
        f64::EPSILON * per_term * r.mu_ratio + per_term * f64::from_bits(1)
    } else {
        f64::EPSILON * (per_term * r.reduction + 0.5)
    }
}
