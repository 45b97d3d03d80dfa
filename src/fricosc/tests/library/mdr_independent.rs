//! The MDR solver and its error estimate against a reference that shares no
//! code with it: its own single-spring solution (bisection on the plain gap
//! `B(t0 + x) - F0 - vbar x`, the seed's eq. 9 integral, eq. 20 for the mean
//! normal force) and its own quadrature (tanh-sinh in `z = x/x_c`, split at the
//! regime thresholds, two step sizes whose difference is its accuracy).
//!
//! At every tolerance from 1e-3 to the default, on the 528-point grid of
//! `mdr.rs` (which includes amp 0.999 and 1.001, vbar 1e-6 and 1 - 1e-6),
//! the solver's `error_estimate` must bound its distance to this reference
//! (up to the reference's own accuracy).

use crate::common::quad::tanh_sinh;
use crate::common::spring_ref::{deficit, mean_b};
use crate::common::tol;
use fricosc::DEFAULT_TOL;

/// `(mu_ratio, accuracy)` of the power law `g = z^n` by the reference.
fn reference(n: f64, v: f64, amp: f64) -> (f64, f64) {
    if amp == 0.0 || v >= 1.0 {
        return (1.0, 0.0);
    }
    let c = (1.0 - v * v).sqrt();
    let z_of = |s: f64| (1.0 - amp * s).clamp(0.0, 1.0 + amp).powf(1.0 / n);
    let mut cuts = vec![0.0, z_of(1.0), z_of(c), z_of(-c), z_of(-1.0)];
    cuts.dedup();
    let f = |z: f64| {
        let s = (1.0 - z.powf(n)) / amp;
        (mean_b(s), deficit(s, v))
    };
    let integrate = |h: f64| {
        let (mut nn, mut dd) = (0.0, 0.0);
        for w in cuts.windows(2) {
            if w[1] > w[0] {
                let (p, q) = tanh_sinh(w[0], w[1], h, &f);
                nn += p;
                dd += q;
            }
        }
        (nn, dd)
    };
    let (n1, d1) = integrate(1.0 / 32.0);
    let (n2, d2) = integrate(1.0 / 64.0);
    let (m1, m2) = (1.0 - d1 / n1, 1.0 - d2 / n2);
    (m2, (m2 - m1).abs() + 1e-15)
}

#[test]
fn the_error_estimate_bounds_the_error_at_every_tolerance_against_an_independent_reference() {
    let vbars = [0.0, 1e-6, 0.05, 0.2, 0.45, 0.7, 0.9, 0.99, 1.0 - 1e-6, 1.0 - 1e-12, 1.0, 1.2];
    let amps = [0.0, 0.1, 0.5, 0.9, 0.999, 1.0, 1.001, 1.3, 2.0, 4.0, 10.0];
    let mut refs = vec![];
    for n in [1.0, 2.0, 1.5, 3.0] {
        for &v in &vbars {
            for &a in &amps {
                refs.push((n, v, a, reference(n, v, a)));
            }
        }
    }
    assert_eq!(refs.len(), 528);
    let worst_ref = refs.iter().map(|r| r.3 .1).fold(0.0, f64::max);
    assert!(worst_ref < 1e-11, "the reference itself is accurate to {worst_ref:e}");
    for tol in [1e-3, 1e-6, 1e-9, 1e-12, DEFAULT_TOL] {
        let mut misses = vec![];
        let mut worst = 0.0f64;
        for &(n, v, a, (mu, acc)) in &refs {
            let r = crate::common::at::power(n, v, a, tol).unwrap();
            let err = (r.ratio.mu_ratio - mu).abs();
            worst = worst.max(err);
            if crate::common::exceeds(err, r.error_estimate + acc) {
                misses.push(format!("n={n} v={v} a={a}: err {err:e} > estimate {:e} + {acc:e}", r.error_estimate));
            }
            // A requested tolerance is met (relative to mu, with the reference's slack).
            assert!(err <= 10.0 * tol.max(1e-14) + acc, "tol {tol:e}, n={n} v={v} a={a}: err {err:e}");
        }
        assert!(misses.is_empty(), "tol {tol:e}: {} misses, e.g. {}", misses.len(), misses[0]);
        eprintln!("tol {tol:e}: worst error {worst:e}, every estimate a bound");
    }
}

