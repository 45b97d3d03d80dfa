//! One spring: regimes, event times and closed-form phase integrals.
//!
//! # Model (seed section 2)
//! Time is the phase `tau = omega t`. The spring's normal force, in units of
//! `kz du`, is the Coulomb bound `B(tau) = (s - cos tau)_+` with `s = u0/du`.
//! The tangential force `F`, in units of `mu0 kz du`, grows at rate `vbar`
//! (eq. 3) while stuck and equals `B` while slipping; out of contact the spring
//! is relaxed. The periodic steady state is the lower envelope
//! `F(tau) = inf_{sigma <= tau} [B(sigma) + vbar (tau - sigma)]`.
//!
//! # One stick phase per period
//! With `w = 1 - vbar`, `alpha = arccos vbar` and `c = sqrt(1 - vbar^2) = sin alpha`,
//! a spring that sticks at all does so exactly once per period, starting at
//! `tau_s = pi/2 - beta` with force `B(tau_s)`:
//! - tangent start (`s >= c`: permanent contact or "slip first"): `beta = alpha`,
//!   i.e. `sin tau_1 = vbar` (eq. 4), where the bound's slope falls to `vbar`;
//! - start at contact (`|s| < c`, "stick first"): `beta = arcsin s`, i.e. the
//!   contact time `cos theta = s` (eq. 18), with force 0.
//!
//! Writing `x = tau - tau_s` and `sin y = y - S(y)`, the gap between the bound and
//! the stick line is
//! `H(x) = B(tau_s + x) - B(tau_s) - vbar x = S(beta - x) - S(beta) + w x`,
//! with `S(y) = y - sin y` (`special::x_minus_sin`). The stick ends at the
//! root `L` of `H` on `(alpha + beta, x_max)`, where `H` decreases from its
//! maximum; `x_max = 2 pi` for a tangent start and `pi + 2 beta` (the loss of
//! contact) for a start at contact, where `H(x_max) = -2 pi vbar` resp.
//! `-vbar (pi + 2 beta)`. For the tangent start `H(L) = 0` is eq. 8 with the
//! sign corrected: `cos tau_2 = sqrt(1 - vbar^2) - vbar (tau_2 - arcsin vbar)`.
//!
//! The friction lost to sticking, per period mean, is the deficit
//! `D = (1/2pi) int_0^L H dx = (1/2pi) [C(beta) - C(beta - L) - S(beta) L + w L^2/2]`
//! with `C(y) = y^2/2 - (1 - cos y)`, `C' = S`. Every term is of the order of
//! the result (about `alpha^4` near `vbar = 1`), so `D` keeps full relative
//! accuracy, except where a stick from contact is short, `beta` near `-alpha`
//! (`s` just above `-c`): there `D` is of order `(alpha + beta)^3` and is
//! computed as a product instead (`short_stick`). And `dD/dL = H(L) = 0`: an
//! error `e` in `L` changes `D` by `O(e^2)`,
//! so the means need `L` only to about 1e-8 relative (`ROOT_RTOL_MEANS` (1e-6), or
//! a Halley step whose next iterate's predicted error is below `ROOT_ACCEPT_MEANS`).
//!
//! Mean tangential force `<F> = <B> - D`, and `mu_macro/mu0 = <F>/<B>`.

use crate::special::{nonneg, x_minus_sin as s_fn};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

mod stick;
mod velocity;

use stick::{stick_phase, Start, SHORT_STICK};
pub(crate) use velocity::{LengthNode, LengthTop, Velocity};

/// How precisely a spring's stick phase is solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Precision {
    /// Enough for the means to full accuracy (`ROOT_RTOL_MEANS` (1e-6)).
    Means,
    /// Event times to full double precision ([`ROOT_RTOL_EVENTS`]).
    Events,
}

impl Precision {
    fn rtol(self) -> f64 {
        match self {
            Precision::Means => ROOT_RTOL_MEANS,
            Precision::Events => ROOT_RTOL_EVENTS,
        }
    }
}

