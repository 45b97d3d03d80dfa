//! Every contact through the `Contact` trait: the equivalent profile, the
//! static and mean normal forces, the time-stepping peer and force histories
//! work for the flat punch, power laws, tabulated tables and the worn tip alike.

use fricosc::contact::{Contact, FlatPunch, PowerLaw};
use fricosc::history::{history, HistoryOptions};
use fricosc::stepper::Stepping;
use fricosc::Shape;

fn table_of_squares() -> Shape {
    // g = x^2 tabulated: the interpolant is exact for quadratics.
    let x: Vec<f64> = (0..=400).map(|i| 0.01 * i as f64).collect();
    let g: Vec<f64> = x.iter().map(|x| x * x).collect();
    let t = fricosc::contact::Table::from_columns(x, g, false, "squares").unwrap().at(1.0).unwrap();
    Shape::from_contact(std::sync::Arc::new(t.named("squares")))
}

/// The static force: Hertz for the paraboloid and the worn tip at E = 0, the
/// tabulated paraboloid equal to it, the flat punch linear; the worn tip lies
/// between the paraboloid and the flat punch of its contact radius.
#[test]
fn static_forces_have_their_closed_forms() {
    let par = PowerLaw { n: 2.0 };
    let tip0 = Shape::parse("flat-tip:0").unwrap();
    let tip = Shape::parse("flat-tip:0.6").unwrap();
    let table = table_of_squares();
    for c in [0.01, 0.3, 1.0, 1.7] {
        let hertz = 4.0 / 3.0 * c * f64::sqrt(c);
        assert!((par.static_force(c) - hertz).abs() <= 4e-16 * hertz);
        assert!((tip0.contact().static_force(c) - hertz).abs() <= 4e-16 * hertz);
        let tab = table.contact().static_force(c);
        assert!((tab - hertz).abs() <= 1e-14 * hertz, "c={c}: {tab} vs {hertz}");
        assert_eq!(FlatPunch.static_force(c), 2.0 * c);
        let worn = tip.contact().static_force(c);
        assert!(worn > hertz * (1.0 - 1e-12) && worn.is_finite(), "c={c}: {worn}");
    }
    for c in [0.3, 0.8, 1.7] {
        let closed = tip.contact().static_force(c);
        let sum = worn_tip_force(0.6, c);
        assert!((closed - sum).abs() < 1e-13 * closed, "c={c}: {closed} vs quadrature {sum}");
    }
}

/// The worn tip's static force `2 int (c - G)_+ dz` by an independent
/// quadrature of its profile `G(z) = z sqrt(z^2 - E^2)/sqrt(1 - E^2)` (written
/// here from the derivation in `src/fricosc/src/contact/flat_tip.rs`, not called).
fn worn_tip_force(e: f64, c: f64) -> f64 {
    let g = |z: f64| if z <= e { 0.0 } else { z * (z * z - e * e).sqrt() / (1.0 - e * e).sqrt() };
    // The edge G(zc) = c: z^4 - E^2 z^2 = c^2 (1 - E^2).
    let zc = ((e * e + (e.powi(4) + 4.0 * c * c * (1.0 - e * e)).sqrt()) / 2.0).sqrt();
    // The flat part (G = 0), then the curved part graded at both ends.
    2.0 * e * c + 2.0 * crate::common::quad::graded(|z| c - g(z), e, zc, 200)
}

/// The default phase average of the static force (used by the worn tip) against
/// the paraboloid's closed-form mean normal force, with and without contact loss.
#[test]
fn default_mean_normal_matches_the_closed_form() {
    let tip0 = Shape::parse("flat-tip:0").unwrap();
    for amp in [0.0, 0.3, 1.0, 2.5, 40.0] {
        let closed = PowerLaw { n: 2.0 }.mean_normal(amp).unwrap();
        let default = tip0.contact().mean_normal(amp).unwrap();
        // Observed 1.7e-15 relative.
        assert!((default - closed).abs() <= 4e-15 * closed, "amp={amp}: {default} vs {closed}");
    }
    // The flat punch: (1/pi) int (1 - amp cos)_+ in units of its stiffness.
    assert_eq!(FlatPunch.mean_normal(0.5).unwrap(), 2.0);
    // Its equivalent profile: 0 across the punch, a wall beyond its edge.
    for (z, g) in [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (1.0 + 1e-15, f64::INFINITY), (3.0, f64::INFINITY)] {
        assert_eq!(FlatPunch.equivalent_profile(z), g, "z = {z}");
    }
}

