//! One spring in the plane over one period (`MODEL-transverse.md`): stick in
//! closed form, slip by the Taylor series of a linear equation, every event on
//! those series.
//!
//! **Slip.** With `f = B e`, `e = (cos th, sin th)`, the law `f' = X' - lambda e`
//! splits into `lambda = X'.e - B'` (along `e`) and `B th' = X' x e`-ish, that is
//! `th' = (cos th X'_y - sin th X'_x)/B` (across it). With `p = tan(th/2) =
//! y1/y2` this Riccati equation is the linear one
//!
//! `y' = M y`, `M = (1/2B) [[-X'_x, X'_y], [X'_y, X'_x]]`,
//!
//! (substitute `cos th = (y2^2 - y1^2)/|y|^2`, `sin th = 2 y1 y2/|y|^2`): `M`
//! is symmetric and traceless, so `det` of the flow is 1 and `d th_end/d
//! th_start = |y_start|^2/|y_end|^2`. The slip ends where `lambda |y|^2 =
//! X'_x (y2^2 - y1^2) + 2 X'_y y1 y2 - B' |y|^2` falls through 0.
//!
//! **Contact.** Where contact is regained (`B = 0`, `B' = beta > 0`) the spring
//! reloads from `f = 0`: it sticks if `|X'| <= beta`; otherwise it slips,
//! starting along `X'` (the one bounded solution of `t B~(t) th' = ...` at the
//! regular singular point; the others grow like `t^-|X'|/beta`). Where contact
//! is lost, the slip aligns with `X'` while `B -> 0`; the walk stops once the
//! rest of `int B` is below [`LOSS_TAIL`] and books that rest along the
//! current direction. Both happen inside the thin layer where `B` is small,
//! and a slip there follows its slow manifold ([`layer`]).
//! The layer also holds a touch of zero (`amp = level`) and a window of
//! contact that barely closes.

use super::clock::Clock;
use super::drive::{Bound, Drive};
use super::layer::{self, Layer, ON_MANIFOLD};
use super::series::{Series, LEN, ORDER};
use super::slip::{growth, quadratics, rate_series, regular, slip_rate, slips, slips_on_contact, turning, zeros};
use crate::error::{Error, Result};
use crate::special::Kahan;
use crate::spring::EventKind;
use std::f64::consts::TAU;

/// A step's truncation target, relative to the state (`|y| = 1`, `|f| <= 1`).
const STEP_TOL: f64 = 1e-17;
/// The target of a [`Spring::coarse`] walk's steps: about `1e-9` a period,
/// far below the residuals it serves, and `(1e-17/1e-9)^(1/ORDER)`, 2.2
/// times, longer steps.
const COARSE_STEP_TOL: f64 = 1e-9;
/// The longest stick step (the series are entire; this keeps `h^k` tame).
const MAX_STICK_STEP: f64 = 1.0;
/// The rest of `int B` before a loss of contact that is booked without steps.
const LOSS_TAIL: f64 = 1e-19;
/// Steps of one period at most (a period takes tens).
const MAX_STEPS: usize = 100_000;

/// One spring: what it sees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Spring {
    pub(crate) drive: Drive,
    pub(crate) bound: Bound,
    layer: Option<Layer>,
    /// Each step's truncation target ([`STEP_TOL`] or [`COARSE_STEP_TOL`]).
    step_tol: f64,
    /// Whether its walks find their [`Walk::sensitivity`].
    sensing: bool,
    /// Each step's length relative to the one its tolerance allows (1, or
    /// less for [`Spring::strided`]).
    stride: f64,
}

/// The state between steps.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    /// `f`, inside the disc; `skip` leading zeros of `B^2 - |f|^2` at the start.
    Stick { f: [f64; 2], skip: usize },
    /// The half-angle vector (`|y| = 1`); `regain` at a contact's first instant.
    Slip { y: [f64; 2], regain: bool },
    /// Out of contact.
    Out,
}

