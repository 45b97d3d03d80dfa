//! The events within a sampling step: the first zero of any of a phase's
//! event functions (rows `w`, the function `w z` positive inside the phase),
//! bracketed on the step's Taylor polynomial, grazing zeros included.

use super::phase::{Generator, Kind, State};
use crate::numerics::root::bracketed;
use nalgebra::SMatrix;

/// Most events in a row within one sampling step, per spring. In a step each
/// event function has at most one extremum, so it changes sign at most
/// twice: a correct phase machine meets a few events a step. More is a phase
/// chattering at a switch (a defect): the step is finished without events
/// and the solve refused (`Foundation::chattered`), never left to run on.
pub(crate) const MAX_EVENTS_IN_A_STEP: usize = 64;

/// A transition inside a period.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SystemEvent {
    /// The phase that starts.
    pub kind: Kind,
    /// Where, in `[0, 2 pi)`.
    pub tau: f64,
    /// The contact force there (units `mu0 kz u0`): after a stick or a slip
    /// begins, the total force; where a spring touches or leaves, that
    /// spring's, 0.
    pub force: f64,
}

/// An event function: the row `w` (the function is `w z`, positive inside
/// the phase) and what its zero means.
pub(crate) type Event<T> = (SMatrix<f64, 1, 8>, T);

/// An event function with the row of its derivative in the phase (`w A`).
pub(crate) type Sloped<T> = (SMatrix<f64, 1, 8>, SMatrix<f64, 1, 8>, T);

/// `events` of the phase with generator `a`, each with its derivative's row.
pub(crate) fn with_slopes<T>(a: &Generator, events: Vec<Event<T>>) -> Vec<Sloped<T>> {
    events.into_iter().map(|(w, tag)| (w, w * a, tag)).collect()
}

/// The first zero within `h` of `z` among `events` of the phase with
/// generator `a` (`end` the state after `h`): its offset and tag. A
/// function below 0 at the step's end has a zero in the step (bracketed),
/// or is already below 0 at its start (a force a rounding beyond its bound
/// after a switch, a contact point a rounding past turning): the phase ends
/// at once. A minimum inside the step that dips below 0 between positive
/// ends (a grazing event) is found from the derivative's sign change. The
/// roots are sought on the step's Taylor polynomial ([`Taylor`]).
#[inline]
pub(crate) fn first_event<T: Copy>(
    a: &Generator,
    events: &[Sloped<T>],
    z: &State,
    h: f64,
    end: &State,
) -> Option<(f64, T)> {
    let mut first: Option<(f64, T)> = None;
    let mut taylor: Option<Taylor> = None;
    for &(w, wa, next) in events {
        let (g0, g1) = ((w * z)[0], (w * end)[0]);
        let s0 = (wa * z)[0];
        let below = g1 < 0.0;
        if below && g0 <= 0.0 {
            // At or a rounding below 0 where the step starts: at once,
            // unless the function rises into the phase (a spring that
            // sticks where it touches, its force and bound both 0).
            let c = taylor.get_or_insert_with(|| Taylor::new(a, z, h)).row(&w);
            let d = rising_from_zero(&c, h, (w.abs() * (a.abs() * z.abs()))[0]).unwrap_or(0.0);
            if first.as_ref().is_none_or(|f| d < f.0) {
                first = Some((d, next));
            }
            continue;
        }
        let grazing = !below && g0 > 0.0 && s0 < 0.0 && (wa * end)[0] > 0.0;
        if !(below || grazing) {
            continue;
        }
        let c = taylor.get_or_insert_with(|| Taylor::new(a, z, h)).row(&w);
        let g = |d: f64| horner(&c, d);
        let root = if below {
            Some(bracketed(g, 0.0, h, 4.0 * f64::EPSILON).x)
        } else {
            let slope: Vec<f64> = c.iter().enumerate().skip(1).map(|(k, ck)| k as f64 * ck).collect();
            let m = bracketed(|d| horner(&slope, d), 0.0, h, 4.0 * f64::EPSILON).x;
            (g(m) < 0.0).then(|| bracketed(g, 0.0, m, 4.0 * f64::EPSILON).x)
        };
        if let Some(d) = root {
            if first.as_ref().is_none_or(|f| d < f.0) {
                first = Some((d, next));
            }
        }
    }
    first
}

