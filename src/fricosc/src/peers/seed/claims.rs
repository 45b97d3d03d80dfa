//! Every quantitative statement of the seed, checked against the exact solver,
//! with a verdict computed from a criterion written beside it.

use crate::model::spring::EventKind;
use crate::peers::seed;
use crate::peers::stepper::{physical_mu_ratio, PhysicalSpring};
use crate::{Conditions, Report, Shape, DEFAULT_TOL};
use std::f64::consts::{PI, TAU};

/// The verdict on one claim, computed from its criterion ([`Claim::criterion`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Verdict {
    /// The statement is right (to the accuracy it states, or exactly).
    Holds,
    /// Right within the tolerance the statement itself gives or implies.
    HoldsApproximately,
    /// The statement's accuracy is better than measured.
    Overstated,
    /// A printed formula or number is off by a recognisable slip (sign, factor).
    Misprint,
    /// Neither: the statement does not hold.
    Wrong,
}

/// One checked statement.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct Claim {
    /// Equation or place in the seed.
    pub claim: String,
    /// What the seed says.
    pub seed_says: String,
    /// What the exact solver gives.
    pub exact_gives: String,
    /// The rule that turns the measured quantities into the verdict.
    pub criterion: String,
    /// The measured quantities the verdict is computed from, by name.
    pub measured: Vec<(String, f64)>,
    /// Largest deviation found (absolute, in the claim's own quantity), if any.
    pub deviation: Option<f64>,
    /// What the deviation is, with its unit.
    pub deviation_is: String,
    /// Where the largest deviation is.
    pub location: String,
    /// The verdict.
    pub verdict: Verdict,
}

impl Verdict {
    /// The verdict's name in a report: `holds`, `holds approximately`,
    /// `overstated`, `misprint`, `wrong`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::HoldsApproximately => "holds approximately",
            Verdict::Overstated => "overstated",
            Verdict::Misprint => "misprint",
            Verdict::Wrong => "wrong",
        }
    }
}

impl Claim {
    /// A measured quantity by name.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.measured.iter().find(|m| m.0 == name).map(|m| m.1)
    }
}

pub(super) fn named(pairs: &[(&str, f64)]) -> Vec<(String, f64)> {
    pairs.iter().map(|&(n, v)| (n.to_string(), v)).collect()
}

/// `mu_macro/mu0` of `shape` at `(vbar, amp)`, NaN where it fails (a claim's
/// verdict then says so).
fn mu_of(shape: &Shape, v: f64, a: f64) -> f64 {
    Conditions::vbar(v, a).and_then(|c| shape.ratio(&c)).map_or(f64::NAN, |r| r.mu_ratio)
}

fn mu_flat(v: f64, a: f64) -> f64 {
    mu_of(&Shape::flat(), v, a)
}

fn mu_mdr(n: f64, v: f64, a: f64) -> f64 {
    Shape::power(n).map_or(f64::NAN, |s| mu_of(&s, v, a))
}

/// The velocity at which small-velocity slopes are measured.
pub(crate) const SLOPE_VBAR: f64 = 1e-10;

/// Small-velocity slope `mu/vbar` of the flat punch, the exact solver's at
/// `vbar = 1e-10`.
#[must_use]
pub fn exact_slope(amp: f64) -> f64 {
    mu_flat(SLOPE_VBAR, amp) / SLOPE_VBAR
}

/// Largest `f(v, p)` over `v` in `{0, 1/k, ..., 1}` and `p` in `ps`, and where.
/// A NaN (a failed evaluation) is the largest of all: it becomes infinity, so
/// that the claim's verdict is "wrong" rather than the NaN being skipped.
fn worst_over(ps: &[f64], k: usize, f: impl Fn(f64, f64) -> f64) -> (f64, (f64, f64)) {
    let mut best = (0.0f64, (0.0, 0.0));
    for &p in ps {
        for j in 0..=k {
            let v = j as f64 / k as f64;
            let d = f(v, p);
            let d = if d.is_nan() { f64::INFINITY } else { d };
            if d > best.0 {
                best = (d, (v, p));
            }
        }
    }
    best
}

