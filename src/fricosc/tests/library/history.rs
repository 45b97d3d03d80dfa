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
        let h = history(
            &Shape::flat(),
            &fricosc::Conditions::vbar(v, a).unwrap(),
            &HistoryOptions::default().with_samples(20000).with_springs(1),
        )
        .unwrap();
        for s in &h.samples {
            assert!(s.tangential <= s.normal + 1e-15 && s.tangential >= 0.0);
        }
        let t: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.tangential)).collect();
        let n: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.normal)).collect();
        let mu = crate::common::at::eval(&Shape::flat(), v, a).unwrap().ratio.mu_ratio;
        // Events are samples, so the trapezoid rule is second order on each smooth piece.
        assert!((mean(&t) / mean(&n) - mu).abs() < 1e-7, "v={v} a={a}: {} vs {mu}", mean(&t) / mean(&n));
    }
}

#[test]
fn mdr_history_averages_to_the_exact_mu() {
    let (v, a) = (0.3, 0.4);
    let h = history(
        &Shape::parabolic(),
        &fricosc::Conditions::vbar(v, a).unwrap(),
        &HistoryOptions::default().with_samples(2000).with_springs(4000).with_spring_at(vec![0.0, 1.1]),
    )
    .unwrap();
    let t: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.tangential)).collect();
    let n: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.normal)).collect();
    let mu = crate::common::at::eval(&Shape::parabolic(), v, a).unwrap().ratio.mu_ratio;
    assert!((mean(&t) / mean(&n) - mu).abs() < 1e-5, "{} vs {mu}", mean(&t) / mean(&n));
    // Chosen springs: the centre one is a flat punch with s = 1/amp; the outer one jumps.
    let c: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.springs[0][1])).collect();
    let cn: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.springs[0][0])).collect();
    let flat = crate::common::at::eval(&Shape::flat(), v, a).unwrap().ratio.mu_ratio;
    assert!((mean(&c) / mean(&cn) - flat).abs() < 1e-6);
    assert!(h.samples.iter().any(|s| s.springs[1][0] == 0.0), "the spring at 1.1 x_c loses contact");
}

/// The limit a request exceeds, with its count and limit, or `None`.
fn too_large(shape: &Shape, amp: f64, o: &HistoryOptions) -> Option<(u128, u128)> {
    match history(shape, &fricosc::Conditions::vbar(0.3, amp).unwrap(), o) {
        Err(fricosc::Error::TooLarge { count, limit, .. }) => Some((count, limit)),
        Err(e) => panic!("{e}"),
        Ok(_) => None,
    }
}

/// Every limit of the library's histories is checked before any work, with
/// the counts of README's limits table computed here on their own: rows =
/// samples + 1 (+ 4 events a period for the flat punch), chosen-spring values
/// = rows x positions, spring evaluations = rows x springs; and the builders
/// set what they name. (The command line's own tests go through the same
/// checks; these read them without it.)
#[test]
fn every_history_limit_is_enforced_with_its_count() {
    use fricosc::history::{MAX_SAMPLES, MAX_SPRINGS, MAX_SPRING_WORK};
    let o = HistoryOptions::default();
    assert_eq!(o.clone().with_periods(3).periods, 3);
    assert_eq!(o.clone().with_springs(7).springs, 7);
    assert_eq!(o.clone().with_samples(9).samples, 9);
    let (flat, para) = (Shape::flat(), Shape::parabolic());
    let max_rows = MAX_SAMPLES as u128;
    // Springs: the limit itself is accepted (and cheap at two rows), one more is not.
    let springs = |n: usize| o.clone().with_samples(1).with_springs(n);
    assert_eq!(too_large(&para, 0.5, &springs(MAX_SPRINGS)), None);
    assert_eq!(too_large(&para, 0.5, &springs(MAX_SPRINGS + 1)), Some((MAX_SPRINGS as u128 + 1, MAX_SPRINGS as u128)));
    // Rows of the flat punch: samples + 1 + 4 periods.
    let rows = o.clone().with_periods(3).with_samples(MAX_SAMPLES - 12).with_springs(1);
    assert_eq!(too_large(&flat, 0.5, &rows), Some((max_rows + 1, max_rows)));
    // Rows of a curved shape: samples + 1 (no events).
    let rows = o.clone().with_periods(3).with_samples(MAX_SAMPLES).with_springs(1);
    assert_eq!(too_large(&para, 0.5, &rows), Some((max_rows + 1, max_rows)));
    // Chosen-spring values: rows x positions.
    let chosen = o.clone().with_samples(999).with_springs(1).with_spring_at(vec![0.5; 10_001]);
    assert_eq!(too_large(&para, 0.5, &chosen), Some((1000 * 10_001, max_rows)));
    // Spring evaluations: rows x springs.
    let work = o.clone().with_samples(4001).with_springs(1_000_000);
    assert_eq!(too_large(&para, 0.5, &work), Some((4002 * 1_000_000, MAX_SPRING_WORK)));
}

