//! Tabulated contacts: an axisymmetric profile `f(r)` (`profile:FILE@U0`) or an
//! MDR equivalent profile `g(x)` (`gx:FILE@U0`), with `U0` the mean indentation
//! in the file's length unit.
//!
//! # Interpolation
//! The table is interpolated by monotone piecewise-cubic Hermite interpolation
//! (three-point slopes with Hyman's limiter): `C^1`, shape-preserving, exact for
//! quadratics, cubic on each interval. For `profile:`, `g` is computed at the table's radii by the MDR
//! transform `g(x) = x int_0^x f'(r)/sqrt(x^2 - r^2) dr = x int_0^(pi/2) f'(x sin t) dt`
//! of the interpolated `f` (in closed form per interval, summed over the
//! intervals hierarchically in `O(n log n)`: [`mdr_transform_knots`]), and
//! interpolated again. The error interpolation adds is estimated by
//! computing `mu` a second time on the table with every other point removed:
//! PCHIP converges like `h^3`, so the difference overestimates the error of the
//! full table; it is reported as `interpolation_error`.
//!
//! # Quadrature
//! With `z = x/x_c` (`g(x_c) = U0`) and `G = g/U0`, the springs are integrated
//! over `z` between breakpoints: the table's knots and the band edges
//! `s = (1 - G(z))/amp = 1, +-sqrt(1 - vbar^2), -1`. On each interval the
//! substitution `z = p + (q - p)(1 - cos t)/2` absorbs the square-root
//! behaviour at `s = +-1`, and Gauss-Legendre at 16 and 32 points gives the
//! value and its error estimate.

use crate::error::{Error, Result};
use crate::quad;
use crate::ratio::Ratio;
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
/// The two orders of the tabulated quadrature per interval: the higher gives the
/// value, their difference the error estimate.
const PASS_ORDERS: (usize, usize) = (16, 32);

/// Most rows of a tabulated profile: the MDR transform is `O(n log n)`
/// ([`mdr_transform_knots`]); 1,000,000 rows take about 30 s on two cores.
pub const MAX_TABLE_ROWS: usize = 1_000_000;

/// Parse the text of a two-column table (`r,f` or `x,g`): comma, semicolon or
/// blank separated, at most one header line (before the first row), `#`
/// comments; `path` names it in messages. Checks: at most [`MAX_TABLE_ROWS`]
/// (it stops reading past them), at least 3 rows, finite values, the first
/// column strictly increasing from 0, the second nondecreasing (it is shifted so
/// that its first value is 0). The core reads no files: the caller does (the
/// command line with a size cap).
pub(crate) fn parse_table(text: &str, path: &str) -> Result<(Vec<f64>, Vec<f64>)> {
    let bad = |reason: String| Error::Parse { context: path.into(), reason };
    let (mut xs, mut ys, mut lines) = (vec![], vec![], vec![]);
    let mut header_seen = false;
    for (ln, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let f: Vec<&str> =
            line.split(|c: char| c == ',' || c == ';' || c.is_whitespace()).filter(|s| !s.is_empty()).collect();
        let nums: Vec<Option<f64>> = f.iter().map(|s| s.parse::<f64>().ok()).collect();
        if xs.is_empty() && !header_seen && nums.iter().any(|v| v.is_none()) {
            header_seen = true;
            continue; // the one header line
        }
        if f.len() != 2 || nums.iter().any(|v| v.is_none()) {
            return Err(bad(format!("line {}: expected two numbers", ln + 1)));
        }
        xs.push(nums[0].unwrap_or(f64::NAN));
        ys.push(nums[1].unwrap_or(f64::NAN));
        lines.push(ln + 1);
        if xs.len() > MAX_TABLE_ROWS {
            break; // check_columns names the limit
        }
    }
    check_columns(xs, ys, path, &|i| format!("line {}", lines[i]))
}