/// A power law's exponent: not a number, not finite or not positive, or out of
/// range, each refused by name.
#[test]
fn power_law_exponents_are_refused_by_name() {
    for (spec, says) in [
        ("power:x", "is not a number"),
        ("power:inf", "finite and > 0"),
        ("power:NaN", "finite and > 0"),
        ("power:-2", "finite and > 0"),
        ("power:0.01", "within [0.05, 1e6]"),
        ("power:2e6", "within [0.05, 1e6]"),
    ] {
        let e = Shape::parse(spec).unwrap_err().to_string();
        assert!(e.contains(says), "{spec}: {e}");
    }
}

/// The time-stepping peer on the tabulated paraboloid equals it on the analytic
/// one (the same grid, the same G up to rounding), and on the worn tip it
/// converges to the exact solver.
#[test]
fn stepping_works_for_every_contact() {
    let st = Stepping { steps_per_period: 400, springs: 200 };
    let par = crate::common::at::stepped(&Shape::parabolic(), 0.3, 0.4, st).unwrap();
    let tab = crate::common::at::stepped(&table_of_squares(), 0.3, 0.4, st).unwrap();
    assert!((par.ratio.mu_ratio - tab.ratio.mu_ratio).abs() < 1e-13, "{par:?} vs {tab:?}");
    let tip = Shape::parse("flat-tip:0.5").unwrap();
    let exact = crate::common::at::eval(&tip, 0.3, 0.4).unwrap().ratio.mu_ratio;
    let err = |m: usize| {
        let st = Stepping { steps_per_period: m, springs: m };
        (crate::common::at::stepped(&tip, 0.3, 0.4, st).unwrap().ratio.mu_ratio - exact).abs()
    };
    let (coarse, fine) = (err(250), err(1000));
    assert!(fine < 0.5 * coarse && fine < 2e-3, "errors {coarse:e} -> {fine:e}");
}

/// Histories of a table and of the worn tip: the normal force at each sample is
/// the static force at that phase's depth in units of the one at depth 1 (Hertz's
/// closed form for the table of squares, an independent quadrature for the worn
/// tip), and the tangential
/// force (a sum over the grid's springs) stays under it, up to the grid's
/// midpoint error.
#[test]
fn histories_work_for_every_contact() {
    let hertz = |c: f64| if c > 0.0 { 4.0 / 3.0 * c * c.sqrt() } else { 0.0 };
    let worn = |c: f64| if c > 0.0 { worn_tip_force(0.5, c) } else { 0.0 };
    let cases: [(Shape, &dyn Fn(f64) -> f64); 2] =
        [(table_of_squares(), &hertz), (Shape::parse("flat-tip:0.5").unwrap(), &worn)];
    for (shape, force) in cases {
        let opts = HistoryOptions::default().with_samples(16).with_springs(2000).with_spring_at(vec![0.5]);
        let h = history(&shape, &fricosc::Conditions::vbar(0.3, 1.4).unwrap(), &opts).unwrap();
        let top = h.samples.iter().map(|s| s.normal).fold(0.0, f64::max);
        for s in &h.samples {
            let depth = 1.0 - 1.4 * s.tau.cos();
            let exact = force(depth) / force(1.0);
            assert!((s.normal - exact).abs() <= 1e-13 * top, "{}: {s:?} vs {exact}", shape.name());
            // Observed at most 2e-8 of the peak above the exact normal force.
            assert!(s.tangential.is_finite() && s.tangential <= s.normal + 2e-7 * top, "{s:?}");
        }
    }
}

