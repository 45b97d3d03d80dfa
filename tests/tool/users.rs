//! `validate` on the files of a stepper written by someone else
//! (`src/python/examples/user_stepper.py` -> `data/user-stepper/`: numpy, SI
//! units, the oscillation written `u0 + du cos(omega t)`, pandas' JSON), each
//! with the problem it must name: a phase-shifted history, forces in newtons
//! of a curved shape, a numpy header, a pandas JSON, a non-converging series
//! (springs cut off at the mean contact radius), a mean over 0.95 of a period.
use crate::common::run as cli;

use std::path::PathBuf;
use std::process::Output;

fn file(name: &str) -> String {
    let p: PathBuf = [env!("CARGO_MANIFEST_DIR"), "data", "user-stepper", name].iter().collect();
    p.display().to_string()
}

fn run(args: &[&str], stdin: Option<&str>) -> Output {
    cli::run(args, stdin)
}

/// The JSON report of a run that exits with `code`.
fn report(args: &[&str], stdin: Option<&str>, code: i32) -> serde_json::Value {
    let out = run(args, stdin);
    assert_eq!(out.status.code(), Some(code), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), 1, "compact JSON: one line");
    serde_json::from_str(&text).unwrap()
}

fn kinds(doc: &serde_json::Value) -> Vec<String> {
    doc["findings"].as_array().unwrap().iter().map(|f| f["kind"].as_str().unwrap().to_string()).collect()
}

const OMEGA: &str = "125663.70614359172"; // 2 pi 20 kHz

/// The history written with `u0 + du cos(omega t)` and `--omega`: the offset pi
/// is found from the normal force and named as that convention; after aligning,
/// the tangential error is the scheme's (observed 5.9e-4) and the normal force
/// agrees to rounding. Before, the file was compared pi out of phase (error 1.41).
/// Without `--omega` the period comes from the normal force: the same errors.
/// The two periods of the file start one step past a period: both count.
#[test]
fn a_phase_shifted_history_is_aligned_and_named() {
    let base = ["validate", "--history", "--vbar", "0.3", "--amp", "1.5", "--static-force", "2.0", "--mu0", "0.3"];
    let hist = file("history-flat.csv");
    let with = report(&[&base[..], &[hist.as_str(), "--omega", OMEGA, "--format", "json"]].concat(), None, 0);
    let origin = &with["time_origin"];
    assert_eq!(origin["source"], "normal_force");
    assert_eq!(origin["offset"].as_f64().unwrap(), std::f64::consts::PI);
    assert_eq!(origin["convention"], "u0 + du cos(omega t)");
    assert_eq!(with["periods"], 2);
    let err = with["max_abs_error"].as_f64().unwrap();
    assert!((4e-4..8e-4).contains(&err), "{err}");
    assert!(with["normal"]["max_abs_error"].as_f64().unwrap() < 1e-12, "{}", with["normal"]);
    assert!((with["normal"]["mean_ratio"].as_f64().unwrap() - 1.0).abs() < 1e-12);
    assert_eq!(kinds(&with), Vec::<String>::new());
    let without = report(&[&base[..], &[hist.as_str(), "--format", "json"]].concat(), None, 0);
    assert_eq!(without["periods"], 2);
    let w = without["time_origin"]["omega"].as_f64().unwrap();
    assert!((w / OMEGA.parse::<f64>().unwrap() - 1.0).abs() < 1e-12, "{w}");
    let e2 = without["max_abs_error"].as_f64().unwrap();
    assert!((e2 - err).abs() < 1e-9, "{e2} vs {err}");
    // The summary says it in words.
    let out = run(&[&base[..], &[hist.as_str(), "--omega", OMEGA, "--format", "summary"]].concat(), None);
    let s = String::from_utf8(out.stdout).unwrap();
    assert!(s.contains("Time origin of your file: +3.141593 rad") && s.contains("u_z = u0 + du cos(omega t)"), "{s}");
}

