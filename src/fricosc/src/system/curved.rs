//! Curved bodies on a system: the foundation as `N` springs with exact events
//! ([`super::springs`]), the attractor of each discretisation found as the
//! flat punch's is (the period map iterated until its state repeats), at
//! `N/2` and `N` springs.
//!
//! # The discretisation and its error
//! The springs are the midpoints of equal cells in `theta` on each piece
//! `[a, b]` of `[0, z_max]`, `z = a + (b - a)(1 - cos theta)/2` (which absorbs
//! the square-root behaviour of the springs' means at a piece's ends), `z_max`
//! the contact's reach at the amplitude, the pieces cut at the geometry's
//! breakpoints, at `z = 1` and where a spring leaves permanent contact
//! (`G = 1 - amp`); each spring has the weight of its cell (the stiffness
//! density is 1: the springs in contact at the mean indentation have the
//! contact's stiffness), neighbours with the same `G` (a flat part) merged.
//! The force and the mean normal force are the same rule's sums, so `mu_N` is
//! a ratio of two midpoint rules; its error falls like `N^-2` (measured: the
//! error of `mu_N` is a third of `mu_N - mu_{N/2}` to within 10 % on
//! paraboloids, cones, `power:3` and worn spheres, with and without contact
//! loss, from `N = 128`; on `power:0.5`, whose profile has a cusp at the
//! centre, up to 0.7 of it at `N = 256`). The answer is the Richardson value
//! `mu_N + (mu_N - mu_{N/2})/3`, its error estimate `|mu_N - mu_{N/2}|` (from
//! `N = 128` the extrapolated value's error was below 0.05 of it, and below
//! 0.4 on `power:0.5`, which at `N = 64` was still far from the asymptote)
//! plus the orbits' closure (`attractor`). Without a period the answer is
//! `mu_N`'s long-time mean, whose error estimate (standard error and drift)
//! is added to `|mu_N - mu_{N/2}|`.

use super::mean::batch_mean;
use super::springs::{Foundation, Spring};
use super::{Params, SystemReport, MAX_ORBIT, MAX_STEPS, MIN_PERIODS, REPEAT};
use crate::error::{Error, Result};
use crate::shape::Shape;

/// Springs of a curved body's finer discretisation by default.
pub const DEFAULT_SPRINGS: usize = 256;
/// Most springs of a curved body's finer discretisation.
pub const MAX_SPRINGS: usize = 1 << 14;
/// Most periods run from the start for one discretisation before the answer
/// is "no period"; fewer (at least 20) where they take more than 2·10^7
/// sampling steps, and as many steps again may refine an orbit found.
pub const MAX_CURVED_PERIODS: usize = 600;

/// The springs `(w_i, b_i)` of `shape` at the amplitude `amp`, about `n`
/// midpoints (module docs).
pub(crate) fn discretise(shape: &Shape, amp: f64, n: usize) -> Result<Vec<(f64, f64)>> {
    let c = shape.contact();
    if c.single_spring() {
        return Ok(vec![(1.0, 1.0)]);
    }
    let reach = c.reach(amp)?;
    let mut cuts = vec![0.0, reach, 1.0];
    if amp < 1.0 {
        cuts.push(c.level(1.0 - amp));
    }
    cuts.extend(c.breakpoints());
    cuts.retain(|z| (0.0..=reach).contains(z));
    cuts.sort_by(f64::total_cmp);
    // A piece thinner than half a cell is merged into its neighbour: a
    // level that tends to a cut (`G = 1 - amp` to the centre as `amp -> 1`)
    // then adds no spring of vanishing weight, and the springs are
    // continuous in `amp` there.
    let min = 0.5 * reach / n as f64;
    let mut kept: Vec<f64> = vec![];
    for z in cuts {
        let inner = kept.len() > 1;
        match kept.last_mut() {
            // The reach ends the last piece, in place of a cut just before it.
            Some(last) if z - *last < min => {
                if z == reach && inner {
                    *last = z;
                }
            }
            _ => kept.push(z),
        }
    }
    let cuts = kept;
    let mut springs: Vec<(f64, f64)> = vec![];
    for piece in cuts.windows(2) {
        let len = piece[1] - piece[0];
        let cells = ((n as f64 * len / reach).round() as usize).max(1);
        let h = std::f64::consts::PI / cells as f64;
        for j in 0..cells {
            let theta = (j as f64 + 0.5) * h;
            let w = 0.5 * len * theta.sin() * h;
            let b = 1.0 - c.equivalent_profile(piece[0] + 0.5 * len * (1.0 - theta.cos()));
            match springs.last_mut() {
                Some(last) if last.1 == b => last.0 += w,
                _ => springs.push((w, b)),
            }
        }
    }
    Ok(springs)
}

