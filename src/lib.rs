//! # fricosc
//!
//! The command-line tool and its reports over [`fricosc_core`], the physics and
//! numerics of friction under normal oscillation (Popov, Popov, Popov 2017).
//! The core's modules are re-exported here under their old paths, so that
//! `fricosc::flat::ratio` and `fricosc_core::flat::ratio` are the same function.
//!
//! ```
//! // Flat punch, vbar = 0.2, du/u0 = 0.5 (reference value to 22 digits).
//! let r = fricosc::flat::ratio(0.2, 0.5).unwrap();
//! assert!((r.mu_ratio - 0.7145191049466343399125).abs() < 1e-15);
//! ```
#![warn(missing_docs)]

pub use fricosc_core::{
    contact, error, flat, mdr, model, numerics, peers, profile, quad, ratio, root, seed, shape, special, spring,
    stepper, Error, Result,
};

pub mod batch;
pub mod bench;
pub mod claims;
pub mod export;
pub mod figures;
pub mod grid;
pub mod history;
pub mod input;
pub mod output;
pub mod plot;
pub mod rows;
pub mod scan;
pub mod scene;
pub mod stress;
pub mod suite;
pub mod validate;
