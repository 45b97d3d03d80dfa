//! Both oscillations beyond a table of `mu`: force histories (`history`,
//! `validate --history` with `--tangential-amp`/`--phase`), `plot` against the
//! phase and over a combined table, and `table --vhat-over-t` against the
//! rigid-body law. Each value is checked against something computed another
//! way: the library's exact solver, the stepping peer, or a closed form.
use crate::common::run as cli;
use std::process::Output;

fn ok(out: &Output) -> String {
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout.clone()).unwrap()
}

fn csv_rows(text: &str) -> Vec<Vec<String>> {
    text.lines().filter(|l| !l.starts_with('#')).skip(1).map(|l| l.split(',').map(String::from).collect()).collect()
}

const AT: [&str; 8] = ["--vhat", "0.2", "--amp", "0.5", "--tangential-amp", "1.5", "--phase", "1.3"];

/// The exact history's events are those of `point` (same phases, to the bit),
/// and a backward slip appears as its own event.
#[test]
fn a_combined_history_has_the_events_of_point() {
    let h = ok(&cli::run(&[&["history", "--samples", "50", "--format", "csv"][..], &AT].concat(), None));
    let events: Vec<(String, f64)> =
        csv_rows(&h).iter().filter(|r| !r[3].is_empty()).map(|r| (r[3].clone(), r[0].parse().unwrap())).collect();
    let p: serde_json::Value = serde_json::from_str(&ok(&cli::run(&[&["point"][..], &AT].concat(), None))).unwrap();
    let named = |k: &str| match k {
        "forward" => "slip".to_string(),
        "backward" => "backward_slip".to_string(),
        k => k.to_string(),
    };
    let mut expected: Vec<(String, f64)> = p["spring"]["events"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (named(e["kind"].as_str().unwrap()), e["tau"].as_f64().unwrap()))
        .collect();
    expected.sort_by(|a, b| a.1.total_cmp(&b.1));
    assert_eq!(events, expected);
    assert!(events.iter().any(|e| e.0 == "backward_slip"));
    // The velocity must be vhat, as for point.
    let out = cli::run(&["history", "--vbar", "0.2", "--amp", "0.5", "--tangential-amp", "1.5"], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
}

/// The stepping peer's combined history validates against the exact one (no
/// finding, exit 0); stepped with the phase's sign reversed it is named as such.
#[test]
fn validate_history_checks_a_combined_history_and_names_its_phase_sign() {
    let dir = tempfile::tempdir().unwrap();
    for (phase, status, named) in [("1.3", 0, None), ("-1.3", 1, Some("-phase"))] {
        let mut args = vec!["history", "--vhat", "0.2", "--amp", "0.5", "--tangential-amp", "1.5", "--phase", phase];
        args.extend(["--method", "stepping", "--steps-per-period", "2000", "--periods", "3", "--format", "csv"]);
        let path = dir.path().join("h.csv");
        std::fs::write(&path, ok(&cli::run(&args, None))).unwrap();
        let out =
            cli::run(&[&["validate", "--history", path.to_str().unwrap(), "--format", "json"][..], &AT].concat(), None);
        assert_eq!(out.status.code(), Some(status), "{}", String::from_utf8_lossy(&out.stderr));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let findings = v["findings"].as_array().unwrap();
        match named {
            None => assert!(findings.is_empty() && v["max_abs_error"].as_f64().unwrap() < 1e-4, "{findings:?}"),
            Some(n) => {
                assert_eq!(findings.len(), 1, "{findings:?}");
                assert_eq!(findings[0]["kind"], "convention");
                assert!(findings[0]["hint"].as_str().unwrap().contains(n));
            }
        }
    }
}

/// `plot --phase LIST` draws against the phase (with vhat and T on the
/// figure and a zero line where mu changes sign) and overlays a combined
/// table at the plot's vhat; a table at another oscillation is refused.
#[test]
fn plot_draws_against_the_phase_and_overlays_a_combined_table() {
    let dir = tempfile::tempdir().unwrap();
    let table = dir.path().join("t.csv");
    let rows =
        ["table", "--vhat", "0.3", "--amp", "0.5", "--tangential-amp", "1.5", "--phase", "0:6:7", "--format", "csv"];
    std::fs::write(&table, ok(&cli::run(&rows, None))).unwrap();
    let plot =
        ["plot", "--vhat", "0.3", "--amp", "0.5", "--tangential-amp", "1.5", "--phase", "0:6.283185307179586:41"];
    let svg = ok(&cli::run(&[&plot[..], &["--overlay", table.to_str().unwrap()]].concat(), None));
    for text in ["phase φ of the tangential oscillation", "v\u{302} = 0.3", "Δx/l = 1.5", "yours"] {
        assert!(svg.contains(text), "{text}");
    }
    let other = ["plot", "--vhat", "0.4", "--amp", "0.5", "--tangential-amp", "1.5", "--phase", "0:6:7"];
    let out = cli::run(&[&other[..], &["--overlay", table.to_str().unwrap()]].concat(), None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("row 0 is at tangential_amp 1.5, vhat 0.3"));
    // Against vhat at one phase the same table is refused: its rows are at other phases.
    let out = cli::run(
        &["plot", "--vhat", "0.1,0.5", "--amp", "0.5", "--tangential-amp", "1.5", "--overlay", table.to_str().unwrap()],
        None,
    );
    assert_eq!(out.status.code(), Some(2));
}

/// At fixed `vhat/T` the friction tends, as `T` grows, to the rigid-body law
/// `mu/mu0 = (2/pi) asin(vhat/T)` (the force is `+-mu0 N` with the sign of
/// the body's velocity `vhat + T cos`): 1/3 at `vhat/T = 1/2`.
#[test]
fn table_holds_vhat_over_t_fixed_and_approaches_the_rigid_body_law() {
    let text = ok(&cli::run(
        &["table", "--vhat-over-t", "0.5", "--amp", "0", "--tangential-amp", "10,10000", "--format", "csv"],
        None,
    ));
    let rows = csv_rows(&text);
    let rigid = 2.0 / std::f64::consts::PI * 0.5f64.asin();
    let err: Vec<f64> = rows.iter().map(|r| (r[6].parse::<f64>().unwrap() - rigid).abs()).collect();
    assert_eq!(rows[1][2], "5000.0", "vhat = 0.5 T");
    // 1.5e-2 at T = 10, 1.4e-5 at T = 10^4 (like 1/T).
    assert!(err[0] > 1e-2 && err[1] < 1.5e-4, "{err:?}");
}
