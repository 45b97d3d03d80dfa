//! What the reports print beside `mu_ratio` — the mean normal force, the static
//! friction, the flat punch's mean tangential force, a power law's band edges
//! and shares, the contacts' names — each against a value computed without the
//! solver (closed forms, 25-digit mpmath values, the test's own spring and
//! quadrature). These are the survivors of the mutation run (`tests/README.md`):
//! mutants of these fields changed what `point` prints and no test saw it.
// The mpmath values keep their published digits on purpose.

use crate::common::quad::tanh_sinh;
use crate::common::spring_ref::{deficit, mean_b};
use fricosc::Shape;
use std::f64::consts::PI;

fn point_json(shape: &Shape, vbar: f64, amp: f64) -> serde_json::Value {
    serde_json::to_value(crate::common::at::report(shape, vbar, amp, fricosc::DEFAULT_TOL).unwrap()).unwrap()
}

#[test]
fn contacts_are_named_as_the_command_line_names_them() {
    for (spec, name) in [
        ("flat", "flat"),
        ("parabolic", "parabolic"),
        ("power:2", "parabolic"),
        ("cone", "cone"),
        ("power:3", "power:3.0"),
    ] {
        assert_eq!(crate::common::shape(spec).unwrap().contact().name(), name, "{spec}");
    }
    assert_eq!(crate::common::shape("flat-tip:0.5").unwrap().contact().name(), "flat-tip:0.5");
    let table = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/profiles/sphere.csv");
    let tab = crate::common::shape(&format!("profile:{table}@1e-6")).unwrap();
    assert_eq!(tab.contact().name(), format!("profile:{table}@1e-6"));
}

/// `(1/pi) int_0^pi (1 - amp cos tau)_+ dtau = 1 + (x - atan x)/pi` with
/// `x = sqrt(amp^2 - 1)` beyond `amp = 1` (`acos(1/amp) = atan x`, which keeps
/// its digits where `1/amp` would lose them); 1 below.
fn flat_mean_normal(amp: f64) -> f64 {
    if amp <= 1.0 {
        1.0
    } else {
        let x = ((amp - 1.0) * (amp + 1.0)).sqrt();
        1.0 + (x - x.atan()) / PI
    }
}

#[test]
fn the_flat_punchs_mean_normal_force_and_its_report() {
    for amp in [0.0, 0.3, 1.0, 1.0 + 1e-9, 1.5, 3.0, 1e3, 1e10] {
        let want = flat_mean_normal(amp);
        let got = crate::common::at::flat_point(0.3, amp).unwrap().mean_normal;
        assert!((got / want - 1.0).abs() <= 4e-16 * amp.max(1.0).log2().max(1.0), "amp {amp}: {got} against {want}");
        // Both sides of the foundation in the contact's units.
        let c = Shape::flat().contact().mean_normal(amp).unwrap();
        assert!((c / (2.0 * want) - 1.0).abs() <= 4e-15, "amp {amp}: {c}");
    }
    // The point's report: the mean normal force, the mean tangential force
    // (mu times it) and the static friction (the minimum over the mean, (1 - amp)_+).
    for (vbar, amp) in [(0.3, 0.5), (0.3, 1.5), (0.8, 2.5)] {
        let p = point_json(&Shape::flat(), vbar, amp);
        let n = p["mean_normal"].as_f64().unwrap();
        assert!((n / flat_mean_normal(amp) - 1.0).abs() <= 1e-15, "{p}");
        let t = p["mean_tangential"].as_f64().unwrap();
        assert!((t - p["mu_ratio"].as_f64().unwrap() * n).abs() <= 1e-15, "{p}");
        assert_eq!(p["mu_static_ratio"].as_f64().unwrap(), (1.0 - amp).max(0.0), "{p}");
    }
}

/// Mean normal forces of power laws (both sides of the foundation, units
/// `E* x_c u0`): `(2n/(n+1))/pi int (1 - amp cos tau)_+^(1 + 1/n) dtau` in
/// 40-digit mpmath, rounded to 22 digits. The huge amplitudes: a node's `y`
/// once came from `1/amp - cos u` with `u` rounded, `2 amp` ulps of `y` (1e-10
/// relative at `power:3.7`, amp 1e9).
const POWER_NORMAL: [(f64, f64, f64); 11] = [
    (2.0, 0.5, 1.396_615_174_212_026_952_9),
    (2.0, 2.0, 2.436_185_533_533_771_139_3),
    (1.0, 0.5, 1.125),
    (1.0, 1.5, 2.089_915_902_860_269_021_0),
    (3.7, 0.5, 1.608_971_025_609_234_384_1),
    (3.7, 2.0, 2.376_359_348_144_179_574_9),
    (3.7, 1e3, 3_007.010_629_954_552_862_964),
    (3.7, 1e6, 19_415_613.975_120_026_068_71),
    (3.7, 1e9, 125_591_759_403.407_775_321_2),
    (0.5, 1e6, 141_471_560_526_765_807.455_8),
    (8.0, 1e6, 3_066_522.292_663_210_238_953),
];

