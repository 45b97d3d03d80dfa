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

use std::f64::consts::TAU;

/// Period means from a time-stepping run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteppedMeans {
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
    pub fn mu_ratio(&self) -> f64 {
        if self.normal > 0.0 {
            self.tangential / self.normal
        } else {
            1.0
        }
    }
}

/// Run the scheme for springs with positions `s[i]` and weights `weight[i]`.
///
/// `steps_per_period >= 1`, `periods >= 2`. Cost: `periods * steps_per_period * s.len()`
/// updates, one `cos` per step.
pub fn run(s: &[f64], weight: &[f64], vbar: f64, steps_per_period: usize, periods: usize) -> SteppedMeans {
    assert_eq!(s.len(), weight.len());
    let m = steps_per_period.max(1);
    let periods = periods.max(2);
    let h = TAU / m as f64;
    let dv = vbar * h;
    // Sliding initial state at tau = 0.
    let mut f: Vec<f64> = s.iter().map(|&si| (si - 1.0).max(0.0)).collect();
    let (mut prev_mu, mut mu, mut t_sum, mut n_sum) = (f64::NAN, f64::NAN, 0.0, 0.0);
    for p in 0..periods {
        let (mut ft, mut fn_) = (0.0, 0.0);
        for k in 1..=m {
            let c = (h * k as f64).cos();
            for ((fi, &si), &wi) in f.iter_mut().zip(s).zip(weight) {
                let b = si - c;
                *fi = if b > 0.0 { (*fi + dv).min(b) } else { 0.0 };
                ft += wi * *fi;
                fn_ += wi * b.max(0.0);
            }
        }
        prev_mu = mu;
        mu = if fn_ > 0.0 { ft / fn_ } else { 1.0 };
        if p + 1 == periods {
            t_sum = ft / m as f64;
            n_sum = fn_ / m as f64;
        }
    }
    SteppedMeans {
        tangential: t_sum,
        normal: n_sum,
        period_change: (mu - prev_mu).abs(),
        steps: (periods * m) as u64,
    }
}

/// `mu_macro/mu0` of a flat punch by time stepping.
pub fn flat_mu_ratio(vbar: f64, amp: f64, steps_per_period: usize) -> SteppedMeans {
    // In units of kz u0 the bound is (1 - amp cos tau)_+ = amp (s - cos tau)_+.
    let s = if amp > 0.0 { 1.0 / amp } else { f64::MAX };
    run(&[s], &[1.0], vbar, steps_per_period, 2)
}
