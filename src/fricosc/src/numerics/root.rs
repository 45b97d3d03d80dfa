//! Root finding: a thin wrapper over the `roots` crate for bracketed searches
//! (analytic bracket in, root and evaluation count out), and a safeguarded
//! Halley iteration for the stick end, which falls back to it.
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

/// Most Halley steps before [`bracketed`] takes over.
const HALLEY_MAX_STEPS: u32 = 12;

/// Root in `[lo, hi]` by Halley's method from `guess`, where
/// `fdd(x) = (f(x), f'(x), f''(x))` shares its work between the three (one or
/// two `sin_cos`, say). The step is `(f/f') / (1 - f f''/(2 f'^2))`, Newton's
/// where that correction is not mild (outside `[1/2, 2]`). Halley converges
/// cubically: from a guess good to `1e-3` two evaluations reach `1e-16`, where
/// Newton needs three. It stops once a step is below `rtol * |x|` (the last step
/// then cubes the error). If a step leaves the bracket, is not finite, or
/// `HALLEY_MAX_STEPS` pass, [`bracketed`] takes over on `[lo, hi]`.
///
/// Written here rather than taken from `roots` (which has Newton but not
/// Halley): the stick end is every spring's inner loop, where the crate's
/// convergence callbacks would cost more than the step.
///
/// `accept`, where not 0, also stops after a Halley step `d` (at most 1e-2
/// relative) once the next iterate's predicted error is below `accept`
/// relative: Halley's error is cubed, `e1 = K e0^3` with
/// `K = (f''/2f')^2 - f'''/6f'` (Taylor), and `|f'''|` is at most 1 for the
/// stick's gaps (a sine's terms and linear ones), so `|e1| <= K |d|^3` with
/// `K = (f''/2f')^2 + 1/(6 |f'|)` to leading order. The means need the stick
/// end only to ~1e-8 (the deficit is stationary in it): one evaluation where
/// the start is good to ~1e-3, where the step rule took two.
// Inlined into each stick form: its closure's `sin_cos` and arithmetic then
// fuse with the caller's (an outlined call cost the parabolic table 0.6 %).
#[inline(always)]
pub(crate) fn halley(
    fdd: impl Fn(f64) -> (f64, f64, f64),
    lo: f64,
    hi: f64,
    guess: f64,
    rtol: f64,
    accept: f64,
) -> Root {
    if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
        // An empty bracket (both ends the same point to rounding): that point is the root.
        return Root { x: lo.min(hi), evaluations: 0 };
    }
    let mut x = guess.clamp(lo, hi);
    for k in 1..=HALLEY_MAX_STEPS {
        let (f, d1, d2) = fdd(x);
        if f == 0.0 {
            return Root { x, evaluations: k };
        }
        let newton = f / d1;
        let denom = 1.0 - 0.5 * newton * d2 / d1;
        let step = if (0.5..=2.0).contains(&denom) { newton / denom } else { newton };
        let x1 = x - step;
        if !(lo..=hi).contains(&x1) {
            // Not finite, or out of the bracket.
            let mut r = bracketed(|x| fdd(x).0, lo, hi, rtol);
            r.evaluations += k;
            return r;
        }
        let (d, scale) = ((x1 - x).abs(), x.abs().max(x1.abs()));
        if d <= rtol * scale + f64::MIN_POSITIVE {
            return Root { x: x1, evaluations: k };
        }
        if accept > 0.0 && step != newton && d <= 1e-2 * scale {
            let c = 0.5 * d2 / d1;
            if (c * c + 1.0 / (6.0 * d1.abs())) * d * d * d <= accept * scale {
                return Root { x: x1, evaluations: k };
            }
        }
        x = x1;
    }
    let mut r = bracketed(|x| fdd(x).0, lo, hi, rtol);
    r.evaluations += HALLEY_MAX_STEPS;
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A predicted error below `accept` ends Halley's method one evaluation
    /// early, with the next iterate within it; not after a Newton step, a step
    /// above 1e-2, or a predicted error above `accept`.
    #[test]
    fn halley_accepts_a_predicted_error() {
        // sin x - 1/2 on [0, 1] (|f'''| <= 1), root pi/6, from 1e-4 and 3e-3 off.
        let root = std::f64::consts::FRAC_PI_6;
        let fdd = |x: f64| (x.sin() - 0.5, x.cos(), -x.sin());
        for (off, accept, evaluations) in [(1e-4, 1e-10, 1), (1e-4, 0.0, 2), (3e-3, 1e-10, 2), (3e-3, 1e-7, 1)] {
            let r = halley(fdd, 0.0, 1.0, root + off, 1e-6, accept);
            assert_eq!(r.evaluations, evaluations, "off {off} accept {accept}");
            assert!((r.x - root).abs() <= accept.max(1e-15) * root, "off {off}: {:e}", r.x - root);
        }
        // Predicted errors: (f''/2f')^2 + 1/(6 f') = 0.083 + 0.19 times d^3 = 1e-12
        // for d = 1e-4 (accepted at 1e-10, not at 1e-13).
        assert_eq!(halley(fdd, 0.0, 1.0, root + 1e-4, 1e-6, 1e-13).evaluations, 2);
        // A step above 1e-2 relative is not accepted, whatever the prediction
        // (the second, ~1e-3, is).
        assert_eq!(halley(fdd, 0.0, 1.0, root + 0.1, 1e-6, 1.0).evaluations, 2);
        // Nor a Newton step (the correction outside [1/2, 2]: here f'' huge).
        let newton = |x: f64| (x - 0.5, 1.0, 1e6);
        assert_eq!(halley(newton, 0.0, 1.0, 0.5 + 1e-4, 1e-9, 1.0).evaluations, 2);
    }

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

    /// Bisection, the fallback of a failed regula falsi, on its own: to the
    /// relative width asked for, from either sign at `lo`, and an exact zero
    /// at a midpoint returned as it is.
    #[test]
    fn bisection_narrows_to_the_tolerance_from_either_side() {
        for (sign, rtol) in [(1.0, 1e-6), (-1.0, 1e-6), (1.0, 1e-15), (-1.0, 4.0 * f64::EPSILON)] {
            let f = |x: f64| sign * (x * x - 2.0);
            let x = bisect(&f, 1.0, f(1.0), 3.0, rtol);
            assert!((x - std::f64::consts::SQRT_2).abs() <= 2.0 * rtol * x, "sign {sign} rtol {rtol:e}: {x}");
        }
        // Far from 1: the width is relative.
        let x = bisect(&|x: f64| x - 3e-200, 1e-200, -2e-200, 4e-200, 1e-12);
        assert!((x / 3e-200 - 1.0).abs() <= 2e-12, "{x:e}");
        let x = bisect(&|x: f64| x - 3e200, 1e200, -2e200, 4e200, 1e-12);
        assert!((x / 3e200 - 1.0).abs() <= 2e-12, "{x:e}");
        // The first midpoint is the root.
        let evals = Cell::new(0);
        let x = bisect(
            &|x: f64| {
                evals.set(evals.get() + 1);
                x - 2.0
            },
            1.0,
            -1.0,
            3.0,
            1e-15,
        );
        assert_eq!((x, evals.get()), (2.0, 1));
    }

    #[test]
    fn collapsed_bracket_returns_the_better_end() {
        let r = bracketed(|x| (x - 1.0).powi(2), 1.0 + 1e-9, 3.0, 1e-15);
        assert_eq!(r.x, 1.0 + 1e-9);
        assert_eq!(r.evaluations, 2);
    }
}