/// Relative root tolerance when only mean forces are wanted. Halley's method
/// stops once a step is below this (relative) and returns the next iterate,
/// whose error is then about its cube (1e-18, at worst Newton's square, 1e-12);
/// the deficit is stationary in the stick length,
/// so its relative error is of the order of that squared again. A Halley step
/// also ends it where its next iterate's predicted error is below
/// [`ROOT_ACCEPT_MEANS`] (one evaluation where the start is good to ~5e-4).
pub(crate) const ROOT_RTOL_MEANS: f64 = 1e-6;
/// The predicted relative error of a stick end that Halley's method accepts
/// when only means are wanted (they need ~1e-8: see [`ROOT_RTOL_MEANS`]); in
/// the tail form relative to the shorter of the tail and the length: it
/// saves most sticks their last evaluation, and keeps a factor 100 of margin
/// below what the means need.
const ROOT_ACCEPT_MEANS: f64 = 1e-10;

/// [`root::halley`]'s acceptance of a predicted error for `rtol`: only for the
/// means (event times are found to the last bit, step by step).
fn accept_of(rtol: f64) -> f64 {
    if rtol == ROOT_RTOL_MEANS {
        ROOT_ACCEPT_MEANS
    } else {
        0.0
    }
}

/// Relative root tolerance when event times are reported.
pub(crate) const ROOT_RTOL_EVENTS: f64 = 4.0 * f64::EPSILON;

/// What one spring does during a period.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Regime {
    /// `s <= -1`: the spring never touches.
    NeverInContact,
    /// `s >= 1`, `vbar >= 1`: always in contact, always slipping (mu = mu0).
    PermanentSlip,
    /// `s >= 1`, `vbar < 1`: always in contact; one slip->stick (eq. 4) and one
    /// stick->slip (eq. 8, corrected) event per period.
    PermanentStickSlip,
    /// `|s| < 1` and no stick (`vbar >= 1`, or `s <= -sqrt(1 - vbar^2)`): contact
    /// is lost and regained (eq. 18), slipping whenever in contact.
    JumpingSlip,
    /// `sqrt(1 - vbar^2) <= s < 1`, `vbar < 1`: contact, slip, stick (eq. 4),
    /// slip (eq. 8), loss of contact.
    JumpingSlipFirst,
    /// `|s| < sqrt(1 - vbar^2)`: sticks from the moment of contact, slips, loses
    /// contact.
    JumpingStickFirst,
}

/// The kind of a transition within the period.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum EventKind {
    /// Contact is (re)gained, with zero force.
    Contact,
    /// Contact is lost; the spring relaxes.
    LossOfContact,
    /// Slip (or contact) turns into stick.
    Stick,
    /// Stick turns into slip (in the sliding direction: `f = +B`).
    Slip,
    /// Stick turns into slip against the sliding direction (`f = -B`; only
    /// under a tangential oscillation).
    BackwardSlip,
}

impl EventKind {
    /// The name reports print (as JSON writes it).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            EventKind::Contact => "contact",
            EventKind::LossOfContact => "loss_of_contact",
            EventKind::Stick => "stick",
            EventKind::Slip => "slip",
            EventKind::BackwardSlip => "backward_slip",
        }
    }
}

/// A transition at phase `tau` in `[0, 2 pi)`, with the forces there.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Event {
    /// What happens.
    pub kind: EventKind,
    /// Phase `omega t` in `[0, 2 pi)`; the indentation is `u0 - du cos tau`.
    pub tau: f64,
    /// Normal force, units `kz du`.
    pub normal: f64,
    /// Tangential force, units `mu0 kz du`.
    pub tangential: f64,
}

/// The stick phase of a period.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stick {
    /// `beta` of the module docs: the stick starts at `tau_s = pi/2 - beta`.
    pub beta: f64,
    /// The phase `tau_s` at which the stick starts, in `[0, pi)`, to full
    /// relative accuracy: `arcsin vbar` (eq. 4) or the contact phase `arccos s`.
    pub start: f64,
    /// Duration `L` of the stick phase (in phase units).
    pub length: f64,
    /// `e = x_max - L` with full relative accuracy: the time from the stick's
    /// end to `2 pi` after its start (tangent start) or to the loss of contact.
    pub tail: f64,
    /// Tangential (= normal) force at the start of the stick, units `mu0 kz du`.
    pub start_force: f64,
}

