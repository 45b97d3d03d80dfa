//! # fricosc
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
//! ```
//! // Flat punch, vbar = 0.2, du/u0 = 0.5 (reference value to 22 digits).
//! let r = fricosc::flat::ratio(0.2, 0.5).unwrap();
//! assert!((r.mu_ratio - 0.7145191049466343399125).abs() < 1e-15);
//! ```
#![warn(missing_docs)]

pub mod error;
pub mod flat;
pub mod root;
pub mod special;
pub mod spring;
pub mod stepper;

pub use error::{Error, Result};
pub mod batch;
pub mod bench;
pub mod claims;
pub mod figures;
pub mod grid;
pub mod history;
pub mod input;
pub mod mdr;
pub mod output;
pub mod plot;
pub mod profile;
pub mod quad;
pub mod ratio;
pub mod rows;
pub mod scene;
pub mod seed;
pub mod shape;
pub mod stress;
pub mod validate;
