//! The attractor's search, for any springs (the flat punch's one, a curved
//! body's many): from the stated start the period map is iterated until its
//! state (each spring's phase, the body and the stuck springs' forces)
//! repeats after `k <= MAX_ORBIT` periods to [`NEAR`]; that orbit is then
//! refined by Newton on `P^k(s) = s` (`super::orbit`), or, for a state of
//! more than [`MAX_NEWTON`] components (thousands of springs, whose dense
//! Jacobian would cost more than the periods), by the map's own
//! contraction ([`contracted`]). Where nothing closes
//! within the periods and steps allowed, Newton is tried once more from the
//! last state, and else the answer is no period: the mean of the last half's
//! per-period values with its standard error and drift (`super::mean`) and
//! the rounding of a period.

use super::mean::batch_mean;
use super::orbit::{close, distance, orbit, rounding_of_a_period, ROUNDING};
use super::reduced::{map_k, stated_start, Reduced};
use super::springs::Foundation;
use super::{chattering, SystemReport, MAX_ORBIT, MAX_STEPS, MIN_PERIODS};
use crate::error::Result;

/// How close a return must come for the search to hand it to Newton, which
/// with the variational Jacobian closes it to rounding in four or five
/// iterations from there (each about a period's work). A return this near
/// that Newton cannot close (the sequence of phases still changing, or a
/// slow quasi-periodic drift) costs an attempt ([`NEWTON_ATTEMPTS`]), and
/// the next must come [`TIGHTEN`] times nearer. A loose threshold hands
/// Newton an orbit periods earlier than a tight one; what that costs is in
/// `fricosc bench`'s table on a system.
const NEAR: f64 = 1e-1;

/// How much nearer a return must come after an attempt Newton could not close.
const TIGHTEN: f64 = 0.1;

/// Most near-repeats refined by Newton before the search goes on without.
const NEWTON_ATTEMPTS: usize = 4;

/// Most components of a state refined by Newton (`2 + N`: 512 springs);
/// beyond, an orbit is refined by the map's contraction ([`contracted`]).
const MAX_NEWTON: usize = 2 + 512;
/// A repeat handed to [`contracted`] (relative to 1 and the state).
const REPEAT: f64 = 1e-9;
/// Orbits closed beyond this are exact to rounding ([`contracted`]).
const TIGHT: f64 = 1e-13;
/// Most orbits run to refine one repeat ([`contracted`]).
const REFINE: usize = 200;

/// The attractor of the springs `fd` from the stated start within
/// `max_periods` (and, once `MIN_PERIODS` are run, `MAX_STEPS` sampling
/// steps, Newton's among them), and the state at `tau = 0` of its first period.
pub(crate) fn attractor(fd: &Foundation, max_periods: usize) -> Result<(SystemReport, Reduced)> {
    let mut s = stated_start(fd);
    let mut seen: Vec<Reduced> = vec![s.clone()];
    let mut per_period = vec![];
    let (mut attempts, mut near) = (0, NEAR);
    for n in 1..=max_periods {
        if n > MIN_PERIODS && fd.steps_run() as f64 > MAX_STEPS {
            break;
        }
        crate::interrupt::check()?;
        let (next, int_f) = map_k(fd, &s, 1);
        if fd.chattered() {
            return Err(chattering());
        }
        per_period.push(int_f);
        s = next;
        let back = |k: usize| &seen[seen.len() - k];
        // A near-repeat that Newton cannot close is not an orbit yet: look
        // on for a nearer one, at most NEWTON_ATTEMPTS times.
        if let Some(k) =
            (1..=MAX_ORBIT.min(n)).find(|&k| close(back(k), &s, near)).filter(|_| attempts < NEWTON_ATTEMPTS)
        {
            let found = if s.1.len() <= MAX_NEWTON {
                attempts += 1;
                near = TIGHTEN * distance(back(k), &s);
                orbit(fd, s.clone(), k, n)
            } else if distance(back(k), &s) <= REPEAT {
                contracted(fd, &s, k, n)?
            } else {
                None
            };
            if let Some(found) = found {
                return if fd.chattered() { Err(chattering()) } else { Ok(found) };
            }
        }
        if seen.len() > MAX_ORBIT {
            seen.remove(0);
        }
        seen.push(s.clone());
    }
    // An orbit that contracts slowly (a multiplier near 1) need not repeat
    // within the periods run: Newton from the last state, at period 1 first
    // (the cheapest; a rotating transient may come closest after a few
    // periods), then at the period whose return came closest.
    let (last, periods) = (seen.len() - 1, per_period.len());
    let gap = |k: usize| distance(&seen[last - k], &s);
    let closest = (1..=MAX_ORBIT.min(last)).min_by(|&a, &b| gap(a).total_cmp(&gap(b)));
    let mut tried = vec![1];
    tried.extend(closest.filter(|&k| k != 1));
    for k in tried.into_iter().filter(|&k| k <= last && s.1.len() <= MAX_NEWTON) {
        if let Some(found) = orbit(fd, s.clone(), k, periods) {
            return if fd.chattered() { Err(chattering()) } else { Ok(found) };
        }
    }
    crate::interrupt::check()?;
    let mean_b = fd.mean_b * std::f64::consts::TAU;
    let tail: Vec<f64> = per_period[periods / 2..].iter().map(|x| x / mean_b).collect();
    let m = batch_mean(&tail, 10);
    let rounding = rounding_of_a_period(fd, &s) / mean_b + ROUNDING * m.mean.abs();
    let report = SystemReport {
        mu_ratio: m.mean,
        period: None,
        standard_error: Some(m.standard_error),
        periods_run: periods,
        multipliers: None,
        events: vec![],
        error_estimate: m.error_estimate() + rounding,
        springs: None,
        held_steps: fd.held(),
    };
    Ok((report, s))
}

