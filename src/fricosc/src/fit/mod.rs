//! The model fitted to measured friction: `mu = mu0 * mu_ratio(shape, vbar,
//! amp)` with `vbar = (kx/kz) v0 / (mu0 omega du)` and `amp = du/u0` (the
//! seed's eqs. 1-3, the same for every MDR spring), for the parameters
//! `mu0`, `kx/kz` (the stiffness ratio) and `u0`, each fitted or fixed, and
//! on a rig's system its stiffness `kappa = K/kx` ([`NAMES`]): held at the
//! rows' values, or fitted ([`Fixed::fit_system_stiffness`]). Every
//! parameter is positive, fitted in its logarithm, within the bounds the
//! user sets ([`Fixed::bounds`]). A system's `kappa` and
//! `Omega = omega/sqrt(kx/m)` are ratios to the contact's `kx`: held, they
//! stay as given while `kx/kz` is fitted (the rig's `K` and `m` taken to
//! follow `kx`); to hold `K` and `m` instead, hold `kx/kz` at the value they
//! were computed with.
//!
//! # Method
//! Weighted least squares (`sigma` per row, else 1) by Levenberg-Marquardt
//! in the logarithms of the free parameters (which keeps them positive), the
//! Jacobian by central differences of the exact solver (a relative step of
//! 1e-5: the solver's 1e-15 error makes the derivative good to about 1e-10).
//! The start needs no user input: `mu0` is the largest measured `mu` (the
//! plateau at `vbar >= 1`), then `u0` and `kx/kz` are the best of a
//! logarithmic grid. The covariance is `(J^T W J)^-1`, scaled by the reduced
//! chi-square where no row gives `sigma` (the residuals then estimate it). A
//! direction the data do not determine (a scaled Jacobian with a condition
//! number beyond 1e8, or a parameter nothing depends on) is named, and its
//! parameters get no standard error.
//!
//! # Goodness of fit
//! With `sigma` the chi-square's p-value (`goodness`); below 0.01 a verdict
//! that names the likely cause, each tried by a refit: the outlying rows
//! left out, a held parameter freed, another shape. Rows whose normalised
//! residual exceeds [`outlier_threshold`] (which grows with the
//! number of rows) are named. Without `sigma` the scale of the
//! errors is the scatter's (a note says what that assumes).

mod bounds;
mod goodness;
mod load;
mod profile;

pub use goodness::outlier_threshold;

use crate::error::{Error, Result};
use crate::shape::Shape;
use crate::Conditions;
use nalgebra::{DMatrix, DVector, SMatrix, SVector};

/// The parameters, in the order of [`FitReport::parameters`] and its
/// covariance: `mu0`, `kx/kz`, `u0` (m), and on a system `kappa = K/kx`.
pub const NAMES: [&str; 4] = ["mu0", "stiffness_ratio", "u0", "system_stiffness"];
/// How many parameters there are at most.
const NP: usize = NAMES.len();
/// A value of each parameter ([`NAMES`]); `kappa` NaN where each row keeps its own system.
type Values = SVector<f64, NP>;

/// One measured row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement {
    /// Sliding velocity `v0` (m/s), `>= 0`.
    pub v0: f64,
    /// Normal oscillation amplitude `du` (m), `> 0`.
    pub du: f64,
    /// Angular frequency `omega` (rad/s), `> 0`.
    pub omega: f64,
    /// Measured macroscopic friction coefficient.
    pub mu: f64,
    /// Its standard uncertainty (`> 0`), if known.
    pub sigma: Option<f64>,
    /// The rig's system the row was measured on (held, not fitted): the model
    /// is then the body's attractor there ([`crate::Conditions::with_system`]).
    pub system: Option<crate::system::System>,
    /// Under load control (a dead-weight rig), the mean normal force the rig
    /// holds (N): the row's mean indentation then follows the shape's force
    /// law from `u0` at the reference load ([`FitReport::reference_load`]).
    /// On every row or on none; without it every row has the one `u0`.
    pub load: Option<f64>,
}

