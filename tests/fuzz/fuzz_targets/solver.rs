#![no_main]
//! The solver entry points on arbitrary (vbar, amp, shape) triples: no panic,
//! results in [0, 1] whenever the inputs are accepted.
use fricosc::{Conditions, Shape};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: (f64, f64, u8, f64)| {
    let (v, a, k, n) = data;
    let shape = match k % 5 {
        0 => Shape::flat(),
        1 => Shape::parabolic(),
        2 => Shape::cone(),
        3 => match Shape::parse(&format!("flat-tip:{:?}", n.fract().abs())) {
            Ok(s) => s,
            Err(_) => return,
        },
        _ => match Shape::parse(&format!("power:{n:?}")) {
            Ok(s) => s,
            Err(_) => return,
        },
    };
    match Conditions::vbar(v, a).and_then(|c| shape.evaluate(&c)) {
        Ok(e) => assert!((0.0..=1.0).contains(&e.ratio.mu_ratio), "{v} {a} {k}: {}", e.ratio.mu_ratio),
        // Valid inputs must give a value: an error there (an internal one) is a finding.
        Err(e) => assert!(!(v.is_finite() && a.is_finite() && v >= 0.0 && a >= 0.0), "{v} {a} {k}: {e}"),
    }
});