/// The period-`k` orbit through (near) `s` by the map's own contraction:
/// orbit after orbit (at most [`REFINE`], within two budgets of steps)
/// until the state closes to [`TIGHT`]; the closure's bound is the last
/// change of the orbit's `mu` summed as a geometric series with the measured
/// contraction `r` of the state, doubled, plus an ulp of the bound a step.
/// The rate is that of the last orbit, below the multiplier where it still
/// rises towards it: doubling `r/(1 - r)` covers a multiplier up to
/// `2r/(1 + r)` (0.982 for a rate of 0.965). `None` where
/// the state does not contract (a slow drift, not an orbit). No multipliers
/// or events are reported (a state of thousands of springs).
fn contracted(fd: &Foundation, s: &Reduced, k: usize, run: usize) -> Result<Option<(SystemReport, Reduced)>> {
    let norm = std::f64::consts::TAU * fd.mean_b * k as f64;
    let block = |s: &Reduced| {
        let (end, int_f) = map_k(fd, s, k);
        (end, int_f / norm)
    };
    let (mut last, mut mu) = block(s);
    let mut n = run + k;
    let (mut d, mut change, mut rate) = (distance(s, &last), f64::INFINITY, 1.0);
    for _ in 0..REFINE {
        crate::interrupt::check()?;
        let (next, m) = block(&last);
        n += k;
        let dn = distance(&last, &next);
        (change, rate, mu, d, last) = ((m - mu).abs(), dn / d, m, dn, next);
        if d <= TIGHT || rate >= 1.0 || fd.steps_run() as f64 > 2.0 * MAX_STEPS {
            break;
        }
    }
    if !(rate < 1.0 || d <= TIGHT) {
        return Ok(None);
    }
    let rounding = f64::EPSILON * fd.steps_run() as f64 / n as f64;
    let closure = rounding + if d <= TIGHT { change } else { 2.0 * change * rate / (1.0 - rate) };
    // The least period: the first divisor of k after which the state is back
    // within ten times its closure.
    let closed = 10.0 * d.max(TIGHT);
    let mut at = last.clone();
    let period = (1..k)
        .find(|&p| {
            at = map_k(fd, &at, 1).0;
            k.is_multiple_of(p) && distance(&last, &at) <= closed
        })
        .unwrap_or(k);
    let report = SystemReport {
        mu_ratio: mu,
        period: Some(period),
        standard_error: None,
        periods_run: n,
        multipliers: None,
        events: vec![],
        error_estimate: closure,
        springs: None,
        held_steps: fd.held(),
    };
    Ok(Some((report, last)))
}

#[cfg(test)]
mod tests {
    use super::{contracted, orbit, Foundation, REFINE};
    use crate::system::phase::Params;
    use crate::system::reduced::{map_k, stated_start, Reduced};

    /// A paraboloid's 64 springs at `vhat = 0.3`, `amp = 0.5` on the system
    /// `(kappa, Omega, zeta)`, and the state 40 periods from the stated start.
    fn forty_periods_on(kappa: f64, omega: f64, zeta: f64) -> (Foundation, Reduced) {
        let p = Params { kappa, omega, zeta, vhat: 0.3, amp: 0.5, t: 0.0, phase: 0.0 };
        let springs = crate::system::springs(&crate::shape::Shape::parabolic(), p.amp, 64).unwrap();
        let fd = Foundation::new(p, &springs);
        let mut s = stated_start(&fd);
        for _ in 0..40 {
            s = map_k(&fd, &s, 1).0;
        }
        (fd, s)
    }

