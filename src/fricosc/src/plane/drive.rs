//! What one spring in the plane sees: the body's position `X(tau)` and the
//! Coulomb bound `B(tau) = (c - amp cos tau)_+`, as values and as power series
//! about any `tau0`.

use super::series::Series;
use std::f64::consts::{PI, TAU};

/// The body's position, per component `i`: `X_i(tau) = v_i tau + s_i sin
/// tau + c_i cos tau`. Sliding along `x` with an oscillation in the sliding
/// direction and one across it is `v = (vhat, 0)`, `s = (T cos phase, W cos
/// psi)` and `c = (T sin phase, W sin psi)`; any rotation of it is one too.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Drive {
    pub(crate) v: [f64; 2],
    pub(crate) s: [f64; 2],
    pub(crate) c: [f64; 2],
}

impl Drive {
    /// Sliding at `vhat` along `x`, `T sin(tau + phase)` along it and `W sin(tau + psi)` across.
    pub(crate) fn sliding(vhat: f64, t: f64, phase: f64, w: f64, psi: f64) -> Drive {
        let (sp, cp) = phase.sin_cos();
        let (sq, cq) = psi.sin_cos();
        Drive { v: [vhat, 0.0], s: [t * cp, w * cq], c: [t * sp, w * sq] }
    }

    /// `X'(tau)`.
    pub(crate) fn velocity_at(&self, tau: f64) -> [f64; 2] {
        let (s, c) = tau.sin_cos();
        [0, 1].map(|i| self.v[i] + self.s[i] * c - self.c[i] * s)
    }

    /// `X''(tau)`.
    pub(crate) fn acceleration_at(&self, tau: f64) -> [f64; 2] {
        let (s, c) = tau.sin_cos();
        [0, 1].map(|i| -self.s[i] * s - self.c[i] * c)
    }

    /// `X'(tau0 + t)` from the series of `cos` and `sin` at `tau0`.
    pub(crate) fn velocity(&self, cos: &Series, sin: &Series) -> [Series; 2] {
        [0, 1].map(|i| Series::constant(self.v[i]) + *cos * self.s[i] - *sin * self.c[i])
    }

    /// `X(tau0 + t) - X(tau0)`, with no constant term.
    pub(crate) fn displacement(&self, cos: &Series, sin: &Series) -> [Series; 2] {
        [0, 1].map(|i| {
            let mut d = (*sin * self.s[i] + *cos * self.c[i]).without_constant();
            d.0[1] += self.v[i];
            d
        })
    }
}

/// The Coulomb bound `B(tau) = (level - amp cos tau)_+` of one spring (the
/// flat punch: `level = 1`), evaluated in factored forms that keep full
/// relative accuracy where it vanishes: `(level - amp) + 2 amp sin^2(tau/2)`
/// while the spring never leaves contact, `2 amp sin((r + t_c)/2) sin((r -
/// t_c)/2)` (`r` the phase reduced to `(-pi, pi]`, `t_c = arccos(level/amp)`)
/// when it does, in contact for `t_c < |r|`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bound {
    pub(crate) level: f64,
    pub(crate) amp: f64,
    /// `t_c`, where the spring leaves contact (`amp > level`).
    pub(crate) edge: Option<f64>,
}

impl Bound {
    pub(crate) fn new(level: f64, amp: f64) -> Bound {
        let edge = (amp > level).then(|| (level / amp).acos());
        Bound { level, amp, edge }
    }

    /// `B(tau)`, 0 out of contact.
    pub(crate) fn at(&self, tau: f64) -> f64 {
        let r = reduce(tau);
        match self.edge {
            None => (self.level - self.amp) + 2.0 * self.amp * (0.5 * r).sin().powi(2),
            Some(e) if r.abs() > e => 2.0 * self.amp * (0.5 * (r + e)).sin() * (0.5 * (r - e)).sin(),
            Some(_) => 0.0,
        }
    }

    /// `B(tau0 + t)` (the analytic continuation through the edges).
    pub(crate) fn series(&self, tau0: f64, cos: &Series) -> Series {
        let mut b = *cos * -self.amp;
        b.0[0] = self.analytic_at(tau0);
        b
    }

    /// `level - amp cos tau` in its factored form, negative out of contact.
    fn analytic_at(&self, tau: f64) -> f64 {
        let r = reduce(tau);
        match self.edge {
            None => self.at(tau),
            Some(e) => 2.0 * self.amp * (0.5 * (r + e)).sin() * (0.5 * (r - e)).sin(),
        }
    }

    /// The distance from the real `tau0` to the nearest zero of the analytic
    /// `level - amp cos tau`: complex, `2 pi k +- i arccosh(level/amp)`, while
    /// in contact always; real, `+-t_c + 2 pi k`, otherwise.
    pub(crate) fn singularity_distance(&self, tau0: f64) -> f64 {
        let r = reduce(tau0);
        match self.edge {
            Some(e) => (r.abs() - e).abs(),
            None if self.amp == 0.0 => f64::INFINITY,
            None => {
                let x = (self.level - self.amp) / self.amp;
                let im = (x + (x * (x + 2.0)).sqrt()).ln_1p();
                r.hypot(im)
            }
        }
    }

    /// `int B` over one period.
    pub(crate) fn period_integral(&self) -> f64 {
        if self.amp == 0.0 {
            TAU * self.level
        } else {
            TAU * self.amp * crate::model::spring::mean_normal(self.level / self.amp)
        }
    }

    /// The next zero of `B` after `tau` where contact is lost and the next where
    /// it is gained (a touch, `amp = level`, is both at `2 pi k`); `None`
    /// while the spring never leaves contact.
    pub(crate) fn next_loss(&self, tau: f64) -> Option<f64> {
        let e = match self.edge {
            Some(e) => e,
            None if self.amp == self.level => 0.0,
            None => return None,
        };
        // From the period of `tau` (rounded down, so that a `tau` an ulp
        // before a loss does not skip it), a period at a time.
        let mut t = TAU * ((tau + e) / TAU).floor() - e;
        while t <= tau {
            t += TAU;
        }
        Some(t)
    }
}

/// `tau` reduced to `(-pi, pi]`.
pub(crate) fn reduce(tau: f64) -> f64 {
    let r = tau - TAU * (tau / TAU).round();
    if r <= -PI {
        r + TAU
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The next loss from an ulp before a loss is that loss, not the next
    /// period's (`tau + t_c` rounds up to `2 pi` there).
    #[test]
    fn the_next_loss_from_an_ulp_before_it() {
        let b = Bound::new(0.42230932523727416, 1.5);
        let loss = TAU - b.edge.unwrap();
        let before = loss - loss * f64::EPSILON;
        assert_eq!(b.next_loss(before), Some(loss));
        assert_eq!(b.next_loss(loss), Some(loss + TAU));
        assert_eq!(b.next_loss(0.0), Some(loss));
    }
}