/// The checks every table passes, from a file or from arrays: at most
/// [`MAX_TABLE_ROWS`] and at least 3 rows, finite values, the first column
/// strictly increasing from 0, the second nondecreasing (returned shifted so that
/// it starts at 0); `label(i)` names row `i` in messages.
pub(crate) fn check_columns(
    xs: Vec<f64>,
    ys: Vec<f64>,
    source: &str,
    label: &dyn Fn(usize) -> String,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let bad = |reason: String| Error::Parse { context: source.into(), reason };
    if xs.len() != ys.len() {
        return Err(bad(format!("the columns differ in length ({} and {})", xs.len(), ys.len())));
    }
    if xs.len() > MAX_TABLE_ROWS {
        return Err(Error::TooLarge {
            what: format!("rows of {source}"),
            count: xs.len() as u128,
            limit: MAX_TABLE_ROWS as u128,
        });
    }
    for i in 0..xs.len() {
        if !xs[i].is_finite() || !ys[i].is_finite() {
            return Err(bad(format!("{}: values must be finite", label(i))));
        }
        if i > 0 && xs[i] <= xs[i - 1] {
            return Err(bad(format!("{}: the first column must increase strictly", label(i))));
        }
        if i > 0 && ys[i] < ys[i - 1] {
            return Err(bad(format!("{}: the profile must not decrease (monotone profiles only)", label(i))));
        }
    }
    if xs.len() < 3 {
        return Err(bad(format!("needs at least 3 rows, found {}", xs.len())));
    }
    if xs[0] != 0.0 {
        return Err(bad("the first column must start at 0 (the axis)".into()));
    }
    let y0 = ys[0];
    Ok((xs, ys.iter().map(|y| y - y0).collect()))
}

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

/// The MDR transform [`mdr_transform`] at every knot of `f`, in `O(n log n)`
/// operations instead of `O(n^2)`.
///
/// # Derivation
/// Write `P_i` for the antiderivative of `f_i'(r)/sqrt(x^2 - r^2)` on interval
/// `i` (built from `A = asin(r/x)`, `Q = sqrt(x^2 - r^2)`, see [`mdr_transform`]).
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

/// A table read once, with its MDR transform done: `g` at the table's radii, in
/// units scaled by the table's extent (`x / x_max`, `g / g_max`) so that tables
/// at any scale of f64 interpolate the same way. The transform does not depend
/// on the mean indentation: a scene's load control reuses it ([`Table::at`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    path: String,
    /// `g/g_max` on `x/x_max` (full table).
    g: Pchip,
    /// The same from every other row (for the interpolation error), if >= 5 rows.
    coarse: Option<Pchip>,
    /// The table's extent: `x_max` and `g_max` in its length unit.
    scale: (f64, f64),
}

impl Table {
    /// Parse and transform a table's text ([`parse_table`]; `path` names it in
    /// messages): `profile` (true: `f(r)`, MDR-transformed) or `g(x)`.
    pub fn parse(text: &str, path: &str, profile: bool) -> Result<Table> {
        let (x, v) = parse_table(text, path)?;
        Self::from_checked(x, v, profile, path)
    }

    /// From arrays (no file): `r, f` of an axisymmetric profile (`profile`) or
    /// `x, g` of an equivalent profile, checked as a file's columns are; `name`
    /// appears in messages.
    ///
    /// ```
    /// use fricosc::profile::Table;
    /// // A paraboloid f = r^2/2 (R = 1) at mean indentation 1e-4: Hertz.
    /// let r: Vec<f64> = (0..=200).map(|i| i as f64 * 0.005).collect();
    /// let f: Vec<f64> = r.iter().map(|r| r * r / 2.0).collect();
    /// let t = Table::from_columns(r, f, true, "paraboloid").unwrap().at(1e-4).unwrap();
    /// assert!((t.contact_radius - 1e-2).abs() < 1e-12); // g = x^2/R: x_c = sqrt(R u0)
    /// ```
    pub fn from_columns(x: Vec<f64>, v: Vec<f64>, profile: bool, name: &str) -> Result<Table> {
        let (x, v) = check_columns(x, v, name, &|i| format!("row {i}"))?;
        Self::from_checked(x, v, profile, name)
    }

