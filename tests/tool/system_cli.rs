//! The system's mass and stiffness through the command line: `batch` rows
//! with `system_stiffness`, `frequency_ratio`, `damping` (each row the
//! library's `Shape::report` on the system, bit for bit), histories of curved bodies on a
//! system, and the refusals (one line, exit 2, nothing on stdout).
use crate::common::on_system as solve;
use crate::common::run::run as fricosc;
use fricosc::system::System;
use fricosc::{Conditions, Shape};

fn stdout(args: &[&str], stdin: Option<&str>) -> String {
    let out = fricosc(args, stdin);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap()
}

fn refused(args: &[&str], stdin: Option<&str>, says: &str) {
    let out = fricosc(args, stdin);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty() && err.lines().count() == 1 && err.contains(says), "{args:?}: {err}");
}

/// Batch rows on a system are the library's answers (its reduction `1 - mu`),
/// in JSON Lines and CSV; rows without a system are unchanged beside them.
#[test]
fn batch_rows_on_a_system_are_the_librarys() {
    let dir = tempfile::tempdir().unwrap();
    let rows = dir.path().join("rows.jsonl");
    let text = concat!(
        r#"{"shape":"flat","vhat":0.3,"amp":0.5,"system_stiffness":1,"frequency_ratio":0.5,"damping":0.3,"id":7}"#,
        "\n",
        r#"{"shape":"cone","vbar":0.3,"amp":1.5,"system_stiffness":2,"frequency_ratio":0.8,"damping":0.1}"#,
        "\n",
        r#"{"shape":"flat","vbar":0.3,"amp":0.5}"#,
        "\n"
    );
    std::fs::write(&rows, text).unwrap();
    let out = stdout(&["batch", rows.to_str().unwrap()], None);
    let v: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let flat =
        solve(&Shape::flat(), &Conditions::vhat(0.3, 0.5).unwrap(), &System::new(1.0, 0.5, 0.3).unwrap()).unwrap();
    let cone =
        solve(&Shape::cone(), &Conditions::vbar(0.3, 1.5).unwrap(), &System::new(2.0, 0.8, 0.1).unwrap()).unwrap();
    assert_eq!(v[0]["mu_ratio"].as_f64(), Some(flat.mu_ratio));
    assert_eq!(v[0]["reduction"].as_f64(), Some(1.0 - flat.mu_ratio));
    assert_eq!(v[0]["id"], 7);
    assert_eq!(v[1]["mu_ratio"].as_f64(), Some(cone.mu_ratio));
    assert_eq!(
        v[2]["mu_ratio"].as_f64(),
        Some(Shape::flat().ratio(&Conditions::vbar(0.3, 0.5).unwrap()).unwrap().mu_ratio)
    );
    let csv = "shape,vhat,amp,system_stiffness,frequency_ratio,damping\nflat,0.3,0.5,1,0.5,0.3\n";
    let out = stdout(&["batch", "--format", "csv", "-"], Some(csv));
    let last: Vec<&str> = out.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(last[6].parse::<f64>().unwrap(), flat.mu_ratio);
    // --springs serves a curved body's rows (batch --help says so; it was
    // refused), checked as the library checks it.
    let sys = System::new(2.0, 0.8, 0.1).unwrap().with_springs(64).unwrap();
    let cone64 = solve(&Shape::cone(), &Conditions::vbar(0.3, 1.5).unwrap(), &sys).unwrap();
    let out = stdout(&["batch", rows.to_str().unwrap(), "--springs", "64"], None);
    let v: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!((v[0]["mu_ratio"].as_f64(), v[1]["mu_ratio"].as_f64()), (Some(flat.mu_ratio), Some(cone64.mu_ratio)));
    refused(&["batch", rows.to_str().unwrap(), "--springs", "16"], None, "invalid springs = 16");
}

