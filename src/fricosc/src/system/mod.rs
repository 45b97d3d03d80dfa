//! Friction on a tribometer with mass and stiffness (Part II of the seed's
//! series): the flat punch's body, of mass `m`, is pulled by the drive
//! through a system spring `K` with a dashpot beside it, and holds the
//! contact spring `kx` (README: the system's mass and stiffness). In the
//! seed's units (`tau = omega t`, lengths in `l = mu0 kz u0/kx`, forces in
//! `mu0 kz u0`):
//!
//! `Omega^2 x'' = kappa (X_d - x) - 2 zeta sqrt(kappa) Omega (x' - X_d') - f`,
//!
//! `kappa = K/kx`, `Omega = omega / sqrt(kx/m)`, `zeta = c / (2 sqrt(K m))`,
//! `X_d = vhat tau + T sin(tau + phase)`, `f` the stop operator of `x` with
//! the bound `(1 - amp cos tau)_+`.
//!
//! # The answer
//! From the stated start (the body at the drive's position with its
//! velocity, the spring relaxed) the period map is iterated until its state
//! `(x - 2 pi vhat n, x', f)` and phase repeat after `k` periods (to
//! `REPEAT`); that orbit is then refined by Newton on `P^k(s) = s` (the
//! Jacobian by central differences of the exact map), its stability read
//! from the eigenvalues of that Jacobian (the Floquet multipliers), and `mu`
//! is `int f / int B` over its `k` periods. Where nothing repeats within
//! [`MAX_PERIODS`], the answer is no period: the mean of the last half's
//! per-period values with its standard error (of batches of 10 periods) and
//! an error estimate that also counts the drift of a transient not yet
//! settled (`Mean::error_estimate`).
//!
//! A massless body (`Omega = 0`) is the stiff problem with the drive scaled
//! by `kappa/(1 + kappa)` (the springs in series): answered by the stiff
//! solver exactly.

mod curved;
mod period;
mod phase;
mod springs;

pub use curved::{DEFAULT_SPRINGS, MAX_CURVED_PERIODS, MAX_SPRINGS};
pub use period::SystemEvent;
pub use phase::Kind;

use crate::conditions::Conditions;
use crate::error::{Error, Result};
use nalgebra::{Matrix3, Vector3};
use period::Phases;
use phase::{Params, State, INT_F, V, X, Y0};

/// The system's parameters (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct System {
    /// `kappa = K/kx`, the system's over the contact's tangential stiffness (> 0).
    pub stiffness: f64,
    /// `Omega`, the excitation over the contact's natural frequency `sqrt(kx/m)`
    /// (`>= 0`; 0 is a massless body).
    pub frequency_ratio: f64,
    /// `zeta`, the system's damping ratio (`>= 0`).
    pub damping: f64,
    /// A curved body's springs (the finer of the two discretisations; the
    /// flat punch is one spring).
    pub springs: usize,
}

impl System {
    /// A checked system.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] unless `stiffness` is finite and `> 0`, and
    /// the others finite and `>= 0` (each at most 1e6).
    pub fn new(stiffness: f64, frequency_ratio: f64, damping: f64) -> Result<System> {
        for (name, v) in [("system-stiffness", stiffness), ("frequency-ratio", frequency_ratio), ("damping", damping)] {
            if !(v.is_finite() && (0.0..=1e6).contains(&v)) {
                return Err(Error::param(name, v, "must be finite, >= 0 and <= 1e6"));
            }
        }
        if stiffness == 0.0 {
            return Err(Error::param(
                "system-stiffness",
                0.0,
                "must be > 0 (without a system spring nothing drives the body)",
            ));
        }
        Ok(System { stiffness, frequency_ratio, damping, springs: DEFAULT_SPRINGS })
    }

    /// The system with a curved body discretised into `springs` springs
    /// (compared with half as many; more springs: a smaller error, `N^-2`, at
    /// a cost about proportional to `N`).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] unless `springs` is in `4..=`[`MAX_SPRINGS`].
    pub fn with_springs(self, springs: usize) -> Result<System> {
        if !(4..=MAX_SPRINGS).contains(&springs) {
            return Err(Error::param("springs", springs as f64, "must be in 4..=16384"));
        }
        Ok(System { springs, ..self })
    }
}

