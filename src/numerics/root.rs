//! A thin wrapper over the `roots` crate: analytic bracket (and a guess) in,
//! root and evaluation count out.
//!
//! Every event time of the exact solver is the unique sign change of a function
//! on an analytically known bracket, so no bracket search is ever needed. When a
//! bracket collapses (a tangency: the sign at one end is lost to rounding) the
//! endpoint with the smaller residual is the root to working accuracy, and it is
//! returned without iterating; the callers document which limit that is.

use std::cell::Cell;

/// Result of one bracketed root search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Root {
    /// The root.
    pub x: f64,
    /// Number of function evaluations spent (the two bracket ends included).
    pub evaluations: u32,
}

/// Stop when the bracket is narrower than `rtol * |x|` (plus a tiny absolute floor).
struct Tolerance {
    rtol: f64,
    max_iter: usize,
}

impl roots::Convergency<f64> for Tolerance {
    fn is_root_found(&mut self, y: f64) -> bool {
        y == 0.0
    }
    fn is_converged(&mut self, a: f64, b: f64) -> bool {
        (a - b).abs() <= self.rtol * a.abs().max(b.abs()) + f64::MIN_POSITIVE
    }
    fn is_iteration_limit_reached(&mut self, iter: usize) -> bool {
        iter >= self.max_iter
    }
}

/// Root of `f` on `[lo, hi]`, where `f(lo)` and `f(hi)` should have opposite signs,
/// by the Illinois variant of regula falsi (`roots::find_root_regula_falsi`).
///
/// `rtol` is the relative bracket width at which the search stops. If rounding has
/// removed the sign change (a collapsed bracket), the end with the smaller `|f|`
/// is returned without iterating.
pub(crate) fn bracketed(f: impl Fn(f64) -> f64, lo: f64, hi: f64, rtol: f64) -> Root {
    let count = Cell::new(0u32);
    let g = |x: f64| {
        count.set(count.get() + 1);
        f(x)
    };
    if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
        return Root { x: lo.min(hi), evaluations: 0 };
    }
    let (flo, fhi) = (g(lo), g(hi));
    if let Some(x) = collapsed(lo, flo, hi, fhi) {
        return Root { x, evaluations: count.get() };
    }
    // The crate evaluates the ends again; the two extra calls are counted too.
    let mut tol = Tolerance { rtol, max_iter: 200 };
    match roots::find_root_regula_falsi(lo, hi, &g, &mut tol) {
        Ok(x) if x >= lo && x <= hi => Root { x, evaluations: count.get() },
        // The secant step overflows for huge |x f| (it returns NaN), or the
        // iteration limit was hit: bisection needs only the signs.
        _ => {
            let x = bisect(&g, lo, flo, hi, rtol);
            Root { x, evaluations: count.get() }
        }
    }
}

