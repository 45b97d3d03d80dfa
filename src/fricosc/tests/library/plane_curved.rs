//! Curved contacts in the plane (`Conditions::with_transverse` on a curved
//! shape): against the one-dimensional exact solver of a drive along a line
//! (a separate code: the stop operator's phases in closed form, its own
//! bands), rotated; against the plane's time stepper with springs,
//! extrapolated in its springs and steps; the symmetry that forbids a
//! force along the sliding direction; the estimate at every tolerance, over
//! an undeclared kink of the profile, and with the springs' rounding; the
//! invariance under the contact's unit of length.
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
/// two estimates of the rotated one-dimensional answer at the default
/// tolerance (observed 1.1e-16, estimate 1.7e-14; without the tail's force
/// along the line, 2.4e-6 off), and at `tol` 1e-3 and 1e-5 (observed 2e-10
/// and 7e-13), where the largest parts of the estimate are the tail's error
/// (2.3e-5 of 2.3e-5) and the coarse springs' own (1.7e-7 of 1.7e-7).
#[test]
fn the_springs_at_a_stiff_contacts_edge_are_the_tail() {
    let (shape, amp, a, phase, alpha) = (Shape::cone(), 0.5, 300.0, 0.4, 0.3f64);
    let one = shape.evaluate(&Conditions::vhat(0.0, amp).unwrap().with_tangential(a, phase).unwrap()).unwrap();
    let c = Conditions::vhat(0.0, amp).unwrap().with_tangential(a * alpha.cos(), phase).unwrap();
    for tol in [1e-3, 1e-5, fricosc::DEFAULT_TOL] {
        let e = plane(&shape, &c.with_tol(tol).unwrap(), a * alpha.sin(), phase);
        let m = one.ratio.mu_ratio;
        let err = (e.ratio.mu_ratio - m * alpha.cos()).abs().max((e.transverse_ratio.unwrap() - m * alpha.sin()).abs());
        let est = e.error_estimate;
        assert!(err <= est + one.error_estimate && est < tol.max(1e-12), "tol {tol:e}: {err:e} {e:?}");
    }
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

/// The paraboloid's profile stretched along `z` by `s` (`G(z/s)`: the same
/// contact in another unit of length): every spring and every force of it
/// scaled by `s`.
#[derive(Debug)]
struct Stretched(f64);

impl fricosc::contact::Contact for Stretched {
    fn name(&self) -> String {
        format!("paraboloid stretched by {}", self.0)
    }
    fn equivalent_profile(&self, z: f64) -> f64 {
        (z / self.0).powi(2)
    }
    fn reach(&self, amp: f64) -> fricosc::Result<f64> {
        Ok(self.0 * (1.0 + amp).sqrt())
    }
    fn static_force(&self, depth: f64) -> f64 {
        self.0 * 4.0 / 3.0 * depth.max(0.0).powf(1.5)
    }
}

/// A contact's unit of length is no input: stretched along `z` by a power
/// of two (its nodes, edges and springs scaled exactly), the answer and its
/// estimate are the unstretched one's, bit for bit, at a loose and at the
/// default tolerance. A share of the tolerance, a resolution or a rounding
/// taken in absolute units of `z` or of force would move them.
#[test]
fn a_contact_stretched_along_z_gives_the_same_answer() {
    let shape = |s: f64| Shape::from_contact(std::sync::Arc::new(Stretched(s)));
    for tol in [1e-6, fricosc::DEFAULT_TOL] {
        let c = Conditions::vhat(0.3, 0.5).unwrap().with_tol(tol).unwrap();
        let one = plane(&shape(1.0), &c, 1.2, 0.7);
        for s in [0.5f64.powi(10), 2.0f64.powi(10)] {
            let e = plane(&shape(s), &c, 1.2, 0.7);
            let same = [e.ratio.mu_ratio, e.transverse_ratio.unwrap(), e.error_estimate]
                == [one.ratio.mu_ratio, one.transverse_ratio.unwrap(), one.error_estimate];
            assert!(same, "tol {tol:e}, s {s}: {e:?} against {one:?}");
        }
    }
}

/// A paraboloid whose profile goes on straight from `z = 1/2` with its
/// slope jumping from 1 to 3/2 (`G(1) = 1`); `declared`: the kink is one of
/// its [`fricosc::contact::Contact::breakpoints`].
#[derive(Debug)]
struct Kinked {
    declared: bool,
}

impl fricosc::contact::Contact for Kinked {
    fn name(&self) -> String {
        format!("kinked paraboloid (declared: {})", self.declared)
    }
    fn equivalent_profile(&self, z: f64) -> f64 {
        if z <= 0.5 {
            z * z
        } else {
            0.25 + 1.5 * (z - 0.5)
        }
    }
    fn reach(&self, amp: f64) -> fricosc::Result<f64> {
        Ok(0.5 + (0.75 + amp) / 1.5)
    }
    /// `2 int (d - G)_+ dz`: `(4/3) d^1.5` up to `d = 1/4`, then `2 (d/2 -
    /// 1/24 + (d - 1/4)^2/3)`.
    fn static_force(&self, d: f64) -> f64 {
        if d <= 0.25 {
            4.0 / 3.0 * d.max(0.0).powf(1.5)
        } else {
            2.0 * (0.5 * d - 1.0 / 24.0 + (d - 0.25).powi(2) / 3.0)
        }
    }
    fn breakpoints(&self) -> Vec<f64> {
        if self.declared {
            vec![0.5]
        } else {
            vec![]
        }
    }
}

/// A kink of the profile that the contact does not declare lies inside a
/// band, where the springs' means have a kink too and the order ladder
/// converges like a power of its order: its last difference, part of the
/// estimate, still bounds the error (against the declared kink at the
/// default tolerance; observed 5.7e-5, 1.1e-7 and 1.9e-8 at `tol` 1e-4,
/// 1e-6 and 1e-8, estimates 4x, 43x and 26x that: the ladder stops at its
/// highest order), which the rest of the estimate alone would not (3e-9 at
/// 1e-4).
#[test]
fn an_undeclared_kink_stays_within_the_estimate() {
    let shape = |declared| Shape::from_contact(std::sync::Arc::new(Kinked { declared }));
    let c = Conditions::vhat(0.3, 0.5).unwrap();
    let exact = plane(&shape(true), &c, 1.2, 0.7);
    for tol in [1e-4, 1e-6, 1e-8] {
        let e = plane(&shape(false), &c.with_tol(tol).unwrap(), 1.2, 0.7);
        let err = (e.ratio.mu_ratio - exact.ratio.mu_ratio)
            .abs()
            .max((e.transverse_ratio.unwrap() - exact.transverse_ratio.unwrap()).abs());
        assert!(err <= e.error_estimate + exact.error_estimate, "tol {tol:e}: {err:e} {e:?}");
    }
}

/// The estimate holds the springs' rounding, `8 eps` of each spring's
/// largest bound `level + amp` integrated over the springs, over the mean
/// normal force: at amp 5, where most springs touch for part of the period
/// only (their level below 0), at least `8 eps int_0^1 (6 - z^2) dz / <N>`
/// with the mean normal force `<N> = (1/pi) int (2/3) (1 - 5 cos tau)_+^1.5
/// dtau` (the paraboloid's `int (d - z^2)_+ dz`; midpoints; 3.0213 by
/// mpmath): 3.3e-15. Observed 4.0 times it; with `|level| - amp` as a
/// spring's scale the estimate was negative.
#[test]
fn the_estimate_holds_the_springs_rounding() {
    let amp = 5.0;
    let e = plane(&Shape::parabolic(), &Conditions::vhat(0.3, amp).unwrap(), 1.2, 0.7);
    let (n, start) = (100_000, (1.0 / amp).acos());
    let window = std::f64::consts::PI - start;
    let normal = (0..n)
        .map(|i| {
            let tau = start + window * (i as f64 + 0.5) / n as f64;
            2.0 / 3.0 * (1.0 - amp * tau.cos()).max(0.0).powf(1.5)
        })
        .sum::<f64>()
        * window
        / n as f64
        / std::f64::consts::PI;
    assert!((normal - 3.0213).abs() < 1e-4, "{normal}");
    let floor = 8.0 * f64::EPSILON * (amp + 1.0 - 1.0 / 3.0) / normal;
    assert!(e.error_estimate >= floor, "{:e} below {floor:e}", e.error_estimate);
}