/// The 40-digit references of `data/mdr-reference.json` (`data/scripts/mdr_reference.py`:
/// the seed's construction of each spring in 60-digit arithmetic, tanh-sinh
/// over the foundation at two precisions): at every tolerance the error
/// estimate bounds the error, with no slack (the references are exact to 25
/// digits or more); at the default tolerance the error is within the
/// published 1e-13, and small values keep their relative accuracy (1e-12 at
/// amp >= 0.999, vbar >= 1e-6; before: 7e-12 at the paraboloid's vbar 0.003,
/// amp 1, outside the estimate at every tolerance). The references include the
/// regime boundary `amp sqrt(1 - vbar^2) = 1`, where the stick-first band
/// starts within an ulp of the contact centre's threshold (before: an error of
/// 1.1e-11 for an estimate of 5e-12 at the paraboloid's amp 5/3, vbar 0.8).
#[test]
fn the_error_estimate_bounds_the_error_against_forty_digit_references() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/mdr-reference.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let cases = v["cases"].as_array().unwrap();
    assert!(cases.len() >= 100, "{} cases", cases.len());
    let mut worst_default = (0.0f64, 0.0f64);
    let mut worst_ratio = 0.0f64;
    // At the default tolerance the estimate is mostly its rounding part: where
    // both `mu` and the reduction exceed 0.1, the quotient's
    // (`ratio::quotient_rounding`, 16 eps a term); where one is below 0.01,
    // the half ulp of `1 - q` (`ratio::rounding_estimate`). The largest error
    // each covers, as a fraction of the estimate.
    let (mut quotient_tightness, mut half_ulp_tightness) = (0.0f64, 0.0f64);
    for tol in [1e-3, 1e-6, 1e-9, 1e-12, DEFAULT_TOL] {
        let mut misses = vec![];
        for c in cases {
            let (n, vbar, amp) = (c["n"].as_f64().unwrap(), c["vbar"].as_f64().unwrap(), c["amp"].as_f64().unwrap());
            let exact = c["mu_ratio"].as_str().unwrap();
            let r = crate::common::at::power(n, vbar, amp, tol).unwrap();
            let err = crate::common::exact_error(r.ratio.mu_ratio, exact);
            if crate::common::exceeds(err, r.error_estimate) {
                misses.push(format!("n={n} vbar={vbar} amp={amp}: error {err:e} > estimate {:e}", r.error_estimate));
            }
            // The estimate certifies the tolerance asked for (and at the default
            // one the published bar): an estimate that bounds by being huge, or a
            // piece accepted too early, is a miss too.
            worst_ratio = worst_ratio.max(r.error_estimate / tol);
            if r.error_estimate > 10.0 * tol && r.error_estimate > tol::MDR_ABS {
                misses.push(format!("n={n} vbar={vbar} amp={amp}: estimate {:e} for tol {tol:e}", r.error_estimate));
            }
            if tol == DEFAULT_TOL {
                let mu: f64 = exact.parse().unwrap();
                let smaller = mu.min(1.0 - mu);
                if smaller >= 0.1 {
                    quotient_tightness = quotient_tightness.max(err / r.error_estimate);
                } else if smaller < 0.01 {
                    half_ulp_tightness = half_ulp_tightness.max(err / r.error_estimate);
                }
                worst_default.0 = worst_default.0.max(err);
                if amp >= 0.999 && vbar >= 1e-6 {
                    worst_default.1 = worst_default.1.max(err / mu);
                }
            }
        }
        assert!(misses.is_empty(), "tol {tol:e}: {} misses:\n{}", misses.len(), misses.join("\n"));
    }
    eprintln!(
        "default tolerance: worst error {:e}, worst relative error at amp >= 0.999 {:e}; largest estimate/tol {worst_ratio:e}; \
         largest error/estimate {quotient_tightness:e} (quotient rounding), {half_ulp_tightness:e} (half ulp)",
        worst_default.0, worst_default.1
    );
    // The rounding parts are bounds, not guesses: each may overstate the worst
    // error it covers by a safety margin, not by orders of magnitude. Observed:
    // 0.072 (n = 2, vbar 0.2, amp 0.3) and 0.49 (n = 2, vbar 0.999, amp 5). A
    // quotient part of 64 eps a term (for 16), or `sqrt(terms)` as `terms`,
    // fails here, as does a half ulp grown to 4 ulp; estimates smaller than
    // the errors fail the bound above. (Within a factor of two either way the
    // rounding part is a choice of margin: the quotient's covers the observed
    // errors 14 times.)
    assert!(quotient_tightness >= 0.04, "the quotient's rounding part overstates: {quotient_tightness:e}");
    assert!(half_ulp_tightness >= 0.2, "the half ulp of 1 - q overstates: {half_ulp_tightness:e}");
    // Published bars, and regression bars at about 10x the observed 7.9e-16 and 1.8e-15.
    assert!(worst_default.0 <= tol::MDR_ABS.min(6e-15), "{:e}", worst_default.0);
    assert!(worst_default.1 <= 1e-12f64.min(2e-14), "{:e}", worst_default.1);
}