    fn from_checked(x: Vec<f64>, v: Vec<f64>, profile: bool, path: &str) -> Result<Table> {
        let bad = |reason: String| Error::Parse { context: path.into(), reason };
        let (xmax, vmax) = (x[x.len() - 1], v[v.len() - 1]);
        if vmax <= 0.0 {
            return Err(bad("the profile is flat (its last value equals its first)".into()));
        }
        let xs: Vec<f64> = x.iter().map(|&xi| xi / xmax).collect();
        let vs: Vec<f64> = v.iter().map(|&vi| vi / vmax).collect();
        // Slopes of the scaled table must be ordinary numbers (a near-vertical
        // step such as 0 -> 1 over 1e-300 cannot be interpolated in f64).
        for i in 1..xs.len() {
            let slope = (vs[i] - vs[i - 1]) / (xs[i] - xs[i - 1]);
            if !slope.is_finite() || xs[i] - xs[i - 1] < 1e-12 {
                return Err(bad(format!(
                    "rows {} and {} are too close ({:?} apart in x, relative {:.1e} of the table's extent) to interpolate",
                    i - 1,
                    i,
                    x[i] - x[i - 1],
                    xs[i] - xs[i - 1]
                )));
            }
        }
        let build = |xs: Vec<f64>, vs: Vec<f64>| -> Result<Pchip> {
            if !profile {
                return Ok(Pchip::new(xs, vs));
            }
            let f = Pchip::new(xs.clone(), vs);
            let gv = mdr_transform_knots(&f);
            // A profile with a steep step has a transform that falls again
            // (g ~ x / sqrt(x^2 - r0^2) after a step at r0): not a simple contact.
            if let Some(i) = (1..gv.len()).find(|&i| gv[i] < gv[i - 1]) {
                let (imax, gmax) =
                    gv.iter().enumerate().fold((0, f64::MIN), |b, (k, &g)| if g > b.1 { (k, g) } else { b });
                return Err(bad(format!(
                    "the MDR transform g(x) of this profile decreases after x = {:?} (largest g = {:?} at x = {:?}): \
                     fricosc handles profiles whose equivalent profile increases",
                    xs[i - 1] * xmax,
                    gmax * vmax,
                    xs[imax] * xmax
                )));
            }
            Ok(Pchip::new(xs, gv))
        };
        let coarse = if xs.len() >= 5 {
            build(xs.iter().step_by(2).copied().collect(), vs.iter().step_by(2).copied().collect()).ok()
        } else {
            None
        };
        let g = build(xs, vs)?;
        let gmax = *g.values().last().unwrap_or(&0.0);
        Ok(Table { path: path.into(), g, coarse, scale: (xmax, gmax * vmax) })
    }

    /// The largest `g` of the (transformed) table, in its length unit.
    pub fn max_g(&self) -> f64 {
        self.scale.1
    }

    /// The contact at mean indentation `u0` (the table's length unit).
    pub fn at(&self, u0: f64) -> Result<Tabulated> {
        if !(u0.is_finite() && u0 > 0.0) {
            return Err(Error::param("U0", u0, "the mean indentation must be finite and > 0"));
        }
        let (xmax, gmax) = self.scale;
        // In the table's scaled units g/g_max of the transformed values.
        let g_top = *self.g.values().last().unwrap_or(&1.0);
        let u = u0 / gmax * g_top;
        if !(u.is_normal() && u <= g_top) {
            return Err(Error::Parse {
                context: self.path.clone(),
                reason: format!(
                    "the table reaches only g = {gmax:?} < U0 = {u0:?}: the contact is wider than the table"
                ),
            });
        }
        let normalise = |g: &Pchip| -> (Pchip, f64) {
            let xc = g.inverse(u);
            let z: Vec<f64> = g.knots().iter().map(|&xi| xi / xc).collect();
            let gz: Vec<f64> = g.values().iter().map(|&gi| gi / u).collect();
            (Pchip::new(z, gz), xc)
        };
        let (g, xc) = normalise(&self.g);
        // The contact at the mean indentation must span more than the table's
        // first interval: inside it the shape is only the interpolating cubic.
        let first = self.g.knots()[1];
        if xc <= first {
            return Err(Error::Parse {
                context: self.path.clone(),
                reason: format!(
                    "the contact radius at U0 = {u0:?} is {:?}, inside the table's first interval [0, {:?}]: the table \
                     does not resolve the contact (add rows near the axis)",
                    xc * xmax,
                    first * xmax
                ),
            });
        }
        let coarse = self.coarse.as_ref().filter(|c| *c.values().last().unwrap_or(&0.0) >= u).map(|c| normalise(c).0);
        Ok(Tabulated { g, coarse, contact_radius: xc * xmax, name: format!("{}@{u0:?}", self.path) })
    }
}

