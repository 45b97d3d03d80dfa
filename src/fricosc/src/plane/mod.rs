//! Oscillation across the sliding direction, exact (`MODEL-transverse.md`):
//! each spring's tangential force is a vector bounded by the circle of radius
//! `B(tau)`, the body moves as `X(tau) = (vhat tau + T sin(tau + phase), W
//! sin(tau + psi))`.
//!
//! The solver walks one period event by event (`spring.rs`): a stick is closed
//! form, a slip the Taylor series of a linear equation for the force's
//! half-angle (its truncation estimated term by term, `series.rs`), every
//! event the first sign change of a series on its step. The steady state is
//! the fixed point of the period map, found by Newton with the map's exact
//! derivative (`d th_end/d th_start = 1/|y_end|^2` along a slip, the identity
//! along a stick, the projection across the circle at the events); a spring
//! that leaves contact, or touches it (`amp = 1`), forgets its past, and one
//! period from contact is its orbit. The last Newton step need not be
//! walked: the means move with the start by the walk's own sensitivity
//! (`corrected`), and what that leaves is second order. The reduction is
//! the deficit `<B - f_x>` integrated as such (`B (1 - e_x) = 2 B y1^2/|y|^2`
//! along a slip), not `1 - mu_ratio`.

mod clock;
mod close;
mod curved;
mod drive;
mod fused;
mod history;
mod layer;
mod series;
mod slip;
mod spring;
mod tail;

use crate::error::{check_nonneg, Error, Result};
use crate::shape::Shape;
use crate::spring::EventKind;
use crate::Conditions;
use close::{closed, corrected, with_events, Seen};
use drive::{Bound, Drive};
use spring::{Spring, Start, Walk};
use std::f64::consts::TAU;

pub(crate) use history::samples;

/// Largest transverse amplitude accepted (pre-slip lengths): as for the
/// oscillation in the sliding direction, the phase's rounding times `W` is
/// the answer's scale beyond it.
pub const MAX_TRANSVERSE_AMP: f64 = 1e6;
/// Largest `|psi|` accepted (radians): beyond it the reduced phase has lost
/// its digits.
pub const MAX_PHASE: f64 = 1e6;

/// The oscillation across the sliding direction: `W = dy/l` (pre-slip
/// lengths) and its phase `psi` against the normal oscillation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transverse {
    amp: f64,
    phase: f64,
}

impl Transverse {
    /// `W` finite in `[0, 1e6]`, `psi` finite with `|psi| <= 1e6`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `transverse-amp` or `transverse-phase`.
    pub fn new(amp: f64, phase: f64) -> Result<Transverse> {
        check_nonneg("transverse-amp", amp)?;
        if amp > MAX_TRANSVERSE_AMP {
            return Err(Error::param("transverse-amp", amp, "must be <= 1e6 pre-slip lengths"));
        }
        if !(phase.is_finite() && phase.abs() <= MAX_PHASE) {
            return Err(Error::param("transverse-phase", phase, "must be finite with |psi| <= 1e6 radians"));
        }
        Ok(Transverse { amp: amp + 0.0, phase: phase.rem_euclid(TAU) })
    }

    /// `W`.
    #[must_use]
    pub fn amp(&self) -> f64 {
        self.amp
    }

    /// `psi`, reduced to `[0, 2 pi)`.
    #[must_use]
    pub fn phase(&self) -> f64 {
        self.phase
    }
}

/// An event of the flat punch's period in the plane (an answer's part, made
/// by the solver only).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct PlaneEvent {
    /// What happens (`slip` is a slip in any direction of the plane).
    pub kind: EventKind,
    /// Phase `omega t` in `[0, 2 pi)`.
    pub tau: f64,
}

/// `mu_macro/mu0` and the mean force across the sliding direction.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct PlaneEvaluation {
    /// `<f_x>/<B>` (in `[-1, 1]`) and `1 -` it.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub ratio: crate::Ratio,
    /// `<f_y>/<B>`.
    pub transverse_ratio: f64,
    /// Estimated absolute error of either ratio.
    pub error_estimate: f64,
    /// The period map's largest multiplier (0 for a spring that forgets its past).
    pub multiplier: f64,
    /// The events of one period of the orbit.
    pub events: Vec<PlaneEvent>,
    /// Periods walked (relaxation and Newton included).
    pub periods: usize,
}

