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
//! The contact is a set of springs (`springs.rs`: the flat punch one, a
//! curved body's foundation many), one period map for all. From the stated
//! start (the body at the drive's position with its velocity, the springs
//! relaxed) the map is iterated until its state (each spring's phase,
//! `(x - 2 pi vhat n, x', f_1, ..., f_N)`) repeats after `k` periods
//! (`search.rs`); that orbit is then refined by Newton on `P^k(s) = s` (the
//! Jacobian by the variational equation along the exact map, `tangent.rs`),
//! its stability read from the eigenvalues of that Jacobian (the Floquet
//! multipliers), and `mu` is `int F / int B` over its `k` periods. Where nothing repeats within
//! [`MAX_PERIODS`], the answer is no period: the mean of the last half's
//! per-period values with its standard error (of batches of 10 periods) and
//! an error estimate that also counts the drift of a transient not yet
//! settled (`Mean::error_estimate`) and the rounding of a period.
//!
//! A massless body (`Omega = 0`) is the stiff problem with the drive scaled
//! by `kappa/(1 + kappa)` (the springs in series): answered by the stiff
//! solver exactly.

mod bands;
mod critical;
mod curved;
mod events;
mod index;
mod mean;
mod orbit;
mod phase;
mod reduced;
mod report;
mod search;
mod springs;
mod tangent;

pub use critical::critical_vbar;
pub use curved::{DEFAULT_SPRINGS, MAX_CURVED_PERIODS, MAX_SPRINGS, MIN_SPRINGS};
pub use events::SystemEvent;
pub use phase::Kind;
pub use report::SystemReport;

use crate::conditions::Conditions;
use crate::error::{Error, Result};
use orbit::ROUNDING;
use phase::Params;
pub(crate) use reduced::{map_k, sample, stated_start, Reduced};
use springs::Foundation;

/// The system's parameters (module docs), checked where built
/// ([`System::new`], [`System::with_springs`]): the fields are private, so a
/// system in hand is always a valid one.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct System {
    stiffness: f64,
    frequency_ratio: f64,
    damping: f64,
    springs: usize,
}

impl System {
    /// A checked system.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] unless `stiffness` is finite and `> 0`, and
    /// the others finite and `>= 0` (each at most 1e6).
    pub fn new(stiffness: f64, frequency_ratio: f64, damping: f64) -> Result<System> {
        if !(stiffness > 0.0 && stiffness <= 1e6) {
            return Err(Error::param(
                "system-stiffness",
                stiffness,
                "must be > 0 and <= 1e6 (without a system spring nothing drives the body)",
            ));
        }
        for (name, v) in [("frequency-ratio", frequency_ratio), ("damping", damping)] {
            if !(v.is_finite() && (0.0..=1e6).contains(&v)) {
                return Err(Error::param(name, v, "must be finite, >= 0 and <= 1e6"));
            }
        }
        Ok(System { stiffness, frequency_ratio, damping, springs: DEFAULT_SPRINGS })
    }

    /// The system with a curved body discretised into `springs` springs
    /// (compared with half as many; more springs: a smaller error, `N^-2`, at
    /// a cost about proportional to `N`).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] unless `springs` is in
    /// [`MIN_SPRINGS`]`..=`[`MAX_SPRINGS`].
    pub fn with_springs(self, springs: usize) -> Result<System> {
        if !(MIN_SPRINGS..=MAX_SPRINGS).contains(&springs) {
            return Err(Error::param(
                "springs",
                springs as f64,
                "must be in 32..=16384 (with fewer, the discretisation's error cannot be bounded from its levels)",
            ));
        }
        Ok(System { springs, ..self })
    }

    /// `kappa = K/kx`, the system's over the contact's tangential stiffness (> 0).
    #[must_use]
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// `Omega`, the excitation over the contact's natural frequency
    /// `sqrt(kx/m)` (`>= 0`; 0 is a massless body).
    #[must_use]
    pub fn frequency_ratio(&self) -> f64 {
        self.frequency_ratio
    }