/// One period's walk.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Walk {
    /// `int f dtau`.
    pub(crate) force: [f64; 2],
    /// `int (B - f_x) dtau`, by its own series (the reduction's share, to
    /// its relative accuracy where `f_x` is nearly `B`).
    pub(crate) deficit: f64,
    /// `int B dtau`, summed step by step as the force is: its difference from
    /// the closed form measures the rounding of both.
    pub(crate) bound: f64,
    /// The force at the end.
    pub(crate) end: [f64; 2],
    /// `d end / d start` (0 once contact is lost).
    pub(crate) jacobian: [[f64; 2]; 2],
    /// `d force / d start` ([`Walker::sense`]; from [`Spring::sensing`] only).
    pub(crate) sensitivity: Option<[[f64; 2]; 2]>,
    /// The estimated truncation error of `force` (absolute).
    pub(crate) truncation: f64,
    /// Events `(tau, kind)`.
    pub(crate) events: Vec<(f64, EventKind)>,
    /// Taylor steps taken.
    pub(crate) steps: usize,
    /// Whether the spring stuck all the way.
    pub(crate) stuck: bool,
    /// Where it stopped, to go on from ([`Start::Resume`]).
    pub(crate) resume: Resume,
}

/// Where a walk stopped: the phase and its state there, so that a walk
/// resumed from it goes on as the one walk would (a stick's leading zeros
/// at an event kept).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Resume {
    tau: f64,
    phase: Phase,
}

/// Where a walk starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Start {
    /// At `tau` with the force `f` (in contact).
    Force(f64, [f64; 2]),
    /// At the first contact at or after `tau`, from `f = 0`.
    Contact(f64),
    /// Where another walk stopped (its Jacobian not carried on).
    Resume(Resume),
}

struct Walker<'a> {
    sp: &'a Spring,
    tau: f64,
    phase: Phase,
    force: [Kahan; 2],
    /// `int (B - f_x)` along the walk.
    deficit: Kahan,
    /// `int B` along the walk, by the same series as the force.
    bound: Kahan,
    truncation: f64,
    /// `d f / d f_start` in stick; row 0 holds `d th / d f_start` in slip.
    jac: [[f64; 2]; 2],
    /// `d (int f) / d f_start` so far ([`Walker::sense`]).
    sens: Option<[[f64; 2]; 2]>,
    events: Vec<(f64, EventKind)>,
    steps: usize,
    stuck: bool,
}

impl Spring {
    pub(crate) fn new(drive: Drive, bound: Bound) -> Spring {
        Spring { drive, bound, layer: Layer::of(&drive, &bound), step_tol: STEP_TOL, sensing: false, stride: 1.0 }
    }

    /// The same spring walked to about `1e-9` a period ([`COARSE_STEP_TOL`]):
    /// for the search of an orbit far from it. Not where it has a thin layer
    /// (a bound that nearly touches zero): a slip enters it on the layer's
    /// manifold only to [`ON_MANIFOLD`], which a coarse walk's direction
    /// does not meet (it would step on through the layer).
    pub(crate) fn coarse(&self) -> Spring {
        let step_tol = if self.layer.is_some() { STEP_TOL } else { COARSE_STEP_TOL };
        Spring { step_tol, sensing: false, ..*self }
    }

    /// The same spring, its exact walks with their [`Walk::sensitivity`]
    /// (a few per cent more work a step).
    pub(crate) fn sensing(&self) -> Spring {
        Spring { sensing: self.is_exact(), ..*self }
    }

    /// The same spring walked by steps `stride` (in `(0, 1]`) times as long
    /// as its own, stick and slip: placed elsewhere, so that their rounding
    /// is another draw, and truncated less ([`super::close::start_noise`]).
    pub(crate) fn strided(&self, stride: f64) -> Spring {
        Spring { stride: stride.clamp(f64::MIN_POSITIVE, 1.0), sensing: false, ..*self }
    }

    /// Whether its walks are to full precision (not [`Spring::coarse`]).
    pub(crate) fn is_exact(&self) -> bool {
        self.step_tol == STEP_TOL
    }