    /// The map's contraction (the refinement beyond `MAX_NEWTON` springs)
    /// closes the same orbit as Newton, on a paraboloid's 64 springs from a
    /// state 40 periods along: the same period, `mu` within the two
    /// estimates, and the state it returns back on itself after a period.
    /// A fast contraction closes to rounding (estimate below 1e-12); slow
    /// ones (a heavily damped body's real multiplier near 1) stop after
    /// `REFINE` orbits with the geometric tail of `mu`'s changes, which must
    /// bound the gap to Newton's orbit and stay within 10 times it (the tail
    /// at the last measured rate alone fell 1e-4 short of the gap at zeta =
    /// 20). It stops once closed (the fast one in two orbits). `periods_run`
    /// counts every period mapped: `REFINE` and the first
    /// where the contraction is slow; else as many as the steps run in the
    /// contraction are periods of the closed orbit's steps.
    #[test]
    fn the_contraction_closes_newtons_orbit() {
        for (kappa, omega, zeta, slow) in
            [(1.0, 0.5, 0.05, false), (0.05, 1.0, 5.0, true), (0.02, 0.5, 10.0, true), (0.01, 0.3, 20.0, true)]
        {
            let (fd, s) = forty_periods_on(kappa, omega, zeta);
            let (newton, at) = orbit(&fd, s.clone(), 1, 40).expect("Newton's orbit");
            let before = fd.steps_run();
            let (mine, end) = contracted(&fd, &s, 1, 40).unwrap().expect("the contraction's orbit");
            let during = fd.steps_run() - before;
            let one = fd.steps_run();
            let back = map_k(&fd, &end, 1).0;
            let one = fd.steps_run() - one;
            let periods = if slow { 1 + REFINE } else { (during / one) as usize };
            assert_eq!((during % one * u64::from(!slow), mine.periods_run), (0, 40 + periods), "{zeta}: {mine:?}");
            assert_eq!((mine.period, newton.period), (Some(1), Some(1)));
            let gap = (mine.mu_ratio - newton.mu_ratio).abs();
            let (est, sum) = (mine.error_estimate, mine.error_estimate + newton.error_estimate);
            assert!(gap <= sum, "{zeta}: {gap:e} {mine:?} {newton:?}");
            if slow {
                assert!(gap > 1e-13 && est <= 10.0 * gap, "{zeta}: {gap:e} {mine:?}");
            } else {
                assert!(est > 0.0 && est < 1e-12 && super::distance(&end, &at) < 1e-9, "{mine:?}");
                assert!(mine.periods_run <= 40 + 4, "closed, yet run on: {mine:?}");
                assert!(super::distance(&back, &end) < 1e-12);
            }
        }
    }

    /// An undamped body's state that drifts (a multiplier of modulus 1, the
    /// distance between returns growing at times) is no orbit: the
    /// contraction gives none, and the search goes on.
    #[test]
    fn a_drift_is_not_contracted_into_an_orbit() {
        let (fd, s) = forty_periods_on(1.0, 0.5, 0.0);
        let found = contracted(&fd, &s, 1, 40).unwrap();
        assert!(found.is_none(), "{:?}", found.map(|f| f.0));
    }

    /// The contraction keeps to its step budget (twice `MAX_STEPS`, the
    /// search's included): a slow contraction charged to within ten and a
    /// half orbits of it stops after eleven (not `REFINE`), its estimate
    /// still bounding the gap to Newton's orbit.
    #[test]
    fn the_contraction_keeps_to_its_step_budget() {
        let (fd, s) = forty_periods_on(0.01, 0.3, 20.0);
        let newton = orbit(&fd, s.clone(), 1, 40).expect("Newton's orbit").0;
        let one = fd.steps_run();
        map_k(&fd, &s, 1);
        let one = (fd.steps_run() - one) as f64;
        fd.count((2.0 * super::MAX_STEPS - 10.5 * one - fd.steps_run() as f64) as u64);
        let mine = contracted(&fd, &s, 1, 40).unwrap().expect("the contraction's orbit").0;
        assert!((50..=53).contains(&mine.periods_run), "{mine:?}");
        let gap = (mine.mu_ratio - newton.mu_ratio).abs();
        assert!(gap <= mine.error_estimate + newton.error_estimate, "{gap:e} {mine:?}");
    }
}