/// Parameters held fixed (the others are fitted).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Fixed {
    /// `mu0`.
    pub mu0: Option<f64>,
    /// `kx/kz`.
    pub stiffness_ratio: Option<f64>,
    /// `u0` (m).
    pub u0: Option<f64>,
    /// Fit the system's stiffness `kappa = K/kx`, one for every row (each
    /// row on a system; the rows' own `kappa` is the start, their frequency
    /// ratio and damping held). Otherwise each row's system is held as given.
    pub fit_system_stiffness: bool,
    /// Bounds `[lo, hi]` on fitted parameters, in the order of [`NAMES`]
    /// (`0 <= lo < hi <= inf`; none: `(0, inf)`): the fit keeps within them,
    /// and a parameter that ends on one is named in a verdict.
    pub bounds: [Option<[f64; 2]>; NP],
}

/// One parameter's value and standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct Parameter {
    /// Its name ([`NAMES`]).
    pub name: &'static str,
    /// The interval it lies in: `[0, inf)` (every parameter is positive),
    /// or the bounds set ([`Fixed::bounds`]).
    pub bounds: [f64; 2],
    /// The fitted (or fixed) value.
    pub value: f64,
    /// Its standard error (0 for a fixed parameter; `None` where the data do
    /// not determine it).
    pub stderr: Option<f64>,
    /// Held fixed.
    pub fixed: bool,
    /// The profile-likelihood interval (one standard error's worth: the
    /// chi-square 1 above its minimum, the others refitted), where it differs
    /// from `value +- stderr` by more than 20 % on a side.
    pub profile: Option<[f64; 2]>,
}

/// A fit's answer.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct FitReport {
    /// The parameters in the order of [`NAMES`]: `mu0`, `kx/kz`, `u0` (m),
    /// and `kappa` where the rows are on a system (fitted, or held at the
    /// one value every row has; where the rows' values differ, not listed).
    pub parameters: Vec<Parameter>,
    /// Covariance of [`FitReport::parameters`] (rows and columns of fixed or
    /// undetermined parameters 0).
    pub covariance: Vec<Vec<f64>>,
    /// Correlation matrix (1 on the diagonal of fitted parameters).
    pub correlation: Vec<Vec<f64>>,
    /// `sum ((model - mu)/sigma)^2`.
    pub chi2: f64,
    /// Rows less fitted parameters.
    pub dof: usize,
    /// `chi2 / dof`.
    pub reduced_chi2: f64,
    /// Per row `mu - model`.
    pub residuals: Vec<f64>,
    /// Per row `vbar` and `amp` at the fitted parameters.
    pub points: Vec<[f64; 2]>,
    /// Whether the rows gave `sigma` (else the covariance is scaled by `reduced_chi2`).
    pub weighted: bool,
    /// What is wrong with the fit, in words: what the data cannot determine,
    /// a chi-square the model cannot explain (with its likely cause), an
    /// iteration that did not converge (empty: nothing found).
    pub verdicts: Vec<String>,
    /// What the fit assumes where the rows do not say (without `sigma`: the
    /// scale of the errors taken from the scatter).
    pub notes: Vec<String>,
    /// With `sigma`: the probability of a chi-square at least this large were
    /// the model right and `sigma` the rows' standard uncertainties.
    pub p_value: Option<f64>,
    /// Per row the residual over its uncertainty (`sigma`, else the scatter's
    /// `sqrt(reduced_chi2)`).
    pub normalised_residuals: Vec<f64>,
    /// Rows (indices) whose normalised residual exceeds `outlier_threshold` in size.
    pub outliers: Vec<usize>,
    /// [`outlier_threshold`] of the number of rows.
    pub outlier_threshold: f64,
    /// Levenberg-Marquardt iterations.
    pub iterations: usize,
    /// Whether Levenberg-Marquardt reached a minimum (no step improves the
    /// chi-square) within its iterations; with nothing fitted, true.
    pub converged: bool,
    /// Under load control: the reference load (N, the rows' median), at which
    /// `u0` is the static indentation.
    pub reference_load: Option<f64>,
}

