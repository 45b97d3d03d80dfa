//! Tabulated shapes against the power laws they sample, bad tables, tables at
//! the edges of f64. (The MDR transform itself is unit-tested beside it:
//! `src/fricosc/src/contact/profile/tests.rs`.)

use std::path::PathBuf;
use tempfile::TempDir;

/// Write the table `rows` as `name` in a scratch folder of its own (removed
/// when the returned guard is dropped, also when the test fails).
fn write_table(name: &str, rows: impl Iterator<Item = (f64, f64)>) -> (TempDir, PathBuf) {
    let scratch = tempfile::Builder::new().prefix("fricosc-profile-").tempdir().unwrap();
    let path = scratch.path().join(name);
    let mut text = String::from("r,f\n");
    for (r, f) in rows {
        text += &format!("{r:?},{f:?}\n");
    }
    std::fs::write(&path, text).unwrap();
    (scratch, path)
}

fn grid(n: usize, max: f64) -> impl Iterator<Item = f64> {
    (0..n).map(move |i| max * i as f64 / (n - 1) as f64)
}

#[test]
fn a_tabulated_sphere_reproduces_parabolic_within_the_interpolation_error() {
    // Sphere of radius 1 indented by u0 = 1e-8: a paraboloid to relative ~1e-8.
    let (radius, u0) = (1.0f64, 1e-8f64);
    let rmax = 4.0 * (radius * u0).sqrt();
    let (_scratch, path) =
        write_table("sphere.csv", grid(300, rmax).map(|r| (r, radius - (radius * radius - r * r).sqrt())));
    let shape = crate::common::shape(&format!("profile:{}@{u0:?}", path.display())).unwrap();
    let parabolic = crate::common::shape("parabolic").unwrap();
    for (v, a) in [(0.3, 0.4), (0.6, 1.0), (0.2, 2.0), (0.9, 0.7)] {
        let t = crate::common::at::eval(&shape, v, a).unwrap();
        let p = crate::common::at::eval(&parabolic, v, a).unwrap();
        let interp = t.interpolation_error.unwrap();
        let err = (t.ratio.mu_ratio - p.ratio.mu_ratio).abs();
        // The sphere differs from the paraboloid by O(u0/R) = 1e-8 in g.
        assert!(err <= interp + t.error_estimate + 10.0 * u0 / radius, "v={v} a={a}: {err:e} > {interp:e}");
        assert!(interp < 1e-5, "v={v} a={a}: interpolation error {interp:e}");
    }
}

#[test]
fn a_tabulated_equivalent_profile_reproduces_the_power_law() {
    let (_scratch, path) = write_table("g.csv", grid(200, 2.0).map(|x| (x, x.powf(2.5))));
    let shape = crate::common::shape(&format!("gx:{}@1", path.display())).unwrap();
    let power = crate::common::shape("power:2.5").unwrap();
    for (v, a) in [(0.3, 0.4), (0.5, 1.5)] {
        let t = crate::common::at::eval(&shape, v, a).unwrap();
        let p = crate::common::at::eval(&power, v, a).unwrap();
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
        // Removed when dropped, also when the test fails.
        let scratch = tempfile::Builder::new().prefix("fricosc-bad-").tempdir().unwrap();
        let dir = scratch.path().to_path_buf();
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        let e = crate::common::shape(&format!("profile:{}@1", p.display())).unwrap_err().to_string();
        assert!(e.contains(frag), "{name}: {e}");
    }
    assert!(crate::common::shape("profile:/nonexistent.csv@1").unwrap_err().to_string().contains("cannot read"));
    assert!(crate::common::shape("profile:/tmp").unwrap_err().to_string().contains("mean indentation"));
    assert!(crate::common::shape("profile:/@1").unwrap_err().to_string().contains("cannot read"));
    assert!(crate::common::shape("gx:x.csv@-1").is_err());
}

/// Tables at the edges of f64: scaled before interpolation they give the same
/// answer at any scale, and a contact the table cannot resolve is refused, never
/// answered with a confident wrong value.
#[test]
fn tabulated_shapes_at_extreme_scales_are_right_or_refused() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-scale-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let write = |name: &str, rows: &[(f64, f64)]| {
        let p = dir.join(name);
        let text: String = rows.iter().map(|(x, g)| format!("{x:e},{g:e}\n")).collect();
        std::fs::write(&p, format!("x,g\n{text}")).unwrap();
        p.to_str().unwrap().to_string()
    };
    let eval = |spec: &str, v: f64, a: f64| crate::common::at::eval(&crate::common::shape(spec)?, v, a);
    let parabolic = crate::common::at::power(2.0, 0.3, 0.4, fricosc::DEFAULT_TOL).unwrap().ratio.mu_ratio;
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
    // And one inside the table.
    let path = write("inner-step.csv", &[(0.0, 0.0), (1.0, 1.0), (1.0 + 1e-13, 2.0), (2.0, 3.0)]);
    let e = eval(&format!("gx:{path}@1"), 0.3, 0.4).unwrap_err().to_string();
    assert!(e.contains("rows 1 and 2 are too close"), "{e}");
}

