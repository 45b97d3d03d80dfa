//! One spring under oscillation in the sliding direction, alone or with the
//! normal oscillation (README: oscillation in the sliding direction): the exact periodic
//! steady state of the stop operator, phase by phase.
//!
//! # Model
//! Time is the phase `tau = omega t`; lengths are in units of the pre-slip
//! length `l = mu0 u0 kz/kx`, forces in units of `mu0 kz u0`. The body moves as
//! `X(tau) = vhat tau + T sin(tau + phase)` ([`Drive`]); the spring's Coulomb
//! bound is `B(tau) = (c - amp cos tau)_+` ([`Bound`]: `c = 1` for the flat
//! punch, `c = 1 - G(z)` for the MDR spring at `z`). The force `f` sticks
//! (`f' = X'`) while `|f| < B`, slips forward (`f = B`) while the body would
//! carry it past the bound (`X' >= B'`), slips backward (`f = -B`) while
//! `X' <= -B'`, and is 0 out of contact.
//!
//! # The steady state from a known state
//! - Jumping springs (`|c| < amp`, and `c = amp`): contact starts at
//!   `tau_c = acos(c/amp)` with `f = 0` (the spring relaxed out of contact), so
//!   one pass over the contact window is the steady state.
//! - Springs always in contact (`c > amp`, or `amp = 0` with `c > 0`): over a
//!   period `f` returns to its value, so `int f' = 0`; sticking alone would give
//!   `int X' = 2 pi vhat > 0`, and a backward slip only adds (there `-B' >= X'`):
//!   every period has a forward slip (for `vhat > 0`; `vhat = 0` is taken as the
//!   limit `vhat -> 0+`, as the seed's `vbar = 0`). A forward slip ends only
//!   where `h = X' - B'` falls through 0, and `h = vhat + R cos(tau + psi)`
//!   falls through 0 once a period, at `tau_e` in closed form. So `f(tau_e) =
//!   B(tau_e)`, and one period from there is the steady state. Where `vhat >= R`
//!   the spring slips forward all the time.
//!
//! # Events
//! In a stick from `(tau0, f0)`, `f = f0 + X(tau) - X(tau0)` meets `+B` where
//! `g+ = f - B` crosses 0 upward and `-B` where `g- = f + B` crosses 0
//! downward. `g+' = h` and `g-' = h2 = X' + B' = vhat + R2 cos(tau + psi2)`
//! have their zeros in closed form, so `g+` and `g-` are monotone between
//! them: each event is the unique sign change on one such piece, found by a
//! bracketed root search (`numerics::root::bracketed`). Slips end at
//! the closed-form zeros of `h` (forward) and `h2` (backward). Every integral
//! of a phase is closed form, written without cancellation for short phases.
//!
//! # A force on its bound
//! `g+ = int h - (B - f)(tau0)` and `g- = int h2 + (f + B)(tau0)` are evaluated
//! from the closed forms of `h` and `h2`, not as `X - B`: where the drive moves
//! with the bound (`vhat ~ 0`, `T ~ amp`, phase `~ pi/2` or `3 pi/2`: `h` or `h2`
//! nearly vanishes) they are as small as `h`, not rounding of `O(T)` terms. A
//! piece of `g` counts only if `g` moves toward 0 on it, which is read from the
//! zero of `h` (or `h2`) that ends it: a force that has just left its bound does
//! not return at once. A phase of zero length is not an event (it is not
//! recorded; only the state changes), and no two follow each other, so a
//! period has a handful of phases.

use crate::numerics::root::bracketed;
use crate::numerics::special::x_minus_sin;
use std::f64::consts::{PI, TAU};

/// The body's tangential motion `X(tau) = vhat tau + T sin(tau + phase)`, in
/// pre-slip lengths.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Drive {
    /// Mean sliding velocity `vhat = v0 / (omega l)` (eq. 15).
    pub vhat: f64,
    /// Tangential amplitude `T = dx / l`.
    pub t: f64,
    /// Phase of the tangential oscillation against the normal one (radians).
    pub phase: f64,
}