    /// The walk from `start` to `end` (`end - start <= 2 pi`-ish).
    pub(crate) fn walk(&self, start: Start, end: f64) -> Result<Walk> {
        let mut w = Walker::at(self, 0.0);
        match start {
            Start::Force(tau, f) => {
                w.tau = tau;
                w.phase = w.enter(f);
            }
            Start::Contact(tau) => {
                w.tau = tau;
                w.jac = [[0.0; 2]; 2];
            }
            Start::Resume(r) => {
                w.tau = r.tau;
                // A stick stopped at its slip (the bound reached at the very
                // end, its zero there not yet a fall) goes on as a start on
                // the circle would.
                w.phase = match r.phase {
                    Phase::Stick { f, skip: 0 } => w.enter(f),
                    p => p,
                };
            }
        }
        while w.tau < end {
            w.steps += 1;
            if w.steps > MAX_STEPS {
                return Err(Error::Internal { what: format!("the plane's walk took {MAX_STEPS} steps") });
            }
            w.stuck &= matches!(w.phase, Phase::Stick { .. });
            w.phase = match w.phase {
                Phase::Stick { f, skip } => w.stick(f, skip, end)?,
                Phase::Slip { y, regain } => w.slip(y, regain, end)?,
                Phase::Out => w.regain(end)?,
            };
        }
        let end_force = match w.phase {
            Phase::Stick { f, .. } => f,
            Phase::Slip { y, .. } => scaled(direction(y), self.bound.at(w.tau)),
            Phase::Out => [0.0; 2],
        };
        Ok(Walk {
            force: [w.force[0].sum, w.force[1].sum],
            deficit: w.deficit.sum,
            bound: w.bound.sum,
            end: end_force,
            jacobian: w.end_jacobian(),
            sensitivity: w.sens,
            truncation: w.truncation,
            stuck: w.stuck && matches!(w.phase, Phase::Stick { .. }),
            events: w.events,
            steps: w.steps,
            resume: Resume { tau: w.tau, phase: w.phase },
        })
    }
}

/// `e(th)` of the half-angle vector `y` (`th = 2 atan2(y1, y2)`).
pub(crate) fn direction(y: [f64; 2]) -> [f64; 2] {
    let n = y[0] * y[0] + y[1] * y[1];
    [(y[1] - y[0]) * (y[1] + y[0]) / n, 2.0 * y[0] * y[1] / n]
}

/// The half-angle vector `(sin(th/2), cos(th/2))` of the direction `e =
/// (cos th, sin th)` (`|e| > 0`), from `2 cos^2(th/2) = 1 + cos th` and
/// `sin th = 2 sin(th/2) cos(th/2)`: along an axis exactly `(0, 1)` or `(1, 0)`.
fn half(e: [f64; 2]) -> [f64; 2] {
    let r = e[0].hypot(e[1]);
    let (c, s) = (e[0] / r, e[1] / r);
    if c >= 0.0 {
        let ch = (0.5 * (1.0 + c)).sqrt();
        [s / (2.0 * ch), ch]
    } else {
        let sh = (0.5 * (1.0 - c)).sqrt();
        [sh, s / (2.0 * sh)]
    }
}

fn scaled(e: [f64; 2], b: f64) -> [f64; 2] {
    [e[0] * b, e[1] * b]
}

/// The root of `g` in the bracket `[a, b]` from [`Series::first_fall`]
/// with the same `skip`: of `g / t^skip`, which a bracket from 0 holds
/// where `g` itself is 0 at 0.
fn refine(g: &Series, skip: usize, a: f64, b: f64) -> f64 {
    let mut d = [0.0; LEN];
    d[..LEN - skip].copy_from_slice(&g.0[skip..]);
    let d = Series(d);
    crate::root::bracketed(|t| d.eval(t), a, b, 4.0 * f64::EPSILON).x
}

