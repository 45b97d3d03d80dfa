//! The sphere worn flat at its tip (`flat-tip:E`), added through the `Contact`
//! trait: its MDR profile against the transform of a tabulated profile of the
//! same body, and its limits (the paraboloid at E = 0, the flat punch as E -> 1).

use fricosc::Shape;

fn mu(spec: &str, v: f64, a: f64) -> (f64, f64) {
    let e = crate::common::at::eval(&Shape::parse(spec).unwrap(), v, a).unwrap();
    (e.ratio.mu_ratio, e.error_estimate)
}

/// E = 0 is the paraboloid, computed by an unrelated quadrature (in t = sqrt(G)
/// against the power-law bands in the angle u).
#[test]
fn zero_flat_is_the_paraboloid() {
    let mut worst = 0.0f64;
    for v in [0.0, 1e-6, 0.1, 0.3, 0.7, 0.99, 1.0 - 1e-6] {
        for a in [0.1, 0.5, 0.9, 0.999, 1.0, 1.3, 2.0, 10.0] {
            let (m, est) = mu("flat-tip:0", v, a);
            let (p, pest) = mu("parabolic", v, a);
            let err = (m - p).abs();
            worst = worst.max(err);
            assert!(err <= est + pest + 1e-15, "v={v} a={a}: {m} vs {p} (estimates {est:e}, {pest:e})");
        }
    }
    assert!(worst < 1e-13, "{worst:e}");
}

/// As E -> 1 the flat takes the whole contact: the flat punch, at rate O(1 - E).
#[test]
fn a_flat_covering_the_contact_is_the_flat_punch() {
    for (v, a) in [(0.3, 0.4), (0.5, 0.9), (0.2, 1.5)] {
        let f = mu("flat", v, a).0;
        let d1 = (mu("flat-tip:0.999", v, a).0 - f).abs();
        let d2 = (mu("flat-tip:0.999999", v, a).0 - f).abs();
        assert!(d2 < 1e-4 && d2 < d1 / 100.0, "v={v} a={a}: {d1:e} {d2:e}");
    }
}

/// The same body as a tabulated axisymmetric profile, f = 0 for r <= a and
/// (r^2 - a^2)/(2R) beyond, goes through the numerical MDR transform and the
/// tabulated quadrature: it agrees within its own interpolation error.
#[test]
fn agrees_with_the_tabulated_profile_of_the_same_body() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-flattip-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    // R = 1, contact radius x_c = 0.1 at the mean indentation, E = a/x_c = 0.5:
    // g(x_c) = x_c sqrt(x_c^2 - a^2)/R = u0.
    let (r_sphere, xc, e) = (1.0f64, 0.1f64, 0.5f64);
    let a = e * xc;
    let u0 = xc * (xc * xc - a * a).sqrt() / r_sphere;
    let rows: String = (0..=2000)
        .map(|i| 0.4 * i as f64 / 2000.0)
        .map(|r: f64| format!("{r:?},{:?}\n", if r <= a { 0.0 } else { (r * r - a * a) / (2.0 * r_sphere) }))
        .collect();
    let file = dir.join("worn.csv");
    std::fs::write(&file, format!("r,f\n{rows}")).unwrap();
    let table = crate::common::shape(&format!("profile:{}@{u0:?}", file.display())).unwrap();
    for (v, amp) in [(0.3, 0.4), (0.1, 0.8), (0.5, 1.5)] {
        let t = crate::common::at::eval(&table, v, amp).unwrap();
        let (m, est) = mu("flat-tip:0.5", v, amp);
        let err = (t.ratio.mu_ratio - m).abs();
        let interp = t.interpolation_error.unwrap();
        assert!(
            err <= interp + t.error_estimate + est,
            "v={v} amp={amp}: {} vs {m} (interp {interp:e})",
            t.ratio.mu_ratio
        );
        // Regression bar, about 10x the observed 1.5e-6 (the table smooths the kink at r = a).
        assert!(err < 2e-5, "v={v} amp={amp}: {err:e}");
    }
    // The transform itself: g(x) = x sqrt(x^2 - a^2)/R at points of the table,
    // through the tabulated contact's normalised profile G(z) = g(x_c z)/U0.
    let text = std::fs::read_to_string(&file).unwrap();
    let t = fricosc::contact::Table::parse(&text, "flat tip", true).unwrap().at(u0).unwrap();
    let xc = t.contact_radius;
    for x in [0.08, 0.1, 0.2, 0.3] {
        let g = u0 * fricosc::contact::Contact::equivalent_profile(&t, x / xc);
        let exact = x * (x * x - a * a).sqrt() / r_sphere;
        assert!((g / exact - 1.0).abs() < 1e-4, "x={x}: {g} vs {exact}");
    }
}