/// The zero within `h` of a function that starts at 0 up to rounding
/// (Taylor coefficients `c`, `c[0] <= 0`) and rises into the phase, then
/// falls below 0 by the step's end; `None` where it does not rise, or does
/// not fall below 0 again within the step (the phase ends at once). It rises where its slope `c[1]` is positive beyond
/// its rounding `slope_rounding` (a bound on `|w| |A| |z|`, times a few
/// ulps), or, the slope 0 up to rounding, where its curvature `c[2]` is
/// positive (contact regained with the body as fast as the bound: `x' =
/// B'`). Its zero is then that of `(g - c[0]) / d` (or `/ d^2`), the
/// polynomial deflated by the zero at the start, bracketed on the step.
fn rising_from_zero(c: &[f64], h: f64, slope_rounding: f64) -> Option<f64> {
    let flat = c[1].abs() <= 8.0 * f64::EPSILON * slope_rounding;
    let skip = match (flat, c.get(2)) {
        (false, _) if c[1] > 0.0 => 1,
        (true, Some(&c2)) if c2 > 0.0 => 2,
        _ => return None,
    };
    let deflated = |d: f64| horner(&c[skip..], d);
    (deflated(h) < 0.0).then(|| bracketed(deflated, 0.0, h, 4.0 * f64::EPSILON).x)
}

/// Most terms of a step's Taylor polynomial.
const MAX_TERMS: usize = 60;

/// `exp(A d) z` on `0 <= d <= h` as its Taylor polynomial `sum_k A^k z d^k/k!`,
/// summed until a term is below 1e-18 of the state (a sampling step is at
/// most a quarter of the fastest time scale, so the terms fall at least like
/// `4^-k/k!`): an event function along the step is a polynomial, its roots
/// cheap to bracket.
pub(crate) struct Taylor {
    terms: Vec<State>,
}

impl Taylor {
    #[inline(never)]
    pub(crate) fn new(a: &Generator, z: &State, h: f64) -> Taylor {
        let scale = 1.0 + z.amax();
        let mut terms = Vec::with_capacity(32);
        terms.push(*z);
        let mut t = *z;
        let mut hk = 1.0;
        for k in 1..=MAX_TERMS {
            t = a * t / k as f64;
            hk *= h;
            terms.push(t);
            if k >= 4 && t.amax() * hk <= 1e-18 * scale {
                break;
            }
        }
        Taylor { terms }
    }

    /// The polynomial's coefficients of the function `w z`.
    pub(crate) fn row(&self, w: &SMatrix<f64, 1, 8>) -> Vec<f64> {
        self.terms.iter().map(|t| (w * t)[0]).collect()
    }
}

/// `sum_k c_k d^k`.
fn horner(c: &[f64], d: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, ck| acc * d + ck)
}

#[cfg(test)]
mod tests {
    use super::{first_event, rising_from_zero, with_slopes, Kind, State};
    use crate::system::phase::{advance, Linear, Params, COS, ONE, SIN};
    use nalgebra::SMatrix;

    /// A grazing event: `g = 0.999 + cos tau` dips below 0 around `tau = pi`
    /// between two positive ends of a step (`pi -+ 0.05`: 2.5e-4). Its first
    /// zero, `pi - arccos 0.999`, is found from the derivative's sign change;
    /// a step checked only at its ends (grazing detection off) misses it, and
    /// a function positive throughout (`1.001 + cos tau`) has none.
    #[test]
    fn a_grazing_event_inside_a_step_is_found() {
        let p = Params { kappa: 1.0, omega: 0.5, zeta: 0.05, vhat: 0.3, amp: 0.5, t: 0.0, phase: 0.0 };
        let a = p.generator_of(Linear::default());
        let start = std::f64::consts::PI - 0.05;
        let mut z = State::zeros();
        (z[ONE], z[COS], z[SIN]) = (1.0, start.cos(), start.sin());
        let end = advance(&a, &z, 0.1);
        for (c, want) in [(0.999, Some(std::f64::consts::PI - 0.999f64.acos())), (1.001, None)] {
            let mut w = SMatrix::<f64, 1, 8>::zeros();
            (w[ONE], w[COS]) = (c, 1.0);
            assert!((w * z)[0] > 0.0 && (w * end)[0] > 0.0);
            let got = first_event(&a, &with_slopes(&a, vec![(w, Kind::Stick)]), &z, 0.1, &end);
            match (got, want) {
                (Some((d, Kind::Stick)), Some(tau)) => assert!((start + d - tau).abs() < 1e-14, "{d} {tau}"),
                (None, None) => {}
                other => panic!("c {c}: {other:?}"),
            }
        }
    }

