//! The command line in the plane: `point` with `--transverse-amp` and
//! `--transverse-phase` gives the library's values bit for bit with the
//! period's events and multiplier, `W = 0` is today's output byte for byte,
//! the plane's stepper answers with `--method stepping`, and bad input is
//! refused (exit 2, one line, nothing on stdout).
use crate::common::run as cli;

use fricosc::plane::Transverse;
use fricosc::{Conditions, Shape};
use std::process::Output;

fn ok(out: &Output) -> serde_json::Value {
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

fn refused(args: &[&str], message: &str) {
    let out = cli::run(args, None);
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    assert!(out.stdout.is_empty(), "{args:?}: stdout {}", String::from_utf8_lossy(&out.stdout));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(message) && err.lines().count() == 1, "{args:?}: {err}");
}

#[test]
fn point_gives_the_librarys_values_events_and_multiplier() {
    let v = ok(&cli::run(
        &[
            "point",
            "--vhat",
            "0.1",
            "--amp",
            "0.8",
            "--tangential-amp",
            "1",
            "--phase",
            "0.3",
            "--transverse-amp",
            "0.8",
            "--transverse-phase",
            "2",
        ],
        None,
    ));
    let c = Conditions::vhat(0.1, 0.8).unwrap().with_tangential(1.0, 0.3).unwrap();
    let e = Shape::flat().evaluate(&c.with_transverse(Transverse::new(0.8, 2.0).unwrap())).unwrap();
    assert_eq!(v["mu_ratio"].as_f64(), Some(e.ratio.mu_ratio));
    assert_eq!(v["transverse_ratio"].as_f64(), e.transverse_ratio);
    assert_eq!(v["error_estimate"].as_f64(), Some(e.error_estimate));
    assert_eq!((v["transverse_amp"].as_f64(), v["transverse_phase"].as_f64()), (Some(0.8), Some(2.0)));
    assert!(v["multiplier"].as_f64().is_some_and(|m| (0.0..1.0).contains(&m)));
    assert!(!v["events"].as_array().unwrap().is_empty());
    // The transverse oscillation alone (amp 0) needs no vbar.
    let v = ok(&cli::run(&["point", "--vhat", "0.05", "--amp", "0", "--transverse-amp", "2"], None));
    assert!(v["transverse_ratio"].as_f64().unwrap().abs() < 1e-15);
}

#[test]
fn no_transverse_amplitude_is_todays_output() {
    for args in [
        &["point", "--vbar", "0.3", "--amp", "0.5"][..],
        &["point", "--vhat", "0.3", "--amp", "1.5", "--tangential-amp", "2"],
    ] {
        let plain = cli::run(args, None);
        let mut with = args.to_vec();
        with.extend(["--transverse-amp", "0", "--transverse-phase", "1"]);
        assert_eq!(cli::run(&with, None).stdout, plain.stdout, "{args:?}");
    }
}

#[test]
fn the_planes_stepper_answers_with_method_stepping() {
    let v = ok(&cli::run(
        &[
            "point",
            "--vhat",
            "0.3",
            "--amp",
            "0.5",
            "--transverse-amp",
            "1.2",
            "--transverse-phase",
            "0.7",
            "--method",
            "stepping",
            "--steps-per-period",
            "20000",
        ],
        None,
    ));
    assert_eq!(v["method"], "stepping");
    let exact = 0.614_622_340_125_886_6;
    let err = (v["mu_ratio"].as_f64().unwrap() - exact).abs();
    assert!(err > 1e-6 && err < 1e-4, "{err:e}: first order at 20,000 steps");
}

#[test]
fn bad_transverse_input_is_refused() {
    let base = ["point", "--vhat", "0.3", "--amp", "0.5"];
    for (extra, message) in [
        (&["--transverse-amp", "-1"][..], "transverse-amp"),
        (&["--transverse-amp", "nan"], "transverse-amp"),
        (&["--transverse-amp", "2e6"], "transverse-amp"),
        (&["--transverse-amp", "1", "--transverse-phase", "2e6"], "transverse-phase"),
        (&["--transverse-phase", "1"], "--transverse-amp"),
        (&["--transverse-amp", "1", "--system-stiffness", "1", "--frequency-ratio", "0.5"], "system"),
    ] {
        let mut args = base.to_vec();
        args.extend(extra);
        refused(&args, message);
    }
}