impl Drive {
    /// `X(b) - X(a)`, without cancellation for `b` near `a`.
    pub(crate) fn dx(&self, a: f64, b: f64) -> f64 {
        let l = b - a;
        self.vhat * l + 2.0 * self.t * (0.5 * (a + b) + self.phase).cos() * (0.5 * l).sin()
    }

    /// `int_a^b (X(tau) - X(a)) dtau`: `vhat L^2/2 + T (2 cos p sin^2(L/2) -
    /// sin p (L - sin L))`, `p = a + phase`, `L = b - a`.
    fn stick_integral(&self, a: f64, b: f64) -> f64 {
        let (l, p) = (b - a, a + self.phase);
        let h = (0.5 * l).sin();
        self.vhat * 0.5 * l * l + self.t * (2.0 * p.cos() * h * h - p.sin() * x_minus_sin(l))
    }
}

/// The Coulomb bound `B(tau) = (c - amp cos tau)_+`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bound {
    /// Its mean level: 1 for the flat punch, `1 - G(z)` for an MDR spring.
    pub c: f64,
    /// The normal amplitude `du/u0`.
    pub amp: f64,
}

impl Bound {
    /// `B(tau)` where in contact (no clipping).
    fn at(&self, tau: f64) -> f64 {
        self.c - self.amp * tau.cos()
    }

    /// `int_a^b (B(tau) - B(a)) dtau = amp (cos a (L - sin L) + 2 sin a sin^2(L/2))`.
    fn rise_integral(&self, a: f64, b: f64) -> f64 {
        let l = b - a;
        let h = (0.5 * l).sin();
        self.amp * (a.cos() * x_minus_sin(l) + 2.0 * a.sin() * h * h)
    }
}

/// What a spring does in a phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum StopKind {
    /// `|f| < B`: the force follows the body.
    Stick,
    /// `f = B`: slipping in the sliding direction.
    Forward,
    /// `f = -B`: slipping against it.
    Backward,
}

/// One phase of the period.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct StopPhase {
    /// What the spring does.
    pub kind: StopKind,
    /// Start (phase; the window starts at the contact or at `tau_e`, so it may
    /// exceed `2 pi`).
    pub start: f64,
    /// End.
    pub end: f64,
    /// The force at the start.
    pub force: f64,
}

/// How a spring touches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Touch {
    /// Never.
    Never,
    /// All the time.
    Permanent,
    /// Part of each period.
    Jumping,
}

/// A spring's steady state.
#[derive(Debug, Clone, PartialEq)]
pub struct StopSpring {
    /// How it touches.
    pub contact: Touch,
    /// The phases of one period in order (out of contact: none).
    pub phases: Vec<StopPhase>,
    /// Where the contact window starts and ends (a whole period where always in contact).
    pub window: (f64, f64),
    /// Period mean of the force `<f>`.
    pub mean_force: f64,
    /// Period mean of the bound `<B>`.
    pub mean_bound: f64,
    /// Period mean of `B - f` (>= 0), computed on its own (no cancellation
    /// where `f` is close to `B`).
    pub mean_deficit: f64,
}

impl StopSpring {
    /// A spring that never touches.
    fn never() -> StopSpring {
        StopSpring {
            contact: Touch::Never,
            phases: vec![],
            window: (0.0, 0.0),
            mean_force: 0.0,
            mean_bound: 0.0,
            mean_deficit: 0.0,
        }
    }
}

/// Relative width of every event's bracket at the end of its search.
const RTOL: f64 = 4.0 * f64::EPSILON;

/// `tau0 + 2 pi k` for the smallest `k` with the result `>= from`.
fn next_at(tau0: f64, from: f64) -> f64 {
    tau0 + TAU * ((from - tau0) / TAU).ceil()
}

