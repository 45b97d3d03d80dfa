//! The seed's approximations, as printed and (where misprinted) corrected, for
//! comparison with the exact solver ([`Approximation`]: `vbar` as in eq. 3,
//! `amp = du/u0`). [`claims`] checks every quantitative statement of the seed
//! against the exact solver (`fricosc claims`).

use std::f64::consts::PI;

mod claims;
mod part_two;
mod transverse;

pub use claims::{claims, exact_slope, Claim, Verdict};

/// `3/4 (v - 1)^2 + 1/4 (v - 1)^4`, the bracket of eqs. 11, 13-17, 25, 27.
fn bracket(vbar: f64) -> f64 {
    let w = (vbar - 1.0) * (vbar - 1.0);
    0.75 * w + 0.25 * w * w
}

/// Residual `cos tau2 - (sqrt(1 - v^2) + v (tau2 - arcsin v))` of eq. 8 as printed
/// (its '+' sign has no root after `tau1 = arcsin v`).
#[must_use]
pub(crate) fn eq8_printed_residual(vbar: f64, tau2: f64) -> f64 {
    tau2.cos() - ((1.0 - vbar * vbar).sqrt() + vbar * (tau2 - vbar.asin()))
}

/// Residual `cos tau2 - (sqrt(1 - v^2) - v (tau2 - arcsin v))` of eq. 8 with the
/// sign corrected: zero at the stick's end.
#[must_use]
pub(crate) fn eq8_corrected_residual(vbar: f64, tau2: f64) -> f64 {
    tau2.cos() - ((1.0 - vbar * vbar).sqrt() - vbar * (tau2 - vbar.asin()))
}

/// Eq. 11 (empirical fit, no contact loss): `1 - amp [3/4 (v-1)^2 + 1/4 (v-1)^4]`;
/// 1 for `vbar >= 1` (the seed: no reduction beyond the critical velocity).
#[must_use]
pub(crate) fn eq11(vbar: f64, amp: f64) -> f64 {
    if vbar >= 1.0 {
        1.0
    } else {
        1.0 - amp * bracket(vbar)
    }
}

/// Eq. 12 (low-velocity asymptote): `1 + amp (-1 + pi v - 4/3 sqrt(pi) v^(3/2) + v^2/2)`.
#[must_use]
pub(crate) fn eq12(vbar: f64, amp: f64) -> f64 {
    1.0 + amp * (-1.0 + PI * vbar - 4.0 / 3.0 * PI.sqrt() * vbar.powf(1.5) + 0.5 * vbar * vbar)
}

/// Eq. 16: eq. 11 in `vhat = vbar amp` (eq. 15).
#[must_use]
pub(crate) fn eq16(vhat: f64, amp: f64) -> f64 {
    eq11(vhat / amp, amp)
}

/// Eq. 17 (rough approximation for jumping): eq. 11 at `amp = 1`.
#[must_use]
pub(crate) fn eq17(vbar: f64) -> f64 {
    eq11(vbar, 1.0)
}

/// Small-velocity slope `mu/(mu0 vbar)` for `amp > 1`, eq. 21 corrected:
/// `(pi - th)^2 / (s (pi - th) + sin th)`, `s = 1/amp`, `th = arccos s`.
#[must_use]
pub(crate) fn eq21_slope(amp: f64) -> f64 {
    let s = 1.0 / amp;
    let th = s.acos();
    (PI - th).powi(2) / (s * (PI - th) + th.sin())
}

/// Eq. 21 as printed: `(1 - th/pi)^2 / (s (1 - th/pi + (1/pi)(amp) sqrt(1 - s^2)))`
/// -- smaller than the exact slope by exactly `pi`.
#[must_use]
pub(crate) fn eq21_slope_printed(amp: f64) -> f64 {
    let s = 1.0 / amp;
    let th = s.acos();
    (1.0 - th / PI).powi(2) / (s * (1.0 - th / PI + amp * (1.0 - s * s).sqrt() / PI))
}

/// Eq. 22 / Fig. 5 caption, the large-amplitude limit of the slope: printed `pi/4`.
pub(crate) const EQ22_PRINTED: f64 = PI / 4.0;
/// The same limit, corrected: `pi^2/4` (eq. 21 corrected as `amp -> infinity`).
pub(crate) const EQ22_CORRECTED: f64 = PI * PI / 4.0;

