//! The one banded integrator: integrals over a contact's springs, band by
//! band, each band by Gauss(-Jacobi) rules of increasing order.
//!
//! A *pass* ([`Pass`]) is one rule of order `m` over one band: the weighted
//! sums of `N` means (the springs' normal force, deficit, tangential force,
//! ...) and, from the same nodes, each sum's truncation estimate
//! ([`crate::numerics::quad::Rule::truncation`]: the decay of the integrand's
//! discrete orthogonal-polynomial coefficients). The *ladder* ([`Ladder`])
//! raises the order of a band's passes until every mean's estimate is within
//! the tolerance relative to the band plus a scale (what the bands before it
//! summed): each next order is the one the measured decay predicts to
//! suffice, at most a doubling, from a fixed set (so that a thread computes
//! few rules for a whole table). After a doubling the last difference of two
//! passes bounds the error too. Those estimates, summed, are the reported
//! truncation error; the rounding part is the caller's (it knows the size
//! of its terms).
//!
//! What a band is, and in which variable its rule runs, is the caller's:
//! [`cosine_pass`] (Gauss-Legendre in `theta`, `z = a + (b - a)(1 - cos
//! theta)/2`, which absorbs a square-root behaviour at both ends) serves
//! every contact described by its geometry alone ([`mdr`]) and the stop
//! operator's bands; the power laws' bands in the angle, with their Jacobi
//! weights and mapped segments, bring their own passes
//! (`contact::mdr::foundation`).

use crate::numerics::quad;

pub(crate) mod bands;
pub(crate) mod mdr;

/// Highest Gauss order a ladder tries by default.
pub(crate) const MAX_ORDER: usize = 256;
/// The orders a ladder may take: from [`LOOSE_ORDER`] or [`MIN_ORDER`] up,
/// each step at most a doubling ([`Ladder::run`]); a fixed set, so that a
/// thread computes few rules (Golub-Welsch) for a whole table (20 is the
/// first order of the power laws' bands in the stick's half-length).
const ORDERS: [usize; 15] = [8, 16, 20, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768, 1024];
/// The next order aims the next pass's predicted estimate at this fraction
/// of the tolerance (the node count is insensitive to it: 1, 0.25, 0.05 and
/// 0.01 gave 27.90, 27.91, 27.97 and 28.02 nodes a point on the parabolic table).
const NEXT_ORDER_MARGIN: f64 = 0.25;
/// First order tried per band at the default tolerance.
pub(crate) const MIN_ORDER: usize = 16;
/// First order tried per band at a tolerance of [`LOOSE_TOL`] or looser (the
/// lowest whose coefficients show a decay, see [`quad::Rule::truncation`]).
pub(crate) const LOOSE_ORDER: usize = 8;
/// Tolerances at or above this start the order ladder at [`LOOSE_ORDER`].
pub(crate) const LOOSE_TOL: f64 = 1e-9;

/// The integrals of `N` means with their truncation estimates, the integral of
/// a rounding magnitude (the size of the terms of a mean that cancels, whose
/// rounding is a few ulps of it), and the node count.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Sums<const N: usize> {
    pub(crate) value: [f64; N],
    pub(crate) error: [f64; N],
    pub(crate) magnitude: f64,
    pub(crate) nodes: usize,
}

impl<const N: usize> Default for Sums<N> {
    fn default() -> Self {
        Sums { value: [0.0; N], error: [0.0; N], magnitude: 0.0, nodes: 0 }
    }
}

impl<const N: usize> std::ops::AddAssign for Sums<N> {
    fn add_assign(&mut self, o: Sums<N>) {
        for k in 0..N {
            self.value[k] += o.value[k];
            self.error[k] += o.error[k];
        }
        self.magnitude += o.magnitude;
        self.nodes += o.nodes;
    }
}

/// One pass's sums: the means, the magnitude, and the truncation estimate of
/// each mean ([`quad::Rule::truncation`]; `None` below order 8).
pub(crate) struct Pass<const N: usize> {
    pub(crate) sum: [f64; N],
    pub(crate) magnitude: f64,
    pub(crate) truncation: Option<[f64; N]>,
    /// Each mean's coefficient decay ([`quad::Rule::decay`]).
    pub(crate) decay: [f64; N],
}

/// A pass's node values: each node's integrand (the means, with the Jacobian
/// and any change of variable, without the rule's weight) and the magnitude,
/// summed by [`Acc::finish`] once the nodes are all evaluated, one mean at a
/// time (its running sums stay in registers across the nodes' library calls).
pub(crate) struct Acc<const N: usize> {
    values: Vec<([f64; N], f64)>,
    /// The means the pass integrates; the others' slots hold 0 and are not summed.
    active: [bool; N],
}