    /// `zeta`, the system's damping ratio (`>= 0`).
    #[must_use]
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// A curved body's springs (the finer of the two discretisations; the
    /// flat punch is one spring).
    #[must_use]
    pub fn springs(&self) -> usize {
        self.springs
    }
}

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
    let finite = a.iter().all(|x| x.is_finite());
    let steps = if finite { std::f64::consts::TAU / springs::sampling_step(&a) } else { f64::INFINITY };
    // Where `Omega^2` underflows (`Omega` below about 1e-162) the generator
    // is not finite: refused as any body too light to resolve.
    if steps > MAX_STEPS_PER_PERIOD {
        let needs = if steps.is_finite() { format!("{steps:.1e}") } else { "far more than 1e6".into() };
        let reason = format!(
            "with stiffness {} and damping {} the body's fastest time scale needs {needs} sampling steps a \
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
        let about =
            if periods < 1e15 { format!("about {}", periods.round() as u64) } else { "far more than 1e15".into() };
        let reason = format!(
            "the system spring pulls the body into steady sliding only after {about} periods of the drive \
             (vhat {}), more than a quarter of the {limit} periods run (the rest must hold the attractor): \
             a stiffer system or a faster drive settles sooner",
            crate::error::Amount(p.vhat)
        );
        return Err(Error::param("system-stiffness", p.kappa, &reason));
    }
    Ok(())
}

/// Longest period of an attractor looked for.
pub(crate) const MAX_ORBIT: usize = 8;

impl System {
    /// The phases' parameters of this system under the drive of `c`.
    fn params(&self, c: &Conditions) -> Params {
        let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
        let (kappa, omega, zeta) = (self.stiffness, self.frequency_ratio, self.damping);
        Params { kappa, omega, zeta, vhat: c.as_vhat(), amp: c.amp(), t, phase }
    }

    /// The body at `tau` (position `x`, velocity `v`) under the drive of `c`:
    /// the drive's lead `X_d - x` and the system's force `kappa (X_d - x) +
    /// 2 zeta sqrt(kappa) Omega (X_d' - v)` (`X_d = vhat tau + T sin(tau + phase)`).
    pub(crate) fn body(&self, c: &Conditions, tau: f64, x: f64, v: f64) -> (f64, f64) {
        let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
        let (s, co) = (tau + phase).sin_cos();
        let lead = c.as_vhat() * tau + t * s - x;
        let damp = phase::dashpot(self.stiffness, self.frequency_ratio, self.damping);
        (lead, self.stiffness * lead + damp * (c.as_vhat() + t * co - v))
    }
}

/// The steady state of `shape` at `c` on the system `sys`: the flat punch
/// exactly, a curved body by its springs (the foundation as
/// [`System::springs`] springs, each with its exact events, and as fewer:
/// the extrapolated value, with an error estimate). The way in is
/// [`crate::Shape::report`] with [`Conditions::with_system`].
///
/// # Errors
/// [`Error::InvalidParameter`] for bad inputs, and for a massless body
/// (`frequency_ratio` 0) on a curved contact.
pub(crate) fn solve(shape: &crate::Shape, c: &Conditions, sys: &System) -> Result<SystemReport> {
    let still = c.tangential().is_none_or(|(t, _)| t == 0.0);
    if c.amp() == 0.0 && still {
        return Ok(no_oscillation());
    }
    if c.as_vhat() == 0.0 && still {
        return at_rest(shape, c);
    }
    let mut r = if shape.contact().single_spring() {
        attractor(c, sys)?.0
    } else {
        curved::solve(shape, params(shape, c, sys)?, sys.springs)?
    };
    within_bounds(&mut r)?;
    Ok(r)
}

