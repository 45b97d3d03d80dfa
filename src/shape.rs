//! Indenter shapes, as named on the command line and in batch files.

use crate::error::{Error, Result};
use crate::flat;
use crate::flat::Ratio;
use serde::Serialize;

/// A contact geometry.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Flat cylindrical punch: one spring (seed section 2).
    Flat,
}

impl Shape {
    /// Parse `flat`.
    pub fn parse(spec: &str) -> Result<Shape> {
        match spec.trim() {
            "flat" => Ok(Shape::Flat),
            other => Err(Error::InvalidShape {
                spec: other.into(),
                reason: "unknown shape (known: flat)".into(),
            }),
        }
    }

    /// The name as printed in outputs.
    pub fn name(&self) -> String {
        match self {
            Shape::Flat => "flat".into(),
        }
    }
}

/// `mu_macro/mu0` of a shape with an error estimate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Evaluation {
    /// Ratio and reduction.
    #[serde(flatten)]
    pub ratio: Ratio,
    /// Estimated absolute error of `mu_ratio`.
    pub error_estimate: f64,
}

/// Accuracy bound of the single-spring solver, from the tests against the
/// 40-digit references and the derived limits (`tests/flat.rs`).
pub const FLAT_ERROR_BOUND: f64 = 1e-15;

/// Evaluate `mu_macro/mu0` for `shape` at `(vbar, amp)`; both finite and `>= 0`.
pub fn evaluate(shape: &Shape, vbar: f64, amp: f64) -> Result<Evaluation> {
    match shape {
        Shape::Flat => Ok(Evaluation {
            ratio: flat::ratio(vbar, amp)?,
            error_estimate: FLAT_ERROR_BOUND,
        }),
    }
}
