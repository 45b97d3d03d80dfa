//! A periodic attractor of the flat punch on a system: the period map's
//! fixed point refined by Newton, its Floquet multipliers and its error
//! estimate.

use super::reduced::{map_k, map_k_events, map_k_tangent, Derivatives, Reduced};
use super::springs::Foundation;
use super::{SystemReport, MAX_STEPS};
use nalgebra::{DMatrix, DVector};

/// Whether two states are the same phase and within `tol` (relative to 1 and the state).
pub(super) fn close(a: &Reduced, b: &Reduced, tol: f64) -> bool {
    distance(a, b) <= tol
}

/// The largest difference of two states relative to 1 and the second
/// (infinite where their phases differ).
pub(super) fn distance(a: &Reduced, b: &Reduced) -> f64 {
    if a.0 != b.0 {
        return f64::INFINITY;
    }
    (&a.1 - &b.1).iter().zip(b.1.iter()).map(|(d, x)| d.abs() / (1.0 + x.abs())).fold(0.0, f64::max)
}

/// How closely Newton's orbit must close (relative to 1 and the state, [`distance`]),
/// or to four times the map's rounding where that is more, up to [`ROUNDED`].
const CLOSED: f64 = 1e-10;
/// The most rounding an orbit's closure may be put down to.
const ROUNDED: f64 = 1e-8;

/// The period-`k` orbit through (near) `s`, refined by Newton, with its
/// multipliers, `mu`, events and error estimate; `None` if Newton does not
/// close it (to 1e-10, or to the map's rounding), or if it does not attract
/// (a multiplier of modulus `>= 1 - NEUTRAL`, or none known: not the
/// attractor the iteration tends to).
pub(super) fn orbit(fd: &Foundation, mut s: Reduced, k: usize, run: usize) -> Option<(SystemReport, Reduced)> {
    // Newton moves the body and the stuck springs' forces (`active`): a
    // slipping or free spring's force is the drive's, its row and column of
    // the Jacobian 0.
    let idx = active(&s);
    let n = idx.len();
    let (mut jac, mut grad) = (DMatrix::identity(n, n), DVector::zeros(n));
    let mut exact = false;
    let mut last = f64::INFINITY;
    // An iteration maps k periods once, four times where the Jacobian is
    // taken by differences; none starts that could end beyond the whole
    // search's budget of twice its own steps.
    let iteration = 4.0 * k as f64 * fd.steps_per_period();
    if fd.steps_run() as f64 + iteration > NEWTON_BUDGET {
        return None;
    }
    for _ in 0..12 {
        // Interrupted: no orbit (the search returns the error at its next period).
        if crate::interrupt::check().is_err() {
            return None;
        }
        if fd.steps_run() as f64 + iteration > NEWTON_BUDGET {
            break;
        }
        let base;
        let full;
        (base, full, exact) = derivatives(fd, &s, k);
        (jac, grad) = (full.0.select_rows(&idx).select_columns(&idx), full.1.select_rows(&idx));
        let r = (&base.0 .1 - &s.1).select_rows(&idx);
        let Some(step) = (&jac - DMatrix::identity(n, n)).lu().solve(&(-r)) else { break };
        for (a, &i) in idx.iter().enumerate() {
            s.1[i] += step[a];
        }
        // Converged, or no longer converging: a step not below half the last
        // is the map's own rounding (Newton's steps fall quadratically until
        // then), where more iterations only move the state within it.
        let size = step.amax();
        if step.iter().zip(&idx).all(|(d, &i)| d.abs() <= 4.0 * f64::EPSILON * (1.0 + s.1[i].abs()))
            || size > 0.5 * last
        {
            break;
        }
        last = size;
    }
    let ((end, int_f), events, held_steps) = map_k_events(fd, &s, k);
    // Not closed even to the most rounding allowed, or not attracting: no
    // orbit (and no more maps; an orbit of period d closing after k = m d
    // has the m-th powers of its multipliers).
    if !close(&end, &s, ROUNDED) {
        return None;
    }
    let multipliers = multipliers(&jac, s.1.len())?;
    let neutral = if exact { NEUTRAL_EXACT } else { NEUTRAL };
    if multipliers.iter().any(|[re, im]| re.hypot(*im).powf(1.0 / k as f64) >= 1.0 - neutral) {
        return None;
    }
    // The same map along other steps: where the map's own rounding (a stiff,
    // light body's 1e5 steps a period) exceeds CLOSED, Newton's orbit closes
    // only to it.
    let perturbed = perturbed(fd, &s, k);
    let rounding = perturbed.iter().map(|(e, _)| distance(e, &end)).fold(0.0, f64::max);
    let closed = CLOSED.max(4.0 * rounding).min(ROUNDED);
    let closes = |a: &Reduced, b: &Reduced| close(a, b, closed);
    if !closes(&end, &s) {
        return None;
    }
    if let Some(least) = least_period(fd, &s, k, run, closes) {
        return least;
    }
    let norm = fd.mean_b * std::f64::consts::TAU * k as f64;
    let mu_ratio = int_f / norm;
    let error_estimate =
        orbit_estimate(&s, (&idx, &jac, &grad), (&end, int_f), &perturbed) / norm + ROUNDING * mu_ratio.abs();
    let report = SystemReport {
        mu_ratio,
        period: Some(k),
        standard_error: None,
        periods_run: run,
        multipliers: Some(multipliers),
        events,
        error_estimate,
        springs: None,
        held_steps,
    };
    Some((report, s))
}