/// Most iterations of Levenberg-Marquardt.
const MAX_ITERATIONS: usize = 200;
/// Most rows the start's grid is evaluated on.
const START_ROWS: usize = 2_000;
/// Largest `|mu|` and `sigma` (and the inverse of the smallest `sigma`): the
/// squares of the residuals stay within a double.
const MAX_MAGNITUDE: f64 = 1e100;
/// Largest condition number of the scaled Jacobian that determines every parameter.
const MAX_CONDITION: f64 = 1e8;

/// `mu` of the model at `p` ([`NAMES`]) for each row, with `(vbar, amp)`;
/// under load control (loads relative to the reference, [`load`]) each
/// row's own mean indentation; on a system its `kappa` `p[3]` where that is
/// finite (fitted, or the one held), else the row's own.
fn model(shape: &Shape, rows: &[Measurement], p: &Values) -> Result<Vec<(f64, [f64; 2])>> {
    PROGRESS.with(|f| f.borrow().as_ref().map(|f| f(rows.len())));
    let q = if rows.iter().any(|r| r.load.is_some()) { load::exponent(shape)? } else { 1.0 };
    crate::numerics::par::map(rows, |r| {
        let u0 = match r.load {
            // A load no indentation holds: an infinite residual, never a step taken.
            Some(l) => match load::indentation(shape, q, p[2], l, r.du)? {
                Some(u) => u,
                None => return Ok((f64::INFINITY, [f64::NAN; 2])),
            },
            None => p[2],
        };
        let (vbar, amp) = (p[1] * r.v0 / (p[0] * r.omega * r.du), r.du / u0);
        let ratio = match r.system {
            // On a system friction may stay reduced beyond vbar = 1.
            Some(sys) => {
                let sys = match p[3] {
                    k if k.is_finite() => with_stiffness(sys, k)?,
                    _ => sys,
                };
                shape.ratio(&Conditions::vbar(vbar, amp)?.with_system(sys))?.mu_ratio
            }
            None if vbar >= 1.0 => 1.0,
            None => shape.ratio(&Conditions::vbar(vbar, amp)?)?.mu_ratio,
        };
        Ok((p[0] * ratio, [vbar, amp]))
    })
    .into_iter()
    .collect()
}

/// `sys` with the stiffness `kappa` (its frequency ratio, damping and springs kept).
fn with_stiffness(sys: crate::system::System, kappa: f64) -> Result<crate::system::System> {
    crate::system::System::new(kappa, sys.frequency_ratio(), sys.damping())?.with_springs(sys.springs())
}

impl FitReport {
    /// The parameter named `name` ([`NAMES`]), where the fit has it.
    pub fn parameter(&self, name: &str) -> Option<&Parameter> {
        self.parameters.iter().find(|p| p.name == name)
    }

    /// The parameter `k` of [`NAMES`] (listed: fitted or held at one value).
    fn parameter_mut(&mut self, k: usize) -> Option<&mut Parameter> {
        self.parameters.iter_mut().find(|p| p.name == NAMES[k])
    }

    /// The values of every parameter ([`NAMES`]; `kappa` NaN where not listed).
    fn values(&self) -> Values {
        Values::from_fn(|k, _| self.parameter(NAMES[k]).map_or(f64::NAN, |p| p.value))
    }

    /// The fitted model's `mu` at one row's conditions (`v0` m/s, `du` m,
    /// `omega` rad/s), on the rig's `system` if any, at `load` (N) where the
    /// fit was under load control.
    ///
    /// # Errors
    /// The solver's, for conditions it refuses (e.g. an amplitude a tabulated
    /// shape does not reach); [`Error::InvalidParameter`] for a load given to
    /// a fit without (or none to one with).
    pub fn predict(
        &self,
        shape: &Shape,
        (v0, du, omega): (f64, f64, f64),
        system: Option<crate::system::System>,
        load: Option<f64>,
    ) -> Result<f64> {
        let p = self.values();
        let load = match (load, self.reference_load) {
            (Some(l), Some(reference)) if l.is_finite() && l > 0.0 => Some(l / reference),
            (None, None) => None,
            (l, _) => {
                let reason = "a load (> 0, N) exactly where the fit was under load control";
                return Err(Error::param("load", l.unwrap_or(f64::NAN), reason));
            }
        };
        let row = Measurement { v0, du, omega, mu: 0.0, sigma: None, system, load };
        Ok(model(shape, &[row], &p)?[0].0)
    }
}

