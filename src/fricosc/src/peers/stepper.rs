//! The seed's time-stepping scheme, the honest peer of the exact solver.
//!
//! Each step moves the upper end of every spring (the tangential force grows
//! by `vbar h`, the normal force is set to the new bound `(s - cos tau)_+`),
//! then return-maps the tangential force onto the Coulomb bound; out of
//! contact the spring is relaxed. By induction the stepped force is
//! `min over grid sigma <= tau of [B(sigma) + vbar (tau - sigma)]`, the exact
//! envelope restricted to grid points: second order while the stick starts at
//! a tangency, first order (and erratic in `M`) once a stick starts at the
//! onset of contact, which falls between grid points.
//!
//! The run starts from the sliding state `F = B` at `tau = 0`; the periodic
//! state is reached after the first stick->slip of every spring, so two
//! periods suffice; the means are taken over the last period (a rectangle rule
//! on a periodic function) and the change from the period before is reported.

use crate::error::{Error, Result};
use crate::ratio::Ratio;
use crate::shape::Shape;
use crate::special::Kahan;
use std::f64::consts::TAU;

/// Period means from a time-stepping run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SteppedMeans {
    /// Weighted sum of the springs' mean tangential forces.
    pub tangential: f64,
    /// Weighted sum of the springs' mean normal forces.
    pub normal: f64,
    /// `|mu(last period) - mu(previous period)|`.
    pub period_change: f64,
    /// Steps taken in all (`periods * steps_per_period`).
    pub steps: u64,
}

impl SteppedMeans {
    /// `mu_macro / mu0 = <F> / <B>` (1 when nothing touches).
    #[must_use]
    pub fn mu_ratio(&self) -> f64 {
        if self.normal > 0.0 {
            self.tangential / self.normal
        } else {
            1.0
        }
    }
}

/// Springs per parallel chunk: each chunk runs the whole time loop on its own
/// (the springs are independent), so the only synchronisation is the final sum.
const CHUNK: usize = 1024;

/// The seed's update of one spring's tangential force over one step: it grows
/// by the drive's increment `df` (`kx v0 dt`; `vbar h` in units of
/// `mu0 kz du`) and is capped by the Coulomb bound `b` (`mu0` times the normal
/// force); without contact (`b <= 0`) it is 0. The one place the scheme lives.
#[inline]
pub(crate) fn update(f: f64, b: f64, df: f64) -> f64 {
    if b > 0.0 {
        (f + df).min(b)
    } else {
        0.0
    }
}

/// A single spring in physical units (seed eq. 1): stiffnesses `kx`, `kz`
/// (N/m), friction coefficient `mu0`, sliding velocity `v0` (m/s), angular
/// frequency `omega` (1/s), mean indentation `u0` and amplitude `du` (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PhysicalSpring {
    /// Tangential stiffness.
    pub kx: f64,
    /// Normal stiffness.
    pub kz: f64,
    /// Coulomb coefficient.
    pub mu0: f64,
    /// Sliding velocity.
    pub v0: f64,
    /// Angular frequency of the normal oscillation.
    pub omega: f64,
    /// Mean indentation.
    pub u0: f64,
    /// Oscillation amplitude.
    pub du: f64,
}

/// `mu/mu0` of one spring by the seed's scheme in physical units (no
/// nondimensionalisation: it checks the seed's claim that the result depends
/// only on `vbar` and `du/u0`), `m` steps per period, the second of two periods.
pub(crate) fn physical_mu_ratio(p: &PhysicalSpring, m: usize) -> f64 {
    let PhysicalSpring { kx, kz, mu0, v0, omega, u0, du } = *p;
    let m = m.max(1);
    let dt = TAU / omega / m as f64;
    let bound = |t: f64| mu0 * kz * (u0 - du * (omega * t).cos());
    let mut f = bound(0.0).max(0.0);
    let (mut sf, mut sn) = (0.0, 0.0);
    for k in 1..=2 * m {
        let b = bound(dt * k as f64);
        f = update(f, b, kx * v0 * dt);
        if k > m {
            sf += f;
            sn += b.max(0.0) / mu0;
        }
    }
    sf / (mu0 * sn)
}

