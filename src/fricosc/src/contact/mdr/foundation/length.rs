//! Stick-first bands integrated in the stick's half-length `h` (where the
//! phase has a square-root branch at the band's bottom) and the contact
//! centre's band.

use super::*;

impl Foundation {
    /// Order-`m` Gauss-Legendre sums over the stick-first band's springs
    /// given by their stick's half-length `h` ([`Velocity::stick_first_by_half_length`]:
    /// no root to find), in `tau = sqrt(h_b - h)` (`h_b` the branch point
    /// above the band, [`Velocity::stick_branch_half_length`], where `sin phi`
    /// goes like `tau`: analytic in `tau`), held as `d = sqrt(h_b) - tau` in
    /// `[0, d_top]` from the band's bottom (`h = 0`), so that `h = d (2
    /// sqrt(h_b) - d) + (h_b - sqrt(h_b)^2)` keeps its digits at small
    /// sticks. The Jacobian is `|dz/du| |du/dh| 2 tau`.
    ///
    /// With `top` (the band's top spring and its phase `u_top`), the phase
    /// of the springs in the top half (`h >= h_top/2`) below
    /// [`FROM_TOP_PHASE`] is `u_top + d`, `d` from
    /// [`Velocity::phase_below_top`], and its sine and cosine are taken of
    /// that: `pi/2 - beta` keeps only its absolute accuracy, and the addition
    /// formulas' `sin u` cancels where `u` is small (the top `u = arcsin
    /// vbar` at small `vbar`: 190 eps at vbar 0.02).
    pub(in crate::contact::mdr) fn pass_length(
        &self,
        vel: &Velocity,
        h_b: f64,
        d_top: f64,
        top: Option<(&LengthTop, f64)>,
        m: usize,
    ) -> Pass {
        let r = quad::rule(m, 0.0);
        let half = 0.5 * d_top;
        let tau = Tau::new(h_b);
        let tau_top = tau.root - d_top;
        let mut acc = Acc::new(&r, self.active(Means::StickFirst));
        for &x in &r.nodes {
            let (d, t) = (half * (1.0 + x), half * (1.0 - x));
            let n = vel.stick_first_by_half_length_with(tau.h(d), self.tangential);
            let dh = 2.0 * (tau.root - d);
            let (beta, sin_u, cos_u, from_star) = self.length_phase(vel, &n, t * (2.0 * tau_top + t), top);
            let jac = dh * n.du_dh * self.jacobian(sin_u, cos_u, 0.0, from_star, Top::Regular);
            let b = if self.normal { mean_normal_sin_cos(beta, cos_u, sin_u) } else { 0.0 };
            let f = [jac * b, jac * n.means.deficit, jac * n.means.tangential];
            acc.add(f, jac * n.means.magnitude);
        }
        acc.finish(&r, if self.amp > 1.0 { half } else { self.amp * half })
    }

    /// The phase of [`Foundation::pass_length`]'s spring `n`, `rho` below the
    /// band's top in `h`: `(beta, sin u, cos u, u - u*)`, from the top where
    /// `top` is given (the top spring and its phase) and the spring lies in
    /// the top half with a phase below [`FROM_TOP_PHASE`], else `n`'s own.
    fn length_phase(
        &self,
        vel: &Velocity,
        n: &LengthNode,
        rho: f64,
        top: Option<(&LengthTop, f64)>,
    ) -> (f64, f64, f64, f64) {
        match top {
            Some((top, u_top)) if rho <= 0.5 * top.h && FRAC_PI_2 - n.beta < FROM_TOP_PHASE => {
                let below = vel.phase_below_top(top, rho, n, u_top);
                let u = u_top + below;
                let (su, cu) = libm::sincos(u);
                (FRAC_PI_2 - u, su, cu, (u_top - self.u_star) + below)
            }
            _ => (n.beta, n.sin_u, n.cos_u, (FRAC_PI_2 - n.beta) - self.u_star),
        }
    }