/// The uniform samples lie at `2 pi periods j / samples`, events between them
/// (each period's the same, one period on);
/// a curved shape's amplitude is refused below 1e-300 (its springs' `s = (1 -
/// G)/amp` overflows) and where its normal force overflows, and accepted at 0.
#[test]
fn history_samples_and_the_curved_amplitudes_refused() {
    use fricosc::history::MIN_CURVED_AMP;
    let h = history(
        &Shape::flat(),
        &fricosc::Conditions::vbar(0.3, 0.5).unwrap(),
        &HistoryOptions::default().with_periods(2).with_samples(8),
    )
    .unwrap();
    let uniform: Vec<f64> = h.samples.iter().filter(|s| s.event.is_none()).map(|s| s.tau).collect();
    assert_eq!(uniform.len(), 9);
    for (j, tau) in uniform.iter().enumerate() {
        assert!((tau - 4.0 * std::f64::consts::PI * j as f64 / 8.0).abs() < 1e-14, "{j}: {tau}");
    }
    // The second period's events are the first's, one period on.
    let events: Vec<f64> = h.samples.iter().filter(|s| s.event.is_some()).map(|s| s.tau).collect();
    let half = events.len() / 2;
    assert!(half >= 2 && events.len() == 2 * half, "{events:?}");
    for k in 0..half {
        assert!((events[k + half] - events[k] - std::f64::consts::TAU).abs() < 1e-13, "{events:?}");
    }
    assert!(h.samples.iter().all(|s| (0.0..=4.0 * std::f64::consts::PI).contains(&s.tau)));
    let refused = |shape: &Shape, amp: f64| {
        matches!(
            history(shape, &fricosc::Conditions::vbar(0.3, amp).unwrap(), &HistoryOptions::default()),
            Err(fricosc::Error::InvalidParameter { .. })
        )
    };
    let para = Shape::parabolic();
    assert!(refused(&para, MIN_CURVED_AMP / 2.0));
    assert!(!refused(&para, MIN_CURVED_AMP));
    assert!(!refused(&para, 0.0));
    // Without oscillation every spring slides: the tangential force is the normal one,
    // for the contact and for a chosen spring.
    let still = history(
        &para,
        &fricosc::Conditions::vbar(0.3, 0.0).unwrap(),
        &HistoryOptions::default().with_samples(4).with_spring_at(vec![0.3]),
    )
    .unwrap();
    for s in &still.samples {
        assert_eq!(s.tangential, s.normal);
        assert_eq!(s.springs[0][1], s.springs[0][0]);
        assert!((s.springs[0][0] - 0.91).abs() < 1e-15);
    }
    // The flat punch has no such floor.
    assert!(!refused(&Shape::flat(), MIN_CURVED_AMP / 2.0));
    // power:0.05: the force grows as amp^(1 + 1/n) = amp^21, which overflows beyond ~1e14.
    let steep = Shape::power(0.05).unwrap();
    assert!(refused(&steep, 1e20));
    assert!(!refused(&steep, 1e10));
}

/// A chosen spring of the paraboloid at `x` (level `1 - x^2`) is the flat punch
/// at amplitude `amp/(1 - x^2)`, scaled by its level: its normal force is
/// `(1 - x^2 - amp cos tau)_+`, its tangential force at most that, and the
/// ratio of their period means the flat punch's `mu` (trapezoid rule, 20,000 samples).
#[test]
fn chosen_springs_are_flat_punches_at_their_level() {
    let (vbar, amp) = (0.3, 0.6);
    let xs = vec![0.0, 0.5, 0.8];
    let o = HistoryOptions::default().with_samples(20_000).with_springs(50).with_spring_at(xs.clone());
    let h = history(&Shape::parabolic(), &fricosc::Conditions::vbar(vbar, amp).unwrap(), &o).unwrap();
    assert_eq!(h.spring_positions, xs);
    for (k, &x) in xs.iter().enumerate() {
        let level = 1.0 - x * x;
        let mut n = vec![];
        let mut t = vec![];
        for s in &h.samples {
            let [nrm, tan] = s.springs[k];
            let exact = (level - amp * s.tau.cos()).max(0.0);
            assert!((nrm - exact).abs() < 1e-15, "x {x} tau {}: {nrm} vs {exact}", s.tau);
            assert!(tan <= nrm + 1e-15 && tan >= -1e-15, "x {x}: {tan} beyond {nrm}");
            n.push((s.tau, nrm));
            t.push((s.tau, tan));
        }
        let flat = crate::common::at::eval(&Shape::flat(), vbar, amp / level).unwrap().ratio.mu_ratio;
        assert!((mean(&t) / mean(&n) - flat).abs() < 1e-6, "x {x}: {} vs {flat}", mean(&t) / mean(&n));
    }
}