/// The attractor of one discretisation.
#[derive(Debug, Clone, Copy)]
struct Found {
    mu: f64,
    /// `None`: no repeat within the budget (then `mu` is a mean).
    period: Option<usize>,
    periods_run: usize,
    /// A bound on the orbit's closure, or the mean's error estimate where there is no period.
    error: f64,
    /// The mean's standard error where there is no period.
    standard_error: Option<f64>,
}

/// The body `(x, x')` and its springs' states at `tau = 0`.
type Body = (f64, f64, Vec<Spring>);

/// Orbits closed beyond this (relative, as [`REPEAT`]) are exact to rounding.
const TIGHT: f64 = 1e-13;
/// Most orbits run to refine one near-repeat.
const REFINE: usize = 200;

/// The state of the period map at `tau = 0` (`x`, `x'`, each spring's kind and force).
type Snapshot = (f64, f64, Vec<(u8, f64)>);

/// The largest difference of two states relative to 1 and the state (infinite where a spring's kind differs).
fn distance(a: &Snapshot, b: &Snapshot) -> f64 {
    let rel = |d: f64, x: f64| (d - x).abs() / (1.0 + x.abs());
    let springs = a.2.iter().zip(&b.2).map(|(p, q)| if p.0 == q.0 { rel(p.1, q.1) } else { f64::INFINITY });
    springs.fold(rel(a.0, b.0).max(rel(a.1, b.1)), f64::max)
}

/// The least period of an orbit closed after `k` periods to `closed`: the
/// first divisor `p` of `k` after which the state is back within ten times
/// that (a period-1 orbit found while a decaying transient still made the
/// state after `k` periods the nearest).
fn least_period(fd: &Foundation, (x, v, state): (f64, f64, &[Spring]), k: usize, closed: f64) -> usize {
    let start = (x, v, fd.forces_at_start(x, state));
    let (mut y, mut w, mut s) = (x, v, state.to_vec());
    for p in 1..k {
        (y, w, _, _) = fd.period(y, w, &mut s, &[]);
        if k.is_multiple_of(p) && distance(&start, &(y, w, fd.forces_at_start(y, &s))) <= 10.0 * closed {
            return p;
        }
    }
    k
}

/// The attractor of one discretisation from the stated start: the period map
/// iterated until its state repeats after `k <= MAX_ORBIT` periods (to
/// [`REPEAT`]; at most [`MAX_CURVED_PERIODS`], and once at least
/// [`MIN_PERIODS`] are run at most [`MAX_STEPS`] sampling steps), then orbit
/// after orbit (up to twice that many steps in all) until it closes to [`TIGHT`]; the
/// closure's bound is the last change of the orbit's `mu` summed as a
/// geometric series with the measured contraction of the state. A
/// near-repeat that does not contract is not an orbit (a slow drift): the
/// search goes on.
fn attractor(fd: &Foundation) -> Result<(Found, Body)> {
    let p = fd.p;
    let start = p.start();
    let (mut x, mut v) = (start[super::phase::X], start[super::phase::V]);
    let mut state = fd.start(x);
    let mut seen = vec![(x, v, fd.forces_at_start(x, &state))];
    let mut per_period = vec![];
    let run = |x: &mut f64, v: &mut f64, state: &mut Vec<Spring>, per: &mut Vec<f64>| {
        let int_f;
        (*x, *v, int_f, _) = fd.period(*x, *v, state, &[]);
        per.push(int_f / (std::f64::consts::TAU * fd.mean_b));
        (*x, *v, fd.forces_at_start(*x, state))
    };
    let mut n = 0;
    let spent = |budgets: f64| fd.steps_run() as f64 > budgets * MAX_STEPS;
    while n < MAX_CURVED_PERIODS && !(n >= MIN_PERIODS && spent(1.0)) {
        n += 1;
        let now = run(&mut x, &mut v, &mut state, &mut per_period);
        if fd.chattered() {
            return Err(super::chattering());
        }
        let repeat = (1..=MAX_ORBIT.min(seen.len())).find(|&k| distance(&seen[seen.len() - k], &now) <= REPEAT);
        if let Some(k) = repeat {
            let block = |per: &[f64]| per[per.len() - k..].iter().sum::<f64>() / k as f64;
            let (mut mu, mut d) = (block(&per_period), distance(&seen[seen.len() - k], &now));
            let (mut last, mut change, mut rate) = (now.clone(), f64::INFINITY, 1.0);
            for _ in 0..REFINE {
                let mut next = last.clone();
                for _ in 0..k {
                    next = run(&mut x, &mut v, &mut state, &mut per_period);
                }
                n += k;
                let (m, dn) = (block(&per_period), distance(&last, &next));
                (change, rate, mu, d, last) = ((m - mu).abs(), dn / d, m, dn, next);
                if d <= TIGHT || rate >= 1.0 || spent(2.0) {
                    break;
                }
            }
            if rate < 1.0 || d <= TIGHT {
                let closure = if d <= TIGHT { change } else { change * rate / (1.0 - rate) };
                let k = least_period(fd, (x, v, &state), k, d.max(TIGHT));
                if fd.chattered() {
                    return Err(super::chattering());
                }
                return Ok((
                    Found { mu, period: Some(k), periods_run: n, error: closure, standard_error: None },
                    (x, v, state),
                ));
            }
        }
        if seen.len() == MAX_ORBIT {
            seen.remove(0);
        }
        seen.push(now);
    }
    let m = batch_mean(&per_period[per_period.len() / 2..], 10);
    let found = Found {
        mu: m.mean,
        period: None,
        periods_run: n,
        error: m.error_estimate(),
        standard_error: Some(m.standard_error),
    };
    Ok((found, (x, v, state)))
}

