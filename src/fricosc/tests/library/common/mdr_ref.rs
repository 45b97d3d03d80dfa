//! A second quadrature for MDR power laws (not independent: it shares
//! `Spring::new` with the solver; its Gauss rules are the tests' own
//! (`common/quad.rs`); the independent check is
//! `mdr_independent.rs`): the integral over `z` is done in
//! the variable `y = z^n` (not the solver's `beta = arcsin s`), with a
//! `y = p + (q-p)(1 - cos t)/2` substitution for the square-root thresholds,
//! Gauss-Jacobi at the centre, geometric splitting near it, and fixed high orders
//! (96 and 128 points per piece, whose difference is returned as the accuracy).
//! Each spring is solved by the generic `Spring::new(s, vbar)`.
use crate::common::quad::gauss_jacobi;
use fricosc::spring::{mean_normal, Spring};
use std::f64::consts::PI;

fn integrand(n: f64, amp: f64, vbar: f64, y: f64) -> (f64, f64) {
    let s = (1.0 - y) / amp;
    if vbar < 1.0 {
        let sp = Spring::new(s, vbar);
        (amp * sp.mean_normal, amp * sp.deficit)
    } else {
        let _ = n;
        (amp * mean_normal(s), 0.0)
    }
}

fn pass(n: f64, amp: f64, vbar: f64, p: f64, q: f64, m: usize) -> (f64, f64) {
    let inv_n = 1.0 / n;
    let (mut sn, mut sd) = (0.0, 0.0);
    if p == 0.0 {
        let beta = 2.0 * inv_n - 1.0;
        let (nodes, weights) = gauss_jacobi(m, beta);
        let scale = (0.5 * PI).powf(beta + 1.0) * q.powf(inv_n) * inv_n;
        for (&x, &w) in nodes.iter().zip(&weights) {
            let t = 0.5 * PI * (1.0 + x);
            let h = (0.5 * t).sin();
            let jac = if beta == 0.0 { 1.0 } else { (h / t).powf(beta) } * (0.5 * t).cos();
            let (fb, fd) = integrand(n, amp, vbar, q * h * h);
            sn += w * jac * fb;
            sd += w * jac * fd;
        }
        (scale * sn, scale * sd)
    } else {
        let (nodes, weights) = gauss_jacobi(m, 0.0);
        let half = 0.5 * (q - p);
        for (&x, &w) in nodes.iter().zip(&weights) {
            let t = 0.5 * PI * (1.0 + x);
            let (st, ct) = t.sin_cos();
            let y = p + half * (1.0 - ct);
            let jac = half * st * y.powf(inv_n - 1.0) * inv_n;
            let (fb, fd) = integrand(n, amp, vbar, y);
            sn += w * jac * fb;
            sd += w * jac * fd;
        }
        (0.5 * PI * sn, 0.5 * PI * sd)
    }
}

/// `(mu_ratio, its accuracy)` by the reference scheme.
pub fn mu_ratio(n: f64, vbar: f64, amp: f64) -> (f64, f64) {
    if amp == 0.0 {
        return (1.0, 0.0);
    }
    let c = if vbar < 1.0 { (1.0 - vbar * vbar).sqrt() } else { 0.0 };
    let y_of = |s: f64| (1.0 - amp * s).clamp(0.0, 1.0 + amp);
    let cuts = [0.0, y_of(1.0), y_of(c), y_of(-c), 1.0 + amp];
    let (mut nn, mut dd, mut err) = (0.0, 0.0, 0.0);
    // Permanent contact in closed form (its deficit D(vbar) is the spring's).
    let y1 = cuts[1];
    let z1 = y1.powf(1.0 / n);
    nn += z1 - z1 * y1 / (n + 1.0);
    if vbar < 1.0 {
        dd += amp * Spring::new(1e300, vbar).deficit * z1;
    }
    for k in 1..4 {
        let (p, q) = (cuts[k], cuts[k + 1]);
        if q <= p {
            continue;
        }
        let mut pieces = vec![];
        let mut lo = p;
        if n != 1.0 && p > 0.0 {
            while 4.0 * lo < q - lo {
                pieces.push((lo, 2.0 * lo));
                lo *= 2.0;
            }
        }
        pieces.push((lo, q));
        for (a, b) in pieces {
            let f1 = pass(n, amp, vbar, a, b, 96);
            let f2 = pass(n, amp, vbar, a, b, 128);
            nn += f2.0;
            dd += f2.1;
            err += (f2.0 - f1.0).abs() + (f2.1 - f1.1).abs();
        }
    }
    (1.0 - dd / nn, err / nn + 1e-15)
}