    /// The stick-first band `h` in `[0, h_top]` by [`Foundation::pass_length`],
    /// one piece from order [`LENGTH_FIRST_ORDER`] ([`MIN_ORDER`] at loose
    /// tolerances: from [`LOOSE_ORDER`], whose estimate claims no decay,
    /// `power:2.5` at vbar 0.2, amp 1.5 took as many nodes at tol 1e-6 as at
    /// the default).
    ///
    /// `u_top`: the top's phase, for [`Foundation::pass_length`]'s phases
    /// from the top (below [`FROM_TOP_PHASE`]).
    pub(in crate::contact::mdr) fn band_by_length(
        &self,
        vel: &Velocity,
        h_top: f64,
        u_top: f64,
        scale: [f64; MEANS],
    ) -> Sums {
        let h_b = vel.stick_branch_half_length();
        let d_top = h_b.sqrt() - (h_b - h_top).max(0.0).sqrt();
        let first = self.length_first_order();
        let top = small_top(vel, h_top, u_top);
        self.ladder().run(first, |m| self.pass_length(vel, h_b, d_top, top.as_ref().map(|t| (t, u_top)), m), scale)
    }

    /// Order-`m` Gauss-Jacobi sums over the whole stick-first band below the
    /// contact centre's threshold (`u` in `[u*, pi/2 + alpha]`, `h` in `[0,
    /// h*]`) in `tau = sqrt(h_b - h)` as [`Foundation::pass_length`], with the
    /// Jacobian's weight `(u - u*)^gamma` taken as `t^gamma`, `t = tau - tau*`
    /// from the top: `u - u*` is `t (2 tau* + t)` times an analytic positive
    /// factor ([`Velocity::phase_below_top`] gives it to full relative
    /// accuracy), so the node's Jacobian is `(1/n) (y/t)^gamma sin u |du/dh| 2
    /// tau`, with `y/t = (y/d) (d/t)`, `d = u - u*`.
    pub(in crate::contact::mdr) fn pass_centre_length(
        &self,
        vel: &Velocity,
        h_b: f64,
        top: &LengthTop,
        m: usize,
    ) -> Pass {
        let r = quad::rule(m, self.gamma);
        let tau = Tau::new(h_b);
        let tau_top = (h_b - top.h).sqrt();
        let half = 0.5 * (tau.root - tau_top);
        let k = 1.0 / self.n;
        let mut acc = Acc::new(&r, self.active(Means::StickFirst));
        for &x in &r.nodes {
            // x = -1 at the top (t = 0), +1 at the bottom (e = 0, h = 0).
            let (t, e) = (half * (1.0 + x), half * (1.0 - x));
            let n = vel.stick_first_by_half_length_with(tau.h(e), self.tangential);
            let rho = t * (2.0 * tau_top + t);
            let d = vel.phase_below_top(top, rho, &n, self.u_star);
            let (sum, s, c) = self.half_angles(d);
            let y_over_t = (2.0 * sum * s / d) * (d / t);
            let (beta, sin_u, cos_u) = self.centre_phase(&n, rho, top.h, d, (s, c));
            let jac = k * self.y_pow(y_over_t) * sin_u * n.du_dh * 2.0 * (tau.root - e);
            let b = if self.normal { mean_normal_sin_cos(beta, cos_u, sin_u) } else { 0.0 };
            let f = [jac * b, jac * n.means.deficit, jac * n.means.tangential];
            acc.add(f, jac * n.means.magnitude);
        }
        acc.finish(&r, half.powf(self.gamma + 1.0))
    }

    /// The phase of [`Foundation::pass_centre_length`]'s spring `n`, `rho`
    /// below the top `h*` in `h` and `d = u - u*` above `u*` in the phase
    /// (`half`: `sin(d/2)`, `cos(d/2)`): `(beta, sin u, cos u)`. In the top
    /// half below [`FROM_TOP_PHASE`], `u = u* + d`, `sin u = sin u* cos d +
    /// cos u* sin d` (both terms `>= 0` there) keeps the digits that the
    /// addition formulas' `sin u` loses where `u*` is small (as
    /// [`Foundation::length_phase`]); else `n`'s own.
    fn centre_phase(&self, n: &LengthNode, rho: f64, top_h: f64, d: f64, half: (f64, f64)) -> (f64, f64, f64) {
        if self.u_star < FROM_TOP_PHASE && rho <= 0.5 * top_h && FRAC_PI_2 - n.beta < FROM_TOP_PHASE {
            let (s, c) = half;
            let (sin_d, cos_d) = (2.0 * s * c, 1.0 - 2.0 * s * s);
            let (sin_star, cos_star) = self.star_sin_cos;
            ((FRAC_PI_2 - self.u_star) - d, sin_star * cos_d + cos_star * sin_d, cos_star * cos_d - sin_star * sin_d)
        } else {
            (n.beta, n.sin_u, n.cos_u)
        }
    }

