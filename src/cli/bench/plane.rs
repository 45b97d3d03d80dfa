//! The plane's cases of `fricosc bench`: the exact solver in the plane against
//! the plane's stepper (the return mapping, `fricosc::stepper::transverse`),
//! at one point of sliding with normal and transverse oscillation (`vhat`
//! 0.3, `amp` 0.5, `W` 1.2, `psi` 0.7).
//!
//! The flat punch's reference is the 20-digit value of
//! `data/plane-reference.json` (`data/scripts/plane_reference.py`). A curved
//! contact in the plane has no independent high-precision value: the
//! paraboloid's reference is the exact solver at the default tolerance (its
//! estimate is stated in the case; the plane's stepper converges to it in
//! `src/fricosc/tests/library/plane_curved.rs`), and its exact points are the
//! looser tolerances measured against it.

use super::{time_per_call, Case, Collector, Point, Ratio, Throughput, Timing};
use fricosc::plane::Transverse;
use fricosc::stepper::Stepping;
use fricosc::{Conditions, Shape};

/// The plane's 20-digit values (`data/scripts/plane_reference.py`).
const PLANE_REFERENCES: &str = include_str!("../../../data/plane-reference.json");

/// The point of both cases: `vhat`, `amp`, `W`, `psi` (the first of
/// `data/plane-reference.json`).
const POINT: [f64; 4] = [0.3, 0.5, 1.2, 0.7];

/// Periods of the stepper (its means are those of the last).
const FLAT_PERIODS: usize = 30;
/// Periods of the stepper with springs (the paraboloid's springs settle faster).
const CURVED_PERIODS: usize = 12;

/// Where the cases go: the report's lists.
pub(super) struct Out<'a> {
    pub(super) cases: &'a mut Vec<Case>,
    pub(super) points: &'a mut Vec<Point>,
    pub(super) failures: &'a mut Vec<String>,
    pub(super) ratios: &'a mut Vec<Ratio>,
}

/// One case: its name, shape, reference (its value, and the text the report
/// shows), the exact solver's tolerances and the stepper's `(steps a period,
/// springs)`.
struct Spec<'a> {
    name: &'a str,
    shape: Shape,
    value: f64,
    reference: String,
    tols: &'a [Option<f64>],
    stepping: &'a [(usize, usize)],
    periods: usize,
}

/// The conditions of the point at the tolerance `tol` (the default where `None`).
fn conditions(tol: Option<f64>) -> fricosc::Result<(Conditions, Transverse)> {
    let [vhat, amp, w, psi] = POINT;
    let c = Conditions::vhat(vhat, amp)?;
    let c = match tol {
        Some(t) => c.with_tol(t)?,
        None => c,
    };
    Ok((c, Transverse::new(w, psi)?))
}

fn exact(shape: &Shape, tol: Option<f64>) -> fricosc::Result<fricosc::Evaluation> {
    conditions(tol).and_then(|(c, tw)| shape.evaluate(&c.with_transverse(tw)))
}

/// Points a second on one core (a pool of one thread) at the point, at the
/// default tolerance: the flat punch and the paraboloid, each with the target
/// of issue 62 (a point in 50 us and in 5 ms).
pub(super) fn throughput(tm: Timing) -> fricosc::Result<Vec<Throughput>> {
    let [vhat, amp, w, psi] = POINT;
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build();
    let pool = one.map_err(|e| fricosc::Error::Internal { what: format!("a pool of one thread: {e}") })?;
    let c = conditions(None).map(|(c, tw)| c.with_transverse(tw))?;
    let mu = |shape: &Shape| shape.evaluate(&c).map_or(f64::NAN, |e| e.ratio.mu_ratio);
    let of = |(name, target, k): (&str, f64, usize)| {
        let shape = Shape::parse(name)?;
        shape.evaluate(&c)?;
        let per = pool.install(|| time_per_call(k, tm.sample, || mu(&shape)));
        let kind = format!("{name} in the plane, vhat {vhat}, amp {amp}, W {w}, psi {psi}");
        Ok(Throughput { kind, points_per_second_per_core: 1.0 / per, target: Some(target) })
    };
    [("flat", 2e4, tm.k), ("parabolic", 200.0, 2)].into_iter().map(of).collect()
}