/// A profile whose MDR transform falls (a step) is refused with the largest g.
#[test]
fn a_non_monotone_transform_is_refused() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-step-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let p = dir.join("step.csv");
    std::fs::write(&p, "r,f\n0,0\n0.5,0\n0.9,0\n0.95,0.5\n1,1\n2,1\n").unwrap();
    let e = crate::common::shape(&format!("profile:{}@0.9", p.display())).unwrap_err().to_string();
    assert!(e.contains("decreases after x") && e.contains("largest g"), "{e}");
    // The largest g is at least the step's height (x/sqrt(x^2 - r^2) >= 1 in
    // the transform), so not the transform's first value 0.
    let largest: f64 = e.split("largest g = ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
    assert!(largest >= 1.0, "{e}");
}

/// At a subnormal amplitude the spring coordinate `(1 - G)/amp` overflows; the
/// fuzzer found "mean normal force inf" there (an internal error). The reduction
/// is linear in the amplitude at small amplitude, and matches the analytic
/// paraboloid's slope for a tabulated `g = x^2`.
#[test]
fn tabulated_contact_at_subnormal_amplitude() {
    let x: Vec<f64> = (0..=200).map(|i| 0.01 * i as f64).collect();
    let g: Vec<f64> = x.iter().map(|x| x * x).collect();
    let t = fricosc::contact::Table::from_columns(x, g, false, "square").unwrap().at(1.0).unwrap();
    let shape = fricosc::Shape::from_contact(std::sync::Arc::new(t));
    let slope = |a: f64| crate::common::at::eval(&shape, 0.3, a).unwrap().ratio.reduction / a;
    let (below, small) = (slope(1e-305), slope(1e-200));
    assert!(((below - small) / small).abs() < 1e-12, "{below} vs {small}");
    // A subnormal reduction carries only its own bits: 1.3e-314 has an ulp of
    // 4.9e-324, a relative 4e-10.
    let tiny = slope(2.1219957905e-314);
    assert!(((tiny - small) / small).abs() < 1e-9, "{tiny} vs {small}");
    let analytic = crate::common::at::power(2.0, 0.3, 1e-200, fricosc::DEFAULT_TOL).unwrap().ratio.reduction;
    let rel = (small - analytic / 1e-200).abs() / small;
    assert!(rel < 1e-6, "tabulated slope {small} vs paraboloid {}: {rel:e}", analytic / 1e-200);
    // The estimates scale with the amplitude too (computed at 1e-300 and
    // scaled: unscaled they would be those of 1e-300, the estimate's half an
    // ulp of 1 among them).
    for a in [1e-305, 2.1219957905e-314] {
        let e = crate::common::at::eval(&shape, 0.3, a).unwrap();
        let scale = a / 1e-300;
        assert!(e.error_estimate <= 1e-15 * scale, "amp {a:e}: estimate {:e}", e.error_estimate);
        let at = crate::common::at::eval(&shape, 0.3, 1e-300).unwrap();
        let interp = e.interpolation_error.unwrap();
        assert!(interp <= at.interpolation_error.unwrap() * scale * 1.0000001 + 1e-323, "amp {a:e}: {interp:e}");
    }
}

