//! Curved bodies on a system: the foundation as `N` springs with exact events
//! ([`super::springs`]), the attractor of each discretisation found by the
//! one search ([`super::search`]: Newton on the period map, as for the flat
//! punch), at `N/8`, `N/4`, `N/2` and `N` springs.
//!
//! # The discretisation and its error
//! `[0, z_max]` (`z_max` the contact's reach at the amplitude) is cut into
//! pieces at the geometry's breakpoints, at `z = 1`, where a spring leaves
//! permanent contact (`G = 1 - amp`), and at the levels where the sequence
//! of phases a spring goes through in the orbit changes ([`super::bands`],
//! on the attractor of `N/8` springs, at least [`CHANGE_SPRINGS`]). A
//! spring's mean force has a kink or a root at such a level; with cells
//! across it, `R_N` below moved by steps of either sign from level to level
//! (on a paraboloid `+2.5e-5, -5.5e-7, +7.3e-7, -2.2e-7` from 32 to 256
//! springs), with the cuts it falls by 16 to 20 a level. Each piece `[a,
//! b]` gets cells in proportion to its rise in the level `G` at the
//! coarsest level (at least one), twice as many at each finer level, equal
//! in `theta` with `G = G(a) + (G(b) - G(a))(1 - cos theta)/2` (which
//! absorbs the square-root behaviour of the springs' means at a piece's
//! ends); a cell is one spring at the level of its midpoint, weighted by its
//! length in `z` (the stiffness density is 1: the springs in contact at the
//! mean indentation have the contact's stiffness). Cells in the level, not
//! in `z`, follow a profile that rises steeply near the centre
//! (`power:0.05`, which cells in `z` left at an error of 7e-4 up to 1,024
//! springs). A flat piece is one spring. The force and the mean normal force
//! are the same rule's sums, so `mu_N` is a ratio of two midpoint rules, its
//! error falling like `N^-2`. Where the phases change at many levels, a
//! body has more springs than `N` (one cell a piece at the coarsest level).
//!
//! The answer ([`extrapolate`]) is the Richardson value `R_N = mu_N + (mu_N -
//! mu_{N/2})/3` where `N/8` to `N` show that asymptote (changes of one sign,
//! the ratio of the last two near 4), with the estimate `2 max(|R_N -
//! R_{N/2}|/4, |R_{N/2} - R_{N/4}|/64)` (`R_N` falling at least like
//! `N^-2` beyond, about like `N^-4` as observed); outside the asymptote
//! `mu_N` with the envelope of its changes carried to `N` at the `N^-2`
//! rate. Against the answer at 4,096 springs on 280 random cases
//! (paraboloids, cones, power laws, flat tips; 89 with a drive in the
//! sliding direction; kappa 0.1 to 31, Omega 0.1 to 1.6, zeta 0.02 to 1)
//! it bounds the error at 32 to 1,024 springs wherever the error exceeds
//! ten times that answer's estimate (1,193 answers, the least 1.2 times
//! the error); at 256 springs it is 10.6 times the error at the median (a
//! tenth below 4.2, a tenth above 30), at 1,024 springs 8.9 times; on 62
//! cases drawn afresh, 9.2 times at 256 springs (a tenth above 25), no
//! miss. Each adds the orbits'
//! estimates (`attractor`); without a period the answer is `mu_N`'s
//! long-time mean, whose error estimate (standard error and drift) is added.

use super::bands::Body;
use super::springs::{Foundation, Record};
use super::{Params, SystemReport};
use crate::error::{Error, Result};
use crate::shape::Shape;

/// Springs of a curved body's finer discretisation by default.
pub const DEFAULT_SPRINGS: usize = 256;
/// Most springs of a curved body's finer discretisation.
pub const MAX_SPRINGS: usize = 1 << 14;
/// Fewest springs of a curved body's finest discretisation: with 16 and
/// fewer the coarsest levels (4 springs and fewer) were at times the same
/// springs, and an estimate of 1.3e-13 was given for an error of 8.6e-2.
pub const MIN_SPRINGS: usize = 32;
/// Most periods run from the start for one discretisation before the answer
/// is "no period"; fewer (at least 20) where they take more than 2·10^7
/// sampling steps, and as many steps again may refine an orbit found.
pub const MAX_CURVED_PERIODS: usize = 600;

/// The springs `(w_i, b_i)` of `shape` at the amplitude `amp`, about `n`
/// midpoints in the level `G` (module docs).
pub(crate) fn discretise(shape: &Shape, amp: f64, n: usize) -> Result<Vec<(f64, f64)>> {
    cells(shape, amp, base(n), LEVELS, &[])
}