/// `table --transverse-amp`: every row is the library's value (`W = 0` rows
/// the problem without it, a force across of 0), the columns name the plane's
/// inputs; stepping, a system and more than 1e5 rows are refused.
#[test]
fn table_rows_are_the_librarys() {
    let out = cli::run(
        &[
            "table",
            "--vhat",
            "0.1,0.3",
            "--amp",
            "0.5,1.5",
            "--transverse-amp",
            "0,1.2",
            "--transverse-phase",
            "0.7",
            "--format",
            "csv",
        ],
        None,
    );
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("shape,vhat,amp,tangential_amp,phase,transverse_amp,transverse_phase,mu_ratio,reduction,transverse_ratio,error_estimate")
    );
    let mut n = 0;
    for line in lines {
        let f: Vec<f64> = line.split(',').skip(1).map(|x| x.parse().unwrap()).collect();
        let c = Conditions::vhat(f[0], f[1]).unwrap().with_transverse(Transverse::new(f[4], f[5]).unwrap());
        let e = Shape::flat().evaluate(&c).unwrap();
        assert_eq!(
            (f[6], f[8], f[9]),
            (e.ratio.mu_ratio, e.transverse_ratio.unwrap_or(0.0), e.error_estimate),
            "{line}"
        );
        n += 1;
    }
    assert_eq!(n, 8);
    let base = ["table", "--amp", "0.5", "--transverse-amp", "1"];
    for (extra, message) in [
        (&["--vbar", "0.3", "--method", "stepping"][..], "stiff system"),
        (&["--vbar", "0.3", "--system-stiffness", "1"], "stiff system"),
        (&["--transverse-phase", "0:1:1000", "--vbar", "0:1:1000"], "more than the limit"),
    ] {
        let mut args = base.to_vec();
        args.extend(extra);
        refused(&args, message);
    }
}

/// `history --transverse-amp`: the force across the sliding direction is a
/// column, each sample the library's bit for bit, the point names `W` and
/// `psi`; `W = 0` is today's history byte for byte; a curved shape's is the
/// library's too; the stepped history, chosen springs and a system are
/// refused.
#[test]
fn history_in_the_plane_has_the_force_across() {
    let base = ["history", "--vhat", "0.2", "--amp", "1.4", "--samples", "50", "--periods", "2"];
    let mut args = base.to_vec();
    args.extend(["--transverse-amp", "0.8", "--transverse-phase", "2"]);
    let v = ok(&cli::run(&args, None));
    let c = Conditions::vhat(0.2, 1.4).unwrap().with_transverse(Transverse::new(0.8, 2.0).unwrap());
    let o = fricosc::history::HistoryOptions::default().with_samples(50).with_periods(2);
    let h = fricosc::history::history(&Shape::flat(), &c, &o).unwrap();
    let rows = v["samples"].as_array().unwrap();
    assert_eq!(rows.len(), h.samples.len());
    assert!(rows.len() > 51, "the events are among the samples");
    for (r, s) in rows.iter().zip(&h.samples) {
        assert_eq!(r["tangential"].as_f64(), Some(s.tangential));
        assert_eq!(r["transverse"].as_f64(), s.transverse);
    }
    assert_eq!((v["transverse_amp"].as_f64(), v["transverse_phase"].as_f64()), (Some(0.8), Some(2.0)));
    args.extend(["--format", "csv"]);
    let csv = String::from_utf8(cli::run(&args, None).stdout).unwrap();
    assert_eq!(csv.lines().nth(1), Some("tau,normal,tangential,transverse,event"));
    let cone = [
        "history",
        "--shape",
        "cone",
        "--vhat",
        "0.2",
        "--amp",
        "1.4",
        "--transverse-amp",
        "0.8",
        "--transverse-phase",
        "2",
    ];
    let v = ok(&cli::run(&[&cone[..], &["--samples", "10", "--springs", "50"]].concat(), None));
    let h =
        fricosc::history::history(&Shape::cone(), &c, &o.with_periods(1).with_samples(10).with_springs(50)).unwrap();
    let rows = v["samples"].as_array().unwrap();
    assert_eq!(rows.len(), 11);
    for (r, s) in rows.iter().zip(&h.samples) {
        assert_eq!((r["tangential"].as_f64(), r["transverse"].as_f64()), (Some(s.tangential), s.transverse));
    }
    let mut zero = base.to_vec();
    zero.extend(["--transverse-amp", "0"]);
    assert_eq!(cli::run(&zero, None).stdout, cli::run(&base, None).stdout);
    for (extra, message) in [
        (&["--method", "stepping"][..], "transverse-amp"),
        (&["--shape", "cone", "--spring-at", "0.5"], "spring-at"),
        (&["--system-stiffness", "1", "--frequency-ratio", "0.5"], "system"),
    ] {
        let mut bad = base.to_vec();
        bad.extend(["--transverse-amp", "1"]);
        bad.extend(extra);
        refused(&bad, message);
    }
}

