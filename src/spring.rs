//! One spring: regimes, event times and closed-form phase integrals.
//!
//! # Model (MODEL.md, seed section 2)
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
//! with `S(y) = y - sin y` ([`crate::special::x_minus_sin`]). The stick ends at the
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
//! accuracy, and `dD/dL = H(L) = 0`: an error `e` in `L` changes `D` by `O(e^2)`,
//! so the means need `L` only to about 1e-8 relative ([`ROOT_RTOL_MEANS`]).
//!
//! Mean tangential force `<F> = <B> - D`, and `mu_macro/mu0 = <F>/<B>`.

use crate::root;
use crate::special::{half_sq_minus_versin as c_fn, x_minus_sin as s_fn};
use serde::Serialize;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Relative root tolerance when only mean forces are wanted. Newton stops once
/// a step is below this (relative) and returns the next iterate, whose error is
/// then about its square (1e-12); the deficit is stationary in the stick length,
/// so its relative error is of the order of that squared again.
pub const ROOT_RTOL_MEANS: f64 = 1e-6;
/// Relative root tolerance when event times are reported.
pub const ROOT_RTOL_EVENTS: f64 = 4.0 * f64::EPSILON;

/// What one spring does during a period.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
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
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EventKind {
    /// Contact is (re)gained, with zero force.
    Contact,
    /// Contact is lost; the spring relaxes.
    LossOfContact,
    /// Slip (or contact) turns into stick.
    Stick,
    /// Stick turns into slip.
    Slip,
}

/// A transition at phase `tau` in `[0, 2 pi)`, with the forces there.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
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
    /// Duration `L` of the stick phase (in phase units).
    pub length: f64,
    /// Tangential (= normal) force at the start of the stick.
    pub start_force: f64,
}

impl Stick {
    /// Phase at which the stick starts (not wrapped).
    pub fn start(&self) -> f64 {
        FRAC_PI_2 - self.beta
    }
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
    /// The stick phase, if the spring sticks.
    pub stick: Option<Stick>,
    /// Function evaluations spent by the root finder.
    pub root_evaluations: u32,
}

/// Period mean of the Coulomb bound, `<B>(s) = <(s - cos tau)_+>`.
///
/// For `|s| < 1` the contact lasts `2 phi` per period with `phi = arccos(-s)`,
/// and `<B> = (s phi + sin phi)/pi = (sin phi - phi cos phi)/pi`, written as
/// `(2 phi sin^2(phi/2) - S(phi))/pi` to keep full relative accuracy where it
/// vanishes like `(1 + s)^(3/2)` at the edge of contact.
pub fn mean_normal(s: f64) -> f64 {
    if s >= 1.0 {
        s
    } else if s <= -1.0 {
        0.0
    } else {
        mean_normal_at_angle((-s).acos())
    }
}

/// `<B>` of a jumping spring from its contact half-angle `phi = arccos(-s)` in
/// `[0, pi]` (the contact lasts `2 phi` per period): `(2 phi sin^2(phi/2) - S(phi))/pi`.
pub fn mean_normal_at_angle(phi: f64) -> f64 {
    let h = (0.5 * phi).sin();
    (2.0 * phi * h * h - s_fn(phi)) / PI
}

/// `<B>` of the spring with `s = sin beta`, from `beta` in `[-pi/2, pi/2]` and its
/// sine and cosine (no further transcendental calls on the hot path): with the
/// contact half-angle `phi = pi/2 + beta`, `<B> = (s phi + cos beta)/pi`, and near
/// the edge of contact (`phi < 2`) the cancellation-free
/// `(phi (1 + s) - S(phi))/pi` with `1 + s = cos^2 beta / (1 - s)`.
pub fn mean_normal_sin_cos(beta: f64, sin_beta: f64, cos_beta: f64) -> f64 {
    let phi = FRAC_PI_2 + beta;
    if phi < 2.0 {
        let one_plus_s = if sin_beta < 0.0 { cos_beta * cos_beta / (1.0 - sin_beta) } else { 1.0 + sin_beta };
        (phi * one_plus_s - s_fn(phi)) / PI
    } else {
        (sin_beta * phi + cos_beta) / PI
    }
}