/// The orbit of a period `d` dividing `k` where `s` is one (`Some` of
/// [`orbit`]'s answer at `d`), or `None` where `k` is the least period. An
/// orbit of period `d` also closes after `k = m d`; and where its multiplier
/// is near `-1` (a flip), a state Newton left `delta` off it along that
/// direction closes after two periods to `(1 - lambda^2) delta` but after
/// one only to `2 delta`: a return within [`FLIP`] after `d` periods is
/// refined at `d`, and taken where that orbit attracts and lies as near.
/// (An undamped body's period-1 orbit with multiplier -0.99993 was reported
/// as period 2: `data/system-orbits.json`.)
fn least_period(
    fd: &Foundation,
    s: &Reduced,
    k: usize,
    run: usize,
    closes: impl Fn(&Reduced, &Reduced) -> bool,
) -> Option<Option<(SystemReport, Reduced)>> {
    for d in (1..k).filter(|&d| k.is_multiple_of(d)) {
        let back = map_k(fd, s, d).0;
        if closes(&back, s) {
            return Some(orbit(fd, s.clone(), d, run));
        }
        if distance(&back, s) <= FLIP {
            if let Some(found) = orbit(fd, s.clone(), d, run).filter(|(_, at)| distance(at, s) <= FLIP) {
                return Some(Some(found));
            }
        }
    }
    None
}

/// How near a return after fewer periods must come to be refined at that
/// period ([`least_period`]): Newton's orbits close to 1e-8 at most
/// ([`ROUNDED`]), and a multiplier within 2e-5 of -1 is neutral
/// ([`NEUTRAL`]), so a flip's one-period return, twice the state's distance
/// from its orbit, is within 2e-8 / (1 - lambda^2) <= 5e-4.
const FLIP: f64 = 1e-3;

/// An orbit whose multiplier, per period of the drive (the `k`-th root of
/// `P^k`'s), is within this of the unit circle is neutral, not attracting
/// (an undamped body ringing at its own frequency while every spring slips:
/// its state never settles, however close the orbit), where the Jacobian is
/// taken by differences: their error and a Jacobian taken across a grazing
/// event put such multipliers at 1 - 2.5e-7 and 1 - 1.4e-5. An undamped
/// body's orbit at 1 - 6.7e-5 (the 40-digit Jacobian's:
/// `data/system-orbits.json`) attracts, and the search reaches it to 1e-6
/// within 25 periods.
const NEUTRAL: f64 = 2e-5;