/// The share of the load on springs that lose contact, against closed forms
/// derived here: the cone (`G(z) = z`, `F(d) = d^2`) has the mean normal force
/// `1 + amp^2/2` and the permanent springs `z < 1 - amp` carry
/// `2 int_0^{1-amp} (1 - z) dz = 1 - amp^2`; the paraboloid (`G = z^2`,
/// `F(d) = (4/3) d^(3/2)`) has `P = 2 (z_p - z_p^3/3)`, `z_p = sqrt(1 - amp)`,
/// and its mean normal force by an independent Gauss-Legendre rule (smooth for
/// `amp < 1`). The flat punch: 0 up to `amp = 1`, 1 beyond; every curved
/// contact: 1 from `amp = 1` on.
#[test]
fn jumping_share_matches_closed_forms() {
    let (x, w) = crate::common::quad::gauss_legendre(64);
    for a in [1e-6, 0.01, 0.3, 0.5, 0.9, 0.999] {
        let cone = 1.0 - (1.0 - a * a) / (1.0 + 0.5 * a * a);
        let got = Shape::cone().jumping_share(a).unwrap();
        assert!((got - cone).abs() <= 4e-15, "cone {a}: {got} vs {cone}");
        let mean: f64 = x
            .iter()
            .zip(&w)
            .map(|(&t, &wt)| {
                let tau = 0.5 * std::f64::consts::PI * (t + 1.0);
                0.5 * wt * (4.0 / 3.0) * (1.0 - a * tau.cos()).powf(1.5)
            })
            .sum();
        let zp = (1.0 - a).sqrt();
        let para = 1.0 - 2.0 * (zp - zp * zp * zp / 3.0) / mean;
        let got = Shape::parabolic().jumping_share(a).unwrap();
        assert!((got - para).abs() <= 1e-13 * para.max(1e-3), "parabolic {a}: {got} vs {para}");
    }
    for (a, flat, curved) in [(0.0, 0.0, 0.0), (0.5, 0.0, 0.156), (1.0, 0.0, 1.0), (1.5, 1.0, 1.0)] {
        assert_eq!(Shape::flat().jumping_share(a).unwrap(), flat);
        let c = Shape::parabolic().jumping_share(a).unwrap();
        assert!((c - curved).abs() < 1e-3, "{a}: {c}");
    }
}

/// One classification for every output: the flat punch by its spring's regime
/// (permanent contact up to amp = 1, slip-first or stick-first beyond, split at
/// `1/amp = sqrt(1 - vbar^2)`), a curved contact mixed below amp = 1 and
/// jumping from it on; at rest at vbar = 0, sliding from vbar = 1 or at amp = 0.
#[test]
fn regimes_of_points() {
    use fricosc::report::ContactRegime as R;
    let (flat, para) = (Shape::flat(), Shape::parabolic());
    assert_eq!(flat.regime(0.0, 0.5).unwrap(), R::AtRest);
    assert_eq!(flat.regime(1.0, 0.5).unwrap(), R::Sliding);
    assert_eq!(flat.regime(0.5, 0.0).unwrap(), R::Sliding);
    assert_eq!(flat.regime(0.5, 1.0).unwrap(), R::PermanentContact);
    // 1/amp against sqrt(1 - 0.6^2) = 0.8: amp 1.2 slips first, 1.3 sticks first.
    assert_eq!(flat.regime(0.6, 1.2).unwrap(), R::JumpingSlipFirst);
    assert_eq!(flat.regime(0.6, 1.3).unwrap(), R::JumpingStickFirst);
    assert_eq!(para.regime(0.6, 0.999).unwrap(), R::Mixed);
    assert_eq!(para.regime(0.6, 1.0).unwrap(), R::Jumping);
    assert!(para.regime(-0.1, 0.5).is_err() && para.regime(0.1, f64::NAN).is_err());
}

