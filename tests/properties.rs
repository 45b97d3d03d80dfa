//! Properties over random inputs (proptest).
use fricosc::flat::ratio;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn mu_ratio_is_in_the_unit_interval_and_reduction_is_its_complement(v in 0.0f64..1.5, a in 0.0f64..20.0) {
        let r = ratio(v, a).unwrap();
        prop_assert!((0.0..=1.0).contains(&r.mu_ratio));
        prop_assert!(r.reduction >= 0.0);
        prop_assert!((r.mu_ratio + r.reduction - 1.0).abs() <= f64::EPSILON);
    }

    #[test]
    fn mu_ratio_is_nondecreasing_in_vbar(v in 0.0f64..1.2, dv in 0.0f64..0.3, a in 0.0f64..20.0) {
        let lo = ratio(v, a).unwrap().mu_ratio;
        let hi = ratio(v + dv, a).unwrap().mu_ratio;
        prop_assert!(hi >= lo - 4.0 * f64::EPSILON, "v={} dv={} a={}: {} > {}", v, dv, a, lo, hi);
    }
}
