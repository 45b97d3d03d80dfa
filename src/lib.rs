//! # fricosc-core
//!
//! Exact steady-state friction under normal (out-of-plane) oscillation, after
//! M. Popov, V. L. Popov, N. V. Popov, *Reduction of friction by normal
//! oscillations. I. Influence of contact stiffness*, Friction (2017).
//!
//! A contact is a set of independent springs. Each spring's normal force
//! follows the imposed oscillation `u0 - du cos(omega t)`; its tangential force
//! sticks or slips under Coulomb's law. The product is `mu_macro/mu0` as a
//! function of the dimensionless velocity `vbar` (eq. 3) and the amplitude
//! `amp = du/u0`.
//!
//! The solver is event-driven and exact: the transition times are roots of
//! closed-form functions on analytic brackets, and each phase is integrated in
//! closed form ([`spring`]). No time stepping is involved; the seed's
//! time-stepping scheme lives in [`stepper`] as an independent check.
//!
//! Layout (dependencies point downwards):
//! - [`numerics`]: root finding, Gauss-Jacobi rules, cancellation-free functions;
//! - [`model`]: `Ratio` (checked results) and one spring (regimes, events, phases);
//! - [`contact`]: the flat punch, power laws (MDR), tabulated profiles, and the
//!   `Shape` that dispatches between them;
//! - [`peers`]: the seed's time-stepping scheme and its approximations (eqs. 11-28).
//!
//! This crate knows nothing about command lines, plots or schemas; with the
//! `serde` feature its result types serialise.
//!
//! ```
//! // Flat punch, vbar = 0.2, du/u0 = 0.5 (reference value to 22 digits).
//! let r = fricosc::flat::ratio(0.2, 0.5).unwrap();
//! assert!((r.mu_ratio - 0.7145191049466343399125).abs() < 1e-15);
//! ```
#![deny(missing_docs)]

pub mod contact;
pub mod error;
pub mod model;
pub mod numerics;
pub mod peers;
pub mod scene;
pub mod validation;

pub use contact::{flat, history, mdr, profile, shape};

#[cfg(feature = "cli")]
#[doc(hidden)]
pub mod cli;
pub use error::{Error, Result};
pub use model::{ratio, spring};
pub use numerics::{quad, root, special};
pub use peers::{seed, stepper};
