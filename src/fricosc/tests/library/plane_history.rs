//! Histories in the plane (`history` under
//! `Conditions::with_transverse`): against the one-dimensional exact history
//! of a drive along a line (rotated), against the plane's own period means
//! (`mu_ratio`, `transverse_ratio`, from the series' integrals, not from the
//! samples), and its refusals.
use fricosc::history::{history, stepped_history, History, HistoryOptions};
use fricosc::plane::Transverse;
use fricosc::{Conditions, Shape};

fn in_plane(c: &Conditions, w: f64, psi: f64, samples: usize) -> History {
    let c = c.with_transverse(Transverse::new(w, psi).unwrap());
    history(&Shape::flat(), &c, &HistoryOptions::default().with_samples(samples)).unwrap()
}

/// Period mean by the trapezoid rule on the (uniform plus event) samples.
fn mean(h: &History, f: impl Fn(&fricosc::history::Sample) -> f64) -> f64 {
    let s = &h.samples;
    let area: f64 = s.windows(2).map(|w| 0.5 * (w[1].tau - w[0].tau) * (f(&w[0]) + f(&w[1]))).sum();
    area / (s[s.len() - 1].tau - s[0].tau)
}

/// A drive along one line at an angle `alpha` (`vhat = 0`, both
/// oscillations in phase): at every sample the force is the
/// one-dimensional history's (the stop operator's phases), rotated, to a
/// few ulp of the bound; contact loss included (`amp = 1.5`). A swapped
/// axis, a sign, or a resumed walk that forgets its phase is off by the
/// bound.
#[test]
fn a_drive_along_a_line_is_the_one_dimensional_history_rotated() {
    for (amp, a, phase, alpha) in [(0.5, 2.0, 0.4, 0.3), (1.5, 1.5, 1.0, 1.1), (0.8, 3.0, 5.0, 2.5)] {
        let (t, w) = (a * f64::cos(alpha), a * f64::sin(alpha));
        let one_d = Conditions::vhat(0.0, amp).unwrap().with_tangential(a, phase).unwrap();
        let one = history(&Shape::flat(), &one_d, &HistoryOptions::default().with_samples(400)).unwrap();
        let (t, phase_t) = (t.abs(), if t < 0.0 { phase + std::f64::consts::PI } else { phase });
        let c = Conditions::vhat(0.0, amp).unwrap().with_tangential(t, phase_t).unwrap();
        let h = in_plane(&c, w, phase, 400);
        let uniform = |h: &History| h.samples.iter().filter(|s| s.event.is_none()).cloned().collect::<Vec<_>>();
        let (p, q) = (uniform(&h), uniform(&one));
        assert_eq!(p.len(), 401);
        assert_eq!(p.len(), q.len());
        for (s, r) in p.iter().zip(&q) {
            assert_eq!(s.tau, r.tau);
            let f = r.tangential;
            let err = (s.tangential - f * alpha.cos()).abs().max((s.transverse.unwrap() - f * alpha.sin()).abs());
            let scale = 1f64.max(s.normal);
            assert!(err <= 16.0 * f64::EPSILON * scale, "amp {amp} tau {}: {s:?} against {f}: {err:e}", s.tau);
            assert!((s.normal - r.normal).abs() <= 4.0 * f64::EPSILON * scale, "{s:?} {r:?}");
        }
    }
}

/// Under all three oscillations, with and without contact loss: the force
/// stays in its disc, the events are the point's (the orbit's), and the
/// samples' trapezoidal means are the point's ratios (events among the
/// samples: second order on each smooth piece, 20,000 samples), over two
/// periods as over one.
#[test]
fn a_history_in_the_plane_averages_to_its_ratios() {
    for (vhat, amp, t, phase, w, psi) in [(0.3, 0.5, 0.4, 0.2, 1.0, 0.7), (0.2, 1.4, 0.0, 0.0, 0.8, 2.0)] {
        let c = Conditions::vhat(vhat, amp).unwrap();
        let c = if t > 0.0 { c.with_tangential(t, phase).unwrap() } else { c };
        let at = c.with_transverse(Transverse::new(w, psi).unwrap());
        let e = Shape::flat().evaluate(&at).unwrap();
        let o = HistoryOptions::default().with_samples(40_000).with_periods(2);
        let h = history(&Shape::flat(), &at, &o).unwrap();
        let across = |s: &fricosc::history::Sample| s.transverse.unwrap();
        let (fx, fy, b) = (mean(&h, |s| s.tangential), mean(&h, across), mean(&h, |s| s.normal));
        let (mx, my) = (e.ratio.mu_ratio, e.transverse_ratio.unwrap());
        assert!(
            (fx / b - mx).abs() < 1e-7 && (fy / b - my).abs() < 1e-7,
            "{c:?}: {} {} against {mx} {my}",
            fx / b,
            fy / b
        );
        assert!(h.samples.iter().all(|s| s.tangential.hypot(across(s)) <= s.normal * (1.0 + 4.0 * f64::EPSILON)));
        let events: Vec<f64> = h.samples.iter().filter(|s| s.event.is_some()).map(|s| s.tau).collect();
        let Ok(fricosc::Report::Plane(r)) = Shape::flat().report(&at) else { panic!("not a plane report") };
        let want: Vec<f64> =
            (0..2).flat_map(|p| r.events.iter().map(move |e| e.tau + std::f64::consts::TAU * p as f64)).collect();
        assert_eq!(events, want);
        assert!(h.point.to_string().ends_with(&format!("W {w}, psi {psi}")), "{}", h.point);
    }
}

