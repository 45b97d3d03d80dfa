//! Indenter shapes, as named on the command line and in batch files.

use crate::error::{check_nonneg, Error, Result};
use crate::flat::Ratio;
use crate::mdr;

/// Smallest accepted power-law exponent: below it the weights `y^(1/n - 1)` are so
/// concentrated at the contact edge that neither this solver nor the independent
/// reference quadrature of the tests agree for `amp > 1` (checked down to 0.03).
pub const MIN_EXPONENT: f64 = 0.05;
/// Largest accepted power-law exponent: beyond it `1/n - 1` rounds towards -1 and
/// the centre's weight stops being integrable in f64; such a profile is the flat
/// punch to within `O(1/N)`.
pub const MAX_EXPONENT: f64 = 1e6;

/// A contact geometry.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Flat cylindrical punch: one spring (seed section 2).
    Flat,
    /// MDR equivalent profile `g ~ |x|^n`, `n > 0` (`cone`: 1, `parabolic`: 2).
    Power(f64),
    /// A tabulated profile (`profile:FILE@U0`) or equivalent profile (`gx:FILE@U0`).
    Tabulated(std::sync::Arc<crate::profile::Tabulated>, String),
    /// A shape implemented through [`crate::contact::Contact`] (see [`crate::contact::REGISTRY`]).
    Registered(Registered),
}

/// A [`crate::contact::Contact`] held by a [`Shape`]; two are equal when their names are.
#[derive(Debug, Clone)]
pub struct Registered(pub std::sync::Arc<dyn crate::contact::Contact>);

impl PartialEq for Registered {
    fn eq(&self, other: &Self) -> bool {
        self.0.name() == other.0.name()
    }
}

impl Shape {
    /// Parse `flat`, `parabolic`, `cone`, `power:N` (`N` finite, `> 0`) or a
    /// registered shape (`flat-tip:E`). Tabulated shapes name a file, and the
    /// core reads no files: they need [`Shape::parse_with`].
    pub fn parse(spec: &str) -> Result<Shape> {
        Self::parse_with(spec, &|path: &str| {
            Err(Error::InvalidShape {
                spec: spec.trim().into(),
                reason: format!("cannot read {path:?}: tabulated shapes need a reader (Shape::parse_with)"),
            })
        })
    }

    /// Parse any shape: those of [`Shape::parse`], and a tabulated
    /// `profile:FILE@U0` / `gx:FILE@U0` (see [`crate::profile`]), whose file's
    /// text `read(FILE)` supplies.
    ///
    /// ```
    /// use fricosc::shape::Shape;
    /// let text = "r,f\n0,0\n0.5,0.125\n1,0.5\n"; // f = r^2/2
    /// let s = Shape::parse_with("profile:table@0.3", &|_| Ok(text.to_string())).unwrap();
    /// assert!(matches!(s, Shape::Tabulated(..)));
    /// ```
    pub fn parse_with(spec: &str, read: &dyn Fn(&str) -> Result<String>) -> Result<Shape> {
        let bad = |reason: &str| Error::InvalidShape { spec: spec.trim().into(), reason: reason.into() };
        match spec.trim() {
            "flat" => Ok(Shape::Flat),
            "parabolic" => Ok(Shape::Power(2.0)),
            "cone" => Ok(Shape::Power(1.0)),
            other if other.starts_with("profile:") || other.starts_with("gx:") => {
                let profile = other.starts_with("profile:");
                let rest = other.split_once(':').map_or("", |p| p.1);
                let (path, u0) = rest
                    .rsplit_once('@')
                    .ok_or_else(|| bad("needs the mean indentation: profile:FILE@U0 or gx:FILE@U0"))?;
                let u0: f64 = u0.trim().parse().map_err(|_| bad("the mean indentation after '@' is not a number"))?;
                let t = crate::profile::Table::parse(&read(path)?, path, profile)?.at(u0)?;
                Ok(Shape::Tabulated(std::sync::Arc::new(t), other.to_string()))
            }
            other if crate::contact::REGISTRY.iter().any(|(p, _)| other.starts_with(p)) => {
                let (prefix, parse) = crate::contact::REGISTRY
                    .iter()
                    .find(|(p, _)| other.starts_with(p))
                    .ok_or_else(|| bad("unknown shape"))?;
                Ok(Shape::Registered(Registered(parse(&other[prefix.len()..])?)))
            }
            other => match other.strip_prefix("power:") {
                Some(n) => {
                    let n: f64 = n.trim().parse().map_err(|_| bad("the exponent is not a number"))?;
                    if !n.is_finite() || n <= 0.0 {
                        Err(bad("the exponent must be finite and > 0"))
                    } else if !(MIN_EXPONENT..=MAX_EXPONENT).contains(&n) {
                        Err(bad("the exponent must be within [0.05, 1e6] (power:N tends to flat as N grows)"))
                    } else {
                        Ok(Shape::Power(n))
                    }
                }
                None => Err(bad(
                    "unknown shape (known: flat, parabolic, cone, power:N, flat-tip:E, profile:FILE@U0, gx:FILE@U0)",
                )),
            },
        }
    }