/// [`NEUTRAL`] where the Jacobian is the variational equation's, exact up
/// to the rounding of its products (about `sqrt(n) eps` over `n` steps: 1e-13
/// at a stiff body's 7e5 steps a period). A stiff, light, undamped body's
/// orbit contracts by 1 - 8.3e-7 a period (central differences of 1e-5 give
/// 1 - 8.1e-7 and 1 + 8.4e-6, forward ones of 1e-6 gave 1 - 7.7e-5: noise
/// of the map's rounding): it attracts.
const NEUTRAL_EXACT: f64 = 1e-9;

/// Most sampling steps a search and its Newton iterations run in all.
pub(super) const NEWTON_BUDGET: f64 = 2.0 * MAX_STEPS;

/// The rounding of `mu = int f / int B` itself: a few ulps.
pub(super) const ROUNDING: f64 = 8.0 * f64::EPSILON;

/// The eigenvalues `[re, im]` of the period map's Jacobian `jac` on Newton's
/// components of a state of `n` (the others' are 0), at most [`MULTIPLIERS`]
/// of them, largest in modulus first (nalgebra's
/// Schur iteration, capped: it may not converge on a Jacobian taken across a
/// change of the sequence of phases); `None` where unknown. A Jacobian of
/// zeros (a heavily damped body forgets a perturbation within the period)
/// has the multipliers 0: nalgebra's Schur scales by the largest entry and
/// fails on it (such an orbit was answered as "no period" after 4,000
/// periods, its mean 2.7e-14 beyond 1 and refused).
fn multipliers(jac: &DMatrix<f64>, n: usize) -> Option<Vec<[f64; 2]>> {
    let reported = n.min(MULTIPLIERS);
    if jac.iter().all(|&x| x == 0.0) {
        return Some(vec![[0.0, 0.0]; reported]);
    }
    let schur = jac
        .iter()
        .all(|x| x.is_finite())
        .then(|| SCHUR_TOLERANCES.iter().find_map(|&eps| jac.clone().try_schur(eps, 10_000)))??;
    let mut all: Vec<[f64; 2]> = schur.complex_eigenvalues().iter().map(|l| [l.re, l.im]).collect();
    // Largest modulus first; a curved body's many springs add multipliers 0
    // (a slipping spring forgets its force): the first MULTIPLIERS are kept.
    all.sort_by(|a, b| b[0].hypot(b[1]).total_cmp(&a[0].hypot(a[1])));
    // The inactive components' multipliers are 0.
    all.resize(reported.max(all.len()), [0.0, 0.0]);
    all.truncate(reported);
    Some(all)
}

/// A bound on the error of `int f` over the orbit `s` of `k` periods (the
/// map `P^k` with Jacobian `jac`, `int f`'s gradient `grad`, its end `end`
/// and integral `int_f` there; `perturbed` the same along other steps). The exact orbit `s*` is where
/// `P^k(s*) = s*`; near it `s* - s = (I - J)^-1 (P^k(s) - s)`, which moves
/// `int f` by `grad . (s* - s)`: the closure. The map is the exact one up to
/// the rounding of its steps, which over many steps (a stiff, light body
/// takes 1e5 a period) is a random walk: the same map along other steps
/// ([`PERTURBED`]) differs from it by about as much, in `int f` directly and
/// in the residual at `s`. The estimate is the closure plus twice the
/// largest of those differences (`tests/library/system.rs` checks it against
/// the 40-digit references and a stiff system's value).
fn orbit_estimate(
    s: &Reduced,
    (idx, jac, grad): (&[usize], &DMatrix<f64>, &DVector<f64>),
    (end, int_f): (&Reduced, f64),
    perturbed: &[(Reduced, f64)],
) -> f64 {
    let n = jac.nrows();
    let lu = (DMatrix::identity(n, n) - jac).lu();
    let moved = |r: DVector<f64>| lu.solve(&r.select_rows(idx)).map_or(f64::INFINITY, |d| grad.dot(&d).abs());
    let rounding =
        perturbed.iter().map(|(e, f)| if e.0 == s.0 { moved(&e.1 - &s.1) + (f - int_f).abs() } else { f64::INFINITY });
    moved(&end.1 - &s.1) + 2.0 * rounding.fold(0.0, f64::max)
}