/// The exact periodic steady state of one spring, as means and phases.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spring {
    /// Mean indentation over amplitude, `u0/du`.
    pub s: f64,
    /// Dimensionless velocity (eq. 3).
    pub vbar: f64,
    /// What the spring does.
    pub regime: Regime,
    /// Period mean of the normal force `<B>`, units `kz du`.
    pub mean_normal: f64,
    /// Period mean of the friction lost to sticking, `<B> - <F>`, units `mu0 kz du`.
    pub deficit: f64,
    /// The sum of the magnitudes of the terms `deficit` is computed from: its
    /// rounding is a few ulps of this (more than of `deficit` where the stick is long).
    pub(crate) deficit_magnitude: f64,
    /// Contact phase `theta = arccos s` of a jumping spring (`|s| < 1`; 0 otherwise):
    /// contact lasts from `theta` to `2 pi - theta` (eq. 18).
    pub theta: f64,
    /// `sin theta = sqrt((1 - s)(1 + s))` (0 where `theta` is).
    sin_theta: f64,
    /// The stick phase, if the spring sticks.
    pub stick: Option<Stick>,
    /// Function evaluations spent by the root finder.
    pub root_evaluations: u32,
}

/// Period mean of the Coulomb bound, `<B>(s) = <(s - cos tau)_+>`.
///
/// For `|s| < 1` the contact lasts `2 phi` per period with `phi = arccos(-s)`,
/// and `<B> = (s phi + sin phi)/pi = (sin phi - phi cos phi)/pi`: for `s >= 0`
/// a sum of non-negative terms, for `s < 0` written as
/// `(2 phi sin^2(phi/2) - S(phi))/pi` to keep full relative accuracy where it
/// vanishes like `(1 + s)^(3/2)` at the edge of contact.
#[must_use]
pub fn mean_normal(s: f64) -> f64 {
    mean_normal_of(s, 1.0 - s)
}

/// [`mean_normal`] with `1 - s` given unrounded by the caller (the flat punch:
/// `(amp - 1)/amp`), as [`Spring`] computes it.
pub(crate) fn mean_normal_of(s: f64, one_minus_s: f64) -> f64 {
    let (theta, sin_theta) = contact_angles(s, one_minus_s);
    mean_normal_contact(s, theta, sin_theta)
}

/// The contact phase `theta = arccos s` and `sin theta = sqrt((1 - s)(1 + s))`
/// (no cancellation) of a spring with `|s| < 1` (`1 - s > 0`: a spring whose
/// `s` rounds to 1 is still jumping); `(0, 0)` otherwise.
fn contact_angles(s: f64, one_minus_s: f64) -> (f64, f64) {
    if one_minus_s > 0.0 && s > -1.0 {
        (contact_phase(s, one_minus_s), (one_minus_s * (1.0 + s)).max(0.0).sqrt())
    } else {
        (0.0, 0.0)
    }
}

/// `<B>(s)` from the contact phase `theta = arccos s` and `sin theta`
/// ([`contact_angles`]). For `0 <= s < 1` the half-angle `phi = pi - theta`
/// lies in `(pi/2, pi]`, and `<B> = (s phi + sin phi)/pi = (s (pi - theta) +
/// sin theta)/pi`, a sum of non-negative terms (no further transcendental
/// call); for `s < 0` the cancellation-free [`mean_normal_at_angle`] of
/// `phi = arccos(-s)`, which vanishes at the edge of contact.
fn mean_normal_contact(s: f64, theta: f64, sin_theta: f64) -> f64 {
    if s >= 1.0 {
        s
    } else if s <= -1.0 {
        0.0
    } else if s >= 0.0 {
        (s * (PI - theta) + sin_theta) / PI
    } else {
        mean_normal_at_angle((-s).acos())
    }
}

/// `<B>` of a jumping spring from its contact half-angle `phi = arccos(-s)` in
/// `[0, pi]` (the contact lasts `2 phi` per period): `(2 phi sin^2(phi/2) - S(phi))/pi`.
pub(crate) fn mean_normal_at_angle(phi: f64) -> f64 {
    let h = (0.5 * phi).sin();
    (2.0 * phi * h * h - s_fn(phi)) / PI
}