impl<'a> Walker<'a> {
    /// A walker on `sp` at `tau`, out of contact, with nothing booked.
    fn at(sp: &'a Spring, tau: f64) -> Walker<'a> {
        Walker {
            sp,
            tau,
            phase: Phase::Out,
            force: [Kahan::default(), Kahan::default()],
            deficit: Kahan::default(),
            bound: Kahan::default(),
            truncation: 0.0,
            jac: [[1.0, 0.0], [0.0, 1.0]],
            sens: sp.sensing.then_some([[0.0; 2]; 2]),
            events: Vec::new(),
            steps: 0,
            stuck: true,
        }
    }
}

impl Walker<'_> {
    /// Stick or slip with the force `f` at `tau`: on the circle (to rounding)
    /// as [`Walker::on_circle`].
    fn enter(&mut self, f: [f64; 2]) -> Phase {
        let b = self.sp.bound.at(self.tau);
        let r = f[0].hypot(f[1]);
        if r > 0.0 && r >= b * (1.0 - 4.0 * f64::EPSILON) {
            // Beyond the circle the start is projected onto it: th = atan2(f) moves by e_perp.df/r.
            return self.on_circle([f[0] / r, f[1] / r], b, r);
        }
        Phase::Stick { f, skip: 0 }
    }

    /// The force `b e` on the circle at `tau`, reached from a force of size
    /// `r` (`b` itself but where a start beyond the circle is projected onto
    /// it): it slips if the slip rate `X'.e - B'` is positive, or 0 to its
    /// rounding and rising ([`slips`]), and sticks otherwise (a touch of the
    /// circle).
    fn on_circle(&mut self, e: [f64; 2], b: f64, r: f64) -> Phase {
        let (cs, sn) = Series::trig(self.tau);
        let (xd, bdot) = (self.sp.drive.velocity(&cs, &sn), sn * self.sp.bound.amp);
        let ([rate, _], tol) = slip_rate(&xd, &bdot, &quadratics(&half(e).map(Series::constant)));
        if slips(rate, tol, self.rate_slope(e, b)) {
            let jt = [0, 1].map(|j| (-e[1] * self.jac[0][j] + e[0] * self.jac[1][j]) / r);
            self.jac = [jt, [0.0; 2]];
            return Phase::Slip { y: half(e), regain: false };
        }
        Phase::Stick { f: scaled(e, b), skip: zeros(rate, tol) }
    }

    /// `d lambda/d tau` of a slip along `e` with the bound `b > 0`, where its
    /// rate is 0: with `th' = X'.e_perp/B`, `lambda' = X''.e + (X'.e_perp)^2/B
    /// - B''` (not a number where `b = 0` and `X'` is along `e`: no rise).
    fn rate_slope(&self, e: [f64; 2], b: f64) -> f64 {
        let (xd, xa) = (self.sp.drive.velocity_at(self.tau), self.sp.drive.acceleration_at(self.tau));
        let across = xd[1] * e[0] - xd[0] * e[1];
        xa[0] * e[0] + xa[1] * e[1] + across * across / b - self.sp.bound.amp * self.tau.cos()
    }

    /// `d f / d f_start` of a stick that starts at the direction `e` with `|f| = b`.
    fn stick_jacobian(&self, e: [f64; 2], b: f64) -> [[f64; 2]; 2] {
        let jt = self.jac[0];
        [[-e[1] * b * jt[0], -e[1] * b * jt[1]], [e[0] * b * jt[0], e[0] * b * jt[1]]]
    }

    fn end_jacobian(&self) -> [[f64; 2]; 2] {
        match self.phase {
            Phase::Stick { .. } => self.jac,
            Phase::Slip { y, .. } => self.stick_jacobian(direction(y), self.sp.bound.at(self.tau)),
            Phase::Out => [[0.0; 2]; 2],
        }
    }