/// The same history shifted to the seed's convention (`t + pi/omega`): offset 0,
/// "the seed's", the same errors.
#[test]
fn a_history_in_the_seeds_convention_needs_no_shift() {
    let text = std::fs::read_to_string(file("history-flat.csv")).unwrap();
    let half = std::f64::consts::PI / OMEGA.parse::<f64>().unwrap();
    let mut shifted = String::from("t,normal,tangential\n");
    for line in text.lines().skip(1) {
        let f: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        shifted += &format!("{:?},{:?},{:?}\n", f[0] + half, f[1], f[2]);
    }
    let args = [
        "validate",
        "--history",
        "-",
        "--vbar",
        "0.3",
        "--amp",
        "1.5",
        "--kz-u0",
        "2.0",
        "--mu0",
        "0.3",
        "--omega",
        OMEGA,
        "--format",
        "json",
    ];
    let doc = report(&args, Some(&shifted), 0);
    assert_eq!(doc["time_origin"]["offset"], 0.0);
    assert_eq!(doc["time_origin"]["convention"], "u0 - du cos(omega t)");
    let err = doc["max_abs_error"].as_f64().unwrap();
    assert!((4e-4..8e-4).contains(&err), "{err}");
}

/// A paraboloid's history in newtons: with `--static-force` the Hertz force at
/// `u0` ((4/3) E* R^1/2 u0^3/2 = 2/15 N) the normal force agrees to the
/// stepper's 1000 springs (mean within 1e-6) and the tangential one to its
/// scheme (observed 2.1e-3, first order); with the flat punch's idea of the unit
/// (the foundation's stiffness times u0: 0.2 N) the normal column's mean is off
/// by a third and named (exit 1).
#[test]
fn a_curved_history_in_newtons_is_read_with_its_static_force() {
    let hist = file("history-parabolic.csv");
    let base =
        ["validate", "--history", &hist, "--shape", "parabolic", "--vbar", "0.3", "--amp", "1.5", "--mu0", "0.3"];
    let good = report(&[&base[..], &["--static-force", "0.13333333333333333", "--format", "json"]].concat(), None, 0);
    assert!((good["normal"]["mean_ratio"].as_f64().unwrap() - 1.0).abs() < 1e-6, "{}", good["normal"]);
    let err = good["max_abs_error"].as_f64().unwrap();
    assert!(err < 4e-3, "{err}");
    assert_eq!(kinds(&good), Vec::<String>::new());
    let wrong = report(&[&base[..], &["--static-force", "0.2", "--format", "json"]].concat(), None, 1);
    assert_eq!(kinds(&wrong), ["normal_scale"]);
    let ratio = wrong["normal"]["mean_ratio"].as_f64().unwrap();
    assert!((ratio - 2.0 / 3.0).abs() < 1e-6, "{ratio}");
    assert!(wrong["findings"][0]["hint"].as_str().unwrap().contains("--static-force"));
    // --report-only: the same report, exit 0.
    report(&[&base[..], &["--static-force", "0.2", "--format", "json", "--report-only"]].concat(), None, 0);
}

/// numpy's `# vbar,amp,mu_ratio` header is read; so are `;`, tab and
/// whitespace delimiters (numpy's default) with the same values; a decimal
/// comma is refused with what to do; a file without any header says how numpy
/// writes one.
#[test]
fn tables_as_numpy_writes_them() {
    let text = std::fs::read_to_string(file("flat@1000.csv")).unwrap();
    assert!(text.starts_with("# vbar,amp,mu_ratio\n"));
    let doc = report(&["validate", &file("flat@1000.csv"), "--format", "json"], None, 0);
    assert_eq!(doc["format"], "CSV (',' delimited)");
    assert_eq!(doc["n"], 18);
    let err = doc["max_abs_error"].as_f64().unwrap();
    assert!((1e-4..1e-3).contains(&err), "{err}");
    for (delim, name) in [(";", "';'"), ("\t", "tab"), (" ", "whitespace")] {
        let t = text.replace(',', delim);
        let d = report(&["validate", "-", "--format", "json"], Some(&t), 0);
        assert_eq!(d["format"], format!("CSV ({name} delimited)"));
        assert_eq!(d["max_abs_error"], doc["max_abs_error"]);
    }
    let comma = "vbar;amp;mu_ratio\n0,2;0,5;0,71\n";
    let out = run(&["validate", "-"], Some(comma));
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("decimal commas are not read"));
    let bare: String = text.lines().skip(1).map(|l| format!("{l}\n")).collect();
    let out = run(&["validate", "-"], Some(&bare));
    assert!(String::from_utf8_lossy(&out.stderr).contains("np.savetxt(file, rows, header='vbar,vhat"));
}