/// Nothing oscillates (`amp = 0`, no tangential drive): `mu = 1` exactly,
/// as without a system (README: definitions). It is the limit `amp -> 0` at
/// a fixed `vbar` (the reduction is `O(amp)`), and Coulomb's law for a
/// contact that slides steadily; a drive at rest (`vhat = 0`) is the limit
/// `vbar -> 0+` of sliding, as everywhere.
fn no_oscillation() -> SystemReport {
    SystemReport {
        mu_ratio: 1.0,
        period: Some(1),
        standard_error: None,
        periods_run: 0,
        multipliers: None,
        events: vec![],
        error_estimate: 0.0,
        springs: None,
        held_steps: 0,
    }
}

/// A drive at rest (`vhat = 0`) under normal oscillation: the limit `vbar
/// -> 0+` of steady sliding, as without a system (README: definitions), the
/// stiff `mu_static = N_min/N_mean`. As the drive creeps, every spring's
/// force ratchets up to its smallest bound and the body's own motion dies
/// with the velocity (the answer's distance from it is `O(vbar)`:
/// `tests/library/system.rs`). The relaxed start itself would stay at 0.
fn at_rest(shape: &crate::Shape, c: &Conditions) -> Result<SystemReport> {
    let e = shape.evaluate(&Conditions::vbar(0.0, c.amp())?.with_tol(c.tol())?)?;
    Ok(SystemReport { mu_ratio: e.ratio.mu_ratio, error_estimate: e.error_estimate, ..no_oscillation() })
}

/// Every spring's force is within its bound, so `|mu| <= 1`: beyond it
/// within the answer's estimate (a rounding, an extrapolation) `mu` is put
/// back onto it; further beyond, or not a number, is a defect of the solver.
fn within_bounds(r: &mut SystemReport) -> Result<()> {
    let excess = r.mu_ratio.abs() - 1.0;
    let allowed = r.error_estimate + ROUNDING;
    if excess.is_nan() || excess > allowed || !allowed.is_finite() {
        return Err(Error::Internal {
            what: format!("mu {:e} with estimate {:e}: beyond |mu| <= 1", r.mu_ratio, r.error_estimate),
        });
    }
    if excess > 0.0 {
        r.mu_ratio = r.mu_ratio.signum();
    }
    Ok(())
}

/// The springs `(weight, 1 - G)` of `shape`'s discretisation into about
/// `n` (the `curved` module's; the flat punch's one).
pub(crate) fn springs(shape: &crate::Shape, amp: f64, n: usize) -> Result<Vec<(f64, f64)>> {
    curved::discretise(shape, amp, n)
}

/// The springs `(weight, 1 - G)` of `shape` on `sys` at `c`: those the
/// system's answer at [`System::springs`] has at its finest level (the
/// `curved` module's, cut where a spring's phases change; the flat punch's one).
pub(crate) fn banded_springs(shape: &crate::Shape, c: &Conditions, sys: &System) -> Result<Vec<(f64, f64)>> {
    curved::banded(shape, params(shape, c, sys)?, sys.springs)
}

/// One period of a curved body's attractor on `sys` ([`System::springs`]
/// springs, `curved::history`): the report and at `taus` the normal and
/// tangential forces, the body's position and velocity, and the forces' unit.
pub(crate) fn curved_history(
    shape: &crate::Shape,
    c: &Conditions,
    sys: &System,
    taus: &[f64],
) -> Result<(SystemReport, Vec<[f64; 5]>)> {
    curved::history(shape, params(shape, c, sys)?, sys.springs, taus)
}

/// The checked parameters of a curved body's problem.
fn params(shape: &crate::Shape, c: &Conditions, sys: &System) -> Result<Params> {
    shape.check_amp(c.amp())?;
    let p = sys.params(c);
    if p.omega > 0.0 {
        check_resolvable(&p, springs(shape, p.amp, 4)?.iter().map(|s| s.0).sum())?;
        check_settles(&p, MAX_CURVED_PERIODS)?;
    }
    Ok(p)
}