    /// `sens += d f/d f_start` integrated over a step: `v[i]` times a row of
    /// the Jacobian at the step's start (a stick's `f` moves with its start
    /// by the Jacobian, row `i`, `v = (t, t)`; a slip's by `d f/d th` times
    /// row 0, `d th/d f_start`, `v` from [`turning`]). The force's
    /// integral is continuous across an event (the force is), so the events'
    /// own moves add nothing at first order. [`Spring::sensing`] only: it serves an
    /// answer's last step to the orbit (`super::corrected`), which is
    /// second order, so `v`'s truncation and the tail before a loss
    /// (`LOSS_TAIL`) are far below what it could move.
    fn sense(&mut self, v: [f64; 2], stick: bool) {
        if let Some(sens) = &mut self.sens {
            for (i, row) in sens.iter_mut().enumerate() {
                let jrow = if stick { self.jac[i] } else { self.jac[0] };
                row[0] += v[i] * jrow[0];
                row[1] += v[i] * jrow[1];
            }
        }
    }

    /// Books a step of length `t`: the force `(fx, fy)`, the bound `b`, the deficit `d = B - f_x`.
    fn book(&mut self, [fx, fy]: [&Series; 2], b: &Series, d: &Series, t: f64) {
        self.bound.add(b.integral(t));
        self.deficit.add(d.integral(t));
        self.force[0].add(fx.integral(t));
        self.force[1].add(fy.integral(t));
    }

    /// The next time, at most `end`, up to which a step of length `t` from `tau` reaches.
    fn advance(&mut self, t: f64, horizon: f64, target: f64) {
        self.tau = if t >= horizon { target } else { self.tau + t };
    }

    /// One stick step: `f = f0 + X(tau) - X(tau0)` until `|f| = B`.
    fn stick(&mut self, f: [f64; 2], skip: usize, end: f64) -> Result<Phase> {
        let tau = self.tau;
        let (cs, sn) = Series::trig(tau);
        let b = self.sp.bound.series(tau, &cs);
        let dx = self.sp.drive.displacement(&cs, &sn);
        let (fx, fy) = (dx[0] + Series::constant(f[0]), dx[1] + Series::constant(f[1]));
        let mut g = b.square() - fx.square() - fy.square();
        g.0[..skip].iter_mut().for_each(|a| *a = 0.0);
        let loss = self.sp.bound.next_loss(tau).filter(|&l| l < end);
        let target = loss.unwrap_or(end);
        let horizon = target - tau;
        let scale = super::force_scale(f);
        let tol = self.sp.step_tol;
        let h =
            Series::step_for(&[(&fx, tol * scale), (&fy, tol * scale), (&b, tol)]).min(MAX_STICK_STEP) * self.sp.stride;
        let h = h.min(horizon);
        if skip > 0 && g.0[skip] < -16.0 * f64::EPSILON * (b.square() + fx.square() + fy.square()).0[skip] {
            // A stick on the circle that leaves it at once, beyond the
            // rounding of `g`, would have slipped ([`slips`]).
            return Err(self.stalled("stick"));
        }
        let fall = g.first_fall(skip, h).map_err(|()| self.stalled("stick"))?;
        let t = fall.map_or(h, |(a, c)| refine(&g, skip, a, c));
        self.book([&fx, &fy], &b, &(b - fx), t);
        self.sense([t, t], true);
        self.truncation += (fx.tail(h) + fy.tail(h)) * h;
        let fe = [fx.eval(t), fy.eval(t)];
        self.advance(t, horizon, target);
        // An event on the loss of contact is the loss (the force is 0 there).
        if loss.is_some() && self.tau == target {
            return Ok(self.lose());
        }
        if fall.is_some() {
            self.events.push((self.tau, EventKind::Slip));
            let (r, b) = (fe[0].hypot(fe[1]), self.sp.bound.at(self.tau));
            if r == 0.0 {
                // A stick from a regained contact that lasted no time (`f = X' t`
                // to first order): the slip starts along `X'` ([`Walker::regain`]).
                return Ok(Phase::Slip { y: half(self.sp.drive.velocity_at(self.tau)), regain: true });
            }
            return Ok(self.on_circle([fe[0] / r, fe[1] / r], b, b));
        }
        Ok(Phase::Stick { f: fe, skip: 0 })
    }