/// Velocity-dependent constants shared by all springs of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Velocity {
    /// `vbar` (eq. 3), `< 1`.
    pub vbar: f64,
    /// `w = 1 - vbar`.
    pub w: f64,
    /// `alpha = arccos vbar`; springs with `|arcsin s| < alpha` stick from contact.
    pub alpha: f64,
    /// Newton start for the stick length of a tangent start.
    tangent_guess: f64,
}

impl Velocity {
    /// Constants for `0 <= vbar < 1`.
    pub fn new(vbar: f64) -> Self {
        let (w, alpha) = velocity_angles(vbar);
        Velocity { vbar, w, alpha, tangent_guess: tangent_length_guess(alpha, vbar) }
    }

    /// Deficit of the stick-first spring with `s = sin beta`, `|beta| < alpha`
    /// (means only, no events).
    pub fn stick_first_deficit(&self, beta: f64) -> f64 {
        stick_phase(beta, self, PI + 2.0 * beta, ROOT_RTOL_MEANS).1
    }
}

/// `2 pi` times the deficit of a stick of length `len` starting at `beta`.
fn deficit_2pi(beta: f64, w: f64, len: f64) -> f64 {
    c_fn(beta) - c_fn(beta - len) - s_fn(beta) * len + 0.5 * w * len * len
}

/// Critical velocity parameters: `(w, alpha) = (1 - vbar, arccos vbar)`, with
/// `alpha = 2 arcsin(sqrt(w/2))` accurate as `vbar -> 1`.
fn velocity_angles(vbar: f64) -> (f64, f64) {
    let w = 1.0 - vbar;
    (w, 2.0 * (0.5 * w).sqrt().asin())
}

/// Newton start for the stick length of a tangent start, `L(alpha)`: a fit of
/// `L/alpha = 3 + 0.1 alpha^2 + ...` (exact slope `3` as `vbar -> 1`), and
/// `L = 2 pi - 2 sqrt(pi vbar)(1 + 0.45 vbar)` as `vbar -> 0` (within 1 %).
fn tangent_length_guess(alpha: f64, vbar: f64) -> f64 {
    if vbar < 0.2 {
        TAU - 2.0 * (PI * vbar).sqrt() * (1.0 + 0.45 * vbar)
    } else {
        let a2 = alpha * alpha;
        alpha * (3.0 + a2 * (0.1 + a2 * (0.01 + 0.018 * a2)))
    }
}

/// Solve the stick phase starting at `beta`: the root of the gap
/// `H(x) = S(beta - x) - S(beta) + w x`, and the deficit.
///
/// The root lies in `[alpha + beta, x_max]`, where `H` falls from its maximum.
/// Newton starts from [`tangent_length_guess`], scaled for a start at contact
/// by the ratio `L / (alpha + beta)`, which runs from 2 (`beta -> -alpha`, where
/// `H ~ eps x - |s| x^2/2`) to the tangent value.
fn stick_phase(beta: f64, vel: &Velocity, x_max: f64, rtol: f64) -> (f64, f64, u32) {
    let (alpha, w, vbar) = (vel.alpha, vel.w, vel.vbar);
    let lo = alpha + beta;
    let lt = vel.tangent_guess;
    let guess = if beta == alpha {
        lt
    } else {
        let ratio_t = lt / (2.0 * alpha);
        lo * (2.0 + (ratio_t - 2.0) * lo / (2.0 * alpha))
    };
    let s_beta = s_fn(beta);
    // f and f' at the same x share one sin_cos (the derivative is asked right after f).
    let cached_cos = std::cell::Cell::new((f64::NAN, 0.0));
    let f = |x: f64| {
        let y = beta - x;
        if y.abs() < 2.0 {
            cached_cos.set((x, y.cos()));
            s_fn(y) - s_beta + w * x
        } else {
            let (sn, cs) = y.sin_cos();
            cached_cos.set((x, cs));
            (y - sn) - s_beta + w * x
        }
    };
    let df = |x: f64| {
        let (cx, cs) = cached_cos.get();
        (if cx == x { cs } else { (beta - x).cos() }) - vbar
    };
    let r = root::newton(f, df, lo, x_max, guess, rtol);
    // The deficit is a mean of a non-negative gap; rounding must not flip it.
    let d = (deficit_2pi(beta, w, r.x) / TAU).max(0.0);
    (r.x, d, r.evaluations)
}

