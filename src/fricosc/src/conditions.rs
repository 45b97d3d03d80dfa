//! What is asked of a contact: the sliding velocity, the normal and the
//! tangential oscillation, and the quadrature tolerance. Checked once, where
//! it is built; everything downstream trusts it.

use crate::error::{check_nonneg, Error, Result};
use crate::plane::Transverse;
use crate::system::System;
use std::f64::consts::TAU;

/// Default relative quadrature tolerance of curved shapes: about what f64 allows.
pub const DEFAULT_TOL: f64 = 4e-15;

/// Largest tangential amplitude and velocity accepted with a tangential
/// oscillation (pre-slip lengths): beyond it the phase's rounding (an ulp of
/// the phase, times `T`) is the answer's scale; near there the rigid-body law
/// `(2/pi) asin(vhat/T)` holds to about 1e-6.
pub(crate) const MAX_TANGENTIAL_AMP: f64 = 1e6;

/// The sliding velocity, in the seed's two forms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Velocity {
    /// `vbar = (kx/kz) v0 / (mu0 omega du)` (eq. 3).
    Vbar(f64),
    /// `vhat = (kx/kz) v0 / (mu0 omega u0) = vbar amp` (eq. 15).
    Vhat(f64),
}

/// The conditions of one point: the velocity, the amplitude `amp = du/u0` of
/// the normal oscillation, optionally an oscillation in the sliding direction
/// (its amplitude `T = dx/l` in pre-slip lengths `l = mu0 u0 kz/kx`, and its
/// phase against the normal oscillation), and the quadrature tolerance of
/// curved shapes.
///
/// ```
/// use fricosc::{Conditions, Shape};
/// // The seed's problem at vbar = 0.3, du/u0 = 0.4.
/// let c = Conditions::vbar(0.3, 0.4)?;
/// assert!((Shape::flat().evaluate(&c)?.ratio.mu_ratio - 0.8317432589602997).abs() < 1e-15);
/// // The same velocity as vhat, with an oscillation in the sliding direction.
/// let c = Conditions::vhat(0.12, 0.4)?.with_tangential(1.5, 0.7)?;
/// assert!(Shape::flat().evaluate(&c)?.ratio.mu_ratio < 0.8);
/// # Ok::<(), fricosc::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conditions {
    velocity: Velocity,
    amp: f64,
    tangential: Option<(f64, f64)>,
    transverse: Option<Transverse>,
    tol: f64,
    system: Option<System>,
}

impl Conditions {
    /// The seed's problem at `vbar` (eq. 3) and `amp`, both finite and `>= 0`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming the bad input.
    pub fn vbar(vbar: f64, amp: f64) -> Result<Conditions> {
        check_nonneg("vbar", vbar)?;
        check_nonneg("amp", amp)?;
        Ok(Conditions {
            velocity: Velocity::Vbar(vbar + 0.0),
            amp: amp + 0.0,
            tangential: None,
            transverse: None,
            tol: DEFAULT_TOL,
            system: None,
        })
    }

    /// The seed's problem at `vhat = vbar amp` (eq. 15) and `amp`, both finite
    /// and `>= 0`; `vbar = vhat/amp` must be finite, unless a tangential
    /// oscillation follows ([`Conditions::with_tangential`]), which needs no
    /// `vbar` (it is undefined at `amp = 0`).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming the bad input.
    pub fn vhat(vhat: f64, amp: f64) -> Result<Conditions> {
        check_nonneg("vhat", vhat)?;
        check_nonneg("amp", amp)?;
        Ok(Conditions {
            velocity: Velocity::Vhat(vhat + 0.0),
            amp: amp + 0.0,
            tangential: None,
            transverse: None,
            tol: DEFAULT_TOL,
            system: None,
        })
    }

