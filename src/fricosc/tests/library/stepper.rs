//! The seed's time-stepping scheme converges to the exact solver, at the order
//! Expected: second order for amp <= 1, first (erratic in M) once contact is lost.
use crate::common::at::flat_ratio as ratio;
use fricosc::stepper::{Stepping, SteppingEvaluation};
use fricosc::Shape;
use std::f64::consts::TAU;

fn flat_mu_ratio(v: f64, a: f64, m: usize) -> SteppingEvaluation {
    crate::common::at::stepped(&Shape::flat(), v, a, Stepping { steps_per_period: m, springs: 1 }).unwrap()
}

/// Least-squares order and the worst error constant err / h^p over a geometric M sweep.
fn sweep(v: f64, a: f64, p: i32) -> (f64, f64, Vec<f64>) {
    let exact = ratio(v, a).unwrap().mu_ratio;
    let (mut sx, mut sy, mut sxx, mut sxy, mut n) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let (mut worst, mut consts) = (0.0f64, vec![]);
    for k in 0..20 {
        let m = (1000.0 * 1.23f64.powi(k)) as usize;
        let run = flat_mu_ratio(v, a, m);
        assert_eq!(run.steps, 2 * m as u64);
        let e = (run.ratio.mu_ratio - exact).abs().max(1e-300);
        let h = TAU / m as f64;
        let (x, y) = ((m as f64).ln(), e.ln());
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        n += 1.0;
        worst = worst.max(e / h.powi(p));
        consts.push(e / h.powi(p));
    }
    (-(n * sxy - sx * sy) / (n * sxx - sx * sx), worst, consts)
}

#[test]
fn second_order_without_contact_loss() {
    // (At small vbar the asymptotic order needs h below the sqrt(vbar) scale of the stick end.)
    for (v, a) in [(0.2, 0.5), (0.5, 1.0), (0.8, 0.5), (0.1, 0.9)] {
        let (order, c, _) = sweep(v, a, 2);
        assert!((1.6..2.5).contains(&order), "v={v} a={a}: order {order}");
        assert!(c < 0.2, "v={v} a={a}: err/h^2 up to {c}");
    }
}

#[test]
fn first_order_and_erratic_once_the_stick_starts_at_contact() {
    for (v, a) in [(0.2, 1.5), (0.5, 2.0), (0.8, 3.0)] {
        let (_, c, consts) = sweep(v, a, 1);
        assert!(c < 0.2, "v={v} a={a}: err/h up to {c}");
        // Not better than first order: err/h stays of order 0.01..0.1 at the finest steps.
        let tail = consts[10..].iter().cloned().fold(0.0, f64::max);
        assert!(tail > 0.01, "v={v} a={a}: err/h at fine steps {tail}");
    }
}

#[test]
fn stepping_agrees_in_every_regime_at_a_million_steps() {
    // Permanent stick-slip, slip-first jumping, stick-first jumping, no stick.
    for (v, a) in [(0.3, 0.7), (0.9, 1.5), (0.3, 1.5), (1.1, 2.0), (0.99, 0.2)] {
        let exact = ratio(v, a).unwrap().mu_ratio;
        let stepped = flat_mu_ratio(v, a, 1_000_000);
        let h = TAU / 1e6;
        assert!((stepped.ratio.mu_ratio - exact).abs() < 0.2 * h, "v={v} a={a}");
        assert!(stepped.period_change < 1e-12, "not periodic after one period");
    }
}