/// Two states repeat where they differ by at most this (relative to 1 and the state).
pub(crate) const REPEAT: f64 = 1e-9;
/// Most periods run from the start before the answer is "no period" (the flat punch).
pub const MAX_PERIODS: usize = 4000;
/// Most sampling steps run from the start (about two seconds); fewer
/// periods than [`MAX_PERIODS`] where a period takes many (at least
/// [`MIN_PERIODS`]).
pub(crate) const MAX_STEPS: f64 = 2e7;
/// Fewest periods run before a search may end for its step budget.
pub(crate) const MIN_PERIODS: usize = 20;
/// Most sampling steps a period of the drive may take: a body whose fastest
/// time scale (its stick frequency, or its damping rate) is shorter is
/// refused, by name, before any work.
pub const MAX_STEPS_PER_PERIOD: f64 = 1e6;

/// The body's fastest time scale resolvable in [`MAX_STEPS_PER_PERIOD`]
/// steps, with the contact's springs all stuck (`contact` their stiffness).
fn check_resolvable(p: &Params, contact: f64) -> Result<()> {
    let a = p.generator_of(phase::Linear { x: contact, ..phase::Linear::default() });
    let steps = std::f64::consts::TAU / springs::sampling_step(&a);
    if steps > MAX_STEPS_PER_PERIOD {
        let reason = format!(
            "with stiffness {} and damping {} the body's fastest time scale needs {steps:.1e} sampling steps a \
             period (at most 1e6): the body is too light or too damped for the drive (a lighter one tends to the \
             massless body, frequency-ratio 0, the flat punch's exact limit)",
            crate::error::Amount(p.kappa),
            crate::error::Amount(p.zeta)
        );
        return Err(Error::param("frequency-ratio", p.omega, &reason));
    }
    Ok(())
}

/// The system spring builds a force of 1 (the Coulomb bound without
/// oscillation) only after about `1/(2 pi kappa vhat)` periods of the drive;
/// where that exceeds a quarter of the periods run (`limit`), the attractor
/// cannot be reached and the system is refused by name (a sliding drive; at
/// `vhat = 0` the answer is the relaxed one, 0).
fn check_settles(p: &Params, limit: usize) -> Result<()> {
    let periods = 1.0 / (std::f64::consts::TAU * p.kappa * p.vhat);
    if p.vhat > 0.0 && periods > limit as f64 / 4.0 {
        let reason = format!(
            "the system spring pulls the body into steady sliding only after about {} periods of the drive \
             (vhat {}); fricosc runs at most {limit}",
            crate::error::Amount(periods.round()),
            crate::error::Amount(p.vhat)
        );
        return Err(Error::param("system-stiffness", p.kappa, &reason));
    }
    Ok(())
}

/// Longest period of an attractor looked for.
pub(crate) const MAX_ORBIT: usize = 8;
/// Most near-repeats refined by Newton before the search goes on without.
const NEWTON_ATTEMPTS: usize = 3;

/// The flat punch's steady state on a system.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SystemReport {
    /// `mu_macro/mu0`: over the attractor's period, or the long-time mean.
    pub mu_ratio: f64,
    /// The attractor's period in periods of the drive (`None`: none found
    /// within [`MAX_PERIODS`]; then `mu_ratio` is a mean).
    pub period: Option<usize>,
    /// The standard error of the mean where there is no period.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub standard_error: Option<f64>,
    /// Periods run from the start before the orbit repeated (or all).
    pub periods_run: usize,
    /// The Floquet multipliers `[re, im]` of the orbit (stable: all inside the unit circle).
    pub multipliers: Vec<[f64; 2]>,
    /// The events of the orbit's first period (the flat punch).
    pub events: Vec<SystemEvent>,
    /// The error estimate of `mu_ratio`: a curved body's (its springs' discretisation and the orbit's
    /// closure), or a mean's without period (twice its standard error plus three times the drift
    /// between the halves of the periods averaged). `None`: the flat punch's exact orbit.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub error_estimate: Option<f64>,
    /// The springs of a curved body's finest discretisation.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub springs: Option<usize>,
}

impl SystemReport {
    /// `mu_ratio` as a [`crate::Ratio`] (its reduction `1 - mu_ratio`).
    #[must_use]
    pub fn ratio(&self) -> crate::Ratio {
        crate::Ratio { mu_ratio: self.mu_ratio, reduction: 1.0 - self.mu_ratio }
    }
}

