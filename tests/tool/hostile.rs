//! Hostile input and hostile output: closed pipes, a full disk, endless inputs.
//! Each case here panicked or ran out of memory before it was fixed.
use std::os::unix::fs::FileTypeExt;
use std::process::{Command, Stdio};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_fricosc"))
}

const COMMANDS: &[&[&str]] = &[
    &["claims"],
    &["claims", "--format", "json"],
    &["scene", "--schema"],
    &["table", "--amp", "0.5", "--vbar", "0:1:20001"],
    &["point", "--vbar", "0.3", "--amp", "0.5"],
    &["--help"],
    &["--version"],
];

/// `/dev/full` accepts the open and fails every write with ENOSPC.
#[test]
fn a_full_disk_is_a_one_line_error_with_exit_2_never_a_panic() {
    for args in COMMANDS {
        let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let out = bin().args(*args).stdout(full).stderr(Stdio::piped()).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.starts_with("error: cannot write stdout"), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    }
}

/// A reader that closes the pipe after a few bytes (`| head -c 10`): quiet exit 0.
#[test]
fn a_closed_pipe_ends_the_program_quietly() {
    for args in COMMANDS {
        let mut child = bin().args(*args).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
        let mut stdout = child.stdout.take().unwrap();
        let mut first = [0u8; 10];
        use std::io::Read;
        let _ = stdout.read(&mut first);
        drop(stdout);
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
        assert!(err.is_empty(), "{args:?}: {err}");
    }
}

/// Endless inputs are refused at their documented cap, before memory runs out.
#[test]
fn endless_inputs_stop_at_the_documented_cap() {
    for args in [
        vec!["batch", "/dev/zero"],
        vec!["validate", "/dev/zero"],
        vec!["scene", "/dev/zero"],
        vec!["point", "--shape", "gx:/dev/zero@1", "--vbar", "0.3", "--amp", "0.5"],
    ] {
        let out = bin().args(&args).stdin(Stdio::null()).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("is more than the limit of"), "{args:?}: {err}");
        assert!(out.stdout.is_empty());
    }
}

/// An endless CSV record (`/dev/zero` has no line end) or a field of 5 MB is
/// refused at the record cap before it is read whole (a 300 MB field peaked
/// at 530 MB, `/dev/zero` grew until the process aborted).
#[test]
fn a_csv_record_beyond_the_cap_is_refused_before_it_is_in_memory() {
    let out = bin()
        .args(["batch", "--format", "csv", "-"])
        .stdin(std::fs::File::open("/dev/zero").unwrap())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("line 1: a record of more than 1048576 bytes"), "{err}");
    let big = format!("shape,vbar,amp\nflat,0.3,\"{}\"\n", "a".repeat(5 << 20));
    let out = crate::common::run::run(&["batch", "--format", "csv"], Some(&big));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.code() == Some(2) && err.contains("line 2: a record of more than 1048576 bytes"), "{err}");
}

/// `--out` names a regular file or nothing: a named pipe (or a device, or a
/// folder) there is refused and left as it was (it was replaced by a regular
/// file). A temporary file that a killed run left beside the target (its
/// process gone) is removed by the next run that writes that target; one of
/// a running process is not.
#[test]
fn outputs_replace_only_regular_files_and_clean_what_a_killed_run_left() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe.svg");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let plot = |out: &std::path::Path| {
        bin().args(["plot", "--shape", "flat", "--vbar", "0:1:5", "--amp", "0.5", "--out"]).arg(out).output().unwrap()
    };
    let out = plot(&fifo);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.code() == Some(2) && err.contains("exists and is not a regular file"), "{err}");
    assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
    // pid 4294967295 never runs; our own test process does.
    let stale = dir.path().join(".fig.svg.fricosc-4294967295-0.tmp");
    let live = dir.path().join(format!(".fig.svg.fricosc-{}-0.tmp", std::process::id()));
    std::fs::write(&stale, "half").unwrap();
    std::fs::write(&live, "half").unwrap();
    assert!(plot(&dir.path().join("fig.svg")).status.success());
    assert!(!stale.exists() && live.exists());
}

