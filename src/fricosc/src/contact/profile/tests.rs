//! Unit tests of the tabulated profiles' internals: the MDR transform (closed
//! form per interval, summed hierarchically) against Hertz, Love, a direct sum,
//! a quadrature in the angle and 40-digit values; the table reader.
use super::transform::*;
use super::*;
use proptest::prelude::*;
use std::f64::consts::PI;

fn grid(n: usize, max: f64) -> impl Iterator<Item = f64> {
    (0..n).map(move |i| max * i as f64 / (n - 1) as f64)
}

#[test]
fn transform_of_a_paraboloid_is_x2_over_r_and_gives_hertz() {
    let r_sphere = 2.0;
    let r: Vec<f64> = grid(400, 3.0).collect();
    let f = Pchip::new(r.clone(), r.iter().map(|x| x * x / (2.0 * r_sphere)).collect());
    for x in [0.1, 0.7, 1.3, 2.9] {
        let g = mdr_transform(&f, x);
        assert!((g / (x * x / r_sphere) - 1.0).abs() < 1e-13, "x={x}: {g}");
    }
    let gx: Vec<f64> = r.iter().map(|&x| mdr_transform(&f, x)).collect();
    let g = Pchip::new(r, gx);
    for d in [0.05, 0.3, 1.0] {
        // Hertz: F = (4/3) E* R^(1/2) d^(3/2), here with E* = 1.
        let hertz = 4.0 / 3.0 * r_sphere.sqrt() * d * d.sqrt();
        assert!((normal_force(&g, d) / hertz - 1.0).abs() < 1e-13, "d={d}");
    }
}

#[test]
fn transform_of_a_cone_is_linear_and_gives_love() {
    let tan_theta: f64 = 0.3;
    let r: Vec<f64> = grid(50, 4.0).collect();
    let f = Pchip::new(r.clone(), r.iter().map(|x| x * tan_theta).collect());
    let gx: Vec<f64> = r.iter().map(|&x| mdr_transform(&f, x)).collect();
    for (&x, &g) in r.iter().zip(&gx) {
        assert!((g - PI / 2.0 * x * tan_theta).abs() < 1e-14 * (1.0 + x), "x={x}");
    }
    let g = Pchip::new(r, gx);
    for d in [0.1, 0.5, 1.2] {
        // Love: F = (2/pi) E* d^2 / tan(theta).
        let love = 2.0 / PI * d * d / tan_theta;
        assert!((normal_force(&g, d) / love - 1.0).abs() < 1e-13, "d={d}");
    }
}

/// A cone tabulated on uneven knots, each far from the last (ratios up to
/// 1e4; slope 1, the heights the knots themselves, so that the interpolant is
/// the cone itself): `g(x) = (pi/2) x` at every knot to a few
/// ulp, directly and by the hierarchical sum. An interval `[r0, x]` with
/// `r0 << x` spans an angle just below `pi/2`, where `asin` of its sine would
/// lose `eps x/r0` (2.7e-13 here): the closed form takes the angle from
/// `atan2` there, and from its series only below 0.1.
#[test]
fn transform_of_a_cone_on_far_apart_knots_keeps_every_digit() {
    let r = vec![0.0, 1e-7, 1e-3, 0.3, 1.0, 1000.0, 1001.0, 3000.0];
    let f = Pchip::new(r.clone(), r.clone());
    let fast = mdr_transform_knots(&f);
    let mut worst = 0.0f64;
    for (i, &x) in r.iter().enumerate().skip(1) {
        let exact = PI / 2.0 * x;
        for g in [mdr_transform(&f, x), fast[i]] {
            worst = crate::numerics::worst_of(worst, (g / exact - 1.0).abs());
        }
    }
    eprintln!("cone on far-apart knots: {worst:e}");
    // Observed 2.2e-16 (asin's angle: 2.7e-13).
    assert!(worst < 2.2e-15, "{worst:e}");
}