/// The reduced state of the period map: `(x, x', f)` at `tau = 0` and the phase.
pub(crate) type Reduced = (Kind, Vector3<f64>);

fn reduce(p: &Params, kind: Kind, z: &State) -> Reduced {
    (kind, Vector3::new(z[X], z[V], p.force(kind, z)))
}

fn expand(p: &Params, (kind, s): &Reduced) -> State {
    let mut z = p.start();
    (z[X], z[V]) = (s[0], s[1]);
    z[Y0] = s[0] - s[2];
    if *kind != phase::Kind::Stick {
        z[Y0] = z[X];
    }
    z
}

/// `k` periods of the map from `s`: the state after them and `int f` over them.
fn map_k(ph: &Phases, s: &Reduced, k: usize) -> (Reduced, f64) {
    let (mut kind, mut z) = (s.0, expand(&ph.p, s));
    let mut int_f = 0.0;
    for _ in 0..k {
        (kind, z, _) = ph.period(kind, z);
        int_f += z[INT_F];
    }
    (reduce(&ph.p, kind, &z), int_f)
}

/// The steady state of `shape` at `c` on the system `sys`: the flat punch
/// exactly, a curved body by its springs (the foundation as
/// [`System::springs`] springs, each with its exact events, and as half as
/// many: the Richardson value, with an error estimate).
///
/// ```
/// use fricosc::system::{solve, System};
/// use fricosc::{Conditions, Shape};
///
/// let sys = System::new(1.0, 0.5, 0.05)?;
/// let r = solve(&Shape::flat(), &Conditions::vbar(0.3, 0.5)?, &sys)?;
/// assert_eq!(r.period, Some(1));
/// assert!(r.mu_ratio > 0.0 && r.mu_ratio < 1.0);
/// # Ok::<(), fricosc::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for bad inputs, and for a massless body
/// (`frequency_ratio` 0) on a curved contact.
pub fn solve(shape: &crate::Shape, c: &Conditions, sys: &System) -> Result<SystemReport> {
    let mut r = if shape.contact().single_spring() {
        attractor(c, sys)?.0
    } else {
        curved::solve(shape, params(shape, c, sys)?, sys.springs)?
    };
    // Every spring's force is within its bound, so |mu| <= 1: a rounding (or
    // an extrapolation) beyond is put back onto it.
    r.mu_ratio = r.mu_ratio.clamp(-1.0, 1.0);
    Ok(r)
}

/// The springs `(weight, 1 - G)` of `shape`'s discretisation into about
/// `n` (the `curved` module's; the flat punch's one).
pub(crate) fn springs(shape: &crate::Shape, amp: f64, n: usize) -> Result<Vec<(f64, f64)>> {
    curved::discretise(shape, amp, n)
}

/// One period of a curved body's attractor on `sys` ([`System::springs`]
/// springs, `curved::history`): the report and the normal and tangential
/// forces at `taus`.
pub(crate) fn curved_history(
    shape: &crate::Shape,
    c: &Conditions,
    sys: &System,
    taus: &[f64],
) -> Result<(SystemReport, Vec<[f64; 2]>)> {
    curved::history(shape, params(shape, c, sys)?, sys.springs, taus)
}

/// The checked parameters of a curved body's problem.
fn params(shape: &crate::Shape, c: &Conditions, sys: &System) -> Result<Params> {
    shape.check_amp(c.amp())?;
    let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
    let p = Params {
        kappa: sys.stiffness,
        omega: sys.frequency_ratio,
        zeta: sys.damping,
        vhat: c.as_vhat(),
        amp: c.amp(),
        t,
        phase,
    };
    if p.omega > 0.0 {
        check_resolvable(&p, springs(shape, p.amp, 4)?.iter().map(|s| s.0).sum())?;
        check_settles(&p, MAX_CURVED_PERIODS)?;
    }
    Ok(p)
}

/// The steady state of `shape` discretised into about `springs` springs
/// (midpoints of equal cells, `curved` module docs), each spring's events
/// exact: the problem a code with that many springs solves, its answer
/// without an error estimate (the attractor found as [`solve`] finds it,
/// without Newton).
///
/// # Errors
/// As [`solve`]; [`Error::InvalidParameter`] for `springs` 0 or above 2^16.
pub fn solve_discretised(shape: &crate::Shape, c: &Conditions, sys: &System, springs: usize) -> Result<SystemReport> {
    if !(1..=1 << 16).contains(&springs) {
        return Err(Error::param("springs", springs as f64, "must be in 1..=65536"));
    }
    curved::discretised(shape, params(shape, c, sys)?, springs)
}

