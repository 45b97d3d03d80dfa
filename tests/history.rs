//! Force histories: from the solver's phases, consistent with its means.
use fricosc::history::{history, HistoryOptions};
use fricosc::Shape;

/// Period mean by the trapezoid rule on the (uniform plus event) samples.
fn mean(samples: &[(f64, f64)]) -> f64 {
    let area: f64 = samples.windows(2).map(|w| 0.5 * (w[1].0 - w[0].0) * (w[0].1 + w[1].1)).sum();
    area / (samples.last().unwrap().0 - samples[0].0)
}

#[test]
fn flat_history_is_bounded_by_the_normal_force_and_averages_to_mu() {
    for (v, a) in [(0.3, 0.5), (0.3, 1.5), (0.95, 2.0), (1.2, 0.7)] {
        let h = history(&Shape::flat(), v, a, &HistoryOptions::default().with_samples(20000).with_springs(1)).unwrap();
        for s in &h.samples {
            assert!(s.tangential <= s.normal + 1e-15 && s.tangential >= 0.0);
        }
        let t: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.tangential)).collect();
        let n: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.normal)).collect();
        let mu = Shape::flat().evaluate(v, a).unwrap().ratio.mu_ratio;
        // Events are samples, so the trapezoid rule is second order on each smooth piece.
        assert!((mean(&t) / mean(&n) - mu).abs() < 1e-7, "v={v} a={a}: {} vs {mu}", mean(&t) / mean(&n));
    }
}

#[test]
fn mdr_history_averages_to_the_exact_mu() {
    let (v, a) = (0.3, 0.4);
    let h = history(
        &Shape::parabolic(),
        v,
        a,
        &HistoryOptions::default().with_samples(2000).with_springs(4000).with_spring_at(vec![0.0, 1.1]),
    )
    .unwrap();
    let t: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.tangential)).collect();
    let n: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.normal)).collect();
    let mu = Shape::parabolic().evaluate(v, a).unwrap().ratio.mu_ratio;
    assert!((mean(&t) / mean(&n) - mu).abs() < 1e-5, "{} vs {mu}", mean(&t) / mean(&n));
    // Chosen springs: the centre one is a flat punch with s = 1/amp; the outer one jumps.
    let c: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.springs[0][1])).collect();
    let cn: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.springs[0][0])).collect();
    let flat = Shape::flat().evaluate(v, a).unwrap().ratio.mu_ratio;
    assert!((mean(&c) / mean(&cn) - flat).abs() < 1e-6);
    assert!(h.samples.iter().any(|s| s.springs[1][0] == 0.0), "the spring at 1.1 x_c loses contact");
}
