//! The period map's derivative along its solution (the variational
//! equation), for Newton and the Floquet multipliers, for any set of springs.
//!
//! The map's state at `tau = 0` is the body `(x, x')` and the level `l_i` of
//! each spring stuck there (a slipping or free spring's force is fixed by the
//! drive). A perturbation at a fixed time moves only `(x, x', int f)` and the
//! levels: the drive's `(1, tau, cos tau, sin tau)` are the same on every
//! solution. The force `F = sum_stuck w_i (x - l_i + b_i) + ...` reads the
//! levels only through `L = sum_stuck w_i l_i`, constant within a phase, so
//! over a phase of length `h` the perturbation of `(x, x', int f, L)` is
//! `exp(B h)` of it: `B` is the generator's upper left 4 x 4 block (the
//! generator is block triangular: the drive's rows read nothing of the body)
//! with the column of `L`, `(0, 1/Omega^2, -1, 0)` (`F` falls by `dL`).
//!
//! At an event where `g` falls through 0 the generator changes from `A-` to
//! `A+`, and the state may be reset linearly, `z+ = R z-`. A perturbation
//! moves the event by `dt = -dg / g'`, and across it (the saltation matrix)
//! `dz+ = R dz- + (A+ R z - R A- z) dt`. Here the bracket is 0 at every
//! event: the total force is continuous (a spring's stick ends where its
//! force reaches `+-B_i`, the slip's force; a slip ends with the stick's
//! force equal to it), which makes the rows of `x'` and `int f` agree; `x`'s
//! row is `x'` on both sides; and a level is constant while its spring
//! sticks, while the level a slip sets, `x +- amp cos tau`, moves at `x' -+
//! B'`, the slip's event function, 0 there. So `dz+ = R dz-`: a spring that
//! sticks or touches again takes the level `x` plus a term the drive fixes
//! (`dl_i = dx`), one that slips or leaves drops its level. Contact is
//! gained and lost at fixed times (the zeros of `B_i`). Across a held phase
//! (a force riding on its bound, `MAX_FLIPS`) the map is not
//! differentiable: the derivative is unknown ([`Tangent::get`] is `None`),
//! and the caller differentiates the map by differences.

use super::phase::{Generator, Params, V, X, Y0};
use super::springs::Spring;
use nalgebra::{Dyn, Matrix4, OMatrix, RowDVector, U4};

/// The row of `L`, the stuck springs' weighted levels, in the body's block.
const L: usize = Y0;

/// The derivative of `(x, x', int f, L)`, a row each, by the start's components.
pub(crate) type Body = OMatrix<f64, U4, Dyn>;

/// The accumulated derivative of `(x, x', int f, L)` and of each stuck
/// spring's level by the state at the start.
pub(crate) struct Tangent {
    /// `d (x, x', int f, L) / d start`, 4 rows.
    body: Body,
    /// Where a step's product is made (then swapped in).
    scratch: Body,
    /// `d l_i / d start` of each spring stuck now (`None`: not stuck).
    levels: Vec<Option<RowDVector<f64>>>,
    known: bool,
}

impl Tangent {
    /// The identity at the start `(x, x', l_i of the springs stuck there)`:
    /// the columns are `x`, `x'` and those levels in the springs' order
    /// (weights `w`).
    pub(crate) fn new(w: &[f64], springs: &[Spring]) -> Tangent {
        let stuck: Vec<usize> = (0..springs.len()).filter(|&i| matches!(springs[i], Spring::Stuck { .. })).collect();
        let columns = 2 + stuck.len();
        let mut body = Body::zeros(columns);
        (body[(X, 0)], body[(V, 1)]) = (1.0, 1.0);
        let mut levels = vec![None; springs.len()];
        for (c, &i) in stuck.iter().enumerate() {
            let mut row = RowDVector::zeros(columns);
            row[2 + c] = 1.0;
            body[(L, 2 + c)] = w[i];
            levels[i] = Some(row);
        }
        let scratch = body.clone();
        Tangent { body, scratch, levels, known: true }
    }