#[test]
fn power_law_mean_normal_forces_against_mpmath() {
    for (n, amp, want) in POWER_NORMAL {
        let shape = crate::common::shape(&format!("power:{n}")).unwrap();
        let got = shape.contact().mean_normal(amp).unwrap();
        assert!((got / want - 1.0).abs() <= 1e-14, "n {n} amp {amp}: {got} against {want}");
        // The point's report, through its bands (scaled back beyond amp = 1).
        let p = point_json(&shape, 0.4, amp);
        let reported = p["mean_normal"].as_f64().unwrap();
        assert!((reported / want - 1.0).abs() <= 1e-13, "n {n} amp {amp}: reported {reported}");
    }
    // Without oscillation: the static force, 2 n/(n + 1), from the contact and
    // from the point's report (both sides of the foundation).
    for n in [0.5, 1.0, 2.0, 3.7] {
        let got = crate::common::shape(&format!("power:{n}")).unwrap().contact().mean_normal(0.0).unwrap();
        assert!((got / (2.0 * n / (n + 1.0)) - 1.0).abs() <= 4e-16, "n {n}: {got}");
        let reported = point_json(&crate::common::shape(&format!("power:{n}")).unwrap(), 0.4, 0.0)["mean_normal"]
            .as_f64()
            .unwrap();
        assert!((reported / (2.0 * n / (n + 1.0)) - 1.0).abs() <= 4e-16, "n {n}: reported {reported}");
    }
    // The tabulated sphere at u0 = 1e-6 of its radius is the paraboloid to O(u0/R).
    let table = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/profiles/sphere.csv");
    let tab = crate::common::shape(&format!("profile:{table}@1e-6")).unwrap();
    for (n, amp, want) in POWER_NORMAL.iter().filter(|c| c.0 == 2.0) {
        let got = tab.contact().mean_normal(*amp).unwrap();
        assert!((got / want - 1.0).abs() <= 1e-5, "tabulated sphere ({n}) amp {amp}: {got} against {want}");
    }
    // The trait's generic phase average (flat-tip:0 is the sphere's paraboloid).
    let tip = crate::common::shape("flat-tip:0").unwrap();
    for (n, amp, want) in POWER_NORMAL.iter().filter(|c| c.0 == 2.0) {
        let got = tip.contact().mean_normal(*amp).unwrap();
        assert!((got / want - 1.0).abs() <= 1e-13, "flat-tip:0 ({n}) amp {amp}: {got} against {want}");
    }
}

/// Static friction is the limit of vanishing velocity: the solver at
/// `vbar = 1e-10` (its bands, not the closed form of `vbar = 0`) is within
/// `1e-8` of the reported `mu_static_ratio`, for every shape; the flat punch's
/// is `(1 - amp)_+`, and every contact that jumps has none.
#[test]
fn static_friction_is_the_small_velocity_limit() {
    for spec in ["flat", "parabolic", "cone", "power:3.7", "flat-tip:0.5"] {
        let shape = crate::common::shape(spec).unwrap();
        for amp in [0.2, 0.6, 0.95, 1.0, 1.7] {
            let ms = shape.contact().mu_static(amp, fricosc::DEFAULT_TOL).unwrap();
            let near = crate::common::at::eval(&shape, 1e-10, amp).unwrap().ratio.mu_ratio;
            assert!((near - ms).abs() <= 1e-8, "{spec} amp {amp}: mu_static {ms}, mu(1e-10) {near}");
            if amp >= 1.0 {
                assert_eq!(ms, 0.0, "{spec} amp {amp}");
            } else {
                assert!(ms > 0.0, "{spec} amp {amp}: {ms}");
            }
            // Reported by the flat punch's and the power laws' points.
            if let Some(reported) = point_json(&shape, 0.3, amp)["mu_static_ratio"].as_f64() {
                assert_eq!(reported, ms, "{spec} amp {amp}");
            } else {
                assert!(spec.starts_with("flat-tip"), "{spec} reports no static friction");
            }
        }
    }
    assert_eq!(Shape::flat().contact().mu_static(0.25, 1e-6).unwrap(), 0.75);
}

