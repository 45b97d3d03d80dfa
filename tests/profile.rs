//! Tabulated shapes: the MDR transform (Hertz, Love) and tabulated profiles
//! against the power laws they sample.
use fricosc::profile::{mdr_transform, normal_force, Pchip};
use fricosc::shape::{evaluate, Shape};
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
    let shape = Shape::parse(&format!("profile:{}@{u0:?}", path.display())).unwrap();
    let parabolic = Shape::parse("parabolic").unwrap();
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
    let shape = Shape::parse(&format!("gx:{}@1", path.display())).unwrap();
    let power = Shape::parse("power:2.5").unwrap();
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
        let e = Shape::parse(&format!("profile:{}@1", p.display())).unwrap_err().to_string();
        assert!(e.contains(frag), "{name}: {e}");
    }
    assert!(Shape::parse("profile:/nonexistent.csv@1").unwrap_err().to_string().contains("cannot read"));
    assert!(Shape::parse("profile:/tmp").unwrap_err().to_string().contains("mean indentation"));
    assert!(Shape::parse("profile:/@1").unwrap_err().to_string().contains("cannot read"));
    assert!(Shape::parse("gx:x.csv@-1").is_err());
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
    let eval = |spec: &str, v: f64, a: f64| fricosc::shape::evaluate(&fricosc::shape::Shape::parse(spec)?, v, a);
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
    let e = fricosc::shape::Shape::parse(&format!("profile:{}@0.9", p.display())).unwrap_err().to_string();
    assert!(e.contains("decreases after x") && e.contains("largest g"), "{e}");
}

/// Exactly one header line is allowed (`/etc/passwd` used to give "found 0 rows").
#[test]
fn only_one_header_line() {
    let dir = std::env::temp_dir().join(format!("fricosc-hdr-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("two.csv");
    std::fs::write(&p, "r,f\nradius,height\n0,0\n1,1\n2,4\n").unwrap();
    let e = fricosc::profile::read_table(p.to_str().unwrap()).unwrap_err().to_string();
    assert!(e.contains("line 2: expected two numbers"), "{e}");
}