    /// A function at 0 up to rounding where a step starts, which rises into
    /// the phase and falls below 0 by the step's end, has its zero past the
    /// maximum: `d (0.5 - 5 d)` (rising, zero 0.1), `d^2 (1 - 10 d)` with a
    /// slope within rounding of 0 (rising by its curvature, zero 0.1); one
    /// falling at once, or flat and curving down, ends the phase at once.
    #[test]
    fn a_function_rising_from_zero_ends_past_its_maximum() {
        let zero = |c: &[f64]| rising_from_zero(c, 0.2, 1.0);
        assert!((zero(&[-1e-17, 0.5, -5.0]).unwrap() - 0.1).abs() < 1e-15);
        assert!((zero(&[-1e-17, -1e-17, 1.0, -10.0]).unwrap() - 0.1).abs() < 1e-15);
        assert_eq!(zero(&[0.0, -0.5, 1.0]), None);
        assert_eq!(zero(&[0.0, 1e-17, -1.0]), None);
        // A slope beyond rounding decides, whatever the curvature.
        assert_eq!(zero(&[0.0, -1e-12, 1.0, -10.0]), None);
        // Rising throughout the step: no zero in it, the phase ends at once.
        assert_eq!(zero(&[-1e-17, 0.5, 1.0]), None);
        // The slope's rounding scales with its bound: a slope of -1e-14 is
        // 0 up to rounding at a bound of 100 (the curvature decides), and
        // falling at a bound of 1e-3 (cargo-mutants: `/` for `*` passed).
        let c = [0.0, -1e-14, 1.0, -10.0];
        assert!((rising_from_zero(&c, 0.2, 100.0).unwrap() - 0.1).abs() < 1e-12);
        assert_eq!(rising_from_zero(&c, 0.2, 1e-3), None);
    }

    /// Of several event functions in one step, the first zero wins, whichever
    /// function it belongs to and in whatever order they come: on the step
    /// from `pi - 0.05` of length 0.2, `cos(pi - 0.05) - cos tau` rises from
    /// 0 at the start (a stick from a regain) and falls to 0 at 0.1,
    /// `cos tau - cos(pi - 0.02)` dips below 0 at 0.03 (grazing), and
    /// `tau_0 + 0.15 - tau` crosses at 0.15.
    #[test]
    fn the_first_zero_of_several_wins() {
        use crate::system::phase::TAU;
        let p = Params { kappa: 1.0, omega: 0.5, zeta: 0.05, vhat: 0.3, amp: 0.5, t: 0.0, phase: 0.0 };
        let a = p.generator_of(Linear::default());
        let start = std::f64::consts::PI - 0.05;
        let mut z = State::zeros();
        (z[ONE], z[COS], z[SIN], z[TAU]) = (1.0, start.cos(), start.sin(), start);
        let end = advance(&a, &z, 0.2);
        let row = |one: f64, cos: f64, tau: f64| {
            let mut w = SMatrix::<f64, 1, 8>::zeros();
            (w[ONE], w[COS], w[TAU]) = (one, cos, tau);
            w
        };
        let rising = (row(start.cos(), -1.0, 0.0), Kind::Stick);
        let grazing = (row(-(std::f64::consts::PI - 0.02).cos(), 1.0, 0.0), Kind::Forward);
        let crossing = (row(start + 0.15, 0.0, -1.0), Kind::Backward);
        for (events, want) in [
            (vec![rising, grazing], (0.03, Kind::Forward)),
            (vec![grazing, rising], (0.03, Kind::Forward)),
            (vec![crossing, rising], (0.1, Kind::Stick)),
            (vec![rising, crossing], (0.1, Kind::Stick)),
            (vec![crossing], (0.15, Kind::Backward)),
        ] {
            let (d, kind) = first_event(&a, &with_slopes(&a, events.clone()), &z, 0.2, &end).unwrap();
            assert!((d - want.0).abs() < 1e-12 && kind == want.1, "{events:?}: {d} {kind:?}");
        }
    }
}
