//! A thin wrapper over the `roots` crate's Brent method: analytic bracket in,
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
pub struct Root {
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

/// Root of `f` on `[lo, hi]`, where `f(lo)` and `f(hi)` should have opposite signs.
///
/// `rtol` is the relative width at which the search stops. If rounding has
/// removed the sign change (a collapsed bracket), the end with the smaller `|f|`
/// is returned. Brent's method cannot fail on a valid bracket within its
/// iteration limit; if it ever did, the last bracket midpoint is returned.
pub fn brent(f: impl Fn(f64) -> f64, lo: f64, hi: f64, rtol: f64) -> Root {
    let count = Cell::new(0u32);
    let g = |x: f64| {
        count.set(count.get() + 1);
        f(x)
    };
    let (flo, fhi) = (g(lo), g(hi));
    if flo == 0.0 {
        return Root { x: lo, evaluations: count.get() };
    }
    if fhi == 0.0 || flo.signum() == fhi.signum() {
        let x = if fhi.abs() <= flo.abs() { hi } else { lo };
        return Root { x, evaluations: count.get() };
    }
    let mut tol = Tolerance { rtol, max_iter: 200 };
    let x = roots::find_root_brent(lo, hi, &g, &mut tol).unwrap_or(0.5 * (lo + hi));
    Root { x, evaluations: count.get() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_a_simple_root_to_the_requested_tolerance() {
        let r = brent(|x| x * x - 2.0, 0.0, 2.0, 1e-15);
        assert!((r.x - std::f64::consts::SQRT_2).abs() < 4e-15);
        assert!(r.evaluations > 2 && r.evaluations < 20, "{}", r.evaluations);
    }

    #[test]
    fn collapsed_bracket_returns_the_better_end() {
        let r = brent(|x| (x - 1.0).powi(2), 1.0 + 1e-9, 3.0, 1e-15);
        assert_eq!(r.x, 1.0 + 1e-9);
        assert_eq!(r.evaluations, 2);
    }
}