/// A tabulated paraboloid (`g = x^2` sampled: the cubic interpolant is exact
/// for it) where `mu` is small (`amp` at and above 1, `vbar -> 0`): `mu` keeps
/// its relative accuracy (from the tangential force's own integral; from `1 -
/// reduction` it kept only ~5e-16 absolute: relative errors of 7.3e-7 and
/// 2.0e-6 at `vbar = 1e-10`, `amp` 1 and 2), within its estimate of the power
/// law's 40-digit-checked value.
#[test]
fn a_tabulated_paraboloid_keeps_small_mu_to_its_relative_accuracy() {
    let (_scratch, path) = write_table("g2.csv", grid(401, 4.0).map(|x| (x, x * x)));
    let shape = crate::common::shape(&format!("gx:{}@1", path.display())).unwrap();
    let parabolic = crate::common::shape("parabolic").unwrap();
    for a in [0.999, 1.0, 2.0] {
        for v in [1e-2, 1e-6, 1e-10] {
            let t = crate::common::at::eval(&shape, v, a).unwrap();
            let p = crate::common::at::eval(&parabolic, v, a).unwrap();
            let err = (t.ratio.mu_ratio - p.ratio.mu_ratio).abs();
            let interp = t.interpolation_error.unwrap();
            assert!(err <= t.error_estimate + p.error_estimate + interp, "a={a} v={v}: {err:e}");
            // An estimate, not a floor: relative to mu, within the published
            // 1e-12 (3.4e-13 at most here, where the truncation part of the
            // 16/32-point difference dominates).
            assert!(t.error_estimate <= 1e-12 * p.ratio.mu_ratio, "a={a} v={v}: {:e}", t.error_estimate);
            // A regression bar at 10 times the worst observed (3.5e-15), within the published 1e-12.
            assert!(err <= 4e-14 * p.ratio.mu_ratio, "a={a} v={v}: relative {:e}", err / p.ratio.mu_ratio);
        }
    }
}

/// The table format at the library level (the command line's tests see it
/// through files): comma, semicolon and blank separators, one header line, `#`
/// comments and blank lines give the same contact, and a second column that
/// does not start at 0 is shifted to; messages name the file's line.
#[test]
fn the_table_format_and_the_lines_its_messages_name() {
    use fricosc::contact::Table;
    let at = |text: &str| Table::parse(text, "t", false).unwrap().at(1.0).unwrap().named("t");
    let base = at("x,g\n0,0\n0.5,0.25\n1,1\n1.5,2.25\n2,4\n");
    for text in [
        "x;g\n0;0\n0.5;0.25\n1;1\n1.5;2.25\n2;4\n",
        "x g\n0 0\n0.5\t0.25\n1  1\n1.5 2.25\n2 4\n",
        "# a comment\n\nx,g\n0,0 # after a row\n0.5,0.25\n\n1,1\n1.5,2.25\n2,4\n",
        "x,g\n0,5\n0.5,5.25\n1,6\n1.5,7.25\n2,9\n",
    ] {
        assert_eq!(at(text), base, "{text:?}");
    }
    for (text, message) in [
        ("x,g\n0,0\n1,1\n1,2\n2,3\n", "t: line 4: the first column must increase strictly"),
        ("x,g\n0,0\n1,1\n0.5,2\n2,3\n", "t: line 4: the first column must increase strictly"),
        ("# c\nx,g\n0,0\n1,1\n2,0.5\n3,4\n", "t: line 5: the profile must not decrease"),
        ("x,g\n0,0\n\n1,inf\n2,3\n", "t: line 4: values must be finite"),
        ("x,g\n0,0\n1,1\n2,x\n", "t: line 4: expected two numbers"),
        ("x,g\n0,0\n1,1,1\n", "t: line 3: expected two numbers"),
    ] {
        let e = Table::parse(text, "t", false).unwrap_err().to_string();
        assert!(e.contains(message), "{text:?}: {e}");
    }
}

/// `MAX_TABLE_ROWS` rows are read (an equivalent profile: no transform to
/// wait for), one more is refused before anything is built, from text and
/// from arrays alike.
#[test]
fn a_table_of_the_most_rows_is_read_and_one_more_refused() {
    use fricosc::contact::{Table, MAX_TABLE_ROWS};
    let rows = |n: usize| -> (Vec<f64>, Vec<f64>) { (0..n).map(|i| (i as f64, (i * i) as f64)).unzip() };
    let text = |n: usize| -> String {
        let mut s = String::with_capacity(24 * n);
        for i in 0..n {
            s += &format!("{i},{}\n", i * i);
        }
        s
    };
    let t = Table::parse(&text(MAX_TABLE_ROWS), "t", false).unwrap();
    assert_eq!(t.max_g(), ((MAX_TABLE_ROWS - 1) * (MAX_TABLE_ROWS - 1)) as f64);
    let e = Table::parse(&text(MAX_TABLE_ROWS + 1), "t", false).unwrap_err();
    assert!(matches!(e, fricosc::Error::TooLarge { .. }), "{e}");
    let (x, g) = rows(MAX_TABLE_ROWS);
    assert!(Table::from_columns(x, g, false, "t").is_ok());
    let (x, g) = rows(MAX_TABLE_ROWS + 1);
    let e = Table::from_columns(x, g, false, "t").unwrap_err();
    assert!(matches!(e, fricosc::Error::TooLarge { .. }), "{e}");
}