/// A curved body in the plane: `point` gives the library's values bit for
/// bit (its springs in bands; no events of one spring).
#[test]
fn a_curved_point_is_the_librarys() {
    let v = ok(&cli::run(
        &[
            "point",
            "--shape",
            "cone",
            "--vhat",
            "0.3",
            "--amp",
            "1.5",
            "--transverse-amp",
            "1",
            "--transverse-phase",
            "0.7",
        ],
        None,
    ));
    let c = Conditions::vhat(0.3, 1.5).unwrap().with_transverse(Transverse::new(1.0, 0.7).unwrap());
    let e = Shape::cone().evaluate(&c).unwrap();
    assert_eq!(v["mu_ratio"].as_f64(), Some(e.ratio.mu_ratio));
    assert_eq!(v["transverse_ratio"].as_f64(), e.transverse_ratio);
    assert_eq!(v["error_estimate"].as_f64(), Some(e.error_estimate));
}

/// A batch row in the plane without normal oscillation (`amp` 0, the
/// velocity as `vhat`) is answered as `point` answers it (a row of today's
/// problem at `amp` 0 with `vhat` is still refused: `vbar` is undefined).
#[test]
fn a_batch_row_across_without_normal_oscillation_is_the_points() {
    let out = cli::run(&["batch", "-", "--format", "csv"], Some("shape,vhat,amp,transverse_amp\ncone,0.3,0,1.0\n"));
    let text = String::from_utf8(out.stdout).unwrap();
    let v = ok(&cli::run(&["point", "--shape", "cone", "--vhat", "0.3", "--amp", "0", "--transverse-amp", "1"], None));
    let want = format!("cone,0.3,0,1.0,{:?},", v["mu_ratio"].as_f64().unwrap());
    assert!(text.lines().nth(1).is_some_and(|l| l.starts_with(&want)), "{text}");
    let plain = cli::run(&["batch", "-", "--format", "csv"], Some("shape,vhat,amp\ncone,0.3,0\n"));
    assert_eq!(plain.status.code(), Some(2));
    assert!(plain.stdout.is_empty() && String::from_utf8_lossy(&plain.stderr).contains("vbar"));
}

/// `validate` reads a table in the plane from its columns: the force across
/// is compared and written (csv, with the exact value's estimate), a row off across is beyond `--max-error`
/// (exit 1), and the correct table passes (exit 0). `--peer` runs the
/// plane's stepper.
#[test]
fn validate_compares_a_table_in_the_plane() {
    let c = Conditions::vhat(0.3, 1.5).unwrap();
    let e = Shape::flat().evaluate(&c.with_transverse(Transverse::new(1.2, 0.7).unwrap())).unwrap();
    let (mu, tr) = (e.ratio.mu_ratio, e.transverse_ratio.unwrap());
    let table = |across: f64| {
        format!(
            "vhat,amp,transverse_amp,transverse_phase,mu_ratio,transverse_ratio\n0.3,1.5,1.2,0.7,{mu:?},{across:?}\n"
        )
    };
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("plane.csv");
    let file = path.to_str().unwrap();
    std::fs::write(&path, table(tr)).unwrap();
    let out = cli::run(&["validate", file, "--format", "csv", "--max-error", "1e-14"], None);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    for name in ["transverse_amp", "transverse_phase", "transverse_ratio", "transverse_exact", "transverse_error"] {
        assert!(header.contains(&name), "{header:?}");
    }
    // The exact value's estimate, as JSON and the library give it.
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let at = reader.headers().unwrap().iter().position(|h| h == "exact_error_estimate").expect("an estimate column");
    let row = reader.records().next().unwrap().unwrap();
    assert_eq!(row[at].parse::<f64>().unwrap(), e.error_estimate, "{text}");
    std::fs::write(&path, table(tr + 1e-6)).unwrap();
    let out = cli::run(&["validate", file, "--format", "summary", "--max-error", "1e-9"], None);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("the force across: largest error 1.000e-6") && text.contains("max_error"), "{text}");
    let out = cli::run(&["validate", file, "--format", "json", "--peer", "1000"], None);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let peer = v["rows"][0]["transverse_peer_error"].as_f64().unwrap();
    assert!(peer != 0.0 && peer.abs() < 1e-2, "{v}");
}