/// Eq. 27 (universal form): `1 - (1 - mu_static)[3/4 (v-1)^2 + 1/4 (v-1)^4]`.
#[must_use]
pub(crate) fn eq27(vbar: f64, mu_static: f64) -> f64 {
    if vbar >= 1.0 {
        1.0
    } else {
        1.0 - (1.0 - mu_static) * bracket(vbar)
    }
}

/// Eq. 28 (simpler form): `1 - (1 - mu_static)(1 - v)^2.4`.
#[must_use]
pub(crate) fn eq28(vbar: f64, mu_static: f64) -> f64 {
    if vbar >= 1.0 {
        1.0
    } else {
        1.0 - (1.0 - mu_static) * (1.0 - vbar).powf(2.4)
    }
}

/// One of the seed's approximations of `mu_macro/mu0` (or of its slope), with
/// its parameters: a curve of one abscissa, [`Approximation::value`]'s `x`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Approximation {
    /// Eq. 11 (empirical fit, no contact loss) against `vbar`:
    /// `1 - amp [3/4 (v-1)^2 + 1/4 (v-1)^4]`, 1 for `vbar >= 1`.
    Eq11 {
        /// `du/u0`.
        amp: f64,
    },
    /// Eq. 12 (low-velocity asymptote) against `vbar`:
    /// `1 + amp (-1 + pi v - 4/3 sqrt(pi) v^(3/2) + v^2/2)`.
    Eq12 {
        /// `du/u0`.
        amp: f64,
    },
    /// Eq. 16, eq. 11 against `vhat = vbar amp` (eq. 15).
    Eq16 {
        /// `du/u0`.
        amp: f64,
    },
    /// Eq. 17 (rough approximation for jumping) against `vbar`: eq. 11 at `amp = 1`.
    Eq17,
    /// The small-velocity slope `mu/(mu0 vbar)` for `amp > 1` against `amp`,
    /// eq. 21 corrected: `(pi - th)^2 / (s (pi - th) + sin th)`, `s = 1/amp`,
    /// `th = arccos s`.
    Eq21Slope,
    /// Eq. 21 as printed against `amp`: smaller than the exact slope by exactly `pi`.
    Eq21SlopePrinted,
    /// Eq. 22 / Fig. 5 caption, the slope's large-amplitude limit as printed: `pi/4`
    /// (a constant of `x`).
    Eq22Printed,
    /// The same limit corrected: `pi^2/4` (eq. 21 corrected as `amp -> infinity`).
    Eq22Corrected,
    /// Eq. 27 (universal form) against `vbar`:
    /// `1 - (1 - mu_static)[3/4 (v-1)^2 + 1/4 (v-1)^4]`, 1 for `vbar >= 1`.
    Eq27 {
        /// The static coefficient's ratio `mu(vbar = 0)/mu0`.
        mu_static: f64,
    },
    /// Eq. 28 (simpler form) against `vbar`: `1 - (1 - mu_static)(1 - v)^2.4`,
    /// 1 for `vbar >= 1`.
    Eq28 {
        /// The static coefficient's ratio `mu(vbar = 0)/mu0`.
        mu_static: f64,
    },
}

impl Approximation {
    /// The approximation at `x`: `vbar` (eqs. 11, 12, 17, 27, 28), `vhat`
    /// (eq. 16) or `amp` (eqs. 21, 22).
    ///
    /// ```
    /// use fricosc::seed::Approximation;
    /// assert_eq!(Approximation::Eq11 { amp: 0.4 }.value(0.0), 0.6);
    /// assert_eq!(Approximation::Eq17.value(1.5), 1.0);
    /// ```
    #[must_use]
    pub fn value(self, x: f64) -> f64 {
        match self {
            Approximation::Eq11 { amp } => eq11(x, amp),
            Approximation::Eq12 { amp } => eq12(x, amp),
            Approximation::Eq16 { amp } => eq16(x, amp),
            Approximation::Eq17 => eq17(x),
            Approximation::Eq21Slope => eq21_slope(x),
            Approximation::Eq21SlopePrinted => eq21_slope_printed(x),
            Approximation::Eq22Printed => EQ22_PRINTED,
            Approximation::Eq22Corrected => EQ22_CORRECTED,
            Approximation::Eq27 { mu_static } => eq27(x, mu_static),
            Approximation::Eq28 { mu_static } => eq28(x, mu_static),
        }
    }
}
