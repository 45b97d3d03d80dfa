//! How an orbit's search closes, and how far its start is from the true
//! one: a walk whose residual is within rounding ([`closed`]), or one a
//! Newton step short of it whose means that step corrects by the walk's
//! sensitivity ([`corrected`]); either way the map's own rounding puts the
//! start [`start_noise`] away.

use super::spring::{Spring, Start, Walk};
use super::{
    answer, events, force_scale, multiplier, newton_step, residual, rounding, PlaneEvaluation, Precision, Visit,
};
use crate::error::Result;
use std::f64::consts::TAU;

/// A start the orbit's search walked from: where its walk ended, and its
/// force's integral.
pub(super) struct Seen {
    pub(super) f: [f64; 2],
    pub(super) force: [f64; 2],
    pub(super) end: [f64; 2],
}

/// The means of the orbit from the exact walk `w` that starts at `f`, a
/// Newton step `s` short of it, without walking from `f + s`: the walk's
/// `int f` plus `G s` (`G` its [`Walk::sensitivity`]), and the start `f + s`.
/// What is left is second order in `s`: `K |s|^2` of the force's integral,
/// and `C |s|^2/(1 - m)` of the start, felt `|G|` times, with `K` and `C`
/// bounded by what the walk from the previous start `before` (a distance
/// `d` away) shows: `|int f - int f_before - G d| / |d|^2` and `|r -
/// r_before - (J - I) d| / |d|^2` (their rounding and truncation, and the
/// previous walk's, only add to them). `f + s` closes the walk's own map,
/// rounding and all: as for a closing walk, the map's rounding leaves
/// [`start_noise`] of the start. `None` where the
/// second-order part exceeds what a closing walk's residual (`8 eps`) would
/// leave: then Newton's walk is taken, as for [`Precision::Exact`].
pub(super) fn corrected(
    sp: &Spring,
    w: &Walk,
    f: [f64; 2],
    before: &Seen,
    (total, periods): (f64, usize),
) -> Option<Result<(PlaneEvaluation, [f64; 2])>> {
    let g = &w.sensitivity?;
    let j = &w.jacobian;
    let m = multiplier(j);
    let r = [w.end[0] - f[0], w.end[1] - f[1]];
    let s = newton_step(j, r)?;
    let [k, c] = curvatures(w, g, f, before);
    let (ss, scale) = (s[0] * s[0] + s[1] * s[1], force_scale(f));
    let size = g.iter().flatten().map(|x| x * x).sum::<f64>().sqrt();
    let second = k * ss + size * c * ss / (1.0 - m);
    if !(m < 1.0 && second <= TAU * 8.0 * f64::EPSILON * scale) {
        return None;
    }
    let gs = times(g, s);
    let mut moved = w.clone();
    moved.force = [w.force[0] + gs[0], w.force[1] + gs[1]];
    moved.deficit = w.deficit - gs[0];
    moved.events.clear();
    let (noise, more) = match start_noise(sp, f, w, m) {
        Ok(noise) => noise,
        Err(e) => return Some(Err(e)),
    };
    let start_error = (second + size * noise) / TAU;
    Some(answer(&moved, total, m, start_error, periods + more).map(|e| (e, [f[0] + s[0], f[1] + s[1]])))
}

/// An orbit's means and start from [`corrected`]: with the events of a
/// walk from that start where [`Precision::Exact`] asks for them (the same
/// means).
pub(super) fn with_events(
    done: Result<(PlaneEvaluation, [f64; 2])>,
    precision: Precision,
    sp: &Spring,
) -> Result<(PlaneEvaluation, Start)> {
    let (mut e, s) = done?;
    if precision == Precision::Exact {
        e.events = events(&sp.walk(Start::Force(0.0, s), TAU)?);
        e.periods += 1;
    }
    Ok((e, Start::Force(0.0, s)))
}

/// `m v`.
fn times(m: &[[f64; 2]; 2], v: [f64; 2]) -> [f64; 2] {
    [m[0][0] * v[0] + m[0][1] * v[1], m[1][0] * v[0] + m[1][1] * v[1]]
}

/// `[K, C]` of [`corrected`]: how far the walk `w` from `f` (its
/// sensitivity `g`) and the one from `before` differ from their linear
/// prediction, the force's integral and the residual, over their distance
/// squared.
pub(super) fn curvatures(w: &Walk, g: &[[f64; 2]; 2], f: [f64; 2], before: &Seen) -> [f64; 2] {
    let d = [f[0] - before.f[0], f[1] - before.f[1]];
    let dd = d[0] * d[0] + d[1] * d[1];
    let (gd, jd) = (times(g, d), times(&w.jacobian, d));
    let k = (w.force[0] - before.force[0] - gd[0]).hypot(w.force[1] - before.force[1] - gd[1]) / dd;
    let (r, rb) = ([w.end[0] - f[0], w.end[1] - f[1]], [before.end[0] - before.f[0], before.end[1] - before.f[1]]);
    let c = (r[0] - rb[0] - jd[0] + d[0]).hypot(r[1] - rb[1] - jd[1] + d[1]) / dd;
    [k, c]
}