/// The springs of `shape` at `p`, about `n`: [`discretise`]'s pieces cut
/// again at the levels where a spring's phases change (module docs).
pub(crate) fn banded(shape: &Shape, p: Params, n: usize) -> Result<Vec<(f64, f64)>> {
    cells(shape, p.amp, base(n), LEVELS, &changes(shape, p, n)?)
}

/// Cells of the coarsest of four levels for `n` springs at the finest.
fn base(n: usize) -> usize {
    (n / LEVELS).max(1)
}

/// The finest level's cells over the coarsest's.
const LEVELS: usize = 8;
/// Changes of phases nearer than this (relative to the levels' range) to the
/// centre cut nothing: where `amp -> 1` the springs there touch for an
/// instant, and changes found within 1e-8 of it came and went with the last
/// ulp of `amp` (a jump of 3.8e-9 in `mu` on 64 springs).
const CENTRE: f64 = 1e-6;
/// Fewest springs whose attractor places the changes of phases.
const CHANGE_SPRINGS: usize = 32;
/// Springs of no weight that look for the changes of phases, in equal steps of the level.
const PROBES: usize = 512;

/// The levels `b` where the sequence of phases of a spring changes, on the
/// attractor of `n/8` springs (at least [`CHANGE_SPRINGS`]); none where that
/// has no period or the body is one spring.
fn changes(shape: &Shape, p: Params, n: usize) -> Result<Vec<f64>> {
    let springs = cells(shape, p.amp, base(n).max(CHANGE_SPRINGS), 1, &[])?;
    if springs.len() == 1 {
        return Ok(vec![]);
    }
    let fd = Foundation::new(p, &springs);
    let (found, body) = attractor(&fd)?;
    match found.period {
        Some(k) => super::bands::changes(&fd, &body, k, -p.amp, 1.0, PROBES),
        None => Ok(vec![]),
    }
}

/// The springs of `base` cells in all (each piece's share in the level,
/// rounded, at least one), each piece's cells times `factor`; the pieces
/// cut at the levels `kinks` too.
fn cells(shape: &Shape, amp: f64, base: usize, factor: usize, kinks: &[f64]) -> Result<Vec<(f64, f64)>> {
    let n = base;
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
    cuts.dedup();
    let levels: Vec<f64> = cuts.iter().map(|&z| c.equivalent_profile(z)).collect();
    let total = levels[levels.len() - 1] - levels[0];
    // A cut whose rise in `G` from the last one kept is below half a cell (a
    // level that tends to a cut, as `G = 1 - amp` to the centre where `amp ->
    // 1`) is dropped, the reach taking the place of the one before it: no
    // thin piece appears there, and the springs are continuous in `amp`. A
    // flat piece (no rise) is kept: it is one spring.
    let min = 0.5 * total / n as f64;
    let mut kept: Vec<(f64, f64)> = vec![(cuts[0], levels[0])];
    for (i, (&z, &g)) in cuts.iter().zip(&levels).enumerate().skip(1) {
        let inner = kept.len() > 1;
        let Some(last) = kept.last_mut() else { continue };
        let rise = g - last.1;
        if rise == 0.0 || rise >= min || (i == cuts.len() - 1 && !inner) {
            kept.push((z, g));
        } else if i == cuts.len() - 1 {
            *last = (z, g);
        }
    }
    // A change of phases cuts its piece however thin (module docs), unless
    // within its bisection's resolution of a cut already there, or within
    // [`CENTRE`] of the centre.
    let (first, last) = (levels[0] + CENTRE * total, levels[levels.len() - 1]);
    for &b in kinks {
        let g = 1.0 - b;
        let gap = |cut: &(f64, f64)| (cut.1 - g).abs() <= super::bands::SAME * total;
        if first < g && g < last && !kept.iter().any(gap) {
            kept.push((c.level(g), g));
            kept.sort_by(|x, y| x.1.total_cmp(&y.1));
        }
    }
    let pieces: Vec<[f64; 4]> = kept.windows(2).map(|p| [p[0].0, p[1].0, p[0].1, p[1].1]).collect();
    let mut springs: Vec<(f64, f64)> = vec![];
    let mut push = |w: f64, b: f64| match springs.last_mut() {
        Some(last) if last.1 == b => last.0 += w,
        _ => springs.push((w, b)),
    };
    for &[za, zb, ga, gb] in &pieces {
        if gb == ga {
            push(zb - za, 1.0 - gb);
            continue;
        }
        let cells = ((n as f64 * (gb - ga) / total).round() as usize).max(1) * factor;
        let h = std::f64::consts::PI / cells as f64;
        let level_at = |theta: f64| ga + 0.5 * (gb - ga) * (1.0 - theta.cos());
        let z_at = |j: usize| match j {
            0 => za,
            j if j == cells => zb,
            j => c.level(level_at(j as f64 * h)).clamp(za, zb),
        };
        let mut lo = za;
        for j in 0..cells {
            let hi = z_at(j + 1);
            push(hi - lo, 1.0 - level_at((j as f64 + 0.5) * h));
            lo = hi;
        }
    }
    Ok(springs)
}