    /// Run `f` on the shape's [`Contact`](crate::contact::Contact): every
    /// evaluation goes through the trait (the enum only adds what the trait does
    /// not cover: the stepping peer, histories and scenes of the built-in shapes).
    pub fn with_contact<T>(&self, f: impl FnOnce(&dyn crate::contact::Contact) -> T) -> T {
        match self {
            Shape::Flat => f(&crate::contact::FlatPunch),
            Shape::Power(n) => f(&crate::contact::PowerLaw { n: *n }),
            Shape::Tabulated(t, _) => f(t.as_ref()),
            Shape::Registered(c) => f(c.0.as_ref()),
        }
    }

    /// `mu_static/mu0` of the shape (the limit `vbar -> 0+`).
    pub fn mu_static(&self, amp: f64, tol: f64) -> Result<f64> {
        self.with_contact(|c| c.mu_static(amp, tol))
    }

    /// The canonical name as printed in outputs.
    pub fn name(&self) -> String {
        match self {
            Shape::Flat => "flat".into(),
            Shape::Power(n) if *n == 2.0 => "parabolic".into(),
            Shape::Power(n) if *n == 1.0 => "cone".into(),
            Shape::Power(n) => format!("power:{n:?}"),
            Shape::Tabulated(_, spec) => spec.clone(),
            Shape::Registered(c) => c.0.name(),
        }
    }
}

/// `mu_macro/mu0` of a shape with an error estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Evaluation {
    /// Ratio and reduction.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub ratio: Ratio,
    /// Estimated absolute error of `mu_ratio`.
    pub error_estimate: f64,
    /// For tabulated shapes: the estimated error that interpolating the table adds.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub interpolation_error: Option<f64>,
}

/// Everything the solver reports about one point: the flat punch's regime and
/// events ([`crate::flat::FlatPoint`]), a power law's bands ([`crate::mdr::MdrPoint`]),
/// or, for other shapes, the evaluation with its error estimates. Serialised
/// (feature `serde`) as one flat object: `fricosc point`'s output and the
/// Python package's `point()`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(untagged))]
pub enum Point {
    /// The flat punch.
    Flat(crate::flat::FlatPoint),
    /// A power-law profile.
    Power(crate::mdr::MdrPoint),
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

/// The detailed [`Point`] of `shape` at `(vbar, amp)`, `tol` as in [`evaluate_with`].
pub fn point(shape: &Shape, vbar: f64, amp: f64, tol: f64) -> Result<Point> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    check_tol(tol)?;
    Ok(match shape {
        Shape::Flat => Point::Flat(crate::flat::point(vbar, amp)?),
        Shape::Power(n) => Point::Power(crate::mdr::point(*n, vbar, amp, tol)?),
        Shape::Tabulated(..) | Shape::Registered(..) => {
            Point::Other { vbar, amp, evaluation: evaluate_with(shape, vbar, amp, tol)? }
        }
    })
}

/// Absolute error estimate of the flat punch's `mu_ratio`: one of `mu_ratio`
/// and the reduction is computed directly with relative error at most
/// [`crate::ratio::ROUNDING_PER_TERM`] eps (measured: 3.3 eps,
/// `tests/flat_events.rs`), the other as its complement, which adds half an ulp
/// of 1; so `eps (16 max(mu, reduction) + 1/2)` bounds either. (Where `mu_ratio`
/// is the small one of a jumping punch its relative error is 16 eps itself.)
pub fn flat_error_estimate(r: &Ratio) -> f64 {
    f64::EPSILON * (crate::ratio::ROUNDING_PER_TERM * r.mu_ratio.max(r.reduction) + 0.5)
}

