//! # fricosc
//!
//! Exact steady-state friction under oscillation, after M. Popov, V. L. Popov,
//! N. V. Popov, *Reduction of friction by normal oscillations. I. Influence of
//! contact stiffness*, Friction (2017).
//!
//! A contact is a set of independent springs. Each spring's normal force
//! follows the imposed oscillation `u0 - du cos(omega t)`; its tangential force
//! sticks or slips under Coulomb's law with coefficient `mu0`, and the body may
//! oscillate in the sliding direction too. The answer is `mu_macro/mu0` for any
//! indenter [`Shape`] under the [`Conditions`] of one point.
//!
//! ```
//! use fricosc::{Conditions, Shape};
//!
//! // A flat punch and a Hertzian (parabolic) contact at vbar = 0.3, du/u0 = 0.4.
//! let c = Conditions::vbar(0.3, 0.4)?;
//! let flat = Shape::flat().evaluate(&c)?;
//! let hertz = Shape::parse("parabolic")?.evaluate(&c)?;
//! assert!((flat.ratio.mu_ratio - 0.8317432589602997).abs() < 1e-15);
//! assert!((hertz.ratio.mu_ratio - 0.7661542311590507).abs() < 1e-15);
//! // Every curved result carries an error estimate that bounds its error.
//! assert!(hertz.error_estimate < 1e-14);
//!
//! // The reduction 1 - mu/mu0 keeps full relative accuracy near vbar = 1.
//! let near = Shape::flat().evaluate(&Conditions::vbar(1.0 - 1e-9, 0.5)?)?;
//! assert!(near.ratio.reduction > 0.0 && near.ratio.reduction < 1e-18);
//! # Ok::<(), fricosc::Error>(())
//! ```
//!
//! # The facade
//! - [`Shape`]: the contact (parse a name, or build one: [`Shape::flat`],
//!   [`Shape::parabolic`], [`Shape::power`], [`Shape::from_contact`]);
//!   [`Shape::evaluate`] gives an [`Evaluation`] (the [`Ratio`] and its error
//!   estimate), [`Shape::report`] a [`Report`] (events, bands);
//! - [`Conditions`]: the velocity, the normal and tangential oscillation and
//!   the tolerance of one point, checked where they are built;
//! - [`contact`]: the [`contact::Contact`] trait (a shape's MDR geometry) and
//!   the built-in contacts; [`report`]: what a report holds;
//! - [`spring`]: one spring of the model and the stop operator, in closed form;
//! - [`history`]: force histories over a period;
//! - [`plane`]: oscillation across the sliding direction, exact (the flat punch);
//! - [`stepper`]: the seed's time-stepping scheme (the independent check) and
//!   [`seed`]: the seed's approximate formulas;
//! - [`validation`]: another code's results against the exact ones;
//!   [`scene`]: physical scenes in SI units; [`io`]: capped reads of files;
//! - [`Error`]: what can go wrong, typed.
//!
//! The solver is event-driven and exact: the transition times are roots of
//! closed-form functions on analytic brackets, and each phase is integrated in
//! closed form. No time stepping is involved. Curved contacts are MDR elastic
//! foundations integrated in analytic bands by Gauss(-Jacobi) quadrature.
//!
//! # Features
//! - `parallel`: tables and arrays on every core (rayon); without it, one thread.
//! - `serde`: the result types serialise; `schema`: the JSON Schema of scenes.
#![deny(missing_docs)]

mod conditions;
pub mod contact;
mod error;
pub mod fit;
mod integrate;
pub mod interrupt;
pub mod io;
mod model;
mod numerics;
mod peers;
pub mod plane;
pub mod report;
pub mod scene;
pub mod system;
pub mod validation;

pub use conditions::{Conditions, InPlane, Velocity, DEFAULT_TOL};
pub use contact::shape::{Evaluation, Report, Shape, MAX_EXPONENT, MIN_EXPONENT};
pub use error::{Error, Result};
pub use model::ratio::Ratio;
pub use numerics::decimal::spaced;
pub use peers::{seed, stepper};

/// One spring of the model in closed form: the seed's single spring
/// ([`spring::Spring`]: regimes, events, means) and the stop operator with a
/// moving bound ([`spring::StopSpring`]: oscillation in the sliding direction).
pub mod spring {
    pub use crate::model::spring::{mean_normal, Event, EventKind, Regime, Spring, Stick};
    pub use crate::model::stop::{solve, Bound, Drive, StopKind, StopPhase, StopSpring, Touch};
}

/// Force histories over a period: the normal and tangential force of a
/// contact against time, exact (the flat punch's phases; a curved contact's
/// normal total in closed form and its tangential total over a grid of springs).
pub mod history {
    pub use crate::contact::history::{
        history, stepped_history, Body, History, HistoryOptions, HistoryPoint, Sample, MAX_PLANE_SPRINGS, MAX_SAMPLES,
        MAX_SPRINGS, MAX_SPRING_WORK, MIN_CURVED_AMP,
    };
}

// Crate-internal short paths.
pub(crate) use contact::{combined, flat, profile, shape};
pub(crate) use model::ratio;
pub(crate) use model::stop;
pub(crate) use numerics::{quad, root, special};

/// README.md's Rust examples, run as doctests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