/// The flat punch against its 20-digit reference: the exact solver at the
/// default tolerance, the stepper with one spring.
pub(super) fn flat(out: &mut Out, tm: Timing, quick: bool) {
    let name = "flat transverse";
    let v: serde_json::Value = serde_json::from_str(PLANE_REFERENCES).unwrap_or_default();
    let case = &v["cases"][0];
    let at = |key: &str| case[key].as_f64();
    let matches = [at("vhat"), at("amp"), at("transverse_amp"), at("transverse_phase")] == POINT.map(Some);
    let Some(reference) = case["mu_ratio"].as_str().filter(|_| matches) else {
        out.failures.push(format!("{name}: no reference value"));
        return;
    };
    let stepping: &[(usize, usize)] =
        if quick { &[(100, 1), (1000, 1)] } else { &[(100, 1), (1000, 1), (10_000, 1), (100_000, 1), (1_000_000, 1)] };
    let spec = Spec {
        name,
        shape: Shape::flat(),
        value: reference.parse().unwrap_or(f64::NAN),
        reference: reference.into(),
        tols: &[None],
        stepping,
        periods: FLAT_PERIODS,
    };
    run(out, &spec, tm);
}

/// The paraboloid against the exact solver at the default tolerance (module
/// docs): the exact solver at looser tolerances, the stepper with springs.
pub(super) fn parabolic(out: &mut Out, tm: Timing, quick: bool) {
    let name = "parabolic transverse";
    let shape = Shape::parabolic();
    let (value, reference) = match exact(&shape, None) {
        Ok(e) => (
            e.ratio.mu_ratio,
            format!(
                "{:?} (the exact solver at the default tolerance, estimate {:.1e})",
                e.ratio.mu_ratio, e.error_estimate
            ),
        ),
        Err(e) => {
            out.failures.push(format!("{name}: no reference value: {e}"));
            return;
        }
    };
    let (tols, stepping): (&[Option<f64>], &[(usize, usize)]) = if quick {
        (&[Some(1e-10)], &[(100, 16), (300, 32)])
    } else {
        (&[Some(1e-3), Some(1e-6), Some(1e-10)], &[(100, 16), (300, 32), (1000, 64), (3000, 128), (10_000, 256)])
    };
    run(out, &Spec { name, shape, value, reference, tols, stepping, periods: CURVED_PERIODS }, tm);
}

/// The case's points, and its ratio of the most accurate runs.
fn run(out: &mut Out, spec: &Spec, tm: Timing) {
    let [vhat, amp, w, psi] = POINT;
    out.cases.push(Case {
        name: spec.name.into(),
        shape: spec.shape.name().into(),
        vbar: vhat / amp,
        amp,
        reference: spec.reference.clone(),
        transverse: Some([w, psi]),
    });
    let mut c = Collector { case: spec.name, reference: spec.value, points: out.points, failures: out.failures };
    let mut exact_best = None;
    for &tol in spec.tols {
        let setting = tol.map_or("default".into(), |t| format!("tol={t:e}"));
        let run = || exact(&spec.shape, tol).map(|e| e.ratio.mu_ratio);
        let t = time_per_call(tm.k, tm.sample, || run().unwrap_or(f64::NAN));
        if let Some(err) = c.record("exact", setting, run(), t) {
            exact_best = Some((err, t));
        }
    }
    let mut stepping_best: Option<(f64, f64)> = None;
    for &(m, n) in spec.stepping {
        let st = Stepping { steps_per_period: m, springs: n };
        let run = || {
            conditions(None)
                .and_then(|(c, tw)| fricosc::stepper::transverse(&spec.shape, &c, tw, st, spec.periods))
                .map(|e| e.mu_ratio)
        };
        let t = time_per_call(tm.k.min(3), tm.sample, || run().unwrap_or(f64::NAN));
        if let Some(err) = c.record("stepping", format!("M={m},N={n}"), run(), t) {
            stepping_best = stepping_best.filter(|&(e, _)| e <= err).or(Some((err, t)));
        }
    }
    if let (Some(exact), Some(stepping)) = (exact_best, stepping_best) {
        out.ratios.push(Ratio::of(spec.name, exact, stepping));
    }
}