/// `vhat + r cos(tau + psi)`: where it falls through 0 (`down`) and where it
/// rises through 0 (`up`), each the first at or after `from`; `None` if it
/// never changes sign.
fn crossings(vhat: f64, r: f64, psi: f64, from: f64) -> Option<(f64, f64)> {
    if vhat >= r {
        return None;
    }
    let a = (-vhat / r).acos();
    Some((next_at(a - psi, from), next_at(-a - psi, from)))
}

/// `(R, psi)` of `T cos(tau + phase) + k sin tau = R cos(tau + psi)`.
fn amplitude(t: f64, phase: f64, k: f64) -> (f64, f64) {
    let (sp, cp) = phase.sin_cos();
    let (x, y) = (t * cp, t * sp - k);
    (x.hypot(y), y.atan2(x))
}

impl Drive {
    /// Whether every spring, whatever its level `c`, slips forward whenever it
    /// touches: `h = X' - B' = vhat + T cos(tau + phase) - amp sin tau` never
    /// falls below 0, i.e. `vhat >= R`, `R` the amplitude of its oscillating part.
    /// Then `f = B` all the time and `mu_macro/mu0 = 1` for every contact.
    #[must_use]
    pub fn always_forward(self, amp: f64) -> bool {
        self.vhat >= amplitude(self.t, self.phase, -amp).0
    }
}

/// The steady state of the spring with bound `b` under drive `d` (inputs
/// finite; `b.amp, d.vhat, d.t >= 0`).
#[must_use]
pub fn solve(b: Bound, d: Drive) -> StopSpring {
    if b.c <= -b.amp || (b.amp == 0.0 && b.c <= 0.0) {
        return StopSpring::never();
    }
    // h = X' - B' and h2 = X' + B' (B' = amp sin tau in contact).
    let (r, psi) = amplitude(d.t, d.phase, -b.amp);
    let (r2, psi2) = amplitude(d.t, d.phase, b.amp);
    let permanent = b.amp == 0.0 || b.c > b.amp;
    let (lo, hi, start, mean_bound) = if permanent {
        match crossings(d.vhat, r, psi, 0.0) {
            // Always slipping forward.
            None => {
                return StopSpring {
                    contact: Touch::Permanent,
                    phases: vec![StopPhase { kind: StopKind::Forward, start: 0.0, end: TAU, force: b.at(0.0) }],
                    window: (0.0, TAU),
                    mean_force: b.c,
                    mean_bound: b.c,
                    mean_deficit: 0.0,
                }
            }
            Some((down, _)) => (down, down + TAU, (StopKind::Stick, b.at(down)), b.c),
        }
    } else {
        // Contact from tau_c = acos(c/amp) to 2 pi - tau_c, starting relaxed.
        let tc = (b.c / b.amp).clamp(-1.0, 1.0).acos();
        // <B> = (1/pi) (c (pi - tc) + amp sin tc) = (amp/pi) (sin x - x cos x), x = pi - tc.
        let x = PI - tc;
        let sin_x_minus_x_cos_x = 2.0 * x * (0.5 * x).sin().powi(2) - x_minus_sin(x);
        let mean = b.amp / PI * sin_x_minus_x_cos_x;
        // f = B = 0 there: it slips forward if X' > B' (h > 0), backward if
        // X' < -B' (h2 < 0), from the same closed forms that end the slips.
        let kind = if wave(d.vhat, r, psi, tc) > 0.0 {
            StopKind::Forward
        } else if wave(d.vhat, r2, psi2, tc) < 0.0 {
            StopKind::Backward
        } else {
            StopKind::Stick
        };
        (tc, TAU - tc, (kind, 0.0), mean.max(0.0))
    };
    let mut phases = vec![];
    // The state: what the spring does from `tau`, its force, and (in a stick)
    // its margins to the bounds, exactly 0 on the side it comes from.
    let (mut tau, (mut kind, mut force)) = (lo, start);
    let mut margins = match (permanent, kind) {
        (true, _) => (0.0, 2.0 * force),
        _ => (0.0, 0.0),
    };
    let (mut sum_f, mut sum_d) = (0.0, 0.0);
    // At most a handful of phases a period (every phase but a zero-length one
    // ends at a zero of h or h2 or between two of them, and a zero-length phase
    // is followed by one that is not); the bound keeps a bug from looping.
    for _ in 0..64 {
        if tau >= hi {
            break;
        }
        let (end, next) = match kind {
            StopKind::Forward => (crossings(d.vhat, r, psi, tau).map_or(hi, |x| x.0.min(hi)), StopKind::Stick),
            StopKind::Backward => (crossings(d.vhat, r2, psi2, tau).map_or(hi, |x| x.1.min(hi)), StopKind::Stick),
            StopKind::Stick => stick_end(d.vhat, tau, margins, hi, (r, psi), (r2, psi2)),
        };
        // A phase of zero length is not an event: only the state changes.
        if end > tau {
            phases.push(StopPhase { kind, start: tau, end, force });
            let (f, dd) = phase_integrals(b, d, kind, (tau, end), force, margins.0);
            sum_f += f;
            sum_d += dd;
        }
        tau = end;
        if end >= hi {
            break;
        }
        let bound = b.at(end);
        (force, margins) = match (kind, next) {
            (StopKind::Forward, _) | (_, StopKind::Forward) => (bound, (0.0, 2.0 * bound)),
            _ => (-bound, (2.0 * bound, 0.0)),
        };
        kind = next;
    }
    if tau < hi {
        // Not reached by the argument above; a period left unfinished is not an answer.
        (sum_f, sum_d) = (f64::NAN, f64::NAN);
    }
    StopSpring {
        contact: if permanent { Touch::Permanent } else { Touch::Jumping },
        phases,
        window: (lo, hi),
        mean_force: sum_f / TAU,
        mean_bound,
        mean_deficit: crate::numerics::special::nonneg(sum_d / TAU),
    }
}