/// Checked rows: finite, positive where they must be, at least as many as the fitted parameters.
fn check(rows: &[Measurement], free: usize) -> Result<()> {
    for (i, r) in rows.iter().enumerate() {
        let bad = |name: &'static str, v: f64, why: &str| Error::param(name, v, &format!("row {i}: {why}"));
        if !(r.v0.is_finite() && r.v0 >= 0.0) {
            return Err(bad("v0", r.v0, "a sliding velocity must be finite and >= 0"));
        }
        if !(r.du.is_finite() && r.du > 0.0) {
            return Err(bad("du", r.du, "an amplitude must be finite and > 0"));
        }
        if !(r.omega.is_finite() && r.omega > 0.0) {
            return Err(bad("omega", r.omega, "a frequency must be finite and > 0"));
        }
        if !(r.mu.is_finite() && r.mu.abs() <= MAX_MAGNITUDE) {
            return Err(bad("mu", r.mu, "must be finite and at most 1e100 in size (a friction coefficient)"));
        }
        if let Some(s) = r.sigma.filter(|s| !(s.is_finite() && (1.0 / MAX_MAGNITUDE..=MAX_MAGNITUDE).contains(s))) {
            return Err(bad("sigma", s, "must be in 1e-100..=1e100 (the chi-square must fit a double)"));
        }
    }
    // Omega = omega/omega_c: one system with mass holds at one frequency.
    for (i, r) in rows.iter().enumerate() {
        let same = |q: &Measurement| q.system == r.system && q.omega != r.omega;
        if r.system.is_some_and(|s| s.frequency_ratio() > 0.0) && rows[..i].iter().any(same) {
            let reason =
                format!("row {i}: a system's frequency-ratio holds at one frequency; these rows are at several");
            return Err(Error::param("frequency-ratio", r.system.map_or(0.0, |s| s.frequency_ratio()), &reason));
        }
    }
    if rows.len() <= free {
        return Err(Error::param("rows", rows.len() as f64, &format!("a fit of {free} parameters needs more rows")));
    }
    Ok(())
}

thread_local! {
    /// The observer of [`fit_with_progress`] on the thread that fits (every
    /// evaluation of the model, the refits of the profiles and verdicts
    /// among them, runs on it).
    static PROGRESS: std::cell::RefCell<Option<Observer>> = const { std::cell::RefCell::new(None) };
}

/// [`fit_with_progress`]'s observer of the rows evaluated.
type Observer = Box<dyn Fn(usize)>;

/// [`fit`], telling `progress` the rows of each evaluation of the model as it
/// starts (a fit's work is that count; its total is not known beforehand:
/// Levenberg-Marquardt's iterations, the profiles' and the verdicts' refits).
///
/// # Errors
/// As [`fit`].
pub fn fit_with_progress(
    shape: &Shape,
    rows: &[Measurement],
    fixed: &Fixed,
    progress: impl Fn(usize) + 'static,
) -> Result<FitReport> {
    /// The observer removed however the fit ends.
    struct Reset;
    impl Drop for Reset {
        fn drop(&mut self) {
            PROGRESS.with(|f| f.borrow_mut().take());
        }
    }
    PROGRESS.with(|f| *f.borrow_mut() = Some(Box::new(progress)));
    let _reset = Reset;
    fit(shape, rows, fixed)
}

