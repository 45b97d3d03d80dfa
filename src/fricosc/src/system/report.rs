//! What a solve on a system reports ([`SystemReport`]): read, not built.

use super::SystemEvent;
#[cfg(doc)]
use super::MAX_PERIODS;

/// The steady state on a system, as the solver reports it (read, not built:
/// `#[non_exhaustive]`).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct SystemReport {
    /// `mu_macro/mu0`: over the attractor's period, or the long-time mean.
    pub mu_ratio: f64,
    /// The attractor's period in periods of the drive (`None`: none found
    /// within [`MAX_PERIODS`]; then `mu_ratio` is a mean).
    pub period: Option<usize>,
    /// The standard error of the mean where there is no period.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub standard_error: Option<f64>,
    /// Periods run from the start before the orbit repeated (or all).
    pub periods_run: usize,
    /// The Floquet multipliers `[re, im]` of the flat punch's orbit, all
    /// inside the unit circle (an orbit with one outside is not reported as
    /// the attractor). `None`: not known (no period, a massless body, a
    /// curved body).
    pub multipliers: Option<Vec<[f64; 2]>>,
    /// The events of the orbit's first period (the flat punch).
    pub events: Vec<SystemEvent>,
    /// A bound on the error of `mu_ratio`: the flat punch's orbit's (its
    /// closure and its rounding, `orbit_estimate`), a curved body's (its
    /// springs' discretisation and the orbits' closure), a mean's without
    /// period (twice its standard error plus three times the drift between
    /// the halves of the periods averaged, plus the rounding of a period),
    /// a massless body's (the stiff solver's).
    pub error_estimate: f64,
    /// The springs of a curved body's finest discretisation.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub springs: Option<usize>,
    /// Sampling steps of the flat punch's orbit's first period (of a mean,
    /// and of a curved body's finest discretisation: of the whole run) in
    /// which the phase was held: its force rode on its
    /// bound, eight phases of zero length in a row at one instant (at a
    /// regain of contact where the body moves as fast as the bound grows,
    /// `f = B = 0` and `x' = B'`). Events are not looked for in such a step;
    /// the force leaves its bound there by a rounding of the velocities'
    /// difference times the step, and the next step's first check ends the
    /// phase where it must. 0 elsewhere.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "is_zero"))]
    pub held_steps: u64,
}

#[cfg(feature = "serde")]
fn is_zero(n: &u64) -> bool {
    *n == 0
}

impl SystemReport {
    /// `mu_ratio` as a [`crate::Ratio`] (its reduction `1 - mu_ratio`).
    #[must_use]
    pub fn ratio(&self) -> crate::Ratio {
        crate::Ratio { mu_ratio: self.mu_ratio, reduction: 1.0 - self.mu_ratio }
    }

    /// The attractor's regime in words: `period k`, or `no period within N
    /// periods (a long-time mean)`.
    #[must_use]
    pub fn regime(&self) -> String {
        match self.period {
            Some(k) => format!("period {k}"),
            None => format!("no period within {} periods (a long-time mean)", self.periods_run),
        }
    }
}
