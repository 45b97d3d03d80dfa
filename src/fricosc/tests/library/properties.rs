//! Properties over random inputs (proptest), each against something the
//! library did not compute.

use crate::common::at::flat_ratio as ratio;
use crate::common::spring_ref::flat_mu;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// The flat punch against the seed's construction of its spring, written
    /// out independently (bisection on the plain gap, elementary means): they
    /// agree to the construction's own accuracy (bisection to 1e-16 in the
    /// stick length, whose error the mean feels only to second order).
    #[test]
    fn the_flat_punch_is_the_seeds_construction(v in 0.0f64..1.5, a in 0.0f64..20.0) {
        let r = ratio(v, a).unwrap();
        let reference = flat_mu(v, a);
        prop_assert!((r.mu_ratio - reference).abs() <= 2e-13, "v={} a={}: {} vs {}", v, a, r.mu_ratio, reference);
    }

    /// Friction never falls as the sliding velocity grows: a property of the
    /// model (a faster drive shortens every stick), not of the code's form.
    #[test]
    fn mu_ratio_is_nondecreasing_in_vbar(v in 0.0f64..1.2, dv in 0.0f64..0.3, a in 0.0f64..20.0) {
        let lo = ratio(v, a).unwrap().mu_ratio;
        let hi = ratio(v + dv, a).unwrap().mu_ratio;
        prop_assert!(hi >= lo - 4.0 * f64::EPSILON, "v={} dv={} a={}: {} > {}", v, dv, a, lo, hi);
    }

    /// Without contact loss (amp <= 1) the reduction is amp times a deficit of
    /// vbar alone (eq. 14), so reduction/amp is the same at two amplitudes, to
    /// rounding; where mu is the small one it is computed from the tangential
    /// force instead, and this checks the two forms against each other.
    #[test]
    fn the_reduction_is_linear_in_the_amplitude_without_contact_loss(v in 0.0f64..0.999, a in 0.01f64..1.0, b in 0.01f64..1.0) {
        let (ra, rb) = (ratio(v, a).unwrap().reduction / a, ratio(v, b).unwrap().reduction / b);
        prop_assert!((ra - rb).abs() <= 1e-14 * ra.max(rb) + 1e-300, "v={} a={} b={}: {} vs {}", v, a, b, ra, rb);
    }
}

/// `(mu_ratio, transverse_ratio, error_estimate)` of `shape` in the plane.
fn in_plane(shape: &fricosc::Shape, c: fricosc::Conditions, w: f64, psi: f64) -> (f64, f64, f64) {
    let e = shape.evaluate(&c.with_transverse(fricosc::plane::Transverse::new(w, psi).unwrap())).unwrap();
    (e.ratio.mu_ratio, e.transverse_ratio.unwrap(), e.error_estimate)
}

/// Conditions with normal oscillation `amp` (exactly 1 where `touch`: a
/// bound that touches zero) and oscillation along the sliding direction.
fn sliding(vhat: f64, amp: f64, touch: bool, (t, phase): (f64, f64)) -> fricosc::Conditions {
    let c = fricosc::Conditions::vhat(vhat, if touch { 1.0 } else { amp }).unwrap();
    if t > 0.0 {
        c.with_tangential(t, phase).unwrap()
    } else {
        c
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// The mirror `y -> -y` is the transverse phase moved by `pi`: the same
    /// friction, the force across negated, each within the two answers'
    /// estimates. The solver does not know the symmetry (its walks from
    /// `psi` and `psi + pi` differ: starts, events, the reloading direction,
    /// the layer's manifold), so a sign or a component handled for one side
    /// only, in any regime drawn (stick and slip, contact lost and regained,
    /// a bound touching zero, all three oscillations), shows here.
    #[test]
    fn the_flat_punch_in_the_plane_mirrors_with_its_transverse_phase(
        vhat in 0.01f64..3.0, amp in 0.0f64..2.5, touch in proptest::bool::weighted(0.15),
        t in prop_oneof![Just(0.0), 0.0f64..2.0], phase in -4.0f64..4.0, w in 0.001f64..3.0, psi in -7.0f64..7.0,
    ) {
        let c = sliding(vhat, amp, touch, (t, phase));
        let flat = fricosc::Shape::flat();
        let (a, b) = (in_plane(&flat, c, w, psi), in_plane(&flat, c, w, psi + std::f64::consts::PI));
        let bar = a.2 + b.2 + 4.0 * f64::EPSILON;
        prop_assert!((a.0 - b.0).abs() <= bar, "mu {:?} {:?}", a, b);
        prop_assert!((a.1 + b.1).abs() <= bar, "across {:?} {:?}", a, b);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// The same mirror for curved contacts (four families drawn) at
    /// a tolerance of 1e-8: their bands, nodes and tails are found for each
    /// answer anew, and agree within the estimates.
    #[test]
    fn a_curved_contact_in_the_plane_mirrors_with_its_transverse_phase(
        shape in prop::sample::select(vec!["parabolic", "cone", "power:1.5", "flat-tip:0.5"]),
        vhat in 0.05f64..1.0, amp in 0.0f64..1.5, w in 0.01f64..2.0, psi in -4.0f64..4.0,
    ) {
        let c = sliding(vhat, amp, false, (0.0, 0.0)).with_tol(1e-8).unwrap();
        let shape = fricosc::Shape::parse(shape).unwrap();
        let (a, b) = (in_plane(&shape, c, w, psi), in_plane(&shape, c, w, psi + std::f64::consts::PI));
        let bar = a.2 + b.2 + 4.0 * f64::EPSILON;
        prop_assert!((a.0 - b.0).abs() <= bar, "mu {:?} {:?}", a, b);
        prop_assert!((a.1 + b.1).abs() <= bar, "across {:?} {:?}", a, b);
    }
}
