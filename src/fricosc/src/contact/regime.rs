//! What a contact's springs do at one point `(vbar, amp)`: the one
//! classification every output uses (`validate`'s rows and convergence orders,
//! `scene`'s rows, the Python reports).
//!
//! The flat punch is one spring, so its regime is that spring's. A curved
//! contact always has springs at its edge that lose contact (those whose
//! profile lies between `u0 - du` and `u0 + du`), so its regime says how much of
//! the load they carry ([`Shape::jumping_share`]): `mixed` below `amp = 1` (the centre
//! stays in contact), `jumping` from `amp = 1` on (every spring loses contact).

use crate::error::{check_nonneg, Result};
use crate::model::spring::{Regime, Spring};
use crate::shape::Shape;

/// What the springs of a contact do at one point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ContactRegime {
    /// `vbar = 0`: the value depends on the start (`validation::AtRest`).
    AtRest,
    /// No spring ever sticks (`vbar >= 1`, or `amp = 0`): `mu = mu0`.
    Sliding,
    /// Flat punch, `amp <= 1`: it sticks and slips and never loses contact.
    PermanentContact,
    /// Flat punch, `amp > 1`: after contact it slips first, then sticks.
    JumpingSlipFirst,
    /// Flat punch, `amp > 1`: it sticks from the moment of contact.
    JumpingStickFirst,
    /// Curved contact, `amp < 1`: the centre stays in contact, the springs at
    /// the edge lose it (a share [`Shape::jumping_share`] of the load).
    Mixed,
    /// Curved contact, `amp >= 1`: every spring loses contact in each period
    /// (also a flat punch at `amp > 1` under an oscillation in the plane).
    Jumping,
}

impl ContactRegime {
    /// The name outputs print (as JSON writes it).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            ContactRegime::AtRest => "at_rest",
            ContactRegime::Sliding => "sliding",
            ContactRegime::PermanentContact => "permanent_contact",
            ContactRegime::JumpingSlipFirst => "jumping_slip_first",
            ContactRegime::JumpingStickFirst => "jumping_stick_first",
            ContactRegime::Mixed => "mixed",
            ContactRegime::Jumping => "jumping",
        }
    }
}

/// [`Shape::regime`] of checked inputs (finite, `>= 0`), for the flat punch or a curved contact.
pub(crate) fn regime_of(flat: bool, vbar: f64, amp: f64) -> ContactRegime {
    if vbar == 0.0 {
        ContactRegime::AtRest
    } else if vbar >= 1.0 || amp == 0.0 {
        ContactRegime::Sliding
    } else if !flat {
        if amp < 1.0 {
            ContactRegime::Mixed
        } else {
            ContactRegime::Jumping
        }
    } else {
        match Spring::new(crate::flat::spring_s(amp), vbar).regime {
            Regime::JumpingStickFirst => ContactRegime::JumpingStickFirst,
            Regime::JumpingSlipFirst | Regime::JumpingSlip => ContactRegime::JumpingSlipFirst,
            _ => ContactRegime::PermanentContact,
        }
    }
}

impl Shape {
    /// The regime of this shape at `(vbar, amp)` (both finite and `>= 0`).
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] for a negative or non-finite input.
    pub fn regime(&self, vbar: f64, amp: f64) -> Result<ContactRegime> {
        check_nonneg("vbar", vbar)?;
        check_nonneg("amp", amp)?;
        Ok(regime_of(self.is_flat(), vbar, amp))
    }

    /// The share of the period-mean normal force carried by springs that lose
    /// contact during the period, in `[0, 1]`: 0 or 1 for the flat punch (`amp <= 1`
    /// or not); for a curved contact `1 - P/<N>`, where `<N>` is
    /// [`crate::contact::Contact::mean_normal`] and `P` the mean force of the springs that
    /// never lose contact, those with `G(z) <= 1 - amp`. Each has the mean force
    /// `2 (1 - G(z))` (the oscillation averages out), so
    /// `P = 2 int_0^{z_p} (1 - G) dz = F(1 - amp) + 2 amp z_p`, with `F` the static
    /// force and `G(z_p) = 1 - amp` (found by bisection; `G` is nondecreasing).
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] for a bad `amp` or one beyond a table's reach.
    pub fn jumping_share(&self, amp: f64) -> Result<f64> {
        check_nonneg("amp", amp)?;
        if amp == 0.0 {
            return Ok(0.0);
        }
        if self.is_flat() || amp >= 1.0 {
            return Ok(if amp > 1.0 || (amp == 1.0 && !self.is_flat()) { 1.0 } else { 0.0 });
        }
        let c = self.contact();
        let mean = c.mean_normal(amp)?;
        let level = 1.0 - amp;
        // G(0) = 0 <= level < 1 = G(1): the bracket holds the root.
        let z = crate::numerics::root::bracketed(|z| c.equivalent_profile(z) - level, 0.0, 1.0, 4.0 * f64::EPSILON).x;
        let permanent = c.static_force(level) + 2.0 * amp * z;
        Ok((1.0 - permanent / mean).clamp(0.0, 1.0))
    }
}