    /// These conditions with an oscillation in the sliding direction of
    /// amplitude `t` (pre-slip lengths, `>= 0`, at most
    /// 1e6) and phase `phase` (radians, finite; reduced to
    /// `[0, 2 pi)`): the body's position is `vhat tau + t sin(tau + phase)`
    /// while the indentation is `u0 - du cos tau`. The velocity must be `vhat`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming the bad input, or the velocity given as `vbar`.
    pub fn with_tangential(self, t: f64, phase: f64) -> Result<Conditions> {
        let Velocity::Vhat(vhat) = self.velocity else {
            return Err(Error::param(
                "tangential-amp",
                t,
                "needs the velocity as vhat (vbar = vhat/amp is undefined without normal oscillation)",
            ));
        };
        check_nonneg("tangential-amp", t)?;
        if !phase.is_finite() {
            return Err(Error::param("phase", phase, "must be finite"));
        }
        if t > MAX_TANGENTIAL_AMP || vhat > MAX_TANGENTIAL_AMP {
            let (name, value) = if vhat > MAX_TANGENTIAL_AMP { ("vhat", vhat) } else { ("tangential-amp", t) };
            return Err(Error::param(
                name,
                value,
                "must be <= 1e6 pre-slip lengths (the rounding of the phase grows with T; near there the rigid-body law (2/pi) asin(vhat/T) holds to ~1e-6)",
            ));
        }
        Ok(Conditions { tangential: Some((t + 0.0, reduce_phase(phase))), ..self })
    }

    /// These conditions with the relative quadrature tolerance `tol` of
    /// curved shapes (ignored by the flat punch): finite, in `(0, 1)`; looser
    /// is faster. Default [`DEFAULT_TOL`].
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a tolerance outside `(0, 1)` or not finite.
    pub fn with_tol(self, tol: f64) -> Result<Conditions> {
        if tol.is_finite() && tol > 0.0 && tol < 1.0 {
            Ok(Conditions { tol, ..self })
        } else {
            Err(Error::param("tol", tol, "must be finite, > 0 and < 1"))
        }
    }

    /// These conditions with the body on a system with mass and stiffness
    /// ([`crate::system`]): [`crate::Shape::evaluate`], `ratio` and `report`
    /// then answer with the body's attractor (a [`crate::Report::System`]).
    ///
    /// ```
    /// use fricosc::system::System;
    /// use fricosc::{Conditions, Report, Shape};
    ///
    /// let c = Conditions::vbar(0.3, 0.5)?.with_system(System::new(1.0, 0.5, 0.05)?);
    /// let Report::System(r) = Shape::flat().report(&c)? else { unreachable!() };
    /// assert_eq!(r.period, Some(1));
    /// assert!(r.mu_ratio > 0.0 && r.mu_ratio < 1.0 && r.error_estimate < 1e-13);
    /// # Ok::<(), fricosc::Error>(())
    /// ```
    #[must_use]
    pub fn with_system(self, system: System) -> Conditions {
        Conditions { system: Some(system), ..self }
    }

    /// These conditions with an oscillation across the sliding direction
    /// ([`crate::plane`]): [`crate::Shape::evaluate`] and `report` then answer
    /// in the plane, with the mean force across the sliding direction. `W = 0`
    /// is the problem without it, answered as before bit for bit.
    ///
    /// ```
    /// use fricosc::plane::Transverse;
    /// use fricosc::{Conditions, Shape};
    ///
    /// let c = Conditions::vhat(0.3, 0.5)?.with_transverse(Transverse::new(1.2, 0.7)?);
    /// let e = Shape::flat().evaluate(&c)?;
    /// assert!((e.ratio.mu_ratio - 0.61462234012588).abs() < 1e-13);
    /// assert!(e.transverse_ratio.is_some_and(|t| t < -0.24));
    /// # Ok::<(), fricosc::Error>(())
    /// ```
    #[must_use]
    pub fn with_transverse(self, w: Transverse) -> Conditions {
        Conditions { transverse: (w.amp() > 0.0).then_some(w), ..self }
    }

    /// The oscillation across the sliding direction, if any (`W > 0`).
    #[must_use]
    pub fn transverse(&self) -> Option<Transverse> {
        self.transverse
    }

    /// These conditions without a system (the stiff problem).
    #[must_use]
    pub fn stiff(self) -> Conditions {
        Conditions { system: None, ..self }
    }

    /// The system the body is on, if any.
    #[must_use]
    pub fn system(&self) -> Option<&System> {
        self.system.as_ref()
    }

    /// The velocity as given.
    #[must_use]
    pub fn velocity(&self) -> Velocity {
        self.velocity
    }