/// The components Newton moves: the body's `(x, x')` and the forces of the
/// springs stuck at `tau = 0`.
fn active(s: &Reduced) -> Vec<usize> {
    let stuck = s.0.iter().enumerate().filter(|(_, k)| **k == super::phase::Kind::Stick).map(|(i, _)| 2 + i);
    [0, 1].into_iter().chain(stuck).collect()
}

/// The tolerances of the Schur iteration's deflation, tried in turn: at one
/// ulp it did not converge within 10,000 iterations on the 86 x 86
/// Jacobian of `power:0.05`'s orbit (vbar 0.3, amp 0.5, on kappa 1, Omega
/// 0.5, zeta 0.05, 255 springs), which was then answered as no period after
/// 600 periods; at 64 ulps a multiplier moves by about that much of the
/// Jacobian's norm.
const SCHUR_TOLERANCES: [f64; 2] = [f64::EPSILON, 64.0 * f64::EPSILON];

/// The multipliers reported: the largest in modulus (the flat punch has three).
const MULTIPLIERS: usize = 3;

/// The scales of the sampling steps along which an orbit's map is run again
/// for its rounding ([`orbit_estimate`]).
const PERTURBED: [f64; 3] = [0.9, 0.8, 0.7];

/// `P^k(s)` and `int f` over it along the sampling steps scaled by each of
/// [`PERTURBED`] (their steps counted in `fd`'s budget).
fn perturbed(fd: &Foundation, s: &Reduced, k: usize) -> Vec<(Reduced, f64)> {
    PERTURBED
        .iter()
        .map(|&scale| {
            let other = fd.rescaled(scale);
            let mapped = map_k(&other, s, k);
            fd.count(other.steps_run());
            mapped
        })
        .collect()
}

/// The rounding of `int f` over one period from `s`: twice the largest
/// difference of the map along other steps ([`PERTURBED`]) from its own, as
/// in [`orbit_estimate`]. A mean without period is made of periods rounded
/// so (a body at 1,300 steps a period put `int f` 2.4e-14 beyond its exact
/// value, relative, where the periods' scatter and drift were 3e-16).
pub(super) fn rounding_of_a_period(fd: &Foundation, s: &Reduced) -> f64 {
    let own = map_k(fd, s, 1).1;
    2.0 * perturbed(fd, s, 1).iter().map(|(_, f)| (f - own).abs()).fold(0.0, f64::max)
}

/// `P^k(s)` and `int f` over it, with the Jacobian of `P^k` at `s` and the
/// gradient of `int f`: by the variational equation along the map
/// ([`super::tangent`]), or where the map is not differentiable on the way
/// (a held phase) by differences ([`jacobian`]).
/// Whether the variational equation gave them is the last.
fn derivatives(fd: &Foundation, s: &Reduced, k: usize) -> ((Reduced, f64), Derivatives, bool) {
    match map_k_tangent(fd, s, k) {
        (base, Some(d)) => (base, d, true),
        (base, None) => {
            let d = jacobian(fd, s, k, &base);
            (base, d, false)
        }
    }
}

/// The Jacobian of `P^k` at `s`, and the gradient of `int f` over its `k`
/// periods, by forward differences from `base = P^k(s)` (steps `1e-6 (1 +
/// |s_i|)`, above the map's own rounding, 1e-10 of the state on a stiff
/// body: relative errors about 1e-6, which leave Newton's convergence
/// superlinear and the estimate's `(I - J)^-1` as good).
pub(super) fn jacobian(
    fd: &Foundation,
    s: &Reduced,
    k: usize,
    (p0, f0): &(Reduced, f64),
) -> (DMatrix<f64>, DVector<f64>) {
    let n = s.1.len();
    let mut j = DMatrix::zeros(n, n);
    let mut g = DVector::zeros(n);
    for i in 0..n {
        let h = 1e-6 * (1.0 + s.1[i].abs());
        let mut a = s.clone();
        a.1[i] += h;
        let (pa, fa) = map_k(fd, &a, k);
        j.set_column(i, &((&pa.1 - &p0.1) / h));
        g[i] = (fa - f0) / h;
    }
    (j, g)
}