/// The contact of a `profile:FILE@U0` (`profile`) or `gx:FILE@U0` shape; `rest`
/// is `FILE@U0`, `spec` the whole name (which the contact keeps).
pub(crate) fn parse_shape(
    rest: &str,
    spec: &str,
    profile: bool,
    read: crate::shape::Reader,
) -> Result<std::sync::Arc<dyn crate::contact::Contact>> {
    let bad = |reason: &str| Error::InvalidShape { spec: spec.into(), reason: reason.into() };
    let (path, u0) =
        rest.rsplit_once('@').ok_or_else(|| bad("needs the mean indentation: profile:FILE@U0 or gx:FILE@U0"))?;
    let u0: f64 = u0.trim().parse().map_err(|_| bad("the mean indentation after '@' is not a number"))?;
    let text = read(path).map_err(|e| Error::File { path: path.into(), source: Box::new(e) })?;
    let t = Table::parse(&text, path, profile)?.at(u0)?.named(spec);
    Ok(std::sync::Arc::new(t))
}

/// A tabulated contact, normalised: `G(z) = g(x_c z)/U0` with `G(1) = 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct Tabulated {
    /// `G` on the normalised knots.
    g: Pchip,
    /// The same from every other knot (for the interpolation error).
    coarse: Option<Pchip>,
    /// Contact radius at the mean indentation, in the table's length unit.
    pub contact_radius: f64,
    /// The name outputs give the shape.
    name: String,
}

impl Tabulated {
    /// This contact named `name` (as outputs print it).
    #[must_use]
    pub fn named(self, name: &str) -> Tabulated {
        Tabulated { name: name.into(), ..self }
    }

    /// The name outputs give the shape.
    pub fn name(&self) -> &str {
        &self.name
    }
}

/// `mu_macro/mu0` of a tabulated contact and its error estimates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TabulatedResult {
    /// Ratio and reduction.
    pub ratio: Ratio,
    /// Quadrature error estimate of `mu_ratio`.
    pub error_estimate: f64,
    /// Interpolation error estimate of `mu_ratio` (0 if the table is too short to tell).
    pub interpolation_error: f64,
}

/// Evaluate a tabulated contact at `(vbar, amp)`; both must be finite and `>= 0`
/// (an error otherwise).
pub(crate) fn evaluate(t: &Tabulated, vbar: f64, amp: f64) -> Result<TabulatedResult> {
    crate::error::check_nonneg("vbar", vbar)?;
    crate::error::check_nonneg("amp", amp)?;
    let (ratio, err) = integrate(&t.g, vbar, amp)?;
    let interpolation_error = match &t.coarse {
        Some(c) => integrate(c, vbar, amp).map_or(0.0, |(r, _)| (r.mu_ratio - ratio.mu_ratio).abs()),
        None => 0.0,
    };
    Ok(TabulatedResult { ratio, error_estimate: err, interpolation_error })
}

/// Mean normal force of the whole contact at amplitude `amp`, units
/// `E* x_c U0` (both sides of the MDR foundation), by the same quadrature.
pub(crate) fn mean_normal(t: &Tabulated, amp: f64) -> Result<f64> {
    crate::error::check_nonneg("amp", amp)?;
    Ok(2.0 * integrate_full(&t.g, 0.5, amp)?.2)
}

/// `G(z)` of a tabulated contact (the cubic interpolant; the end cubics
/// extrapolate beyond the table).
pub(crate) fn equivalent_profile(t: &Tabulated, z: f64) -> f64 {
    t.g.eval(z).0
}

