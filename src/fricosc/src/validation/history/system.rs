//! A history on a system with mass and stiffness: the period-1 attractor at
//! the file's phases (its tangential force, the body's lag `X_d - x` and
//! velocity), the body's columns against it, and the usual mistakes of the
//! system's equation tried where the force's errors are of order one.

use super::super::convention::LARGE_ERROR;
use super::super::system::{EXPLAINS, MISTAKES};
use super::super::{finding, Finding, FindingKind};
use crate::error::Result;
use crate::shape::Shape;
use crate::system::System;

/// The exact tangential force, and the body's lag and velocity, at the
/// seed's phases `taus`, with the attractor's events.
pub(super) type Exact = (Vec<f64>, Vec<[f64; 2]>, Vec<crate::model::spring::Event>);

/// [`Exact`] of `shape` under `c` on `sys` (a body with mass).
pub(super) fn exact(shape: &Shape, c: &crate::Conditions, sys: &System, taus: &[f64]) -> Result<Exact> {
    let (rows, events) = crate::contact::history::system_at(shape, c, sys, taus)?;
    Ok((rows.iter().map(|r| r[0]).collect(), rows.iter().map(|r| [r[1], r[2]]).collect(), events))
}

/// The file's body columns against the exact body over the last period.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BodyComparison {
    /// Largest `|lag - exact|`, the lag `X_d - x` in pre-slip lengths.
    pub lag_max_abs_error: f64,
    /// Largest `|velocity - exact|`, `dx/dtau` in pre-slip lengths.
    pub velocity_max_abs_error: f64,
    /// The exact lag's range over the period (max - min).
    pub lag_range: f64,
    /// The exact velocity's range.
    pub velocity_range: f64,
}

/// The largest errors of `yours` (lag, velocity at each sample) against `exact`.
pub(super) fn compare_body(yours: &[[f64; 2]], exact: &[[f64; 2]]) -> BodyComparison {
    let worst = |j: usize| yours.iter().zip(exact).map(|(y, e)| (y[j] - e[j]).abs()).fold(0.0, f64::max);
    let range = |j: usize| {
        let (lo, hi) = exact.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| (l.min(e[j]), h.max(e[j])));
        hi - lo
    };
    BodyComparison {
        lag_max_abs_error: worst(0),
        velocity_max_abs_error: worst(1),
        lag_range: range(0),
        velocity_range: range(1),
    }
}

/// The samples (file indices) whose body's lag or velocity errs by more
/// than [`LARGE_ERROR`] of its range (or is not a number): the system's
/// equation or its units.
pub(super) fn body_finding(b: &BodyComparison, samples: &[super::HistorySample]) -> Option<Finding> {
    let off = |e: f64, r: f64| e.is_nan() || e.abs() > LARGE_ERROR * r;
    let bad = samples.iter().filter(|s| match (s.body_yours, s.body_exact) {
        (Some(y), Some(e)) => off(y[0] - e[0], b.lag_range) || off(y[1] - e[1], b.velocity_range),
        _ => false,
    });
    let rows: Vec<usize> = bad.map(|s| s.index).collect();
    let hint = format!(
        "the body's lag X_d - x errs by up to {:.3e} (its range {:.3e}) and its velocity by {:.3e} (range {:.3e}): \
         the system's equation (mass Omega^2 x'', spring kappa, dashpot 2 zeta sqrt(kappa) Omega) or the units (lengths \
         in pre-slip lengths mu0 kz u0 / kx, velocities d/dtau)",
        b.lag_max_abs_error, b.lag_range, b.velocity_max_abs_error, b.velocity_range
    );
    finding(FindingKind::LargeErrors, rows, &hint)
}

/// Where the force's largest error `worst` (of `yours` at the seed's phases
/// `taus`) is of order one: the usual mistake of the system's equation whose
/// attractor the file meets far better ([`EXPLAINS`] of the error as read),
/// the best of them, on the samples `rows` of large errors. Mistakes whose
/// attractor has no period 1 are passed over.
pub(super) fn mistake(
    shape: &Shape,
    (c, sys): (&crate::Conditions, &System),
    taus: &[f64],
    (yours, rows): (&[f64], Vec<usize>),
    worst: f64,
) -> Option<Finding> {
    let mut best: Option<(f64, &str)> = None;
    for (read, name) in MISTAKES {
        let Ok(as_read) = read(sys) else { continue };
        let exact_t = match as_read {
            Some(s) if s.frequency_ratio() > 0.0 => exact(shape, c, &s, taus).map(|e| e.0),
            Some(s) => crate::system::massless(c, &s).and_then(|m| stiff_at(shape, &m, taus)),
            None => stiff_at(shape, &c.stiff(), taus),
        };
        let Ok(exact_t) = exact_t else { continue };
        let err = yours.iter().zip(&exact_t).map(|(y, e)| (y - e).abs()).fold(0.0, f64::max);
        if err <= EXPLAINS * worst && best.is_none_or(|b| err < b.0) {
            best = Some((err, name));
        }
    }
    let (err, name) = best?;
    let hint = format!(
        "your history matches the exact attractor with {name}: largest error {err:.1e} there, {worst:.1e} as read \
         (tried: the damping left out, Omega for Omega^2 and Omega^4, Omega^2 in the dashpot, kappa inverted, no system)"
    );
    finding(FindingKind::Convention, rows, &hint)
}

/// The stiff problem's exact tangential force at `taus`.
fn stiff_at(shape: &Shape, c: &crate::Conditions, taus: &[f64]) -> Result<Vec<f64>> {
    let e = super::exact::Exact::new(shape, c)?;
    Ok(crate::numerics::par::map(taus, |&t| e.tangential(t)))
}
