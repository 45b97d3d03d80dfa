//! Inputs at the edges of the domain: an answer within its estimate or a
//! typed error naming the input, never a panic or an internal error.

use crate::common::at;
use fricosc::{Error, Shape};

/// Amplitudes whose force integral over the foundation overflows double
/// precision (`z_max = (1 + amp)^(1/n)` itself, for small `n`): an invalid
/// `amp`, not a panic in the band search (`power:0.5` at 1e300 panicked,
/// `flat-tip:0.5` at 1e250 was an internal error, NaN).
#[test]
fn an_amplitude_beyond_double_precision_is_named() {
    for (spec, amp) in [
        ("power:0.5", 1e300),
        ("power:0.05", 1e16),
        ("power:0.1", 1e50),
        ("power:0.2", 1e100),
        ("power:0.3", 1e100),
        ("flat-tip:0.5", 1e250),
    ] {
        let shape = crate::common::shape(spec).unwrap();
        match at::combined(&shape, [0.3, amp, 1.0, 0.0], fricosc::DEFAULT_TOL) {
            Err(Error::InvalidParameter { name: "amp", .. }) => {}
            other => panic!("{spec} at amp {amp:e}: {other:?}"),
        }
    }
    // Below that the answer is -k/amp (the springs push back as often as they
    // pull): finite, of the size the smaller amplitudes give.
    let r = at::combined(&Shape::parabolic(), [0.3, 1e15, 1.0, 0.0], fricosc::DEFAULT_TOL).unwrap();
    let k = at::combined(&Shape::parabolic(), [0.3, 1e10, 1.0, 0.0], fricosc::DEFAULT_TOL).unwrap();
    assert!((r.ratio.mu_ratio * 1e15 / (k.ratio.mu_ratio * 1e10) - 1.0).abs() < 1e-6, "{r:?} {k:?}");
}

/// `power:0.05` one ulp below `amp = 1`: its permanent band is subnormal
/// (`(1 - amp)^20`) and the slip-first band's width overflowed in its
/// cancellation-free form (`deficit NaN`, exit 3, in `point` while `table`
/// answered). The report now answers, continuous with `amp = 1` itself (where
/// no band is permanent: another path), and a static limit in `[0, 1 - amp]`.
#[test]
fn an_amplitude_an_ulp_below_one_is_reported() {
    let amp = 1.0 - f64::EPSILON / 2.0;
    let p = at::mdr_point(0.05, 0.3, amp, fricosc::DEFAULT_TOL).unwrap();
    let one = at::mdr_point(0.05, 0.3, 1.0, fricosc::DEFAULT_TOL).unwrap();
    let e = (p.result.ratio.mu_ratio - one.result.ratio.mu_ratio).abs();
    assert!(e <= p.result.error_estimate + one.result.error_estimate, "{p:?} against {one:?}");
    assert!(p.mu_static_ratio >= 0.0 && p.mu_static_ratio <= 1.0 - amp, "{}", p.mu_static_ratio);
}

/// A phase is its exact remainder modulo `2 pi` (to an ulp or two): the answer
/// at 1e16 is the answer at 2.2474252491623665 (mpmath's remainder) within its
/// estimate (with the double `2 pi` the phase was 0.1 off: the flat punch gave 0.075 for -0.087).
#[test]
fn a_huge_phase_gives_the_answer_of_its_remainder() {
    for spec in ["flat", "parabolic"] {
        let shape = crate::common::shape(spec).unwrap();
        let at_phase = |p: f64| at::combined(&shape, [0.3, 0.5, 1.5, p], fricosc::DEFAULT_TOL).unwrap();
        for (huge, rem) in [(1e16, 2.2474252491623665), (-1e16, 4.03576005801722), (1e300, 4.099312823027354)] {
            let (a, b) = (at_phase(huge), at_phase(rem));
            let e = (a.ratio.mu_ratio - b.ratio.mu_ratio).abs();
            assert!(e <= a.error_estimate + b.error_estimate, "{spec} at {huge:e}: {a:?} against {b:?}");
        }
    }
}