/// The orbit whose exact walk `w` from `f` closes (its residual within
/// rounding), contracting at the rate `m`, after `periods`. The start is
/// within Newton's remaining step of the fixed point of the map as
/// computed (at most `res/(1 - m)`), and that within [`start_noise`] of the
/// true one. Where that noise is measured (`1 - m` small) and Newton's
/// step is beyond it, the step is taken (one walk): a residual an ulp of
/// the force, along a slow direction, is a start `1/(1 - m)` ulps off.
pub(super) fn closed(
    sp: &Spring,
    (f, w): Visit,
    total: f64,
    m: f64,
    periods: usize,
) -> Result<(PlaneEvaluation, Start)> {
    let (noise, more) = start_noise(sp, f, &w, m)?;
    let rest = |f: [f64; 2], w: &Walk| {
        let r = [w.end[0] - f[0], w.end[1] - f[1]];
        (newton_step(&w.jacobian, r), residual(f, w) / (1.0 - m))
    };
    let (step, bound) = rest(f, &w);
    let (f, w, periods) = match step.filter(|s| more > 0 && s[0].hypot(s[1]) > noise) {
        Some(s) => {
            let g = [f[0] + s[0], f[1] + s[1]];
            (g, sp.walk(Start::Force(0.0, g), TAU)?, periods + more + 1)
        }
        None => (f, w, periods + more),
    };
    let start_error = match (more, rest(f, &w)) {
        (0, _) => bound,
        (_, (step, bound)) => step.map_or(bound, |s| s[0].hypot(s[1])),
    };
    Ok((answer(&w, total, m, start_error + noise, periods)?, Start::Force(0.0, f)))
}

/// Below this distance of an orbit's multiplier from 1, the rounding of
/// its period map is measured ([`start_noise`]); elsewhere its share of the
/// start's error is within about `1e-14` of the force a priori.
const NOISE_MEASURED_BELOW: f64 = 0.1;
/// The strides of [`start_noise`]'s walks ([`Spring::strided`]): steps
/// placed unlike the exact walk's and each other's.
const NOISE_STRIDES: [f64; 2] = [0.81, 0.66];
/// How far beyond the largest measured share [`start_noise`] puts it: the
/// difference of two independent draws of a 2-D normal rounding falls
/// below a quarter of one draw's size with a chance of about 1.6%, the
/// larger of two such differences less often.
const NOISE_SAFETY: f64 = 4.0;

/// How far the rounding of the period map puts a closed orbit's start
/// from the true one, and the periods walked to find it, at the start `f`
/// (its exact walk `w`, its Jacobian's multiplier `m`). A map rounded by
/// `b` has its fixed point `(I - J)^-1 b` away: a priori at most
/// `m e/(1 - m)` for a period's rounding `e` ([`rounding`], ulps of the
/// force; `m e` as the last period's is the mean's own). Where `1 - m` is
/// below [`NOISE_MEASURED_BELOW`] that bound is large, and where the slow
/// direction is a small component of the force (a force that turns on its
/// circle near an axis) its rounding is far below the force's ulps: there
/// `b` is measured, as the differences of `w`'s end from the ends of walks
/// from `f` by other steps ([`Spring::strided`], whose truncation is below
/// `w`'s), and the largest `(I - J)^-1 b` times [`NOISE_SAFETY`] is the
/// share, at least an ulp of the force. Coarse walks take the a priori
/// bound.
fn start_noise(sp: &Spring, f: [f64; 2], w: &Walk, m: f64) -> Result<(f64, usize)> {
    let scale = force_scale(f);
    let priori = m * rounding(w, scale) / (1.0 - m);
    if !sp.is_exact() || 1.0 - m >= NOISE_MEASURED_BELOW {
        return Ok((priori, 0));
    }
    let mut share = f64::EPSILON * scale;
    for stride in NOISE_STRIDES {
        let end = sp.strided(stride).walk(Start::Force(0.0, f), TAU)?.end;
        let moved =
            newton_step(&w.jacobian, [end[0] - w.end[0], end[1] - w.end[1]]).map_or(priori, |s| s[0].hypot(s[1]));
        share = share.max(NOISE_SAFETY * moved);
    }
    Ok((share, NOISE_STRIDES.len()))
}