#[test]
fn transform_of_a_sphere_tends_to_hertz_at_small_depth() {
    // f = R - sqrt(R^2 - r^2); Hertz holds as d/R -> 0, the deviation is O(d/R).
    let radius = 1.0f64;
    let r: Vec<f64> = grid(600, 0.1).collect();
    let f = Pchip::new(r.clone(), r.iter().map(|x| radius - (radius * radius - x * x).sqrt()).collect());
    let g = Pchip::new(r.clone(), r.iter().map(|&x| mdr_transform(&f, x)).collect());
    let dev = |d: f64| normal_force(&g, d) / (4.0 / 3.0 * radius.sqrt() * d * d.sqrt()) - 1.0;
    let (d1, d2) = (dev(1e-3), dev(1e-4));
    assert!(d1.abs() < 2e-3 && d2.abs() < 2e-4, "{d1:e} {d2:e}");
    assert!((d1 / d2 - 10.0).abs() < 0.5, "not O(d/R): {d1:e} {d2:e}");
}

/// Exactly one header line is allowed (`/etc/passwd` used to give "found 0 rows").
#[test]
fn only_one_header_line() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-hdr-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let p = dir.join("two.csv");
    std::fs::write(&p, "r,f\nradius,height\n0,0\n1,1\n2,4\n").unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    let e = parse_table(&text, p.to_str().unwrap()).unwrap_err().to_string();
    assert!(e.contains("line 2: expected two numbers"), "{e}");
}

/// Tables for the transform tests: uniform, graded towards the axis and
/// randomly spaced knots, each with a smooth profile and with random steps
/// (rough data, where the cubic pieces' derivatives jump from knot to knot).
fn transform_tables(n: usize) -> Vec<Pchip> {
    let mut seed = 12345u64;
    let mut rand = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let uniform: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
    let graded: Vec<f64> = (0..n).map(|i| (i as f64 / (n - 1) as f64).powi(3)).collect();
    let mut jitter = vec![0.0];
    for _ in 1..n {
        let last = *jitter.last().unwrap();
        jitter.push(last + 0.01 + rand());
    }
    let mut tables = Vec::new();
    for r in [uniform, graded, jitter] {
        let top = r[n - 1];
        let smooth: Vec<f64> = r.iter().map(|x| (x / top).powi(2) / 2.0 + (x / top).powi(4)).collect();
        let mut steps = vec![0.0];
        for _ in 1..n {
            let last = *steps.last().unwrap();
            steps.push(last + rand() * rand());
        }
        tables.push(Pchip::new(r.clone(), smooth));
        tables.push(Pchip::new(r, steps));
    }
    tables
}

/// The hierarchical transform at the knots agrees with the direct sum over the
/// intervals below each knot; a misplaced block boundary, a source summed twice
/// or too few Chebyshev points shows up far above rounding.
#[test]
fn fast_transform_matches_direct_sum() {
    let mut worst = 0.0f64;
    for p in transform_tables(3000) {
        let fast = mdr_transform_knots(&p);
        for (i, &x) in p.knots().iter().enumerate() {
            let direct = mdr_transform(&p, x);
            worst = crate::numerics::worst_of(worst, (fast[i] - direct).abs() / direct.abs().max(f64::MIN_POSITIVE));
        }
    }
    // Observed 5.7e-15 (relative, every knot): the interpolated far sums agree
    // with the direct ones to rounding.
    assert!(worst < 2e-14, "hierarchical vs direct transform: {worst:e}");
}