#[cfg(test)]
mod tests {
    use super::{distance, multipliers, orbit, NEWTON_BUDGET};
    use crate::system::phase::Params;
    use crate::system::reduced::{foundation, map_k, stated_start};
    use nalgebra::{DMatrix, DVector};

    /// A Jacobian of zeros (a heavily damped body's, by differences) has the
    /// multipliers 0, where nalgebra's Schur fails on it; one that is not
    /// finite has none known.
    #[test]
    fn a_zero_jacobian_has_multipliers_zero() {
        assert_eq!(multipliers(&DMatrix::zeros(3, 3), 3), Some(vec![[0.0, 0.0]; 3]));
        assert_eq!(multipliers(&DMatrix::from_element(3, 3, f64::NAN), 3), None);
        let m = multipliers(&DMatrix::from_diagonal(&DVector::from_vec(vec![0.5, -0.25, 0.0])), 3).unwrap();
        assert_eq!(m, [[0.5, 0.0], [-0.25, 0.0], [0.0, 0.0]]);
        // Of many (a curved body's springs), the three largest in modulus, largest first.
        let m = multipliers(&DMatrix::from_diagonal(&DVector::from_vec(vec![0.1, 0.0, -0.7, 0.0, 0.3])), 9).unwrap();
        assert_eq!(m, [[-0.7, 0.0], [0.3, 0.0], [0.1, 0.0]]);
        // A spring slipping at tau = 0 (not among Newton's components): its multiplier 0.
        let m = multipliers(&DMatrix::from_diagonal(&DVector::from_vec(vec![-0.5, 0.25])), 3).unwrap();
        assert_eq!(m, [[-0.5, 0.0], [0.25, 0.0], [0.0, 0.0]]);
    }
    use crate::system::phase::Kind;

    /// Newton starts no iteration that could end beyond the budget of the
    /// whole search ([`NEWTON_BUDGET`]): from the same state, the orbit is
    /// found with the budget unspent and refused with it spent but for
    /// three periods (an iteration is counted as four).
    #[test]
    fn newton_keeps_to_its_budget() {
        let p = Params { kappa: 1.0, omega: 0.5, zeta: 0.05, vhat: 0.3, amp: 0.5, t: 0.0, phase: 0.0 };
        let fd = foundation(p);
        let mut s = stated_start(&fd);
        for _ in 0..12 {
            s = map_k(&fd, &s, 1).0;
        }
        assert!(orbit(&fd, s.clone(), 1, 12).is_some());
        let spent = foundation(p);
        spent.count((NEWTON_BUDGET - 3.0 * spent.steps_per_period()) as u64);
        assert!(orbit(&spent, s, 1, 12).is_none());
    }

    /// Two states' distance is relative to 1 and the second's entries, and
    /// infinite across phases (cargo-mutants: `%` for `/` passed, the
    /// references' states being of order 1): a body 1e6 along, 1 apart, is
    /// 1e-6 apart; forces 0.25 apart at 0.25 are 0.2 apart.
    #[test]
    fn the_distance_is_relative_and_phases_differ_infinitely() {
        let v = |x: [f64; 3]| DVector::from_vec(x.to_vec());
        let a = (vec![Kind::Stick], v([1e6 + 1.0, 0.0, 0.5]));
        let b = (vec![Kind::Stick], v([1e6, 0.0, 0.25]));
        assert_eq!(distance(&a, &b), 0.25 / 1.25);
        let far = (vec![Kind::Stick], v([1e6 + 1.0, 0.0, 0.25]));
        assert_eq!(distance(&far, &b), 1.0 / (1.0 + 1e6));
        assert_eq!(distance(&(vec![Kind::Forward], b.1.clone()), &b), f64::INFINITY);
    }
}