/// Steps computed per block of the cosine table: memory stays at this many
/// values whatever the steps per period (a whole table of 10^8 steps took 800 MB).
const COS_BLOCK: usize = 4096;

/// The seed's scheme for `count` springs given by `spring(i) = (s_i, weight_i)`, generated
/// a chunk at a time: memory is bounded by a few chunks per thread, whatever
/// `count` and `steps_per_period` are.
pub(crate) fn run_with(
    count: usize,
    spring: &(dyn Fn(usize) -> (f64, f64) + Sync),
    vbar: f64,
    steps_per_period: usize,
    periods: usize,
) -> SteppedMeans {
    let m = steps_per_period.max(1);
    let periods = periods.max(2);
    let h = TAU / m as f64;
    let dv = vbar * h;
    // Per chunk: (tangential, normal) sums of the last two periods.
    let chunk_sums = |start: usize| -> [f64; 4] {
        let end = (start + CHUNK).min(count);
        let (sc, wc): (Vec<f64>, Vec<f64>) = (start..end).map(spring).unzip();
        // Sliding initial state at tau = 0.
        let mut f: Vec<f64> = sc.iter().map(|&si| (si - 1.0).max(0.0)).collect();
        let mut out = [0.0; 4];
        let mut cos = Vec::with_capacity(COS_BLOCK.min(m));
        for p in 0..periods {
            // Per-step partial sums, added into the period totals with Kahan
            // compensation: with 10^7 steps a plain sum loses ~1e-10 to rounding.
            let (mut ft, mut fnn) = (Kahan::default(), Kahan::default());
            for block in (1..=m).step_by(COS_BLOCK) {
                cos.clear();
                cos.extend((block..(block + COS_BLOCK).min(m + 1)).map(|k| (h * k as f64).cos()));
                for &c in &cos {
                    let (mut st, mut sn) = (0.0, 0.0);
                    for ((fi, &si), &wi) in f.iter_mut().zip(&sc).zip(&wc) {
                        let b = si - c;
                        *fi = update(*fi, b, dv);
                        st += wi * *fi;
                        sn += wi * b.max(0.0);
                    }
                    ft.add(st);
                    fnn.add(sn);
                }
            }
            let (ft, fnn) = (ft.sum, fnn.sum);
            if p + 2 >= periods {
                let k = 2 * (p + 2 - periods);
                out[k] = ft;
                out[k + 1] = fnn;
            }
        }
        out
    };
    let starts: Vec<usize> = (0..count).step_by(CHUNK).collect();
    // The chunks' sums in parallel, added in order.
    let sums = crate::numerics::par::map(&starts, |&start| chunk_sums(start))
        .into_iter()
        .fold([0.0; 4], |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]);
    let mu = |t: f64, n: f64| if n > 0.0 { t / n } else { 1.0 };
    SteppedMeans {
        tangential: sums[2] / m as f64,
        normal: sums[3] / m as f64,
        period_change: (mu(sums[2], sums[3]) - mu(sums[0], sums[1])).abs(),
        steps: (periods * m) as u64,
    }
}

/// `mu_macro/mu0` of any contact by time stepping, over two periods: its
/// foundation on the uniform grid of [`crate::contact::grid`] (`st.springs`
/// springs at the midpoints of the part that ever touches; one for the flat
/// punch). Returns the means and the number of springs stepped.
pub(crate) fn contact_mu_ratio(
    contact: &dyn crate::contact::Contact,
    vbar: f64,
    amp: f64,
    st: Stepping,
) -> crate::Result<(SteppedMeans, usize)> {
    let count = if contact.single_spring() { 1 } else { st.springs.max(1) };
    if amp == 0.0 {
        return Ok((SteppedMeans { tangential: 1.0, normal: 1.0, period_change: 0.0, steps: 0 }, count));
    }
    let (dz, s_of) = crate::contact::grid(contact, amp, count)?;
    Ok((run_with(count, &|i| (s_of(i), dz), vbar, st.steps_per_period, 2), count))
}