/// Fit `shape`'s model to `rows` with `fixed` parameters held (module docs);
/// every parameter may be held (the report is then that model's chi-square).
///
/// # Errors
/// [`Error::InvalidParameter`] for a bad row (named), fixed values that are
/// not finite, positive and normal, fewer rows than fitted parameters plus
/// one, or a mix of rows with and without `sigma`; the solver's errors.
pub fn fit(shape: &Shape, rows: &[Measurement], fixed: &Fixed) -> Result<FitReport> {
    for (name, v) in NAMES.iter().zip([fixed.mu0, fixed.stiffness_ratio, fixed.u0]) {
        if let Some(v) = v.filter(|v| !(v.is_normal() && *v > 0.0)) {
            return Err(Error::param(name, v, "a fixed parameter must be finite, > 0 and a normal double"));
        }
    }
    let given = given(rows, fixed)?;
    let bounds = bounds::checked(fixed, &given)?;
    let free = (0..NP).filter(|&k| given[k].is_none()).count();
    check(rows, free)?;
    if rows.iter().any(|r| r.sigma.is_some()) && rows.iter().any(|r| r.sigma.is_none()) {
        return Err(Error::param("sigma", f64::NAN, "give sigma on every row or on none"));
    }
    let (rows, reference) = load::relative(rows)?;
    if reference.is_some() {
        load::exponent(shape)?;
    }
    let mut r = fit_checked(shape, &rows, &given, &bounds)?;
    r.reference_load = reference;
    profile::profile(shape, &rows, (&given, &bounds), &mut r);
    goodness::judge(shape, &rows, (&given, &bounds), &mut r)?;
    Ok(r)
}

/// Each parameter's held value ([`NAMES`]), `None` where it is fitted:
/// `fixed`'s, and `kappa` the one every row's system has (NaN where they
/// differ or no row is on a system: each row's own), or fitted.
fn given(rows: &[Measurement], fixed: &Fixed) -> Result<[Option<f64>; NP]> {
    let kappas: Vec<Option<f64>> = rows.iter().map(|r| r.system.map(|s| s.stiffness())).collect();
    let common = kappas.first().copied().flatten().filter(|_| kappas.windows(2).all(|w| w[0] == w[1]));
    if fixed.fit_system_stiffness && kappas.iter().any(Option::is_none) {
        let reason = "fitting the system's stiffness needs every row on a system (its kappa the start)";
        return Err(Error::param("system-stiffness", f64::NAN, reason));
    }
    let kappa = if fixed.fit_system_stiffness { None } else { Some(common.unwrap_or(f64::NAN)) };
    Ok([fixed.mu0, fixed.stiffness_ratio, fixed.u0, kappa])
}

/// The parameters a fit reports: all but `kappa` where it is neither
/// fitted nor one value held (`given[3]` NaN).
fn listed(given: &[Option<f64>; NP]) -> Vec<usize> {
    (0..NP).filter(|&k| given[k].is_none_or(|v| !v.is_nan())).collect()
}

/// The rows' residuals `(model - mu)/sigma` (`sigma` 1 where none is given) at `p`.
fn scaled_residuals(shape: &Shape, rows: &[Measurement], p: &Values) -> Result<DVector<f64>> {
    let m = model(shape, rows, p)?;
    Ok(DVector::from_iterator(rows.len(), m.iter().zip(rows).map(|(m, r)| (m.0 - r.mu) / r.sigma.unwrap_or(1.0))))
}

/// The median of the rows' system stiffness (the start of a fitted `kappa`), NaN without systems.
fn median_kappa(rows: &[Measurement]) -> f64 {
    let mut k: Vec<f64> = rows.iter().filter_map(|r| r.system.map(|s| s.stiffness())).collect();
    k.sort_by(f64::total_cmp);
    k.get(k.len() / 2).copied().unwrap_or(f64::NAN)
}

