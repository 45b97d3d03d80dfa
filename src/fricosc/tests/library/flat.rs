//! The single spring (flat punch) against derived limits and independent values.
// Reference values keep all their published digits on purpose.
use crate::common::at::flat_ratio as ratio;
use crate::common::tol;
use std::f64::consts::PI;

fn mu(v: f64, a: f64) -> f64 {
    ratio(v, a).unwrap().mu_ratio
}

/// 50-digit values from `data/scripts/near_critical.py` (the seed's tau form of the
/// stick, evaluated in mpmath; independent of fricosc's rearranged S/C form).
const NEAR_CRITICAL: [(f64, f64, f64); 8] = [
    (0.6, 0.999, 4.298043219550465912711544e-7),
    (0.6, 0.999999, 4.297184323165322628692625e-13),
    (0.6, 0.999999999, 4.297183221275317564127957e-19),
    (0.6, 0.999999999999, 4.296993343405168339563147e-25),
    (2.0, 0.999, 1.176261324570768940066967e-6),
    (2.0, 0.999999, 1.176026267232335905218315e-12),
    (2.0, 0.999999999, 1.176025965674038168022255e-18),
    (2.0, 0.999999999999, 1.175974001097685731249117e-24),
];

#[test]
fn reduction_keeps_full_relative_accuracy_down_to_1_minus_vbar_1e_12() {
    for (amp, v, red) in NEAR_CRITICAL {
        let r = ratio(v, amp).unwrap();
        let rel = (r.reduction - red).abs() / red;
        assert!(rel <= tol::REDUCTION_REL, "amp={amp} vbar={v}: {} vs {red} (rel {rel:e})", r.reduction);
        // mu_ratio itself is 1 - reduction to rounding.
        assert!((r.mu_ratio - (1.0 - red)).abs() <= f64::EPSILON);
    }
}

#[test]
fn reduction_approaches_the_derived_leading_term_9_over_4pi() {
    // Scaling x = alpha u of the stick gap gives H ~ -(alpha^3/6)(u+1)^2(u-2), so
    // 2 pi D ~ (9/8) alpha^4 = (9/2) w^2 and D ~ 9 w^2 / (4 pi), w = 1 - vbar.
    // The next term is O(w) relative (about 0.2 w).
    for k in [20, 30, 40] {
        let w = (2.0f64).powi(-k);
        let v = 1.0 - w;
        for amp in [0.3, 1.0] {
            let lead = amp * 9.0 * w * w / (4.0 * PI);
            let rel = (ratio(v, amp).unwrap().reduction / lead - 1.0).abs();
            assert!(rel < 0.3 * w + 1e-14, "w = 2^-{k}, amp {amp}: rel {rel:e}");
        }
    }
}

#[test]
fn zero_velocity_limit_is_1_minus_amp_without_contact_loss_and_0_with_it() {
    for a in [0.0, 1e-300, 0.1, 0.5, 0.999, 1.0] {
        assert!((mu(0.0, a) - (1.0 - a)).abs() <= tol::FLAT_ABS, "a = {a}");
        // Approach: mu = 1 - a + a pi vbar + O(vbar^{3/2}) (eq. 12's first terms).
        let v = 1e-10;
        assert!((mu(v, a) - (1.0 - a + a * PI * v)).abs() < 10.0 * v.powf(1.5) + 1e-15, "a = {a}");
    }
    for a in [1.0 + 1e-12, 1.5, 2.0, 10.0, 1e300] {
        assert!(mu(0.0, a).abs() <= tol::FLAT_ABS, "a = {a}: {}", mu(0.0, a));
    }
}

#[test]
fn at_and_above_the_critical_velocity_there_is_no_reduction() {
    for a in [0.0, 0.5, 1.0, 2.0, 1e6] {
        for v in [1.0, 1.0 + f64::EPSILON, 1.2, 1e300] {
            let r = ratio(v, a).unwrap();
            assert_eq!((r.mu_ratio, r.reduction), (1.0, 0.0), "v={v} a={a}");
        }
    }
}

/// The corrected eq. 21 slope: `(pi - th)^2 / (s (pi - th) + sin th)`, `s = 1/a`.
fn slope_eq21(a: f64) -> f64 {
    let s = 1.0 / a;
    let th = s.acos();
    (PI - th).powi(2) / (s * (PI - th) + th.sin())
}