/// The closed-form interval integrals against an independent quadrature of
/// `g(x) = x int_0^(pi/2) f'(x sin t) dt` (20-point Gauss-Legendre in `t` on
/// each interval's image, `t = atan2(r, sqrt(x^2 - r^2))`, `f'` from the
/// interpolant's own derivative) on the smooth tables. (On rough data this
/// quadrature is itself ill-conditioned, `f''/f'` times the rounding of
/// `x sin t`; the 40-digit test below covers that case.)
#[test]
fn transform_matches_quadrature_in_the_angle() {
    let rule = crate::quad::rule(20, 0.0);
    let mut worst = 0.0f64;
    for p in transform_tables(400).iter().step_by(2) {
        let r = p.knots();
        for j in (1..r.len()).step_by(7) {
            let x = r[j];
            let mut sum = 0.0;
            for w in r[..=j].windows(2) {
                let angle = |r: f64| r.atan2(((x - r) * (x + r)).sqrt());
                let (t0, t1) = (angle(w[0]), angle(w[1]));
                let h = 0.5 * (t1 - t0);
                for (&u, &wt) in rule.nodes.iter().zip(&rule.weights) {
                    sum += wt * h * p.eval(x * (t0 + h * (1.0 + u)).sin()).1;
                }
            }
            let exact = x * sum;
            // Relative to |exact|: a wrong derivative can make it negative (a
            // negative ratio would vanish in the max), or infinite where it
            // divides by a zero end slope (and a NaN would).
            worst = crate::numerics::worst_of(worst, (mdr_transform(p, x) - exact).abs() / exact.abs());
        }
    }
    // Observed 2.9e-15 relative.
    assert!(worst < 3e-14, "closed form vs quadrature in t: {worst:e}");
}

/// A rough table (steep steps beside flat pieces, uneven spacing) against
/// 40-digit values from `data/scripts/mdr_transform_rough.py`, which rebuilds the
/// same interpolant and integrates each cubic in the angle. (A difference of
/// antiderivatives, the transform before this one, was off by 1e-8 relative on
/// a 3000-row table of random steps.)
#[test]
fn transform_of_a_rough_table_matches_forty_digit_values() {
    let n = 60;
    let r: Vec<f64> = (0..n).map(|i| if i == 0 { 0.0 } else { i as f64 + ((7 * i) % 11) as f64 / 13.0 }).collect();
    let mut f = vec![0.0];
    for i in 1..n {
        let last = f[i - 1];
        f.push(last + ((5 * i) % 17) as f64 / 19.0);
    }
    let p = Pchip::new(r, f);
    let all = mdr_transform_knots(&p);
    #[allow(clippy::excessive_precision)]
    let exact = [
        (1, 0.62005118162956443359),
        (7, 3.9149113209678732038),
        (20, 13.766927586502410389),
        (41, 25.705797303866612382),
        (59, 38.262597312990320903),
    ];
    for (j, g) in exact {
        let x = p.knots()[j];
        for (how, got) in [("direct", mdr_transform(&p, x)), ("hierarchical", all[j])] {
            let rel = ((got - g) / g).abs();
            // Observed 4.1e-16.
            assert!(rel < 4e-15, "{how} g at knot {j}: {got:?}, exact {g:?} (relative {rel:e})");
        }
    }
}

proptest! {
        /// The hierarchical transform at the knots equals the direct sum on random
        /// rough tables (up to 600 rows, so the far sums are interpolated).
        #[test]
        fn hierarchical_transform_equals_direct(steps in prop::collection::vec((1e-4f64..1.0, 0.0f64..2.0), 40..600)) {
            let (mut x, mut f) = (vec![0.0], vec![0.0]);
            for (dx, df) in steps {
                x.push(x[x.len() - 1] + dx);
                f.push(f[f.len() - 1] + df * df * df);
            }
            let p = Pchip::new(x, f);
            let fast = mdr_transform_knots(&p);
            for (i, &xi) in p.knots().iter().enumerate().skip(1) {
                let direct = mdr_transform(&p, xi);
                let scale = direct.abs().max(1e-300);
                prop_assert!((fast[i] - direct).abs() <= 2e-14 * scale, "knot {i}: {} vs {direct}", fast[i]);
            }
        }
}