/// [`fit`] of checked inputs within `bounds`, without the goodness of fit's
/// verdicts; a parameter resting on a bound is reported as [`bounds`] says.
fn fit_checked(
    shape: &Shape,
    rows: &[Measurement],
    given: &[Option<f64>; NP],
    bounds: &bounds::Bounds,
) -> Result<FitReport> {
    let free: Vec<usize> = (0..NP).filter(|&k| given[k].is_none()).collect();
    let weighted = rows.iter().any(|r| r.sigma.is_some());
    let residuals = |p: &Values| scaled_residuals(shape, rows, p);
    // The start's grid on at most START_ROWS rows, evenly spread (a large file's start costs no more).
    let every = rows.len().div_ceil(START_ROWS);
    // The start from the stiff model (on a system each point costs a thousand times more).
    let few: Vec<Measurement> = rows.iter().step_by(every).map(|r| Measurement { system: None, ..*r }).collect();
    let few_residuals = |p: &Values| scaled_residuals(shape, &few, p);
    let mut start = start(shape, &few, given, &few_residuals)?;
    start[3] = given[3].unwrap_or_else(|| median_kappa(rows));
    let start = bounds::project(start, &free, bounds);
    let (p, iterations, converged) =
        if free.is_empty() { (start, 0, true) } else { levenberg_marquardt(start, &free, bounds, &residuals)? };
    if rows.iter().any(|r| r.load.is_some()) && !residuals(&p)?.iter().all(|x| x.is_finite()) {
        return Err(load::unheld());
    }
    let resting = bounds::resting(&p, &free, bounds);
    let moving: Vec<usize> = free.iter().copied().filter(|k| !resting.contains(k)).collect();
    let mut r = report(shape, rows, p, (&moving, &listed(given)), weighted, iterations, &residuals)?;
    r.converged = converged;
    for (k, q) in listed(given).into_iter().zip(r.parameters.iter_mut()) {
        q.bounds = bounds[k];
        if resting.contains(&k) {
            (q.fixed, q.stderr) = (false, None);
        }
    }
    r.verdicts.extend(resting.iter().map(|&k| bounds::verdict(k, p[k])));
    Ok(r)
}

type Residuals<'a> = dyn Fn(&Values) -> Result<DVector<f64>> + 'a;

/// The start: `mu0` the largest `mu` (or fixed), then the best `(u0, kx/kz)`
/// of a logarithmic grid (the fixed ones as given) on the stiff model: `u0`
/// from 0.2 to 20 times the largest `du`, `kx/kz` where the median row's
/// `vbar` runs from 0.01 to 10 (`kappa` NaN: the caller's).
fn start(shape: &Shape, rows: &[Measurement], given: &[Option<f64>; NP], res: &Residuals) -> Result<Values> {
    let mu0 = given[0].unwrap_or_else(|| rows.iter().map(|r| r.mu).fold(f64::MIN, f64::max).max(1e-12));
    let du_max = rows.iter().map(|r| r.du).fold(0.0, f64::max);
    let mut scales: Vec<f64> = rows.iter().filter(|r| r.v0 > 0.0).map(|r| mu0 * r.omega * r.du / r.v0).collect();
    scales.sort_by(f64::total_cmp);
    let scale = scales.get(scales.len() / 2).copied().unwrap_or(1.0);
    let u0s: Vec<f64> = match given[2] {
        Some(u) => vec![u],
        None => (0..=20).map(|k| du_max * 0.2 * 10f64.powf(2.0 * k as f64 / 20.0)).collect(),
    };
    let ratios: Vec<f64> = match given[1] {
        Some(r) => vec![r],
        None => (0..=24).map(|k| scale * 10f64.powf(-2.0 + 3.0 * k as f64 / 24.0)).collect(),
    };
    let mut best = (f64::INFINITY, Values::new(mu0, ratios[0], u0s[0], f64::NAN));
    for &u0 in &u0s {
        for &r in &ratios {
            let p = Values::new(mu0, r, u0, f64::NAN);
            if shape.check_amp(du_max / u0).is_err() {
                continue;
            }
            let chi2 = res(&p)?.norm_squared();
            if chi2 < best.0 {
                best = (chi2, p);
            }
        }
    }
    Ok(best.1)
}

/// The Jacobian of the residuals in the logarithms of the `free` parameters.
fn jacobian(p: &Values, free: &[usize], n: usize, res: &Residuals) -> Result<DMatrix<f64>> {
    let mut j = DMatrix::zeros(n, free.len());
    for (c, &k) in free.iter().enumerate() {
        let h: f64 = 1e-5;
        let (mut a, mut b) = (*p, *p);
        a[k] *= h.exp();
        b[k] *= (-h).exp();
        j.set_column(c, &((res(&a)? - res(&b)?) / (2.0 * h)));
    }
    Ok(j)
}