/// The end of a stick that starts at `tau0` with the margins `(B - f, f + B)`
/// (before `hi`), and what
/// follows: a forward slip where `f - B` rises through 0, a backward slip
/// where `f + B` falls through 0, whichever comes first; `(hi, Stick)` if
/// neither does before `hi`.
fn stick_end(
    vhat: f64,
    tau0: f64,
    (up, down): (f64, f64),
    hi: f64,
    (r, psi): (f64, f64),
    (r2, psi2): (f64, f64),
) -> (f64, StopKind) {
    // g+ = f - B = int h - up and g- = f + B = int h2 + down, each from the
    // closed form of its own derivative: where X' and B' nearly cancel (the
    // degenerate drive) they are as small as h, not rounding of X - B.
    let g_plus = |tau: f64| wave_integral(vhat, r, psi, tau0, tau) - up;
    let g_minus = |tau: f64| wave_integral(vhat, r2, psi2, tau0, tau) + down;
    let forward = first_crossing(&g_plus, (tau0, hi), (vhat, r, psi), true);
    let backward = first_crossing(&g_minus, (tau0, hi), (vhat, r2, psi2), false);
    match (forward, backward) {
        (Some(x), Some(y)) if y < x => (y, StopKind::Backward),
        (Some(x), _) => (x, StopKind::Forward),
        (None, Some(y)) => (y, StopKind::Backward),
        (None, None) => (hi, StopKind::Stick),
    }
}

/// `vhat + r cos(tau + psi)` (`h` or `h2`).
fn wave(vhat: f64, r: f64, psi: f64, tau: f64) -> f64 {
    vhat + r * (tau + psi).cos()
}

/// `int_a^b (vhat + r cos(tau + psi)) dtau = vhat L + 2 r cos((a+b)/2 + psi) sin(L/2)`.
fn wave_integral(vhat: f64, r: f64, psi: f64, a: f64, b: f64) -> f64 {
    let l = b - a;
    vhat * l + 2.0 * r * (0.5 * (a + b) + psi).cos() * (0.5 * l).sin()
}