/// Plain bisection on a sign-changing bracket, to `rtol` relative width (or
/// until the midpoint no longer moves).
fn bisect(f: &impl Fn(f64) -> f64, mut lo: f64, flo: f64, mut hi: f64, rtol: f64) -> f64 {
    let positive_at_lo = flo > 0.0;
    for _ in 0..2100 {
        let mid = 0.5 * lo + 0.5 * hi;
        if mid <= lo || mid >= hi || (hi - lo) <= rtol * lo.abs().max(hi.abs()) {
            break;
        }
        let fm = f(mid);
        if fm == 0.0 {
            return mid;
        }
        if (fm > 0.0) == positive_at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * lo + 0.5 * hi
}

/// The root when the bracket has no sign change left (or an end is a root).
fn collapsed(lo: f64, flo: f64, hi: f64, fhi: f64) -> Option<f64> {
    if flo == 0.0 {
        Some(lo)
    } else if fhi == 0.0 || flo.signum() == fhi.signum() {
        Some(if fhi.abs() <= flo.abs() { hi } else { lo })
    } else {
        None
    }
}

/// Root in `[lo, hi]` by Newton's method from `guess`
/// (`roots::find_root_newton_raphson`), where `fdf(x) = (f(x), f'(x))` shares
/// its work between the two (one `sin_cos`, say): the crate asks for `f` and
/// `f'` separately at the same `x`, and the pair is cached here, out of the
/// caller's sight. Newton stops once a step is below `rtol * |x|` (the last step
/// then squares the error). If it fails or leaves the bracket, [`bracketed`]
/// takes over on `[lo, hi]`.
pub(crate) fn newton(fdf: impl Fn(f64) -> (f64, f64), lo: f64, hi: f64, guess: f64, rtol: f64) -> Root {
    if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
        // An empty bracket (both ends the same point to rounding): that point is the root.
        return Root { x: lo.min(hi), evaluations: 0 };
    }
    let count = Cell::new(0u32);
    let last = Cell::new((f64::NAN, 0.0, 0.0));
    let eval = |x: f64| {
        let (lx, fx, dfx) = last.get();
        if lx == x {
            return (fx, dfx);
        }
        count.set(count.get() + 1);
        let (fx, dfx) = fdf(x);
        last.set((x, fx, dfx));
        (fx, dfx)
    };
    let f = |x: f64| eval(x).0;
    let df = |x: f64| eval(x).1;
    let mut tol = Tolerance { rtol, max_iter: 12 };
    let start = guess.clamp(lo, hi);
    match roots::find_root_newton_raphson(start, &f, &df, &mut tol) {
        Ok(x) if x >= lo && x <= hi => Root { x, evaluations: count.get() },
        _ => {
            let mut r = bracketed(|x| fdf(x).0, lo, hi, rtol);
            r.evaluations += count.get();
            r
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_a_simple_root_to_the_requested_tolerance() {
        let r = bracketed(|x| x * x - 2.0, 0.0, 2.0, 1e-15);
        assert!((r.x - std::f64::consts::SQRT_2).abs() < 4e-15);
        assert!(r.evaluations > 2 && r.evaluations < 20, "{}", r.evaluations);
    }

    /// Regula falsi's secant step overflows for huge `x f(x)`; bisection takes over.
    #[test]
    fn huge_values_fall_back_to_bisection_not_nan() {
        let r = bracketed(|x| x * 1e100 - 3e293, 1e192, 1e194, 1e-15);
        assert!((r.x / 3e193 - 1.0).abs() < 1e-14, "{}", r.x);
    }

    #[test]
    fn collapsed_bracket_returns_the_better_end() {
        let r = bracketed(|x| (x - 1.0).powi(2), 1.0 + 1e-9, 3.0, 1e-15);
        assert_eq!(r.x, 1.0 + 1e-9);
        assert_eq!(r.evaluations, 2);
    }
}

#[cfg(test)]
mod newton_tests {
    use super::*;

    #[test]
    fn newton_converges_quadratically_from_a_close_guess() {
        let r = newton(|x| (x * x - 2.0, 2.0 * x), 0.0, 2.0, 1.4, 1e-10);
        assert!((r.x - std::f64::consts::SQRT_2).abs() < 4e-16);
        assert!(r.evaluations <= 5, "{}", r.evaluations);
    }

    #[test]
    fn newton_leaving_the_bracket_falls_back_to_regula_falsi() {
        // From 0.1 the first Newton step of x^2 - 2 jumps to 10.05, outside [0, 2].
        let r = newton(|x| (x * x - 2.0, 2.0 * x), 0.0, 2.0, 0.1, 1e-14);
        assert!((r.x - std::f64::consts::SQRT_2).abs() < 1e-14);
    }
}

#[cfg(test)]
mod empty_bracket_tests {
    use super::*;

    #[test]
    fn an_inverted_or_empty_bracket_returns_without_panicking() {
        let r = newton(|x| (x, 1.0), 2.2e-16, 0.0, 1.0, 1e-10);
        assert_eq!((r.x, r.evaluations), (0.0, 0));
        assert_eq!(bracketed(|x| x, 1.0, 1.0, 1e-10).x, 1.0);
    }
}