    /// The derivative of `(x, x', int f, L)` so far (`None` where it is not
    /// known: a held phase), and that of each stuck spring's level.
    pub(crate) fn get(&self) -> Option<(&Body, &[Option<RowDVector<f64>>])> {
        (self.known && self.body.iter().all(|x| x.is_finite())).then_some((&self.body, &self.levels))
    }

    /// A step of length `h` in the phase with generator `a` (`exp` the
    /// block's exponential over `h` where made already, [`block`]).
    pub(crate) fn step(&mut self, p: &Params, a: &Generator, h: f64, exp: Option<&Matrix4<f64>>) {
        let e = match exp {
            Some(e) => *e,
            None => (block(p, a) * h).exp(),
        };
        e.mul_to(&self.body, &mut self.scratch);
        std::mem::swap(&mut self.body, &mut self.scratch);
    }

    /// Spring `i` (weight `w`) changed from `old` to `new`: a spring that
    /// sticks or touches takes `dl = dx`, one that slips or leaves drops its level.
    pub(crate) fn change(&mut self, i: usize, w: f64, old: Spring, new: Spring) {
        let stuck = |s: Spring| matches!(s, Spring::Stuck { .. });
        if stuck(old) {
            if let Some(row) = self.levels[i].take() {
                let sum = self.body.row(L) - row * w;
                self.body.set_row(L, &sum);
            }
        }
        if stuck(new) {
            let row = self.body.row(X).into_owned();
            let sum = self.body.row(L) + &row * w;
            self.body.set_row(L, &sum);
            self.levels[i] = Some(row);
        }
    }

    /// A phase held across an event: the map is not differentiable there.
    pub(crate) fn lose(&mut self) {
        self.known = false;
    }
}

/// The generator of `(x, x', int f, L)` in the phase `a` (module docs).
pub(crate) fn block(p: &Params, a: &Generator) -> Matrix4<f64> {
    let mut b = a.fixed_view::<4, 4>(0, 0).into_owned();
    b.set_column(L, &nalgebra::Vector4::new(0.0, 1.0 / (p.omega * p.omega), -1.0, 0.0));
    b
}

#[cfg(test)]
mod tests {
    use crate::system::orbit::jacobian;
    use crate::system::phase::Params;
    use crate::system::reduced::{foundation, map_k, map_k_tangent, stated_start};

    /// The variational equation's derivatives of the period map and of `int
    /// f` are those of forward differences of the map (independent of
    /// them: the map run again from states moved by 1e-6), at states of the
    /// transient of bodies that stick and slip forward, lose contact, slip
    /// backward under a tangential drive, over one period and two.
    #[test]
    fn the_tangent_is_the_maps_derivative() {
        let base = Params { kappa: 1.0, omega: 0.5, zeta: 0.05, vhat: 0.3, amp: 0.5, t: 0.0, phase: 0.0 };
        let cases = [
            (base, 1),
            (Params { kappa: 2.0, omega: 0.7, zeta: 0.1, vhat: 0.4, amp: 1.5, ..base }, 1),
            (Params { vhat: 0.2, amp: 0.8, t: 2.0, phase: 1.0, ..base }, 1),
            (Params { kappa: 0.5, omega: 1.2, zeta: 0.02, ..base }, 2),
        ];
        let mut worst = 0.0f64;
        for (p, k) in cases {
            let fd = foundation(p);
            let mut s = stated_start(&fd);
            for n in 0..6 {
                let (mapped, derivatives) = map_k_tangent(&fd, &s, k);
                let (jac, grad) = derivatives.expect("no held phase");
                assert_eq!(mapped, map_k(&fd, &s, k), "{p:?}");
                let (fd_jac, fd_grad) = jacobian(&fd, &s, k, &mapped);
                let scale = 1.0 + fd_jac.amax().max(fd_grad.amax());
                let off = (&jac - &fd_jac).amax().max((&grad - &fd_grad).amax()) / scale;
                worst = worst.max(off);
                assert!(off < 2e-5, "{p:?} period {n}: {jac} {fd_jac} {grad} {fd_grad}");
                s = mapped.0;
            }
        }
        eprintln!("worst {worst:e}");
    }
}