/// The steady state of `shape` discretised into about `springs` springs
/// (midpoints of equal cells, `curved` module docs), each spring's events
/// exact, on the system of `c` ([`Conditions::with_system`]): the problem a
/// code with that many springs solves, its answer without an error estimate
/// (the attractor found as [`crate::Shape::report`] finds it).
///
/// # Errors
/// As [`crate::Shape::report`]; [`Error::InvalidParameter`] for conditions
/// without a system, or `springs` 0 or above 2^16.
pub fn solve_discretised(shape: &crate::Shape, c: &Conditions, springs: usize) -> Result<SystemReport> {
    let Some(sys) = c.system() else {
        return Err(Error::param("system-stiffness", 0.0, "a discretised body is solved on a system"));
    };
    if !(1..=1 << 16).contains(&springs) {
        return Err(Error::param("springs", springs as f64, "must be in 1..=65536"));
    }
    curved::discretised(shape, params(shape, c, sys)?, springs)
}

/// The attractor from the stated start, and (for a body with mass) the
/// phases and the state at `tau = 0` of its first period.
pub(crate) fn attractor(c: &Conditions, sys: &System) -> Result<(SystemReport, Option<(Foundation, Reduced)>)> {
    if sys.frequency_ratio == 0.0 {
        let r = crate::shape::Shape::flat().evaluate(&massless(c, sys)?)?;
        let report = SystemReport {
            mu_ratio: r.ratio.mu_ratio,
            period: Some(1),
            standard_error: None,
            periods_run: 0,
            multipliers: None,
            events: vec![],
            error_estimate: r.error_estimate,
            springs: None,
            held_steps: 0,
        };
        return Ok((report, None));
    }
    let p = sys.params(c);
    check_resolvable(&p, 1.0)?;
    check_settles(&p, MAX_PERIODS)?;
    let fd = reduced::foundation(p);
    let (report, at) = search::attractor(&fd, MAX_PERIODS)?;
    Ok((report, Some((fd, at))))
}

/// A massless body's problem (`Omega = 0`): the stiff one with the drive
/// scaled by `kappa/(1 + kappa)` (the contact and system springs in series).
pub(crate) fn massless(c: &Conditions, sys: &System) -> Result<Conditions> {
    let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
    let scale = sys.stiffness / (1.0 + sys.stiffness);
    Conditions::vhat(c.as_vhat() * scale, c.amp())?.with_tangential(t * scale, phase)?.with_tol(c.tol())
}

/// The flat punch's `mu` of each of the first `n` periods from the stated
/// start on `sys` (normal oscillation, `c`'s velocity and amplitude): what a
/// run of `k` periods that averages its last reports is the `k`-th, so a
/// table from too short a run meets this transient, not the attractor.
/// Empty for a massless body (no transient of its own).
pub(crate) fn transient(c: &Conditions, sys: &System, n: usize) -> Result<Vec<f64>> {
    if sys.frequency_ratio == 0.0 || c.amp() == 0.0 {
        return Ok(vec![]);
    }
    let p = sys.params(c);
    check_resolvable(&p, 1.0)?;
    let fd = reduced::foundation(p);
    let mean_b = fd.mean_b * std::f64::consts::TAU;
    let mut s = stated_start(&fd);
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        crate::interrupt::check()?;
        let (next, int_f) = map_k(&fd, &s, 1);
        if fd.chattered() {
            return Err(chattering());
        }
        out.push(int_f / mean_b);
        s = next;
    }
    Ok(out)
}

