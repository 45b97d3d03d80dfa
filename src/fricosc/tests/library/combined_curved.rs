//! Curved contacts under combined oscillation against their own tanh-sinh
//! quadrature over `z` (split where a fine scan finds the springs' phase
//! sequences change) and against the stepping peer run to convergence.

use crate::combined::{evaluate, evaluate_oscillation, osc, Oscillation};
use crate::common::quad::tanh_sinh;
use fricosc::spring::{solve, Bound, Drive, StopKind};
use fricosc::stepper::Stepping;
use fricosc::DEFAULT_TOL;

/// The phase kinds a spring goes through and how it touches.
fn sequence(b: Bound, d: Drive) -> (fricosc::spring::Touch, Vec<StopKind>) {
    let s = solve(b, d);
    let mut k: Vec<StopKind> = s.phases.iter().filter(|p| p.end > p.start).map(|p| p.kind).collect();
    k.dedup();
    (s.contact, k)
}

/// `(mu, reduction)` of a power law `G = z^n` by its own quadrature: a
/// 2048-point scan for changes of the phase sequence (bisected to rounding),
/// tanh-sinh on each piece at two steps; returns the finer and the difference.
fn independent(n: f64, o: &Oscillation) -> (f64, f64, f64) {
    let [vhat, amp, t, phase] = *o;
    let d = Drive { vhat, t, phase };
    let level = |z: f64| Bound { c: 1.0 - z.powf(n), amp };
    // The deepest indentation 1 + amp reaches z^n = 1 + amp.
    let zmax = (1.0f64 + amp).powf(1.0 / n);
    let mut cuts = vec![0.0, zmax];
    let grid = 2048;
    let sig = |z: f64| sequence(level(z), d);
    let mut prev = sig(1e-12);
    for k in 1..=grid {
        let z = zmax * k as f64 / grid as f64 * (1.0 - 1e-12);
        let s = sig(z);
        if s != prev {
            let (mut lo, mut hi) = (zmax * (k - 1) as f64 / grid as f64, z);
            for _ in 0..200 {
                let m = 0.5 * (lo + hi);
                if m <= lo || m >= hi {
                    break;
                }
                if sig(m) == prev {
                    lo = m
                } else {
                    hi = m
                }
            }
            cuts.push(0.5 * (lo + hi));
            prev = s;
        }
    }
    cuts.sort_by(f64::total_cmp);
    let f = |z: f64| {
        let s = solve(level(z), d);
        (s.mean_force, s.mean_deficit)
    };
    let total =
        |h: f64| cuts.windows(2).map(|w| tanh_sinh(w[0], w[1], h, &f)).fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
    let (coarse, fine) = (total(1.0 / 16.0), total(1.0 / 32.0));
    // Mean normal force of z^n over [0, zmax]: 2 int (1 - z^n) dz (amp < 1: the whole disc; the
    // oscillation's mean of (c - amp cos)_+ otherwise, by the same quadrature).
    let normal = 2.0
        * cuts
            .windows(2)
            .map(|w| tanh_sinh(w[0], w[1], 1.0 / 32.0, &|z| (solve(level(z), d).mean_bound, 0.0)).0)
            .sum::<f64>();
    let diff = ((fine.0 - coarse.0).abs().max((fine.1 - coarse.1).abs())) * 2.0 / normal;
    (2.0 * fine.0 / normal, 2.0 * fine.1 / normal, diff)
}

#[test]
fn curved_contacts_agree_with_an_independent_quadrature_within_their_estimate() {
    let cases = [
        (2.0, osc(0.5, 0.2, 0.3, 0.0)),
        (2.0, osc(0.0, 0.3, 2.0, 0.0)),
        (2.0, osc(1.5, 0.3, 0.4, 2.5)),
        (1.0, osc(0.9, 0.05, 0.8, 2.0)),
        (1.0, osc(2.0, 0.6, 3.0, 1.0)),
        (3.0, osc(0.3, 0.01, 0.5, 4.0)),
    ];
    for (n, o) in cases {
        let shape = crate::common::shape(&format!("power:{n}")).unwrap();
        let (mu, red, acc) = independent(n, &o);
        assert!(acc <= 1e-14, "n {n} {o:?}: the reference itself is good to {acc:e} only");
        for tol in [1e-4, 1e-8, DEFAULT_TOL] {
            let r = evaluate(&shape, &o, tol).unwrap();
            let e = (r.ratio.mu_ratio - mu).abs().max((r.ratio.reduction - red).abs());
            assert!(
                e <= r.error_estimate + acc,
                "n {n} {o:?} tol {tol:e}: error {e:e} > estimate {:e}",
                r.error_estimate
            );
            if tol == DEFAULT_TOL {
                // Each band is named after what the spring at its middle does.
                let [vhat, amp, t, phase] = o;
                let d = Drive { vhat, t, phase };
                assert!(!r.bands.is_empty(), "n {n} {o:?}");
                // The bands' shares of <f> add up to the whole.
                let total: f64 = r.bands.iter().map(|b| b.share).sum();
                assert!((total - 1.0).abs() <= 1e-12, "n {n} {o:?}: shares add up to {total}");
                for band in &r.bands {
                    let z = 0.5 * (band.from + band.to);
                    let (contact, kinds) = sequence(Bound { c: 1.0 - z.powf(n), amp }, d);
                    let contact = match contact {
                        fricosc::spring::Touch::Never => "never",
                        fricosc::spring::Touch::Permanent => "permanent",
                        fricosc::spring::Touch::Jumping => "jumping",
                    };
                    let kinds: Vec<&str> = kinds
                        .iter()
                        .map(|k| match k {
                            StopKind::Stick => "stick",
                            StopKind::Forward => "forward",
                            StopKind::Backward => "backward",
                        })
                        .collect();
                    assert_eq!(band.regime, format!("{contact}: {}", kinds.join(", ")), "n {n} {o:?}: {band:?}");
                }
                assert!(e <= 1e-13, "n {n} {o:?}: error {e:e}");
                assert!(r.error_estimate <= 1e-12, "n {n} {o:?}: estimate {:e}", r.error_estimate);
            }
        }
    }
}

/// The stepping peer (the seed's scheme with the stop operator's two-way
/// clamp) converges to the exact answer at first order in the step.
#[test]
fn stepping_peer_converges_to_the_exact_answer() {
    let cases = [
        ("flat", osc(0.0, 0.3, 2.0, 0.0), 1),
        ("flat", osc(2.0, 0.6, 3.0, 1.0), 1),
        ("flat", osc(0.9, 0.05, 0.8, 2.0), 1),
        ("parabolic", osc(0.5, 0.2, 1.0, 1.0), 4000),
    ];
    for (spec, o, springs) in cases {
        let shape = crate::common::shape(spec).unwrap();
        let exact = evaluate(&shape, &o, DEFAULT_TOL).unwrap().ratio.mu_ratio;
        let err = |m: usize| {
            let st = Stepping { steps_per_period: m, springs };
            (evaluate_oscillation(&shape, &o, st, 3).unwrap().ratio.mu_ratio - exact).abs()
        };
        let (coarse, fine) = if springs == 1 { (err(4000), err(64000)) } else { (err(500), err(4000)) };
        assert!(fine < 2e-3, "{spec} {o:?}: stepping error {fine:e}");
        assert!(fine < 0.5 * coarse || fine < 1e-5, "{spec} {o:?}: {coarse:e} -> {fine:e} does not converge");
    }
}