/// The first point in `(lo, hi]` where `g` rises through 0 (`rising`) or falls
/// through 0, `g' = vhat + r cos(tau + psi)`: `g` is monotone between the
/// zeros of `g'`, so a piece holds one sign change at most, and only a piece on
/// which `g` moves the wanted way can hold it. Which way `g` moves on a piece
/// is read from the zero that ends it (`g'` is positive before a fall through 0
/// and negative before a rise), not from rounded values of `g'`: a force that
/// has just left its bound (at a zero of `g'`) does not return to it at once,
/// and no two phases of zero length follow each other.
fn first_crossing(
    g: &dyn Fn(f64) -> f64,
    (lo, hi): (f64, f64),
    (vhat, r, psi): (f64, f64, f64),
    rising: bool,
) -> Option<f64> {
    // The zeros, each the first at or after `lo`, labelled `true` where `g'`
    // falls through 0 (a tie puts the fall first: `g'` only touches 0 there).
    // `hi - lo <= 2 pi`: their next turns lie at or beyond `hi`.
    let mut zeros: Vec<(f64, bool)> = match crossings(vhat, r, psi, lo) {
        Some((down, up)) => vec![(down, true), (up, false)],
        None => vec![],
    };
    zeros.retain(|&(x, _)| x > lo);
    zeros.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.cmp(&a.1)));
    // `g'` is positive on a piece that ends where it falls; with no zero at all
    // (`vhat >= r`) it is positive throughout.
    let mut increasing = zeros.first().is_none_or(|z| z.1);
    let past = |x: f64| if rising { x > 0.0 } else { x < 0.0 };
    let mut a = lo;
    for (e, falls) in zeros.into_iter().chain(std::iter::once((f64::INFINITY, false))) {
        let e = e.min(hi);
        if increasing == rising && past(g(e)) {
            // g is on the near side at a (or at the crossing's start to rounding).
            return Some(bracketed(g, a, e, RTOL).x);
        }
        if e >= hi {
            return None;
        }
        increasing = !falls;
        a = e;
    }
    None
}

/// `(int f, int (B - f))` over the phase `kind` on `(a, e)`, from the force
/// `f0` (on a slip `+-B`) and, in a stick, the margin `up = B - f` at its start.
fn phase_integrals(b: Bound, d: Drive, kind: StopKind, (a, e): (f64, f64), f0: f64, up: f64) -> (f64, f64) {
    let l = e - a;
    if l <= 0.0 {
        return (0.0, 0.0);
    }
    // On a slip int B = B(a) L + int (B - B(a)), B(a) = |f0|.
    let int_b = || f0.abs() * l + b.rise_integral(a, e);
    match kind {
        StopKind::Forward => (int_b(), 0.0),
        StopKind::Backward => {
            let i = int_b();
            (-i, 2.0 * i)
        }
        // B - f = (B(a) - f0) + (B - B(a)) - (X - X(a)).
        StopKind::Stick => {
            let x = d.stick_integral(a, e);
            (f0 * l + x, up * l + b.rise_integral(a, e) - x)
        }
    }
}

impl StopSpring {
    /// The force at phase `tau` (any real; reduced to the period) in the steady
    /// state (bound `b`, drive `d`), within its bound `[-B, B]`.
    #[must_use]
    pub fn force_at(&self, b: Bound, d: Drive, tau: f64) -> f64 {
        if self.contact == Touch::Never {
            return 0.0;
        }
        let (lo, _) = self.window;
        let t = lo + (tau - lo).rem_euclid(TAU);
        for p in &self.phases {
            if t >= p.start && t <= p.end {
                return match p.kind {
                    StopKind::Forward => b.at(t).max(0.0),
                    StopKind::Backward => -b.at(t).max(0.0),
                    // |f| <= B: at the stick's end the two differ by rounding only.
                    StopKind::Stick => {
                        let bound = b.at(t).max(0.0);
                        (p.force + d.dx(p.start, t)).clamp(-bound, bound)
                    }
                };
            }
        }
        0.0
    }
}
