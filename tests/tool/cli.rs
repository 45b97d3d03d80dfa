//! The command-line interface: each subcommand, and bad input.
// Reference values keep all their published digits on purpose.
#![allow(clippy::excessive_precision)]
use crate::common::run as cli;

use std::process::Output;

fn fricosc(args: &[&str], stdin: Option<&str>) -> Output {
    cli::run(args, stdin)
}

fn json(out: &Output) -> serde_json::Value {
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn point_prints_one_json_object() {
    let v = json(&fricosc(&["point", "--shape", "flat", "--vbar", "0.2", "--amp", "0.5"], None));
    assert_eq!(v["shape"], "flat");
    assert_eq!(v["regime"], "permanent_stick_slip");
    assert!((v["mu_ratio"].as_f64().unwrap() - 0.7145191049466343399125).abs() < 1e-15);
    assert_eq!(v["events"].as_array().unwrap().len(), 2);
    // --vhat: vbar = vhat / amp.
    let w = json(&fricosc(&["point", "--vhat", "0.1", "--amp", "0.5"], None));
    assert_eq!(w["vbar"], 0.2);
    assert_eq!(w["mu_ratio"], v["mu_ratio"]);
}

#[test]
fn table_json_and_csv_agree() {
    let v = json(&fricosc(&["table", "--shape", "flat", "--amp", "0,0.2,0.4", "--vbar", "0:1.2:121"], None));
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 363);
    assert_eq!(rows[0]["vbar"], 0.0);
    assert_eq!(rows[362]["vbar"], 1.2);
    let csv = fricosc(&["table", "--amp", "0,0.2,0.4", "--vbar", "0:1.2:121", "--format", "csv"], None);
    let text = String::from_utf8(csv.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "shape,vbar,amp,mu_ratio,reduction");
    assert_eq!(lines.len(), 364);
    for (line, row) in lines[1..].iter().zip(rows) {
        let f: Vec<&str> = line.split(',').collect();
        // Round-trip precision: the CSV text parses to the same f64 as the JSON number.
        assert_eq!(f[3].parse::<f64>().unwrap(), row["mu_ratio"].as_f64().unwrap());
    }
}

/// One number prints as one text in every command: `point`'s JSON (serde_json),
/// a table's JSON and CSV, and the grid values a table caches, including the
/// exponent forms (`1e+20`, `1e-7`) and values printed on many rows.
#[test]
fn a_number_prints_alike_in_point_and_table() {
    let p = fricosc(&["point", "--vbar", "1e-7", "--amp", "1e20"], None);
    let text = String::from_utf8(p.stdout.clone()).unwrap();
    let v = json(&p);
    assert!(text.contains("\"amp\": 1e+20,") && text.contains("\"vbar\": 1e-7,"), "{text}");
    let csv = fricosc(&["table", "--vbar", "1e-7,0.5,1e-7", "--amp", "1e20,3", "--format", "csv"], None);
    let csv = String::from_utf8(csv.stdout).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 7, "{csv}");
    let mu = v["mu_ratio"].to_string();
    assert_eq!(lines[1], format!("flat,1e-7,1e+20,{mu},{}", v["reduction"]));
    assert_eq!(lines[3], lines[1], "a cached grid value prints as the first time");
    assert!(lines[4].starts_with("flat,1e-7,3.0,") && lines[5].starts_with("flat,0.5,3.0,"), "{csv}");
    let j = fricosc(&["table", "--vbar", "1e-7", "--amp", "1e20"], None);
    let j = String::from_utf8(j.stdout).unwrap();
    assert!(j.contains(&format!("{{\"vbar\":1e-7,\"amp\":1e+20,\"mu_ratio\":{mu},")), "{j}");
}