/// Steep power laws at `amp = 1` and small `vbar` (`data/mdr-amp-one.json`,
/// `data/scripts/mdr_reference.py --amp-one`): the slip-first band is
/// `vbar^(2/n)` wide there, far wider than the `O(vbar)` tangential force it
/// carries, which was summed as `<B> - D` (the difference of two numbers near
/// 1): `n = 3.7` at vbar 1e-16 was 3.5e-8 off for an estimate of 2e-8. And
/// the stick-first band's top (`arcsin vbar`) lies far closer to the
/// Jacobian's branch point than the 2^-90 of the band's width its mapping
/// took as the least distance: `n = 20` at vbar 1e-30 was 7e-10 off (at
/// 1e-40, 2.5e-5 for an estimate of 6.9e-6). At every tolerance the estimate
/// bounds the error; at the default one the error is within 1e-12 of `mu`.
#[test]
fn steep_power_laws_at_amp_one_keep_every_digit_of_a_small_mu() {
    let worst = worst_relative_error_within_the_estimates("mdr-amp-one.json", 8);
    eprintln!("steep power laws at amp 1: worst relative error {worst:e}");
    // Regression bar, about ten times the observed 3.2e-16.
    assert!(worst <= 3e-15, "{worst:e}");
}

/// The power-law cases of a reference file (`count` of them), at every
/// tolerance within the estimate, and at the default one within 1e-12 of `mu`
/// (the published bar): their largest relative error there.
fn worst_relative_error_within_the_estimates(file: &str, count: usize) -> f64 {
    let cases = crate::common::data_cases(file);
    assert_eq!(cases.len(), count);
    let mut worst = 0.0f64;
    for c in &cases {
        let (n, vbar, amp) = (c["n"].as_f64().unwrap(), c["vbar"].as_f64().unwrap(), c["amp"].as_f64().unwrap());
        let exact = c["mu_ratio"].as_str().unwrap();
        let mu: f64 = exact.parse().unwrap();
        for tol in [1e-3, 1e-6, 1e-9, 1e-12, DEFAULT_TOL] {
            let r = crate::common::at::power(n, vbar, amp, tol).unwrap();
            let err = crate::common::exact_error(r.ratio.mu_ratio, exact);
            assert!(
                !crate::common::exceeds(err, r.error_estimate),
                "n={n} vbar={vbar} amp={amp} tol {tol:e}: {err:e} > {:e}",
                r.error_estimate
            );
            if tol == DEFAULT_TOL {
                assert!(err <= 1e-12 * mu, "n={n} vbar={vbar} amp={amp}: relative error {:e}", err / mu);
                worst = worst.max(err / mu);
            }
        }
    }
    worst
}

/// Between vbar 0.001 and 0.1 (`data/mdr-small-vbar.json`,
/// `data/scripts/mdr_reference.py --small-vbar`: 140 points, vbar 0.001 to
/// 0.05, exponents 0.5 to 3, amp 0.3 to 3): the stick-first band is integrated in the stick's
/// half-length there, the springs near a small top phase (`arcsin vbar`, or
/// the contact centre's threshold `u*` close to it) with their phase taken
/// from the top. At every tolerance the estimate bounds the error; at the
/// default one `mu` is within 1e-12 of itself (the published bar) and, as a
/// regression bar, about ten times the observed.
#[test]
fn small_velocities_in_the_half_length_keep_every_digit() {
    let worst = worst_relative_error_within_the_estimates("mdr-small-vbar.json", 140);
    eprintln!("small velocities: worst relative error {worst:e}");
    // Regression bar, about ten times the observed 9.0e-16 (n = 2, vbar 0.05,
    // amp 0.95: in the phase, whose code the half-length forms left alone;
    // the phase form at every point gave the same worst, 8.7e-16 in mpmath).
    assert!(worst <= 1e-14, "{worst:e}");
}
