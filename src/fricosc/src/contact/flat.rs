//! The flat cylindrical punch: one spring with `s = u0/du = 1/amp` (seed section 2).
//!
//! Forces here are in units of the static normal force: `kz u0` (normal) and
//! `mu0 kz u0` (tangential), so that `amp = 0` (no oscillation) stays finite.

use crate::error::{check_nonneg, Result};
use crate::model::spring::{Event, EventKind, Precision, Regime, Spring};
use crate::ratio::Ratio;
use crate::special::one_minus_a_cos_asin;

/// The exact steady state of a flat punch.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FlatPoint {
    /// Dimensionless velocity (eq. 3).
    pub vbar: f64,
    /// Amplitude `du/u0`.
    pub amp: f64,
    /// `mu_macro/mu0` and the reduction.
    #[cfg_attr(feature = "serde", serde(flatten))]
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

/// The spring of a flat punch of amplitude `amp`: `s = 1/amp`, with
/// `1 - s = (amp - 1)/amp` passed unrounded (the contact phase near `amp = 1`).
/// `s` comes from [`spring_s`], the one place it is formed (with its stand-in
/// for `amp = 0`).
pub(crate) fn spring(vbar: f64, amp: f64, precision: Precision) -> Spring {
    let s = spring_s(amp);
    // 1 - s = (amp - 1)/amp without cancellation (only used where |s| < 1, so
    // its -inf at amp = 0, where s stands in as f64::MAX, is never read).
    let one_minus_s = (amp - 1.0) / amp;
    // s - sqrt(1 - vbar^2) = (1 - amp sqrt(1 - vbar^2))/amp from amp and vbar
    // themselves (exact inputs): its sign decides the regime, and it is the
    // start force of a stick from the bound.
    let margin = (amp > 1.0 && vbar < 1.0).then(|| one_minus_a_cos_asin(amp, vbar) / amp);
    Spring::with_complement(s, one_minus_s, vbar, precision, margin)
}

/// `s = u0/du = 1/amp` of the flat punch's spring; `f64::MAX` where `1/amp`
/// overflows (`amp = 0` or subnormal): a spring always in contact, whose stick
/// phases and deficit do not depend on `s`.
pub(crate) fn spring_s(amp: f64) -> f64 {
    let s = 1.0 / amp;
    if s.is_finite() {
        s
    } else {
        f64::MAX
    }
}

/// Mean normal force of the flat punch over a period, units `kz u0`: 1 without
/// contact loss, `amp <B>(1/amp)` (eq. 20) with it.
#[must_use]
pub fn mean_normal(amp: f64) -> f64 {
    if amp <= 1.0 {
        1.0
    } else {
        amp * crate::model::spring::mean_normal_of(spring_s(amp), (amp - 1.0) / amp)
    }
}

/// Below this `D/<B>` a jumping punch's reduction is the smaller of `mu` and
/// the reduction without computing `<F>` (its `mu` is above 0.55, where the
/// comparison `<F>/<B> < 1/2` could not go the other way by rounding): the
/// branch the full comparison takes, without the tangential force's cost.
const REDUCTION_CLEARLY_SMALL: f64 = 0.45;

/// Whether a spring's `D/<B>` is below [`REDUCTION_CLEARLY_SMALL`] (a NaN is not).
fn clearly_small(sp: &Spring) -> bool {
    sp.deficit < REDUCTION_CLEARLY_SMALL * sp.mean_normal
}

/// Reduction from the spring: for `amp <= 1`, `<B> = s = 1/amp` and the
/// reduction is `amp * D` (no division by a large `s`).
#[inline]
pub(crate) fn ratio_of(sp: &Spring, amp: f64) -> Result<Ratio> {
    let context = "flat punch";
    if amp <= 1.0 {
        let reduction = amp * sp.deficit;
        // Where mu is the small one (amp near 1, vbar near 0), from its own
        // integral: amp <F> = (1 - amp sqrt(1 - vbar^2)) + amp (<F> - F(tau_s)),
        // both cancellation-free (the difference 1 - reduction would keep only
        // the absolute accuracy of 1).
        // (The excess, a sine and a series, only where it is used.)
        match (reduction > 0.5).then(|| sp.tangent_excess()).flatten() {
            Some(x) => Ratio::from_mu(one_minus_a_cos_asin(amp, sp.vbar) + amp * x, context),
            None => Ratio::from_reduction(reduction, context),
        }
    } else if matches!(sp.regime, Regime::JumpingStickFirst | Regime::JumpingSlipFirst) && !clearly_small(sp) {
        // The smaller of the two from its own integral (full relative accuracy:
        // mu -> 0 as vbar -> 0, the reduction as vbar -> 1), the other its complement.
        // (A reduction clearly below 1/2 is the smaller without the tangential
        // force's integral, which costs a sine and a series: the branch below.)
        let mu_ratio = sp.mean_tangential() / sp.mean_normal;
        if mu_ratio < 0.5 {
            Ratio::from_mu(mu_ratio, context)
        } else {
            Ratio::from_deficit(sp.deficit, sp.mean_normal, context)
        }
    } else {
        Ratio::from_deficit(sp.deficit, sp.mean_normal, context)
    }
}