/// A looser tolerance does less work and stays within its error estimate.
#[test]
fn the_error_estimate_bounds_the_error_at_every_tolerance() {
    let shape = Shape::parse("flat-tip:0.3").unwrap();
    for (v, a) in [(0.3, 0.4), (0.05, 0.95), (0.6, 3.0), (1e-4, 1.2)] {
        let best = crate::common::at::eval(&shape, v, a).unwrap().ratio.mu_ratio;
        for tol in [1e-3, 1e-6, 1e-9, 1e-12] {
            let e = crate::common::at::eval_tol(&shape, v, a, tol).unwrap();
            let err = (e.ratio.mu_ratio - best).abs();
            assert!(err <= e.error_estimate + 1e-15, "v={v} a={a} tol={tol:e}: {err:e} > {:e}", e.error_estimate);
        }
    }
    assert!(Shape::parse("flat-tip:1").is_err() && Shape::parse("flat-tip:-0.1").is_err());
    assert_eq!(Shape::parse("flat-tip:0.25").unwrap().name(), "flat-tip:0.25");
    // A negative zero is the paraboloid's flat of no width, named as +0.
    assert_eq!(Shape::parse("flat-tip:-0").unwrap().name(), "flat-tip:0.0");
    // Without a stick (vbar >= 1) or an oscillation, mu = 1 exactly: no error.
    for (v, a) in [(1.0, 0.5), (1.5, 3.0), (0.3, 0.0)] {
        let e = crate::common::at::eval(&shape, v, a).unwrap();
        assert_eq!((e.ratio.mu_ratio, e.ratio.reduction, e.error_estimate), (1.0, 0.0, 0.0), "v={v} a={a}");
    }
}

/// At a subnormal amplitude (the spring coordinate `(1 - G)/amp` overflows) the
/// reduction is the small-amplitude slope times the amplitude, as at 1e-200:
/// an internal error ("mean normal force NaN") before.
#[test]
fn subnormal_amplitude_gives_the_linear_reduction() {
    let shape = Shape::parse("flat-tip:0.5").unwrap();
    let slope = |a: f64| crate::common::at::eval(&shape, 0.3, a).unwrap().ratio.reduction / a;
    let (below, small) = (slope(1e-305), slope(1e-200));
    assert!(((below - small) / small).abs() < 1e-12, "{below} vs {small}");
    // 2.1e-314 is subnormal: the reduction carries about 4e-10 relative.
    let tiny = slope(2.1219957905e-314);
    assert!(((tiny - small) / small).abs() < 1e-9, "{tiny} vs {small}");
    // The estimate bounds mu's error (1 - mu = the reduction, rounded away in
    // mu = 1) and scales with the amplitude (below an ulp).
    for a in [1e-305, 2.1219957905e-314] {
        let e = crate::common::at::eval(&shape, 0.3, a).unwrap();
        assert!(
            e.ratio.reduction <= e.error_estimate && e.error_estimate <= 1e-20,
            "amp {a:e}: {:e}",
            e.error_estimate
        );
    }
}

/// At a huge amplitude the flat (scaled by `1/sqrt(amp)`) vanishes against the
/// contact: the paraboloid, to its error estimate; a flat whose square is
/// subnormal (1e-160) or zero (1e-170, where `t^2` of the pieces cut at its
/// scale underflows too: NaN if the flat were kept) likewise, at any amplitude.
#[test]
fn a_flat_negligible_against_the_contact_is_the_paraboloid() {
    let cases = [
        ("flat-tip:0.5", 1e300),
        ("flat-tip:0.9", 1e250),
        ("flat-tip:1e-160", 0.5),
        ("flat-tip:1e-160", 2.0),
        ("flat-tip:1e-170", 0.5),
        ("flat-tip:1e-170", 2.0),
    ];
    for (spec, amp) in cases {
        for v in [0.1, 0.6] {
            let tip = crate::common::at::eval(&Shape::parse(spec).unwrap(), v, amp).unwrap();
            let par = crate::common::at::eval(&Shape::parabolic(), v, amp).unwrap();
            let err = (tip.ratio.mu_ratio - par.ratio.mu_ratio).abs();
            assert!(err <= tip.error_estimate + par.error_estimate, "{spec} amp {amp:e} v {v}: {err:e}");
        }
    }
}

