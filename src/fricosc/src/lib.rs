//! # fricosc
//!
//! Exact steady-state friction under normal (out-of-plane) oscillation, after
//! M. Popov, V. L. Popov, N. V. Popov, *Reduction of friction by normal
//! oscillations. I. Influence of contact stiffness*, Friction (2017).
//!
//! A contact is a set of independent springs. Each spring's normal force
//! follows the imposed oscillation `u0 - du cos(omega t)`; its tangential force
//! sticks or slips under Coulomb's law with coefficient `mu0`. The answer is
//! `mu_macro/mu0` as a function of the dimensionless velocity `vbar` (eq. 3 of
//! the paper) and the amplitude `amp = du/u0`, for any indenter [`Shape`].
//!
//! ```
//! use fricosc::Shape;
//!
//! // A flat punch and a Hertzian (parabolic) contact at vbar = 0.3, du/u0 = 0.4.
//! let flat = Shape::flat().evaluate(0.3, 0.4)?;
//! let hertz = Shape::parse("parabolic")?.evaluate(0.3, 0.4)?;
//! assert!((flat.ratio.mu_ratio - 0.8317432589602997).abs() < 1e-15);
//! assert!((hertz.ratio.mu_ratio - 0.7661542311590507).abs() < 1e-15);
//! // Every curved result carries an error estimate that bounds its error.
//! assert!(hertz.error_estimate < 1e-14);
//!
//! // The reduction 1 - mu/mu0 keeps full relative accuracy near vbar = 1.
//! let near = Shape::flat().evaluate(1.0 - 1e-9, 0.5)?;
//! assert!(near.ratio.reduction > 0.0 && near.ratio.reduction < 1e-18);
//! # Ok::<(), fricosc::Error>(())
//! ```
//!
//! # The facade
//! - [`Shape`]: the contact (parse a name, or build one: [`Shape::flat`],
//!   [`Shape::parabolic`], [`Shape::power`], [`Shape::from_contact`]), evaluated by
//!   [`Shape::evaluate`] (an [`Evaluation`]: the [`Ratio`] and its error
//!   estimate) or [`Shape::point`] (a [`Point`]: regime and events of the flat
//!   punch, bands of power laws), with [`Options`];
//! - [`spring`]: one spring of the model, its regimes and events in closed form;
//! - [`flat`] and [`mdr`]: the flat punch and power-law contacts directly;
//!   [`profile`]: tabulated profiles; [`flat_tip`]: a worn sphere;
//! - [`history`]: force histories over a period;
//! - [`stepper`]: the paper's time-stepping scheme (the independent check) and
//!   [`seed`]: the paper's approximate formulas;
//! - [`validation`]: another code's results against the exact ones;
//!   [`scene`]: physical scenes in SI units;
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
//! - `cli` (default): the `fricosc` command-line tool. With
//!   `default-features = false` the library has no CLI, plot or schema dependency.
#![deny(missing_docs)]

mod contact;
pub mod error;
pub mod io;
mod model;
mod numerics;
mod peers;
pub mod scene;
pub mod validation;

pub use contact::regime::ContactRegime;
pub use contact::shape::{Evaluation, Options, Point, Reader, Shape, DEFAULT_TOL, MAX_EXPONENT, MIN_EXPONENT};
pub use contact::{combined, flat, flat_tip, history, mdr, profile, regime, Contact, FlatPunch, PowerLaw};
pub use error::{Error, Result};
pub use model::ratio::Ratio;
pub use model::{spring, stop, vbar_from_vhat};
pub use numerics::decimal::spaced;
pub use peers::{seed, stepper};

// Crate-internal short paths.
pub(crate) use contact::shape;
pub(crate) use model::ratio;
pub(crate) use numerics::{quad, root, special};

/// README.md's Rust examples, run as doctests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