/// The seed's time stepping as a history: `periods x steps + 1` rows at
/// `tau = 2 pi k / steps`, the normal force the bound, the tangential force
/// within it, and the last period's means converging to the exact `mu`
/// (1.9e-8 at 2,000 steps a period, 5.2e-9 at 4,000);
/// refused without oscillation, with zero periods or steps, and beyond the row
/// limit with its count.
#[test]
fn the_stepped_history_converges_to_the_exact_mu() {
    use fricosc::history::{stepped_history, MAX_SAMPLES};
    let (vbar, amp) = (0.3, 0.5);
    let mu = crate::common::at::eval(&Shape::flat(), vbar, amp).unwrap().ratio.mu_ratio;
    let err = |steps: usize| {
        let h = stepped_history(&fricosc::Conditions::vbar(vbar, amp).unwrap(), 3, steps).unwrap();
        assert_eq!(h.samples.len(), 3 * steps + 1);
        for (k, s) in h.samples.iter().enumerate() {
            let tau = std::f64::consts::TAU * k as f64 / steps as f64;
            assert!((s.tau - tau).abs() < 1e-12, "{k}: {} vs {tau}", s.tau);
            assert!((s.normal - (1.0 - amp * s.tau.cos())).abs() < 1e-15);
            assert!(s.tangential <= s.normal + 1e-15, "{k}: {} beyond {}", s.tangential, s.normal);
        }
        let last = &h.samples[2 * steps..];
        let t: Vec<(f64, f64)> = last.iter().map(|s| (s.tau, s.tangential)).collect();
        let n: Vec<(f64, f64)> = last.iter().map(|s| (s.tau, s.normal)).collect();
        mean(&t) / mean(&n) - mu
    };
    let (e1, e2) = (err(2000), err(4000));
    // Observed 1.9e-8 and -5.2e-9: the scheme and the trapezoid rule converge together.
    assert!(e1.abs() < 2e-7 && e2.abs() < 5e-8 && e2.abs() < e1.abs(), "{e1:e} then {e2:e}");
    assert!(stepped_history(&fricosc::Conditions::vbar(vbar, 0.0).unwrap(), 3, 100).is_err());
    assert!(stepped_history(&fricosc::Conditions::vbar(vbar, amp).unwrap(), 0, 100).is_err());
    assert!(stepped_history(&fricosc::Conditions::vbar(vbar, amp).unwrap(), 3, 0).is_err());
    match stepped_history(&fricosc::Conditions::vbar(vbar, amp).unwrap(), 10, MAX_SAMPLES / 10) {
        Err(fricosc::Error::TooLarge { count, limit, .. }) => {
            assert_eq!((count, limit), (MAX_SAMPLES as u128 + 1, MAX_SAMPLES as u128))
        }
        other => panic!("{other:?}"),
    }
}