/// `<B>` of the spring with `s = sin beta`, from `beta` in `[-pi/2, pi/2]` and its
/// sine and cosine (no further transcendental calls on the hot path): with the
/// contact half-angle `phi = pi/2 + beta`, `<B> = (s phi + cos beta)/pi`, and near
/// the edge of contact (`phi < 2`) the cancellation-free
/// `(phi (1 + s) - S(phi))/pi` with `1 + s = cos^2 beta / (1 - s)`.
pub(crate) fn mean_normal_sin_cos(beta: f64, sin_beta: f64, cos_beta: f64) -> f64 {
    let phi = FRAC_PI_2 + beta;
    if phi < 2.0 {
        let one_plus_s = if sin_beta < 0.0 { cos_beta * cos_beta / (1.0 - sin_beta) } else { 1.0 + sin_beta };
        (phi * one_plus_s - s_fn(phi)) / PI
    } else {
        (sin_beta * phi + cos_beta) / PI
    }
}

/// The contact phase `theta = arccos s` of a jumping spring, `|s| < 1`, from
/// `s` and `1 - s`: `2 arcsin(sqrt((1 - s)/2))` for `s > 1/2` (no rounding of
/// `s` near 1 enters), `arccos s` elsewhere (well conditioned there).
pub(crate) fn contact_phase(s: f64, one_minus_s: f64) -> f64 {
    if s > 0.5 {
        2.0 * (0.5 * one_minus_s).sqrt().asin()
    } else {
        s.acos()
    }
}

impl Spring {
    /// Steady state of a spring with `s = u0/du` at velocity `vbar`, computing
    /// stick times to `ROOT_RTOL_MEANS` (1e-6) (enough for means to full accuracy).
    ///
    /// `vbar = 0` is the limit `vbar -> 0+`: exactly at zero velocity the
    /// tangential force is not determined by the oscillation (it depends on the
    /// initial state), and the limit is the value every time stepper converges to.
    /// Inputs must be finite with `vbar >= 0` (checked by the public APIs above this).
    #[must_use]
    pub fn new(s: f64, vbar: f64) -> Self {
        Self::solve(s, 1.0 - s, vbar, ROOT_RTOL_MEANS, None)
    }

    /// As [`Spring::new`], with event times to full double precision.
    #[must_use]
    pub fn with_events(s: f64, vbar: f64) -> Self {
        Self::solve(s, 1.0 - s, vbar, ROOT_RTOL_EVENTS, None)
    }

    /// As [`Spring::new`] (or [`Spring::with_events`]) for a spring given by
    /// `s` and `one_minus_s = 1 - s` computed without cancellation by the caller
    /// (the flat punch: `(amp - 1)/amp`), so that the contact phase `arccos s`
    /// keeps its relative accuracy as `s -> 1-`. `margin`, if given (only
    /// for `s > 0`), is `s - sqrt(1 - vbar^2)` computed by the caller from its
    /// exact inputs (the flat punch: `(1 - amp sqrt(1 - vbar^2))/amp`): its sign
    /// decides a jumping spring's start where `s` itself is too rounded to, and
    /// after a start on the bound (also in permanent contact) it is the start
    /// force: where it is small (`s -> 1`, `vbar -> 0`), `s` itself is rounded
    /// by more than it.
    pub(crate) fn with_complement(
        s: f64,
        one_minus_s: f64,
        vbar: f64,
        precision: Precision,
        margin: Option<f64>,
    ) -> Self {
        Self::solve(s, one_minus_s, vbar, precision.rtol(), margin)
    }