#[test]
fn small_velocity_slope_is_the_corrected_eq_21_and_the_printed_one_is_pi_too_small() {
    for a in [1.01, 1.5, 2.0, 5.0, 100.0] {
        // mu = slope vbar (1 + O(vbar)): the relative deviation shrinks tenfold per decade.
        let dev = |v: f64| (mu(v, a) / v / slope_eq21(a) - 1.0).abs();
        let (d5, d6) = (dev(1e-5), dev(1e-6));
        assert!(d6 < 2e-4 && d6 < 0.2 * d5, "a={a}: deviations {d5:e}, {d6:e}");
        // As printed, (1 - th/pi)^2 / (...) is smaller by exactly pi.
        let s = 1.0 / a;
        let th = s.acos();
        let printed = (1.0 - th / PI).powi(2) / (s * (1.0 - th / PI + th.sin() / (PI * s)));
        assert!((slope_eq21(a) / printed - PI).abs() < 1e-12);
    }
}

/// Down to the smallest subnormal `vbar`, a lost contact's `mu` is the corrected
/// eq. 21 slope times `vbar`, within an ulp of the subnormals (at `amp = 1`:
/// `pi vbar`, 1.5e-323 at 5e-324, where the spring's `vbar^2/2` used to
/// underflow to 0).
#[test]
fn subnormal_velocities_keep_the_slope() {
    for a in [1.0, 1.5, 3.0, 100.0] {
        for v in [5e-324, 1.5e-323, 1e-320, 1e-310, 2e-300, 1e-272] {
            let (got, want) = (mu(v, a), slope_eq21(a) * v);
            let ulp = (4.0 * f64::EPSILON * want).max(2f64.powi(-1074));
            assert!((got - want).abs() <= ulp, "amp {a}, vbar {v:e}: {got:e} against {want:e}");
        }
    }
}

#[test]
fn large_amplitude_slope_tends_to_pi_squared_over_4_not_pi_over_4() {
    let a = 1e9;
    let slope = mu(1e-9, a) / 1e-9;
    assert!((slope - PI * PI / 4.0).abs() < 1e-6, "{slope}");
    assert!((slope - PI / 4.0).abs() > 1.0);
}

#[test]
fn continuous_across_amplitude_one() {
    for v in [1e-6, 0.1, 0.5, 0.9, 0.999] {
        for d in [1e-6, 1e-9, 1e-12] {
            let jump = (mu(v, 1.0 + d) - mu(v, 1.0 - d)).abs();
            // mu is Lipschitz in a with constant below 2: the jump is that plus rounding.
            assert!(jump <= 4.0 * d + 4.0 * f64::EPSILON, "v={v} d={d}: {jump:e}");
        }
    }
}

#[test]
fn continuous_across_the_slip_first_stick_first_switch() {
    // amp > 1 with s = 1/amp = sqrt(1 - vbar^2): the switch happens at vbar = sqrt(1 - s^2).
    for a in [1.2, 2.0, 7.0] {
        let s: f64 = 1.0 / a;
        let vc = (1.0 - s * s).sqrt();
        for d in [1e-6, 1e-9, 1e-12] {
            let jump = (mu(vc + d, a) - mu(vc - d, a)).abs();
            assert!(jump <= 4.0 * d + 4.0 * f64::EPSILON, "a={a} d={d}: {jump:e}");
        }
    }
}

#[test]
fn continuous_at_the_critical_velocity() {
    for a in [0.5, 1.0, 3.0] {
        let below = ratio(1.0 - 1e-9, a).unwrap().reduction;
        assert!(below > 0.0 && below < a * 1e-18, "a={a}: {below:e}");
    }
}

#[test]
fn bad_parameters_are_errors_not_panics() {
    for (v, a) in
        [(f64::NAN, 0.5), (0.5, f64::NAN), (f64::INFINITY, 0.5), (0.5, f64::INFINITY), (-0.1, 0.5), (0.5, -1e-300)]
    {
        assert!(ratio(v, a).is_err(), "v={v} a={a}");
        assert!(crate::common::at::flat_point(v, a).is_err());
    }
}

#[test]
fn events_are_on_the_bound_and_in_order() {
    for (v, a) in [(0.3, 0.5), (0.3, 1.5), (0.9, 1.5), (0.95, 4.0), (1.2, 2.0), (0.0, 0.5)] {
        let p = crate::common::at::flat_point(v, a).unwrap();
        for w in p.events.windows(2) {
            assert!(w[0].tau <= w[1].tau);
        }
        for e in &p.events {
            assert!((0.0..std::f64::consts::TAU).contains(&e.tau));
            assert_eq!(e.normal, e.tangential);
            assert!((e.normal - (1.0 - a * e.tau.cos()).max(0.0)).abs() < 1e-14 || e.normal == 0.0);
        }
    }
    // Stick from contact: contact, stick at the same phase, slip, loss.
    let kinds = |v: f64, a: f64| -> Vec<String> {
        crate::common::at::flat_point(v, a).unwrap().events.iter().map(|e| format!("{:?}", e.kind)).collect()
    };
    assert_eq!(kinds(0.3, 1.5), ["Contact", "Stick", "Slip", "LossOfContact"]);
    // Slip first (s = 0.5 >= sqrt(1 - 0.95^2) = 0.31): contact, (slip), stick, slip, loss.
    assert_eq!(kinds(0.95, 2.0), ["Contact", "Stick", "Slip", "LossOfContact"]);
    let p = crate::common::at::flat_point(0.95, 2.0).unwrap();
    assert_eq!(format!("{:?}", p.regime), "JumpingSlipFirst");
    assert!(p.events[1].tau > p.events[0].tau + 0.1, "the stick starts after a slip phase");
}