/// The attractor of one discretisation.
#[derive(Debug, Clone, Copy)]
struct Found {
    mu: f64,
    /// `None`: no period within the budget (then `mu` is a mean).
    period: Option<usize>,
    periods_run: usize,
    /// The orbit's error estimate, or the mean's where there is no period.
    error: f64,
    /// The mean's standard error where there is no period.
    standard_error: Option<f64>,
    /// Steps held (`SystemReport::held_steps`).
    held: u64,
}

/// The attractor of one discretisation by the one search
/// ([`super::search::attractor`], within [`MAX_CURVED_PERIODS`]), and the
/// body `(x, x')` and its springs at `tau = 0` of its first period.
fn attractor(fd: &Foundation) -> Result<(Found, Body)> {
    let (r, at) = super::search::attractor(fd, MAX_CURVED_PERIODS)?;
    let found = Found {
        mu: r.mu_ratio,
        period: r.period,
        periods_run: r.periods_run,
        error: r.error_estimate,
        standard_error: r.standard_error,
        held: r.held_steps,
    };
    Ok((found, super::reduced::expand(fd, &at)))
}

/// The attractor of `shape` discretised into about `n` springs, its error
/// estimate that of the discretised problem (the orbit's closure, or the
/// mean's).
pub(crate) fn discretised(shape: &Shape, p: Params, n: usize) -> Result<SystemReport> {
    let springs = banded(shape, p, n)?;
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
        held_steps: f.held,
    }
}

/// The steady state of a curved body at `c` on the system `p` with at most
/// `springs` springs (module docs).
pub(crate) fn solve(shape: &Shape, p: Params, springs: usize) -> Result<SystemReport> {
    if p.omega == 0.0 {
        return Err(massless());
    }
    let kinks = changes(shape, p, springs)?;
    let level = |factor: usize| -> Result<(Found, usize)> {
        let nodes = cells(shape, p.amp, base(springs), factor, &kinks)?;
        Ok((attractor(&Foundation::new(p, &nodes))?.0, nodes.len()))
    };
    let (fine, count) = level(LEVELS)?;
    let coarser = [level(1)?.0, level(2)?.0, level(4)?.0];
    let (mu, estimate) = extrapolate(&coarser, &fine);
    Ok(report(&Found { mu, ..fine }, estimate, count))
}

/// The answer and its error estimate from the attractors of `N/8`, `N/4`,
/// `N/2` (`coarser`) and `N` springs (module docs): Richardson's value
/// `R_N = mu_N + (mu_N - mu_{N/2})/3` where the four are the same orbit and
/// their changes fall like `N^-2` (one sign, and the ratio of the last two
/// within [`ASYMPTOTIC`]), its estimate `2 max(|R_N - R_{N/2}|/4,
/// |R_{N/2} - R_{N/4}|/64)`; otherwise `mu_N` with the envelope of its
/// changes carried to `N` at the `N^-2` rate, `max(|d_N|, |d_{N/2}|/4,
/// |d_{N/4}|/16)` (`d_N = mu_N - mu_{N/2}`): were they at that rate, the
/// error of `mu_N` would be a third of it. Each adds the orbits' closures
/// and rounding (or the means' estimates).
fn extrapolate(coarser: &[Found; 3], f: &Found) -> (f64, f64) {
    let [e, q, h] = coarser;
    let closure = e.error + q.error + h.error + f.error;
    let (d0, d1, d2) = (q.mu - e.mu, h.mu - q.mu, f.mu - h.mu);
    let same = f.period.is_some() && coarser.iter().all(|c| c.period == f.period);
    // One sign: `d1` and `d2` share one where their ratio is in `ASYMPTOTIC`.
    let monotone = d0 != 0.0 && d0.signum() == d1.signum();
    if same && monotone && ASYMPTOTIC.contains(&(d1 / d2)) {
        let (rf, rh, rq) = (f.mu + d2 / 3.0, h.mu + d1 / 3.0, q.mu + d0 / 3.0);
        let envelope = ((rf - rh).abs() / 4.0).max((rh - rq).abs() / 64.0);
        (rf, 2.0 * envelope + closure)
    } else {
        let envelope = d2.abs().max(d1.abs() / 4.0).max(d0.abs() / 16.0);
        (f.mu, envelope + closure)
    }
}