/// The refusal of a solve whose period ran out of events (a defect of the
/// phase machine, never a property of the inputs).
pub(crate) fn chattering() -> Error {
    Error::Internal {
        what: format!(
            "a phase chattered: more than {} events in a row (a spring) within one sampling step",
            events::MAX_EVENTS_IN_A_STEP
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::{attractor, within_bounds, Conditions, System, SystemReport, MAX_STEPS};

    /// The search and Newton keep to their budget: a stiff undamped body
    /// (7e5 sampling steps a period). With a Jacobian by differences the
    /// closest return (after 8 periods) was refined first, 56 periods an
    /// iteration, and the whole ran 3.85 budgets (7.7e7 steps, 3.8 s); no
    /// iteration starts beyond two budgets (`orbit.rs`'s unit test) and
    /// period 1 is tried first. Its orbit contracts by 1 - 8.3e-7 a period
    /// (the friction's dissipation, by the variational equation): the answer
    /// is that orbit. (The value a mean of 4,000 periods of the flat punch's
    /// former machine gave, 0.06163313793972596, was that code's own, its
    /// drive's `cos tau` drifting over 7e5 rotations a period; it is 9.5e-13
    /// from this orbit.)
    #[test]
    fn newton_keeps_to_the_step_budget() {
        let c = Conditions::vhat(0.0275 * 1.515, 1.515).unwrap();
        let (r, at) = attractor(&c, &System::new(1e6, 0.0356, 0.0).unwrap()).unwrap();
        let steps = at.unwrap().0.steps_run() as f64;
        assert!(steps <= 2.5 * MAX_STEPS, "{:.2} budgets", steps / MAX_STEPS);
        assert_eq!(r.period, Some(1));
        let slowest = r.multipliers.as_ref().unwrap().iter().map(|[re, im]| re.hypot(*im)).fold(0.0, f64::max);
        assert!(slowest < 1.0 && slowest > 1.0 - 1e-5, "{r:?}");
        assert!(r.error_estimate < 1e-10, "{r:?}");
    }

    /// Only rounding is put back onto `|mu| <= 1`: beyond by less than the
    /// estimate, `mu` is `+-1`; beyond by more, or not a number, an internal
    /// error (a clamp there hid a solver's defect as a plausible 1.0).
    #[test]
    fn only_rounding_is_clamped() {
        let r = |mu: f64, e: f64| SystemReport {
            mu_ratio: mu,
            period: Some(1),
            standard_error: None,
            periods_run: 1,
            multipliers: None,
            events: vec![],
            error_estimate: e,
            springs: None,
            held_steps: 0,
        };
        for (mu, e, want) in [(1.0 + 1e-9, 2e-9, Some(1.0)), (-1.0 - 1e-9, 2e-9, Some(-1.0)), (0.5, 1e-9, Some(0.5))] {
            let mut x = r(mu, e);
            assert_eq!(within_bounds(&mut x).ok().map(|()| x.mu_ratio), want, "{mu} {e}");
        }
        for (mu, e) in [(1.0 + 1e-9, 1e-10), (-1.0 - 1e-6, 1e-9), (f64::NAN, 1e-9), (0.5, f64::INFINITY)] {
            assert!(within_bounds(&mut r(mu, e)).is_err_and(|e| e.is_internal()), "{mu} {e}");
        }
    }
    use super::phase::{series, Linear, Params, State, ONE};

    /// The series a sampling step is advanced by against nalgebra's Pade
    /// exponential of the whole generator: `exp(a h) z`, and `h phi_1(a0 h) u`
    /// (`u` the constant state's column, `a0` the generator without it) as
    /// `exp(a h) e_1 - e_1`. Observed: 5.6e-17 relative to the state at most.
    #[test]
    fn the_step_series_meet_the_pade_exponential() {
        let p = Params { kappa: 1.5, omega: 0.4, zeta: 0.05, vhat: 0.3, amp: 0.7, t: 0.8, phase: 0.6 };
        let close = |x: &State, y: &State| (x - y).amax() <= 5e-16 * (1.0 + y.amax());
        let stick = Linear { x: 1.0, y0: -1.0, ..Linear::default() };
        let forward = Linear { one: 1.0, cos: -p.amp, ..Linear::default() };
        for f in [stick, forward, Linear { x: 3.0, one: 0.7, cos: -0.2, y0: 0.0 }] {
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
}