/// A UTF-8 byte-order mark (written by spreadsheets) is not part of a header.
#[test]
fn a_byte_order_mark_is_tolerated() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-bom-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let path = dir.join("t.csv");
    std::fs::write(&path, "\u{feff}vbar,amp,mu_ratio\n0.5,0.5,0.8992738983331657\n").unwrap();
    let out = bin().args(["validate", path.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

/// Misleading or silent cases of the hostile-input issue: each is now a clear error or normalised.
#[test]
fn negative_zero_empty_out_and_history_springs() {
    let out = bin().args(["table", "--vbar", "-0.0", "--amp", "0.5", "--format", "csv"]).output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(!text.contains("-0.0"), "{text}");
    for args in [["bench", "--out", ""], ["figures", "--out", ""]] {
        let out = bin().args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains("output folder is empty"));
    }
    let out = bin()
        .args(["history", "--shape", "parabolic", "--vbar", "0.3", "--amp", "0.5", "--springs", "2000000"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("history springs: 2000000 is more than the limit of 1000000"), "{err}");
    assert!(out.stdout.is_empty());
}

fn run_stdin(args: &[&str], input: &str) -> std::process::Output {
    use std::io::Write;
    let mut child =
        bin().args(args).stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    child.stdin.take().unwrap().write_all(input.as_bytes()).unwrap();
    child.wait_with_output().unwrap()
}

fn refused(out: &std::process::Output, needle: &str) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains(needle), "{err}");
    assert_eq!(err.lines().count(), 1);
    assert!(out.stdout.is_empty());
}

