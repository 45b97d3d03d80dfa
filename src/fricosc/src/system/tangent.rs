//! The period map's derivative along its solution (the variational
//! equation), for Newton and the Floquet multipliers.
//!
//! A perturbation `dz` of the state at a fixed time moves only
//! `(x, x', int f, y0)`, the first four components: the drive's `(1, tau,
//! cos tau, sin tau)` are the same on every solution. The generator is block
//! triangular (those four rows read nothing of the first four), so over a
//! phase of length `h` the perturbation is `exp(A11 h) dz`, `A11` the
//! generator's upper left 4 x 4 block.
//!
//! At an event where `g` falls through 0 the generator changes from `A-` to
//! `A+`, and the state may be reset linearly, `z+ = R z-`. A perturbation
//! moves the event by `dt = -dg / g'`, and across it (the saltation matrix)
//! `dz+ = R dz- + (A+ R z - R A- z) dt`. Here the bracket is 0 at every
//! event, so `dz+ = R dz-`: the contact force is continuous (a stick ends
//! where `f` reaches `+-B`, the slip's force; a slip ends with the stick's
//! `f = x - y0 = +-B`), which makes the rows of `x'` and `int f` agree; `x`'s
//! row is `x'` on both sides; and `y0` is constant in a stick, while `R`'s
//! `y0 = x -+ B` moves at `x' -+ B'`, the slip's event function, 0 there. `R`
//! is the identity but where a spring sticks or touches again (`y0` is then
//! `x` less a force the drive fixes, so `dy0 = dx`). Contact is gained and
//! lost at fixed times (the zeros of `B`). Across a held phase (a force
//! riding on its bound, `MAX_FLIPS`) the map is not differentiable: the
//! derivative is unknown ([`Tangent::get`] is `None`), and the caller
//! differentiates the map by differences.

use super::phase::{Generator, X, Y0};
use nalgebra::Matrix4;

/// The accumulated derivative `d z(tau) / d z(0)` of the first four components.
pub(crate) struct Tangent {
    m: Matrix4<f64>,
    known: bool,
}

impl Tangent {
    /// The identity: nothing run yet.
    pub(crate) fn new() -> Tangent {
        Tangent { m: Matrix4::identity(), known: true }
    }

    /// The derivative so far, `None` where it is not known (a held phase).
    pub(crate) fn get(&self) -> Option<Matrix4<f64>> {
        (self.known && self.m.iter().all(|x| x.is_finite())).then_some(self.m)
    }

    /// A step of length `h` in the phase with generator `a` (`exp` its
    /// exponential over `h` where made already), at whose end a spring
    /// sticks or touches again where `relax` ([`Tangent::relax`]).
    pub(crate) fn step(&mut self, a: &Generator, h: f64, exp: Option<&Generator>, relax: bool) {
        let e = match exp {
            Some(e) => e.fixed_view::<4, 4>(0, 0).into_owned(),
            None => (a.fixed_view::<4, 4>(0, 0) * h).exp(),
        };
        self.m = e * self.m;
        if relax {
            self.relax();
        }
    }

    /// A spring sticks (at an event) or touches again (at a fixed time):
    /// `y0` is `x` less a force the drive fixes, so `dy0 = dx`.
    fn relax(&mut self) {
        let x = self.m.row(X).into_owned();
        self.m.set_row(Y0, &x);
    }

    /// A phase held across an event: the map is not differentiable there.
    pub(crate) fn lose(&mut self) {
        self.known = false;
    }
}

#[cfg(test)]
mod tests {
    use crate::system::orbit::jacobian;
    use crate::system::period::Phases;
    use crate::system::phase::Params;
    use crate::system::{map_k, map_k_tangent, stated_start};

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
            let ph = Phases::new(p);
            let mut s = stated_start(&p);
            for n in 0..6 {
                let (mapped, derivatives) = map_k_tangent(&ph, &s, k);
                let (jac, grad) = derivatives.expect("no held phase");
                assert_eq!(mapped, map_k(&ph, &s, k), "{p:?}");
                let (fd_jac, fd_grad) = jacobian(&ph, &s, k, &mapped);
                let scale = 1.0 + fd_jac.amax().max(fd_grad.amax());
                let off = (jac - fd_jac).amax().max((grad - fd_grad).amax()) / scale;
                worst = worst.max(off);
                assert!(off < 2e-5, "{p:?} period {n}: {jac} {fd_jac} {grad} {fd_grad}");
                s = mapped.0;
            }
        }
        eprintln!("worst {worst:e}");
    }

    /// Across a held phase (a regain of contact as fast as the bound grows,
    /// `tests/library/system.rs`'s held case) the derivative is unknown, and
    /// known in every period that holds nothing.
    #[test]
    fn a_held_phase_has_no_derivative() {
        let p = Params {
            kappa: 0.337_820_789_648_731_2,
            omega: 0.168_419_513_808_616_25,
            zeta: 0.1,
            vhat: 0.061_192_540_819_875_59,
            amp: 1.124_000_596_964_073_4,
            t: 0.0,
            phase: 0.0,
        };
        let ph = Phases::new(p);
        let mut s = stated_start(&p);
        let mut held = 0;
        for _ in 0..120 {
            let before = ph.held();
            let (mapped, derivatives) = map_k_tangent(&ph, &s, 1);
            let holds = ph.held() > before;
            held += usize::from(holds);
            assert_eq!(derivatives.is_none(), holds);
            s = mapped.0;
        }
        assert!(held > 10, "{held}");
    }
}
