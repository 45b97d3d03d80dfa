//! Validating a table in the plane (`transverse_amp`, `transverse_phase`,
//! `transverse_ratio`): the independent 20-digit values of
//! `data/scripts/plane_reference.py` pass; values off along or across, a
//! convention of the phase or amplitude across, values beyond a bound or
//! the plane's stepping peer are each named.
use crate::common::data_cases;
use fricosc::stepper::Stepping;
use fricosc::validation::{compare_oscillation, Check, FindingKind, OscillationInput};
use fricosc::Shape;

/// The reference's rows, read as `f64`, each with both of its values.
fn reference() -> Vec<OscillationInput> {
    let cases = data_cases("plane-reference.json");
    let row = |c: &serde_json::Value| {
        let g = |k: &str| c[k].as_f64().unwrap();
        let s = |k: &str| c[k].as_str().unwrap().parse::<f64>().unwrap();
        OscillationInput::new(g("vhat"), g("amp"), s("mu_ratio"))
            .with_tangential(g("tangential_amp"), g("phase"))
            .with_transverse(g("transverse_amp"), g("transverse_phase"), Some(s("transverse_ratio")))
    };
    cases.iter().map(row).collect()
}

fn kinds(rows: &[OscillationInput], check: &Check) -> Vec<FindingKind> {
    let v = compare_oscillation(&Shape::flat(), rows, check).unwrap();
    v.findings.iter().map(|f| f.kind).collect()
}

/// The independent values: errors along and across below 1e-14, or within
/// the exact value's estimate (the two slowly contracting orbits, 3.1e-13
/// across at an estimate of 2.1e-12), each row's regime the events of its
/// period, no finding even at `max_error` 1e-14; a value off by 1e-11
/// (beyond 1e-14 and the estimate) is a finding.
#[test]
fn the_independent_reference_passes() {
    let mut rows = reference();
    let check = Check::default().with_max_error(Some(1e-14));
    let v = compare_oscillation(&Shape::flat(), &rows, &check).unwrap();
    assert!(v.findings.is_empty(), "{:?}", v.findings);
    for r in &v.rows {
        let across = r.transverse.as_ref().and_then(|t| t.transverse_error).unwrap();
        let within = 1e-14 + r.exact_error_estimate;
        assert!(r.error.abs() < 1e-14 && across.abs() <= within, "{r:?}");
    }
    assert!(v.transverse.as_ref().unwrap().n == rows.len());
    assert!(v.rows.iter().all(|r| r.regime.starts_with("in the plane")), "{:?}", v.rows);
    let r = &mut rows[15];
    *r = r.with_transverse(r.transverse_amp, r.transverse_phase, r.transverse_ratio.map(|t| t + 1e-11));
    assert_eq!(kinds(&rows, &check), [FindingKind::MaxError]);
}

/// A force across off by 1e-6 (the one along exact) is beyond `max_error`
/// 1e-9; a force across outside `[-1, 1]` is named; a row along the
/// sliding direction only is compared with no force across.
#[test]
fn errors_across_are_counted() {
    let mut rows = reference();
    let r = &mut rows[2];
    *r = r.with_transverse(r.transverse_amp, r.transverse_phase, r.transverse_ratio.map(|t| t + 1e-6));
    assert_eq!(kinds(&rows, &Check::default().with_max_error(Some(1e-9))), [FindingKind::MaxError]);
    let v = compare_oscillation(&Shape::flat(), &rows, &Check::default()).unwrap();
    let worst = v.transverse.unwrap();
    assert!(worst.worst_row == 2 && (worst.max_abs_error - 1e-6).abs() < 1e-12, "{worst:?}");
    rows[2] = rows[2].with_transverse(rows[2].transverse_amp, rows[2].transverse_phase, Some(-1.5));
    assert!(kinds(&rows, &Check::default()).contains(&FindingKind::BelowMinusOne));
    let along = OscillationInput::new(0.3, 0.5, 0.9372633409484812).with_transverse(0.0, 0.0, Some(0.25));
    let v = compare_oscillation(&Shape::flat(), &[along], &Check::default()).unwrap();
    let t = v.rows[0].transverse.as_ref().unwrap();
    assert_eq!((t.transverse_exact, t.transverse_error), (0.0, Some(0.25)));
}

/// A table whose values were computed with the phase across of the other
/// sign (or from the normal force's maximum) is named by that convention;
/// one with the amplitude across halved gets errors of order one.
#[test]
fn conventions_across_are_named() {
    let shape = Shape::flat();
    let at = |w: f64, q: f64| {
        let c = fricosc::Conditions::vhat(0.3, 1.5).unwrap();
        let e = shape.evaluate(&c.with_transverse(fricosc::plane::Transverse::new(w, q).unwrap())).unwrap();
        (e.ratio.mu_ratio, e.transverse_ratio.unwrap())
    };
    let psis = [0.4, 1.0, 2.2];
    let table = |read: &dyn Fn(f64, f64) -> (f64, f64)| -> Vec<OscillationInput> {
        psis.iter()
            .map(|&q| {
                let (m, t) = read(1.2, q);
                OscillationInput::new(0.3, 1.5, m).with_transverse(1.2, q, Some(t))
            })
            .collect()
    };
    let hint = |rows: &[OscillationInput]| {
        let v = compare_oscillation(&shape, rows, &Check::default()).unwrap();
        v.findings.iter().map(|f| format!("{:?}: {}", f.kind, f.hint)).collect::<Vec<_>>().join("; ")
    };
    assert_eq!(hint(&table(&at)), "");
    assert!(hint(&table(&|w, q| at(w, -q))).contains("the transverse phase's sign reversed"));
    let maximum = hint(&table(&|w, q| at(w, q + std::f64::consts::PI)));
    assert!(maximum.contains("(psi + pi)"), "{maximum}");
    assert!(hint(&table(&|w, q| at(0.5 * w, q))).contains("(W/2)"));
}

/// With the plane's stepping peer: a value along off by 1e-2 is ten times
/// the peer's error at 4,000 steps a period (about 2e-4) and named; the
/// peer's errors across are reported beside the table's.
#[test]
fn the_planes_peer_is_run_beside() {
    let mut rows = reference();
    rows.truncate(3);
    rows[1].mu_ratio += 1e-2;
    let check = Check::default().with_peer(Some(Stepping { steps_per_period: 4000, springs: 1 }));
    let v = compare_oscillation(&Shape::flat(), &rows, &check).unwrap();
    let worse: Vec<_> = v.findings.iter().filter(|f| f.kind == FindingKind::WorseThanPeer).collect();
    assert_eq!(worse.len(), 1);
    assert_eq!(worse[0].rows, [1]);
    for r in &v.rows {
        let p = r.transverse.as_ref().unwrap().transverse_peer_error.unwrap();
        assert!(p != 0.0 && p.abs() < 1e-2, "{p}");
    }
}