    /// The stick-first band below the contact centre's threshold `u*` as one
    /// piece of [`Foundation::pass_centre_length`], where its singularities
    /// above the top lie at least [`CENTRE_WHOLE_DISTANCE`] of its width away
    /// in `tau`: `tau = -tau*` (the other root of `u = u*`) and the Jacobian's
    /// other branch point `u = -u*` (its distance in `tau` estimated from the
    /// slope at the top). `None` where they lie closer.
    pub(in crate::contact::mdr) fn band_centre_whole(&self, vel: &Velocity, scale: [f64; MEANS]) -> Option<Sums> {
        if self.u_star >= FRAC_PI_2 + vel.alpha {
            return None;
        }
        let h_b = vel.stick_branch_half_length();
        let top = vel.length_top(vel.stick_half_length_at(self.u_star));
        if top.h.is_nan() || top.h >= h_b {
            return None;
        }
        let tau_top = (h_b - top.h).sqrt();
        let span = h_b.sqrt() - tau_top;
        let slope = top.node.du_dh * 2.0 * tau_top;
        let near = (2.0 * tau_top).min(2.0 * self.u_star / slope);
        if near < CENTRE_WHOLE_DISTANCE * span {
            return None;
        }
        let first = self.length_first_order();
        Some(self.ladder().run(first, |m| self.pass_centre_length(vel, h_b, &top, m), scale))
    }

    /// A stick-first band whose top is the contact centre's threshold `u*`
    /// (`kind` [`Top::Centre`]): one Gauss-Jacobi piece in the stick's
    /// half-length where its singularities allow
    /// ([`Foundation::band_centre_whole`]); else graded towards `u*` in the
    /// phase as [`Foundation::band`] does, but its lowest piece, from the
    /// last cut (at least an eighth of the band's width below `u*`) to the
    /// bottom, in the half-length ([`Foundation::band_by_length`], its top
    /// found by one root). Without a cut (the branch point far),
    /// [`Foundation::band`].
    pub(in crate::contact::mdr) fn band_centre_by_length(
        &self,
        vel: &Velocity,
        top: f64,
        bottom: f64,
        near: (f64, f64),
        scale: [f64; MEANS],
    ) -> Sums {
        if let Some(s) = self.band_centre_whole(vel, scale) {
            return s;
        }
        let width = bottom - top;
        let (jac, above, below) = self.floored_distances(top, width, Top::Centre, near);
        let mut cuts = vec![top];
        grade(&mut cuts, jac, JACOBIAN_GRADE_RATIO * width, top, 1.0);
        grade(&mut cuts, above, GRADE_RATIO * width, top, 1.0);
        // Without a cut above, the band is split in half where the phase
        // would grade towards its bottom at least twice (the means'
        // singularity `near.1` below it, which the half-length does not see).
        if cuts.len() < 2 && below < CENTRE_SPLIT_BELOW * width {
            cuts.push(top + 0.5 * width);
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        let low = cuts[cuts.len() - 1];
        if cuts.len() < 2 || low >= bottom {
            return self.band(top, bottom, Top::Centre, Means::StickFirst, near, scale);
        }
        // The widest piece first: its sums set the scale of the others.
        let mut total = self.band_by_length(vel, vel.stick_half_length_at(low), low, scale);
        let mut pieces: Vec<(f64, f64)> = cuts.windows(2).map(|w| (w[0], w[1])).collect();
        pieces.sort_by(|a, b| (b.1 - b.0).total_cmp(&(a.1 - a.0)));
        for (a, b) in pieces {
            let k = if a == top { Top::Centre } else { Top::Regular };
            let sc = std::array::from_fn(|i| scale[i] + total.value[i].abs());
            total += self.piece(a, b, k, Means::StickFirst, sc);
        }
        total
    }
}

/// The half-length forms' variable `tau = sqrt(h_b - h)`, held as the
/// distance `e = sqrt(h_b) - tau` from the band's bottom (`h = 0`).
struct Tau {
    /// `sqrt(h_b)`.
    root: f64,
    /// `h_b - sqrt(h_b)^2`, exact (a fused multiply-add).
    residual: f64,
}

/// The top spring of a band in the half-length whose top phase `u_top` is
/// below [`FROM_TOP_PHASE`] (its springs near the top take their phase from
/// it: [`Foundation::length_phase`]), else `None`.
fn small_top(vel: &Velocity, h_top: f64, u_top: f64) -> Option<LengthTop> {
    (u_top < FROM_TOP_PHASE).then(|| vel.length_top(h_top))
}

impl Tau {
    fn new(h_b: f64) -> Self {
        let root = h_b.sqrt();
        Tau { root, residual: root.mul_add(-root, h_b) }
    }