/// Ambiguous or empty tables are refused, not read in some arbitrary way.
#[test]
fn duplicate_keys_duplicate_columns_and_empty_tables_are_refused() {
    refused(
        &run_stdin(&["batch"], r#"[{"shape":"flat","vbar":0.1,"vbar":0.9,"amp":1}]"#),
        "row 0: duplicate key 'vbar'",
    );
    refused(&run_stdin(&["validate", "-"], r#"[{"vbar":0.1,"amp":1,"amp":2,"mu_ratio":0.5}]"#), "duplicate key 'amp'");
    refused(&run_stdin(&["validate", "-"], "vbar,amp,vbar,mu_ratio\n0.5,0.5,0.5,0.9\n"), "column 'vbar' twice");
    refused(&run_stdin(&["validate", "-", "--max-error", "0"], "vbar,amp,mu_ratio\n"), "has no rows");
    refused(&run_stdin(&["validate", "-"], r#"{"rows": []}"#), "has no rows");
    // Extra columns are named in the report.
    let out = run_stdin(&["validate", "-"], "vbar,amp,mu_ratio,note\n0.5,0.5,0.8992738983331657,x\n");
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["ignored_columns"], serde_json::json!(["note"]));
}

/// A shape with a comma is quoted in CSV output and reads back as one field.
#[test]
fn csv_output_is_real_csv() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-csv-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let file = dir.join("a,b.csv");
    std::fs::write(&file, "r,f\n0,0\n1,0.5\n2,2\n3,4.5\n").unwrap();
    let shape = format!("profile:{}@2", file.display());
    let out =
        bin().args(["table", "--shape", &shape, "--vbar", "0.3", "--amp", "0.5", "--format", "csv"]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let mut rd = csv::Reader::from_reader(&out.stdout[..]);
    let rec = rd.records().next().unwrap().unwrap();
    assert_eq!(&rec[0], shape.as_str());
    assert_eq!(rec.len(), 5);
}

/// Batch rows keep their own bytes; results are spliced in before the closing brace.
#[test]
fn batch_keeps_row_bytes_and_replaces_given_results() {
    let out = run_stdin(&["batch"], "[{\"shape\": \"flat\",  \"vbar\": 1.5, \"amp\": 0.5, \"x\": [1,  2]},\n{\"shape\":\"flat\",\"vbar\":2,\"amp\":1,\"mu_ratio\":7}]");
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains(
            "{\"shape\": \"flat\",  \"vbar\": 1.5, \"amp\": 0.5, \"x\": [1,  2],\"mu_ratio\":1.0,\"reduction\":0.0}"
        ),
        "{text}"
    );
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v[1]["mu_ratio"], 1.0);
    assert_eq!(v[1].as_object().unwrap().len(), 5);
}

/// Scene edge values: each was a panic, a `null` with exit 0, or a misleading message.
#[test]
fn scene_edge_values_are_errors_naming_the_cause() {
    let base = serde_json::json!({
        "materials": {"e1_pa": 2.1e11, "nu1": 0.3, "e2_pa": 2.1e11, "nu2": 0.3},
        "mu0": 0.5,
        "indenter": {"sphere": {"radius_m": 0.005}},
        "loading": {"mean_indentation_m": 1e-6},
        "oscillation": {"amplitude_m": 0.5e-6, "frequency_hz": 100.0},
        "velocity": {"values_m_per_s": [0.0, 1e-4]}
    });
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-scene-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let run = |patch: &[(&str, serde_json::Value)]| {
        let mut s = base.clone();
        for (path, v) in patch {
            let mut node = &mut s;
            let keys: Vec<&str> = path.split('.').collect();
            for k in &keys[..keys.len() - 1] {
                node = &mut node[*k];
            }
            node[keys[keys.len() - 1]] = v.clone();
        }
        let f = dir.join("s.json");
        std::fs::write(&f, s.to_string()).unwrap();
        bin().args(["scene", f.to_str().unwrap()]).output().unwrap()
    };
    use serde_json::json;
    let cases: Vec<(Vec<(&str, serde_json::Value)>, &str)> = vec![
        (vec![("loading", json!({"mean_normal_force_n": 1e300}))], "exceeds the sphere radius"),
        (vec![("oscillation.frequency_hz", json!(1e308))], "frequency_hz"),
        (vec![("materials.g1_pa", json!(5e-324))], "G*"),
        (vec![("materials.e1_pa", json!(5e-324))], "E*"),
        (vec![("mu0", json!(5e-324))], "critical velocity"),
        (vec![("mu0", json!(1e300))], "mu0"),
        (
            vec![(
                "velocity",
                json!({"sweep": {"start_m_per_s": 5e-324, "stop_m_per_s": 1.0, "count": 5, "log": true}}),
            )],
            "overflow",
        ),
        (vec![("velocity.values_m_per_s", json!([1.7e308]))], "rows[0].vbar"),
        (vec![("loading.mean_indentation_m", json!(1e300))], "exceeds the sphere radius"),
        (vec![("loading.mean_indentation_m", json!(0.01))], "exceeds the sphere radius"),
        (vec![("oscillation.amplitude_m", json!(0.0))], "amplitude_m"),
    ];
    for (patch, needle) in cases {
        let out = run(&patch);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{patch:?}: {err} {}", String::from_utf8_lossy(&out.stdout));
        assert!(err.contains(needle), "{patch:?}: {err}");
        assert!(out.stdout.is_empty(), "{patch:?}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    // A cone under 1e300 N panicked; the model is scale-free, so it is answered.
    let out = run(&[
        ("indenter", json!({"cone": {"half_angle_deg": 60.0}})),
        ("loading", json!({"mean_normal_force_n": 1e300})),
    ]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!((v[0]["mean_normal_force_n"].as_f64().unwrap() / 1e300 - 1.0).abs() < 1e-12);
    // An unreachable load names the smallest reachable force.
    let out = run(&[("loading", json!({"mean_normal_force_n": 1e-12})), ("oscillation.amplitude_m", json!(1e-5))]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("smallest reachable mean normal force is about"));
    // A power law of exponent 300 works (the hand-written Gamma overflowed from 283).
    let out = run(&[("indenter", json!({"power_law": {"c": 1.0, "n": 300.0}}))]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // A contact radius beyond 0.1 R warns on stderr, still answers.
    let out = run(&[("loading.mean_indentation_m", json!(1e-4))]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).starts_with("warning:"));
    // A positional array is not a scene.
    let f = dir.join("arr.json");
    std::fs::write(&f, "[]").unwrap();
    let out = bin().args(["scene", f.to_str().unwrap()]).output().unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("a scene is a JSON object"));
}

/// Errors found after some rows were computed used to leave those rows on stdout.
#[test]
fn nothing_on_stdout_when_the_exit_code_is_2() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-late-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let gx = dir.join("sq.csv");
    let rows: String = (0..=40).map(|i| 0.05 * i as f64).map(|x| format!("{x},{}\n", x * x)).collect();
    std::fs::write(&gx, format!("x,g\n{rows}")).unwrap();
    let gx_shape = format!("gx:{}@1", gx.display());
    let cases: Vec<(Vec<&str>, &str)> = vec![
        // amp 5 needs g up to 6 U0; the table ends at 4: the amp 0.5 rows came out first.
        (vec!["table", "--shape", &gx_shape, "--vbar", "0:1:100", "--amp", "0.5,5"], "before the contact edge"),
        (
            vec!["table", "--vbar", "0:1:5", "--amp", "0.5", "--method", "stepping", "--steps-per-period", "0"],
            "steps-per-period",
        ),
        (
            // Stepping a table (now supported): amp 5 needs the table beyond its end.
            vec![
                "table",
                "--shape",
                &gx_shape,
                "--vbar",
                "0.5",
                "--amp",
                "0.5,5",
                "--method",
                "stepping",
                "--springs",
                "50",
            ],
            "before the contact edge",
        ),
        (vec!["table", "--vbar", "0.9999999999999998:0.9999999999999999:3", "--amp", "0.5"], "distinct double values"),
        (vec!["point", "--vhat", "1e308", "--amp", "1e-10"], "vhat / amp = 1e308 / 1e-10 overflows"),
        (
            vec!["table", "--vbar", "0.5", "--amp", "0.5", "--method", "stepping", "--steps-per-period", "-1"],
            "invalid value '-1'",
        ),
        (
            vec![
                "history",
                "--shape",
                "flat",
                "--vbar",
                "0.3",
                "--amp",
                "0.5",
                "--periods",
                "10000000",
                "--samples",
                "1",
            ],
            "history rows (samples + 1 + events)",
        ),
        (
            vec!["history", "--shape", "parabolic", "--vbar", "0.3", "--amp", "0.5", "--spring-at", "0:1:10000000"],
            "chosen-spring values",
        ),
        (
            vec![
                "history",
                "--shape",
                "parabolic",
                "--vbar",
                "0.3",
                "--amp",
                "0.5",
                "--spring-at",
                "0:1:100000",
                "--samples",
                "1000",
            ],
            "chosen-spring values",
        ),
        (
            vec!["history", "--shape", "parabolic", "--vbar", "0.3", "--amp", "0.5", "--spring-at", "-1e308:1e308:3"],
            "spring position = -1e308",
        ),
    ];
    for (args, needle) in cases {
        let out = bin().args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}: {} bytes on stdout", out.stdout.len());
    }
    let file = dir.join("afile");
    std::fs::write(&file, "x").unwrap();
    let out = bin().args(["figures", "--out", file.to_str().unwrap()]).output().unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("exists and is not a folder"));
}

/// A profile one row past the documented limit is refused as it is read, before
/// any transform work: the limit is enforced, and quickly (a transform of
/// 1,000,001 rows would take half a minute).
#[test]
fn a_profile_past_the_row_limit_is_refused_before_the_transform() {
    use std::fmt::Write as _;
    let rows = fricosc::contact::MAX_TABLE_ROWS + 1;
    let mut text = String::with_capacity(rows * 12);
    for i in 0..rows {
        let _ = writeln!(text, "{i},{i}");
    }
    let scratch = tempfile::Builder::new().prefix("fricosc-rows-").tempdir().unwrap();
    let path = scratch.path().join("rows.csv");
    std::fs::write(&path, text).unwrap();
    let shape = format!("profile:{}@1", path.display());
    let out = bin().args(["point", "--shape", &shape, "--vbar", "0.3", "--amp", "0.5"]).output().unwrap();
    refused(&out, &format!("is more than the limit of {}", fricosc::contact::MAX_TABLE_ROWS));
}