/// `Table::at` refuses a mean indentation that is not finite and positive,
/// naming it, and one the table does not reach; `max_g` is the table's largest
/// `g`, transformed for a profile (`f = r^2/2` has `g = x^2`).
#[test]
fn a_table_at_a_mean_indentation_and_its_largest_g() {
    use fricosc::contact::Table;
    let x: Vec<f64> = (0..=40).map(|i| 0.05 * i as f64).collect();
    let g: Vec<f64> = x.iter().map(|x| x * x).collect();
    let f: Vec<f64> = x.iter().map(|x| 0.5 * x * x).collect();
    let table = Table::from_columns(x.clone(), g, false, "squares").unwrap();
    assert_eq!(table.max_g(), 4.0);
    let profile = Table::from_columns(x, f, true, "paraboloid").unwrap();
    assert!((profile.max_g() - 4.0).abs() <= 1e-14, "{}", profile.max_g());
    for u0 in [-1.0, 0.0, -0.0, f64::NAN, f64::INFINITY] {
        let e = table.at(u0).unwrap_err().to_string();
        assert!(e.contains("U0") && e.contains("the mean indentation must be finite and > 0"), "{u0}: {e}");
    }
    for u0 in [4.0000001, 1e300] {
        let e = table.at(u0).unwrap_err().to_string();
        assert!(e.contains("the contact is wider than the table"), "{u0}: {e}");
    }
    assert!((table.at(4.0).unwrap().contact_radius - 2.0).abs() <= 1e-15);
}

/// Through the `Contact` trait: a tabulated contact's reach (`G(z) = 1 + amp`,
/// `z = sqrt(1 + amp)` for `g = x^2` at `U0 = 1`) and its refusal where the
/// table ends first, its breakpoints (the knots over the contact radius, where
/// the sliding-direction quadrature cuts), and the exact answers without a
/// stick (`vbar >= 1`, `amp = 0`: `mu = 1` with no error at all).
#[test]
fn a_tabulated_contact_through_the_trait() {
    use fricosc::contact::Contact;
    let x: Vec<f64> = (0..=40).map(|i| 0.05 * i as f64).collect();
    let g: Vec<f64> = x.iter().map(|x| x * x).collect();
    let t = fricosc::contact::Table::from_columns(x.clone(), g, false, "squares").unwrap().at(1.0).unwrap();
    for amp in [0.0, 0.5, 2.0, 3.0] {
        let z = t.reach(amp).unwrap();
        assert!((z - (1.0 + amp).sqrt()).abs() <= 1e-15, "amp {amp}: {z}");
    }
    let e = t.reach(3.0000001).unwrap_err().to_string();
    assert!(e.contains("the tabulated profile ends at g = 4.0 U0"), "{e}");
    let e = t.evaluate(0.3, 3.0000001, fricosc::DEFAULT_TOL).unwrap_err().to_string();
    assert!(e.contains("amp") && e.contains("the tabulated profile ends at g = 4.0 U0"), "{e}");
    assert!(t.evaluate(0.3, 3.0, fricosc::DEFAULT_TOL).is_ok());
    // The mean normal force without oscillation is the static force at the mean indentation.
    assert_eq!(t.mean_normal(0.0).unwrap(), t.static_force(1.0));
    assert!((t.static_force(1.0) - 4.0 / 3.0).abs() <= 1e-14);
    assert!(t.reach(-1.0).is_err());
    let knots: Vec<f64> = x.iter().map(|x| x / t.contact_radius).collect();
    assert_eq!(t.breakpoints(), knots);
    // The profile at a knot, at the last one and beyond it (the end cubic
    // extrapolates; exact for a quadratic).
    for z in [0.0, 0.05, 1.0, 1.97, 2.0, 2.5] {
        // Extrapolation amplifies rounding (5.7e-14 observed at 2.5).
        let tol = if z <= 2.0 { 1e-14 } else { 1e-13 };
        assert!((t.equivalent_profile(z) - z * z).abs() <= tol, "z {z}: {}", t.equivalent_profile(z));
    }
    for (vbar, amp) in [(1.0, 0.5), (1.5, 2.0), (0.3, 0.0)] {
        let e = t.evaluate(vbar, amp, fricosc::DEFAULT_TOL).unwrap();
        assert_eq!((e.ratio.mu_ratio, e.ratio.reduction, e.error_estimate), (1.0, 0.0, 0.0), "{vbar} {amp}");
        assert_eq!(e.interpolation_error, Some(0.0));
    }
}