/// A shape through the library's `Shape` API alone (what the Python package and
/// other programs call): its name (`Debug`, equality), its checks before any
/// work, `mu_static` against the flat punch's closed form `(1 - amp)_+`, and
/// the flat punch's error estimate, which bounds the error against the
/// 40-digit references and is a few ulps, not a constant.
#[test]
fn the_shape_api_names_checks_and_bounds() {
    let (flat, par) = (Shape::parse("flat").unwrap(), Shape::parse("parabolic").unwrap());
    assert_eq!(format!("{flat:?}"), "Shape(flat)");
    assert_eq!(format!("{par:?}"), "Shape(parabolic)");
    assert!(flat == Shape::parse("flat").unwrap() && flat != par);
    let tol = fricosc::DEFAULT_TOL;
    for amp in [0.0, 0.25, 0.4, 1.0, 1.5] {
        assert_eq!(flat.mu_static(amp, tol).unwrap(), (1.0 - amp).max(0.0), "amp {amp}");
    }
    assert_eq!(par.mu_static(1.5, tol).unwrap(), 0.0);
    assert_eq!(par.mu_static(0.0, tol).unwrap(), 1.0);
    for bad in [-1.0, f64::NAN, f64::INFINITY] {
        assert!(flat.mu_static(bad, tol).is_err(), "amp {bad}");
        assert!(crate::common::at::report(&flat, bad, 0.5, tol).is_err(), "vbar {bad}");
        assert!(crate::common::at::report(&flat, 0.5, bad, tol).is_err(), "amp {bad}");
    }
    assert!(flat.mu_static(0.5, 0.0).is_err() && crate::common::at::report(&flat, 0.5, 0.5, 0.0).is_err());
    let mut checked = 0;
    for c in crate::common::reference_cases().iter().filter(|c| c.shape == "flat") {
        let e = crate::common::at::eval(&flat, c.vbar, c.amp).unwrap();
        let error = crate::common::exact_error(e.ratio.mu_ratio, &c.mu_text);
        assert!(error <= e.error_estimate, "vbar {} amp {}: error {error:e} > {:e}", c.vbar, c.amp, e.error_estimate);
        assert!(e.error_estimate <= 2e-15, "vbar {} amp {}: estimate {:e}", c.vbar, c.amp, e.error_estimate);
        checked += 1;
    }
    assert!(checked >= 10, "{checked} flat references");
    // At amp = 1 mu = pi vbar (1 + O(vbar)): subnormal at vbar = 1e-320, where
    // the estimate's relative part underflows and the subnormals' spacing is the bound.
    let vbar = 1e-320;
    let e = crate::common::at::eval(&flat, vbar, 1.0).unwrap();
    let error = (e.ratio.mu_ratio - std::f64::consts::PI * vbar).abs();
    assert!(e.error_estimate >= f64::from_bits(1) && error <= e.error_estimate, "{e:?}");
}

/// `Shape::ratio` (the ratio without its estimate: the flat punch's own path,
/// the others through `evaluate`) gives `evaluate`'s numbers bit for bit,
/// across the flat punch's regimes and every contact kind, and refuses what
/// `evaluate` refuses.
#[test]
fn the_ratio_alone_is_the_evaluations_ratio() {
    let shapes = [
        Shape::parse("flat").unwrap(),
        Shape::parse("parabolic").unwrap(),
        Shape::parse("flat-tip:0.5").unwrap(),
        table_of_squares(),
    ];
    for shape in &shapes {
        for vbar in [0.0, 1e-9, 0.05, 0.3, 0.69, 0.71, 0.999, 1.0, 2.0] {
            for amp in [0.0, 0.3, 0.9, 1.0, 1.2, 3.0] {
                let (r, e) = (
                    crate::common::at::ratio(shape, vbar, amp).unwrap(),
                    crate::common::at::eval(shape, vbar, amp).unwrap().ratio,
                );
                assert_eq!(
                    (r.mu_ratio.to_bits(), r.reduction.to_bits()),
                    (e.mu_ratio.to_bits(), e.reduction.to_bits()),
                    "{shape:?} vbar {vbar} amp {amp}"
                );
            }
        }
        for bad in [-1.0, f64::NAN, f64::INFINITY] {
            assert!(
                crate::common::at::ratio(shape, bad, 0.5).is_err()
                    && crate::common::at::ratio(shape, 0.5, bad).is_err(),
                "{shape:?} {bad}"
            );
        }
    }
    // Beyond the table's reach (its last row: x = 4).
    assert!(
        crate::common::at::ratio(&shapes[3], 0.5, 20.0).is_err()
            && crate::common::at::eval(&shapes[3], 0.5, 20.0).is_err()
    );
}

/// The regimes' names as outputs print them: each variant's `name` is its
/// serde name (snake case), and they are distinct.
#[test]
fn regime_names_are_their_serialised_names() {
    use fricosc::report::ContactRegime::*;
    let all = [AtRest, Sliding, PermanentContact, JumpingSlipFirst, JumpingStickFirst, Mixed, Jumping];
    let names: std::collections::BTreeSet<&str> = all.iter().map(|r| r.name()).collect();
    assert_eq!(names.len(), all.len());
    for r in all {
        assert_eq!(serde_json::to_value(r).unwrap(), serde_json::Value::from(r.name()));
        assert!(r.name().len() > 3 && r.name().chars().all(|c| c.is_ascii_lowercase() || c == '_'), "{}", r.name());
    }
}