/// Under a tangential oscillation the flat punch's history is the stop
/// operator's phases: against the same problem stepped (`stepped_history`: the
/// force moved with the body and held in `[-B, B]` step by step, no phases and
/// no events) within its first-order error, and its trapezoidal mean over the
/// samples (events included) is the solver's `mu` from its closed-form means.
/// Points: both slip directions (a), contact loss (b), no normal oscillation
/// (c), the body always forward (d).
#[test]
fn a_combined_history_agrees_with_time_stepping_and_with_mu() {
    use fricosc::history::stepped_history;
    let steps = 100_000;
    // Each with ten times the stepper's largest difference at 10^5 steps a
    // period (5.9e-10, 2.0e-5 with contact loss, 2.2e-11, 6.2e-15).
    let cases = [
        (0.2, 0.5, 1.5, 1.3, 6e-9),
        (0.6, 2.0, 3.0, 1.0, 2e-4),
        (0.05, 0.0, 1.0, 0.0, 2e-10),
        (2.0, 1.5, 0.5, 4.0, 6e-14),
    ];
    for (v, a, t, p, bar) in cases {
        let c = fricosc::Conditions::vhat(v, a).unwrap().with_tangential(t, p).unwrap();
        let h = history(&Shape::flat(), &c, &HistoryOptions::default().with_samples(steps)).unwrap();
        let tn: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.tangential)).collect();
        let nn: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.normal)).collect();
        let mu = Shape::flat().ratio(&c).unwrap().mu_ratio;
        assert!((mean(&tn) / mean(&nn) - mu).abs() < 1e-9, "{c:?}: {} vs {mu}", mean(&tn) / mean(&nn));
        let stepped = stepped_history(&c, 3, steps).unwrap();
        let uniform: Vec<f64> = h.samples.iter().filter(|s| s.event.is_none()).map(|s| s.tangential).collect();
        let last = &stepped.samples[2 * steps..];
        let worst = uniform.iter().zip(last).map(|(x, s)| (x - s.tangential).abs()).fold(0.0, f64::max);
        assert!(worst < bar, "{c:?}: {worst}");
        // The force never leaves its bound, and slips both ways where T is large enough.
        assert!(h.samples.iter().all(|s| s.tangential.abs() <= s.normal));
    }
}

/// A curved contact under a tangential oscillation: the grid's trapezoidal
/// mean is the solver's `mu` (second order in the springs' spacing and the samples).
#[test]
fn a_curved_combined_history_averages_to_the_exact_mu() {
    let c = fricosc::Conditions::vhat(0.2, 0.5).unwrap().with_tangential(1.5, 1.3).unwrap();
    let o = HistoryOptions::default().with_samples(2000).with_springs(4000).with_spring_at(vec![0.0]);
    let h = history(&Shape::parabolic(), &c, &o).unwrap();
    let t: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.tangential)).collect();
    let n: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.normal)).collect();
    let mu = Shape::parabolic().ratio(&c).unwrap().mu_ratio;
    // 5.3e-9 off at 4000 springs and 2000 samples.
    assert!((mean(&t) / mean(&n) - mu).abs() < 5e-8, "{} vs {mu}", mean(&t) / mean(&n));
    // The centre spring is a flat punch of the same drive.
    let centre: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.springs[0][1])).collect();
    let centre_n: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, s.springs[0][0])).collect();
    let flat = Shape::flat().ratio(&c).unwrap().mu_ratio;
    assert!((mean(&centre) / mean(&centre_n) - flat).abs() < 1e-6);
    assert_eq!(h.point.in_plane.tangential_amp, Some(1.5));
}

/// On a system with mass and stiffness the history is one period of the
/// attractor: its trapezoidal mean (the period closed by its first sample,
/// events included) is the attractor's `mu`, the force within its bound;
/// a massless body's is the stiff one at the scaled drive.
#[test]
fn a_history_on_a_system_averages_to_its_mu() {
    use crate::common::on_system as solve;
    use fricosc::system::System;
    for (om, amp) in [(0.5, 0.5), (0.5, 1.5), (1.2, 0.5)] {
        let c = fricosc::Conditions::vhat(0.3, amp).unwrap();
        let sys = System::new(1.0, om, 0.3).unwrap();
        let h = history(&Shape::flat(), &c.with_system(sys), &HistoryOptions::default().with_samples(20_000)).unwrap();
        let close = |f: fn(&fricosc::history::Sample) -> f64| {
            let mut v: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, f(s))).collect();
            v.push((std::f64::consts::TAU, v[0].1));
            v
        };
        let mu = mean(&close(|s| s.tangential)) / mean(&close(|s| s.normal));
        let exact = solve(&Shape::flat(), &c, &sys).unwrap().mu_ratio;
        assert!((mu - exact).abs() < 1e-7, "Omega {om} amp {amp}: {mu} vs {exact}");
        assert!(h.samples.iter().all(|s| s.tangential.abs() <= s.normal));
    }
    let c = fricosc::Conditions::vhat(0.3, 0.5).unwrap();
    let massless = HistoryOptions::default().with_samples(50);
    let stiff = history(
        &Shape::flat(),
        &fricosc::Conditions::vhat(0.15, 0.5).unwrap().with_tangential(0.0, 0.0).unwrap(),
        &HistoryOptions::default().with_samples(50),
    )
    .unwrap();
    let h = history(&Shape::flat(), &c.with_system(System::new(1.0, 0.0, 0.0).unwrap()), &massless).unwrap();
    assert!(h.samples.iter().zip(&stiff.samples).all(|(a, b)| a.tangential == b.tangential));
}