    /// The amplitude `du/u0` of the normal oscillation.
    #[must_use]
    pub fn amp(&self) -> f64 {
        self.amp
    }

    /// The tangential oscillation `(T, phase)`, phase in `[0, 2 pi)`, if any.
    #[must_use]
    pub fn tangential(&self) -> Option<(f64, f64)> {
        self.tangential
    }

    /// The quadrature tolerance.
    #[must_use]
    pub fn tol(&self) -> f64 {
        self.tol
    }

    /// The velocity as `vhat = vbar amp` (eq. 15).
    #[must_use]
    pub fn as_vhat(&self) -> f64 {
        match self.velocity {
            Velocity::Vbar(v) => v * self.amp,
            Velocity::Vhat(v) => v,
        }
    }

    /// The velocity as `vbar` (eq. 3): as given, or `vhat/amp`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] where `vhat/amp` is undefined (`amp = 0`)
    /// or overflows.
    pub fn as_vbar(&self) -> Result<f64> {
        match self.velocity {
            Velocity::Vbar(v) => Ok(v),
            Velocity::Vhat(v) => vbar_from_vhat(v, self.amp),
        }
    }
}

/// The oscillations in the plane of a point, as outputs report them: `T` and
/// its phase along the sliding direction, `W` and `psi` across it (phases in
/// `[0, 2 pi)`), each absent without that oscillation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct InPlane {
    /// The tangential amplitude `T = dx/l`, if the body oscillates in the sliding direction.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub tangential_amp: Option<f64>,
    /// Its phase against the normal oscillation (radians in `[0, 2 pi)`).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub phase: Option<f64>,
    /// The transverse amplitude `W = dy/l`, if the body oscillates across the sliding direction.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub transverse_amp: Option<f64>,
    /// Its phase against the normal oscillation (radians in `[0, 2 pi)`).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub transverse_phase: Option<f64>,
}

impl InPlane {
    /// The oscillations in the plane of `c`.
    #[must_use]
    pub fn of(c: &Conditions) -> InPlane {
        InPlane::new(c.tangential(), c.transverse())
    }

    /// From `(T, phase)` and the transverse drive.
    pub(crate) fn new(tangential: Option<(f64, f64)>, w: Option<Transverse>) -> InPlane {
        InPlane {
            tangential_amp: tangential.map(|x| x.0),
            phase: tangential.map(|x| x.1),
            transverse_amp: w.map(|w| w.amp()),
            transverse_phase: w.map(|w| w.phase()),
        }
    }

    /// Whether the body oscillates in the plane at all.
    #[must_use]
    pub fn any(&self) -> bool {
        self.tangential_amp.is_some() || self.transverse_amp.is_some()
    }
}

/// `vbar` (eq. 3) from `vhat = vbar amp` (eq. 15): `vhat / amp`, refused where
/// `amp` is 0 (the velocity has no `vbar` then) or the quotient overflows.
fn vbar_from_vhat(vhat: f64, amp: f64) -> Result<f64> {
    if amp > 0.0 {
        let vbar = vhat / amp;
        if vbar.is_finite() {
            Ok(vbar)
        } else {
            Err(Error::param("vbar", vbar, &format!("vhat / amp = {vhat:?} / {amp:?} overflows double precision")))
        }
    } else {
        Err(Error::param("amp", amp, "vhat needs amp > 0 (vbar = vhat / amp)"))
    }
}