/// The share of the load on springs that lose contact: none for the flat punch
/// up to `amp = 1`, all beyond; all for a curved shape from `amp = 1`; and in
/// between, for the paraboloid, `1 - P/<N>` with `P` the permanent springs'
/// share (here against its own quadrature's limits: in (0, 1), increasing).
#[test]
fn jumping_shares_at_their_limits() {
    let (flat, par) = (Shape::parse("flat").unwrap(), Shape::parse("parabolic").unwrap());
    for (amp, want) in [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (1.5, 1.0)] {
        assert_eq!(flat.jumping_share(amp).unwrap(), want, "flat {amp}");
    }
    for (amp, want) in [(0.0, 0.0), (1.0, 1.0), (1.5, 1.0)] {
        assert_eq!(par.jumping_share(amp).unwrap(), want, "parabolic {amp}");
    }
    let shares: Vec<f64> = [0.1, 0.5, 0.9].iter().map(|&a| par.jumping_share(a).unwrap()).collect();
    assert!(shares[0] > 0.0 && shares[2] < 1.0 && shares.windows(2).all(|w| w[0] < w[1]), "{shares:?}");
}

/// Curved contacts at `amp >= 1` and velocities down to the smallest
/// subnormal, where `mu` is `vbar` times a slope: within its estimate of that
/// slope (taken at `vbar = 1e-30`, accurate to ~1e-15; `mu/vbar` changes by
/// ~15 vbar) times `vbar`. Solved directly, the springs' forces went
/// subnormal and `mu` lost digits its estimate did not cover (the paraboloid at
/// `amp = 2`: 2.4056e-320 for 2.4079e-320 with an estimate of 0; at `vbar =
/// 1e-310`, 3.6e-323 off for 5e-324); at `amp = 1` the slip-first band's width
/// underflowed from `vbar` ~1e-155 (the paraboloid's `mu/vbar` 2.5685883889
/// at 1e-160 and 3.45 at 1e-200 for 2.5685834706, and the same 3.45 at
/// every subnormal velocity, solved at 6e-232: the slope this test took at
/// 1e-250 agreed with it).
#[test]
fn curved_contacts_at_subnormal_velocities() {
    let shapes = [
        Shape::parse("parabolic").unwrap(),
        Shape::parse("cone").unwrap(),
        Shape::parse("power:1.5").unwrap(),
        Shape::parse("flat-tip:0.3").unwrap(),
        table_of_squares(),
    ];
    for shape in &shapes {
        for amp in [1.0, 2.0] {
            let slope = crate::common::at::eval(shape, 1e-30, amp).unwrap().ratio.mu_ratio / 1e-30;
            for vbar in [1e-100, 1e-160, 1e-200, 1e-250, 1e-280, 1e-290, 1e-300, 1e-310, 1e-320, 5e-324] {
                let e = crate::common::at::eval(shape, vbar, amp).unwrap();
                let expected = slope * vbar;
                let err = (e.ratio.mu_ratio - expected).abs();
                assert!(
                    err <= e.error_estimate + 4e-15 * expected,
                    "{} amp {amp} vbar {vbar:e}: {:e} vs {expected:e}, estimate {:e}",
                    shape.name(),
                    e.ratio.mu_ratio,
                    e.error_estimate
                );
                // And the estimate is an estimate: an error of the scaled solve
                // or of the scaling grows it (the linearisation's term is the
                // scaled velocity times 1e3 mu), it must not cover by size.
                // Nor a floor: it carries the scaled solve's estimate (a few
                // eps of mu), which a scaling that dropped it would lose.
                if expected > 1e-300 {
                    assert!(e.error_estimate >= 1e-15 * expected, "{} amp {amp} vbar {vbar:e}", shape.name());
                }
                assert!(
                    e.error_estimate <= 1e-13 * expected + f64::from_bits(2),
                    "{} amp {amp} vbar {vbar:e}: estimate {:e}",
                    shape.name(),
                    e.error_estimate
                );
                assert_eq!(e.ratio.reduction, 1.0);
            }
        }
    }
}
