//! Tabulated shapes: the MDR transform (Hertz, Love) and tabulated profiles
//! against the power laws they sample.
use fricosc::profile::{mdr_transform, normal_force, Pchip};
use fricosc::shape::evaluate;
use std::f64::consts::PI;
use std::path::PathBuf;

fn write_table(name: &str, rows: impl Iterator<Item = (f64, f64)>) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("fricosc-profile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    let mut text = String::from("r,f\n");
    for (r, f) in rows {
        text += &format!("{r:?},{f:?}\n");
    }
    std::fs::write(&path, text).unwrap();
    path
}

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

#[test]
fn a_tabulated_sphere_reproduces_parabolic_within_the_interpolation_error() {
    // Sphere of radius 1 indented by u0 = 1e-8: a paraboloid to relative ~1e-8.
    let (radius, u0) = (1.0f64, 1e-8f64);
    let rmax = 4.0 * (radius * u0).sqrt();
    let path = write_table("sphere.csv", grid(300, rmax).map(|r| (r, radius - (radius * radius - r * r).sqrt())));
    let shape = fricosc::cli::input::parse_shape(&format!("profile:{}@{u0:?}", path.display())).unwrap();
    let parabolic = fricosc::cli::input::parse_shape("parabolic").unwrap();
    for (v, a) in [(0.3, 0.4), (0.6, 1.0), (0.2, 2.0), (0.9, 0.7)] {
        let t = evaluate(&shape, v, a).unwrap();
        let p = evaluate(&parabolic, v, a).unwrap();
        let interp = t.interpolation_error.unwrap();
        let err = (t.ratio.mu_ratio - p.ratio.mu_ratio).abs();
        // The sphere differs from the paraboloid by O(u0/R) = 1e-8 in g.
        assert!(err <= interp + t.error_estimate + 10.0 * u0 / radius, "v={v} a={a}: {err:e} > {interp:e}");
        assert!(interp < 1e-5, "v={v} a={a}: interpolation error {interp:e}");
    }
}

#[test]
fn a_tabulated_equivalent_profile_reproduces_the_power_law() {
    let path = write_table("g.csv", grid(200, 2.0).map(|x| (x, x.powf(2.5))));
    let shape = fricosc::cli::input::parse_shape(&format!("gx:{}@1", path.display())).unwrap();
    let power = fricosc::cli::input::parse_shape("power:2.5").unwrap();
    for (v, a) in [(0.3, 0.4), (0.5, 1.5)] {
        let t = evaluate(&shape, v, a).unwrap();
        let p = evaluate(&power, v, a).unwrap();
        let err = (t.ratio.mu_ratio - p.ratio.mu_ratio).abs();
        assert!(err <= t.interpolation_error.unwrap() + t.error_estimate, "v={v} a={a}: {err:e}");
    }
}