/// Levenberg-Marquardt in the logarithms of the free parameters from `p`,
/// each step projected onto `bounds`: the parameters, the iterations, and
/// whether it converged (a step below 1e-12, a chi-square that no longer
/// falls, or no step that lowers it).
fn levenberg_marquardt(
    mut p: Values,
    free: &[usize],
    bounds: &bounds::Bounds,
    res: &Residuals,
) -> Result<(Values, usize, bool)> {
    let mut r = res(&p)?;
    let mut chi2 = r.norm_squared();
    let mut lambda = 1e-3;
    for it in 1..=MAX_ITERATIONS {
        let j = jacobian(&p, free, r.len(), res)?;
        let jtj = j.transpose() * &j;
        let mut g = j.transpose() * &r;
        let held = bounds::held_columns(&p, free, bounds, g.as_slice());
        let mut improved = false;
        while lambda < 1e16 {
            let mut a = jtj.clone();
            for d in 0..free.len() {
                a[(d, d)] += lambda * jtj[(d, d)].max(1e-300);
            }
            for &c in &held {
                // No step for a parameter the descent pushes beyond its bound.
                a.row_mut(c).fill(0.0);
                a.column_mut(c).fill(0.0);
                (a[(c, c)], g[c]) = (1.0, 0.0);
            }
            let Some(step) = a.lu().solve(&(-&g)) else { break };
            let mut q = p;
            for (c, &k) in free.iter().enumerate() {
                q[k] *= step[c].exp();
            }
            // Projected onto the bounds: the step taken is what is left of it.
            let q = bounds::project(q, free, bounds);
            let taken = free.iter().map(|&k| (q[k] / p[k]).ln().abs()).fold(0.0, f64::max);
            let rq = match res(&q) {
                Ok(rq) => rq,
                Err(_) => {
                    lambda *= 10.0;
                    continue;
                }
            };
            let chi2q = rq.norm_squared();
            if chi2q <= chi2 {
                let small = taken < 1e-12 || chi2 - chi2q <= 1e-15 * chi2;
                (p, r, chi2, improved) = (q, rq, chi2q, true);
                lambda = (lambda / 10.0).max(1e-12);
                if small {
                    return Ok((p, it, true));
                }
                break;
            }
            lambda *= 10.0;
        }
        if !improved {
            return Ok((p, it, true));
        }
    }
    Ok((p, MAX_ITERATIONS, false))
}

/// The covariance, standard errors and verdicts at the fitted `p` (the
/// `free` parameters fitted, the `listed` ones reported).
fn report(
    shape: &Shape,
    rows: &[Measurement],
    p: Values,
    (free, listed): (&[usize], &[usize]),
    weighted: bool,
    iterations: usize,
    res: &Residuals,
) -> Result<FitReport> {
    let fitted = model(shape, rows, &p)?;
    let chi2 = res(&p)?.norm_squared();
    let dof = rows.len() - free.len();
    let reduced_chi2 = chi2 / dof as f64;
    let j = jacobian(&p, free, rows.len(), res)?;
    let mut verdicts = vec![];
    let stiff = rows.iter().all(|r| r.system.is_none());
    let determined = determined(&j, free, &fitted, stiff, &mut verdicts);
    let mut cov = SMatrix::<f64, NP, NP>::zeros();
    let kept: Vec<usize> = (0..free.len()).filter(|&c| determined[c]).collect();
    if !kept.is_empty() {
        let jk = j.select_columns(&kept);
        if let Some(inv) = (jk.transpose() * &jk).try_inverse() {
            let scale = if weighted { 1.0 } else { reduced_chi2 };
            // The upper triangle, mirrored: the inverse is symmetric to rounding only.
            for (a, &ca) in kept.iter().enumerate() {
                for (b, &cb) in kept.iter().enumerate().skip(a) {
                    let (ka, kb) = (free[ca], free[cb]);
                    cov[(ka, kb)] = inv[(a, b)] * scale * p[ka] * p[kb];
                    cov[(kb, ka)] = cov[(ka, kb)];
                }
            }
        }
    }
    let param = |k: usize| {
        let c = free.iter().position(|&f| f == k);
        let stderr = match c {
            None => Some(0.0),
            Some(c) if determined[c] => Some(cov[(k, k)].sqrt()),
            Some(_) => None,
        };
        Parameter {
            name: NAMES[k],
            bounds: [0.0, f64::INFINITY],
            value: p[k],
            stderr,
            fixed: c.is_none(),
            profile: None,
        }
    };
    let correlation = |a: usize, b: usize| {
        let d = (cov[(a, a)] * cov[(b, b)]).sqrt();
        if d > 0.0 {
            cov[(a, b)] / d
        } else {
            0.0
        }
    };
    let matrix =
        |f: &dyn Fn(usize, usize) -> f64| listed.iter().map(|&a| listed.iter().map(|&b| f(a, b)).collect()).collect();
    Ok(FitReport {
        parameters: listed.iter().map(|&k| param(k)).collect(),
        covariance: matrix(&|a, b| cov[(a, b)]),
        correlation: matrix(&correlation),
        chi2,
        dof,
        reduced_chi2,
        residuals: rows.iter().zip(&fitted).map(|(r, m)| r.mu - m.0).collect(),
        points: fitted.iter().map(|m| m.1).collect(),
        weighted,
        verdicts,
        notes: vec![],
        p_value: None,
        normalised_residuals: vec![],
        outliers: vec![],
        outlier_threshold: outlier_threshold(rows.len()),
        iterations,
        converged: true,
        reference_load: None,
    })
}

