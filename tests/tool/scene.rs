//! Physical scenes: unit invariance, load control, stiffness checks, the schema, the examples.
use fricosc::scene::SceneResult;
use fricosc_cli::scene::{parse, solve};
use std::f64::consts::PI;

/// The answer of a scene with one amplitude.
fn run(json: &str) -> SceneResult {
    let mut r = solve(&parse(json, "test.json").unwrap(), "test.json").unwrap();
    assert_eq!(r.len(), 1);
    r.remove(0)
}

fn sphere(e: f64, r: f64, u0: f64, du: f64, f: f64, v: &[f64]) -> String {
    format!(
        r#"{{"materials": {{"e1_pa": {e:?}, "nu1": 0.3, "e2_pa": {e:?}, "nu2": 0.3}}, "mu0": 0.4,
            "indenter": {{"sphere": {{"radius_m": {r:?}}}}}, "loading": {{"mean_indentation_m": {u0:?}}},
            "oscillation": {{"amplitude_m": {du:?}, "frequency_hz": {f:?}}}, "velocity": {{"values_m_per_s": {v:?}}}}}"#
    )
}

#[test]
fn scenes_in_different_units_with_the_same_vbar_and_amp_agree_to_1e_14() {
    let a = run(&sphere(2e11, 5e-3, 1e-6, 1.3e-6, 1e3, &[1e-5, 3e-4, 1e-3]));
    // Every dimension rescaled: moduli x 1e-4, lengths x 1e3, frequency x 1e-2;
    // vbar ~ v/(omega du): velocities scale with omega du (x 10).
    let b = run(&sphere(2e7, 5.0, 1e-3, 1.3e-3, 10.0, &[1e-4, 3e-3, 1e-2]));
    assert!((a.amplitude_ratio / b.amplitude_ratio - 1.0).abs() < 1e-15);
    for (x, y) in a.rows.iter().zip(b.rows.iter()) {
        assert!((x.vbar / y.vbar - 1.0).abs() < 1e-14);
        assert!((x.mu_ratio - y.mu_ratio).abs() < 1e-14, "{} vs {}", x.mu_ratio, y.mu_ratio);
    }
}