/// The answer under the conditions `c` and the transverse oscillation `w`:
/// the flat punch's orbit (module docs), with its events where `events` is
/// set (else its means only, the same bits, [`Precision::Means`]), or a curved contact's
/// springs ([`curved`]).
///
/// # Errors
/// [`Error::InvalidParameter`] for a system (not solved in the plane yet)
/// or a drive too stiff to step, [`Error::Internal`] when no attracting
/// orbit is found.
pub(crate) fn solve(shape: &Shape, c: &Conditions, w: Transverse, events: bool) -> Result<PlaneEvaluation> {
    let sp = centre(c, w)?;
    let contact = shape.contact();
    if contact.single_spring() {
        let precision = if events { Precision::Exact } else { Precision::Means };
        orbit_to(&sp, precision, None).map(|(e, _)| e)
    } else {
        curved::solve(contact, sp.drive, c.amp(), c.tol())
    }
}

/// Whether the conditions `c` (with a transverse oscillation) are solved in
/// the plane: what [`Shape::evaluate`] would refuse before any work (a
/// system, a slip too stiff to step), refused now, so that a batch checks
/// every row before it writes one.
///
/// # Errors
/// [`Error::InvalidParameter`], naming what is refused.
pub fn check(_shape: &Shape, c: &Conditions) -> Result<()> {
    match c.transverse() {
        Some(w) => centre(c, w).map(drop),
        None => Ok(()),
    }
}

/// The spring at the centre of the contact (the flat punch's) under `c` and
/// `w`, or what is refused before any work.
fn centre(c: &Conditions, w: Transverse) -> Result<Spring> {
    if let Some(sys) = c.system() {
        return Err(Error::param(
            "system-stiffness",
            sys.stiffness(),
            "a body on a system is not solved in the plane yet",
        ));
    }
    let o = crate::combined::Oscillation::of(c);
    let sp = Spring::new(Drive::sliding(o.vhat, o.tangential_amp, o.phase, w.amp, w.phase), Bound::new(1.0, o.amp));
    check_work(&sp, [("vhat", o.vhat), ("tangential-amp", o.tangential_amp), ("transverse-amp", w.amp)])?;
    Ok(sp)
}

/// Taylor steps a period may take at most, estimated before any work from
/// `int |X'|/(4 B) dtau`; a stiffer slip is refused by name.
pub const MAX_PERIOD_STEPS: f64 = 2e4;