/// The attractor of `shape` discretised into about `n` springs, its error
/// estimate that of the discretised problem (the orbit's closure, or the
/// mean's).
pub(crate) fn discretised(shape: &Shape, p: Params, n: usize) -> Result<SystemReport> {
    let springs = discretise(shape, p.amp, n)?;
    let f = attractor(&Foundation::new(p, &springs))?.0;
    Ok(report(&f, f.error, springs.len()))
}

/// The report of an attractor `f` of `springs` springs.
fn report(f: &Found, error_estimate: f64, springs: usize) -> SystemReport {
    SystemReport {
        mu_ratio: f.mu,
        period: f.period,
        standard_error: f.standard_error,
        periods_run: f.periods_run,
        multipliers: None,
        events: vec![],
        error_estimate,
        springs: Some(springs),
    }
}

/// The steady state of a curved body at `c` on the system `p` with at most
/// `springs` springs (module docs).
pub(crate) fn solve(shape: &Shape, p: Params, springs: usize) -> Result<SystemReport> {
    if p.omega == 0.0 {
        return Err(massless());
    }
    let coarse = attractor(&Foundation::new(p, &discretise(shape, p.amp, springs / 2)?))?.0;
    let nodes = discretise(shape, p.amp, springs)?;
    let fine = attractor(&Foundation::new(p, &nodes))?.0;
    let change = fine.mu - coarse.mu;
    // Richardson on the N^-2 error where both are the same orbit.
    let extrapolate = fine.period.is_some() && fine.period == coarse.period;
    let closure = fine.error + coarse.error;
    let mu = if extrapolate { fine.mu + change / 3.0 } else { fine.mu };
    Ok(report(&Found { mu, ..fine }, change.abs() + closure, nodes.len()))
}

/// One period of the attractor of `shape` discretised into about `n`
/// springs (the first of its orbit, or the last run where none was found):
/// its `mu`, period and springs, and at each of `taus` (ascending in
/// `[0, 2 pi)`) the normal and tangential forces over the normal force at
/// the mean indentation (`sum w_i B_i / sum w_i b_i`, `F / sum w_i b_i`).
pub(crate) fn history(shape: &Shape, p: Params, n: usize, taus: &[f64]) -> Result<(SystemReport, Vec<[f64; 2]>)> {
    if p.omega == 0.0 {
        return Err(massless());
    }
    let nodes = discretise(shape, p.amp, n)?;
    let fd = Foundation::new(p, &nodes);
    let (found, (x, v, mut state)) = attractor(&fd)?;
    let tangential = fd.period(x, v, &mut state, taus).3;
    if fd.chattered() {
        return Err(super::chattering());
    }
    let norm: f64 = nodes.iter().map(|(w, b)| w * b.max(0.0)).sum();
    let normal = |tau: f64| nodes.iter().map(|(w, b)| w * (b - p.amp * tau.cos()).max(0.0)).sum::<f64>() / norm;
    let forces = taus.iter().zip(tangential).map(|(&tau, f)| [normal(tau), f / norm]).collect();
    Ok((report(&found, found.error, nodes.len()), forces))
}

fn massless() -> Error {
    Error::param(
        "frequency-ratio",
        0.0,
        "a massless body on a curved contact is not solved: give a frequency ratio > 0",
    )
}