/// Which free parameters the data determine (per column of `j`), with the
/// verdicts in words: all rows at `vbar >= 1` leave `kx/kz` and `u0` free
/// (on a stiff rig: on a system friction may stay reduced there); a
/// column of zeros or a scaled Jacobian beyond [`MAX_CONDITION`] names the
/// parameters of its weakest direction.
fn determined(
    j: &DMatrix<f64>,
    free: &[usize],
    fitted: &[(f64, [f64; 2])],
    stiff: bool,
    verdicts: &mut Vec<String>,
) -> Vec<bool> {
    let mut ok = vec![true; free.len()];
    if stiff && fitted.iter().all(|m| m.1[0] >= 1.0) {
        verdicts.push("all rows have vbar >= 1 (no reduction: mu = mu0 there): kx/kz and u0 are not determined".into());
        for (c, &k) in free.iter().enumerate() {
            ok[c] = k == 0;
        }
        return ok;
    }
    let norms: Vec<f64> = (0..free.len()).map(|c| j.column(c).norm()).collect();
    let top = norms.iter().copied().fold(0.0, f64::max);
    for (c, &n) in norms.iter().enumerate() {
        if n.is_nan() || n <= 1e-12 * top {
            ok[c] = false;
            verdicts.push(format!("{}: the rows do not depend on it", NAMES[free[c]]));
        }
    }
    let live: Vec<usize> = (0..free.len()).filter(|&c| ok[c]).collect();
    if live.len() > 1 {
        let mut scaled = j.select_columns(&live);
        for (c, &l) in live.iter().enumerate() {
            scaled.column_mut(c).scale_mut(1.0 / norms[l]);
        }
        let svd = scaled.svd(false, true);
        let s = &svd.singular_values;
        let (smax, smin) = (s.max(), s.min());
        if smin * MAX_CONDITION < smax {
            if let Some(vt) = svd.v_t {
                // Every weak direction (a rank short by more than one has several).
                let weak: Vec<usize> = (0..s.len()).filter(|&d| s[d] * MAX_CONDITION < smax).collect();
                let names: Vec<&str> = (0..live.len())
                    .filter(|&c| weak.iter().any(|&d| vt[(d, c)].abs() > 0.1))
                    .map(|c| NAMES[free[live[c]]])
                    .collect();
                for c in (0..live.len()).filter(|&c| weak.iter().any(|&d| vt[(d, c)].abs() > 0.1)) {
                    ok[live[c]] = false;
                }
                verdicts.push(format!(
                    "{} are not determined separately by these rows (the scaled Jacobian's condition number is {:.1e})",
                    names.join(" and "),
                    smax / smin
                ));
            }
        }
    }
    ok
}