#[test]
fn mdr_point_reports_bands_and_table_accepts_tol() {
    let v = json(&fricosc(&["point", "--shape", "parabolic", "--vbar", "0.6", "--amp", "1"], None));
    assert!((v["mu_ratio"].as_f64().unwrap() - 0.859054694109526657223).abs() < 1e-13);
    let bands = v["bands"].as_array().unwrap();
    let kinds: Vec<&str> = bands.iter().map(|b| b["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["slip_first", "stick_first", "slip_only"]);
    let share: f64 = bands.iter().map(|b| b["normal_share"].as_f64().unwrap()).sum();
    assert!((share - 1.0).abs() < 1e-14);
    assert_eq!(v["mu_static_ratio"], 0.0);
    let t = json(&fricosc(&["table", "--shape", "cone", "--amp", "0.5", "--vbar", "0.3", "--tol", "1e-6"], None));
    assert!((t["rows"][0]["mu_ratio"].as_f64().unwrap() - 0.6635626779221783060765).abs() < 1e-6);
}

#[test]
fn batch_keeps_other_fields_and_order() {
    let input = r#"[{"id": 7, "shape": "flat", "vbar": 0.5, "amp": 2.0, "note": "x"},
                    {"shape": "flat", "vbar": 1.2, "amp": 0.7}]"#;
    let v = json(&fricosc(&["batch"], Some(input)));
    let a = v.as_array().unwrap();
    assert_eq!(a.len(), 2);
    let keys: Vec<&String> = a[0].as_object().unwrap().keys().collect();
    assert_eq!(keys, ["id", "shape", "vbar", "amp", "note", "mu_ratio", "reduction"]);
    assert!((a[0]["mu_ratio"].as_f64().unwrap() - 0.7482912652565906262288).abs() < 1e-15);
    assert_eq!(a[1]["mu_ratio"], 1.0);
    // The same from a file, and '-' for stdin.
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-cli-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let f = dir.join("in.json");
    std::fs::write(&f, input).unwrap();
    assert_eq!(json(&fricosc(&["batch", f.to_str().unwrap()], None)), v);
    assert_eq!(json(&fricosc(&["batch", "-"], Some(input))), v);
}

#[test]
fn batch_of_a_hundred_thousand_rows() {
    let rows: Vec<String> = (0..100_000)
        .map(|i| format!(r#"{{"shape":"flat","vbar":{},"amp":{}}}"#, (i % 120) as f64 / 100.0, (i % 30) as f64 / 10.0))
        .collect();
    let out = fricosc(&["batch"], Some(&format!("[{}]", rows.join(","))));
    assert_eq!(json(&out).as_array().unwrap().len(), 100_000);
}

/// Each bad input: exit 2, one line on stderr naming the problem, nothing on stdout.
#[test]
fn bad_input_is_one_line_exit_2_and_no_stdout() {
    let cases: &[(&[&str], Option<&str>, &str)] = &[
        (&["point", "--vbar", "nan", "--amp", "1"], None, "not finite"),
        (&["point", "--vbar", "inf", "--amp", "1"], None, "not finite"),
        (&["point", "--vbar", "1e999", "--amp", "1"], None, "not finite"),
        (&["point", "--vbar", "-0.1", "--amp", "1"], None, "must be >= 0"),
        (&["point", "--vbar", "0.1", "--amp", "-1"], None, "must be >= 0"),
        (&["point", "--vbar", "", "--amp", "1"], None, "not a number"),
        (&["point", "--vbar", "abc", "--amp", "1"], None, "not a number"),
        (&["point", "--vhat", "0.1", "--amp", "0"], None, "amp > 0"),
        (&["point", "--vbar", "0.1"], None, "--amp"),
        (&["point", "--shape", "sphere", "--vbar", "0.1", "--amp", "1"], None, "unknown shape"),
        (&["point", "--shape", "power:0", "--vbar", "0.1", "--amp", "1"], None, "must be finite and > 0"),
        (&["point", "--shape", "power:-1", "--vbar", "0.1", "--amp", "1"], None, "must be finite and > 0"),
        (&["point", "--shape", "power:abc", "--vbar", "0.1", "--amp", "1"], None, "not a number"),
        (&["point", "--shape", "power:6.5e91", "--vbar", "0.1", "--amp", "1"], None, "within [0.05, 1e6]"),
        (&["point", "--shape", "parabolic", "--vbar", "0.1", "--amp", "1", "--tol", "0"], None, "tol"),
        (&["table", "--amp", "1", "--vbar", "1:0:3"], None, "below start"),
        (&["table", "--amp", "1", "--vbar", "0:1:0"], None, "count must be >= 1"),
        (&["table", "--amp", "1", "--vbar", "0:1:1000000000000"], None, "more than the limit"),
        (&["table", "--amp", "0:1:100000", "--vbar", "0:1:100000"], None, "more than the limit"),
        (&["table", "--amp", "1,x", "--vbar", "0"], None, "not a number"),
        (&["batch"], Some("[{\"shape\":\"flat\",\"vbar\":0.1,\"amp\":1}"), "malformed JSON"),
        (&["batch"], Some(""), "empty input"),
        (&["batch"], Some("{}"), "JSON array"),
        (&["batch"], Some("[{\"shape\":\"flat\",\"amp\":1}]"), "missing field 'vbar'"),
        (&["batch"], Some("[{\"shape\":\"flat\",\"vbar\":\"0.1\",\"amp\":1}]"), "must be a number"),
        (&["batch"], Some("[{\"shape\":1,\"vbar\":0.1,\"amp\":1}]"), "'shape' must be a string"),
        (
            &["batch"],
            Some("[{\"shape\":\"flat\",\"vbar\":0.1,\"amp\":1},{\"shape\":\"flat\",\"vbar\":-1,\"amp\":1}]"),
            "row 1",
        ),
        (&["batch", "/nonexistent/file.json"], None, "cannot read"),
        (&["batch", "/"], None, "cannot read"),
        (&["frobnicate"], None, "unrecognized subcommand"),
    ];
    for (args, stdin, fragment) in cases {
        let out = fricosc(args, *stdin);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?} wrote to stdout");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(fragment), "{args:?}: '{err}' lacks '{fragment}'");
        assert!(!err.contains("panicked"));
    }
}

#[test]
fn stepping_method_for_point_table_and_batch() {
    let v = json(&fricosc(
        &[
            "point",
            "--shape",
            "parabolic",
            "--vbar",
            "0.3",
            "--amp",
            "0.4",
            "--method",
            "stepping",
            "--steps-per-period",
            "400",
            "--springs",
            "400",
        ],
        None,
    ));
    assert_eq!(v["method"], "stepping");
    assert_eq!(v["steps"], 800);
    assert_eq!(v["springs"], 400);
    // First order in 1/M and 1/N: within 1e-2 of the reference at 400 x 400.
    assert!((v["mu_ratio"].as_f64().unwrap() - 0.7661542311590507962135).abs() < 1e-2);
    let t = json(&fricosc(
        &["table", "--amp", "0.5", "--vbar", "0.5", "--method", "stepping", "--steps-per-period", "20000"],
        None,
    ));
    assert!((t["rows"][0]["mu_ratio"].as_f64().unwrap() - 0.8992738983331656556021).abs() < 1e-7);
    let b = json(&fricosc(
        &["batch", "--method", "stepping", "--steps-per-period", "20000"],
        Some(r#"[{"shape":"flat","vbar":0.5,"amp":0.5}]"#),
    ));
    assert_eq!(b[0]["mu_ratio"], t["rows"][0]["mu_ratio"]);
}

#[test]
fn validate_exit_codes_0_within_1_exceeded_2_bad_input() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-validate-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let table = fricosc(
        &[
            "table",
            "--amp",
            "0.5,1.5",
            "--vbar",
            "0.1:0.9:5",
            "--method",
            "stepping",
            "--steps-per-period",
            "1000",
            "--format",
            "csv",
        ],
        None,
    );
    let csv = dir.join("stepped.csv");
    std::fs::write(&csv, &table.stdout).unwrap();
    let f = csv.to_str().unwrap();
    let within = fricosc(&["validate", "--shape", "flat", f, "--max-error", "1e-3"], None);
    assert_eq!(within.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&within.stdout).unwrap();
    assert_eq!(v["n"], 10);
    let max = v["max_abs_error"].as_f64().unwrap();
    assert!(max > 1e-6 && max < 1e-3, "{max}");
    assert_eq!(v["worst"]["error"].as_f64().unwrap().abs(), max);
    let exceeded = fricosc(&["validate", "--shape", "flat", f, "--max-error", "1e-9"], None);
    assert_eq!(exceeded.status.code(), Some(1));
    assert!(!exceeded.stdout.is_empty(), "the comparison is printed also when it fails");
    // The exact table validates to rounding; JSON input from stdin.
    let exact = fricosc(&["table", "--amp", "0.5,1.5", "--vbar", "0.1:0.9:5"], None);
    let ok = fricosc(&["validate", "-", "--max-error", "0"], Some(std::str::from_utf8(&exact.stdout).unwrap()));
    assert_eq!(ok.status.code(), Some(0), "{}", String::from_utf8_lossy(&ok.stderr));
    for (stdin, frag) in [
        ("vbar,amp\n0.1,0.5\n", "no column 'mu_ratio' (or 'mu'): a table needs vbar (or vhat), amp and mu_ratio"),
        ("[{\"vbar\":0.1,\"mu_ratio\":0.5}]", "no column 'amp'; this table (JSON array of rows) has vbar, mu_ratio"),
        ("[{\"vbar\":0.1,\"amp\":0.5}]", "no column 'mu_ratio' (or 'mu')"),
        ("", "empty input"),
    ] {
        let bad = fricosc(&["validate", "-"], Some(stdin));
        assert_eq!(bad.status.code(), Some(2));
        assert!(bad.stdout.is_empty());
        assert!(String::from_utf8_lossy(&bad.stderr).contains(frag), "{}", String::from_utf8_lossy(&bad.stderr));
    }
}

#[test]
fn quick_bench_writes_json_csv_and_svg_without_failures() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-bench-").tempdir().unwrap();
    let dir = scratch.path().join("out");
    let out = fricosc(&["bench", "--quick", "--out", dir.to_str().unwrap()], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("work-precision.json")).unwrap()).unwrap();
    assert_eq!(report["failures"].as_array().unwrap().len(), 0);
    assert_eq!(report["ratios"].as_array().unwrap().len(), 5, "three stiff cases and two in the plane");
    for r in report["ratios"].as_array().unwrap() {
        let exact = r["exact_error"].as_f64().unwrap();
        assert!(exact <= 1e-13 && exact < r["stepping_error"].as_f64().unwrap(), "{r}");
        // A curved contact in the plane is slower than the quick run's
        // coarse stepping (README states its cost).
        if r["case"] != "parabolic transverse" {
            assert!(r["time_ratio"].as_f64().unwrap() > 1.0, "stepping beat the exact solver: {r}");
        }
    }
    // Points a second on one core for the six kinds (stiff, on a system, in
    // the plane; flat, curved), the plane's with their targets.
    let kinds: Vec<&str> =
        report["throughput"].as_array().unwrap().iter().map(|t| t["kind"].as_str().unwrap()).collect();
    assert!(kinds.len() == 6 && kinds[2].contains("on a system") && kinds[3].contains("parabolic"), "{kinds:?}");
    assert!(kinds[4].starts_with("flat in the plane") && kinds[5].starts_with("parabolic in the plane"));
    let targets: Vec<Option<f64>> =
        report["throughput"].as_array().unwrap().iter().map(|t| t["target"].as_f64()).collect();
    assert_eq!(targets, [None, None, None, None, Some(2e4), Some(200.0)]);
    assert!(report["throughput"]
        .as_array()
        .unwrap()
        .iter()
        .all(|t| t["points_per_second_per_core"].as_f64().unwrap() > 0.0));
    assert!(std::fs::read_to_string(dir.join("work-precision.svg")).unwrap().starts_with("<svg"));
    assert!(std::fs::read_to_string(dir.join("work-precision.csv"))
        .unwrap()
        .starts_with("case,method,setting,error,time_s"));
}

