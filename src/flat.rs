//! The flat cylindrical punch: one spring with `s = u0/du = 1/amp` (seed section 2).
//!
//! Forces here are in units of the static normal force: `kz u0` (normal) and
//! `mu0 kz u0` (tangential), so that `amp = 0` (no oscillation) stays finite.

use crate::error::{check_nonneg, Result};
use crate::spring::{Event, EventKind, Regime, Spring};
use serde::Serialize;

/// `mu_macro/mu0` and `1 - mu_macro/mu0`, the latter with full relative accuracy.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Ratio {
    /// `mu_macro / mu0`.
    pub mu_ratio: f64,
    /// `1 - mu_macro/mu0`, computed directly (not as a difference).
    pub reduction: f64,
}

impl Ratio {
    /// From the mean stick deficit and the mean normal force of the same contact.
    pub fn from_deficit(deficit: f64, mean_normal: f64) -> Self {
        if deficit <= 0.0 || mean_normal <= 0.0 {
            return Ratio { mu_ratio: 1.0, reduction: 0.0 };
        }
        let reduction = (deficit / mean_normal).min(1.0);
        Ratio { mu_ratio: 1.0 - reduction, reduction }
    }
}

/// The exact steady state of a flat punch.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FlatPoint {
    /// Dimensionless velocity (eq. 3).
    pub vbar: f64,
    /// Amplitude `du/u0`.
    pub amp: f64,
    /// `mu_macro/mu0` and the reduction.
    #[serde(flatten)]
    pub ratio: Ratio,
    /// `mu_static/mu0`, the limit `vbar -> 0+`: `1 - amp` for `amp <= 1`, else 0.
    pub mu_static_ratio: f64,
    /// Regime of the spring.
    pub regime: Regime,
    /// Mean normal force, units `kz u0` (1 without contact loss; eq. 20 with it).
    pub mean_normal: f64,
    /// Mean tangential force, units `mu0 kz u0`.
    pub mean_tangential: f64,
    /// Events of one period, forces in units of `kz u0` and `mu0 kz u0`.
    pub events: Vec<Event>,
    /// Root-finder function evaluations spent.
    pub root_evaluations: u32,
}

/// The spring of a flat punch of amplitude `amp` (`s = 1/amp`). For `amp = 0`
/// the permanent-contact spring with `s = 1` stands in: its stick phases and
/// deficit do not depend on `s`.
fn spring(vbar: f64, amp: f64, events: bool) -> Spring {
    let s = if amp > 0.0 { 1.0 / amp } else { 1.0 };
    let s = if s.is_finite() { s } else { f64::MAX };
    if events {
        Spring::with_events(s, vbar)
    } else {
        Spring::new(s, vbar)
    }
}

/// Reduction from the spring: for `amp <= 1`, `<B> = s = 1/amp` and the
/// reduction is `amp * D` (no division by a large `s`).
fn ratio_of(sp: &Spring, amp: f64) -> Ratio {
    if amp <= 1.0 {
        let reduction = (amp * sp.deficit).min(1.0);
        Ratio { mu_ratio: 1.0 - reduction, reduction }
    } else if sp.regime == Regime::JumpingStickFirst && sp.mean_normal > 0.0 {
        // The smaller of the two from its own integral (full relative accuracy:
        // mu -> 0 as vbar -> 0, the reduction as vbar -> 1), the other its complement.
        let mu_ratio = (sp.mean_tangential() / sp.mean_normal).clamp(0.0, 1.0);
        if mu_ratio < 0.5 {
            Ratio { mu_ratio, reduction: 1.0 - mu_ratio }
        } else {
            Ratio::from_deficit(sp.deficit, sp.mean_normal)
        }
    } else {
        Ratio::from_deficit(sp.deficit, sp.mean_normal)
    }
}

/// `mu_macro/mu0` of a flat punch; `vbar, amp` finite and `>= 0`.
///
/// ```
/// let r = fricosc::flat::ratio(0.5, 0.5).unwrap();
/// assert!((r.mu_ratio - 0.8992738983331656556).abs() < 1e-15);
/// ```
pub fn ratio(vbar: f64, amp: f64) -> Result<Ratio> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    Ok(ratio_of(&spring(vbar, amp, false), amp))
}

/// `mu_static/mu0` of a flat punch: the minimum normal force over the mean, `(1 - amp)_+`.
pub fn mu_static_ratio(amp: f64) -> f64 {
    (1.0 - amp).max(0.0)
}

/// The full steady state of a flat punch, with events to full precision.
pub fn point(vbar: f64, amp: f64) -> Result<FlatPoint> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    let sp = spring(vbar, amp, true);
    let ratio = ratio_of(&sp, amp);
    // In units of kz u0 the bound is (1 - amp cos tau)_+; every event lies on it.
    let events = sp
        .events()
        .into_iter()
        .map(|e| {
            let f = match e.kind {
                EventKind::Contact | EventKind::LossOfContact => 0.0,
                _ if sp.regime == Regime::JumpingStickFirst && e.kind == EventKind::Stick => 0.0,
                _ => (1.0 - amp * e.tau.cos()).max(0.0),
            };
            Event { normal: f, tangential: f, ..e }
        })
        .collect();
    let mean_normal = if amp <= 1.0 { 1.0 } else { amp * sp.mean_normal };
    Ok(FlatPoint {
        vbar,
        amp,
        ratio,
        mu_static_ratio: mu_static_ratio(amp),
        regime: sp.regime,
        mean_normal,
        mean_tangential: ratio.mu_ratio * mean_normal,
        events,
        root_evaluations: sp.root_evaluations,
    })
}