#[cfg(test)]
mod halley_tests {
    use super::*;

    #[test]
    fn halley_converges_cubically_from_a_close_guess() {
        // From 1.4 (error 1e-2): errors 1e-6 and 1e-19, and the third step is below 1e-10.
        let r = halley(|x| (x * x * x - 2.0 * x, 3.0 * x * x - 2.0, 6.0 * x), 1.0, 2.0, 1.4, 1e-10, 0.0);
        assert!((r.x - std::f64::consts::SQRT_2).abs() <= 2.3e-16, "{}", r.x);
        assert_eq!(r.evaluations, 3);
        // Newton (f'' = 0 given) needs a fourth.
        let n = halley(|x| (x * x * x - 2.0 * x, 3.0 * x * x - 2.0, 0.0), 1.0, 2.0, 1.4, 1e-10, 0.0);
        assert_eq!(n.evaluations, 4);
    }

    #[test]
    fn halley_leaving_the_bracket_falls_back_to_regula_falsi() {
        // From 0.1 the first step of x^2 - 2 leaves [0, 2].
        let r = halley(|x| (x * x - 2.0, 2.0 * x, 2.0), 0.0, 2.0, 0.1, 1e-14, 0.0);
        assert!((r.x - std::f64::consts::SQRT_2).abs() < 1e-14);
        assert!(r.evaluations > 3, "{}", r.evaluations);
    }

    /// Evaluations are reported (`Spring::root_evaluations`): a fallback adds
    /// the Halley steps spent to the bracketed search's own.
    #[test]
    fn a_fallback_counts_the_halley_steps_before_it() {
        let f = |x: f64| x * x - 2.0;
        let plain = bracketed(f, 0.0, 2.0, 1e-14);
        // Leaves the bracket at the first step.
        let out = halley(|x| (f(x), 2.0 * x, 2.0), 0.0, 2.0, 0.1, 1e-14, 0.0);
        assert_eq!(out.evaluations, 1 + plain.evaluations);
        // A derivative 1000x too large: tiny steps, all inside, never converged.
        let slow = halley(|x| (f(x), 2000.0 * x, 0.0), 0.0, 2.0, 1.0, 1e-14, 0.0);
        assert_eq!(slow.evaluations, HALLEY_MAX_STEPS + plain.evaluations);
        assert!((slow.x - std::f64::consts::SQRT_2).abs() < 1e-14);
    }

    #[test]
    fn a_root_at_the_guess_costs_one_evaluation() {
        assert_eq!(halley(|x| (x - 1.0, 1.0, 0.0), 0.0, 2.0, 1.0, 1e-10, 0.0), Root { x: 1.0, evaluations: 1 });
    }
}

#[cfg(test)]
mod empty_bracket_tests {
    use super::*;

    #[test]
    fn an_inverted_or_empty_bracket_returns_without_panicking() {
        let r = halley(|x| (x, 1.0, 0.0), 2.2e-16, 0.0, 1.0, 1e-10, 0.0);
        assert_eq!((r.x, r.evaluations), (0.0, 0));
        assert_eq!(bracketed(|x| x, 1.0, 1.0, 1e-10).x, 1.0);
    }
}
