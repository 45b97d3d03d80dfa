//! Curved contacts in the plane (`Conditions::with_transverse` on a curved
//! shape): against the one-dimensional exact solver of a drive along a line
//! (a separate code: the stop operator's phases in closed form, its own
//! bands), rotated; against the plane's time stepper with springs,
//! extrapolated in its springs and steps; the symmetry that forbids a
//! force along the sliding direction; the estimate at every tolerance.
use fricosc::plane::Transverse;
use fricosc::stepper::{transverse, Stepping};
use fricosc::{Conditions, Evaluation, Shape};

fn plane(shape: &Shape, c: &Conditions, w: f64, psi: f64) -> Evaluation {
    shape.evaluate(&c.with_transverse(Transverse::new(w, psi).unwrap())).unwrap()
}

/// A drive along a line at an angle `alpha` (`vhat = 0`, both oscillations
/// in phase): the force stays on the line and is the one-dimensional
/// solver's, rotated, within the two estimates; the plane's estimate below
/// 1e-7 (observed errors 6e-15 to 9e-14, estimates 2.6 to 1,900 times
/// them; a spring whose own walk estimates 3e-5 puts `flat-tip:0.5` at
/// 1.8e-8). A wrong weight, level or normalisation of the springs is off
/// by 1e-3 and more. The reduction is `1 - mu_ratio` along `x`.
#[test]
fn a_drive_along_a_line_is_the_one_dimensional_answer_rotated() {
    for name in ["parabolic", "cone", "power:3", "flat-tip:0.5"] {
        let shape = Shape::parse(name).unwrap();
        for (amp, a, phase, alpha) in [(0.5, 2.0, 0.4, 0.3f64), (1.5, 1.5, 1.0, 1.1)] {
            let line = Conditions::vhat(0.0, amp).unwrap().with_tangential(a, phase).unwrap();
            let one = shape.evaluate(&line).unwrap();
            let (t, w) = (a * alpha.cos(), a * alpha.sin());
            let c = Conditions::vhat(0.0, amp).unwrap().with_tangential(t, phase).unwrap();
            let e = plane(&shape, &c, w, phase);
            let m = one.ratio.mu_ratio;
            let err =
                (e.ratio.mu_ratio - m * alpha.cos()).abs().max((e.transverse_ratio.unwrap() - m * alpha.sin()).abs());
            let est = e.error_estimate;
            assert!(err <= est + one.error_estimate && est < 1e-7, "{name} amp {amp}: error {err:e}, estimate {est:e}");
            // The reduction along `x`, `1 - m cos(alpha)` (absolute, as README says).
            let off = (e.ratio.reduction - (1.0 - m * alpha.cos())).abs();
            assert!(off <= est + one.error_estimate, "{name} amp {amp}: reduction off by {off:e}");
        }
    }
}

/// A drive along a line of amplitude 300: the springs at the cone's edge
/// would take over 5000 Taylor steps a period and are not walked (the tail:
/// the last walked spring's ratios times their normal force). Within the
/// two estimates of the rotated one-dimensional answer (observed 1.1e-16,
/// estimate 1.7e-14); without the tail's force along the line, 2.4e-6 off.
#[test]
fn the_springs_at_a_stiff_contacts_edge_are_the_tail() {
    let (shape, amp, a, phase, alpha) = (Shape::cone(), 0.5, 300.0, 0.4, 0.3f64);
    let one = shape.evaluate(&Conditions::vhat(0.0, amp).unwrap().with_tangential(a, phase).unwrap()).unwrap();
    let c = Conditions::vhat(0.0, amp).unwrap().with_tangential(a * alpha.cos(), phase).unwrap();
    let e = plane(&shape, &c, a * alpha.sin(), phase);
    let m = one.ratio.mu_ratio;
    let err = (e.ratio.mu_ratio - m * alpha.cos()).abs().max((e.transverse_ratio.unwrap() - m * alpha.sin()).abs());
    assert!(err <= e.error_estimate + one.error_estimate && e.error_estimate < 1e-12, "{err:e} {e:?}");
}

/// The estimate bounds the error at every tolerance: against the rotated
/// one-dimensional answer, at `tol` 1e-3, 1e-6, 1e-10 and the default.
#[test]
fn the_estimate_bounds_the_error_at_every_tolerance() {
    let (shape, amp, a, phase, alpha) = (Shape::cone(), 0.8, 3.0, 5.0, 2.5);
    let line = Conditions::vhat(0.0, amp).unwrap().with_tangential(a, phase).unwrap();
    let m = shape.evaluate(&line).unwrap().ratio.mu_ratio;
    let (t, w) = (a * f64::cos(alpha), a * f64::sin(alpha));
    let c = Conditions::vhat(0.0, amp).unwrap().with_tangential(t.abs(), phase + std::f64::consts::PI).unwrap();
    for tol in [1e-3, 1e-6, 1e-10, fricosc::DEFAULT_TOL] {
        let e = plane(&shape, &c.with_tol(tol).unwrap(), w, phase);
        let err = (e.ratio.mu_ratio - m * alpha.cos()).abs().max((e.transverse_ratio.unwrap() - m * alpha.sin()).abs());
        assert!(
            err <= e.error_estimate && e.error_estimate < tol.max(1e-9),
            "tol {tol:e}: {err:e} {:e}",
            e.error_estimate
        );
    }
}

/// Without sliding and without oscillation along the sliding direction
/// every spring's force stays across it: no force along `x`, to rounding.
#[test]
fn no_force_along_the_sliding_direction_without_a_drive_along_it() {
    for (name, amp, w, psi) in [("parabolic", 0.5, 1.2, 0.7), ("cone", 1.5, 0.8, 2.0)] {
        let e = plane(&Shape::parse(name).unwrap(), &Conditions::vhat(0.0, amp).unwrap(), w, psi);
        assert!(e.ratio.mu_ratio.abs() < 1e-15 && e.transverse_ratio.unwrap().abs() > 1e-3, "{name}: {e:?}");
    }
}

/// Sliding with an oscillation across it, without (`amp = 0`: the springs
/// at the contact's edge are the tail, their ratios the last walked one's)
/// and with normal oscillation: the plane's stepper with springs,
/// extrapolated in its steps (first order) and springs (second), meets the
/// exact values (observed 1e-8 and 4e-8, the stepper's own error 2e-5).
#[test]
fn the_plane_stepper_with_springs_converges_to_it() {
    let shape = Shape::parabolic();
    let tw = Transverse::new(1.0, 0.7).unwrap();
    for amp in [0.0, 0.5] {
        let c = Conditions::vhat(0.3, amp).unwrap();
        let e = plane(&shape, &c, 1.0, 0.7);
        let run = |n: usize, m: usize| {
            let r = transverse(&shape, &c, tw, Stepping { steps_per_period: m, springs: n }, 12).unwrap();
            [r.mu_ratio, r.transverse_ratio]
        };
        let (coarse, fine, finer) = (run(128, 10_000), run(256, 10_000), run(256, 20_000));
        let exact = [e.ratio.mu_ratio, e.transverse_ratio.unwrap()];
        for k in 0..2 {
            let extrapolated = 2.0 * finer[k] - fine[k] - (coarse[k] - fine[k]) / 3.0;
            let err = (extrapolated - exact[k]).abs();
            assert!(err < 2e-7, "amp {amp} component {k}: {err:e}");
        }
        assert!((finer[0] - exact[0]).abs() > 1e-6, "the stepping's own error is visible");
    }
}
