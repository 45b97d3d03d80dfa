//! `fricosc::fit`: the model fitted to measurements. Exact synthetic rows
//! from an independent script (`data/scripts/fit_synthetic.py`: the flat
//! punch's 50-digit steady state, not fricosc) give the parameters back;
//! noisy rows give parameters within their standard errors at the expected
//! rate; undetermined parameters and bad rows are named.
use fricosc::fit::{fit, Fixed, Measurement};
use fricosc::Shape;

/// The rows of `data/fit-synthetic-flat.csv` (`mu0 = 0.35`, `kx/kz = 0.8`, `u0 = 1e-6` m).
fn synthetic() -> Vec<Measurement> {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/fit-synthetic-flat.csv")).unwrap();
    text.lines()
        .skip(1)
        .map(|l| {
            let f: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            Measurement { v0: f[0], du: f[1], omega: 2.0 * std::f64::consts::PI * f[2], mu: f[3], sigma: None }
        })
        .collect()
}

/// Exact rows give the parameters back to 1e-7 (relative), all three fitted.
#[test]
fn exact_rows_give_the_parameters_back() {
    let r = fit(&Shape::flat(), &synthetic(), &Fixed::default()).unwrap();
    for (got, want) in [(r.mu0.value, 0.35), (r.stiffness_ratio.value, 0.8), (r.u0.value, 1e-6)] {
        assert!((got / want - 1.0).abs() < 1e-7, "{got} vs {want}: {r:?}");
    }
    assert!(r.verdicts.is_empty() && r.chi2 < 1e-20, "{r:?}");
}