/// Eq. 11's bar: "very accurately" read as 1 % of the amplitude (the reduction at `vbar = 0`).
pub(crate) const EQ11_TOL: f64 = 0.01;
/// "About 20 %": within 5 percentage points.
pub(crate) const DROP_TOL: f64 = 0.05;
/// Eq. 27's bar: "approximately valid" read as within 0.05 of `mu0`.
pub(crate) const EQ27_TOL: f64 = 0.05;

/// Verdict of an approximation with error `err` against its bar `tol`.
pub(crate) fn graded(err: f64, tol: f64) -> Verdict {
    if err <= tol {
        Verdict::HoldsApproximately
    } else if err <= 3.0 * tol {
        Verdict::Overstated
    } else {
        Verdict::Wrong
    }
}

/// `mu/mu0` as a function of `(vbar, amp)`.
type Mu = Box<dyn Fn(f64, f64) -> f64>;

/// The shapes the shape-dependent claims are checked on.
fn shapes() -> [(&'static str, Mu); 3] {
    [
        ("flat", Box::new(mu_flat)),
        ("parabolic", Box::new(|v, a| mu_mdr(2.0, v, a))),
        ("cone", Box::new(|v, a| mu_mdr(1.0, v, a))),
    ]
}

/// Check every claim: one function per claim, each computing its measured
/// quantities and its verdict from the criterion written beside it (a few
/// seconds: two claims run the time stepper).
#[must_use]
pub fn claims() -> Vec<Claim> {
    vec![
        eq8_sign(),
        eq11_error(),
        eq12_exactness(),
        eq21_factor_pi(),
        eq22_limit(),
        slope_drop(),
        eq28_against_eq27(),
        critical_velocity(),
        eq27_shape_independence(),
        two_parameters(),
        eq14_small_amplitude(),
        static_friction_minimum_normal(),
        super::part_two::stiff_system(),
        super::part_two::heavy_soft_system(),
        super::part_two::resonance_removes_critical_velocity(),
        super::transverse::three_directions(),
        super::transverse::no_critical_velocity(),
        super::transverse::sideways_force(),
    ]
}

/// Eq. 8's sign, at vbar = 0.5, amp = 0.5: tau2 from the solver's events.
fn eq8_sign() -> Claim {
    let v = 0.5f64;
    let t1 = v.asin();
    let t2 = match Conditions::vbar(v, 0.5).and_then(|c| Shape::flat().report(&c)) {
        Ok(Report::Flat(p)) => p.events.iter().find(|e| e.kind == EventKind::Slip).map_or(f64::NAN, |e| e.tau),
        _ => f64::NAN,
    };
    let printed = |t: f64| seed::eq8_printed_residual(v, t);
    let corrected = |t: f64| seed::eq8_corrected_residual(v, t);
    let worst_printed = (1..=1000).map(|k| printed(t1 + k as f64 * TAU / 1000.0)).fold(f64::NEG_INFINITY, f64::max);
    let (r_printed, r_corrected) = (printed(t2).abs(), corrected(t2).abs());
    Claim {
        claim: "eq. 8 (stick -> slip)".into(),
        seed_says: "cos tau2 = vbar (tau2 - arcsin vbar) + sqrt(1 - vbar^2)".into(),
        exact_gives: format!(
            "cos tau2 = sqrt(1 - vbar^2) - vbar (tau2 - arcsin vbar); at vbar = 0.5, tau2 = {t2:.12}; the printed \
             form has no root after tau1 (its residual stays <= {worst_printed:.3e})"
        ),
        criterion: "holds if the printed form vanishes at the slip phase (residual < 1e-12); misprint if it has no \
                    root after tau1 (residual < 0 on a 1000-point grid) while the sign-corrected form vanishes"
            .into(),
        measured: named(&[
            ("tau2", t2),
            ("printed_residual", r_printed),
            ("corrected_residual", r_corrected),
            ("printed_max_residual", worst_printed),
        ]),
        deviation: Some(r_printed),
        deviation_is: "|printed eq. 8 residual| at the exact stick end tau2 (a difference of cosines, dimensionless)"
            .into(),
        location: "vbar = 0.5, amp = 0.5".into(),
        verdict: if r_printed < 1e-12 {
            Verdict::Holds
        } else if worst_printed < 0.0 && r_corrected < 1e-12 {
            Verdict::Misprint
        } else {
            Verdict::Wrong
        },
    }
}

/// Eq. 11's error, relative to amp.
fn eq11_error() -> Claim {
    let amps: Vec<f64> = (1..=10).map(|i| i as f64 / 10.0).collect();
    let (worst, at) = worst_over(&amps, 1000, |v, a| (seed::eq11(v, a) - mu_flat(v, a)).abs() / a);
    Claim {
        claim: "eq. 11 (empirical fit, amp <= 1)".into(),
        seed_says: "approximates the numerical results 'very accurately'".into(),
        exact_gives: format!("largest error {worst:.4} amp, exact at vbar = 0 and 1"),
        criterion: format!(
            "'very accurately' read as within {EQ11_TOL} amp (1 % of the reduction at vbar = 0): holds approximately \
             within it, overstated within 3x it, wrong beyond"
        ),
        measured: named(&[("max_error_over_amp", worst), ("at_vbar", at.0), ("at_amp", at.1)]),
        deviation: Some(worst),
        deviation_is: "max |eq. 11 - exact| / (du/u0) (mu/mu0 per unit amplitude)".into(),
        location: format!("vbar = {}, amp = {} (the same at every amp to 1e-3)", at.0, at.1),
        verdict: graded(worst, EQ11_TOL),
    }
}

/// Eq. 12's asymptotic exactness at amp = 1 (Fig. 3 inset).
fn eq12_exactness() -> Claim {
    let err12 = |v: f64| (seed::eq12(v, 1.0) - mu_flat(v, 1.0)).abs();
    let (e3, e4, e5) = (err12(1e-3), err12(1e-4), err12(1e-5));
    let order = (e4 / e5).log10();
    Claim {
        claim: "eq. 12 (low-velocity asymptote)".into(),
        seed_says: "asymptotically exact as vbar -> 0".into(),
        exact_gives: format!(
            "error {e3:.2e}, {e4:.2e}, {e5:.2e} at vbar = 1e-3, 1e-4, 1e-5 (amp = 1): O(vbar^{order:.2}), \
             vanishing faster than every term of eq. 12"
        ),
        criterion: "asymptotically exact: the error must vanish faster than eq. 12's last term vbar^2, i.e. its \
                    observed order between vbar = 1e-4 and 1e-5 exceeds 2"
            .into(),
        measured: named(&[("error_1e-3", e3), ("error_1e-4", e4), ("error_1e-5", e5), ("order", order)]),
        deviation: Some(e3),
        deviation_is: "|eq. 12 - exact| (mu/mu0)".into(),
        location: "amp = 1, vbar = 1e-3".into(),
        verdict: if order > 2.0 { Verdict::Holds } else { Verdict::Wrong },
    }
}

/// Eq. 21's factor pi.
fn eq21_factor_pi() -> Claim {
    let amps21 = [1.5, 2.0, 10.0];
    let ratios: Vec<f64> = amps21.iter().map(|&a| exact_slope(a) / seed::eq21_slope_printed(a)).collect();
    let ratio = ratios.iter().sum::<f64>() / ratios.len() as f64;
    let spread = ratios.iter().map(|r| (r / ratio - 1.0).abs()).fold(0.0, f64::max);
    let dev21 = amps21.iter().map(|&a| (exact_slope(a) / seed::eq21_slope(a) - 1.0).abs()).fold(0.0, f64::max);
    Claim {
        claim: "eq. 21 (low-velocity slope, amp > 1)".into(),
        seed_says: "mu/mu0 = vbar (1 - th/pi)^2 / (s (1 - th/pi + (1/pi)(du/u0) sqrt(1 - s^2)))".into(),
        exact_gives: format!(
            "exact slope / printed slope = {ratio:.9} at every amplitude: pi (3.141592654) to 1e-9, so the printed \
             formula lacks a factor pi; corrected: (pi - th)^2 / (s (pi - th) + sin th), matching the solver to \
             {dev21:.1e}"
        ),
        criterion: "holds if exact / printed slope is 1 within 1e-6; misprint if it is one constant factor at every \
                    amplitude (spread < 1e-6) equal to pi within 1e-6; wrong otherwise"
            .into(),
        measured: named(&[
            ("slope_amp_1.5", exact_slope(1.5)),
            ("slope_amp_2", exact_slope(2.0)),
            ("slope_amp_10", exact_slope(10.0)),
            ("ratio_to_printed", ratio),
            ("ratio_spread", spread),
        ]),
        deviation: Some((ratio - 1.0).abs()),
        deviation_is: "exact / printed slope - 1 (dimensionless)".into(),
        location: "amp = 1.5, 2, 10 (vbar = 1e-10)".into(),
        verdict: if (ratio - 1.0).abs() < 1e-6 {
            Verdict::Holds
        } else if spread < 1e-6 && (ratio / PI - 1.0).abs() < 1e-6 {
            Verdict::Misprint
        } else {
            Verdict::Wrong
        },
    }
}

/// Eq. 22 and the Fig. 5 caption.
fn eq22_limit() -> Claim {
    let big = exact_slope(1e8);
    Claim {
        claim: "eq. 22 and Fig. 5 caption (large-amplitude slope)".into(),
        seed_says: format!("limit pi/4 = {:.4}", seed::EQ22_PRINTED),
        exact_gives: format!("slope {big:.6} at amp = 1e8; the limit is pi^2/4 = {:.6}", seed::EQ22_CORRECTED),
        criterion: "holds if the slope at amp = 1e8 is pi/4 within 1e-6; misprint if it is pi^2/4 (the printed value \
                    times the factor pi of eq. 21) within 1e-6; wrong otherwise"
            .into(),
        measured: named(&[("slope_amp_1e8", big)]),
        deviation: Some((big - seed::EQ22_PRINTED).abs()),
        deviation_is: "|slope - pi/4| (slope mu/(mu0 vbar), dimensionless)".into(),
        location: "amp = 1e8".into(),
        verdict: if (big / seed::EQ22_PRINTED - 1.0).abs() < 1e-6 {
            Verdict::Holds
        } else if (big / seed::EQ22_CORRECTED - 1.0).abs() < 1e-6 {
            Verdict::Misprint
        } else {
            Verdict::Wrong
        },
    }
}

/// "The slope drops by about 20 %".
fn slope_drop() -> Claim {
    let big = exact_slope(1e8);
    let s1 = exact_slope(1.0);
    let (mut smin, mut amin) = (f64::INFINITY, 1.0);
    for k in 1..=400 {
        let a = 1.0 + k as f64 / 100.0;
        let sl = exact_slope(a);
        if sl < smin {
            smin = sl;
            amin = a;
        }
    }
    let drop_limit = 1.0 - big / s1;
    let drop_max = 1.0 - smin / s1;
    Claim {
        claim: "Fig. 5 inset (slope drops by about 20 %)".into(),
        seed_says: "once the sample jumps the slope drops by about 20 % and then stays nearly constant".into(),
        exact_gives: format!(
            "slope {s1:.6} (= pi) at amp = 1, a minimum {smin:.4} at amp = {amin:.2} (a drop of {:.1} %), then rising to \
             pi^2/4 = {big:.6} as amp -> infinity (a drop of {:.2} %, 1 - pi/4)",
            100.0 * drop_max,
            100.0 * drop_limit
        ),
        criterion: format!(
            "'about 20 %' read as 20 +- {:.0} %: holds approximately if the drop to the limiting slope is within it, \
             overstated if only the deepest drop misses it, wrong if the limiting drop does",
            100.0 * DROP_TOL
        ),
        measured: named(&[("slope_amp_1", s1), ("min_slope", smin), ("drop_max", drop_max), ("drop_limit", drop_limit)]),
        deviation: Some(drop_max - 0.2),
        deviation_is: "deepest drop - 20 % (fraction of the slope at amp = 1)".into(),
        location: format!("amp = {amin:.2}"),
        verdict: if (drop_limit - 0.2).abs() > DROP_TOL {
            Verdict::Wrong
        } else if (drop_max - 0.2).abs() > DROP_TOL {
            Verdict::Overstated
        } else {
            Verdict::HoldsApproximately
        },
    }
}

/// Eq. 28 against eq. 27.
fn eq28_against_eq27() -> Claim {
    let statics: Vec<f64> = (0..=100).map(|i| i as f64 / 100.0).collect();
    let (w28, at28) = worst_over(&statics, 1000, |v, ms| (seed::eq28(v, ms) - seed::eq27(v, ms)).abs());
    Claim {
        claim: "eq. 28 vs eq. 27".into(),
        seed_says: "differs from (27) by 1 % or less".into(),
        exact_gives: format!("largest difference {w28:.5} (of mu0)"),
        criterion: "the seed's own bar, 1 % of mu0: holds within it, overstated within 3x it, wrong beyond".into(),
        measured: named(&[("max_difference", w28), ("at_vbar", at28.0), ("at_mu_static", at28.1)]),
        deviation: Some(w28),
        deviation_is: "max |eq. 28 - eq. 27| (mu/mu0)".into(),
        location: format!("vbar = {}, mu_static/mu0 = {}", at28.0, at28.1),
        verdict: match graded(w28, 0.01) {
            Verdict::HoldsApproximately => Verdict::Holds,
            other => other,
        },
    }
}

/// The critical velocity vbar = 1 for every shape (eq. 26).
fn critical_velocity() -> Claim {
    let shapes = shapes();
    let mut critical_ok = true;
    let mut worst_below = 1.0f64;
    for (_, f) in &shapes {
        for a in [0.3, 1.0, 2.0] {
            critical_ok &= f(1.0, a) == 1.0 && f(1.1, a) == 1.0 && f(1.0 - 1e-6, a) < 1.0;
            worst_below = worst_below.min(1.0 - f(1.0 - 1e-3, a));
        }
    }
    Claim {
        claim: "eq. 26 (critical velocity)".into(),
        seed_says: "vbar = 1 for all shapes, with and without jumping".into(),
        exact_gives: format!(
            "mu = mu0 exactly for vbar >= 1 and mu < mu0 just below (reduction >= {worst_below:.1e} at 1 - vbar = 1e-3) for flat, parabolic, cone at amp 0.3, 1, 2"
        ),
        criterion: "holds if mu = mu0 exactly at vbar = 1 and 1.1 and mu < mu0 at 1 - vbar = 1e-6, for every shape \
                    and amplitude checked; wrong otherwise"
            .into(),
        measured: named(&[("all_checks_pass", if critical_ok { 1.0 } else { 0.0 }), ("min_reduction_1e-3", worst_below)]),
        deviation: None,
        deviation_is: "none (a yes/no check)".into(),
        location: "flat, parabolic, cone".into(),
        verdict: if critical_ok { Verdict::Holds } else { Verdict::Wrong },
    }
}

/// The small-amplitude slope `D = reduction N0 / (kz du)` of `shape`, with `N0`
/// the static normal force and `kz` the incremental stiffness `2 E* x_c`
/// (the flat punch's `kz u0` is its static force): eq. 14's bracket, if the
/// seed is right that it holds for every shape.
/// NaN where anything fails (the claim's verdict then says so).
fn small_amplitude_slope(spec: &str, vbar: f64, amp: f64) -> f64 {
    let Ok(shape) = Shape::parse(spec) else { return f64::NAN };
    let reduction = Conditions::vbar(vbar, amp).and_then(|c| shape.ratio(&c)).map_or(f64::NAN, |r| r.reduction);
    let n0 = shape.contact().mean_normal(0.0).unwrap_or(f64::NAN);
    reduction * n0 / (2.0 * amp)
}

/// Shape independence at small amplitude, eqs. 14 and 25 (the bar: 1e-5 relative at amp = 1e-6).
const EQ14_TOL: f64 = 1e-5;

/// Eqs. 14 and 25: at small amplitude the friction change does not depend on the shape.
fn eq14_small_amplitude() -> Claim {
    let amp = 1e-6;
    let mut spread = 0.0f64;
    let mut bracket_error = 0.0f64;
    let mut parts = vec![];
    let mut measured = vec![];
    for vbar in [0.2, 0.5, 0.8] {
        let d: Vec<f64> =
            ["flat", "parabolic", "cone", "power:3.7"].iter().map(|s| small_amplitude_slope(s, vbar, amp)).collect();
        let (lo, hi) = d.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
        // f64::max drops a NaN: a failed evaluation must fail the claim instead.
        let this = if d.iter().all(|x| x.is_finite()) { (hi - lo) / hi.abs() } else { f64::INFINITY };
        spread = spread.max(this);
        let bracket = 0.75 * (vbar - 1.0) * (vbar - 1.0) + 0.25 * (vbar - 1.0).powi(4);
        bracket_error = bracket_error.max((bracket - d[0]).abs());
        parts.push(format!("vbar {vbar}: {:.9} (flat) .. {:.9}", d[0], d[3]));
        measured.push((format!("slope_flat_vbar_{vbar}"), d[0]));
        measured.push((format!("slope_parabolic_vbar_{vbar}"), d[1]));
        measured.push((format!("slope_cone_vbar_{vbar}"), d[2]));
    }
    measured.push(("relative_spread".into(), spread));
    measured.push(("bracket_error".into(), bracket_error));
    Claim {
        claim: "eqs. 14, 25 (small amplitude)".into(),
        seed_says: "the change of friction -mu0 kz du [3/4 (vbar-1)^2 + 1/4 (vbar-1)^4] holds for every shape at small \
                    amplitude, kz the incremental normal stiffness"
            .into(),
        exact_gives: format!(
            "reduction N0/(kz du) at du/u0 = 1e-6 for flat, parabolic, cone, power:3.7: {}; relative spread {spread:.1e} \
             (shape independence holds); the bracket itself is eq. 11's, off by up to {bracket_error:.4}",
            parts.join("; ")
        ),
        criterion: format!(
            "holds if the slopes of the four shapes agree to {EQ14_TOL:e} relative at du/u0 = 1e-6 (their \
             difference is O(du/u0)); wrong otherwise. The bracket's accuracy is eq. 11's claim"
        ),
        measured,
        deviation: Some(spread),
        deviation_is: "(max - min) / max of reduction N0/(kz du) over the four shapes (relative, dimensionless)"
            .into(),
        location: "vbar 0.2, 0.5, 0.8; du/u0 = 1e-6".into(),
        verdict: if spread <= EQ14_TOL { Verdict::Holds } else { Verdict::Wrong },
    }
}

/// "The static friction force is determined just by the minimum of the normal
/// force": mu at vbar = 1e-10 (the solver) against N_min / N_mean.
fn static_friction_minimum_normal() -> Claim {
    let mut worst = 0.0f64;
    let mut measured = vec![];
    for spec in ["flat", "parabolic", "cone", "flat-tip:0.5"] {
        let Ok(shape) = Shape::parse(spec) else {
            worst = f64::INFINITY;
            continue;
        };
        for amp in [0.2, 0.5, 0.8, 1.5] {
            let mu = mu_of(&shape, 1e-10, amp);
            let c = shape.contact();
            let ratio = c.mean_normal(amp).map(|mean| c.static_force(1.0 - amp) / mean).unwrap_or(f64::NAN);
            // A NaN (a failed evaluation) fails the claim: f64::max would drop it.
            worst = worst.max(if (mu - ratio).is_finite() { (mu - ratio).abs() } else { f64::INFINITY });
            measured.push((format!("{spec}_amp_{amp}_mu"), mu));
            measured.push((format!("{spec}_amp_{amp}_nmin_over_nmean"), ratio));
        }
    }
    measured.push(("max_difference".into(), worst));
    Claim {
        claim: "section 5 (static friction)".into(),
        seed_says: "the static friction force is determined just by the minimum of the normal force during the cycle"
            .into(),
        exact_gives: format!(
            "mu/mu0 at vbar = 1e-10 equals N_min/N_mean to {worst:.1e} for flat, parabolic, cone and flat-tip:0.5 at \
             du/u0 = 0.2, 0.5, 0.8, 1.5"
        ),
        criterion: "holds if they agree to 1e-8 (mu approaches its static value like pi vbar du/u0); wrong otherwise"
            .into(),
        measured,
        deviation: Some(worst),
        deviation_is: "max |mu/mu0 - N_min/N_mean| (mu/mu0)".into(),
        location: "vbar = 1e-10".into(),
        verdict: if worst <= 1e-8 { Verdict::Holds } else { Verdict::Wrong },
    }
}

/// Eq. 27's shape independence.
fn eq27_shape_independence() -> Claim {
    let shapes = shapes();
    let mut parts = vec![];
    let mut w27 = 0.0f64;
    for (name, f) in &shapes {
        let mu_static = |a: f64| match *name {
            "flat" => Shape::flat().mu_static(a, DEFAULT_TOL).unwrap_or(f64::NAN),
            "parabolic" => Shape::parabolic().mu_static(a, DEFAULT_TOL).unwrap_or(f64::NAN),
            _ => Shape::cone().mu_static(a, DEFAULT_TOL).unwrap_or(f64::NAN),
        };
        let (w, at) =
            worst_over(&[0.2, 0.4, 0.6, 0.8, 1.0, 1.5, 2.0], 200, |v, a| (seed::eq27(v, mu_static(a)) - f(v, a)).abs());
        w27 = w27.max(w);
        parts.push(format!("{name} {w:.3} (vbar {}, amp {})", at.0, at.1));
    }
    Claim {
        claim: "eq. 27 (shape independence)".into(),
        seed_says: "approximately valid for all shapes, jumping or not; shape enters only through mu_static".into(),
        exact_gives: format!("largest error: {}", parts.join("; ")),
        criterion: format!(
            "'approximately valid' read as within {EQ27_TOL} of mu0 at every shape, amplitude and velocity: holds \
             approximately within it, overstated within 3x it, wrong beyond"
        ),
        measured: named(&[("max_error", w27)]),
        deviation: Some(w27),
        deviation_is: "max |eq. 27 - exact| (mu/mu0)".into(),
        location: "amp in 0.2..2, vbar in [0, 1]".into(),
        verdict: graded(w27, EQ27_TOL),
    }
}

/// mu depends only on (vbar, amp): two dimensional systems with the same pair.
fn two_parameters() -> Claim {
    let (kx, kz, mu0, omega, u0, du) = (3.0e7, 4.0e7, 0.3, 2.0 * PI * 100.0, 2e-6, 1e-6);
    let v0 = 0.4 * kz * mu0 * omega * du / kx;
    let vbar = kx * v0 / (kz * mu0 * omega * du);
    let a_ = physical_mu_ratio(&PhysicalSpring { kx, kz, mu0, v0, omega, u0, du }, 20000);
    // A second system: stiffnesses x 1e3, kz/kx changed, frequency x 7, lengths x 1e-3, same (vbar, amp).
    let (kx2, kz2, mu02, omega2, u02, du2) = (5.0e10, 2.0e10, 0.6, omega * 7.0, u0 * 1e-3, du * 1e-3);
    let v02 = vbar * kz2 * mu02 * omega2 * du2 / kx2;
    let b_ = physical_mu_ratio(
        &PhysicalSpring { kx: kx2, kz: kz2, mu0: mu02, v0: v02, omega: omega2, u0: u02, du: du2 },
        20000,
    );
    let exact = mu_flat(vbar, du / u0);
    // The same with two physical scenes (sphere, exact solver), lengths x 1e3,
    // moduli x 1e-4, frequency x 1e-2, velocities scaled with omega du.
    let scene = |e: f64, r: f64, u: f64, d: f64, f: f64, v: f64| {
        use crate::scene::{Indenter, Loading, Materials, Oscillation, Scene, Values, VelocitySpec};
        let s = Scene {
            name: None,
            materials: Materials { e1_pa: e, nu1: 0.3, e2_pa: e, nu2: 0.3, g1_pa: None, g2_pa: None },
            mu0: 0.4,
            indenter: Indenter::Sphere { radius_m: r },
            loading: Loading { mean_indentation_m: Some(u), mean_normal_force_n: None },
            oscillation: Oscillation {
                amplitude_m: Some(Values::One(d)),
                amplitude_fraction: None,
                frequency_hz: f,
                tangential_amplitude_m: None,
                tangential_phase_rad: 0.0,
                transverse_amplitude_m: None,
                transverse_phase_rad: 0.0,
            },
            velocity: VelocitySpec { values_m_per_s: Some(vec![v]), sweep: None },
            system: None,
        };
        let no_files = |_: &str| Err(std::io::Error::other("a sphere reads no file"));
        crate::scene::solve_with(&s, "claim", &no_files, &|_| {})
            .map_or(f64::NAN, |r| r[0].rows.get(0).map_or(f64::NAN, |x| x.mu_ratio))
    };
    let (sa, sb) = (scene(2e11, 5e-3, 1e-6, 1.3e-6, 1e3, 3e-4), scene(2e7, 5.0, 1e-3, 1.3e-3, 10.0, 3e-3));
    Claim {
        claim: "section 2 (two dimensionless parameters)".into(),
        seed_says: "mu/mu0 depends only on vbar (eq. 3) and du/u0".into(),
        exact_gives: format!(
            "two dimensional systems (stiffnesses, mu0, frequency and lengths changed by up to 1e3) with vbar = {vbar:.6}, \
             amp = 0.5 give {a_:.12} and {b_:.12} by the seed's scheme (M = 20000); exact {exact:.12}. Two \
             sphere scenes (lengths x 1e3, moduli x 1e-4, frequency x 1e-2) give {sa:.15} and {sb:.15}"
        ),
        criterion: "holds if the two stepped systems agree to 1e-10 and with the exact value to 1e-6 (M = 20000), and \
                    the two scenes to 1e-14; wrong otherwise"
            .into(),
        measured: named(&[("stepped_a", a_), ("stepped_b", b_), ("exact", exact), ("scene_a", sa), ("scene_b", sb)]),
        deviation: Some((a_ - b_).abs().max((sa - sb).abs())),
        deviation_is: "max of |system a - system b| over both pairs (mu/mu0)".into(),
        location: "flat punch (time stepping in physical units) and sphere scenes".into(),
        verdict: if (a_ - b_).abs() < 1e-10 && (a_ - exact).abs() < 1e-6 && (sa - sb).abs() < 1e-14 {
            Verdict::Holds
        } else {
            Verdict::Wrong
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A failed evaluation (NaN) anywhere on the grid makes the claim wrong.
    #[test]
    fn a_nan_is_the_worst_deviation() {
        let (w, at) = worst_over(&[1.0], 4, |v, _| if v == 0.5 { f64::NAN } else { v * 0.1 });
        assert_eq!((w, at), (f64::INFINITY, (0.5, 1.0)));
        assert_eq!(graded(w, 0.01), Verdict::Wrong);
        assert_eq!(worst_over(&[1.0], 4, |v, _| v * 0.1).0, 0.1);
    }
}