/// The contact force at `taus` (ascending, in `[0, 2 pi)`) over one period
/// from the state `s` at `tau = 0` ([`attractor`]'s).
pub(crate) fn sample((ph, s): &(Phases, Reduced), taus: &[f64]) -> Vec<f64> {
    ph.sampled(s.0, expand(&ph.p, s), taus).3
}

/// The attractor from the stated start, and (for a body with mass) the
/// phases and the state at `tau = 0` of its first period.
pub(crate) fn attractor(c: &Conditions, sys: &System) -> Result<(SystemReport, Option<(Phases, Reduced)>)> {
    let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
    let (vhat, amp, kappa) = (c.as_vhat(), c.amp(), sys.stiffness);
    if sys.frequency_ratio == 0.0 {
        let scale = kappa / (1.0 + kappa);
        let stiff = Conditions::vhat(vhat * scale, amp)?.with_tangential(t * scale, phase)?.with_tol(c.tol())?;
        let r = crate::shape::Shape::flat().ratio(&stiff)?;
        let report = SystemReport {
            mu_ratio: r.mu_ratio,
            period: Some(1),
            standard_error: None,
            periods_run: 0,
            multipliers: vec![],
            events: vec![],
            error_estimate: None,
            springs: None,
        };
        return Ok((report, None));
    }
    let p = Params { kappa, omega: sys.frequency_ratio, zeta: sys.damping, vhat, amp, t, phase };
    check_resolvable(&p, 1.0)?;
    check_settles(&p, MAX_PERIODS)?;
    let ph = Phases::new(p);
    let start = p.start();
    let mut s = reduce(&p, if amp < 1.0 { Kind::Stick } else { Kind::Free }, &start);
    let mut seen: Vec<Reduced> = vec![s];
    let mut per_period = vec![];
    let mut attempts = 0;
    // At most MAX_STEPS sampling steps in all (a fast, undamped body takes many a period).
    let periods = MAX_PERIODS.min((MAX_STEPS / ph.steps_per_period()).max(MIN_PERIODS as f64) as usize);
    for n in 1..=periods {
        let (next, int_f) = map_k(&ph, &s, 1);
        if ph.chattered() {
            return Err(chattering());
        }
        per_period.push(int_f);
        s = next;
        let back = |k: usize| &seen[seen.len() - k];
        // A near-repeat that Newton cannot close is not an orbit (a slow
        // quasi-periodic drift): look on, at most NEWTON_ATTEMPTS times.
        if let Some(k) =
            (1..=MAX_ORBIT.min(n)).find(|&k| close(back(k), &s, REPEAT)).filter(|_| attempts < NEWTON_ATTEMPTS)
        {
            attempts += 1;
            if let Some((r, at)) = orbit(&ph, s, k, n) {
                return if ph.chattered() { Err(chattering()) } else { Ok((r, Some((ph, at)))) };
            }
        }
        seen.push(s);
    }
    let mean_b = crate::flat::mean_normal(amp) * std::f64::consts::TAU;
    let tail: Vec<f64> = per_period[periods / 2..].iter().map(|x| x / mean_b).collect();
    let m = batch_mean(&tail, 10);
    let report = SystemReport {
        mu_ratio: m.mean,
        period: None,
        standard_error: Some(m.standard_error),
        periods_run: periods,
        multipliers: vec![],
        events: vec![],
        error_estimate: Some(m.error_estimate()),
        springs: None,
    };
    Ok((report, Some((ph, s))))
}

/// The refusal of a solve whose period ran out of events (a defect of the
/// phase machine, never a property of the inputs).
pub(crate) fn chattering() -> Error {
    Error::Internal {
        what: format!(
            "a phase chattered: more than {} events in a row (a spring) within one sampling step",
            period::MAX_EVENTS_IN_A_STEP
        ),
    }
}

/// Whether two states are the same phase and within `tol` (relative to 1 and the state).
fn close(a: &Reduced, b: &Reduced, tol: f64) -> bool {
    a.0 == b.0 && (a.1 - b.1).iter().zip(b.1.iter()).all(|(d, x)| d.abs() <= tol * (1.0 + x.abs()))
}