#[test]
fn tabulated_shapes_from_the_command_line_and_their_bad_inputs() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-cli-tab-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let good = dir.join("paraboloid.csv");
    let rows: String = (0..101)
        .map(|i| {
            let r = i as f64 * 0.04;
            format!("{r},{}\n", r * r / 2.0)
        })
        .collect();
    std::fs::write(&good, format!("r,f\n{rows}")).unwrap();
    let spec = format!("profile:{}@1", good.display());
    let v = json(&fricosc(&["point", "--shape", &spec, "--vbar", "0.3", "--amp", "0.4"], None));
    assert!((v["mu_ratio"].as_f64().unwrap() - 0.7661542311590507962135).abs() < 1e-12, "{v}");
    assert!(v["interpolation_error"].as_f64().unwrap() < 1e-12);
    let bad = |name: &str, text: Option<&str>| {
        let p = dir.join(name);
        if let Some(t) = text {
            std::fs::write(&p, t).unwrap();
        }
        format!("profile:{}@1", p.display())
    };
    let cases = [
        (bad("nonmono.csv", Some("0,0\n1,2\n2,1\n")), "must not decrease"),
        (bad("inf.csv", Some("0,0\n1,inf\n2,3\n")), "finite"),
        (bad("empty.csv", Some("")), "at least 3 rows"),
        (bad("missing.csv", None), "cannot read"),
        (format!("profile:{}@1", dir.display()), "cannot read"),
        (format!("profile:{}", good.display()), "mean indentation"),
        (format!("profile:{}@20", good.display()), "wider than the table"),
    ];
    for (spec, frag) in cases {
        let out = fricosc(&["point", "--shape", &spec, "--vbar", "0.3", "--amp", "0.4"], None);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{spec}: {err}");
        assert!(out.stdout.is_empty());
        assert_eq!(err.trim_end().lines().count(), 1);
        assert!(err.contains(frag), "{spec}: '{err}' lacks '{frag}'");
    }
    // The table must reach the contact edge at the requested amplitude.
    let out = fricosc(&["point", "--shape", &spec, "--vbar", "0.3", "--amp", "20"], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("before the contact edge"));
}