/// A curved body's history on a system is one period of its springs'
/// attractor: its trapezoidal mean is that discretisation's `mu` (the
/// springs' own events are not samples: the trapezoid's error is second
/// order: 3.1e-10 and 7.3e-10 at 20,000 samples), the force within its bound.
#[test]
fn a_curved_history_on_a_system_averages_to_its_springs_mu() {
    use fricosc::system::{solve_discretised, System};
    for (shape, amp) in [(Shape::parabolic(), 0.5), (Shape::cone(), 1.5)] {
        let c = fricosc::Conditions::vhat(0.3, amp).unwrap();
        let sys = System::new(1.0, 0.5, 0.3).unwrap().with_springs(64).unwrap();
        let h = history(&shape, &c.with_system(sys), &HistoryOptions::default().with_samples(20_000)).unwrap();
        let close = |f: fn(&fricosc::history::Sample) -> f64| {
            let mut v: Vec<(f64, f64)> = h.samples.iter().map(|s| (s.tau, f(s))).collect();
            v.push((std::f64::consts::TAU, v[0].1));
            v
        };
        let mu = mean(&close(|s| s.tangential)) / mean(&close(|s| s.normal));
        let exact = solve_discretised(&shape, &c.with_system(sys), 64).unwrap().mu_ratio;
        assert!((mu - exact).abs() < 1e-7, "{} amp {amp}: {mu} vs {exact}", shape.name());
        let excess = h.samples.iter().map(|s| s.tangential.abs() - s.normal).fold(f64::MIN, f64::max);
        // Rounding of a sum of 64 springs (observed 1.0e-14).
        assert!(excess <= 1e-13, "{} amp {amp}: above the bound by {excess:e}", shape.name());
    }
}

/// The body on a system in a history obeys its own equation: with the
/// samples equally spaced (the flat punch's events are extra samples: they
/// are left out), `Omega^2 x''` by central differences of the velocity is the
/// system's force less the contact's (to the differences' error, of order
/// `h` where a stick ends and `x'''` jumps: observed 2.8e-5 and 4.7e-5 at
/// 20,000 samples), and over the period the body moves at the drive's mean
/// velocity (observed 1.6e-13) and the system's force averages to the
/// contact's (5.3e-10).
/// A lag, velocity or force taken at the wrong phase, or without the drive's
/// oscillation, is off by 1e-2 and more.
#[test]
fn a_body_on_a_system_obeys_its_equation() {
    use fricosc::system::System;
    for (shape, t, zeta) in [(Shape::flat(), 0.0, 0.05), (Shape::flat(), 0.8, 0.3), (Shape::parabolic(), 0.0, 0.05)] {
        let c = fricosc::Conditions::vhat(0.3, 0.5).unwrap().with_tangential(t, 0.7).unwrap();
        let sys = System::new(1.0, 0.5, zeta).unwrap().with_springs(64).unwrap();
        let n = 20_000;
        let h = history(&shape, &c.with_system(sys), &HistoryOptions::default().with_samples(n)).unwrap();
        let even: Vec<&fricosc::history::Sample> = h.samples.iter().filter(|s| s.event.is_none()).collect();
        assert_eq!(even.len(), n);
        let body = |s: &fricosc::history::Sample| s.body.unwrap();
        // A curved body's forces are per the normal force at the mean
        // indentation, not the body's: its equation holds up to that scale,
        // its means exactly.
        let step = std::f64::consts::TAU / n as f64;
        let mut worst: f64 = 0.0;
        for w in even.windows(3).filter(|_| shape.is_flat()) {
            let accel = (body(w[2]).body_velocity - body(w[0]).body_velocity) / (2.0 * step);
            worst = worst.max((0.25 * accel - (body(w[1]).system_force - w[1].tangential)).abs());
        }
        assert!(worst < 1e-4, "{} T {t}: {worst:e}", shape.name());
        let avg = |f: &dyn Fn(&fricosc::history::Sample) -> f64| even.iter().map(|s| f(s)).sum::<f64>() / n as f64;
        assert!((avg(&|s| body(s).body_velocity) - 0.3).abs() < 1e-11, "{}", shape.name());
        assert!((avg(&|s| body(s).system_force) - avg(&|s| s.tangential)).abs() < 5e-9, "{}", shape.name());
    }
}