/// `phase mod 2 pi` in `[0, 2 pi)` to an ulp or two of the exact remainder
/// at every magnitude: `atan2(sin phase, cos phase)`, whose `sin` and `cos`
/// reduce their argument exactly (libm's Payne-Hanek reduction), where a
/// remainder taken with the double `2 pi` would be off by `|phase| 2.4e-16 /
/// 2 pi`. A phase already in `[0, 2 pi)` is kept as given.
fn reduce_phase(phase: f64) -> f64 {
    if (0.0..TAU).contains(&phase) {
        return phase + 0.0;
    }
    let r = libm::atan2(libm::sin(phase), libm::cos(phase));
    let r = if r < 0.0 { r + TAU } else { r + 0.0 };
    // A remainder within half an ulp below 2 pi rounds to it: the same phase as 0.
    if r >= TAU {
        0.0
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `amp = 0` is refused as such (not as an overflow of `vhat / 0`), with
    /// `vhat` zero or not; the overflow is named.
    #[test]
    fn vbar_from_vhat_refuses_a_zero_amplitude_by_name() {
        for vhat in [0.0, 0.3] {
            let e = Conditions::vhat(vhat, 0.0).unwrap().as_vbar().unwrap_err().to_string();
            assert!(e.contains("needs amp > 0") && !e.contains("overflows"), "{e}");
        }
        let e = Conditions::vhat(1e300, 1e-300).unwrap().as_vbar().unwrap_err().to_string();
        assert!(e.contains("overflows"), "{e}");
        assert_eq!(Conditions::vhat(0.0, 5e-324).unwrap().as_vbar().unwrap(), 0.0);
    }

    /// Every input is checked where the conditions are built, by name.
    #[test]
    fn bad_inputs_are_named() {
        let name = |e: Error| match e {
            Error::InvalidParameter { name, .. } => name,
            _ => "",
        };
        assert_eq!(name(Conditions::vbar(-1.0, 0.5).unwrap_err()), "vbar");
        assert_eq!(name(Conditions::vbar(0.5, f64::NAN).unwrap_err()), "amp");
        assert_eq!(name(Conditions::vhat(f64::INFINITY, 0.5).unwrap_err()), "vhat");
        let c = Conditions::vhat(0.3, 0.5).unwrap();
        assert_eq!(name(c.with_tangential(-1.0, 0.0).unwrap_err()), "tangential-amp");
        assert_eq!(name(c.with_tangential(1.0, f64::NAN).unwrap_err()), "phase");
        assert_eq!(name(c.with_tangential(2e6, 0.0).unwrap_err()), "tangential-amp");
        assert_eq!(name(c.with_tol(1.0).unwrap_err()), "tol");
        assert_eq!(name(Conditions::vbar(0.3, 0.5).unwrap().with_tangential(1.0, 0.0).unwrap_err()), "tangential-amp");
        // -0 is 0; a phase is reduced to [0, 2 pi).
        let c = Conditions::vhat(-0.0, 0.5).unwrap().with_tangential(1.0, -1.0).unwrap();
        assert_eq!(c.as_vhat().to_bits(), 0);
        assert_eq!(c.tangential(), Some((1.0, TAU - 1.0)));
    }

    /// The exact remainders `x - 2 pi floor(x / 2 pi)` (mpmath, 400 digits,
    /// rounded to double): within 2 ulps at every magnitude. The double `2 pi`
    /// would miss them by 1.6e-11 at 1e6 and by 0.1 at 1e16.
    #[test]
    fn a_large_phase_is_reduced_exactly() {
        let exact = [
            (1e6, 5.925621140093852),
            (1e10, 5.773954235013852),
            (1e16, 2.2474252491623665),
            (-1e16, 4.03576005801722),
            (1e300, 4.099312823027354),
            (f64::MAX, 3.136630678439006),
            (-3.0, 3.2831853071795867),
            (7.0, 0.7168146928204135),
        ];
        for (x, r) in exact {
            let (_, got) = Conditions::vhat(0.1, 0.5).unwrap().with_tangential(1.0, x).unwrap().tangential().unwrap();
            assert!((got - r).abs() <= 2.0 * f64::EPSILON * r, "{x}: {got} against {r}");
        }
    }

    /// A value beyond the limit is named with its own value (`vhat = 3e6`
    /// was reported with `T`'s 1e7).
    #[test]
    fn the_input_beyond_the_limit_is_named_with_its_value() {
        let e = Conditions::vhat(3e6, 0.0).unwrap().with_tangential(1e7, 0.0).unwrap_err().to_string();
        assert!(e.starts_with("invalid vhat = 3e6: must be <= 1e6"), "{e}");
        let e = Conditions::vhat(0.3, 0.0).unwrap().with_tangential(1e7, 0.0).unwrap_err().to_string();
        assert!(e.starts_with("invalid tangential-amp = 1e7: must be <= 1e6"), "{e}");
    }
}
