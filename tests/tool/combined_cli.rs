//! The command line under oscillation in the sliding direction: `point`,
//! `table`, `batch`, `plot` and `validate` with `--tangential-amp`/`--phase`
//! (or the columns `tangential_amp`, `phase`) give the library's values bit
//! for bit, `T = 0` is the seed's problem, and bad input is refused (exit 2,
//! nothing on stdout).
use crate::common::run as cli;

use fricosc::Shape;
use std::process::Output;

fn ok(out: &Output) -> String {
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout.clone()).unwrap()
}

fn refused(args: &[&str], stdin: Option<&str>, message: &str) {
    let out = cli::run(args, stdin);
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    assert!(out.stdout.is_empty(), "{args:?}: stdout {}", String::from_utf8_lossy(&out.stdout));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(message) && err.lines().count() == 1, "{args:?}: {err}");
}

fn exact(shape: &Shape, vhat: f64, amp: f64, t: f64, phase: f64) -> f64 {
    crate::common::at::combined(shape, vhat, amp, t, phase).unwrap().ratio.mu_ratio
}

#[test]
fn point_reports_the_spring_and_the_library_value() {
    let v: serde_json::Value = serde_json::from_str(&ok(&cli::run(
        &["point", "--vhat", "0.6", "--amp", "2", "--tangential-amp", "3", "--phase", "1"],
        None,
    )))
    .unwrap();
    assert_eq!(v["mu_ratio"].as_f64().unwrap(), exact(&Shape::flat(), 0.6, 2.0, 3.0, 1.0));
    assert_eq!(v["spring"]["regime"], "jumping: stick, backward, stick, forward");
    let kinds: Vec<&str> =
        v["spring"]["events"].as_array().unwrap().iter().map(|e| e["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["contact", "backward", "stick", "forward", "loss_of_contact"]);
    // A curved contact reports its bands, whose shares add up to 1.
    let p: serde_json::Value = serde_json::from_str(&ok(&cli::run(
        &["point", "--shape", "parabolic", "--vhat", "0.2", "--amp", "0.5", "--tangential-amp", "1"],
        None,
    )))
    .unwrap();
    let shares: f64 = p["bands"].as_array().unwrap().iter().map(|b| b["share"].as_f64().unwrap()).sum();
    assert!((shares - 1.0).abs() < 1e-12, "{shares}");
    // T = 0: the seed's value, bit for bit.
    let seed: serde_json::Value =
        serde_json::from_str(&ok(&cli::run(&["point", "--shape", "cone", "--vhat", "0.3", "--amp", "0.7"], None)))
            .unwrap();
    let zero: serde_json::Value = serde_json::from_str(&ok(&cli::run(
        &["point", "--shape", "cone", "--vhat", "0.3", "--amp", "0.7", "--tangential-amp", "0"],
        None,
    )))
    .unwrap();
    assert_eq!(seed["mu_ratio"].as_f64().unwrap().to_bits(), zero["mu_ratio"].as_f64().unwrap().to_bits());
}

#[test]
fn table_batch_and_validate_agree_bit_for_bit() {
    let args = [
        "table",
        "--shape",
        "parabolic",
        "--vhat",
        "0.1,0.6",
        "--amp",
        "0,1.5",
        "--tangential-amp",
        "0,0.5,3",
        "--phase",
        "0,2",
        "--format",
        "csv",
    ];
    let text = ok(&cli::run(&args, None));
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("shape,vhat,amp,tangential_amp,phase,mu_ratio,reduction"));
    let rows: Vec<Vec<f64>> =
        lines.map(|l| l.split(',').skip(1).map(|x| x.parse().unwrap()).collect()).collect::<Vec<_>>();
    assert_eq!(rows.len(), 24);
    let p = Shape::parabolic();
    for r in &rows {
        assert_eq!(r[4], exact(&p, r[0], r[1], r[2], r[3]), "{r:?}");
    }
    assert!(rows.iter().any(|r| r[4] < 0.0), "the ratchet appears in this table");
    // The same rows through batch (CSV in, CSV out; the velocity as vhat).
    let out = ok(&cli::run(&["batch", "-", "--format", "csv"], Some(&text)));
    assert_eq!(out, text, "batch fills mu_ratio and reduction with the same bits");
    // validate: the exact table has no error and no finding; a sign flipped is found.
    let v = ok(&cli::run(&["validate", "-", "--format", "json"], Some(&text)));
    let report: serde_json::Value = serde_json::from_str(&v).unwrap();
    assert_eq!(report["max_abs_error"].as_f64(), Some(0.0), "{v}");
    // One value a little off: beyond --max-error, exit 1 and the row named.
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let mut cells: Vec<String> = lines[7].split(',').map(String::from).collect();
    cells[5] = (cells[5].parse::<f64>().unwrap() + 1e-9).to_string();
    lines[7] = cells.join(",");
    let broken = lines.join("\n");
    let out = cli::run(&["validate", "-", "--format", "json", "--max-error", "1e-10"], Some(&broken));
    assert_eq!(out.status.code(), Some(1), "an error beyond --max-error exits 1");
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(report["worst_row"].as_u64(), Some(6));
    assert!((report["max_abs_error"].as_f64().unwrap() - 1e-9).abs() < 1e-12);
}

#[test]
fn validate_names_values_below_minus_one_and_a_stepper_worse_than_the_peer() {
    let table = "vhat,amp,tangential_amp,phase,mu_ratio\n0.6,2,3,1,-1.2\n0.1,0.5,1,0,0.3\n";
    let out = cli::run(&["validate", "-", "--format", "json", "--peer", "4000"], Some(table));
    assert_eq!(out.status.code(), Some(1));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let kinds: Vec<&str> = report["findings"].as_array().unwrap().iter().map(|f| f["kind"].as_str().unwrap()).collect();
    assert!(kinds.contains(&"below_minus_one") && kinds.contains(&"worse_than_peer"), "{kinds:?}");
}

#[test]
fn bad_oscillation_input_is_refused_before_any_output() {
    refused(&["point", "--vbar", "0.3", "--amp", "1", "--tangential-amp", "1"], None, "--vhat");
    refused(&["point", "--vhat", "0.3", "--amp", "1", "--phase", "1"], None, "--tangential-amp");
    refused(&["point", "--vhat", "0.3", "--amp", "1", "--tangential-amp", "2e6"], None, "1e6");
    refused(&["point", "--vhat", "0.3", "--amp", "1", "--tangential-amp", "-1"], None, "must be >= 0");
    refused(&["point", "--vhat", "0.3", "--amp", "1", "--tangential-amp", "1", "--phase", "nan"], None, "phase");
    refused(&["table", "--vbar", "0.3", "--amp", "1", "--tangential-amp", "1"], None, "--vhat");
    refused(&["table", "--vhat", "0.3", "--amp", "1", "--tangential-amp", "1,3e6"], None, "1e6");
    refused(
        &["batch", "-"],
        Some(
            r#"[{"shape":"flat","vhat":0.3,"amp":1,"tangential_amp":1},{"shape":"flat","vhat":0.3,"amp":1,"phase":1}]"#,
        ),
        "'phase' needs 'tangential_amp'",
    );
    refused(&["batch", "-", "--format", "csv"], Some("shape,vbar,amp,tangential_amp\nflat,0.3,1,1\n"), "'vhat'");
    refused(&["validate", "-"], Some("vbar,amp,tangential_amp,mu_ratio\n0.3,1,1,0.5\n"), "'vhat'");
    refused(&["plot", "--vbar", "0,1", "--amp", "1", "--tangential-amp", "1"], None, "--vhat");
}

#[test]
fn plot_draws_the_combined_curves() {
    let svg =
        ok(&cli::run(&["plot", "--vhat", "0:1.5:31", "--amp", "0.5,2", "--tangential-amp", "2", "--phase", "1"], None));
    assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"), "{}", &svg[..50]);
    // The axis reaches below 0: the curves do.
    assert!(svg.contains("−0.5") || svg.contains("-0.5"), "a negative tick");
}

/// README's table under oscillation in the sliding direction is the command
/// README prints, and its output the file README names.
#[test]
fn readme_example_is_what_the_command_prints() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let command =
        "fricosc table --shape parabolic --vhat 0.3 --amp 0.5,1.5 --tangential-amp 2 --phase 0,1.2,3.1416,4.2";
    assert!(readme.contains(command) && readme.contains("`data/table-combined.csv`"), "README's example");
    let block = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/data/table-combined.csv")).unwrap();
    let args = [
        "table",
        "--shape",
        "parabolic",
        "--vhat",
        "0.3",
        "--amp",
        "0.5,1.5",
        "--tangential-amp",
        "2",
        "--phase",
        "0,1.2,3.1416,4.2",
        "--format",
        "csv",
    ];
    assert_eq!(ok(&cli::run(&args, None)), block);
}

/// A phase beyond `2 pi` is taken as radians, with a warning on stderr that
/// names the radians of the same number of degrees (`--phase 90` was
/// silently 90 rad); the answer is unchanged and the exit code 0.
#[test]
fn a_phase_beyond_two_pi_is_warned_about() {
    let out = cli::run(&["point", "--vhat", "0.3", "--amp", "0.5", "--tangential-amp", "1", "--phase", "90"], None);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && err.contains("warning: --phase 90 is radians") && err.contains("1.5707963267948966"),
        "{err}"
    );
    let quiet = cli::run(&["point", "--vhat", "0.3", "--amp", "0.5", "--tangential-amp", "1", "--phase", "1.5"], None);
    assert!(quiet.stderr.is_empty());
}
