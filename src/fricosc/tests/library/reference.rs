//! The public 40-digit reference values: the committed copy in
//! `data/reference-values.json`, equal to the file the project was given
//! where that sits beside the checkout.
use crate::common::{reference_cases, tol};

#[test]
fn the_copy_in_data_equals_shared_when_present() {
    // The committed copy is what every test reads; it must exist and hold every case.
    let ours = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/reference-values.json"))
        .expect("data/reference-values.json (the committed copy of the public reference values) is missing");
    let cases = reference_cases();
    assert_eq!(cases.iter().filter(|c| c.shape == "flat").count(), 12);
    assert_eq!(cases.len(), 19, "12 flat, 7 parabolic and cone cases");
    let shared = concat!(env!("CARGO_MANIFEST_DIR"), "/../../../shared/reference-values.json");
    match std::fs::read_to_string(shared) {
        Ok(text) => assert_eq!(text, ours, "data/reference-values.json is stale: copy shared/reference-values.json"),
        Err(_) => eprintln!("note: ../shared is absent; the committed copy in data/ was checked alone"),
    }
}

#[test]
fn flat_cases_match_to_1e_14() {
    let mut n = 0;
    for c in reference_cases().iter().filter(|c| c.shape == "flat") {
        let r = crate::common::at::flat_ratio(c.vbar, c.amp).unwrap();
        let err = (r.mu_ratio - c.mu_ratio).abs();
        assert!(
            err <= tol::FLAT_ABS.min(tol::FLAT_ABS_REGRESSION),
            "flat vbar={} amp={}: {} vs {} (err {err:e})",
            c.vbar,
            c.amp,
            r.mu_ratio,
            c.mu_text
        );
        if c.reduction > 0.0 {
            let rel = (r.reduction - c.reduction).abs() / c.reduction;
            assert!(rel <= 1e-13, "reduction rel err {rel:e} at vbar={} amp={}", c.vbar, c.amp);
        } else {
            assert_eq!(r.reduction, 0.0);
        }
        n += 1;
    }
    assert_eq!(n, 12);
}

/// The tests' exact error of a double against decimal text: below an ulp too.
#[test]
fn the_exact_error_helper_measures_below_an_ulp() {
    assert_eq!(crate::common::exact_error(0.5, "0.5"), 0.0);
    // 0.1 is 0.1000000000000000055511151231257827... as a double.
    let e = crate::common::exact_error(0.1, "0.1");
    assert!((e / 5.551115123125783e-18 - 1.0).abs() < 1e-12, "{e:e}");
    let e = crate::common::exact_error(1e-20, "1.0000000000000001e-20");
    assert!(e > 0.0 && e < 1e-35, "{e:e}");
    assert!((crate::common::exact_error(0.3, "0.30000000000000004") / 5.1102230246251565e-17 - 1.0).abs() < 1e-12);
    assert!((crate::common::exact_error(2.0, "1.5") - 0.5).abs() < 1e-16);
}
