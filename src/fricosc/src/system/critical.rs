//! Where friction's reduction vanishes on a system: the least `vbar` from
//! which every spring slips forward for ever (`mu = 1`).
//!
//! In pure forward slip every spring in contact carries its bound, so the
//! force is known in advance, `F(tau) = sum_i w_i (b_i - amp cos tau)_+`
//! (the springs of [`super::solve`]'s finer discretisation), whatever the
//! body does, and the body's equation is linear. Its steady response is `x =
//! vhat tau + x_0 + y(tau)`: the drive's `vhat tau` is answered exactly (the
//! spring's `kappa vhat tau` and the dashpot's `c vhat` cancel in `x - X_d`
//! and `x' - X_d'`), and `y` is the periodic response to `-F` at `vhat = 0`.
//! A spring in contact slips forward as long as its contact point moves
//! forward, `x' >= B_i' = amp sin tau`, the same for every spring; the
//! centre (`b = 1`) is the longest in contact. So pure slip holds from
//!
//! `vhat_c = max over the centre's contact of (amp sin tau - y'(tau))`,
//!
//! and `vbar_c = vhat_c / amp` (0 where the maximum is negative: the
//! reduction vanishes at every velocity, as at the stick resonance). For the
//! flat punch without contact loss `y` is one harmonic and
//! `vbar_c = |kappa + 1 - Omega^2 + i c| / |kappa - Omega^2 + i c|`
//! (`c = 2 zeta sqrt(kappa) Omega`): 1 on a stiff system, `(1 + kappa)/kappa`
//! on a massless one (the springs in series). Where the slip's period map
//! has a multiplier 1 (an undamped slip resonance) there is no steady slip:
//! none.

use super::phase::{advance, Linear, Params, State, COS, SIN, V, X};
use super::System;
use crate::conditions::Conditions;
use crate::error::Result;
use nalgebra::{Matrix2, Vector2};
use std::f64::consts::TAU as TWO_PI;

/// The least `vbar` from which `mu = 1` on `sys` at amplitude `amp` (no
/// tangential drive), or `None` where steady slip has no periodic response.
///
/// ```
/// use fricosc::system::{critical_vbar, System};
/// use fricosc::Shape;
/// // A massless body: the springs in series, vbar_c = (1 + kappa)/kappa.
/// let massless = critical_vbar(&Shape::flat(), 0.5, &System::new(1.0, 0.0, 0.0)?)?;
/// assert!((massless.unwrap() - 2.0).abs() < 1e-14);
/// # Ok::<(), fricosc::Error>(())
/// ```
///
/// # Errors
/// As [`crate::Shape::report`] on a system for the shape and the amplitude.
pub fn critical_vbar(shape: &crate::Shape, amp: f64, sys: &System) -> Result<Option<f64>> {
    // The amplitude checked as every point's is; the drive at rest (module docs).
    Conditions::vhat(0.0, amp)?;
    shape.check_amp(amp)?;
    if amp == 0.0 {
        return Ok(Some(0.0));
    }
    let p = Params {
        kappa: sys.stiffness,
        omega: sys.frequency_ratio,
        zeta: sys.damping,
        vhat: 0.0,
        amp,
        t: 0.0,
        phase: 0.0,
    };
    let springs = super::springs(shape, amp, sys.springs)?;
    let lag = if p.omega == 0.0 {
        massless_lag(&p, &pieces(&p, &springs))
    } else {
        let Some(slip) = Slip::new(p, &springs) else { return Ok(None) };
        slip.max_lag()
    };
    Ok(Some((lag / amp).max(0.0)))
}