    fn lose(&mut self) -> Phase {
        self.events.push((self.tau, EventKind::LossOfContact));
        self.jac = [[0.0; 2]; 2];
        Phase::Out
    }

    fn stalled(&self, what: &str) -> Error {
        Error::Internal { what: format!("the plane's {what} event at tau = {} did not isolate", self.tau) }
    }
}

impl Walker<'_> {
    /// One slip step along the half-angle series until the slip rate falls through 0.
    fn slip(&mut self, y0: [f64; 2], regain: bool, end: f64) -> Result<Phase> {
        let (tau, bound) = (self.tau, self.sp.bound);
        let loss = bound.next_loss(tau).filter(|&l| l <= end);
        if let (Some(l), false) = (bound.next_loss(tau), regain) {
            // The tail before a loss is booked along the slip's direction (a
            // walk that stops inside it, at `end`, goes on from there).
            let b = bound.series(tau, &Series::trig(tau).0);
            let rest = b.integral(l - tau);
            if l - tau < 0.5 && rest <= LOSS_TAIL {
                let (e, stop) = (direction(y0), l.min(end));
                let part = if stop == l { rest } else { b.integral(stop - tau) };
                self.bound.add(part);
                self.force[0].add(e[0] * part);
                self.force[1].add(e[1] * part);
                self.deficit.add(2.0 * y0[0] * y0[0] / (y0[0] * y0[0] + y0[1] * y0[1]) * part);
                self.truncation += 2.0 * part;
                self.tau = stop;
                return Ok(if stop == l { self.lose() } else { Phase::Slip { y: y0, regain: false } });
            }
        }
        let mut target = loss.unwrap_or(end);
        if let Some(ly) = self.sp.layer {
            match ly.exit_if_inside(tau) {
                Some(exit) if regain || self.near_manifold(y0) => return self.traverse(exit, end),
                Some(_) => {}
                None => target = target.min(ly.next_entry(tau)),
            }
        }
        // A slip from contact starts inside the layer, on its manifold (above).
        let clock = if regain { Clock::Tau } else { Clock::for_slip(&bound, tau, loss) };
        self.slip_step(y0, regain, clock, target, loss)
    }

    /// One slip step by `clock` from `y0` towards `target`.
    fn slip_step(&mut self, y0: [f64; 2], regain: bool, clock: Clock, target: f64, loss: Option<f64>) -> Result<Phase> {
        let (tau, bound) = (self.tau, self.sp.bound);
        let (cs, sn, rate) = clock.trig(tau);
        let b = bound.series(tau, &cs);
        // `X'` and `B'` in `tau`; `X'` and `B` times `dtau/dt` in the clock's time.
        let (xd_tau, bdot) = (self.sp.drive.velocity(&cs, &sn), sn * bound.amp);
        let (xd, bt) = match rate {
            Some(w) => (xd_tau.map(|v| v * w), b * w),
            None => (xd_tau, b),
        };
        let lam = growth(&b, &xd, y0);
        let (y, rho) = (regular(&b, &xd, y0, lam), clock.radius(&bound, tau));
        let horizon = clock.horizon(tau, target);
        let quad = quadratics(&y);
        let q = b.div(&quad[0]);
        let bn = match rate {
            Some(w) => q * w,
            None => q,
        };
        let [fx, fy, deficit] = bn.mul_each([&quad[1], &quad[2], &quad[3]]);
        let st = self.sp.step_tol;
        // The force's series serve its integral, whose truncation is about
        // `h/(N + 2)` times the series' at `h` ([`Series::integral_tail`]): they may
        // stop short of `st` by that factor, at the step the direction's allow.
        let cap = Series::step_for(&[(&y[0], st), (&y[1], st)]).min(0.5 * rho) * self.sp.stride;
        let cap = cap.min(horizon);
        let sf = st * (ORDER + 2) as f64 / cap;
        let h = Series::step_for(&[(&fx, sf), (&fy, sf)]).min(cap);
        let ([r0, r1], tol) = slip_rate(&xd_tau, &bdot, &quad);
        // A rate on 0 to rounding is 0: the slip goes on if it rises.
        let skip = usize::from(!regain && r0 <= tol);
        if skip == 1 && !slips(r0, tol, r1) {
            return Ok(self.slip_ends(direction(y0), zeros(r0, tol)));
        }
        // The rate's series; its value at the start as decided above
        // (`w lambda n / n^2`), 0 where it is 0 to rounding and rises.
        let mut ev = rate_series(&q, lam);
        let w0 = rate.map_or(1.0, |w| w.0[0]);
        ev.0[0] = if skip == 1 { 0.0 } else { r0 * w0 / (quad[0].0[0] * quad[0].0[0]) };
        let fall = ev.first_fall(skip, h).map_err(|()| self.stalled("slip"))?;
        let t = fall.map_or(h, |(a, c)| refine(&ev, skip, a, c));
        self.book([&fx, &fy], &bt, &deficit, t);
        if self.sens.is_some() && self.jac[0] != [0.0; 2] {
            self.sense(turning([&fx, &fy], &quad[0], lam, t), false);
        }
        // The truncation of the force's integral on this step, and the
        // direction's tail (an angle), felt by a force of about this size for
        // up to a period.
        self.truncation +=
            fx.integral_tail(h) + fy.integral_tail(h) + 2.0 * (y[0].tail(h) + y[1].tail(h)) * b.0[0].abs() * TAU;
        let ye = [y[0].eval(t), y[1].eval(t)];
        let norm = ye[0].hypot(ye[1]);
        if !regain {
            // `d angle_end / d angle_0 = det Phi / |y(t)|^2`, `det Phi = 1`
            // (`M` is traceless), `|y(t)| = e^(lam t) |z(t)|`.
            let d = (-2.0 * lam * t).exp() / (norm * norm);
            self.jac[0] = self.jac[0].map(|j| j * d);
        }
        let ye = [ye[0] / norm, ye[1] / norm];
        self.tau = if t >= horizon { target } else { clock.time(tau, t) };
        if loss == Some(self.tau) {
            return Ok(self.lose());
        }
        if fall.is_some() {
            return Ok(self.slip_ends(direction(ye), 2));
        }
        Ok(Phase::Slip { y: ye, regain: false })
    }

    /// The slip ends at `tau` with the direction `e`: stick from `f = B e`
    /// (`skip` leading zeros of `B^2 - |f|^2`, [`zeros`]).
    fn slip_ends(&mut self, e: [f64; 2], skip: usize) -> Phase {
        let b = self.sp.bound.at(self.tau);
        self.events.push((self.tau, EventKind::Stick));
        self.jac = self.stick_jacobian(e, b);
        Phase::Stick { f: scaled(e, b), skip }
    }

    /// Out of contact until the next contact (before `end`): stick or slip from `f = 0`.
    fn regain(&mut self, end: f64) -> Result<Phase> {
        let bound = self.sp.bound;
        let e = bound.edge.unwrap_or(0.0);
        let k = ((self.tau - e) / std::f64::consts::TAU).ceil();
        let tc = (std::f64::consts::TAU * k + e).max(self.tau);
        if tc >= end {
            self.tau = end;
            return Ok(Phase::Out);
        }
        self.events.push((tc, EventKind::Contact));
        self.jac = [[0.0; 2]; 2];
        let xd = self.sp.drive.velocity_at(tc);
        let speed = xd[0].hypot(xd[1]);
        self.tau = tc;
        if bound.edge.is_none() {
            // A touch of zero: the slip starts along X' on the layer's manifold.
            if self.sp.layer.is_none() || speed == 0.0 {
                return Err(Error::param(
                    "amp",
                    bound.amp,
                    "touches zero where the body is at rest: the reloading direction is undefined",
                ));
            }
            return Ok(Phase::Slip { y: half(xd), regain: true });
        }
        if slips_on_contact(xd, self.sp.drive.acceleration_at(tc), bound.amp * e.sin(), bound.level) {
            Ok(Phase::Slip { y: [0.0, 1.0], regain: true })
        } else {
            Ok(Phase::Stick { f: [0.0; 2], skip: 2 })
        }
    }

    /// Whether the slip's direction is within reach of the layer's slow
    /// manifold: [`ON_MANIFOLD`], or the manifold's own first-order error.
    fn near_manifold(&self, y: [f64; 2]) -> bool {
        let (m, neglected) = layer::manifold(&self.sp.drive, &self.sp.bound, self.tau);
        let e = direction(y);
        e[0] * m[0] + e[1] * m[1] > 0.0 && (e[0] * m[1] - e[1] * m[0]).abs() <= ON_MANIFOLD + 16.0 * neglected
    }

    /// A slip on the slow manifold through the layer until `exit` (or `end`),
    /// contact lost and regained on the way where the bound closes.
    fn traverse(&mut self, exit: f64, end: f64) -> Result<Phase> {
        let (drive, bound) = (self.sp.drive, self.sp.bound);
        let stop = exit.min(end);
        let center = std::f64::consts::TAU * (self.tau / std::f64::consts::TAU).round();
        let closes = match bound.edge {
            Some(e) => Some(center - e).filter(|&l| self.tau < l && l <= stop),
            // A touch of zero loses and regains contact at an instant; a
            // bound that stays above zero, however little, keeps it.
            None => Some(center).filter(|&c| bound.level <= bound.amp && self.tau < c && c <= stop),
        };
        let book = |w: &mut Self, a: f64, b: f64| {
            let (f, err) = layer::integral(&drive, &bound, a, b);
            w.force[0].add(f[0]);
            w.force[1].add(f[1]);
            w.bound.add(f[2]);
            // The layer's `int B` is small: its difference keeps an ulp of the period's.
            w.deficit.add(f[2] - f[0]);
            w.truncation += err;
        };
        self.jac = [[0.0; 2]; 2];
        if let Some(c) = closes {
            if let Some(t) = self.manifold_sticks(c) {
                book(self, self.tau, t);
                self.tau = t;
                return Ok(self.slip_ends(layer::manifold(&drive, &bound, t).0, 2));
            }
            book(self, self.tau, c);
            self.tau = c;
            if bound.edge.is_some() {
                return Ok(self.lose());
            }
            self.events.push((c, EventKind::LossOfContact));
            self.events.push((c, EventKind::Contact));
        }
        let stop = self.manifold_sticks(stop).unwrap_or(stop);
        book(self, self.tau, stop);
        self.tau = stop;
        let m = layer::manifold(&drive, &bound, stop).0;
        if stop < exit.min(end) {
            return Ok(self.slip_ends(m, 2));
        }
        Ok(Phase::Slip { y: half(m), regain: false })
    }

    /// Where a slip on the layer's manifold from `tau` stops before `b`: its
    /// rate `X'.e(th_m) - B'` falls through 0 (near a contact regained about
    /// as fast as the bound grows; `None` where it stays positive at `b`).
    fn manifold_sticks(&self, b: f64) -> Option<f64> {
        let (drive, bound) = (self.sp.drive, self.sp.bound);
        let rate = |t: f64| {
            let (m, v) = (layer::manifold(&drive, &bound, t).0, drive.velocity_at(t));
            v[0] * m[0] + v[1] * m[1] - bound.amp * t.sin()
        };
        match (rate(self.tau), rate(b)) {
            // A body at rest in the layer has no manifold (its integral fails).
            (a, r) if r > 0.0 || a.is_nan() || r.is_nan() => None,
            (r, _) if r <= 0.0 => Some(self.tau),
            _ => Some(crate::root::bracketed(rate, self.tau, b, 4.0 * f64::EPSILON).x),
        }
    }
}

#[cfg(test)]
#[path = "spring_tests.rs"]
mod tests;