/// A row's system is checked before any output, by name.
#[test]
fn bad_system_rows_are_named() {
    let csv = |row: &str| format!("shape,vbar,amp,system_stiffness,frequency_ratio,damping\n{row}\n");
    let cases = [
        ("flat,0.3,0.5,,0.5,", "need 'system_stiffness'"),
        ("flat,0.3,0.5,-1,0.5,0", "system-stiffness"),
        ("flat,0.3,0.5,1,nan,0", "frequency_ratio"),
        ("flat,0.3,0.5,1,0.5,1e7", "damping"),
        ("cone,0.3,0.5,1,0,0", "massless"),
    ];
    for (row, says) in cases {
        refused(&["batch", "--format", "csv", "-"], Some(&csv(row)), says);
    }
    refused(&["batch", "--format", "csv", "--method", "stepping", "-"], Some(&csv("flat,0.3,0.5,1,0.5,0")), "exactly");
}

/// `history` of a curved body on a system: one period of its springs'
/// attractor, its mean that discretisation's `mu` (within the trapezoid's
/// error); `--springs` sets their number.
#[test]
fn a_curved_history_on_a_system() {
    let args = ["history", "--shape", "parabolic", "--vhat", "0.15", "--amp", "0.5", "--system-stiffness", "1"];
    let more =
        ["--frequency-ratio", "0.5", "--damping", "0.05", "--springs", "32", "--samples", "4000", "--format", "csv"];
    let out = stdout(&[&args[..], &more[..]].concat(), None);
    let rows: Vec<Vec<f64>> =
        out.lines().skip(2).map(|l| l.split(',').filter_map(|x| x.parse().ok()).collect()).collect();
    let mean = |k: usize| rows.iter().map(|r| r[k]).sum::<f64>() / rows.len() as f64;
    let sys = System::new(1.0, 0.5, 0.05).unwrap();
    let c = Conditions::vhat(0.15, 0.5).unwrap();
    let exact = fricosc::system::solve_discretised(&Shape::parabolic(), &c.with_system(sys), 32).unwrap().mu_ratio;
    assert!((mean(2) / mean(1) - exact).abs() < 1e-6, "{} vs {exact}", mean(2) / mean(1));
    // The body beside the forces: its mean velocity the drive's, the
    // system's mean force the contact's.
    assert_eq!(out.lines().nth(1), Some("tau,normal,tangential,event,body_lag,body_velocity,system_force"));
    assert!((mean(4) - 0.15).abs() < 1e-9 && (mean(5) - mean(2)).abs() < 1e-6, "{} {}", mean(4), mean(5));
    refused(
        &["history", "--shape", "cone", "--vhat", "0.1", "--amp", "0.5", "--system-stiffness", "1"],
        None,
        "massless",
    );
    // The option at fault is named (it was "invalid shape 'flat'").
    refused(&[&args[..], &["--frequency-ratio", "0.5", "--periods", "2"]].concat(), None, "invalid periods");
    refused(&[&args[..], &["--frequency-ratio", "0.5", "--spring-at", "0.5"]].concat(), None, "spring-at:");
}