/// A power law's bands: their edges are the regime thresholds in closed form
/// (`s = (1 - z^n)/amp` at 1, `+-sqrt(1 - vbar^2)` and -1), and each band's
/// normal and tangential shares are its integrals over the total, computed here
/// by tanh-sinh with the test's own spring.
#[test]
fn power_law_bands_have_the_thresholds_and_shares() {
    for (n, vbar, amp) in [(2.0, 0.6, 1.0), (2.0, 0.3, 0.5), (1.0, 0.5, 2.0), (3.7, 0.2, 1.5)] {
        let p = point_json(&crate::common::shape(&format!("power:{n}")).unwrap(), vbar, amp);
        let c = (1.0 - vbar * vbar).sqrt();
        // Where s crosses each threshold, within the contact (z >= 0).
        let mut want: Vec<f64> =
            [1.0, c, -c, -1.0].iter().map(|&s| 1.0 - amp * s).filter(|&d| d > 0.0).map(|d| d.powf(1.0 / n)).collect();
        want.insert(0, 0.0);
        want.dedup();
        let bands = p["bands"].as_array().unwrap();
        let mut edges: Vec<f64> = bands.iter().map(|b| b["x_range"][0].as_f64().unwrap()).collect();
        edges.push(bands.last().unwrap()["x_range"][1].as_f64().unwrap());
        assert_eq!(edges.len(), want.len(), "n {n} vbar {vbar} amp {amp}: {edges:?} against {want:?}");
        for (e, w) in edges.iter().zip(&want) {
            assert!((e - w).abs() <= 1e-15 * w.max(1.0), "n {n} vbar {vbar} amp {amp}: edge {e} against {w}");
        }
        // Shares: the spring at z has s = (1 - z^n)/amp, normal amp <B>(s), friction amp (<B> - D).
        let spring = |z: f64| {
            let s = (1.0 - z.powf(n)) / amp;
            (mean_b(s), mean_b(s) - deficit(s, vbar))
        };
        let per_band: Vec<(f64, f64)> = edges.windows(2).map(|w| tanh_sinh(w[0], w[1], 1.0 / 64.0, &spring)).collect();
        let (tn, tt) = per_band.iter().fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
        for (b, (bn, bt)) in bands.iter().zip(&per_band) {
            let (sn, st) = (b["normal_share"].as_f64().unwrap(), b["tangential_share"].as_f64().unwrap());
            assert!(
                (sn - bn / tn).abs() <= 1e-10,
                "n {n} vbar {vbar} amp {amp}: normal share {sn} against {}",
                bn / tn
            );
            assert!(
                (st - bt / tt).abs() <= 1e-10,
                "n {n} vbar {vbar} amp {amp}: tangential share {st} against {}",
                bt / tt
            );
        }
    }
}

/// The bands' tangential shares keep their accuracy as `mu -> 0` (amp >= 1,
/// vbar -> 0, down to subnormal velocities): they sum to 1 to rounding. Taken
/// as shares of `<N> - D`, they lost `mu`'s relative accuracy (the paraboloid's
/// one band at amp 2 held 0.62 of the force at vbar 1e-16 and none at 1e-20;
/// at vbar 1e-3 the shares summed to 1 - 1.1e-13), and `point` took the bands
/// of a subnormal velocity from a direct solve, its forces subnormal.
#[test]
fn band_shares_sum_to_one_as_mu_vanishes() {
    for spec in ["parabolic", "cone", "power:3.7"] {
        for amp in [1.0, 1.5, 2.0] {
            for vbar in [1e-3, 1e-8, 1e-16, 1e-20, 1e-310, 5e-324] {
                let p = point_json(&crate::common::shape(spec).unwrap(), vbar, amp);
                let bands = p["bands"].as_array().unwrap();
                let share = |k: &str| bands.iter().map(|b| b[k].as_f64().unwrap()).sum::<f64>();
                for k in ["normal_share", "tangential_share"] {
                    let s = share(k);
                    assert!((s - 1.0).abs() <= 4.0 * f64::EPSILON, "{spec} amp {amp} vbar {vbar:e}: {k} sum {s}");
                }
                for b in bands {
                    let st = b["tangential_share"].as_f64().unwrap();
                    assert!((0.0..=1.0 + f64::EPSILON).contains(&st), "{spec} amp {amp} vbar {vbar:e}: {b}");
                }
            }
        }
    }
}

/// At `vbar = 0` and `amp > 1` the tangential force vanishes (`mu = 0`
/// exactly): every band's tangential share is then 0, not `0/0` (a NaN would
/// print as `null`), while the normal shares still sum to 1; and no spring
/// slips only.
#[test]
fn band_shares_without_tangential_force_are_zero() {
    for spec in ["parabolic", "cone", "power:3.7"] {
        for amp in [1.5, 2.0, 10.0] {
            let p = point_json(&crate::common::shape(spec).unwrap(), 0.0, amp);
            assert_eq!(p["mu_ratio"].as_f64(), Some(0.0), "{spec} amp {amp}");
            let bands = p["bands"].as_array().unwrap();
            assert!(!bands.is_empty(), "{spec} amp {amp}");
            // Nothing slips only at vbar = 0 (it was reported an ulp wide).
            assert!(bands.iter().all(|b| b["kind"] != "slip_only"), "{spec} amp {amp}: {bands:?}");
            let mut normal = 0.0;
            for b in bands {
                assert_eq!(b["tangential_share"].as_f64(), Some(0.0), "{spec} amp {amp}: {b}");
                normal += b["normal_share"].as_f64().unwrap();
            }
            assert!((normal - 1.0).abs() <= 4.0 * f64::EPSILON, "{spec} amp {amp}: normal shares sum to {normal}");
        }
    }
}
