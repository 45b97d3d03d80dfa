//! The interpolant of a table and its MDR transform: monotone cubic Hermite
//! pieces, the transform of each piece in closed form (in the angle), summed
//! over the table hierarchically; and the normal force of an equivalent profile.

use crate::quad;
use crate::root;
use crate::special;
use std::f64::consts::PI;

/// Monotone piecewise-cubic Hermite interpolant: three-point slopes (exact for
/// quadratics, so the interpolation error is `O(h^3)` for smooth data) with
/// Hyman's monotonicity limiter, and one-sided three-point end slopes.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Pchip {
    x: Vec<f64>,
    y: Vec<f64>,
    d: Vec<f64>,
}

impl Pchip {
    /// Interpolant through `(x[i], y[i])`, `x` strictly increasing, `y` nondecreasing.
    pub(crate) fn new(x: Vec<f64>, y: Vec<f64>) -> Pchip {
        let n = x.len();
        let h: Vec<f64> = (0..n - 1).map(|i| x[i + 1] - x[i]).collect();
        let del: Vec<f64> = (0..n - 1).map(|i| (y[i + 1] - y[i]) / h[i]).collect();
        // Three-point (parabolic) slopes, exact for quadratics, then the Hyman
        // limiter |d| <= 3 min(|del|) that keeps the cubic monotone.
        let mut d = vec![0.0; n];
        for i in 1..n - 1 {
            if del[i - 1] * del[i] > 0.0 {
                let p = (h[i] * del[i - 1] + h[i - 1] * del[i]) / (h[i - 1] + h[i]);
                let lim = 3.0 * del[i - 1].abs().min(del[i].abs());
                d[i] = p.signum() * p.abs().min(lim);
            }
        }
        // One-sided three-point end slopes, limited to keep monotonicity.
        let end = |h0: f64, h1: f64, d0: f64, d1: f64| {
            let s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
            if s.signum() != d0.signum() {
                0.0
            } else if d0.signum() != d1.signum() && s.abs() > 3.0 * d0.abs() {
                3.0 * d0
            } else {
                s
            }
        };
        if n == 2 {
            d[0] = del[0];
            d[1] = del[0];
        } else {
            d[0] = end(h[0], h[1], del[0], del[1]);
            d[n - 1] = end(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
        }
        Pchip { x, y, d }
    }

    /// The knots.
    pub(crate) fn knots(&self) -> &[f64] {
        &self.x
    }

    /// The values at the knots.
    pub(crate) fn values(&self) -> &[f64] {
        &self.y
    }

    fn segment(&self, t: f64) -> usize {
        let n = self.x.len();
        match self.x.binary_search_by(|v| v.total_cmp(&t)) {
            Ok(i) => i.min(n - 2),
            Err(i) => i.saturating_sub(1).min(n - 2),
        }
    }

    /// Value and derivative at `t` (extrapolating the end cubics outside).
    pub(crate) fn eval(&self, t: f64) -> (f64, f64) {
        let i = self.segment(t);
        let h = self.x[i + 1] - self.x[i];
        let u = (t - self.x[i]) / h;
        let (y0, y1, d0, d1) = (self.y[i], self.y[i + 1], self.d[i] * h, self.d[i + 1] * h);
        // In the difference form (`y1 - y0` once), so that a table with a large
        // offset loses nothing to cancellation between the value basis functions.
        let (u2, u3, dy) = (u * u, u * u * u, y1 - y0);
        let v = y0 + u2 * (3.0 - 2.0 * u) * dy + (u3 - 2.0 * u2 + u) * d0 + (u3 - u2) * d1;
        let dv = 6.0 * u * (1.0 - u) * dy + (3.0 * u2 - 4.0 * u + 1.0) * d0 + (3.0 * u2 - 2.0 * u) * d1;
        (v, dv / h)
    }

    /// The derivative on interval `i` about its left end: `(d_i, a1, a2)` with
    /// `f'(x_i + rho) = d_i + a1 rho + a2 rho^2`.
    fn derivative_about_left(&self, i: usize) -> (f64, f64, f64) {
        let h = self.x[i + 1] - self.x[i];
        let (d0, d1) = (self.d[i], self.d[i + 1]);
        let del = (self.y[i + 1] - self.y[i]) / h;
        let a1 = (6.0 * del - 4.0 * d0 - 2.0 * d1) / h;
        let a2 = (-6.0 * del + 3.0 * d0 + 3.0 * d1) / (h * h);
        (d0, a1, a2)
    }

    /// The `t` with value `v` (the interpolant is nondecreasing; `v` within its range).
    pub(crate) fn inverse(&self, v: f64) -> f64 {
        let i = match self.y.binary_search_by(|w| w.total_cmp(&v)) {
            Ok(i) => return self.x[i],
            Err(i) => i.saturating_sub(1).min(self.x.len() - 2),
        };
        root::bracketed(|t| self.eval(t).0 - v, self.x[i], self.x[i + 1], 4.0 * f64::EPSILON).x
    }
}

/// Gauss-Legendre order per knot interval of the normal force `normal_force`:
/// the integrand is the cubic interpolant itself, integrated exactly from 2 points
/// on; 12 leaves margin for the inverse at the edge.
const NORMAL_FORCE_ORDER: usize = 12;
/// `g(x) = x int_0^x f'(r) / sqrt(x^2 - r^2) dr` for the interpolated profile `f`, at `x`:
/// `x` times the sum of [`interval_integrals`] over the table below `x`.
/// Linear in the rows; [`mdr_transform_knots`] gives all knots at once.
#[cfg(test)]
pub(crate) fn mdr_transform(f: &Pchip, x: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    x * interval_integrals(f, 0, f.x.len() - 1, x)
}

/// `sum_(lo <= i < hi) int_(r_i)^(min(r_(i+1), x)) f'(r) / sqrt(x^2 - r^2) dr`
/// over the intervals `i` of `f` (those starting at or above `x` contribute nothing).
///
/// # Derivation
/// With `r = x sin t` the integral over one interval becomes `int f'(x sin t) dt`
/// over `[t0, t0 + D]`, and with the interval's derivative written about its
/// left end, `f' = d0 + a1 rho + a2 rho^2`, `rho = x (sin t - sin t0)`, it is
/// `d0 J0 + a1 J1 + a2 J2` with (`s = sin t0 = r0/x`, `c = cos t0 = Q0/x`,
/// `Q = sqrt(x^2 - r^2)`, `h = sin^2(D/2)`, `S(y) = y - sin y`,
/// `W(y) = int_0^y (1 - cos)^2`):
/// - `J0 = D`,
/// - `J1 = x (2 c h - s S(D))`,
/// - `J2 = x^2 (s^2 W(D) - 4 s c h^2 + c^2 S(2D)/4)`.
///
/// `D` comes from `sin D = (r1 - r0)(r1 + r0)/(r1 Q0 + r0 Q1)` and
/// `cos D = (Q0 Q1 + r0 r1)/x^2` by `atan2` (sums of positive terms), and
/// `h = sin^2 D / (2 (1 + cos D))`, so every moment keeps its relative accuracy,
/// even for an interval far below `x` (where a difference of antiderivatives
/// would cancel to `(h/x)^3` of its terms). Since `t1 <= pi/2`, `c >= sin D`,
/// which bounds the cancellation in `J1` and `J2` to a small factor.
pub(crate) fn interval_integrals(f: &Pchip, lo: usize, hi: usize, x: f64) -> f64 {
    let q = |r: f64| if r >= x { 0.0 } else { ((x - r) * (x + r)).sqrt() };
    let mut sum = 0.0;
    let mut q0 = q(f.x[lo]);
    for i in lo..hi {
        let r0 = f.x[i];
        if r0 >= x {
            break;
        }
        let r1 = f.x[i + 1].min(x);
        let q1 = q(r1);
        let sin_d = (r1 - r0) * (r1 + r0) / (r1 * q0 + r0 * q1);
        let cos_d = (q0 * q1 + r0 * r1) / (x * x);
        // atan2 keeps D accurate up to pi/2; for small D the series is cheaper.
        let d = if sin_d < special::ASIN_SERIES_LIMIT { special::asin_small(sin_d) } else { sin_d.atan2(cos_d) };
        let h = sin_d * sin_d / (2.0 * (1.0 + cos_d));
        let (sn, cs) = (r0 / x, q0 / x);
        let j1 = x * (2.0 * cs * h - sn * special::x_minus_sin(d));
        let j2 = x
            * x
            * (sn * sn * special::versin_sq_integral(d) - 4.0 * sn * cs * h * h
                + 0.25 * cs * cs * special::x_minus_sin(2.0 * d));
        let (d0, a1, a2) = f.derivative_about_left(i);
        sum += d0 * d + a1 * j1 + a2 * j2;
        q0 = q1;
    }
    sum
}

/// Chebyshev points per target block in [`mdr_transform_knots`]: the far sum is
/// analytic on the block with its nearest branch point (`x = r_k`) three
/// half-widths from the centre, so interpolation converges like
/// `rho^-n`, `rho = 3 + sqrt 8 = 5.83`; 24 points give `5.83^-23 = 2e-18` of
/// the terms' sizes, below their rounding.
const FAR_POINTS: usize = 24;
/// Target blocks of at most this many knots sum their near sources directly.
const LEAF_TARGETS: usize = 32;

/// The MDR transform (`mdr_transform`, a test's reference) at every knot of `f`, in `O(n log n)`
/// operations instead of `O(n^2)`.
///
/// # Derivation
/// Write `P_i` for the antiderivative of `f_i'(r)/sqrt(x^2 - r^2)` on interval
/// `i` (built from `A = asin(r/x)`, `Q = sqrt(x^2 - r^2)`, see `mdr_transform`).
/// Summing `P_i(r_(i+1)) - P_i(r_i)` over the intervals below a knot `x = r_j`
/// and regrouping by knot gives
/// `g(r_j)/r_j = a1_0 r_j + sum_(k=1)^(j-1) K_k(r_j) + (pi/2)(d_j - b1 r_j + 3/2 b2 r_j^2)`,
/// where the first term is `-P_0(0)`, the last `P_(j-1)(r_j)` (with `b1`, `b2`
/// the left interval's derivative `d_j + b1 rho + b2 rho^2` about its right end),
/// and each interior knot contributes the jump of the derivative's quadratic:
/// with `f'_(k-1) - f'_k = e1 rho + e2 rho^2` about `r_k` (no constant term, as
/// `f'` is continuous),
/// `K_k(x) = e1 (-Q - r_k A) + e2 ((x^2/2 + r_k^2) A + 3/2 r_k Q)` at `r = r_k`.
///
/// The sum over `k` is split hierarchically: the knots are bisected into target
/// blocks `[c, d]` of width `W`; the sources `r_k < c - W` not yet summed by a
/// parent form a function of `x` analytic on the block, which is evaluated at
/// `FAR_POINTS` (24) Chebyshev points and interpolated (barycentric formula) at the
/// block's knots. Each level costs `O(n)` kernel evaluations; blocks of at most
/// `LEAF_TARGETS` (32) knots sum the remaining near sources directly.
pub(crate) fn mdr_transform_knots(f: &Pchip) -> Vec<f64> {
    let r = &f.x;
    let mut sums = vec![0.0; r.len()];
    far_sums(f, 0, (0.0, r[r.len() - 1]), 0, &mut sums);
    r.iter().zip(&sums).map(|(&x, &s)| x * s).collect()
}

/// `out[t] = sum_(lo <= i < first + t)` of the [`interval_integrals`] at knot
/// `first + t`, for the knots in the block `[c, d]`, with the intervals below
/// `lo` already summed by the caller.
fn far_sums(f: &Pchip, first: usize, (c, d): (f64, f64), lo: usize, out: &mut [f64]) {
    let (r, nt) = (&f.x, out.len());
    if nt == 0 {
        return;
    }
    let width = d - c;
    // Intervals well separated from the block: right ends r_(i+1) < c - width.
    let hi = r[1..].partition_point(|&x| x < c - width).max(lo).min(first);
    let m = hi - lo;
    if m > 0 {
        if m * nt <= FAR_POINTS * (m + nt) {
            for (t, o) in out.iter_mut().enumerate() {
                *o += interval_integrals(f, lo, hi, r[first + t]);
            }
        } else {
            let cheb = chebyshev_points(c, d);
            let vals: Vec<f64> = cheb.iter().map(|&x| interval_integrals(f, lo, hi, x)).collect();
            for (t, o) in out.iter_mut().enumerate() {
                *o += barycentric(&cheb, &vals, r[first + t]);
            }
        }
    }
    if nt <= LEAF_TARGETS || width <= 0.0 {
        for (t, o) in out.iter_mut().enumerate() {
            *o += interval_integrals(f, hi, first + t, r[first + t]);
        }
        return;
    }
    let mid = 0.5 * (c + d);
    let split = r[first..first + nt].partition_point(|&x| x < mid);
    let (left, right) = out.split_at_mut(split);
    crate::numerics::par::join(
        || far_sums(f, first, (c, mid), hi, left),
        || far_sums(f, first + split, (mid, d), hi, right),
    );
}

/// Chebyshev points of the second kind on `[c, d]`, ends included.
fn chebyshev_points(c: f64, d: f64) -> [f64; FAR_POINTS] {
    let (mid, half) = (0.5 * (c + d), 0.5 * (d - c));
    std::array::from_fn(|i| mid + half * (PI * i as f64 / (FAR_POINTS - 1) as f64).cos())
}

/// Barycentric interpolation at Chebyshev points of the second kind (weights
/// `(-1)^i`, halved at the ends): forward stable (Higham 2004).
fn barycentric(nodes: &[f64; FAR_POINTS], vals: &[f64], x: f64) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for (i, (&xi, &fi)) in nodes.iter().zip(vals).enumerate() {
        let diff = x - xi;
        if diff == 0.0 {
            return fi;
        }
        let mut w = if i % 2 == 0 { 1.0 } else { -1.0 };
        if i == 0 || i == FAR_POINTS - 1 {
            w *= 0.5;
        }
        let t = w / diff;
        num += t * fi;
        den += t;
    }
    num / den
}

/// MDR normal force at indentation `d` of the equivalent profile `g`, in units
/// of `E*` times length squared: `2 int_0^a (d - g(x)) dx` with `g(a) = d`.
pub(crate) fn normal_force(g: &Pchip, d: f64) -> f64 {
    let a = g.inverse(d);
    let mut cuts: Vec<f64> = g.knots().iter().copied().filter(|&x| x < a).collect();
    cuts.push(a);
    let rule = quad::rule(NORMAL_FORCE_ORDER, 0.0);
    let mut sum = 0.0;
    for w in cuts.windows(2) {
        let h = 0.5 * (w[1] - w[0]);
        for (&u, &wt) in rule.nodes.iter().zip(&rule.weights) {
            sum += wt * h * (d - g.eval(w[0] + h * (1.0 + u)).0);
        }
    }
    2.0 * sum
}