impl<const N: usize> Acc<N> {
    pub(crate) fn new(rule: &quad::Rule, active: [bool; N]) -> Self {
        Acc { values: Vec::with_capacity(rule.nodes.len()), active }
    }

    /// The next node's integrand values `f` and magnitude.
    pub(crate) fn add(&mut self, f: [f64; N], magnitude: f64) {
        self.values.push((f, magnitude));
    }

    /// The pass, every sum times `scale`: the weighted sums of the means and
    /// of the magnitude, each mean's discrete coefficients of
    /// [`quad::Rule::tail`], and from them the truncation estimates. Node `i`
    /// of [`Acc::add`] is node `i` of `rule`.
    pub(crate) fn finish(&self, rule: &quad::Rule, scale: f64) -> Pass<N> {
        let n = self.values.len().min(rule.weights.len()).min(rule.tail.len());
        let (values, weights, tails) = (&self.values[..n], &rule.weights[..n], &rule.tail[..n]);
        let mut sum = [0.0; N];
        let mut coef = [[0.0; quad::TAIL_ROWS]; N];
        for k in (0..N).filter(|&k| self.active[k]) {
            let (mut s, mut c) = (0.0, [0.0; quad::TAIL_ROWS]);
            for ((f, _), (w, tail)) in values.iter().zip(weights.iter().zip(tails)) {
                let fk = f[k];
                s += w * fk;
                for r in 0..quad::TAIL_ROWS {
                    c[r] += tail[r] * fk;
                }
            }
            (sum[k], coef[k]) = (s, c);
        }
        let magnitude = values.iter().zip(weights).fold(0.0, |m, ((_, mag), w)| m + w * mag);
        // Every mean has an estimate, or (below order 8) none has.
        let t = coef.each_ref().map(|c| rule.truncation(c));
        let truncation = t.iter().all(Option::is_some).then(|| t.map(|e| scale.abs() * e.unwrap_or(f64::INFINITY)));
        let decay = coef.each_ref().map(|c| rule.decay(c));
        Pass { sum: sum.map(|x| scale * x), magnitude: scale.abs() * magnitude, truncation, decay }
    }
}

/// Order-`m` Gauss-Legendre pass over `z` in `[a, b]` in `theta`, `z = a + (b
/// - a)(1 - cos theta)/2`, `dz = (b - a) sin(theta)/2 dtheta`: the
/// substitution absorbs a square-root behaviour of the integrand at both ends
/// (where springs start or stop losing contact). `f(z)` is the node's means
/// and magnitude per unit `z`.
pub(crate) fn cosine_pass<const N: usize>(
    a: f64,
    b: f64,
    m: usize,
    active: [bool; N],
    f: &dyn Fn(f64) -> ([f64; N], f64),
) -> Pass<N> {
    cosine_pass_by((a, b, Ends::Both), m, active, |zs| zs.iter().map(|&z| f(z)).collect())
}

/// Where a [`cosine_pass`] clusters its nodes: at both ends of the band,
/// or at its lower end only (a band whose upper end is not an edge of the
/// integrand, which is analytic across it, and whose nodes cost most there).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Ends {
    Both,
    Lower,
}

/// [`cosine_pass`] with the nodes spread over the cores
/// ([`crate::numerics::par`]): for integrands that take long (a spring's
/// steady state in the plane each); the same bits. With [`Ends::Lower`],
/// Gauss-Legendre in `theta` on `[0, pi/2]`, `z = a + (b - a)(1 - cos
/// theta)`, `dz = (b - a) sin(theta) dtheta`: the square root at `a` is
/// absorbed as before, and at `b` (`dz/dtheta = b - a`) the nodes are
/// spaced as plain Gauss-Legendre's, about `(b - a)/m^2` from the end where
/// [`Ends::Both`] puts the last about `(b - a)/m^4` from it.
pub(crate) fn cosine_pass_parallel<const N: usize>(
    (a, b, ends): (f64, f64, Ends),
    m: usize,
    active: [bool; N],
    f: &(dyn Fn(f64) -> ([f64; N], f64) + Sync),
) -> Pass<N> {
    cosine_pass_by((a, b, ends), m, active, |zs| crate::numerics::par::map(zs, |&z| f(z)))
}