#[test]
fn load_control_round_trips_to_1e_12() {
    // Forces above each contact's floor (the mean force at zero mean indentation,
    // which the oscillation alone produces): jumping and non-jumping solutions.
    let cases = [
        (0.5e-6, r#"{"sphere": {"radius_m": 0.01}}"#, [5.0, 50.0, 500.0]),
        (3e-6, r#"{"cone": {"slope": 0.2}}"#, [10.0, 100.0, 1000.0]),
        (2e-6, r#"{"flat_punch": {"radius_m": 0.002}}"#, [500.0, 5000.0, 50000.0]),
    ];
    for (du, shape, forces) in cases {
        let load = |loading: &str| {
            format!(
                r#"{{"materials": {{"e1_pa": 1e11, "nu1": 0.25, "e2_pa": 2e11, "nu2": 0.3}}, "mu0": 0.3, "indenter": {shape},
                    "loading": {loading}, "oscillation": {{"amplitude_m": {du:?}, "frequency_hz": 50}},
                    "velocity": {{"values_m_per_s": [0.001]}}}}"#
            )
        };
        for f in forces {
            let solved = run(&load(&format!(r#"{{"mean_normal_force_n": {f:?}}}"#)));
            let back = run(&load(&format!(r#"{{"mean_indentation_m": {:?}}}"#, solved.mean_indentation_m)));
            assert!((back.mean_normal_force_n / f - 1.0).abs() < 1e-12, "{shape} F={f}: {}", back.mean_normal_force_n);
            assert!(solved.note.contains("load control"));
        }
    }
}

#[test]
fn hertz_and_flat_punch_stiffness() {
    // A vanishing oscillation (du/u0 = 1e-9, an O(amp^2) = 1e-18 change of the
    // mean force; amplitude 0 itself is refused): Hertz's
    // F = (4/3) E* R^(1/2) u0^(3/2), kz = 2 E* sqrt(R u0).
    let (e, r, u0) = (2.1e11f64, 0.01f64, 2e-6f64);
    let s = run(&sphere(e, r, u0, u0 * 1e-9, 100.0, &[0.01]));
    let e_star = e / (2.0 * (1.0 - 0.09));
    assert!((s.e_star_pa / e_star - 1.0).abs() < 1e-15);
    let hertz = 4.0 / 3.0 * e_star * r.sqrt() * u0.powf(1.5);
    assert!((s.mean_normal_force_n / hertz - 1.0).abs() < 1e-14, "{} vs {hertz}", s.mean_normal_force_n);
    assert!((s.kz_n_per_m / (2.0 * e_star * (r * u0).sqrt()) - 1.0).abs() < 1e-14);
    assert_eq!(s.rows.get(0).unwrap().mu_ratio, 1.0);
    // G* by eq. 24 with G = E/(2(1 + nu)); critical velocity eq. 26.
    let g = e / 2.6;
    let g_star = 1.0 / (2.0 * (2.0 - 0.3) / (4.0 * g));
    assert!((s.g_star_pa / g_star - 1.0).abs() < 1e-15);
    // Flat punch: kz = 2 E* a, F = kz u0 without contact loss; eq. 26: v* = (E*/G*) mu0 omega du.
    let flat = run(r#"{"materials": {"e1_pa": 1e11, "nu1": 0.5, "e2_pa": 1e11, "nu2": 0.5}, "mu0": 0.2,
        "indenter": {"flat_punch": {"radius_m": 0.003}}, "loading": {"mean_indentation_m": 1e-6},
        "oscillation": {"amplitude_fraction": 0.4, "frequency_hz": 10}, "velocity": {"values_m_per_s": [0.0]}}"#);
    let es = 1.0 / (2.0 * 0.75 / 1e11);
    assert!((flat.kz_n_per_m / (2.0 * es * 0.003) - 1.0).abs() < 1e-15);
    assert!((flat.mean_normal_force_n / (flat.kz_n_per_m * 1e-6) - 1.0).abs() < 1e-15);
    let v_star = flat.e_star_pa / flat.g_star_pa * 0.2 * 2.0 * PI * 10.0 * 0.4e-6;
    assert!((flat.critical_velocity_m_per_s / v_star - 1.0).abs() < 1e-15);
    assert!((flat.mu_static.unwrap() - 0.2 * 0.6).abs() < 1e-16);
}

#[test]
fn the_schema_file_is_in_sync() {
    let committed = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/data/scene.schema.json")).unwrap();
    assert_eq!(
        committed.trim_end(),
        fricosc_cli::scene::schema().trim_end(),
        "run: fricosc scene --schema > data/scene.schema.json"
    );
}

#[test]
fn every_example_scene_runs() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/data/scenes");
    let mut n = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "json") {
            continue;
        }
        let src = p.to_string_lossy();
        for r in solve(&parse(&std::fs::read_to_string(&p).unwrap(), &src).unwrap(), &src).unwrap() {
            assert!(!r.rows.is_empty() && r.rows.iter().all(|x| (0.0..=1.0).contains(&x.mu_ratio)), "{}", p.display());
        }
        n += 1;
    }
    assert!(n >= 4);
}

#[test]
fn bad_scenes_name_the_file_field_and_problem() {
    let base = sphere(2e11, 5e-3, 1e-6, 1e-7, 1e3, &[1e-3]);
    let cases = [
        (base.replace("\"nu1\": 0.3", "\"nu1\": 0.7"), "materials.nu1"),
        (base.replace("\"radius_m\": 0.005", "\"radius_m\": -1.0"), "indenter.sphere.radius_m"),
        (base.replace("\"mu0\": 0.4", "\"mu0\": 0.4, \"colour\": 1"), "unknown field"),
        (base.replace("\"frequency_hz\": 1000.0", "\"frequency_hz\": 0.0"), "oscillation.frequency_hz"),
        (base.replace("[0.001]", "[-0.001]"), "velocity.values_m_per_s[0]"),
        (
            base.replace("\"mean_indentation_m\": 1e-6", "\"mean_indentation_m\": 1e-6, \"mean_normal_force_n\": 1"),
            "exactly one",
        ),
    ];
    for (json, frag) in cases {
        let e = parse(&json, "s.json").and_then(|s| solve(&s, "s.json")).unwrap_err().to_string();
        assert!(e.contains("s.json") && e.contains(frag), "{frag}: {e}");
    }
}

#[test]
fn a_tabulated_sphere_scene_matches_the_analytic_one_to_the_sphere_s_own_difference() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/data/scenes/");
    let load = |f: &str| {
        let p = format!("{dir}{f}");
        solve(&parse(&std::fs::read_to_string(&p).unwrap(), &p).unwrap(), &p).unwrap()
    };
    // The analytic scene's third amplitude, 0.16 um, is the tabulated scene's.
    let (tab, ana) = (&load("tabulated-sphere.json")[0], &load("steel-sphere-fig9.json")[2]);
    assert_eq!(ana.amplitude_m, 0.16e-6);
    // Same mean indentation; the exact sphere differs from Hertz's paraboloid by O(u0/R) = 4e-5.
    assert!((tab.mean_normal_force_n / ana.mean_normal_force_n - 1.0).abs() < 1e-4);
    assert!((tab.rows.get(0).unwrap().mu_ratio / ana.rows.get(0).unwrap().mu_ratio - 1.0).abs() < 1e-4);
    let p = format!("{dir}tabulated-sphere.json");
    let json = std::fs::read_to_string(&p)
        .unwrap()
        .replace("\"mean_indentation_m\": 1.8614506668782813e-7", "\"mean_normal_force_n\": 1");
    // Load control with the table: 1 N, as the analytic scene, at nearly its indentation.
    let lc = &parse(&json, &p).and_then(|s| solve(&s, &p)).unwrap()[0];
    assert!((lc.mean_normal_force_n - 1.0).abs() < 1e-12, "{}", lc.mean_normal_force_n);
    assert!((lc.mean_indentation_m / ana.mean_indentation_m - 1.0).abs() < 1e-4);
}

/// Several scenes: JSON is a list (one per file, also for one file), CSV one
/// long table with a scene column and the scene-level results on every row;
/// a scene from stdin.
#[test]
fn output_has_one_shape_for_any_number_of_scenes() {
    use std::process::Command;
    let root = env!("CARGO_MANIFEST_DIR");
    let run =
        |args: &[&str]| Command::new(env!("CARGO_BIN_EXE_fricosc")).args(args).current_dir(root).output().unwrap();
    let one: serde_json::Value =
        serde_json::from_slice(&run(&["scene", "data/scenes/flat-punch.json"]).stdout).unwrap();
    assert_eq!(one.as_array().map(Vec::len), Some(1));
    let out = run(&["scene", "data/scenes/flat-punch.json", "data/scenes/soft-cone.json", "--format", "csv"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let mut rd = csv::Reader::from_reader(text.as_bytes());
    let header = rd.headers().unwrap().clone();
    assert_eq!(&header[0], "scene");
    assert!(header.iter().any(|h| h == "critical_velocity_m_per_s") && header.iter().any(|h| h == "mu_ratio"));
    let rows: Vec<csv::StringRecord> = rd.records().map(|r| r.unwrap()).collect();
    let scenes: std::collections::BTreeSet<String> = rows.iter().map(|r| r[0].to_string()).collect();
    assert_eq!(scenes.len(), 2, "{text}");
    assert!(rows.iter().all(|r| r.len() == header.len()));
    assert_eq!(text.lines().filter(|l| l.starts_with("scene,")).count(), 1, "one header");
    // The flat punch's sweep shows the reduction below its critical velocity.
    let below = rows.iter().filter(|r| r[0].starts_with("flat") && r[11].parse::<f64>().unwrap() < 1.0).count();
    assert!(below >= 6, "{below} velocities below the critical one");
    // stdin.
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_fricosc"))
        .args(["scene", "-"])
        .current_dir(root)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let text = std::fs::read_to_string(std::path::Path::new(root).join("data/scenes/soft-cone.json")).unwrap();
    child.stdin.take().unwrap().write_all(text.as_bytes()).unwrap();
    let out = child.wait_with_output().unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v.as_array().map(Vec::len), Some(1));
}

/// Sweeps print what the user meant: 0.005, not 0.005000000000000001 (binary
/// noise within two ulps is rounded away; the value printed is the value used).
#[test]
fn sweeps_have_no_binary_noise() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_fricosc"))
        .args(["scene", "data/scenes/soft-cone.json"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let vs: Vec<f64> =
        v[0]["rows"].as_array().unwrap().iter().map(|r| r["velocity_m_per_s"].as_f64().unwrap()).collect();
    assert_eq!(&vs[..4], &[0.0, 0.005, 0.01, 0.015]);
    assert!(vs.windows(2).all(|w| w[1] > w[0]));
}

/// An amplitude list or sweep is a family: each member is bit for bit the
/// scene with that one amplitude; every member is checked, and the limits
/// enforced, before any work.
#[test]
fn amplitude_families_equal_their_single_members() {
    let base = sphere(2e11, 5e-3, 1e-6, 1e-7, 1e3, &[1e-4, 1e-3, 3e-3]);
    let with = |amp: &str| base.replace("\"amplitude_m\": 1e-7", &format!("\"amplitude_m\": {amp}"));
    let family = solve(&parse(&with("[1e-7, 5e-7, 2e-6]"), "f.json").unwrap(), "f.json").unwrap();
    assert_eq!(family.len(), 3);
    for (member, du) in family.iter().zip([1e-7, 5e-7, 2e-6]) {
        let single = run(&with(&format!("{du:e}")));
        assert_eq!(member.amplitude_m, du);
        for (a, b) in member.rows.iter().zip(single.rows.iter()) {
            assert_eq!(a.mu_macro.to_bits(), b.mu_macro.to_bits());
        }
        assert_eq!(member.mu_static.map(f64::to_bits), single.mu_static.map(f64::to_bits));
    }
    // A sweep: decimal values, the stop exact; logarithmic.
    let sweep =
        solve(&parse(&with(r#"{"start": 1e-7, "stop": 3e-7, "count": 3}"#), "f.json").unwrap(), "f.json").unwrap();
    assert_eq!(sweep.iter().map(|r| r.amplitude_m).collect::<Vec<_>>(), [1e-7, 2e-7, 3e-7]);
    let log =
        solve(&parse(&with(r#"{"start": 1e-8, "stop": 1e-6, "count": 3, "log": true}"#), "f.json").unwrap(), "f.json")
            .unwrap();
    assert_eq!(log.iter().map(|r| r.amplitude_m).collect::<Vec<_>>(), [1e-8, 1e-7, 1e-6]);
    // Under load control each amplitude solves its own mean indentation.
    let lc = base.replace("\"mean_indentation_m\": 1e-6", "\"mean_normal_force_n\": 5.0");
    let lc = lc.replace("\"amplitude_m\": 1e-7", "\"amplitude_m\": [1e-7, 1e-6]");
    let r = solve(&parse(&lc, "f.json").unwrap(), "f.json").unwrap();
    assert!(r.iter().all(|x| (x.mean_normal_force_n - 5.0).abs() < 1e-11));
    assert!(r[1].mean_indentation_m != r[0].mean_indentation_m);
    // Bad members and sizes, named.
    let many = format!("[{}]", vec!["1e-7"; 1001].join(","));
    let velocities: Vec<f64> = (0..2000).map(|k| k as f64 * 1e-6).collect();
    let too_many_rows = sphere(2e11, 5e-3, 1e-6, 1e-7, 1e3, &velocities)
        .replace("\"amplitude_m\": 1e-7", "\"amplitude_m\": {\"start\": 1e-7, \"stop\": 1e-6, \"count\": 501}");
    for (json, frag) in [
        (with("[1e-7, 0.0]"), "oscillation.amplitude_m[1]"),
        (with("[]"), "needs 1 to 1000 values"),
        (with(&many), "needs 1 to 1000 values"),
        (with(r#"{"start": 0, "stop": 1e-6, "count": 3}"#), "oscillation.amplitude_m.start"),
        (with(r#"{"start": 1e-6, "stop": 1e-7, "count": 3}"#), "oscillation.amplitude_m.stop"),
        (with(r#"{"start": 1e-7, "stop": 1e-6, "count": 1001}"#), "oscillation.amplitude_m.count"),
        (with(r#""big""#), "a number, a list of numbers, or a sweep"),
        (too_many_rows, "rows (amplitudes x velocities)"),
    ] {
        let e = parse(&json, "f.json").and_then(|s| solve(&s, "f.json")).unwrap_err().to_string();
        assert!(e.contains(frag), "{frag}: {e}");
    }
}

/// `scene --plot`: mu_macro against v, one curve per amplitude, SVG or PNG.
#[test]
fn scene_plot_draws_one_curve_per_amplitude() {
    use std::process::Command;
    let root = env!("CARGO_MANIFEST_DIR");
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-scene-plot-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let scene = format!("{root}/data/scenes/steel-sphere-fig9.json");
    for name in ["f.svg", "f.png"] {
        let path = dir.join(name);
        let out = Command::new(env!("CARGO_BIN_EXE_fricosc"))
            .args(["scene", &scene, "--plot", path.to_str().unwrap()])
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(json.as_array().unwrap().len(), 4);
        let bytes = std::fs::read(&path).unwrap();
        if name.ends_with("svg") {
            let svg = String::from_utf8(bytes).unwrap();
            assert!(fricosc_cli::chart::parse_size(&svg).is_ok());
            assert_eq!(svg.matches("<g data-series=").count(), 4);
            for label in ["60 nm", "100 nm", "160 nm", "270 nm", "(m/s)", "μ"] {
                assert!(svg.contains(label), "{label}");
            }
        } else {
            assert_eq!(&bytes[1..4], b"PNG");
        }
    }
    // A bad name: refused before the work, nothing on stdout.
    let out = Command::new(env!("CARGO_BIN_EXE_fricosc")).args(["scene", &scene, "--plot", "f.gif"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty() && String::from_utf8_lossy(&out.stderr).contains("must end in .svg or .png"));
}

/// A scene of one velocity still draws: an axis around it, one marked curve point.
#[test]
fn a_single_velocity_scene_draws() {
    for v in [0.0, 1e-3] {
        let r = run(&sphere(2e11, 5e-3, 1e-6, 1e-7, 1e3, &[v]));
        let svg = fricosc_cli::scene::family_chart(&[("one".to_string(), r)]).svg();
        assert!(fricosc_cli::chart::parse_size(&svg).is_ok(), "{v}");
        assert!(!svg.contains("NaN") && !svg.contains("inf") && svg.contains("<circle"), "{v}");
    }
}