/// `plot --transverse-amp`: the plane's curves against `vhat`, a table of
/// the same oscillation overlaid (`table --transverse-amp`'s CSV), one at
/// another `W` refused naming its row; on a system, against `vbar` or at
/// several phases, refused by name.
#[test]
fn plot_draws_the_plane_and_overlays_its_table() {
    let dir = tempfile::tempdir().unwrap();
    let table = dir.path().join("plane.csv");
    let rows = ["table", "--vhat", "0.1,0.3", "--amp", "0.5", "--transverse-amp", "1", "--format", "csv"];
    let out = cli::run(&rows, None);
    assert!(out.status.success());
    std::fs::write(&table, &out.stdout).unwrap();
    let plot = ["plot", "--vhat", "0.05,0.2,0.4", "--amp", "0,0.5", "--overlay", table.to_str().unwrap()];
    let out = cli::run(&[&plot[..], &["--transverse-amp", "1"]].concat(), None);
    let svg = String::from_utf8(out.stdout).unwrap();
    assert!(out.status.success() && svg.contains("yours") && svg.contains("<svg"), "{svg}");
    let out = cli::run(&[&plot[..], &["--transverse-amp", "2"]].concat(), None);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.code() == Some(2) && err.contains("row 0") && err.contains("across (2.0, 0.0)"), "{err}");
    let out = cli::run(&plot, None);
    assert!(String::from_utf8_lossy(&out.stderr).contains("'transverse_amp'"));
    let refused_message = "a plot across the sliding direction draws against --vhat, stiff, at one --phase";
    let base = ["plot", "--vhat", "0.1,0.2", "--amp", "0.5", "--transverse-amp", "1"];
    for extra in [vec!["--system-stiffness", "1"], vec!["--tangential-amp", "1", "--phase", "0,1"]] {
        refused(&[&base[..], &extra[..]].concat(), refused_message);
    }
    refused(&["plot", "--vbar", "0.1,0.2", "--amp", "0.5", "--transverse-amp", "1"], refused_message);
}

/// `validate --history --transverse-amp` of a history in the plane
/// (`history --transverse-amp`'s CSV, with its `transverse` column): the
/// exact history passes with both forces compared (the CSV's columns
/// `transverse_exact`, `transverse_yours`), its force across negated fails;
/// the file without `--transverse-amp` is refused naming the column (it was
/// compared as the line's history, the force across ignored), and
/// `--transverse-amp` without `--history` by name.
#[test]
fn validate_history_compares_a_history_in_the_plane() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("plane-history.csv");
    let args =
        ["history", "--vhat", "0.3", "--amp", "0.5", "--transverse-amp", "1.2", "--periods", "2", "--format", "csv"];
    let out = cli::run(&args, None);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    std::fs::write(&path, &text).unwrap();
    let file = path.to_str().unwrap();
    let base = ["validate", "--history", file, "--vhat", "0.3", "--amp", "0.5"];
    let v = ok(&cli::run(&[&base[..], &["--transverse-amp", "1.2", "--format", "json"]].concat(), None));
    assert!(v["findings"].as_array().unwrap().is_empty(), "{v}");
    assert!(v["transverse"]["max_abs_error"].as_f64().unwrap() < 1e-14, "{v}");
    let kinds: Vec<&str> = v["events"].as_array().unwrap().iter().map(|e| e["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["stick", "slip"]);
    let out = cli::run(&[&base[..], &["--transverse-amp", "1.2", "--format", "csv"]].concat(), None);
    let csv = String::from_utf8(out.stdout).unwrap();
    assert!(csv.lines().next().unwrap().ends_with(",transverse_exact,transverse_yours"), "{csv}");
    // The force across negated: the largest errors are named.
    let mut rows: Vec<String> = text.lines().map(String::from).collect();
    for row in rows.iter_mut().skip(2) {
        let mut cells: Vec<String> = row.split(',').map(String::from).collect();
        cells[3] = format!("{}", -cells[3].parse::<f64>().unwrap());
        *row = cells.join(",");
    }
    std::fs::write(&path, rows.join("\n")).unwrap();
    let out = cli::run(&[&base[..], &["--transverse-amp", "1.2", "--format", "json"]].concat(), None);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{v}");
    assert!(v["transverse"]["max_abs_error"].as_f64().unwrap() > 0.1, "{v}");
    refused(&base, "transverse");
    refused(&["validate", file, "--transverse-amp", "1"], "--transverse-amp");
}