impl Spring {
    /// Steady state of a spring with `s = u0/du` at velocity `vbar`, computing
    /// stick times to [`ROOT_RTOL_MEANS`] (enough for means to full accuracy).
    ///
    /// `vbar = 0` is the limit `vbar -> 0+`: exactly at zero velocity the
    /// tangential force is not determined by the oscillation (it depends on the
    /// initial state), and the limit is the value every time stepper converges to.
    /// Inputs must be finite with `vbar >= 0` (checked by the public APIs above this).
    pub fn new(s: f64, vbar: f64) -> Self {
        Self::solve(s, vbar, ROOT_RTOL_MEANS)
    }

    /// As [`Spring::new`], with event times to full double precision.
    pub fn with_events(s: f64, vbar: f64) -> Self {
        Self::solve(s, vbar, ROOT_RTOL_EVENTS)
    }

    fn solve(s: f64, vbar: f64, rtol: f64) -> Self {
        let mean_normal = mean_normal(s);
        let mut out = Spring {
            s,
            vbar,
            regime: Regime::NeverInContact,
            mean_normal,
            deficit: 0.0,
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
        let alpha = vel.alpha;
        let c = alpha.sin();
        let (beta, x_max, regime) = if s >= 1.0 {
            (alpha, TAU, Regime::PermanentStickSlip)
        } else if s >= c {
            (alpha, TAU, Regime::JumpingSlipFirst)
        } else if s > -c {
            let beta = s.asin();
            (beta, PI + 2.0 * beta, Regime::JumpingStickFirst)
        } else {
            out.regime = Regime::JumpingSlip;
            return out;
        };
        let (length, deficit, evals) = stick_phase(beta, &vel, x_max, rtol);
        let start_force = if regime == Regime::JumpingStickFirst { 0.0 } else { s - c };
        out.regime = regime;
        out.deficit = deficit;
        out.stick = Some(Stick { beta, length, start_force });
        out.root_evaluations = evals;
        out
    }

    /// Period mean of the tangential force, units `mu0 kz du`.
    ///
    /// For a stick from contact it is integrated directly, with full relative
    /// accuracy where it is small (`vbar -> 0`, where `<B> - D` would cancel):
    /// the stick contributes `vbar L^2/2`, the slip from `theta + L` to the loss of
    /// contact, with `e = pi + 2 beta - L` and `B = y - S(beta) + S(beta - y)` at
    /// `y` before the loss, `e^2/2 - S(beta) e + C(beta) - C(beta - e)`.
    pub fn mean_tangential(&self) -> f64 {
        match (self.regime, self.stick) {
            (Regime::JumpingStickFirst, Some(st)) => {
                let b = st.beta;
                let e = (PI + 2.0 * b - st.length).max(0.0);
                let slip = 0.5 * e * e - s_fn(b) * e + (c_fn(b) - c_fn(b - e));
                ((0.5 * self.vbar * st.length * st.length + slip.max(0.0)) / TAU).min(self.mean_normal)
            }
            _ => self.mean_normal - self.deficit,
        }
    }

    /// The events of one period, sorted by phase in `[0, 2 pi)`.
    ///
    /// Solve with [`Spring::with_events`] for event times to full precision.
    pub fn events(&self) -> Vec<Event> {
        let bound = |tau: f64| (self.s - tau.cos()).max(0.0);
        let wrap = |tau: f64| {
            let t = tau.rem_euclid(TAU);
            if t >= TAU {
                0.0
            } else {
                t
            }
        };
        let mut ev = Vec::with_capacity(4);
        if matches!(self.regime, Regime::NeverInContact) {
            return ev;
        }
        if self.s < 1.0 {
            // Contact from theta = arccos s to 2 pi - theta (eq. 18).
            let theta = self.s.acos();
            ev.push(Event { kind: EventKind::Contact, tau: theta, normal: 0.0, tangential: 0.0 });
            ev.push(Event { kind: EventKind::LossOfContact, tau: wrap(TAU - theta), normal: 0.0, tangential: 0.0 });
        }
        if let Some(st) = self.stick {
            // A stick from contact starts exactly at the contact phase theta.
            let t0 = if self.regime == Regime::JumpingStickFirst { self.s.acos() } else { st.start() };
            let t1 = t0 + st.length;
            let f1 = st.start_force + self.vbar * st.length;
            let n0 = if self.regime == Regime::JumpingStickFirst { 0.0 } else { bound(t0) };
            ev.push(Event { kind: EventKind::Stick, tau: wrap(t0), normal: n0, tangential: st.start_force });
            ev.push(Event { kind: EventKind::Slip, tau: wrap(t1), normal: bound(t1), tangential: f1 });
        }
        // Stable sort: at equal phases the contact precedes the stick it starts.
        ev.sort_by(|a, b| a.tau.total_cmp(&b.tau));
        ev
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mean_normal_matches_the_seed_eq_20_form() {
        // Eq. 20 / (kz u0) with s = u0/du: <B>/s = 1 - th/pi + sin(th)/(pi s).
        for &s in &[-0.9, -0.3, 0.0, 0.2, 0.7, 0.999] {
            let th = f64::acos(s);
            let eq20 = s * (1.0 - th / PI) + th.sin() / PI;
            assert!((mean_normal(s) - eq20).abs() < 1e-15, "s = {s}");
        }
        assert_eq!(mean_normal(2.5), 2.5);
        assert_eq!(mean_normal(-1.0), 0.0);
    }

    #[test]
    fn mean_normal_from_sine_and_cosine_matches_the_arccos_form() {
        for k in 0..=1000 {
            let beta = -FRAC_PI_2 + PI * k as f64 / 1000.0;
            let (sb, cb) = beta.sin_cos();
            let (a, b) = (mean_normal_sin_cos(beta, sb, cb), mean_normal_at_angle(FRAC_PI_2 + beta));
            // Near the edge of contact phi = pi/2 + beta carries a rounding of
            // 1e-16/phi relative, and <B> ~ phi^3: the two forms agree to that.
            let phi = FRAC_PI_2 + beta;
            let tol = 2e-15 + 4e-16 / phi.max(1e-300);
            assert!((a - b).abs() <= tol * b, "beta {beta}: {a} vs {b}");
        }
    }

    #[test]
    fn corrected_eq_8_holds_at_the_stick_end_and_the_printed_sign_fails() {
        let v: f64 = 0.3;
        let sp = Spring::with_events(2.0, v);
        let st = sp.stick.unwrap();
        let t1 = v.asin();
        let t2 = t1 + st.length;
        let corrected = (1.0 - v * v).sqrt() - v * (t2 - t1);
        assert!((t2.cos() - corrected).abs() < 1e-14);
        // The printed '+' form has no root after tau1: its residual stays away from zero.
        let printed = |t: f64| t.cos() - ((1.0 - v * v).sqrt() + v * (t - t1));
        assert!((1..1000).all(|k| printed(t1 + k as f64 * TAU / 1000.0) < -1e-6));
    }
}