/// pandas' default `to_json()` (the `columns` orient) gives the report of the
/// CSV (to its 10 significant digits: pandas' default `double_precision`); so
/// do the other orients with names and JSON Lines; the `values` orient (no
/// names) is refused with the orient to use.
#[test]
fn tables_as_pandas_writes_them() {
    let csv = report(&["validate", &file("flat@1000.csv"), "--format", "json"], None, 0);
    let doc = report(&["validate", &file("flat.json"), "--format", "json"], None, 0);
    assert_eq!(doc["format"], "pandas 'columns' JSON");
    let errors = |d: &serde_json::Value| -> Vec<f64> {
        d["rows"].as_array().unwrap().iter().map(|r| r["error"].as_f64().unwrap()).collect()
    };
    for (x, y) in errors(&doc).iter().zip(errors(&csv)) {
        assert!((x - y).abs() <= 1e-10, "{x} vs {y}");
    }
    assert_eq!(errors(&doc).len(), 18);
    // The other orients, built from the same rows.
    let rows: Vec<(f64, f64, f64)> = csv["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| (r["vbar"].as_f64().unwrap(), r["amp"].as_f64().unwrap(), r["mu_ratio"].as_f64().unwrap()))
        .collect();
    let rec = |&(v, a, m): &(f64, f64, f64)| format!(r#"{{"vbar":{v:?},"amp":{a:?},"mu_ratio":{m:?}}}"#);
    let records = format!("[{}]", rows.iter().map(rec).collect::<Vec<_>>().join(","));
    let index = format!(
        "{{{}}}",
        rows.iter().enumerate().map(|(i, r)| format!("\"{i}\":{}", rec(r))).collect::<Vec<_>>().join(",")
    );
    let data = rows.iter().map(|(v, a, m)| format!("[{v:?},{a:?},{m:?}]")).collect::<Vec<_>>().join(",");
    let split = format!(
        r#"{{"columns":["vbar","amp","mu_ratio"],"index":[{}],"data":[{data}]}}"#,
        (0..rows.len()).map(|i| i.to_string()).collect::<Vec<_>>().join(",")
    );
    let table = format!(
        r#"{{"schema":{{"fields":[{{"name":"index","type":"integer"}}],"primaryKey":["index"]}},"data":[{}]}}"#,
        rows.iter()
            .enumerate()
            .map(|(i, (v, a, m))| format!(r#"{{"index":{i},"vbar":{v:?},"amp":{a:?},"mu_ratio":{m:?}}}"#))
            .collect::<Vec<_>>()
            .join(",")
    );
    let lines: String = rows.iter().map(|r| rec(r) + "\n").collect();
    for (text, format) in [
        (records, "JSON array of rows"),
        (index, "pandas 'index' JSON"),
        (split, "pandas 'split' JSON"),
        (table, "pandas 'table' JSON"),
        (lines, "JSON Lines"),
    ] {
        let d = report(&["validate", "-", "--format", "json"], Some(&text), 0);
        assert_eq!(d["format"], format);
        assert_eq!(d["rows"], csv["rows"], "{format}");
    }
    let values = format!("[{data}]");
    let out = run(&["validate", "-"], Some(&values));
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("orient='records'"));
    let null = r#"{"vbar":{"0":null},"amp":{"0":0.5},"mu_ratio":{"0":0.5}}"#;
    let out = run(&["validate", "-"], Some(null));
    assert!(String::from_utf8_lossy(&out.stderr).contains("'vbar' is null (pandas writes NaN"));
}

/// Springs cut off at the mean contact radius: every row's error is the same
/// at every resolution (observed orders -0.2 to 0.1; before, no finding and
/// "needed" resolutions of 1e200): named `resolution_independent`, the needed
/// resolutions `unreachable`, exit 1. The correct paraboloid converges at first
/// order with no finding (exit 0).
#[test]
fn a_non_converging_series_is_named() {
    let series = |name: &str, code: i32| {
        let files: Vec<String> = [250, 500, 1000].iter().map(|m| file(&format!("{name}@{m}.csv"))).collect();
        let mut args = vec!["validate", "--series", "--shape", "parabolic", "--target", "1e-6", "--format", "json"];
        args.extend(files.iter().map(String::as_str));
        report(&args, None, code)
    };
    let cut = series("parabolic-cutoff", 1);
    assert!(kinds(&cut).contains(&"resolution_independent".to_string()), "{:?}", kinds(&cut));
    let rows = cut["rows"].as_array().unwrap();
    let stuck = rows.iter().filter(|r| r["status"] == "resolution_independent").count();
    assert!(stuck >= 12, "{stuck} of {}", rows.len());
    let failing = |r: &&serde_json::Value| r["status"] != "exact" && r["status"] != "converging";
    assert!(rows.iter().filter(failing).all(|r| r["needed_resolution"] == "unreachable"));
    let good = series("parabolic", 0);
    assert_eq!(kinds(&good), Vec::<String>::new());
    let rows = good["rows"].as_array().unwrap();
    assert!(rows.iter().all(|r| r["status"] == "converging" || r["status"] == "exact"), "{good}");
    let converging = rows.iter().filter(|r| r["status"] == "converging");
    assert!(converging.map(|r| r["needed_resolution"].as_f64().unwrap()).all(|m| m > 500.0 && m < 1e6));
}

/// The mean over 0.95 of the last period: the `vbar = 0` rows (nothing moves
/// there; the exact value is 1 - amp) are as far off as the others: named
/// `static_limit` in one table; in the series every moving row is
/// resolution-independent too.
#[test]
fn a_window_short_of_a_period_is_named() {
    let one = report(&["validate", &file("flat-window95@1000.csv"), "--format", "json"], None, 1);
    assert_eq!(kinds(&one), ["static_limit"]);
    assert_eq!(one["findings"][0]["rows"], serde_json::json!([0]));
    // The correct stepper's vbar = 0 rows are exact: no finding.
    let ok = report(&["validate", &file("flat@1000.csv"), "--format", "json"], None, 0);
    assert_eq!(kinds(&ok), Vec::<String>::new());
    let files: Vec<String> = [250, 500, 1000, 2000].iter().map(|m| file(&format!("flat-window95@{m}.csv"))).collect();
    let mut args = vec!["validate", "--series", "--format", "json"];
    args.extend(files.iter().map(String::as_str));
    let s = report(&args, None, 1);
    assert_eq!(kinds(&s), ["static_limit", "resolution_independent"]);
    let correct: Vec<String> = [250, 500, 1000, 2000].iter().map(|m| file(&format!("flat@{m}.csv"))).collect();
    let mut args = vec!["validate", "--series", "--format", "json"];
    args.extend(correct.iter().map(String::as_str));
    let c = report(&args, None, 0);
    assert_eq!(kinds(&c), Vec::<String>::new());
}

/// `--peer M`: the stepping peer at the user's resolution beside each row. The
/// cut-off springs' rows with ten times the peer's error are named (rms 4.9
/// times the peer's); the correct stepper's errors are the peer's size (rms
/// ratio 1.04, no finding).
#[test]
fn the_peer_separates_bugs_from_discretisation() {
    let args = |name: &str| {
        vec![
            "validate".to_string(),
            file(name),
            "--shape".into(),
            "parabolic".into(),
            "--peer".into(),
            "250".into(),
            "--format".into(),
            "json".into(),
        ]
    };
    let a = args("parabolic-cutoff@250.csv");
    let cut = report(&a.iter().map(String::as_str).collect::<Vec<_>>(), None, 1);
    assert!(kinds(&cut).contains(&"worse_than_peer".to_string()), "{:?}", kinds(&cut));
    assert_eq!(cut["peer"]["steps_per_period"], 250);
    let a = args("parabolic@250.csv");
    let good = report(&a.iter().map(String::as_str).collect::<Vec<_>>(), None, 0);
    assert_eq!(kinds(&good), Vec::<String>::new());
    let ratio = |d: &serde_json::Value| d["rms_error"].as_f64().unwrap() / d["peer"]["rms_error"].as_f64().unwrap();
    assert!((0.8..1.25).contains(&ratio(&good)), "{}", ratio(&good));
    assert!(ratio(&cut) > 3.0, "{}", ratio(&cut));
    // The CSV has the peer's column.
    let mut a = args("parabolic@250.csv");
    a[7] = "csv".into();
    let out = run(&a.iter().map(String::as_str).collect::<Vec<_>>(), None);
    assert!(String::from_utf8(out.stdout).unwrap().lines().next().unwrap().ends_with(",peer_error"));
}

/// `--format csv` of a history: one line per sample of the last period, with
/// the exact and the file's forces and their errors.
#[test]
fn a_history_comparison_as_csv() {
    let hist = file("history-flat.csv");
    let args = [
        "validate",
        "--history",
        &hist,
        "--vbar",
        "0.3",
        "--amp",
        "1.5",
        "--static-force",
        "2",
        "--mu0",
        "0.3",
        "--format",
        "csv",
    ];
    let out = run(&args, None);
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("index,tau,exact,yours,error,normal_exact,normal_yours,normal_error"));
    let rows: Vec<Vec<f64>> = lines.map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect();
    assert_eq!(rows.len(), 1000);
    for r in &rows {
        assert_eq!(r[4], r[3] - r[2]);
        assert!(r[7].abs() < 1e-12, "{r:?}");
    }
}

/// `plot --overlay`: the user's points as markers over the exact curves, one
/// group per amplitude in the colour of that amplitude's curve; a file for
/// another shape is refused.
#[test]
fn plot_overlays_your_points() {
    let out = run(&["plot", "--amp", "0.5,1.5", "--vbar", "0:1.2:25", "--overlay", &file("flat@250.csv")], None);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let svg = String::from_utf8(out.stdout).unwrap();
    let group = |name: &str| {
        let at = svg.find(&format!("data-series=\"{name}\"")).unwrap_or_else(|| panic!("{name}: {svg}"));
        svg[at..].split("</g>").next().unwrap().to_string()
    };
    for a in ["0.5", "1.5"] {
        let mine = group(&format!("flat@250.csv, du/u0 = {a}"));
        assert_eq!(mine.matches("<circle").count(), 9, "{mine}");
        let curve = group(&format!("exact, du/u0 = {a}"));
        let colour = |g: &str, key: &str| g.split(key).nth(1).unwrap()[..7].to_string();
        assert_eq!(colour(&mine, "fill=\""), colour(&curve, "stroke=\""));
    }
    let other = run(
        &["plot", "--shape", "cone", "--amp", "0.5", "--vbar", "0:1:5", "--overlay", "-"],
        Some("shape,vbar,amp,mu_ratio\nflat,0.1,0.5,0.6\n"),
    );
    assert_eq!(other.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&other.stderr).contains("its points are for shape 'flat'"));
}