    fn solve(s: f64, one_minus_s: f64, vbar: f64, rtol: f64, margin: Option<f64>) -> Self {
        let (theta, sin_theta) = contact_angles(s, one_minus_s);
        let mean_normal = mean_normal_contact(s, theta, sin_theta);
        let mut out = Spring {
            s,
            vbar,
            regime: Regime::NeverInContact,
            mean_normal,
            deficit: 0.0,
            deficit_magnitude: 0.0,
            theta,
            sin_theta,
            stick: None,
            root_evaluations: 0,
        };
        if s <= -1.0 {
            return out;
        }
        if vbar >= 1.0 {
            out.regime = if s >= 1.0 { Regime::PermanentSlip } else { Regime::JumpingSlip };
            return out;
        }
        let vel = Velocity::new(vbar);
        // c = sqrt(1 - vbar^2) = sqrt((1 - vbar)(1 + vbar)).
        let c = || (vel.w * (1.0 + vbar)).sqrt();
        // Which side of c the spring is on decides its start, free of the
        // rounding of c (a spring at the switch must not land on the wrong side,
        // where its start force would be a negative rounding error): for
        // 0 < s < 1 the sign of s - c itself (the caller's margin, else
        // (s^2 - c^2)/(s + c)), which is then the start force on the bound; for
        // s <= 0 the sign of s^2 - c^2 = vbar^2 - (1 - s)(1 + s) (error-free
        // products), i.e. whether |s| >= c.
        let square = || crate::special::square_margin(vbar, one_minus_s, s);
        // A stick from contact: its distance eps = alpha + beta from the end of
        // the sticks (beta = -alpha, s = -c). Near it (s < 0) from the inputs
        // alone, as the angle whose sine is sin(alpha + beta) = c sin(theta) +
        // vbar s = (c^2 - s^2)/(c sin(theta) - vbar s) with s^2 - c^2 = s^2 +
        // vbar^2 - 1 summed error-free: the short stick's deficit, of order eps^3, then
        // keeps its relative accuracy ([`short_stick`]).
        // (Computed only for a spring that sticks from contact: every node of a
        // tabulated or worn body's bands is solved here.)
        let contact = || {
            let plain = vel.alpha + (FRAC_PI_2 - theta);
            let eps = if s < 0.0 && plain < 2.0 * SHORT_STICK * vel.alpha {
                let margin = crate::special::squares_minus_one(s, vbar);
                (-margin / (c() * sin_theta - vbar * s)).asin()
            } else {
                plain
            };
            Start::Contact { theta, sin_theta, cos_theta: s, eps }
        };
        let (start, regime, start_force) = if one_minus_s <= 0.0 {
            // In permanent contact: s - c = (s - 1) + vbar^2/(1 + c) (no
            // cancellation of 1 - c as vbar -> 0), or the caller's margin.
            let s_minus_c = margin.unwrap_or_else(|| (s - 1.0) + vbar * vbar / (1.0 + c()));
            (Start::Tangent, Regime::PermanentStickSlip, s_minus_c)
        } else if s > 0.0 {
            let s_minus_c = margin.unwrap_or_else(|| square() / (s + c()));
            if s_minus_c >= 0.0 {
                (Start::Tangent, Regime::JumpingSlipFirst, nonneg(s_minus_c))
            } else {
                (contact(), Regime::JumpingStickFirst, 0.0)
            }
        } else if square() < 0.0 {
            (contact(), Regime::JumpingStickFirst, 0.0)
        } else {
            out.regime = Regime::JumpingSlip;
            return out;
        };
        let sol = stick_phase(start, &vel, rtol);
        let (beta, tau_s) = match start {
            Start::Tangent => (vel.alpha, vel.delta),
            Start::Contact { theta, .. } => (FRAC_PI_2 - theta, theta),
        };
        out.regime = regime;
        out.deficit = sol.deficit;
        out.deficit_magnitude = sol.magnitude;
        out.stick = Some(Stick { beta, start: tau_s, length: sol.length, tail: sol.tail, start_force });
        out.root_evaluations = sol.evaluations;
        out
    }

    /// Period mean of the tangential force, units `mu0 kz du`.
    ///
    /// For a stick from contact it is integrated directly, with full relative
    /// accuracy where it is small (`vbar -> 0`, where `<B> - D` would cancel):
    /// the stick contributes `vbar L^2/2`; the slip lasts the tail `e` before the
    /// loss of contact at `2 pi - theta`, where `B(2 pi - theta - y) =
    /// s (1 - cos y) + sin(theta) sin y`, so it contributes
    /// `s S(e) + 2 sin(theta) sin^2(e/2)`: for `s >= 0` (every flat punch) a sum
    /// of non-negative terms. A jumping spring that slips first adds the slip
    /// from contact to the stick, `d = delta - theta` long (the same form), and
    /// the stick's own `F(tau_s) L`; its final slip lasts `e - delta - theta`.
    /// In permanent contact it is `F(tau_s) + (<F> - F(tau_s))`
    /// (`Spring::tangent_excess`), both parts without cancellation.
    #[must_use]
    pub fn mean_tangential(&self) -> f64 {
        // Integral of B over the `y` before the loss of contact (or after the contact).
        let edge = |y: f64| {
            let h = (0.5 * y).sin();
            self.s * s_fn(y) + 2.0 * self.sin_theta * h * h
        };
        match (self.regime, self.stick) {
            (Regime::JumpingStickFirst, Some(st)) => (0.5 * self.vbar * st.length * st.length + edge(st.tail)) / TAU,
            (Regime::JumpingSlipFirst, Some(st)) => {
                let before = edge(nonneg(st.start - self.theta));
                let after = edge(nonneg(st.tail - st.start - self.theta));
                let stick = st.length * (st.start_force + 0.5 * self.vbar * st.length);
                (before + stick + after) / TAU
            }
            (Regime::PermanentStickSlip, Some(st)) => st.start_force + self.tangent_excess().unwrap_or(f64::NAN),
            // No stick: no deficit, the spring slides whenever it touches.
            _ => self.mean_normal,
        }
    }