/// A curved contact's history in the plane sums its springs on a uniform
/// grid (as under the other oscillations): its period means are the point's
/// ratios (bands and Gauss-Legendre, estimates near 1e-14) to the grid's and
/// the trapezoid's errors (ten times the larger of the two observed at 1000
/// springs, second order: the cone's was 9.3e-9 at 4000). At `vhat = W = 20` the
/// springs at the contact's edge, whose periods would take over 5000 Taylor
/// steps, slip as the rigid body does: taken so from the first spring whose
/// bound touches zero (where a count of steps also exceeds it, though its
/// bound is of order 1), the means were 2.7e-7 off.
#[test]
fn a_curved_history_in_the_plane_averages_to_the_points_ratios() {
    for (shape, vhat, amp, w, psi, observed) in [
        (Shape::parabolic(), 0.2, 1.5, 0.7, 1.0, 1.6e-9),
        (Shape::cone(), 0.3, 0.5, 1.0, 0.0, 1.5e-7),
        (Shape::parabolic(), 20.0, 0.5, 20.0, 0.0, 9.8e-9),
    ] {
        let at = Conditions::vhat(vhat, amp).unwrap().with_transverse(Transverse::new(w, psi).unwrap());
        let e = shape.evaluate(&at).unwrap();
        let h = history(&shape, &at, &HistoryOptions::default().with_samples(1024).with_springs(1000)).unwrap();
        assert!(h.samples.iter().all(|s| s.event.is_none()));
        let (fx, fy, b) = (mean(&h, |s| s.tangential), mean(&h, |s| s.transverse.unwrap()), mean(&h, |s| s.normal));
        let (dx, dy) = (fx / b - e.ratio.mu_ratio, fy / b - e.transverse_ratio.unwrap());
        assert!(dx.abs().max(dy.abs()) < 10.0 * observed, "{} {vhat} {amp} {w}: {dx:e} {dy:e}", shape.name());
    }
}

/// Along a line (`vhat = 0`, both oscillations in phase) a curved
/// contact's history in the plane is the one-dimensional history of the
/// same grid of springs rotated: the stop operator's phases against the
/// walk's Taylor series, spring by spring, summed in the same order.
#[test]
fn a_curved_drive_along_a_line_is_the_one_dimensional_history_rotated() {
    let (amp, a, phase, alpha) = (0.8, 2.0, 0.4, 0.6);
    let (t, w) = (a * f64::cos(alpha), a * f64::sin(alpha));
    let o = HistoryOptions::default().with_samples(200).with_springs(500);
    for shape in [Shape::parabolic(), Shape::cone()] {
        let one_d = Conditions::vhat(0.0, amp).unwrap().with_tangential(a, phase).unwrap();
        let one = history(&shape, &one_d, &o).unwrap();
        let c = Conditions::vhat(0.0, amp).unwrap().with_tangential(t, phase).unwrap();
        let h = history(&shape, &c.with_transverse(Transverse::new(w, phase).unwrap()), &o).unwrap();
        let worst = h.samples.iter().zip(&one.samples).map(|(p, q)| {
            assert_eq!((p.tau, p.normal), (q.tau, q.normal));
            let (x, y) = (q.tangential * alpha.cos(), q.tangential * alpha.sin());
            (p.tangential - x).abs().max((p.transverse.unwrap() - y).abs())
        });
        // 3.6e-15 observed (the bound's scale is 1).
        assert!(worst.fold(0.0, f64::max) < 4e-14, "{}", shape.name());
    }
}