/// A flat far below every other length (E = 1e-152 at amp = 2.2e-159): near the
/// axis t^2 underflowed and the profile's map gave NaN (found by the solver
/// fuzz target). It is the paraboloid there.
#[test]
fn a_vanishing_flat_at_a_tiny_amplitude_is_the_paraboloid() {
    let amp = 2.2138601171837047e-159;
    for e in ["1e-152", "6.015012502120174e-153"] {
        let tip =
            crate::common::at::eval(&Shape::parse(&format!("flat-tip:{e}")).unwrap(), 0.5625000000004549, amp).unwrap();
        let par = crate::common::at::eval(&Shape::parabolic(), 0.5625000000004549, amp).unwrap();
        let rel = (tip.ratio.reduction - par.ratio.reduction).abs() / par.ratio.reduction;
        assert!(rel < 1e-12, "E = {e}: {} vs {}", tip.ratio.reduction, par.ratio.reduction);
    }
}

/// `flat-tip:0.3` and `flat-tip:0.7` against independent values (the MDR
/// profile integrated by mpmath's tanh-sinh over `z`, each spring's steady
/// state from the seed's description: `data/scripts/mdr_reference.py
/// --flat-tip`, committed as `data/flat-tip-reference.json`), below, at and
/// above `amp = 1` and down to `vbar = 1e-12`, and at `amp = 1` down to 1e-30
/// (where `mu/vbar` still moves like `vbar^(1/2)`) and 1e-130 (below the
/// `2^-400` where the solve runs at a scaled velocity): `mu_ratio` (also relative to
/// itself where it is small: it came from `1 - reduction`, with a relative
/// error of 1.3e-10 at `amp = 1, vbar = 1e-6`) and the reduction, and the
/// error estimate bounds the error at the default tolerance and at 1e-9.
#[test]
fn worn_spheres_match_independent_values() {
    let cases = crate::common::data_cases("flat-tip-reference.json");
    assert_eq!(cases.len(), 34);
    let (mut worst, mut worst_rel) = (0.0f64, 0.0f64);
    for c in &cases {
        let spec = format!("flat-tip:{}", c["flat_ratio"].as_str().unwrap());
        let (vbar, amp) = (c["vbar"].as_f64().unwrap(), c["amp"].as_f64().unwrap());
        let (mu, red) = (c["mu_ratio"].as_str().unwrap(), c["reduction"].as_str().unwrap());
        let shape = Shape::parse(&spec).unwrap();
        let e = crate::common::at::eval(&shape, vbar, amp).unwrap();
        let err = crate::common::exact_error(e.ratio.mu_ratio, mu);
        let rel = err / mu.parse::<f64>().unwrap();
        (worst, worst_rel) = (worst.max(err), worst_rel.max(rel));
        assert!(err <= 1e-13 && rel <= 1e-12, "{spec} vbar={vbar} amp={amp}: {} vs {mu} ({err:e})", e.ratio.mu_ratio);
        assert!(
            err <= e.error_estimate,
            "{spec} vbar={vbar} amp={amp}: error {err:e} > estimate {:e}",
            e.error_estimate
        );
        // The estimate is an estimate, not a floor: at most ten times the
        // tolerance, relative to mu where mu is the small one.
        assert!(
            e.error_estimate <= 10.0 * fricosc::DEFAULT_TOL * e.ratio.mu_ratio.min(1.0),
            "{spec} vbar={vbar} amp={amp}: {:e}",
            e.error_estimate
        );
        let rel = crate::common::exact_error(e.ratio.reduction, red) / red.parse::<f64>().unwrap();
        assert!(rel <= 1e-13, "{spec} vbar={vbar} amp={amp}: reduction {rel:e}");
        let loose = crate::common::at::eval_tol(&shape, vbar, amp, 1e-9).unwrap();
        let err = crate::common::exact_error(loose.ratio.mu_ratio, mu);
        assert!(
            err <= loose.error_estimate,
            "{spec} vbar={vbar} amp={amp} tol 1e-9: {err:e} > {:e}",
            loose.error_estimate
        );
    }
    eprintln!("flat-tip against 22-digit values: worst {worst:.1e}, relative {worst_rel:.1e}");
    // Regression bars, about 10 times the worst observed (5.9e-17 and 4.6e-16).
    assert!(worst <= 1e-15 && worst_rel <= 5e-15, "{worst:e}, relative {worst_rel:e}");
}