/// `validate --system-stiffness`: a stepper's table on the system (the
/// library's stepping peer with the body, 1000 steps a period: first order)
/// is within 1e-3 of the attractors, with no finding; the same rows solved
/// without the system (a stepper that forgot the body) are beyond it (exit
/// 1), and a value above 1 is named.
#[test]
fn validate_compares_a_table_on_a_system() {
    let sys = System::new(1.0, 0.5, 0.1).unwrap();
    let rows: Vec<(f64, f64)> = vec![(0.1, 0.5), (0.3, 0.5), (1.0, 0.5), (0.1, 1.5), (0.5, 1.5)];
    let table = |mu: &dyn Fn(&Conditions) -> f64| {
        let mut t = String::from("vbar,amp,mu_ratio\n");
        for &(vbar, amp) in &rows {
            t += &format!("{vbar},{amp},{}\n", mu(&Conditions::vbar(vbar, amp).unwrap()));
        }
        t
    };
    let stepped = table(&|c| fricosc::stepper::system(&Shape::flat(), &c.with_system(sys), 1000, 40).unwrap());
    let forgot = table(&|c| Shape::flat().ratio(c).unwrap().mu_ratio);
    let args = ["validate", "-", "--system-stiffness", "1", "--frequency-ratio", "0.5", "--damping", "0.1"];
    let run = |t: &str, extra: &[&str]| fricosc(&[&args[..], extra].concat(), Some(t));
    let out = run(&stepped, &["--format", "json", "--max-error", "1e-3"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let largest = v["max_abs_error"].as_f64().unwrap();
    assert!(largest > 1e-6 && largest < 1e-3 && v["findings"].as_array().unwrap().is_empty(), "{v}");
    assert_eq!(v["system"]["stiffness"], 1.0);
    let out = run(&forgot, &["--format", "json", "--max-error", "1e-3"]);
    assert_eq!(out.status.code(), Some(1));
    // The stiff answer is named as such, and the bound exceeded is a finding.
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let kinds: Vec<&str> = v["findings"].as_array().unwrap().iter().map(|f| f["kind"].as_str().unwrap()).collect();
    assert!(kinds.contains(&"convention") && kinds.contains(&"max_error"), "{v}");
    assert!(v.to_string().contains("no system at all"), "{v}");
    let above: Vec<&str> = stepped.lines().map(|l| if l.starts_with("0.1,0.5,") { "0.1,0.5,1.5" } else { l }).collect();
    let out = run(&(above.join("\n") + "\n"), &["--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["findings"][0]["kind"], "above_one", "{v}");
}

/// `validate` on a system in the stiff layout: per amplitude, each row's
/// period and the exact value's estimate in the CSV; a stepper without its
/// damping (the library's stepping peer with the body, run on the system with
/// zeta 0) is named as such against the system with zeta 0.1 (the errors
/// are 1e-2 and more; 2e-3 and less with the damping left out); a JSON
/// null (a diverged value as pandas writes it) is a finding on its row.
#[test]
fn validate_on_a_system_names_the_mistake() {
    let undamped = System::new(1.0, 0.5, 0.0).unwrap();
    let mut t = String::from("vbar,amp,mu_ratio\n");
    for amp in [0.5, 1.5] {
        for vbar in [0.1, 0.3, 0.5, 0.8, 1.2, 1.6] {
            let c = Conditions::vbar(vbar, amp).unwrap().with_system(undamped);
            t += &format!("{vbar},{amp},{}\n", fricosc::stepper::system(&Shape::flat(), &c, 1000, 40).unwrap());
        }
    }
    let args = ["validate", "-", "--system-stiffness", "1", "--frequency-ratio", "0.5", "--damping", "0.1"];
    let out = fricosc(&[&args[..], &["--format", "summary"]].concat(), Some(&t));
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("- convention: 12 rows") && text.contains("\namp "), "{text}");
    let json = stdout(&[&args[..], &["--format", "json", "--report-only"]].concat(), Some(&t));
    assert!(json.contains("your values match the exact ones with the damping left out (zeta = 0)"), "{json}");
    let csv = stdout(&[&args[..], &["--format", "csv", "--report-only"]].concat(), Some(&t));
    let header = csv.lines().next().unwrap();
    assert!(header.ends_with(",regime,jumping_share,period,exact_error_estimate"), "{header}");
    assert!(csv.lines().nth(1).unwrap().split(',').nth(9) == Some("1"), "{csv}");
    let exact = solve(&Shape::flat(), &Conditions::vbar(0.5, 0.5).unwrap(), &System::new(1.0, 0.5, 0.1).unwrap());
    let json = format!(
        r#"[{{"vbar": 0.3, "amp": 0.5, "mu_ratio": null}}, {{"vbar": 0.5, "amp": 0.5, "mu_ratio": {}}}]"#,
        exact.unwrap().mu_ratio
    );
    let out = fricosc(&[&args[..], &["--format", "json"]].concat(), Some(&json));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!((out.status.code(), &v["findings"][0]["kind"]), (Some(1), &"diverged".into()), "{v}");
    assert_eq!((&v["findings"][0]["rows"], v["findings"].as_array().unwrap().len()), (&serde_json::json!([0]), 1));
}

/// `plot --system-stiffness`: each curve's points are the library's
/// attractors (a curved body's at the given springs); the drawing names the
/// system; several phases on a system are refused.
#[test]
fn plot_on_a_system_draws_the_attractors() {
    let sys = System::new(1.0, 1.0, 0.05).unwrap().with_springs(32).unwrap();
    let fig =
        fricosc_cli::figures::user_with(&Shape::cone(), &[0.5, 1.5], &[0.1, 0.5, 1.0], false, (None, None), Some(&sys))
            .unwrap();
    for curve in &fig.curves {
        let amp = curve.amp.unwrap();
        for p in &curve.points {
            assert_eq!(p[1], solve(&Shape::cone(), &Conditions::vbar(p[0], amp).unwrap(), &sys).unwrap().mu_ratio);
        }
    }
    let args = ["plot", "--shape", "cone", "--vbar", "0.1,0.5,1", "--amp", "0.5,1.5", "--system-stiffness", "1"];
    let svg = stdout(&[&args[..], &["--frequency-ratio", "1", "--damping", "0.05", "--springs", "32"]].concat(), None);
    assert_eq!(svg.matches("<g data-series=").count(), 2);
    assert!(svg.contains("on a system K/kx = 1, Ω = 1, ζ = 0.05"));
    let phases =
        ["plot", "--vhat", "0.1", "--amp", "0.5", "--tangential-amp", "1", "--phase", "0,1", "--system-stiffness", "1"];
    refused(&[&phases[..], &["--frequency-ratio", "1"]].concat(), None, "one --phase");
}

/// A scene with a `system` (mass, stiffness, damping in SI units): its
/// parameters in the contact's units (`kappa = K/kx`, `Omega = omega
/// sqrt(m/kx)`, `zeta = c/(2 sqrt(K m))`, from the scene's own `kx`), every
/// row the library's attractor there; bad values are named.
#[test]
fn a_scene_on_a_system() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("pin.json");
    let scene = |system: &str| {
        format!(
            r#"{{"materials": {{"e1_pa": 2.1e11, "nu1": 0.3, "e2_pa": 7.0e10, "nu2": 0.33}}, "mu0": 0.3,
            "indenter": {{"flat_punch": {{"radius_m": 0.001}}}}, "loading": {{"mean_indentation_m": 1e-6}},
            "oscillation": {{"amplitude_fraction": 0.5, "frequency_hz": 1000}},
            "velocity": {{"values_m_per_s": [1e-3, 3e-3]}}, "system": {system}}}"#
        )
    };
    std::fs::write(&path, scene(r#"{"mass_kg": 0.01, "stiffness_n_per_m": 1e7, "damping_n_s_per_m": 30}"#)).unwrap();
    let v: serde_json::Value = serde_json::from_str(&stdout(&["scene", path.to_str().unwrap()], None)).unwrap();
    let r = &v[0];
    let (kx, omega) = (r["kx_n_per_m"].as_f64().unwrap(), 2.0 * std::f64::consts::PI * 1000.0);
    let sys = &r["system"];
    assert_eq!(sys["stiffness"].as_f64().unwrap(), 1e7 / kx);
    assert_eq!(sys["frequency_ratio"].as_f64().unwrap(), omega * (0.01 / kx).sqrt());
    assert_eq!(sys["damping"].as_f64().unwrap(), 30.0 / (2.0 * (1e7f64 * 0.01).sqrt()));
    let system = System::new(1e7 / kx, omega * (0.01 / kx).sqrt(), 30.0 / (2.0 * (1e7f64 * 0.01).sqrt())).unwrap();
    for row in r["rows"].as_array().unwrap() {
        let c = Conditions::vbar(row["vbar"].as_f64().unwrap(), 0.5).unwrap();
        assert_eq!(row["mu_ratio"].as_f64().unwrap(), solve(&Shape::flat(), &c, &system).unwrap().mu_ratio);
    }
    // The system's own critical velocity and the rows' regimes from it: a
    // row is `sliding` exactly where the system's answer is 1 (the stiff
    // critical velocity, 1e-3 m/s apart here, was reported for every system).
    let vbar_c = fricosc::system::critical_vbar(&Shape::flat(), 0.5, &system).unwrap().unwrap();
    let v_crit = r["critical_velocity_m_per_s"].as_f64().unwrap();
    assert_eq!(r["system_critical_velocity_m_per_s"].as_f64(), Some(vbar_c * v_crit));
    let mut sweep = scene(r#"{"mass_kg": 0.01, "stiffness_n_per_m": 1e7, "damping_n_s_per_m": 30}"#);
    sweep = sweep.replace(
        r#""values_m_per_s": [1e-3, 3e-3]"#,
        r#""sweep": {"start_m_per_s": 1e-4, "stop_m_per_s": 3e-3, "count": 30}"#,
    );
    std::fs::write(&path, sweep).unwrap();
    let v: serde_json::Value = serde_json::from_str(&stdout(&["scene", path.to_str().unwrap()], None)).unwrap();
    for row in v[0]["rows"].as_array().unwrap() {
        let (mu, sliding) = (row["mu_ratio"].as_f64().unwrap(), row["regime"] == "sliding");
        assert_eq!(sliding, row["vbar"].as_f64().unwrap() >= vbar_c, "{row}");
        assert_eq!(sliding, mu == 1.0, "{row}");
    }
    for (bad, says) in [
        (r#"{"mass_kg": 0, "stiffness_n_per_m": 1e7}"#, "system.mass_kg"),
        (r#"{"mass_kg": 1, "stiffness_n_per_m": -1}"#, "system.stiffness_n_per_m"),
        (r#"{"mass_kg": 1, "stiffness_n_per_m": 1e7, "damping_n_s_per_m": -1}"#, "system.damping_n_s_per_m"),
        (r#"{"mass_kg": 1, "stiffness_n_per_m": 1e20}"#, "system-stiffness"),
        (r#"{"mass": 1, "stiffness_n_per_m": 1e7}"#, "mass"),
    ] {
        std::fs::write(&path, scene(bad)).unwrap();
        refused(&["scene", path.to_str().unwrap()], None, says);
    }
}

/// A table on a system as a rig owner reads it: the velocity as given
/// (`vbar 0.3`, not the `vhat` it makes, 0.15000000000000002), `reduction`
/// beside `mu_ratio`, the period a whole number, and where none was found
/// an empty CSV field (a literal `null` was written) and JSON's `null`.
#[test]
fn a_table_on_a_system_reads_as_given() {
    let args = ["table", "--vbar", "0.3", "--amp", "0.5,1.5", "--system-stiffness", "1", "--frequency-ratio"];
    let csv = stdout(&[&args[..], &["0.5", "--damping", "0.05", "--format", "csv"]].concat(), None);
    let mut lines = csv.lines();
    let header = "shape,vbar,amp,tangential_amp,phase,mu_ratio,reduction,period,standard_error,error_estimate";
    assert_eq!(lines.next(), Some(header));
    let sys = System::new(1.0, 0.5, 0.05).unwrap();
    for (line, amp) in lines.zip([0.5, 1.5]) {
        let r = solve(&Shape::flat(), &Conditions::vbar(0.3, amp).unwrap(), &sys).unwrap();
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(&cells[..3], &["flat", "0.3", &amp.to_string()], "{line}");
        assert_eq!(cells[5].parse::<f64>().unwrap(), r.mu_ratio);
        assert_eq!(cells[6].parse::<f64>().unwrap(), 1.0 - r.mu_ratio);
        assert_eq!((cells[7], cells[8]), ("1", ""), "{line}");
        assert_eq!(cells[9].parse::<f64>().unwrap(), r.error_estimate);
    }
    // No period (undamped at the stick resonance): empty in CSV, null in JSON.
    let none = ["table", "--vbar", "0.3", "--amp", "0.5", "--system-stiffness", "1", "--frequency-ratio", "1.41"];
    let csv = stdout(&[&none[..], &["--format", "csv"]].concat(), None);
    let row: Vec<&str> = csv.lines().nth(1).unwrap().split(',').collect();
    assert!(row[7].is_empty() && row[8].parse::<f64>().unwrap() > 0.0 && !csv.contains("null"), "{csv}");
    let json: serde_json::Value = serde_json::from_str(&stdout(&none, None)).unwrap();
    assert!(json["rows"][0]["period"].is_null(), "{json}");
}

/// A table keyed by `vhat` is reported by `vhat`: the summary's worst row
/// was "vbar 0.9" for the file's `vhat 0.45` (amp 0.5), on a system as
/// without one; the CSV's velocity column is `vhat` as given, the JSON rows
/// carry it beside the `vbar` compared (0.3 for 0.15 at amp 0.5).
#[test]
fn the_summary_keys_rows_as_the_file_does() {
    let t = "vhat,amp,mu_ratio\n0.15,0.5,0.63\n0.3,0.5,0.8\n0.45,0.5,0.9\n";
    let system = ["--system-stiffness", "1", "--frequency-ratio", "0.5", "--damping", "0.05"];
    for (extra, worst) in
        [(&system[..], "at row 2 (vhat 0.45, amp 0.5: 0.9 against"), (&[], "at row 0 (vhat 0.15, amp 0.5")]
    {
        let args = [&["validate", "-", "--format", "summary", "--report-only"][..], extra].concat();
        let text = stdout(&args, Some(t));
        assert!(text.contains(worst) && !text.contains("(vbar "), "{text}");
        let csv = stdout(&[&["validate", "-", "--format", "csv", "--report-only"][..], extra].concat(), Some(t));
        assert!(csv.starts_with("row,vhat,amp,") && csv.lines().nth(1).unwrap().starts_with("0,0.15,0.5,"), "{csv}");
        let json = stdout(&[&["validate", "-", "--format", "json", "--report-only"][..], extra].concat(), Some(t));
        let row = &serde_json::from_str::<serde_json::Value>(&json).unwrap()["rows"][0];
        assert!(row["vhat"] == 0.15 && row["vbar"] == 0.3, "{row}");
    }
}

/// `validate --history` on a system: a massless body's history is the stiff
/// one at the drive scaled by `kappa/(1 + kappa)` (springs in series: 0.3 on
/// a system of stiffness 1 is 0.15 stiff); an attractor without period 1 is
/// refused by name, as are body columns without a body with mass and a lag
/// without its velocity. (A stepper's history against the attractor, with
/// its body: `src/python/tests/test_system_bugs.py`.)
#[test]
fn validate_compares_a_history_on_a_system() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("h.csv");
    let file = path.to_str().unwrap();
    let stiff = stdout(&["history", "--vhat", "0.15", "--amp", "1.5", "--samples", "500", "--format", "csv"], None);
    std::fs::write(&path, stiff.lines().skip(1).map(|l| format!("{l}\n")).collect::<String>()).unwrap();
    let args = ["validate", "--history", file, "--vhat", "0.3", "--amp", "1.5", "--format", "json"];
    let out: serde_json::Value =
        serde_json::from_str(&stdout(&[&args[..], &["--system-stiffness", "1"]].concat(), None)).unwrap();
    assert!(out["max_abs_error"].as_f64().unwrap() < 1e-15 && out["findings"] == serde_json::json!([]), "{out}");
    let undamped = ["--system-stiffness", "1", "--frequency-ratio", "1.5", "--damping", "0"];
    let no_period = ["validate", "--history", file, "--vhat", "0.3", "--amp", "1.2"];
    refused(&[&no_period[..], &undamped[..]].concat(), None, "no period");
    let rows: String = (0..=14).map(|k| format!("{},0,0,0\n", 0.5 * k as f64)).collect();
    std::fs::write(&path, format!("tau,tangential,body_lag,body_velocity\n{rows}")).unwrap();
    refused(&args, None, "body columns");
    std::fs::write(&path, "tau,tangential,body_lag\n0,0,0\n7,0,0\n").unwrap();
    refused(&args, None, "together");
}