/// `mu_macro/mu0` of a flat punch; `vbar, amp` finite and `>= 0`.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] for a negative or non-finite input;
/// [`crate::Error::Internal`] for a bug.
pub fn ratio(vbar: f64, amp: f64) -> Result<Ratio> {
    check_nonneg("vbar", vbar)?;
    check_nonneg("amp", amp)?;
    // Where the contact is lost, `mu` is linear in `vbar` below VBAR_LINEAR,
    // and the spring's own terms (`vbar^2/2` ...) would underflow: solved at a
    // scaled velocity and scaled back (`VelocityScale`, as curved contacts).
    let at = crate::contact::VelocityScale::of(vbar, amp);
    let r = ratio_of(&spring(at.vbar, amp, Precision::Means), amp)?;
    Ok(at.back(r, 0.0).0)
}

/// `mu_static/mu0` of a flat punch: the minimum normal force over the mean, `(1 - amp)_+`.
#[must_use]
pub fn mu_static_ratio(amp: f64) -> f64 {
    (1.0 - amp).max(0.0)
}

/// The full steady state of a flat punch, with events to full precision.
///
/// `mu_ratio` is the value of [`ratio`] (one value per input, whatever the
/// command); the events come from a second solve at the event tolerance.
///
/// # Errors
/// As [`ratio`].
pub fn point(vbar: f64, amp: f64) -> Result<FlatPoint> {
    let ratio = ratio(vbar, amp)?;
    let sp = spring(vbar, amp, Precision::Events);
    // In units of kz u0 every event force lies on the bound (1 - amp cos tau)_+
    // and on the stick line: amp F(tau_s) = 1 - amp sqrt(1 - vbar^2) after a
    // tangent start (cancellation-free), 0 after a start at contact, plus
    // amp vbar L at the stick's end.
    let start = if sp.regime == Regime::JumpingStickFirst { 0.0 } else { one_minus_a_cos_asin(amp, vbar) };
    let length = sp.stick.map_or(0.0, |st| st.length);
    let events = sp
        .events()
        .into_iter()
        .map(|e| {
            let f = match e.kind {
                EventKind::Contact | EventKind::LossOfContact => 0.0,
                EventKind::Stick => start,
                // The seed's spring never slips backward.
                EventKind::Slip | EventKind::BackwardSlip => start + amp * vbar * length,
            };
            Event { normal: f, tangential: f, ..e }
        })
        .collect();
    let mean_normal = mean_normal(amp);
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

/// The normal and tangential force of the flat punch's spring `sp` (solved at
/// `vbar`, `amp`) at phase `tau`, in units of `kz u0` and `mu0 kz u0`: the bound
/// `(1 - amp cos tau)_+`, and in the stick the line from the stick's start force
/// (`1 - amp sqrt(1 - vbar^2)` cancellation-free after a tangent start, 0 after
/// a start at contact) at rate `amp vbar`. Written in these units, not as
/// `amp` times the spring's own (units `kz du`), so that no `s = 1/amp`
/// overflows at tiny amplitudes; `amp = 0` is sliding at the constant bound 1.
pub(crate) fn forces_at(sp: &Spring, amp: f64, tau: f64) -> (f64, f64) {
    let b = (1.0 - amp * tau.cos()).max(0.0);
    if b == 0.0 || amp == 0.0 {
        return (b, b);
    }
    if let Some(st) = sp.stick {
        let x = (tau - st.start).rem_euclid(std::f64::consts::TAU);
        if x < st.length {
            let start = if sp.regime == Regime::JumpingStickFirst { 0.0 } else { one_minus_a_cos_asin(amp, sp.vbar) };
            return (b, (start + amp * sp.vbar * x).min(b));
        }
    }
    (b, b)
}