/// How closely Newton's orbit must close (the same measure as [`REPEAT`]).
const CLOSED: f64 = 1e-10;

/// Fewest batches a mean's estimate is made of ([`batch_mean`]): two halves of four.
const MIN_BATCHES: usize = 8;

/// The long-time mean of a response without period.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Mean {
    pub mean: f64,
    /// The standard error of `mean` from the batches' scatter.
    pub standard_error: f64,
    /// `|m2 - m1|`, the means of the batches' later and earlier halves: a
    /// transient not yet settled shows here, not in the scatter.
    pub drift: f64,
}

impl Mean {
    /// The error estimate: twice the standard error plus three drifts.
    /// A transient decaying like `c/t` leaves the mean over `[T/2, T]` at
    /// `2 ln 2 c/T` from its limit, while its halves' means are
    /// `4 ln(3/2) c/T` and `4 ln(4/3) c/T`: a drift of `0.47 c/T`, so three
    /// drifts cover it, and any faster decay. A stationary response's drift
    /// is about 1.6 standard errors, so there the estimate is about 7 of them.
    pub fn error_estimate(&self) -> f64 {
        2.0 * self.standard_error + 3.0 * self.drift
    }
}

/// The mean of `xs` from batches of `size`: its standard error and drift
/// ([`Mean`]). A short tail (a stiff body's 20 periods) is cut into batches
/// small enough that there are at least [`MIN_BATCHES`]: with one batch the
/// scatter and the drift would both be 0, an estimate of 0 for a mean that
/// has not settled.
pub(crate) fn batch_mean(xs: &[f64], size: usize) -> Mean {
    let avg = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let size = size.min(xs.len() / MIN_BATCHES).max(1);
    let batches: Vec<f64> = xs.chunks_exact(size).map(avg).collect();
    let n = batches.len() as f64;
    let mean = avg(&batches);
    let var = batches.iter().map(|b| (b - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    let (early, late) = batches.split_at(batches.len() / 2);
    let drift = if early.is_empty() { 0.0 } else { (avg(late) - avg(early)).abs() };
    Mean { mean, standard_error: (var / n).sqrt(), drift }
}

/// The period-`k` orbit through (near) `s`, refined by Newton, with its
/// multipliers, `mu` and events; `None` if Newton does not close it to 1e-10.
fn orbit(ph: &Phases, mut s: Reduced, k: usize, run: usize) -> Option<(SystemReport, Reduced)> {
    let residual = |s: &Reduced| map_k(ph, s, k).0 .1 - s.1;
    let mut jac = Matrix3::identity();
    let mut last = f64::INFINITY;
    for _ in 0..12 {
        jac = jacobian(ph, &s, k);
        let r = residual(&s);
        let Some(step) = (jac - Matrix3::identity()).lu().solve(&(-r)) else { break };
        s.1 += step;
        // Converged, or no longer converging: a step not below half the last
        // is the map's own rounding (Newton's steps fall quadratically until
        // then), where more iterations only move the state within it.
        let size = step.amax();
        if step.iter().zip(s.1.iter()).all(|(d, x)| d.abs() <= 4.0 * f64::EPSILON * (1.0 + x.abs()))
            || size > 0.5 * last
        {
            break;
        }
        last = size;
    }
    let (end, int_f) = map_k(ph, &s, k);
    let closes = |a: &Reduced, b: &Reduced| close(a, b, CLOSED);
    if !closes(&end, &s) {
        return None;
    }
    // The least period: an orbit of period d also closes after k = m d.
    if let Some(d) = (1..k).find(|&d| k.is_multiple_of(d) && closes(&map_k(ph, &s, d).0, &s)) {
        return orbit(ph, s, d, run);
    }
    // nalgebra's Schur iteration, capped (it may not converge on a Jacobian
    // taken across a change of the sequence of phases).
    let schur = jac.iter().all(|x| x.is_finite()).then(|| jac.try_schur(f64::EPSILON, 10_000)).flatten();
    let multipliers = schur.map_or(vec![], |s| s.complex_eigenvalues().iter().map(|l| [l.re, l.im]).collect());
    let events = ph.period(s.0, expand(&ph.p, &s)).2;
    let mean_b = crate::flat::mean_normal(ph.p.amp) * std::f64::consts::TAU * k as f64;
    let report = SystemReport {
        mu_ratio: int_f / mean_b,
        period: Some(k),
        standard_error: None,
        periods_run: run,
        multipliers,
        events,
        error_estimate: None,
        springs: None,
    };
    Some((report, s))
}

/// The Jacobian of `P^k` at `s` by central differences (steps `1e-6 (1 + |s_i|)`).
fn jacobian(ph: &Phases, s: &Reduced, k: usize) -> Matrix3<f64> {
    let mut j = Matrix3::zeros();
    for i in 0..3 {
        let h = 1e-6 * (1.0 + s.1[i].abs());
        let (mut a, mut b) = (*s, *s);
        a.1[i] += h;
        b.1[i] -= h;
        let d = (map_k(ph, &a, k).0 .1 - map_k(ph, &b, k).0 .1) / (2.0 * h);
        j.set_column(i, &d);
    }
    j
}

#[cfg(test)]
mod tests {
    use super::batch_mean;
    use super::phase::{series, Kind, Linear, Params, State, ONE};

    /// The series a sampling step is advanced by against nalgebra's Pade
    /// exponential of the whole generator: `exp(a h) z`, and `h phi_1(a0 h) u`
    /// (`u` the constant state's column, `a0` the generator without it) as
    /// `exp(a h) e_1 - e_1`. Observed: 5.6e-17 relative to the state at most.
    #[test]
    fn the_step_series_meet_the_pade_exponential() {
        let p = Params { kappa: 1.5, omega: 0.4, zeta: 0.05, vhat: 0.3, amp: 0.7, t: 0.8, phase: 0.6 };
        let close = |x: &State, y: &State| (x - y).amax() <= 5e-16 * (1.0 + y.amax());
        for f in [p.linear(Kind::Stick), p.linear(Kind::Forward), Linear { x: 3.0, one: 0.7, cos: -0.2, y0: 0.0 }] {
            let a = p.generator_of(f);
            let h = super::springs::sampling_step(&a);
            let pade = (a * h).exp();
            let z = p.start();
            assert!(close(&series(&a, &z, h, 0).unwrap(), &(pade * z)), "{f:?}");
            let mut a0 = a;
            a0.set_column(ONE, &State::zeros());
            let mut want = pade.column(ONE).into_owned();
            want[ONE] -= 1.0;
            assert!(close(&series(&a0, &(a.column(ONE) * h), h, 1).unwrap(), &want), "{f:?}");
        }
    }

    /// A transient decaying like `1/t` over the tail `[1000, 2000)`: the
    /// mean is 2.94 drifts from its limit (derivation at `Mean::error_estimate`),
    /// within the estimate; with two drifts it would not be.
    #[test]
    fn the_estimate_covers_a_transient_decaying_like_one_over_t() {
        let xs: Vec<f64> = (1000..2000).map(|t| 1.0 - 1e-3 / t as f64).collect();
        let m = batch_mean(&xs, 10);
        let error = 1.0 - m.mean;
        assert!(error <= m.error_estimate() && error > 2.9 * m.drift, "{m:?}");
    }

    /// A short tail (10 periods, as a stiff body runs 20): batches small
    /// enough for a scatter and a drift. With batches of 10 it was one batch,
    /// and the estimate 0 for a mean 3e-4 from its limit.
    #[test]
    fn a_short_tail_still_has_an_estimate() {
        let xs: Vec<f64> = (10..20).map(|t| 1.0 - 1e-3 / t as f64).collect();
        let m = batch_mean(&xs, 10);
        let error = 1.0 - m.mean;
        assert!(error > 0.0 && error <= m.error_estimate(), "{m:?}");
    }

    /// A stationary response (a fixed pseudo-random sequence): the estimate
    /// covers the mean's error and is a few standard errors, not more.
    #[test]
    fn a_stationary_response_is_a_few_standard_errors() {
        let mut s = 12345u64;
        let xs: Vec<f64> = (0..2000)
            .map(|_| {
                s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                0.5 + ((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 1e-3
            })
            .collect();
        let m = batch_mean(&xs, 10);
        assert!((m.mean - 0.5).abs() <= m.error_estimate(), "{m:?}");
        assert!(m.error_estimate() <= 12.0 * m.standard_error && m.standard_error < 1e-5, "{m:?}");
    }
}