/// What the plane does not solve is refused by name before any work: chosen
/// springs, more springs than a history in the plane sums, a system, the
/// stepped history.
#[test]
fn a_history_in_the_plane_refuses_what_it_does_not_solve() {
    let c = Conditions::vhat(0.3, 0.5).unwrap().with_transverse(Transverse::new(1.0, 0.0).unwrap());
    let o = HistoryOptions::default();
    let chosen = history(&Shape::parabolic(), &c, &o.clone().with_spring_at(vec![0.5])).unwrap_err().to_string();
    assert!(chosen.contains("spring-at"), "{chosen}");
    let many = fricosc::history::MAX_PLANE_SPRINGS + 1;
    let err = history(&Shape::cone(), &c, &o.clone().with_springs(many)).unwrap_err();
    assert!(matches!(err, fricosc::Error::TooLarge { count, .. } if count == many as u128), "{err}");
    let sys = fricosc::system::System::new(1.0, 0.5, 0.05).unwrap();
    let on_system = history(&Shape::flat(), &c.with_system(sys), &o).unwrap_err().to_string();
    assert!(on_system.contains("system-stiffness"), "{on_system}");
    let stepped = stepped_history(&c, 1, 1000).unwrap_err().to_string();
    assert!(stepped.contains("transverse-amp"), "{stepped}");
}

/// `compare_history` in the plane: the exact history (the flat punch's and
/// a cone's, whose grid is the reference's) passes with both forces within
/// a few ulp; the column across with conditions along a line is refused
/// naming it; the flat punch's forces 10 % above the circle are named above
/// the bound (the magnitude, not the force along, against `B`); without the
/// column across only the force along is compared and no events are sought.
#[test]
fn a_history_in_the_plane_is_validated_with_its_force_across() {
    use fricosc::validation::{compare_history, FindingKind, HistoryData, TimeAxis};
    let c = Conditions::vhat(0.2, 1.4).unwrap().with_transverse(Transverse::new(0.8, 2.0).unwrap());
    for (shape, events) in [(Shape::flat(), 3), (Shape::cone(), 0)] {
        let o = HistoryOptions::default().with_periods(2).with_samples(400);
        let h = history(&shape, &c, &o).unwrap();
        let col = |f: fn(&fricosc::history::Sample) -> f64| h.samples.iter().map(f).collect::<Vec<f64>>();
        let (tau, n, fx, fy) =
            (col(|s| s.tau), col(|s| s.normal), col(|s| s.tangential), col(|s| s.transverse.unwrap()));
        let data = HistoryData {
            time: TimeAxis::Phase(&tau),
            tangential: &fx,
            normal: Some(&n),
            transverse: Some(&fy),
            body: None,
        };
        let v = compare_history(&shape, &c, &data, 1e-9).unwrap();
        let across = v.transverse.unwrap().max_abs_error;
        assert!(v.findings.is_empty() && v.max_abs_error < 1e-14 && across < 1e-14, "{}: {v:?}", shape.name());
        // Each exact event found within a sample's spacing (a contact that
        // starts in stick is found as contact and stick, the orbit's as contact).
        assert_eq!(v.exact_events.len(), events, "{}", shape.name());
        for e in &v.exact_events {
            let timing = v.events.iter().filter(|f| f.kind == e.kind).filter_map(|f| f.timing_error);
            assert!(timing.map(f64::abs).fold(f64::INFINITY, f64::min) < 0.032, "{e:?} in {:?}", v.events);
        }
        let err = compare_history(&shape, &Conditions::vhat(0.2, 1.4).unwrap(), &data, 1e-9).unwrap_err().to_string();
        assert!(err.contains("transverse") && err.contains("--transverse-amp"), "{err}");
        if !shape.is_flat() {
            continue;
        }
        let (gx, gy): (Vec<f64>, Vec<f64>) = fx.iter().zip(&fy).map(|(x, y)| (1.1 * x, 1.1 * y)).unzip();
        let over = HistoryData { tangential: &gx, transverse: Some(&gy), ..data };
        let v = compare_history(&shape, &c, &over, 1e-9).unwrap();
        assert!(v.findings.iter().any(|f| f.kind == FindingKind::AboveBound), "{}: {:?}", shape.name(), v.findings);
        let along = compare_history(&shape, &c, &HistoryData { transverse: None, ..data }, 1e-9).unwrap();
        assert!(along.findings.is_empty() && along.transverse.is_none() && along.events.is_empty(), "{along:?}");
    }
}