#[test]
fn root_evaluation_counts_are_those_of_newton_from_the_fitted_guess() {
    // A counter catches a silent change of algorithm that a tolerance misses.
    let mut total = 0;
    for i in 1..100 {
        let v = i as f64 / 100.0;
        for a in [0.5, 1.5, 3.0] {
            let n = fricosc::spring::Spring::new(1.0 / a, v).root_evaluations;
            assert!(n <= 6, "v={v} a={a}: {n} evaluations");
            total += n;
        }
    }
    assert!(total <= 4 * 99 * 3, "{total}");
}

#[test]
fn small_mu_keeps_relative_accuracy_when_jumping() {
    // mu_ratio -> 0 like slope * vbar (corrected eq. 21); integrated directly, it keeps
    // its relative accuracy where 1 - reduction would leave only an absolute 1e-16.
    for a in [1.2, 2.0, 10.0] {
        let v = 1e-12;
        let rel = (mu(v, a) / v / slope_eq21(a) - 1.0).abs();
        assert!(rel < 1e-8, "a={a}: rel {rel:e}");
    }
}

/// Springs that stick from contact just above `s = -sqrt(1 - vbar^2)`, where
/// sticks vanish (a spring of a curved body's foundation, or `Spring::new`
/// called with such an `s`): the deficit (about `eps^3`, down to 1e-40 here),
/// the tangential force and the stick's end against independent 40-digit
/// values (`data/scripts/short_sticks.py`, committed as
/// `data/short-sticks.json`). The form that summed order-one terms kept
/// `1e-16 (alpha/eps)^3` of the deficit: 0.3 relative at `s = -c + 1e-6`,
/// `vbar = 0.3`.
#[test]
fn short_sticks_keep_every_digit() {
    use fricosc::spring::{Regime, Spring};
    let cases = crate::common::data_cases("short-sticks.json");
    assert_eq!(cases.len(), 54);
    let (mut worst_d, mut worst_f, mut worst_t) = (0.0f64, 0.0f64, 0.0f64);
    for c in &cases {
        let text = |k: &str| c[k].as_str().unwrap().to_string();
        let (vbar, s): (f64, f64) = (text("vbar").parse().unwrap(), text("s").parse().unwrap());
        let rel = |got: f64, k: &str| crate::common::exact_error(got, &text(k)) / text(k).parse::<f64>().unwrap().abs();
        for sp in [Spring::new(s, vbar), Spring::with_events(s, vbar)] {
            assert_eq!(sp.regime, Regime::JumpingStickFirst, "vbar {vbar} s {s}");
            worst_d = worst_d.max(rel(sp.deficit, "deficit"));
            worst_f = worst_f.max(rel(sp.mean_tangential(), "mean_tangential"));
            assert!(rel(sp.deficit, "deficit") <= 1e-13, "vbar {vbar} s {s}: deficit {:e}", sp.deficit);
            assert!(rel(sp.mean_tangential(), "mean_tangential") <= 1e-14, "vbar {vbar} s {s}");
        }
        let phase = Spring::with_events(s, vbar).slip_phase().unwrap();
        worst_t = worst_t.max(crate::common::exact_error(phase, &text("slip_phase")));
        assert!(crate::common::exact_error(phase, &text("slip_phase")) <= 1e-14, "vbar {vbar} s {s}: {phase}");
    }
    eprintln!("short sticks: deficit {worst_d:.1e}, tangential {worst_f:.1e} relative; slip phase {worst_t:.1e}");
    // Regression bars, about 10 times the worst observed (deficit 7.1e-15 where
    // the general form takes over at eps = alpha/4; tangential 9.3e-16; phase 6.6e-16).
    assert!(worst_d <= 7e-14 && worst_f <= 9.3e-15 && worst_t <= 7e-15, "{worst_d:e} {worst_f:e} {worst_t:e}");
}
