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