    /// `h = h_b - tau^2 = e (2 sqrt(h_b) - e) + (h_b - sqrt(h_b)^2)`, which
    /// keeps its digits at small sticks (`e -> 0`).
    fn h(&self, e: f64) -> f64 {
        e * (2.0 * self.root - e) + self.residual
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`Foundation::length_phase`] and [`Foundation::centre_phase`] keep
    /// `sin u` to its relative accuracy where `u` is small (the band's top at
    /// small `vbar`; as the top, `arcsin vbar`, and `u*` there), against the
    /// 40-digit phases of `data/half-length.json` of the springs `rho` below
    /// the exact top (the 8 of its 60 in the top half below
    /// [`FROM_TOP_PHASE`], vbar 0.001 to 0.1): within 32 eps (observed 22.5,
    /// at vbar 0.001 and `rho = 0.003`: the computed top `h_t` is itself
    /// rounded, its `u` 5.6e-16 above `arcsin vbar`, and `d` measured from it
    /// is 2.8e-17 off the exact top's, `|du/dh|` falling fast below the top),
    /// where `n`'s own `sin u` is 2,098 eps off (the addition formulas'
    /// rounding at `u = 0.001`); `beta` and `cos u` within 4 eps absolute.
    #[test]
    fn the_phase_near_a_small_top_keeps_its_digits() {
        let cases = crate::numerics::reference_cases("half-length.json");
        let (mut worst, mut own, mut count) = (0.0f64, 0.0f64, 0);
        for c in &cases {
            let (vbar, rho) = (c["vbar"].as_f64().unwrap(), c["rho"].as_f64().unwrap());
            let u: f64 = c["u_below_top"].as_str().unwrap().parse().unwrap();
            let vel = Velocity::new(vbar);
            let f = Foundation::new(2.0, 0.5, Some(vel), 1e-15);
            let h_t = vel.tangent_half_length();
            let n = vel.stick_first_by_half_length(h_t - rho);
            if rho > 0.5 * h_t || FRAC_PI_2 - n.beta >= FROM_TOP_PHASE {
                continue;
            }
            count += 1;
            let top = small_top(&vel, h_t, vel.delta).expect("a small top");
            let (beta, sin_u, cos_u, _) = f.length_phase(&vel, &n, rho, Some((&top, vel.delta)));
            // The same springs below a centre's threshold `u* = arcsin vbar`.
            let centre = Foundation { u_star: vel.delta, star_sin_cos: libm::sincos(vel.delta), ..f };
            let d = vel.phase_below_top(&top, rho, &n, vel.delta);
            let (_, s, c) = centre.half_angles(d);
            let (beta_centre, sin_u_centre, cos_u_centre) = centre.centre_phase(&n, rho, h_t, d, (s, c));
            // sin of the rounded reference is within an ulp of sin u; beta and
            // cos u are near pi/2 and 1, where their absolute accuracy counts.
            let rel = |x: f64| (x / u.sin() - 1.0).abs() / f64::EPSILON;
            let abs = |x: f64, r: f64| 8.0 * (x - r).abs() / f64::EPSILON;
            let (b, cu) = (FRAC_PI_2 - u, u.cos());
            let others = [abs(beta, b), abs(beta_centre, b), abs(cos_u, cu), abs(cos_u_centre, cu)];
            let e = others.into_iter().fold(rel(sin_u).max(rel(sin_u_centre)), f64::max);
            worst = crate::numerics::worst_of(worst, e);
            own = crate::numerics::worst_of(own, rel(n.sin_u));
        }
        eprintln!("sin u near a small top ({count} springs): {worst} eps; the node's own {own} eps");
        assert_eq!(count, 8);
        assert!(worst <= 32.0 && own > 1000.0, "{worst} eps, own {own} eps");
    }
}