/// Resolution of the time-stepping peer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Stepping {
    /// Time steps per oscillation period (`M`).
    pub steps_per_period: usize,
    /// Springs of an MDR foundation (`N`; the flat punch has one).
    pub springs: usize,
}

/// Largest `M` and `N` accepted (each); their product is bounded by [`MAX_STEPPING_WORK`].
pub(crate) const MAX_STEPPING: usize = 100_000_000;
/// Largest `M * N` (spring updates per period) accepted: two periods of 10^11
/// updates take about four minutes on two cores (0.6 ns per update measured);
/// memory stays at a few MB whatever `M` and `N` (`run_with`).
pub(crate) const MAX_STEPPING_WORK: u128 = 100_000_000_000;

impl Stepping {
    /// Check the resolution and the shape before any work (and any output).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a resolution out of its range.
    pub fn check(&self, shape: &Shape) -> Result<()> {
        for (name, v) in [("steps-per-period", self.steps_per_period), ("springs", self.springs)] {
            if v == 0 || v > MAX_STEPPING {
                return Err(Error::param(name, v as f64, "must be between 1 and 1e8"));
            }
        }
        let springs = if shape.is_flat() { 1 } else { self.springs };
        if self.steps_per_period as u128 * springs as u128 > MAX_STEPPING_WORK {
            return Err(Error::param("springs", self.springs as f64, "steps-per-period x springs must be <= 1e11"));
        }
        Ok(())
    }
}

/// Result of the time-stepping peer.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SteppingEvaluation {
    /// Ratio and reduction (`1 - mu_ratio`, no special care: this is the peer).
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub ratio: Ratio,
    /// Time steps taken (two periods).
    pub steps: u64,
    /// Springs stepped.
    pub springs: usize,
    /// `|mu(last period) - mu(previous period)|`.
    pub period_change: f64,
}

/// `mu_macro/mu0` under the conditions `c` by time stepping: the seed's
/// scheme, or under a tangential oscillation the stop operator's
/// (three periods from a sliding start).
///
/// # Errors
/// [`Error::InvalidParameter`] for a resolution beyond the limits, an
/// undefined `vbar` or conditions on a system ([`system`] steps those);
/// [`Error::Internal`] for a non-finite result.
pub fn evaluate(shape: &Shape, c: &crate::Conditions, st: Stepping) -> Result<SteppingEvaluation> {
    if let Some(sys) = c.system() {
        let reason = "the seed's scheme has no body: step it on a system with `stepper::system`";
        return Err(Error::param("system-stiffness", sys.stiffness(), reason));
    }
    match c.tangential() {
        Some(_) => evaluate_oscillation(shape, c, st, OSCILLATION_PERIODS),
        None => evaluate_normal(shape, c.as_vbar()?, c.amp(), st),
    }
}

/// The seed's scheme at `(vbar, amp)`.
fn evaluate_normal(shape: &Shape, vbar: f64, amp: f64, st: Stepping) -> Result<SteppingEvaluation> {
    st.check(shape)?;
    // Any contact: its foundation on a uniform grid (crate::contact::grid).
    let (run, springs) = contact_mu_ratio(shape.contact(), vbar, amp, st)?;
    // The peer's raw value: outside [0, 1] it says something about the peer.
    let mu = run.mu_ratio();
    if !mu.is_finite() {
        return Err(Error::Internal { what: format!("time stepping gave mu_ratio = {mu:?}") });
    }
    Ok(SteppingEvaluation {
        ratio: Ratio { mu_ratio: mu, reduction: 1.0 - mu },
        steps: run.steps,
        springs,
        period_change: run.period_change,
    })
}