    /// For a spring in permanent contact (`s >= 1`, a tangent start): the mean
    /// tangential force above the stick's start force, `<F> - F(tau_s)`, units
    /// `mu0 kz du`, with full relative accuracy where `<F>` is small (`vbar -> 0`
    /// with `s -> 1`, where `<B> - D` cancels).
    ///
    /// The stick from `tau_s = arcsin vbar` contributes `F(tau_s) L + vbar L^2/2`;
    /// the slip over the tail `e = 2 pi - L`, `int (s - cos tau)`, is
    /// `s e - vbar + sin(tau_s - e) = F(tau_s) e + c S(e) - 2 vbar sin^2(e/2)`
    /// (`c = sqrt(1 - vbar^2)`). So `2 pi (<F> - F(tau_s)) = vbar L^2/2 + c S(e) -
    /// 2 vbar sin^2(e/2)`: positive terms but the last, which is below `e^2/L^2`
    /// of the first.
    pub(crate) fn tangent_excess(&self) -> Option<f64> {
        let st = self.stick?;
        if self.regime != Regime::PermanentStickSlip {
            return None;
        }
        let (v, l, e) = (self.vbar, st.length, st.tail);
        let c = (1.0 - v * v).sqrt();
        let h = (0.5 * e).sin();
        Some((0.5 * v * l * l + c * s_fn(e) - 2.0 * v * h * h) / TAU)
    }

    /// Phase at which the stick ends, wrapped to `[0, 2 pi)`, from the tail
    /// (full relative accuracy near 0, absolute `ulp(2 pi)` near `2 pi`).
    #[must_use]
    pub fn slip_phase(&self) -> Option<f64> {
        let st = self.stick?;
        let t = if self.regime == Regime::JumpingStickFirst {
            TAU - self.theta - st.tail
        } else if st.tail > st.start {
            // 2 pi + tau_s - e.
            TAU - (st.tail - st.start)
        } else {
            // Wrapped past 2 pi (at vbar = 0 the stick lasts the whole period).
            st.start - st.tail
        };
        Some(t)
    }

    /// The events of one period, sorted by phase in `[0, 2 pi)`.
    ///
    /// Solve with [`Spring::with_events`] for event times to full precision.
    /// Forces are those of the stick line (equal to the bound at both ends):
    /// `F(tau_s)` and `F(tau_s) + vbar L`, sums of non-negative terms.
    #[must_use]
    pub fn events(&self) -> Vec<Event> {
        let mut ev = Vec::with_capacity(4);
        if matches!(self.regime, Regime::NeverInContact) {
            return ev;
        }
        if self.s < 1.0 {
            // Contact from theta = arccos s to 2 pi - theta (eq. 18).
            let theta = self.theta;
            ev.push(Event { kind: EventKind::Contact, tau: theta, normal: 0.0, tangential: 0.0 });
            ev.push(Event { kind: EventKind::LossOfContact, tau: TAU - theta, normal: 0.0, tangential: 0.0 });
        }
        if let (Some(st), Some(t1)) = (self.stick, self.slip_phase()) {
            let f0 = st.start_force;
            let f1 = f0 + self.vbar * st.length;
            ev.push(Event { kind: EventKind::Stick, tau: st.start, normal: f0, tangential: f0 });
            ev.push(Event { kind: EventKind::Slip, tau: t1, normal: f1, tangential: f1 });
        }
        // Stable sort: at equal phases the contact precedes the stick it starts.
        ev.sort_by(|a, b| a.tau.total_cmp(&b.tau));
        ev
    }
}

#[cfg(test)]
mod tests;