#[test]
fn bad_tables_are_errors() {
    let cases: &[(&str, &str, &str)] = &[
        ("nonmono.csv", "0,0\n1,1\n2,0.5\n", "must not decrease"),
        ("nan.csv", "0,0\n1,nan\n2,3\n", "finite"),
        ("short.csv", "0,0\n1,1\n", "at least 3 rows"),
        ("axis.csv", "1,0\n2,1\n3,2\n", "start at 0"),
        ("text.csv", "r,f\n0,0\n1,x\n", "two numbers"),
        ("empty.csv", "", "at least 3 rows"),
    ];
    for (name, text, frag) in cases {
        let dir = std::env::temp_dir().join(format!("fricosc-bad-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        let e = fricosc::cli::input::parse_shape(&format!("profile:{}@1", p.display())).unwrap_err().to_string();
        assert!(e.contains(frag), "{name}: {e}");
    }
    assert!(fricosc::cli::input::parse_shape("profile:/nonexistent.csv@1")
        .unwrap_err()
        .to_string()
        .contains("cannot read"));
    assert!(fricosc::cli::input::parse_shape("profile:/tmp").unwrap_err().to_string().contains("mean indentation"));
    assert!(fricosc::cli::input::parse_shape("profile:/@1").unwrap_err().to_string().contains("cannot read"));
    assert!(fricosc::cli::input::parse_shape("gx:x.csv@-1").is_err());
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

/// Tables at the edges of f64: scaled before interpolation they give the same
/// answer at any scale, and a contact the table cannot resolve is refused, never
/// answered with a confident wrong value.
#[test]
fn tabulated_shapes_at_extreme_scales_are_right_or_refused() {
    let dir = std::env::temp_dir().join(format!("fricosc-scale-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, rows: &[(f64, f64)]| {
        let p = dir.join(name);
        let text: String = rows.iter().map(|(x, g)| format!("{x:e},{g:e}\n")).collect();
        std::fs::write(&p, format!("x,g\n{text}")).unwrap();
        p.to_str().unwrap().to_string()
    };
    let eval = |spec: &str, v: f64, a: f64| fricosc::shape::evaluate(&fricosc::cli::input::parse_shape(spec)?, v, a);
    let parabolic = fricosc::mdr::power_law(2.0, 0.3, 0.4, fricosc::mdr::DEFAULT_TOL, false).unwrap().ratio.mu_ratio;
    // g = x^2 on 0..2 (41 rows) at several scales of x and g.
    for (sx, sg) in [(1.0, 1.0), (1e-150, 1e-300), (1e150, 1e300), (1e-300, 1e-300)] {
        let rows: Vec<(f64, f64)> = (0..=40).map(|i| 0.05 * i as f64).map(|x| (x * sx, x * x * sg)).collect();
        let path = write(&format!("sq{sx:e}.csv"), &rows);
        let e = eval(&format!("gx:{path}@{:e}", 1.0 * sg), 0.3, 0.4).unwrap();
        let err = (e.ratio.mu_ratio - parabolic).abs();
        assert!(
            err <= e.interpolation_error.unwrap() + 1e-12,
            "scale {sx:e}/{sg:e}: {} vs {parabolic}",
            e.ratio.mu_ratio
        );
    }
    // The contact far inside the first interval (the issue's @1e-40: the cone's value with a tiny estimate).
    let rows: Vec<(f64, f64)> = (0..=40).map(|i| 0.05 * i as f64).map(|x| (x, x * x)).collect();
    let path = write("sq.csv", &rows);
    for u0 in ["1e-40", "1e-150", "1e-300"] {
        let e = eval(&format!("gx:{path}@{u0}"), 0.3, 0.4).unwrap_err().to_string();
        assert!(e.contains("does not resolve the contact"), "{u0}: {e}");
    }
    // A near-vertical first step.
    let path = write("step.csv", &[(0.0, 0.0), (1e-300, 1.0), (1.0, 2.0), (2.0, 3.0)]);
    assert!(eval(&format!("gx:{path}@1"), 0.3, 0.4).unwrap_err().to_string().contains("too close"));
}

/// A profile whose MDR transform falls (a step) is refused with the largest g.
#[test]
fn a_non_monotone_transform_is_refused() {
    let dir = std::env::temp_dir().join(format!("fricosc-step-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("step.csv");
    std::fs::write(&p, "r,f\n0,0\n0.5,0\n0.9,0\n0.95,0.5\n1,1\n2,1\n").unwrap();
    let e = fricosc::cli::input::parse_shape(&format!("profile:{}@0.9", p.display())).unwrap_err().to_string();
    assert!(e.contains("decreases after x") && e.contains("largest g"), "{e}");
}

/// Exactly one header line is allowed (`/etc/passwd` used to give "found 0 rows").
#[test]
fn only_one_header_line() {
    let dir = std::env::temp_dir().join(format!("fricosc-hdr-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("two.csv");
    std::fs::write(&p, "r,f\nradius,height\n0,0\n1,1\n2,4\n").unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    let e = fricosc::profile::parse_table(&text, p.to_str().unwrap()).unwrap_err().to_string();
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
    use fricosc::profile::mdr_transform_knots;
    let mut worst = 0.0f64;
    for p in transform_tables(3000) {
        let fast = mdr_transform_knots(&p);
        for (i, &x) in p.knots().iter().enumerate() {
            let direct = mdr_transform(&p, x);
            worst = worst.max((fast[i] - direct).abs() / direct.abs().max(f64::MIN_POSITIVE));
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
    let rule = fricosc::quad::rule(20, 0.0);
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
            worst = worst.max((mdr_transform(p, x) - exact).abs() / exact);
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
    use fricosc::profile::mdr_transform_knots;
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

/// At a subnormal amplitude the spring coordinate `(1 - G)/amp` overflows; the
/// fuzzer found "mean normal force inf" there (an internal error). The reduction
/// is linear in the amplitude at small amplitude, and matches the analytic
/// paraboloid's slope for a tabulated `g = x^2`.
#[test]
fn tabulated_contact_at_subnormal_amplitude() {
    let x: Vec<f64> = (0..=200).map(|i| 0.01 * i as f64).collect();
    let g: Vec<f64> = x.iter().map(|x| x * x).collect();
    let t = fricosc::profile::Table::from_columns(x, g, false, "square").unwrap().at(1.0).unwrap();
    let slope = |a: f64| fricosc::profile::evaluate(&t, 0.3, a).unwrap().ratio.reduction / a;
    let (below, small) = (slope(1e-305), slope(1e-200));
    assert!(((below - small) / small).abs() < 1e-12, "{below} vs {small}");
    // A subnormal reduction carries only its own bits: 1.3e-314 has an ulp of
    // 4.9e-324, a relative 4e-10.
    let tiny = slope(2.1219957905e-314);
    assert!(((tiny - small) / small).abs() < 1e-9, "{tiny} vs {small}");
    let analytic = fricosc::mdr::power_law(2.0, 0.3, 1e-200, fricosc::mdr::DEFAULT_TOL, false).unwrap().ratio.reduction;
    let rel = (small - analytic / 1e-200).abs() / small;
    assert!(rel < 1e-6, "tabulated slope {small} vs paraboloid {}: {rel:e}", analytic / 1e-200);
}