/// [`cosine_pass`] with the integrand evaluated at every node by `eval` (in order).
fn cosine_pass_by<const N: usize>(
    (a, b, ends): (f64, f64, Ends),
    m: usize,
    active: [bool; N],
    eval: impl FnOnce(&[f64]) -> Vec<([f64; N], f64)>,
) -> Pass<N> {
    let rule = quad::rule(m, 0.0);
    // `theta = span (1 + x)` over the rule's `x` in `[-1, 1]`, `z = a + reach (1 - cos theta)`.
    let (span, reach) = match ends {
        Ends::Both => (0.5 * std::f64::consts::PI, 0.5 * (b - a)),
        Ends::Lower => (0.25 * std::f64::consts::PI, b - a),
    };
    let angles: Vec<(f64, f64)> = rule.nodes.iter().map(|&x| (span * (1.0 + x)).sin_cos()).collect();
    let zs: Vec<f64> = angles.iter().map(|&(_, ct)| a + reach * (1.0 - ct)).collect();
    let mut acc = Acc::new(&rule, active);
    for ((v, mag), &(st, _)) in eval(&zs).into_iter().zip(&angles) {
        acc.add(v.map(|v| v * st), mag * st);
    }
    acc.finish(&rule, span * reach)
}

/// An order ladder: its tolerance (relative), its highest order, the
/// rounding floor of its integrand (a band whose estimates are within
/// `noise` times its magnitude, the size of its terms, is accepted too: the
/// integrand's own rounding keeps the coefficients from decaying further),
/// and how a pass's error is estimated.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Ladder {
    pub(crate) tol: f64,
    pub(crate) max_order: usize,
    pub(crate) noise: f64,
    /// The error of a pass is its difference from the pass before it, the
    /// orders doubling: for integrands whose bands may hold a kink (the stop
    /// operator's, where an event appears between two samples of the band
    /// search), where the coefficients' decay, which assumes an analytic
    /// integrand, would claim too much; otherwise the coefficients' estimate.
    pub(crate) difference: bool,
}

impl Ladder {
    /// A ladder to `tol` up to [`MAX_ORDER`], without a rounding floor, by
    /// the coefficients' estimate.
    pub(crate) fn new(tol: f64) -> Self {
        Ladder { tol, max_order: MAX_ORDER, noise: 0.0, difference: false }
    }

    /// The first order of a band: [`MIN_ORDER`], or [`LOOSE_ORDER`] at a
    /// tolerance of [`LOOSE_TOL`] or looser.
    pub(crate) fn first_order(&self) -> usize {
        if self.tol >= LOOSE_TOL {
            LOOSE_ORDER
        } else {
            MIN_ORDER
        }
    }

    /// Passes `pass(m)` at increasing orders from `first` until every mean's
    /// error (its truncation estimate; after a doubling of the order, at most
    /// the difference of the two passes) is within the tolerance relative to
    /// the pass plus `scale` (or the rounding floor), or the highest order is
    /// reached.
    pub(crate) fn run<const N: usize>(
        &self,
        first: usize,
        pass: impl Fn(usize) -> Pass<N>,
        scale: [f64; N],
    ) -> Sums<N> {
        let mut m = first;
        let mut nodes = 0;
        let mut prev: Option<(usize, [f64; N])> = None;
        loop {
            let p = pass(m);
            nodes += m;
            // After a doubling of the order, the last difference bounds the
            // error too (where the integrand's rounding noise sets the
            // coefficients' floor, far above the error of the sum, which
            // averages it). After a smaller step the two errors can be alike,
            // and their difference far below either: not used.
            let err: [f64; N] = std::array::from_fn(|k| {
                let t = if self.difference { f64::INFINITY } else { p.truncation.map_or(f64::INFINITY, |t| t[k]) };
                match prev {
                    Some((mp, q)) if m == 2 * mp => t.min((p.sum[k] - q[k]).abs()),
                    _ => t,
                }
            });
            let floor = self.noise * p.magnitude;
            let lim: [f64; N] = std::array::from_fn(|k| (self.tol * (p.sum[k].abs() + scale[k])).max(floor));
            if (0..N).all(|k| err[k] <= lim[k]) || m >= self.max_order {
                return Sums { value: p.sum, error: err, magnitude: p.magnitude, nodes };
            }
            prev = Some((m, p.sum));
            m = if self.difference { (2 * m).min(self.max_order) } else { self.next_order(m, &p, &err, &lim) };
        }
    }