/// `z` with `G(z) = 1 + amp`: an error if the table ends before.
pub(crate) fn reach(t: &Tabulated, amp: f64) -> Result<f64> {
    crate::error::check_nonneg("amp", amp)?;
    let gmax = *t.g.values().last().unwrap_or(&0.0);
    if gmax < 1.0 + amp {
        return Err(Error::param(
            "amp",
            amp,
            &format!("the tabulated profile ends at g = {gmax:?} U0, before the contact edge at (1 + amp) U0"),
        ));
    }
    Ok(t.g.inverse(1.0 + amp))
}

/// Static normal force at indentation `depth U0`, units `E* x_c U0` (both sides).
pub(crate) fn static_force(t: &Tabulated, depth: f64) -> f64 {
    if depth > 0.0 {
        normal_force(&t.g, depth)
    } else {
        0.0
    }
}

fn integrate(g: &Pchip, vbar: f64, amp: f64) -> Result<(Ratio, f64)> {
    if amp == 0.0 || vbar >= 1.0 {
        return Ok((Ratio { mu_ratio: 1.0, reduction: 0.0 }, 0.0));
    }
    integrate_full(g, vbar, amp).map(|(r, e, _)| (r, e))
}

/// Ratio, error estimate, and the one-sided mean normal `int amp <B> dz`.
fn integrate_full(g: &Pchip, vbar: f64, amp: f64) -> Result<(Ratio, f64, f64)> {
    if amp > 0.0 && amp < crate::contact::AMP_LINEAR {
        let (at, estimate, nn) = integrate_full(g, vbar, crate::contact::AMP_LINEAR)?;
        let k = amp / crate::contact::AMP_LINEAR;
        return Ok((at.scaled(k), estimate * k, nn));
    }
    if amp == 0.0 {
        // No oscillation: one side's static force, int (1 - G(z))_+ dz.
        return Ok((Ratio { mu_ratio: 1.0, reduction: 0.0 }, 0.0, 0.5 * normal_force(g, 1.0)));
    }
    let gmax = *g.values().last().unwrap_or(&0.0);
    if gmax < 1.0 + amp {
        return Err(Error::param(
            "amp",
            amp,
            &format!("the tabulated profile ends at g = {:?} U0, before the contact edge at (1 + amp) U0", gmax),
        ));
    }
    let c = (1.0 - vbar * vbar).sqrt();
    let z_of = |s: f64| {
        let y = 1.0 - amp * s;
        if y <= 0.0 {
            0.0
        } else {
            g.inverse(y)
        }
    };
    let zmax = z_of(-1.0);
    let mut cuts: Vec<f64> = g.knots().iter().copied().filter(|&z| z > 0.0 && z < zmax).collect();
    cuts.extend([0.0, zmax, z_of(1.0), z_of(c), z_of(-c)]);
    cuts.retain(|&z| (0.0..=zmax).contains(&z));
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let pass = |p: f64, q: f64, m: usize| {
        crate::contact::cosine_band(p, q, m, vbar, amp, &|z| ((1.0 - g.eval(z).0) / amp, 1.0))
    };
    let (mut nn, mut dd, mut en, mut ed) = (0.0, 0.0, 0.0, 0.0);
    for w in cuts.windows(2) {
        let (a, b) = (pass(w[0], w[1], PASS_ORDERS.0), pass(w[0], w[1], PASS_ORDERS.1));
        nn += b.0;
        dd += b.1;
        en += (b.0 - a.0).abs();
        ed += (b.1 - a.1).abs();
    }
    // Truncation (the 16/32-point difference per interval) plus rounding.
    let reduction = if nn > 0.0 { dd / nn } else { 0.0 };
    let terms = (PASS_ORDERS.0 + PASS_ORDERS.1) * (cuts.len() - 1);
    let truncation = crate::ratio::quotient_error(nn, dd, en, ed);
    let estimate = truncation + crate::ratio::rounding_estimate(reduction, terms);
    let ratio = Ratio::from_deficit_within(dd, nn, estimate, "tabulated contact")?;
    Ok((ratio, estimate, nn))
}

#[cfg(test)]
#[path = "profile_tests.rs"]
mod tests;
