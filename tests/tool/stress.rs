//! Numerical stress: random and edge points, and continuity across every regime boundary.
use fricosc::DEFAULT_TOL;
use fricosc_cli::stress::{check, default_shapes};

/// A 10^5-point subset of `fricosc stress --points 1000000` (README: Stress).
#[test]
fn a_hundred_thousand_random_and_edge_points_pass_every_check() {
    let r = check(100_000, 7, &default_shapes());
    assert!(r.points >= 100_000);
    // Oscillation in the sliding direction too: a hundredth as many.
    assert!(r.oscillation_points >= 1_000, "{}", r.oscillation_points);
    assert_eq!(r.failure_count, 0, "{:#?}", r.failures);
}

fn mu(n: f64, v: f64, a: f64) -> f64 {
    let c = fricosc::Conditions::vbar(v, a).and_then(|c| c.with_tol(DEFAULT_TOL)).unwrap();
    fricosc::Shape::power(n).unwrap().ratio(&c).unwrap().mu_ratio
}

/// Jumps of mu across a boundary at distance d on both sides: Lipschitz part
/// (|dmu/dx| < 10 here) plus the solver's accuracy.
fn assert_continuous(what: &str, f: impl Fn(f64) -> f64, x0: f64) {
    for d in [1e-6, 1e-9, 1e-12] {
        let jump = (f(x0 + d) - f(x0 - d)).abs();
        assert!(jump <= 20.0 * d + 2e-13, "{what} at {x0} +- {d:e}: jump {jump:e}");
    }
}

#[test]
fn mdr_is_continuous_across_every_regime_boundary() {
    for n in [1.0, 2.0, 3.7] {
        for v in [1e-3, 0.3, 0.8, 0.999] {
            // amp = 1: the permanent-contact band vanishes.
            assert_continuous(&format!("n={n} v={v} amp"), |a| mu(n, v, a), 1.0);
        }
        for a in [0.3, 1.0, 2.5] {
            // vbar = 1: the stick band vanishes.
            assert_continuous(&format!("n={n} a={a} vbar"), |v| mu(n, v, a), 1.0);
        }
        for a in [1.2f64, 3.0] {
            // amp sqrt(1 - vbar^2) = 1: the stick-first band reaches the centre.
            let v0 = (1.0 - 1.0 / (a * a)).sqrt();
            assert_continuous(&format!("n={n} a={a} centre switch"), |v| mu(n, v, a), v0);
        }
    }
}