/// The pieces of a period between the contact changes of `springs` (`(w_i,
/// b_i)`), each with the force of its springs in forward slip.
fn pieces(p: &Params, springs: &[(f64, f64)]) -> Vec<(f64, f64, Linear)> {
    let mut cuts: Vec<f64> = vec![0.0, TWO_PI];
    for &(_, b) in springs {
        if b < p.amp {
            let gain = (b / p.amp).clamp(-1.0, 1.0).acos();
            cuts.extend([gain, TWO_PI - gain]);
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    cuts.windows(2)
        .map(|w| {
            let mid = 0.5 * (w[0] + w[1]);
            let touching = springs.iter().filter(|&&(_, b)| b - p.amp * mid.cos() > 0.0);
            let (sw, swb) = touching.fold((0.0, 0.0), |(a, c), &(wi, bi)| (a + wi, c + wi * bi));
            (w[0], w[1], Linear { one: swb, cos: -p.amp * sw, ..Linear::default() })
        })
        .collect()
}

/// A massless body follows its force: `kappa (X_d - x) = F`, so `y' = -F'/kappa`
/// and the lag is `amp sin tau (1 + W(tau)/kappa)`, `W` the weight in contact.
fn massless_lag(p: &Params, pieces: &[(f64, f64, Linear)]) -> f64 {
    let (on, off) = contact_of_centre(p.amp);
    let mut best = f64::NEG_INFINITY;
    for &(a, b, f) in pieces {
        let (lo, hi) = (a.max(on), b.min(off));
        if lo < hi {
            let top = if (lo..=hi).contains(&std::f64::consts::FRAC_PI_2) { 1.0 } else { lo.sin().max(hi.sin()) };
            best = best.max(p.amp * top * (1.0 - f.cos / (p.amp * p.kappa)));
        }
    }
    best
}

/// Where the centre (`b = 1`) is in contact: `cos tau < 1/amp`.
fn contact_of_centre(amp: f64) -> (f64, f64) {
    if amp > 1.0 {
        ((1.0 / amp).acos(), TWO_PI - (1.0 / amp).acos())
    } else {
        (0.0, TWO_PI)
    }
}

/// The body in pure forward slip: the pieces of a period between the
/// springs' contact changes, each with its force, and the periodic state at
/// `tau = 0`.
struct Slip {
    p: Params,
    /// `(start, end, force)` of each piece.
    pieces: Vec<(f64, f64, Linear)>,
    start: State,
}

impl Slip {
    /// The pieces of `springs` (`(w_i, b_i)`) and the periodic response; `None`
    /// where the period map of the slip has a multiplier 1.
    fn new(p: Params, springs: &[(f64, f64)]) -> Option<Slip> {
        let mut slip = Slip { p, pieces: pieces(&p, springs), start: p.start() };
        // The period map is affine in (x, x'): its fixed point.
        let at = |x: f64, v: f64| {
            let mut z = p.start();
            (z[X], z[V]) = (x, v);
            let end = slip.period(z);
            Vector2::new(end[X], end[V])
        };
        let d = at(0.0, 0.0);
        let m = Matrix2::from_columns(&[at(1.0, 0.0) - d, at(0.0, 1.0) - d]);
        let lhs = Matrix2::identity() - m;
        let fixed = lhs.lu().solve(&d)?;
        if !fixed.iter().all(|x| x.is_finite()) || lhs.determinant().abs() < 1e-12 {
            return None;
        }
        (slip.start[X], slip.start[V]) = (fixed[0], fixed[1]);
        Some(slip)
    }

    /// The state after one period from `z` at `tau = 0`.
    fn period(&self, mut z: State) -> State {
        for &(a, b, f) in &self.pieces {
            z = advance(&self.p.generator_of(f), &z, b - a);
        }
        z
    }

    /// `max (amp sin tau - y'(tau))` over the centre's contact: sampled on
    /// each piece at the body's sampling step, each rise refined at the zero
    /// of its derivative.
    fn max_lag(&self) -> f64 {
        let amp = self.p.amp;
        let (on, off) = contact_of_centre(amp);
        let mut best = f64::NEG_INFINITY;
        let mut z = self.start;
        for &(a, b, f) in &self.pieces {
            let g = self.p.generator_of(f);
            let lag = |s: &State| amp * s[SIN] - s[V];
            let slope = |s: &State| amp * s[COS] - (g * s)[V];
            let (lo, hi) = (a.max(on), b.min(off));
            if lo < hi {
                let n = ((hi - lo) / super::springs::sampling_step(&g)).ceil().max(1.0) as usize;
                let h = (hi - lo) / n as f64;
                let at = |t: f64| advance(&g, &z, t - a);
                let states: Vec<State> = (0..=n).map(|k| at(lo + k as f64 * h)).collect();
                best = states.iter().map(lag).fold(best, f64::max);
                for (k, w) in states.windows(2).enumerate() {
                    if slope(&w[0]) > 0.0 && slope(&w[1]) < 0.0 {
                        let (t0, t1) = (lo + k as f64 * h, lo + (k + 1) as f64 * h);
                        let t = crate::numerics::root::bracketed(|t| slope(&at(t)), t0, t1, 4.0 * f64::EPSILON).x;
                        best = best.max(lag(&at(t)));
                    }
                }
            }
            z = advance(&g, &z, b - a);
        }
        best
    }
}