/// Evaluate `mu_macro/mu0` at the default tolerance.
///
/// ```
/// use fricosc::shape::{evaluate, Shape};
/// // The parabolic (Hertz) contact at vbar = 0.3, du/u0 = 0.4, and a worn sphere.
/// let e = evaluate(&Shape::parse("parabolic").unwrap(), 0.3, 0.4).unwrap();
/// assert!((e.ratio.mu_ratio - 0.7661542311590507).abs() < 1e-15);
/// assert!(e.error_estimate < 1e-14);
/// let worn = evaluate(&Shape::parse("flat-tip:0.5").unwrap(), 0.3, 0.4).unwrap();
/// assert!(worn.ratio.mu_ratio > e.ratio.mu_ratio); // closer to the flat punch
/// ```
pub fn evaluate(shape: &Shape, vbar: f64, amp: f64) -> Result<Evaluation> {
    evaluate_with(shape, vbar, amp, mdr::DEFAULT_TOL)
}

/// Evaluate `mu_macro/mu0` for `shape` at `(vbar, amp)`, both finite and `>= 0`;
/// `tol` is the relative quadrature tolerance of MDR shapes (ignored for `flat`).
pub fn evaluate_with(shape: &Shape, vbar: f64, amp: f64, tol: f64) -> Result<Evaluation> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    check_tol(tol)?;
    shape.with_contact(|c| c.evaluate(vbar, amp, tol))
}

/// Check a tolerance: finite, `> 0` and `< 1`.
pub fn check_tol(tol: f64) -> Result<f64> {
    if tol.is_finite() && tol > 0.0 && tol < 1.0 {
        Ok(tol)
    } else {
        Err(Error::param("tol", tol, "must be finite, > 0 and < 1"))
    }
}

/// How `mu_macro/mu0` is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Method {
    /// The event-driven exact solver.
    Exact,
    /// The seed's time-stepping scheme ([`crate::stepper`]).
    Stepping,
}

/// Resolution of the time-stepping peer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Stepping {
    /// Time steps per oscillation period (`M`).
    pub steps_per_period: usize,
    /// Springs of an MDR foundation (`N`; the flat punch has one).
    pub springs: usize,
}

/// Largest `M` and `N` accepted (each); their product is bounded by [`MAX_STEPPING_WORK`].
pub const MAX_STEPPING: usize = 100_000_000;
/// Largest `M * N` (spring updates per period) accepted: two periods of 10^11
/// updates take about four minutes on two cores (0.6 ns per update measured);
/// memory stays at a few MB whatever `M` and `N` ([`crate::stepper::run_with`]).
pub const MAX_STEPPING_WORK: u128 = 100_000_000_000;

impl Stepping {
    /// Check the resolution and the shape before any work (and any output).
    pub fn check(&self, shape: &Shape) -> Result<()> {
        for (name, v) in [("steps-per-period", self.steps_per_period), ("springs", self.springs)] {
            if v == 0 || v > MAX_STEPPING {
                return Err(Error::param(name, v as f64, "must be between 1 and 1e8"));
            }
        }
        let springs = if shape.with_contact(|c| c.single_spring()) { 1 } else { self.springs };
        if self.steps_per_period as u128 * springs as u128 > MAX_STEPPING_WORK {
            return Err(Error::param("springs", self.springs as f64, "steps-per-period x springs must be <= 1e11"));
        }
        Ok(())
    }
}

/// Result of the time-stepping peer.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SteppingEvaluation {
    /// Ratio and reduction (`1 - mu_ratio`, no special care: this is the peer).
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub ratio: Ratio,
    /// Time steps taken (two periods).
    pub steps: u64,
    /// Springs stepped.
    pub springs: usize,
    /// `|mu(last period) - mu(previous period)|`.
    pub period_change: f64,
}

/// `mu_macro/mu0` by the seed's time-stepping scheme.
pub fn evaluate_stepping(shape: &Shape, vbar: f64, amp: f64, st: Stepping) -> Result<SteppingEvaluation> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    st.check(shape)?;
    // Any contact: its foundation on a uniform grid (crate::contact::grid).
    let (run, springs) = shape.with_contact(|c| crate::stepper::contact_mu_ratio(c, vbar, amp, st))?;
    // The peer's raw value: outside [0, 1] it says something about the peer.
    let mu = run.mu_ratio();
    if !mu.is_finite() {
        return Err(Error::Internal { what: format!("time stepping gave mu_ratio = {mu:?}") });
    }
    Ok(SteppingEvaluation {
        ratio: Ratio { mu_ratio: mu, reduction: 1.0 - mu },
        steps: run.steps,
        springs,
        period_change: run.period_change,
    })
}