/// The stop operator's update over one step, the scheme for oscillation in
/// the sliding direction: the force moves with the body by `dx` and is held in
/// `[-b, b]` (a slip either way); out of contact (`b <= 0`) it is 0.
#[inline]
pub(crate) fn update_two_way(f: f64, b: f64, dx: f64) -> f64 {
    if b > 0.0 {
        (f + dx).clamp(-b, b)
    } else {
        0.0
    }
}

/// Periods the oscillation peer runs: from a sliding start every spring
/// slips forward within the first period, which fixes its state.
pub(crate) const OSCILLATION_PERIODS: usize = 3;

/// `mu_macro/mu0` under oscillation in the sliding direction
/// ([`crate::combined`]) by time stepping: `st.springs` springs at the
/// midpoints of `0 <= z < reach(amp)` (one for the flat punch), each with the
/// bound `(1 - G(z) - amp cos tau)_+`, all moved by the body's
/// `X(tau) = vhat tau + T sin(tau + phase)` step by step
/// (`update_two_way`), started sliding (`f = B` at `tau = 0`); the means of
/// the last of `periods` periods (rectangle rule on the periodic state).
///
/// # Errors
/// [`Error::InvalidParameter`] for bad inputs or resolutions beyond the limits;
/// [`Error::Internal`] for a non-finite result.
pub(crate) fn evaluate_oscillation(
    shape: &Shape,
    c: &crate::Conditions,
    st: Stepping,
    periods: usize,
) -> Result<SteppingEvaluation> {
    let o = crate::combined::Oscillation::of(c);
    if periods == 0 || periods > 1000 {
        return Err(Error::param("periods", periods as f64, "must be between 1 and 1000"));
    }
    let levels = levels(shape, o.amp, st)?;
    let count = levels.len();
    let m = st.steps_per_period;
    let h = TAU / m as f64;
    let x_step = |k: usize| {
        // X(tau_k) - X(tau_{k-1}), without cancellation.
        let (a, b) = (h * (k - 1) as f64, h * k as f64);
        o.vhat * h + 2.0 * o.tangential_amp * (0.5 * (a + b) + o.phase).cos() * (0.5 * h).sin()
    };
    let chunk_sums = |start: usize| -> [f64; 4] {
        let cs = &levels[start..(start + CHUNK).min(count)];
        let mut f: Vec<f64> = cs.iter().map(|&ci| (ci - o.amp).max(0.0)).collect();
        let mut out = [0.0; 4];
        for p in 0..periods {
            let (mut ft, mut fnn) = (Kahan::default(), Kahan::default());
            for k in 1..=m {
                let tau = h * k as f64;
                let (ct, dx) = (tau.cos(), x_step(k));
                let (mut s_t, mut s_n) = (0.0, 0.0);
                for (fi, &ci) in f.iter_mut().zip(cs) {
                    let b = ci - o.amp * ct;
                    *fi = update_two_way(*fi, b, dx);
                    s_t += *fi;
                    s_n += b.max(0.0);
                }
                ft.add(s_t);
                fnn.add(s_n);
            }
            // The last period in out[2..], the one before in out[..2].
            if p + 1 == periods {
                (out[2], out[3]) = (ft.sum, fnn.sum);
            } else if p + 2 == periods {
                (out[0], out[1]) = (ft.sum, fnn.sum);
            }
        }
        out
    };
    let starts: Vec<usize> = (0..count).step_by(CHUNK).collect();
    let sums = crate::numerics::par::map(&starts, |&s| chunk_sums(s))
        .into_iter()
        .fold([0.0; 4], |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]);
    let mu = |t: f64, n: f64| if n > 0.0 { t / n } else { 1.0 };
    let last = mu(sums[2], sums[3]);
    if !last.is_finite() {
        return Err(Error::Internal { what: format!("time stepping gave mu_ratio = {last:?}") });
    }
    Ok(SteppingEvaluation {
        ratio: Ratio { mu_ratio: last, reduction: 1.0 - last },
        steps: (periods * m) as u64,
        springs: count,
        period_change: if periods >= 2 { (last - mu(sums[0], sums[1])).abs() } else { f64::NAN },
    })
}