/// Refuse, before any work, what the walk cannot do in reasonable time: a
/// slip's direction relaxes at the rate `|X'|/B`, and a Taylor step spans
/// about `4 B/|X'|` of it, so a period takes about `int |X'|/(4 B) dtau`
/// steps outside the thin layer (64 samples of the period); beyond
/// [`MAX_PERIOD_STEPS`] the drive named (the largest) is refused: there the
/// slip is the rigid body's to within `B/|X'|` (`stepper::rigid_limit`). A
/// bound that (nearly) touches zero at `tau = 0` (`|amp - 1| <= 1e-5`) where
/// the body (nearly) rests has no reloading direction.
fn check_work(sp: &Spring, drives: [(&'static str, f64); 3]) -> Result<()> {
    let (name, value) = drives.into_iter().fold(("vhat", 0.0), |a, d| if d.1 > a.1 { d } else { a });
    let v0 = sp.drive.velocity_at(0.0);
    if (sp.bound.amp - sp.bound.level).abs() <= 1e-5 && v0[0].hypot(v0[1]) < 1e-6 * value.max(1.0) {
        return Err(Error::param(
            "amp",
            sp.bound.amp,
            "nearly touches zero at tau = 0 where the body is nearly at rest: the reloading direction is undefined",
        ));
    }
    let steps = period_steps(sp);
    if steps > MAX_PERIOD_STEPS {
        return Err(Error::param(
            name,
            value,
            &format!("makes a slip too stiff to step exactly (about {steps:.0} steps a period, more than 2e4); there friction is the rigid body's to within a pre-slip length over the amplitude"),
        ));
    }
    Ok(())
}

/// The Taylor steps of a period of `sp`, about `int |X'|/(4 B) dtau`
/// outside the thin layer (64 samples of the period; [`check_work`]).
pub(crate) fn period_steps(sp: &Spring) -> f64 {
    let n = 64;
    let floor = layer::thickness(&sp.drive, &sp.bound);
    (0..n)
        .map(|k| {
            let tau = TAU * (k as f64 + 0.5) / n as f64;
            let (b, v) = (sp.bound.at(tau), sp.drive.velocity_at(tau));
            if b > floor {
                v[0].hypot(v[1]) / (4.0 * b) * TAU / n as f64
            } else {
                0.0
            }
        })
        .sum()
}

/// The residual (relative to the force's scale) below which the orbit's
/// search walks exactly ([`Spring::coarse`] above it).
const COARSE_UNTIL: f64 = 1e-3;

/// Periods one orbit's search may walk at most (Newton's steps, their
/// halvings and the leaps; a relaxation has its own budget).
const MAX_ORBIT_PERIODS: usize = 2000;
/// Halvings of one Newton step at most.
const MAX_HALVINGS: usize = 6;

/// How closely an orbit is walked: to full precision, its means to full
/// precision (the same bits; from a walk a Newton step off the orbit,
/// [`corrected`], whose events are not the orbit's and are not given), or
/// by [`Spring::coarse`] walks only (about `1e-9` a period, within its
/// estimate: a band search's sequence of events, a loose tolerance).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Precision {
    Exact,
    Means,
    Coarse,
}

/// The residual (relative to the force's scale) at which a coarse orbit is
/// closed: its share of the answer, `2 pi` times it over `1 - m`, counted
/// in the estimate, about the walks' own truncation (their rounding of the
/// map, from how their steps fall, is below it).
const COARSE_CLOSE: f64 = 1e-9;

/// The attracting orbit of `sp` and where it starts at `tau = 0`, exact.
fn orbit(sp: &Spring) -> Result<(PlaneEvaluation, Start)> {
    orbit_to(sp, Precision::Exact, None)
}

/// The attracting orbit of `sp` walked to `precision`, and where it starts,
/// searched from the force `from` at `tau = 0` (a neighbour's start, or
/// from [`rigid_start`] where none is given; only the way to the orbit
/// depends on it).
pub(crate) fn orbit_to(sp: &Spring, precision: Precision, from: Option<[f64; 2]>) -> Result<(PlaneEvaluation, Start)> {
    let total = sp.bound.period_integral();
    if sp.bound.amp >= sp.bound.level {
        let walk = sp.walk(Start::Contact(0.0), TAU)?;
        return Ok((answer(&walk, total, 0.0, 0.0, 1)?, Start::Contact(0.0)));
    }
    // Far from the orbit the walks are coarse (`Spring::coarse`); from a
    // residual of [`COARSE_UNTIL`] on, exact: Newton's next start is then
    // within about the square of it, and one or two exact walks close the search.
    let coarse = sp.coarse();
    // An exact walk from a start Newton's step is not expected to close finds its
    // sensitivity ([`SENSE_ABOVE`]) to close the search itself ([`corrected`]).
    let exact = [*sp, sp.sensing()];
    let sensing = usize::from(precision != Precision::Coarse);
    let mut cur = &coarse;
    let mut f = from.unwrap_or_else(|| rigid_start(sp));
    let mut periods = 1;
    let mut w = cur.walk(Start::Force(0.0, f), TAU)?;
    let (mut leaping, mut seen) = (false, None::<Seen>);
    // From a neighbour's start (a curved contact's node) the search is near at once: its coarse walk
    // is the visit before Newton's exact one, which senses and closes ([`corrected`]: the coarse
    // walk's truncation only enlarges the curvatures it measures; where they refuse, Newton walks on).
    if precision == Precision::Means && from.is_some() && !coarse.is_exact() {
        seen = Some(Seen { f, force: w.force, end: w.end });
    }
    while periods < MAX_ORBIT_PERIODS {
        let res = residual(f, &w);
        if !cur.is_exact() {
            // Near the orbit (where an exact one is asked), or a period that
            // only sticks: on exactly, Newton's step taken as it is where it
            // stays that near (not along a slow drift, which leaps).
            let near = precision != Precision::Coarse && res <= COARSE_UNTIL * force_scale(f);
            if near || w.stuck {
                let r = [w.end[0] - f[0], w.end[1] - f[1]];
                let step = newton_step(&w.jacobian, r)
                    .filter(|s| near && s[0].hypot(s[1]) <= COARSE_UNTIL * force_scale(f))
                    .unwrap_or([0.0; 2]);
                // Its sensitivity serves only with a visit before it ([`corrected`]).
                (cur, f) = (&exact[sensing * usize::from(seen.is_some())], [f[0] + step[0], f[1] + step[1]]);
                w = cur.walk(Start::Force(0.0, f), TAU)?;
                (periods, leaping) = (periods + 1, false);
                continue;
            }
        }
        // An exact orbit closes on an exact walk only.
        let close = match (precision, cur.is_exact()) {
            (_, true) => 8.0 * f64::EPSILON,
            (Precision::Coarse, false) => COARSE_CLOSE,
            (_, false) => f64::NEG_INFINITY,
        };
        let before = seen.replace(Seen { f, force: w.force, end: w.end });
        if cur.is_exact() && res > close * force_scale(f) {
            if let Some(done) = before.and_then(|b| corrected(cur, &w, f, &b, (total, periods))) {
                return with_events(done, precision, &exact[0]);
            }
            cur = &exact[sensing * usize::from(res > SENSE_ABOVE * force_scale(f))];
        }
        if res <= close * force_scale(f) {
            let m = multiplier(&w.jacobian);
            // A neutral orbit (a period that only sticks repeats from any
            // start): the one the relaxed start reaches is the answer. The
            // Jacobian is a product of the steps' factors, each rounded: a
            // multiplier within their rounding of 1 is neutral.
            if m >= 1.0 - 4.0 * f64::EPSILON * (w.steps as f64 + 1.0) {
                return relaxed(cur, total, periods);
            }
            return closed(cur, (f, w), total, m, periods);
        }
        if w.stuck {
            // A period of stick only drifts by X(2 pi) - X(0): go where the drift first slips.
            f = first_slip(cur, f, [w.end[0] - f[0], w.end[1] - f[1]])?;
            w = cur.walk(Start::Force(0.0, f), TAU)?;
            periods += 1;
            continue;
        }
        // Newton's step; where it fails, a leap along the map's drift (and
        // more leaps while they go on: Newton again once one does not).
        let (tried, walked) = if leaping { (None, 0) } else { newton(cur, f, &w, res)? };
        periods += walked;
        if !cur.is_exact() && (tried.is_none() || walked > 1) {
            // Only Newton's plain steps are coarse: on exactly from where it got.
            cur = &exact[sensing];
            f = tried.map_or(f, |(g, _)| g);
            w = cur.walk(Start::Force(0.0, f), TAU)?;
            periods += 1;
            continue;
        }
        (f, w, leaping) = match tried {
            // A step halved thrice or more is held back by the drift's
            // curvature (a force that turns round its circle): leap next.
            Some((g, wg)) => (g, wg, walked > 3),
            None => {
                let ((g, wg), walked, leapt) = leap(cur, f, &w)?;
                periods += walked;
                (g, wg, leapt)
            }
        };
    }
    Err(Error::Internal { what: format!("no attracting periodic orbit in the plane after {periods} periods") })
}

/// Where a search with no better start begins: where the body moves at
/// `tau = 0` by at least its bound a radian (`|X'(0)| >= B(0) > 0`), the
/// rigid body's force, `B(0)` along `X'(0)`, which a spring that slips
/// there lags by about `B/|X'|` of a turn; else 0 (a slower body's spring
/// may stick, anywhere in the disc).
fn rigid_start(sp: &Spring) -> [f64; 2] {
    let (v, b) = (sp.drive.velocity_at(0.0), sp.bound.at(0.0));
    let speed = v[0].hypot(v[1]);
    if speed >= b && b > 0.0 {
        [b * v[0] / speed, b * v[1] / speed]
    } else {
        [0.0; 2]
    }
}

/// A start of the period map and the walk of its period.
type Visit = ([f64; 2], Walk);

/// The residual `|P(f) - f|` of the walk `w` from `f`.
fn residual(f: [f64; 2], w: &Walk) -> f64 {
    (w.end[0] - f[0]).hypot(w.end[1] - f[1])
}

/// Newton's step from `f` (its walk `w`, its residual `res`), halved until
/// the residual falls (the map is only piecewise smooth: a step may cross
/// where its events change): the start and walk it reached, if any, and the
/// periods walked.
fn newton(sp: &Spring, f: [f64; 2], w: &Walk, res: f64) -> Result<(Option<Visit>, usize)> {
    let r = [w.end[0] - f[0], w.end[1] - f[1]];
    let step = newton_step(&w.jacobian, r).unwrap_or(r);
    let mut lambda = 1.0;
    for walked in 1..=MAX_HALVINGS {
        let g = [f[0] + lambda * step[0], f[1] + lambda * step[1]];
        let wg = sp.walk(Start::Force(0.0, g), TAU)?;
        if residual(g, &wg) < res {
            return Ok((Some((g, wg)), walked));
        }
        lambda *= 0.5;
    }
    Ok((None, MAX_HALVINGS))
}

/// The largest leap along the map's drift, in periods ([`leap`]).
const MAX_LEAP: f64 = 1e9;
/// How far a leap may move the start, relative to its size (or 1).
const LEAP_REACH: f64 = 0.05;
/// How much larger than before a leap's residual may be: along the slow
/// drift the residual changes little, and the leap's error across it (the
/// drift's curvature times the leap squared) is what this admits.
const LEAP_GROWTH: f64 = 1.25;

/// Where Newton's step fails (the orbit beyond a change of the period's
/// events, which its linearisation does not see) and the map is nearly
/// neutral, the map drifts along its slow direction by about the residual
/// `r` a period (a spring that only grazes its bound under a slow slide
/// turns its force round the circle over thousands of periods). From
/// `P(f)`, `k` periods of that drift are leapt at once (in polar
/// coordinates, as the force turns) and one period walked from there to
/// settle what the leap missed across the drift (a leap that lands among
/// the states that stick all period goes on along their drift to where the
/// spring slips, then settles); `k` runs from `LEAP_REACH / |r|` (at most
/// `1 / (1 - m)`, over which the drift decays at the multiplier `m`, and
/// [`MAX_LEAP`]) down by 4 until the settled
/// start has moved at least `k |r| / 2`, still drifts the same way, and has
/// a residual at most [`LEAP_GROWTH`] times that at `f`; else `k = 1`, the
/// map's own next period. Only a way towards the orbit: only a walked
/// residual ends the search. The start, its walk, the periods walked and
/// whether it leapt.
fn leap(sp: &Spring, f: [f64; 2], w: &Walk) -> Result<(Visit, usize, bool)> {
    let r = [w.end[0] - f[0], w.end[1] - f[1]];
    let size = r[0].hypot(r[1]);
    let reach = LEAP_REACH * force_scale(f);
    // Beyond `1 / (1 - m)` periods the drift has decayed: Newton's to take.
    let decay = 1.0 / (1.0 - multiplier(&w.jacobian)).max(1.0 / MAX_LEAP);
    let mut k = (reach / size).min(decay).floor();
    let mut walked = 0;
    let polar = |x: [f64; 2]| (x[0].hypot(x[1]), x[1].atan2(x[0]));
    let ((r0, a0), (r1, a1)) = (polar(f), polar(w.end));
    while k > 1.0 {
        let (rg, ag) = (r1 + k * (r1 - r0), a1 + k * (a1 - a0));
        let mut g = [rg * ag.cos(), rg * ag.sin()];
        let mut wg = sp.walk(Start::Force(0.0, g), TAU)?;
        if wg.stuck {
            // Leapt inside the states that stick all period: on along their drift to where it slips.
            g = first_slip(sp, g, [wg.end[0] - g[0], wg.end[1] - g[1]])?;
            wg = sp.walk(Start::Force(0.0, g), TAU)?;
            walked += 1;
        }
        let h = wg.end;
        let wh = sp.walk(Start::Force(0.0, h), TAU)?;
        walked += 2;
        let moved = (h[0] - w.end[0]).hypot(h[1] - w.end[1]);
        let ahead = (wh.end[0] - h[0]) * r[0] + (wh.end[1] - h[1]) * r[1] > 0.0;
        if residual(h, &wh) <= LEAP_GROWTH * size && moved >= 0.5 * k * size && ahead {
            return Ok(((h, wh), walked, true));
        }
        k = (k / 4.0).floor();
    }
    Ok(((w.end, sp.walk(Start::Force(0.0, w.end), TAU)?), walked + 1, false))
}

/// The residual (relative to the force's scale) above which an exact walk
/// is followed by one that finds its sensitivity:
/// from below it, Newton's next residual, about the square of it times the
/// map's curvature (of order 1), is expected to close the search by itself.
const SENSE_ABOVE: f64 = 1e-8;

/// Periods run from the relaxed start at most, where the orbit is neutral.
const MAX_RELAXED: usize = 400;

/// Periods whose residuals, falling geometrically, bound the rest of a
/// relaxation that has not closed ([`relaxed`]).
const GEOMETRIC_TAIL: usize = 20;

/// The orbit the relaxed start reaches, period after period, where Newton's
/// is neutral (a shakedown into pure stick: every state that sticks all
/// period is periodic, and the relaxed start picks one). Where it does not
/// close within [`MAX_RELAXED`] periods but its last [`GEOMETRIC_TAIL`]
/// residuals fall at least by a ratio `q < 1` a period, the start is within
/// `r q/(1 - q)` (`r` the last residual) of the limit's, and so is the
/// force all period (the stop operator does not expand a difference of
/// starts): that is the answer's residual.
fn relaxed(sp: &Spring, total: f64, newton_periods: usize) -> Result<(PlaneEvaluation, Start)> {
    let mut f = [0.0; 2];
    let mut residuals = Vec::with_capacity(MAX_RELAXED);
    for k in 1..=MAX_RELAXED {
        let w = sp.walk(Start::Force(0.0, f), TAU)?;
        let res = (w.end[0] - f[0]).hypot(w.end[1] - f[1]);
        let periods = newton_periods + k;
        if res <= 8.0 * f64::EPSILON * force_scale(f) {
            return Ok((answer(&w, total, multiplier(&w.jacobian), res, periods)?, Start::Force(0.0, f)));
        }
        residuals.push(res);
        if k == MAX_RELAXED {
            let tail = &residuals[residuals.len() - GEOMETRIC_TAIL..];
            let q = tail.windows(2).map(|p| p[1] / p[0]).fold(0.0, f64::max);
            if q < 1.0 {
                let rest = res * q / (1.0 - q);
                return Ok((answer(&w, total, multiplier(&w.jacobian), rest, periods)?, Start::Force(0.0, f)));
            }
        }
        f = w.end;
    }
    Err(Error::Internal { what: format!("a neutral orbit in the plane not reached in {MAX_RELAXED} periods") })
}

/// Along a drift `d` of a period that only sticks, the first start `f + s d`
/// whose period slips (bisection on `s`): Newton's start on the far side of
/// the many periods a slow drift takes to reach the circle.
fn first_slip(sp: &Spring, f: [f64; 2], d: [f64; 2]) -> Result<[f64; 2]> {
    let at = |s: f64| [f[0] + s * d[0], f[1] + s * d[1]];
    let slips = |s: f64| sp.walk(Start::Force(0.0, at(s)), TAU).map(|w| !w.stuck);
    let mut hi = 1.0;
    while !slips(hi)? {
        hi *= 2.0;
        if hi > 1e300 {
            return Err(Error::Internal { what: "a drift in the plane that never slips".into() });
        }
    }
    let mut lo = 0.0;
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if slips(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(at(hi))
}

/// Newton's step `-(J - I)^-1 r` for the residual `r = P(f) - f`.
fn newton_step(j: &[[f64; 2]; 2], r: [f64; 2]) -> Option<[f64; 2]> {
    let (a, b, c, d) = (j[0][0] - 1.0, j[0][1], j[1][0], j[1][1] - 1.0);
    let det = a * d - b * c;
    (det != 0.0 && det.is_finite()).then(|| [-(d * r[0] - b * r[1]) / det, -(-c * r[0] + a * r[1]) / det])
}

/// The largest modulus of the eigenvalues of `j`.
fn multiplier(j: &[[f64; 2]; 2]) -> f64 {
    let (tr, det) = (j[0][0] + j[1][1], j[0][0] * j[1][1] - j[0][1] * j[1][0]);
    let disc = 0.25 * tr * tr - det;
    if disc >= 0.0 {
        (0.5 * tr).abs() + disc.sqrt()
    } else {
        det.abs().sqrt()
    }
}

/// The scale of a force's rounding: its largest component, at least 1.
pub(crate) fn force_scale(f: [f64; 2]) -> f64 {
    1f64.max(f[0].abs()).max(f[1].abs())
}

/// The rounding of a sum over the steps of the walk `w` (each rounds at
/// about an ulp of the running total `scale`, at random).
fn rounding(w: &Walk, scale: f64) -> f64 {
    f64::EPSILON * ((w.steps as f64).sqrt() + 2.0) * scale
}

/// The events of the walk `w`, their phases in `[0, 2 pi)`.
fn events(w: &Walk) -> Vec<PlaneEvent> {
    w.events.iter().map(|&(tau, kind)| PlaneEvent { kind, tau: tau.rem_euclid(TAU) }).collect()
}

/// An answer's transverse ratio `tr` and estimate, checked: the estimate
/// at least 0 (a sum of errors' sizes), the ratio finite and within it of
/// `[-1, 1]` (`|<f_y>| <= <B>`). Either off is a bug, never an answer.
pub(crate) fn checked(tr: f64, error_estimate: f64, context: &str) -> Result<()> {
    if error_estimate.is_nan() || error_estimate < 0.0 {
        return Err(Error::Internal { what: format!("error_estimate = {error_estimate:?} in the plane ({context})") });
    }
    if !(tr.is_finite() && tr.abs() <= 1.0 + error_estimate) {
        return Err(Error::Internal { what: format!("transverse_ratio = {tr:?} in the plane ({context})") });
    }
    Ok(())
}

/// The evaluation of the period walked by `w`, whose start is within
/// `start_error` of the orbit's: so is its force all period (the stop
/// operator does not expand a difference of starts).
fn answer(w: &Walk, total: f64, multiplier: f64, start_error: f64, periods: usize) -> Result<PlaneEvaluation> {
    let (mu, tr) = (w.force[0] / total, w.force[1] / total);
    // Each step's sum rounds at about an ulp of the running total, at random;
    // `int B` summed as the force is, against its closed form, measures the
    // rounding of the steps' integrals and of the normalisation together
    // (a slip throughout has `|<f>| = <B>` exactly).
    let scale = 1f64.max(mu.abs()).max(tr.abs());
    let rounding = rounding(w, scale);
    let consistency = if w.bound > 0.0 { (w.bound - total).abs() / total * scale } else { 0.0 };
    let error_estimate = (w.truncation + TAU * start_error) / total + rounding + consistency;
    checked(tr, error_estimate, "one spring")?;
    Ok(PlaneEvaluation {
        ratio: crate::Ratio::signed(mu, w.deficit / total, error_estimate, "the plane")?,
        transverse_ratio: tr,
        error_estimate,
        multiplier,
        events: events(w),
        periods,
    })
}

#[cfg(test)]
mod tests;