/// The ratios of successive changes read as the `N^-2` asymptote (4).
const ASYMPTOTIC: std::ops::RangeInclusive<f64> = 2.5..=6.5;

/// One period of the attractor of `shape` discretised into about `n`
/// springs (the first of its orbit, or the last run where none was found):
/// its `mu`, period and springs, and at each of `taus` (ascending in
/// `[0, 2 pi)`) the normal and tangential forces over the normal force at
/// the mean indentation (`sum w_i B_i / sum w_i b_i`, `F / sum w_i b_i`),
/// the body's position and velocity, and that normal force.
pub(crate) fn history(shape: &Shape, p: Params, n: usize, taus: &[f64]) -> Result<(SystemReport, Vec<[f64; 5]>)> {
    if p.omega == 0.0 {
        return Err(massless());
    }
    let nodes = banded(shape, p, n)?;
    let fd = Foundation::new(p, &nodes);
    let (found, (x, v, mut state)) = attractor(&fd)?;
    let mut rec = Record { samples: taus, ..Record::default() };
    fd.period(x, v, &mut state, &mut rec);
    let tangential = rec.forces;
    if fd.chattered() {
        return Err(super::chattering());
    }
    let norm: f64 = nodes.iter().map(|(w, b)| w * b.max(0.0)).sum();
    let normal = |tau: f64| nodes.iter().map(|(w, b)| w * (b - p.amp * tau.cos()).max(0.0)).sum::<f64>() / norm;
    let forces = taus.iter().zip(tangential).map(|(&tau, [f, x, v])| [normal(tau), f / norm, x, v, norm]).collect();
    Ok((report(&found, found.error, nodes.len()), forces))
}

fn massless() -> Error {
    Error::param(
        "frequency-ratio",
        0.0,
        "a massless body on a curved contact is not solved: give a frequency ratio > 0",
    )
}

#[cfg(test)]
mod tests {
    use super::{extrapolate, Found};

    fn found(mu: f64, error: f64, period: Option<usize>) -> Found {
        Found { mu, period, periods_run: 0, error, standard_error: None, held: 0 }
    }

    /// Changes that fall by 4 exactly are the `N^-2` asymptote: Richardson's
    /// value is the limit, and the estimate the envelope of its own changes
    /// (here none) plus every level's closure.
    #[test]
    fn the_asymptote_gives_the_limit_and_the_closures() {
        let (limit, c) = (0.5, 1.0e-3);
        let levels = [limit + 64.0 * c, limit + 16.0 * c, limit + 4.0 * c, limit + c];
        let coarser = [levels[0], levels[1], levels[2]].map(|mu| found(mu, 1e-9, Some(1)));
        let (mu, estimate) = extrapolate(&coarser, &found(levels[3], 2e-9, Some(1)));
        assert!((mu - limit).abs() < 1e-15, "{mu}");
        assert!((estimate - 5e-9).abs() < 1e-15, "{estimate:e}");
    }

    /// Outside the asymptote (an orbit of another period, or changes of two
    /// signs) the answer is the finest level, its estimate the envelope
    /// `max(|d_N|, |d_{N/2}|/4, |d_{N/4}|/16)` plus the closures.
    #[test]
    fn outside_the_asymptote_the_envelope_of_the_changes() {
        let cases = [
            // d = 1.6e-2, 8e-4, 1e-4 (ratios 20 and 8): the first change rules.
            ([0.5, 0.516, 0.5168, 0.5169], [Some(1); 4], 1e-3),
            // d = -1e-3, 2e-3, -1e-4: the middle one.
            ([0.5, 0.499, 0.501, 0.5009], [Some(1); 4], 5e-4),
            // Changes of 4 exactly (each carried to N is 3e-3), the coarsest of period 2.
            ([0.564, 0.516, 0.504, 0.501], [Some(2), Some(1), Some(1), Some(1)], 3e-3),
            // The last two fall by 4, the first is of the other sign (either way).
            ([0.5, 0.532, 0.528, 0.527], [Some(1); 4], 2e-3),
            ([0.5, 0.49, 0.494, 0.495], [Some(1); 4], 1e-3),
            // No first change: not one sign.
            ([0.5, 0.5, 0.504, 0.505], [Some(1); 4], 1e-3),
        ];
        for (mus, periods, envelope) in cases {
            let coarser = [0, 1, 2].map(|i| found(mus[i], 1e-12, periods[i]));
            let (mu, estimate) = extrapolate(&coarser, &found(mus[3], 1e-12, periods[3]));
            assert_eq!(mu, mus[3]);
            assert!((estimate - envelope - 4e-12).abs() < 1e-14 * envelope.max(1.0) + 1e-15, "{mus:?}: {estimate:e}");
        }
    }
}