/// The levels `1 - G(z)` of `st.springs` springs at the midpoints of the
/// part of `shape` that touches at amplitude `amp` (the flat punch: one, at
/// 1), the resolution checked first.
pub(crate) fn levels(shape: &Shape, amp: f64, st: Stepping) -> Result<Vec<f64>> {
    st.check(shape)?;
    let c = shape.contact();
    if c.single_spring() {
        return Ok(vec![1.0]);
    }
    let count = st.springs.max(1);
    let dz = c.reach(amp)? / count as f64;
    Ok((0..count).map(|i| 1.0 - c.equivalent_profile((i as f64 + 0.5) * dz)).collect())
}

pub use super::stepper2d::{rigid_limit, transverse, TransverseStepping};

/// `mu_macro/mu0` of `shape` on a system with mass and stiffness
/// ([`crate::system`]) by time stepping, the independent check of its exact
/// solver: from the stated start (the body at the drive's position with its
/// velocity, every spring relaxed) `periods` periods of `steps_per_period`
/// steps, each the body's velocity then position (semi-implicit Euler, first
/// order) and every contact force moved by the body's step and held in
/// `[-B, B]` (as under a tangential oscillation); the mean over the last
/// period. A curved body is the same [`crate::system::System::springs`]
/// springs as the exact solver's finer discretisation. The attractor must be
/// reached within the periods run (a period-1 orbit is assumed: the last
/// period is the answer).
///
/// The system is the conditions' ([`crate::Conditions::with_system`]).
///
/// # Errors
/// [`Error::InvalidParameter`] for conditions without a system, a massless
/// body (`Omega = 0`: no dynamics to step) or resolutions beyond the limits.
pub fn system(shape: &crate::Shape, c: &crate::Conditions, steps_per_period: usize, periods: usize) -> Result<f64> {
    let Some(sys) = c.system() else {
        return Err(Error::param(
            "system-stiffness",
            0.0,
            "the stepping peer with a body needs conditions on a system",
        ));
    };
    let om = sys.frequency_ratio();
    if om == 0.0 {
        return Err(Error::param("frequency-ratio", om, "stepping needs a body with mass (> 0)"));
    }
    let springs = crate::system::banded_springs(shape, c, sys)?;
    let work = steps_per_period as u128 * periods as u128 * springs.len() as u128;
    if steps_per_period == 0 || periods == 0 || work > MAX_STEPPING_WORK {
        return Err(Error::param(
            "steps-per-period",
            steps_per_period as f64,
            "steps x periods x springs must be in 1..=1e11",
        ));
    }
    let (t, phase) = c.tangential().unwrap_or((0.0, 0.0));
    let (vhat, amp, kappa) = (c.as_vhat(), c.amp(), sys.stiffness());
    let damp = 2.0 * sys.damping() * kappa.sqrt() * om;
    let drive = |tau: f64| (vhat * tau + t * (tau + phase).sin(), vhat + t * (tau + phase).cos());
    let h = TAU / steps_per_period as f64;
    let (mut x, mut v) = drive(0.0);
    let mut f = vec![0.0; springs.len()];
    let (mut sum_f, mut sum_b) = (0.0, 0.0);
    for k in 1..=steps_per_period * periods {
        let tau = h * (k - 1) as f64;
        let (xd, vd) = drive(tau);
        let total: f64 = springs.iter().zip(&f).map(|((w, _), fi)| w * fi).sum();
        v += h * (kappa * (xd - x) - damp * (v - vd) - total) / (om * om);
        x += h * v;
        let cos = amp * (h * k as f64).cos();
        for ((w, b), fi) in springs.iter().zip(f.iter_mut()) {
            *fi = update_two_way(*fi, b - cos, h * v);
            if k > steps_per_period * (periods - 1) {
                sum_f += w * *fi;
                sum_b += w * (b - cos).max(0.0);
            }
        }
    }
    Ok(sum_f / sum_b)
}