/// The same shape, vbar, amp and tolerance give bit-identical values in every command.
#[test]
fn one_value_per_input() {
    let cases = [("flat", "0.3", "1.5"), ("flat", "1e-12", "2"), ("parabolic", "0", "1"), ("cone", "0.45", "0.999")];
    for (shape, vbar, amp) in cases {
        let p = json(&fricosc(&["point", "--shape", shape, "--vbar", vbar, "--amp", amp], None));
        let t = json(&fricosc(&["table", "--shape", shape, "--vbar", vbar, "--amp", amp], None));
        let batch = format!(r#"[{{"shape":"{shape}","vbar":{vbar},"amp":{amp}}}]"#);
        let b = json(&fricosc(&["batch", "-"], Some(&batch)));
        let lib = crate::common::eval(
            &fricosc_cli::input::parse_shape(shape).unwrap(),
            vbar.parse().unwrap(),
            amp.parse().unwrap(),
        )
        .unwrap()
        .ratio
        .mu_ratio;
        let bits = |v: &serde_json::Value| v.as_f64().unwrap().to_bits();
        assert_eq!(bits(&p["mu_ratio"]), lib.to_bits(), "{shape} {vbar} {amp}: point");
        assert_eq!(bits(&t["rows"][0]["mu_ratio"]), lib.to_bits(), "{shape} {vbar} {amp}: table");
        assert_eq!(bits(&b[0]["mu_ratio"]), lib.to_bits(), "{shape} {vbar} {amp}: batch");
    }
}

/// The help texts belong to their commands; no arguments prints the help; options of the
/// stepping peer are refused without `--method stepping`.
#[test]
fn help_texts_and_stepping_only_options() {
    let help = String::from_utf8(fricosc(&["--help"], None).stdout).unwrap();
    let line = |cmd: &str| help.lines().find(|l| l.trim_start().starts_with(cmd)).unwrap_or("").to_string();
    assert!(line("batch").contains("JSON array"), "{help}");
    assert!(line("validate").contains("Compare another code") && !line("validate").contains("JSON array of"), "{help}");
    let table = String::from_utf8(fricosc(&["table", "--help"], None).stdout).unwrap();
    assert!(table.contains("start:stop:count"));
    assert!(!table.contains("fricosc::"), "no code links in help");
    let none = fricosc(&[], None);
    assert_eq!(none.status.code(), Some(2));
    assert!(none.stdout.is_empty());
    assert!(String::from_utf8_lossy(&none.stderr).contains("Usage: fricosc [OPTIONS] <COMMAND>"));
    let out = fricosc(&["point", "--vbar", "0.3", "--amp", "0.5", "--steps-per-period", "10"], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("applies only with --method stepping"));
}

/// `plot`: the user's curves as SVG (stdout) or PNG (by the file's name); every
/// bad request is refused before any work, with nothing on stdout.
#[test]
fn plot_draws_the_users_curves_and_refuses_bad_requests() {
    let out = fricosc(&["plot", "--shape", "cone", "--amp", "0.5,1,2", "--vbar", "0:1.2:61"], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let svg = String::from_utf8(out.stdout).unwrap();
    assert!(fricosc_cli::chart::parse_size(&svg).is_ok());
    assert_eq!(svg.matches("<g data-series=").count(), 3);
    assert!(svg.contains("v\u{304}"));
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-plot-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let png = dir.join("p.png");
    let out = fricosc(&["plot", "--amp", "0.5", "--vhat", "0,0.5,1", "--out", png.to_str().unwrap()], None);
    assert!(out.status.success() && out.stdout.is_empty());
    assert_eq!(&std::fs::read(&png).unwrap()[1..4], b"PNG");
    let thirteen = (1..=13).map(|k| k.to_string()).collect::<Vec<_>>().join(",");
    for (args, message) in [
        (vec!["plot", "--amp", "0.5", "--vbar", "0,1", "--out", "p.pdf"], "must end in .svg or .png"),
        (vec!["plot", "--amp", &thirteen, "--vbar", "0,1"], "amplitudes in one plot"),
        (vec!["plot", "--amp", "0.5", "--vbar", "0:1:100001"], "velocities in one plot"),
        (vec!["plot", "--amp", "0.5", "--vbar", "0.3"], "two different velocities"),
        (vec!["plot", "--amp", "-1", "--vbar", "0,1"], "amp"),
        (vec!["plot", "--shape", "nope", "--amp", "1", "--vbar", "0,1"], "nope"),
    ] {
        let out = fricosc(&args, None);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty() && err.contains(message) && err.lines().count() == 1, "{args:?}: {err}");
    }
}

/// `point` on a system with mass and stiffness: the library's attractor bit
/// for bit (its period, multipliers and events; a curved body's error
/// estimate and springs); the stepping method is refused, as are a system
/// without stiffness and a massless curved body.
#[test]
fn point_on_a_system_reports_the_attractor() {
    let args = ["point", "--vhat", "0.3", "--amp", "0.5", "--system-stiffness", "1", "--frequency-ratio", "0.5"];
    let v = json(&fricosc(&[&args[..], &["--damping", "0.3"]].concat(), None));
    let sys = fricosc::system::System::new(1.0, 0.5, 0.3).unwrap();
    let r =
        crate::common::on_system(&fricosc::Shape::flat(), &fricosc::Conditions::vhat(0.3, 0.5).unwrap(), &sys).unwrap();
    assert_eq!(v["mu_ratio"].as_f64().unwrap(), r.mu_ratio);
    assert_eq!((&v["period"], &v["regime"], &v["vhat"]), (&1.into(), &"period 1".into(), &0.3.into()));
    assert_eq!(v["reduction"].as_f64(), Some(1.0 - r.mu_ratio));
    // The velocity as given: vbar 0.6 stays 0.6 (its vhat is 0.3).
    let given = json(&fricosc(&["point", "--vbar", "0.6", "--amp", "0.5", "--system-stiffness", "1"], None));
    assert!(given["vbar"] == 0.6 && given.get("vhat").is_none(), "{given}");
    assert_eq!(v["events"].as_array().unwrap().len(), r.events.len());
    // A table on the system: each row the library's attractor.
    let table = ["table", "--vbar", "0.6,1.2", "--amp", "0.5", "--system-stiffness", "1", "--frequency-ratio", "0.5"];
    let out = fricosc(&[&table[..], &["--damping", "0.3", "--format", "csv"]].concat(), None);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let rows: Vec<Vec<&str>> = text.lines().skip(1).map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2);
    for (row, vhat) in rows.iter().zip([0.3, 0.6]) {
        let c = fricosc::Conditions::vhat(vhat, 0.5).unwrap();
        assert_eq!(
            row[5].parse::<f64>().unwrap(),
            crate::common::on_system(&fricosc::Shape::flat(), &c, &sys).unwrap().mu_ratio
        );
    }
    let curved =
        json(&fricosc(&[&args[..], &["--damping", "0.3", "--shape", "cone", "--springs", "32"]].concat(), None));
    let r = crate::common::on_system(
        &fricosc::Shape::cone(),
        &fricosc::Conditions::vhat(0.3, 0.5).unwrap(),
        &sys.with_springs(32).unwrap(),
    )
    .unwrap();
    assert_eq!(curved["mu_ratio"].as_f64().unwrap(), r.mu_ratio);
    assert_eq!(curved["error_estimate"].as_f64(), Some(r.error_estimate));
    assert_eq!(curved["springs"].as_u64(), r.springs.map(|n| n as u64));
    let zero = ["point", "--vhat", "0.3", "--amp", "0.5", "--system-stiffness", "0"];
    let massless = ["point", "--vhat", "0.3", "--amp", "0.5", "--system-stiffness", "1", "--shape", "cone"];
    for run in [massless.to_vec(), [&args[..], &["--method", "stepping"]].concat(), zero.to_vec()] {
        let out = fricosc(&run, None);
        assert_eq!(out.status.code(), Some(2), "{run:?}");
        assert!(out.stdout.is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("massless body") || err.contains("exactly only") || err.contains("system-stiffness = 0"),
            "{err}"
        );
    }
}