    /// The order to try after a pass of order `m` failed: the smallest of
    /// [`ORDERS`] above `m` whose estimate, if the coefficients decay
    /// geometrically, falls to [`NEXT_ORDER_MARGIN`] of the tolerance, and at
    /// most `2 m` (and the highest order). With `c_k ~ rho^k` the estimate of
    /// [`quad::Rule::truncation`] is `~ E1 q ~ rho^(3m/2)`, `q = rho^(m/2)` the
    /// measured decay, so order `m'` scales it by `q^(3 (m' - m)/m)`. Where no
    /// decay is measured (`q >= 1`, or none claimed) the order doubles. Only
    /// the choice of the next order rests on this model: a pass is accepted
    /// by its own estimate alone.
    fn next_order<const N: usize>(&self, m: usize, p: &Pass<N>, err: &[f64; N], lim: &[f64; N]) -> usize {
        let mut need = 0.0f64;
        for k in 0..N {
            if err[k] > lim[k] {
                let q = p.decay[k];
                need = if q > 0.0 && q < 1.0 {
                    let excess = (err[k] / (NEXT_ORDER_MARGIN * lim[k])).ln();
                    need.max(excess * m as f64 / (3.0 * -q.ln()))
                } else {
                    f64::INFINITY
                };
            }
        }
        let want = if need < m as f64 { m + (need.ceil() as usize).max(1) } else { 2 * m };
        let max = self.max_order;
        ORDERS.into_iter().find(|&o| o >= want).unwrap_or(max).min(max).min(2 * m).max(m + 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pass's sums: each active mean's weighted sum (here of 1, x and x^2
    /// over [-1, 1]: 2, 0 and 2/3), its discrete coefficients (a polynomial
    /// of degree 2 has none at the tail's degrees: no truncation, and
    /// `c_k = 0` for the whole tail), the magnitude (here 3 a node: 6), every
    /// sum times `scale` (and the magnitude and estimates times its size);
    /// an inactive mean's slot is not summed (its 5 a node would give 10).
    #[test]
    fn a_pass_sums_the_active_means_and_the_magnitude() {
        let r = quad::rule(16, 0.0);
        let mut acc = Acc::new(&r, [true, true, false]);
        for &x in &r.nodes {
            acc.add([1.0, x, 5.0 + x * x], 3.0);
        }
        let p = acc.finish(&r, -0.5);
        assert!((p.sum[0] + 1.0).abs() < 1e-15 && p.sum[1].abs() < 1e-15 && p.sum[2] == 0.0, "{:?}", p.sum);
        assert!((p.magnitude - 3.0).abs() < 1e-15, "{}", p.magnitude);
        // No truncation: the tail's coefficients of a quadratic are zero but
        // for the rounding of sums of 16 terms of order 1 (the rule's own
        // orthogonality residual at order 16 is 6e-16 to 9e-16), so the
        // estimate is at most 16 eps; a truncation (below) is 1e-12 and more.
        let t = p.truncation.unwrap();
        assert!(t.iter().all(|&e| e < 16.0 * f64::EPSILON), "{t:?}");
        // x^20 over [-1, 1] is 2/21; 8 nodes (exact to degree 15) miss it, and the estimate sees it.
        let r = quad::rule(8, 0.0);
        let mut acc = Acc::new(&r, [true; 3]);
        for &x in &r.nodes {
            acc.add([x.powi(20), 0.0, 1.0], 0.0);
        }
        let p = acc.finish(&r, 1.0);
        let err = (p.sum[0] - 2.0 / 21.0).abs();
        let t = p.truncation.unwrap();
        assert!(err > 1e-12 && err <= t[0] && t[2] < 1e-15, "{err:e} {t:?}");
    }

    /// [`Ladder::next_order`] against orders worked out by hand from its
    /// model (`m' - m >= m ln(err/(margin lim)) / (3 ln(1/q))`, the smallest
    /// of [`ORDERS`] above, at most `2 m` and the highest order).
    #[test]
    fn the_next_order_is_the_predicted_one() {
        let f = Ladder::new(crate::DEFAULT_TOL);
        let pass = |decay: [f64; 3]| Pass { sum: [1.0; 3], magnitude: 0.0, truncation: None, decay };
        let lim = [1e-15; 3];
        let within = 1e-16;
        // q = 0.01, 100 times the limit: ln(400) 16/(3 ln 100) = 6.9 -> 23 -> 24.
        assert_eq!(f.next_order(16, &pass([0.01, 0.5, 0.5]), &[1e-13, within, within], &lim), 24);
        // Two failing means: the larger need (q = 0.1, 10 times: ln(40) 16/(3 ln 10) = 8.5 -> 25 -> 32).
        assert_eq!(f.next_order(16, &pass([0.01, 0.1, 0.5]), &[1e-13, 1e-14, within], &lim), 32);
        // A slow decay needs more than a doubling: the doubling.
        assert_eq!(f.next_order(16, &pass([0.5, 0.5, 0.5]), &[1e-9, within, within], &lim), 32);
        // No decay measured (q = 1, or q = 0: no coefficients), the doubling.
        assert_eq!(f.next_order(24, &pass([1.0, 0.5, 0.5]), &[1e-14, within, within], &lim), 48);
        assert_eq!(f.next_order(24, &pass([0.0, 0.5, 0.5]), &[1e-14, within, within], &lim), 48);
        // A fast decay just above the limit: the next order of the set (24 + 2 -> 32).
        assert_eq!(f.next_order(24, &pass([1e-4, 0.5, 0.5]), &[2e-15, within, within], &lim), 32);
        // ln(40) 32/(3 ln 10) = 17.1 -> 50 -> 64.
        assert_eq!(f.next_order(32, &pass([0.1, 0.5, 0.5]), &[1e-14, within, within], &lim), 64);
        // A mean exactly at its limit is within it: its slow decay does not count.
        assert_eq!(f.next_order(16, &pass([0.01, 0.9, 0.5]), &[1e-13, 1e-15, within], &lim), 24);
        // The highest order caps the step: 192 -> 256 by default, 384 with a higher cap.
        assert_eq!(f.next_order(192, &pass([0.5, 0.5, 0.5]), &[1e-9, within, within], &lim), 256);
        let high = Ladder { max_order: 1024, ..f };
        assert_eq!(high.next_order(192, &pass([0.5, 0.5, 0.5]), &[1e-9, within, within], &lim), 384);
    }

    /// A cosine pass integrates what the substitution makes analytic: a
    /// square root at either end, `int_0^1 sqrt(z (1 - z)) dz = pi/8`, to
    /// rounding at order 16 (an entire function of `theta`), with a
    /// truncation estimate that bounds the error beyond rounding (a few ulps,
    /// the caller's to add) and falls with the order.
    #[test]
    fn a_cosine_pass_absorbs_square_roots_at_both_ends() {
        let f = |z: f64| ([(z * (1.0 - z)).sqrt()], 0.0);
        for (m, bound) in [(16, 1e-11), (32, 1e-15)] {
            let p = cosine_pass(0.0, 1.0, m, [true], &f);
            let err = (p.sum[0] - std::f64::consts::PI / 8.0).abs();
            let est = p.truncation.unwrap()[0];
            let rounding = 4.0 * f64::EPSILON * p.sum[0];
            assert!(err < 1e-15 && est + rounding >= err && est < bound, "order {m}: {err:e}, estimate {est:e}");
        }
    }

    /// A pass clustered at its lower end only: a square root there and an
    /// integrand analytic at the upper end, `int_1^3 sqrt(z - 1) e^(-z) dz =
    /// e^-1 gamma(3/2, 2)` in closed form (`gamma(3/2, x) = sqrt(pi)/2 erf(sqrt x)
    /// - sqrt(x) e^-x`; `erf(sqrt 2)` rounded), to rounding at order 32;
    /// the last node 1 to 4 times `(b - a)/m^2` from the
    /// upper end (with both ends clustered, within 8 times `(b - a)/m^4`), the
    /// first within 4 times `(b - a)/m^4` of the lower.
    #[test]
    fn a_pass_clustered_at_its_lower_end_keeps_its_nodes_from_the_upper() {
        let erf = 0.954_499_736_103_641_6;
        let exact = (-1.0f64).exp() * (std::f64::consts::PI.sqrt() / 2.0 * erf - 2.0f64.sqrt() * (-2.0f64).exp());
        let zs = std::sync::Mutex::new(Vec::new());
        let f = |z: f64| {
            zs.lock().unwrap().push(z);
            ([(z - 1.0).sqrt() * (-z).exp()], 0.0)
        };
        let p = cosine_pass_parallel((1.0, 3.0, Ends::Lower), 32, [true], &f);
        assert!((p.sum[0] - exact).abs() < 4.0 * f64::EPSILON * exact, "{} {exact}", p.sum[0]);
        let ends = |ends: Ends| {
            zs.lock().unwrap().clear();
            cosine_pass_parallel((1.0, 3.0, ends), 32, [true], &f);
            let z = zs.lock().unwrap();
            let (lo, hi) = z.iter().fold((f64::INFINITY, 0.0f64), |(l, h), &z| (l.min(z - 1.0), h.max(z)));
            (lo, 3.0 - hi)
        };
        let (m2, m4) = (2.0 / 32.0f64.powi(2), 2.0 / 32.0f64.powi(4));
        let (lower, upper) = ends(Ends::Lower);
        assert!(lower < 4.0 * m4 && upper > m2 && upper < 4.0 * m2, "{lower:e} {upper:e}");
        let (_, both) = ends(Ends::Both);
        assert!(both < 8.0 * m4, "{both:e}");
    }
}
