//! `validate` against stepped tables with planted bugs: each finding class is
//! provoked by the bug it is meant to name, and a correct table provokes none.
//! The stepper here is the seed's scheme written out for one spring (the flat
//! punch), with the start and the number of periods as parameters, so that the
//! bugs of a user's stepper can be planted in it.
use crate::common::run as cli;

use fricosc::history::HistoryOptions;
use fricosc::report::ContactRegime;
use fricosc::validation::{compare, AtRest, Check, FindingKind, HistoryData, HistoryValidation, TimeAxis};
use fricosc::Shape;
use std::process::Command;

/// `mu/mu0` of the flat punch by the seed's scheme: `m` steps per period,
/// `periods` periods, the last one averaged; `relaxed`: the spring starts at
/// `F = 0` (else at the bound, sliding).
fn stepper(vbar: f64, amp: f64, m: usize, periods: usize, relaxed: bool) -> f64 {
    let h = std::f64::consts::TAU / m as f64;
    let bound = |tau: f64| (1.0 / amp - tau.cos()).max(0.0);
    let mut f = if relaxed { 0.0 } else { bound(0.0) };
    let (mut sf, mut sn) = (0.0, 0.0);
    for k in 1..=periods * m {
        let b = bound(h * k as f64);
        f = if b > 0.0 { (f + vbar * h).min(b) } else { 0.0 };
        if k > (periods - 1) * m {
            sf += f;
            sn += b;
        }
    }
    sf / sn
}

const VBAR: [f64; 8] = [0.0, 0.05, 0.1, 0.3, 0.5, 0.8, 1.0, 1.1];
const AMP: [f64; 3] = [0.3, 0.8, 1.5];

fn table(mu: impl Fn(f64, f64) -> f64) -> Vec<(f64, f64, f64)> {
    AMP.iter().flat_map(|&a| VBAR.iter().map(move |&v| (v, a))).map(|(v, a)| (v, a, mu(v, a))).collect()
}

/// A history on the seed's phase axis against the exact one (tolerance 1e-9).
fn compare_history(shape: &Shape, v: f64, a: f64, t: &[f64], f: &[f64], n: Option<&[f64]>) -> HistoryValidation {
    let data = HistoryData { time: TimeAxis::Phase(t), tangential: f, normal: n, transverse: None, body: None };
    fricosc::validation::compare_history(shape, &fricosc::Conditions::vbar(v, a).unwrap(), &data, 1e-9).unwrap()
}

fn kinds(rows: &[(f64, f64, f64)], at_rest: AtRest) -> Vec<FindingKind> {
    compare(&Shape::flat(), rows, &Check::default().with_at_rest(at_rest))
        .unwrap()
        .findings
        .iter()
        .map(|f| f.kind)
        .collect()
}

/// The derivation of the two conventions at vbar = 0: a relaxed start stays at
/// exactly 0, a sliding start converges to mu_static = 1 - amp.
#[test]
fn the_two_starts_at_zero_velocity() {
    for amp in [0.3, 0.8, 1.5] {
        assert_eq!(stepper(0.0, amp, 1000, 5, true), 0.0);
        let sliding = stepper(0.0, amp, 100_000, 3, false);
        // mu_static = N_min / N_mean of the flat punch.
        let exact = (1.0f64 - amp).max(0.0);
        assert!((sliding - exact).abs() < 1e-4, "amp {amp}: {sliding} vs {exact}");
    }
}

/// A converged, correct stepper (sliding start, many periods): no finding, and
/// the errors are the scheme's own (first order with contact loss).
#[test]
fn a_correct_table_has_no_findings() {
    let rows = table(|v, a| stepper(v, a, 20_000, 60, false));
    let v = compare(&Shape::flat(), &rows, &Check::default().with_at_rest(AtRest::Sliding)).unwrap();
    assert!(v.findings.is_empty(), "{:?}", v.findings);
    assert!(v.max_abs_error < 2e-3, "{}", v.max_abs_error);
    // Every regime appears, each with its rows.
    let regimes: Vec<ContactRegime> = v.by_regime.iter().map(|g| g.regime).collect();
    assert_eq!(
        regimes,
        [
            ContactRegime::AtRest,
            ContactRegime::Sliding,
            ContactRegime::PermanentContact,
            ContactRegime::JumpingSlipFirst,
            ContactRegime::JumpingStickFirst
        ]
    );
    assert_eq!(v.by_amp.iter().map(|g| g.summary.n).sum::<usize>(), rows.len());
}

/// Normalising by the normal force at one instant (here its peak, 1 + amp,
/// instead of the mean 1): values above 1 and not 1 above vbar = 1.
#[test]
fn wrong_normalisation_is_named() {
    let rows = table(|v, a| stepper(v, a, 20_000, 60, false) * 1.218);
    let k = kinds(&rows, AtRest::Sliding);
    assert!(k.contains(&FindingKind::AboveOne) && k.contains(&FindingKind::NotOneAboveCritical), "{k:?}");
}

/// A relaxed start gives 0 at vbar = 0: named as the other convention, and no
/// finding (and no error there) with --at-rest relaxed.
#[test]
fn a_relaxed_start_is_named_and_accepted_with_its_convention() {
    let rows = table(|v, a| stepper(v, a, 20_000, 60, v == 0.0));
    let k = kinds(&rows, AtRest::Sliding);
    assert_eq!(k, [FindingKind::AtRestConvention], "{k:?}");
    let relaxed = compare(&Shape::flat(), &rows, &Check::default().with_at_rest(AtRest::Relaxed)).unwrap();
    assert!(relaxed.findings.is_empty(), "{:?}", relaxed.findings);
    assert!(relaxed.rows.iter().filter(|r| r.vbar == 0.0).all(|r| r.error == 0.0));
}

/// Too few periods from a relaxed start: far off at low velocity (the issue's
/// -0.53 at vbar = 0.1 after 3 periods), named as not in steady state.
#[test]
fn too_few_periods_are_named() {
    let rows = table(|v, a| if v == 0.0 { stepper(0.0, a, 20_000, 60, false) } else { stepper(v, a, 20_000, 3, true) });
    let v = compare(&Shape::flat(), &rows, &Check::default().with_at_rest(AtRest::Sliding)).unwrap();
    let steady = v.findings.iter().find(|f| f.kind == FindingKind::NotSteady).expect("not_steady finding");
    // The flagged rows are the low-velocity ones.
    assert!(steady.rows.iter().all(|&i| rows[i].0 > 0.0 && rows[i].0 < 0.3), "{steady:?}");
}

/// A table that loses friction at higher velocity (a convergence failure at a
/// few rows) is named as not monotone, at those rows.
#[test]
fn a_decrease_in_velocity_is_named() {
    let rows = table(|v, a| {
        let m = stepper(v, a, 20_000, 60, false);
        if v == 0.5 && a == 0.8 {
            m - 0.3
        } else {
            m
        }
    });
    let v = compare(&Shape::flat(), &rows, &Check::default().with_at_rest(AtRest::Sliding)).unwrap();
    let f = v.findings.iter().find(|f| f.kind == FindingKind::NotMonotone).expect("not_monotone finding");
    assert_eq!(f.rows, [VBAR.len() + 4], "{f:?}");
}

fn fricosc_cmd(args: &[&str], stdin: &str) -> std::process::Output {
    cli::run(args, Some(stdin))
}

/// The command line: the shape from the file (JSON field, CSV column), a
/// conflicting --shape refused, vhat and mu with --mu0 read, the three formats.
#[test]
fn the_command_reads_shapes_velocities_and_formats() {
    let exact = |v: f64, a: f64| crate::common::eval(&Shape::parabolic(), v, a).unwrap().ratio.mu_ratio;
    // JSON with its shape: compared with the paraboloid, not the flat punch.
    let json = format!(
        r#"{{"shape": "parabolic", "rows": [{{"vbar": 0.5, "amp": 0.5, "mu_ratio": {:?}}}]}}"#,
        exact(0.5, 0.5)
    );
    let out = fricosc_cmd(&["validate", "-", "--format", "json", "--max-error", "0"], &json);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["shape"], "parabolic");
    assert_eq!(doc["shape_source"], "file");
    let refused = fricosc_cmd(&["validate", "-", "--shape", "cone"], &json);
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("--shape says 'cone'"));
    // CSV with a shape column, vhat and mu (mu0 = 0.4).
    let (v, a) = (0.3, 1.5);
    let csv = format!("shape,vhat,amp,mu,code\nparabolic,{:?},{a:?},{:?},x\n", v * a, 0.4 * exact(v, a));
    let out = fricosc_cmd(&["validate", "-", "--mu0", "0.4", "--format", "json"], &csv);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(doc["max_abs_error"].as_f64().unwrap() < 1e-15, "{doc}");
    assert_eq!(doc["ignored_columns"], serde_json::json!(["code"]));
    // The paraboloid's springs all lose contact at amp 1.5: its regime says so.
    assert_eq!(doc["rows"][0]["regime"], "jumping");
    assert_eq!(doc["rows"][0]["jumping_share"], 1.0);
    let no_mu0 = fricosc_cmd(&["validate", "-"], &csv);
    assert!(String::from_utf8_lossy(&no_mu0.stderr).contains("mu0 is needed"));
    // CSV output: one line per row plus the header, the velocity as the file
    // gives it (vhat); the summary names findings.
    let csv_out = fricosc_cmd(&["validate", "-", "--mu0", "0.4", "--format", "csv"], &csv);
    let text = String::from_utf8(csv_out.stdout).unwrap();
    assert_eq!(text.lines().count(), 2);
    assert!(text.starts_with("row,vhat,amp,mu_ratio,exact,error,relative_error,regime,jumping_share\n"), "{text}");
    assert!(text.lines().nth(1).unwrap().starts_with(&format!("0,{:?},", v * a)), "{text}");
    let bad = "vbar,amp,mu_ratio\n0.5,0.5,1.2\n1.1,0.5,1.2\n";
    let summary = fricosc_cmd(&["validate", "-", "--format", "summary"], bad);
    let text = String::from_utf8(summary.stdout).unwrap();
    assert!(text.contains("above_one: 2 rows (0, 1)") && text.contains("check the normalisation"), "{text}");
    assert!(text.lines().all(|l| l.chars().count() <= 100), "{text}");
}

/// README's walk-through: the example stepper with its three planted bugs is
/// named by four findings; with `--fixed` by none. Needs python3 (a failure
/// without it: the walk-through is README's promise).
#[test]
fn the_readme_walk_through_names_every_planted_bug() {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/src/python/examples/buggy_stepper.py");
    let run = |args: &[&str]| Command::new("python3").arg(script).args(args).output();
    let buggy = run(&[]).expect("python3 is needed to run README's walk-through (apt install python3)");
    assert!(buggy.status.success(), "{}", String::from_utf8_lossy(&buggy.stderr));
    let out = fricosc_cmd(&["validate", "-", "--format", "json"], std::str::from_utf8(&buggy.stdout).unwrap());
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let kinds: Vec<&str> = doc["findings"].as_array().unwrap().iter().map(|f| f["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["above_one", "not_one_above_critical", "not_steady", "at_rest_convention"]);
    let fixed = run(&["--fixed"]).unwrap();
    let out = fricosc_cmd(&["validate", "-", "--format", "json"], std::str::from_utf8(&fixed.stdout).unwrap());
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["findings"], serde_json::json!([]), "{doc}");
    assert!(doc["max_abs_error"].as_f64().unwrap() < 1e-3);
}

/// The convergence study on the built-in peer (the seed's scheme) at 1000 to
/// 64000 steps per period: second order without contact loss, first order
/// where the stick starts at contact (the onset falls between steps), with the
/// files' resolutions read from their names or after '@', and the plot drawn.
#[test]
fn the_series_finds_the_orders_of_the_seeds_scheme() {
    use fricosc::stepper::Stepping;

    // Removed when dropped, also when the test fails.

    let scratch = tempfile::Builder::new().prefix("fricosc-series-").tempdir().unwrap();

    let dir = scratch.path().to_path_buf();
    let mut args: Vec<String> = vec!["validate".into(), "--series".into(), "--format".into(), "json".into()];
    for k in 0..7 {
        let m = 1000usize << k;
        let mut text = String::from("vbar,amp,mu_ratio\n");
        for a in [0.5, 0.9, 1.5, 2.0] {
            for v in [0.2, 0.4, 0.6, 0.8] {
                let st = Stepping { steps_per_period: m, springs: 1 };
                let mu = crate::common::at::stepped(&Shape::flat(), v, a, st).unwrap().ratio.mu_ratio;
                text += &format!("{v:?},{a:?},{mu:?}\n");
            }
        }
        // Both ways of naming the resolution.
        let (file, arg) = if k % 2 == 0 {
            (dir.join(format!("run@{m}.csv")), dir.join(format!("run@{m}.csv")).display().to_string())
        } else {
            let f = dir.join(format!("run-{k}.csv"));
            (f.clone(), format!("{}@{m}", f.display()))
        };
        std::fs::write(&file, text).unwrap();
        args.push(arg);
    }
    let plot = dir.join("series.svg");
    args.extend(["--target".into(), "1e-6".into(), "--plot".into(), plot.display().to_string()]);
    let out = Command::new(env!("CARGO_BIN_EXE_fricosc")).args(&args).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let median = |regime: &str| {
        doc["by_regime"].as_array().unwrap().iter().find(|g| g["regime"] == regime).unwrap()["median_order"]
            .as_f64()
            .unwrap()
    };
    // Observed 1.94 and 1.00.
    assert!((1.7..2.3).contains(&median("permanent_contact")), "{doc}");
    assert!((0.8..1.2).contains(&median("jumping_stick_first")), "{doc}");
    assert_eq!(doc["resolutions"].as_array().unwrap().len(), 7);
    assert!(doc["rows"].as_array().unwrap().iter().all(|r| r["needed_resolution"].as_f64().is_some_and(|m| m > 0.0)));
    assert!(std::fs::read_to_string(&plot).unwrap().starts_with("<svg"));
    // A file without its resolution is refused.
    let bad = Command::new(env!("CARGO_BIN_EXE_fricosc"))
        .args([
            "validate",
            "--series",
            dir.join("run-1.csv").to_str().unwrap(),
            dir.join("run-3.csv").to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("needs its resolution"));
}

/// `history --method stepping` (the peer) against the exact history: every
/// event of the period found, each within one step of the exact phase (the
/// scheme is first order in the event times), periodic after the first period.
#[test]
fn history_events_of_the_peer_are_within_one_step() {
    for (v, a) in [(0.3, 1.5), (0.3, 0.5), (0.9, 1.5)] {
        for m in [250usize, 1000, 4000, 16000] {
            let h = fricosc::history::stepped_history(&fricosc::Conditions::vbar(v, a).unwrap(), 3, m).unwrap();
            let (t, f, n): (Vec<f64>, Vec<f64>, Vec<f64>) = (
                h.samples.iter().map(|s| s.tau).collect(),
                h.samples.iter().map(|s| s.tangential).collect(),
                h.samples.iter().map(|s| s.normal).collect(),
            );
            let r = compare_history(&Shape::flat(), v, a, &t, &f, Some(&n));
            let step = std::f64::consts::TAU / m as f64;
            let kinds: Vec<_> = r.exact_events.iter().map(|e| e.kind).collect();
            for k in &kinds {
                assert!(r.events.iter().any(|e| e.kind == *k), "v={v} a={a} M={m}: {k:?} not found: {:?}", r.events);
            }
            for e in &r.events {
                let err = e.timing_error.unwrap().abs();
                assert!(err <= step, "v={v} a={a} M={m}: {e:?} (step {step})");
            }
            assert_eq!(r.periodic, Some(true), "v={v} a={a} M={m}");
            assert!(r.max_abs_error < 0.2 * step * (1.0 + a), "v={v} a={a} M={m}: {}", r.max_abs_error);
        }
    }
}

/// Planted in a history: a relaxed start run for two periods at low velocity
/// (not periodic, with the periods still needed), and a velocity off by 30 %
/// (the slip starts far from its exact phase: many steps).
#[test]
fn history_bugs_are_named() {
    let (v, a, m) = (0.05, 0.5, 2000usize);
    let step = std::f64::consts::TAU / m as f64;
    let run = |periods: usize, vscale: f64, relaxed: bool| {
        let s = 1.0 / a;
        let mut f = if relaxed { 0.0 } else { s - 1.0 };
        let (mut t, mut ft, mut nn) = (vec![], vec![], vec![]);
        for k in 0..=periods * m {
            let tau = step * k as f64;
            let b = (s - tau.cos()).max(0.0);
            if k > 0 {
                // The user's own update: grow by the drive, capped by the bound.
                f = if b > 0.0 { (f + vscale * v * step).min(b) } else { 0.0 };
            }
            t.push(tau);
            ft.push(f * a);
            nn.push(b * a);
        }
        compare_history(&Shape::flat(), v, a, &t, &ft, Some(&nn))
    };
    let short = run(3, 1.0, true);
    assert_eq!(short.periodic, Some(false), "{short:?}");
    assert!(short.period_drift.unwrap() > 1e-3);
    let long = run(60, 1.0, true);
    assert_eq!(long.periodic, Some(true), "{:?}", long.period_drift);
    let fast = run(60, 1.3, false);
    let slip = fast.events.iter().find(|e| e.kind == fricosc::spring::EventKind::Slip).unwrap();
    assert!(slip.timing_error.unwrap().abs() > 10.0 * step, "{slip:?}");
}

/// The command line: a time column with --omega, or with the period found from
/// the normal force; the summary names the events.
#[test]
fn validate_history_reads_time_columns() {
    let h = fricosc::history::stepped_history(&fricosc::Conditions::vbar(0.3, 1.5).unwrap(), 3, 1000).unwrap();
    let omega = 2.0 * std::f64::consts::PI * 50.0; // 50 Hz
    let mut text = String::from("t,normal,tangential\n");
    for s in &h.samples {
        text += &format!("{:?},{:?},{:?}\n", s.tau / omega, s.normal, s.tangential);
    }
    for extra in [vec!["--omega", "314.1592653589793"], vec![]] {
        let mut args = vec!["validate", "--history", "-", "--vbar", "0.3", "--amp", "1.5", "--format", "json"];
        args.extend(extra.iter());
        let out = fricosc_cmd(&args, &text);
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(doc["events"].as_array().unwrap().len(), 4, "{doc}");
        assert!(doc["max_abs_error"].as_f64().unwrap() < 1e-3, "{doc}");
    }
    let out =
        fricosc_cmd(&["validate", "--history", "-", "--vbar", "0.3", "--amp", "1.5", "--format", "summary"], &text);
    let s = String::from_utf8(out.stdout).unwrap();
    assert!(s.contains("loss_of_contact") && s.contains("Periodic"), "{s}");
}

/// An event-driven code with the printed sign of eq. 8 finds no end of the
/// stick (the seed's misprint: no root after the stick starts) and lets the
/// force grow past the Coulomb bound: named, with the phases where it happens.
#[test]
fn a_missed_stick_end_is_named() {
    let (v, a, m) = (0.3, 0.5, 2000usize);
    let step = std::f64::consts::TAU / m as f64;
    let s = 1.0 / a;
    let (mut t, mut ft, mut nn) = (vec![], vec![], vec![]);
    let mut f = s - 1.0;
    let mut sticking = false;
    for k in 0..=3 * m {
        let tau = step * k as f64;
        let b = (s - tau.cos()).max(0.0);
        if k > 0 {
            // Once stuck, never slips again within the period (no stick end found).
            let next = f + v * step;
            sticking = sticking || next < b;
            f = if sticking && (tau % std::f64::consts::TAU) > 0.1 { next } else { next.min(b) };
        }
        t.push(tau);
        ft.push(f * a);
        nn.push(b * a);
    }
    let r = compare_history(&Shape::flat(), v, a, &t, &ft, Some(&nn));
    assert!(r.above_bound_count > 100 && !r.above_bound.is_empty(), "{}", r.above_bound_count);
    // The exact history never is above its bound.
    let exact = fricosc::history::history(
        &Shape::flat(),
        &fricosc::Conditions::vbar(v, a).unwrap(),
        &HistoryOptions::default().with_periods(2).with_samples(500),
    )
    .unwrap();
    let (t, f, n): (Vec<f64>, Vec<f64>, Vec<f64>) = (
        exact.samples.iter().map(|s| s.tau).collect(),
        exact.samples.iter().map(|s| s.tangential).collect(),
        exact.samples.iter().map(|s| s.normal).collect(),
    );
    let r = compare_history(&Shape::flat(), v, a, &t, &f, Some(&n));
    assert_eq!(r.above_bound_count, 0);
    assert!(r.max_abs_error < 1e-15, "{}", r.max_abs_error);
}

/// Forces in newtons: --static-force (and its alias --kz-u0) and --mu0 normalise them.
#[test]
fn history_forces_in_physical_units() {
    let h = fricosc::history::stepped_history(&fricosc::Conditions::vbar(0.3, 0.5).unwrap(), 2, 800).unwrap();
    let (kz_u0, mu0) = (250.0, 0.4);
    let mut text = String::from("tau,normal,tangential\n");
    let mut plain = String::from("tau,normal,tangential\n");
    for s in &h.samples {
        text += &format!("{:?},{:?},{:?}\n", s.tau, s.normal * kz_u0, s.tangential * mu0 * kz_u0);
        plain += &format!("{:?},{:?},{:?}\n", s.tau, s.normal, s.tangential);
    }
    let run = |args: &[&str], input: &str| -> serde_json::Value {
        let out = fricosc_cmd(args, input);
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_slice(&out.stdout).unwrap()
    };
    let base = ["validate", "--history", "-", "--vbar", "0.3", "--amp", "0.5", "--format", "json"];
    let scaled = run(&[&base[..], &["--kz-u0", "250", "--mu0", "0.4"]].concat(), &text);
    let direct = run(&base, &plain);
    let (x, y) = (scaled["max_abs_error"].as_f64().unwrap(), direct["max_abs_error"].as_f64().unwrap());
    assert!((x - y).abs() <= 1e-15 * y.max(1e-300) + 1e-16, "{x} vs {y}");
    assert_eq!(scaled["events"].as_array().unwrap().len(), direct["events"].as_array().unwrap().len());
}

/// A curved contact's history: the exact normal force and the tangential force
/// of the reference grid; the history fricosc writes with as many springs
/// agrees to rounding, a coarse one to its grid's error (second order).
#[test]
fn curved_histories_are_compared_with_the_reference_grid() {
    let shape = Shape::parabolic();
    let cols = |springs: usize| {
        let h = fricosc::history::history(
            &shape,
            &fricosc::Conditions::vbar(0.3, 1.3).unwrap(),
            &HistoryOptions::default().with_periods(2).with_samples(300).with_springs(springs),
        )
        .unwrap();
        let t: Vec<f64> = h.samples.iter().map(|s| s.tau).collect();
        let f: Vec<f64> = h.samples.iter().map(|s| s.tangential).collect();
        let n: Vec<f64> = h.samples.iter().map(|s| s.normal).collect();
        compare_history(&shape, 0.3, 1.3, &t, &f, Some(&n))
    };
    // The reference grid of `compare_history` has 20,000 springs.
    let same = cols(20_000);
    assert!(same.max_abs_error < 1e-13, "{}", same.max_abs_error);
    assert!(same.events.is_empty() && same.exact_events.is_empty() && same.above_bound_count == 0);
    let (e100, e400) = (cols(100).max_abs_error, cols(400).max_abs_error);
    assert!(e100 > 0.0 && e400 < e100 / 6.0, "{e100:e} -> {e400:e}");
}

/// A series of histories from the peer (250 to 16000 steps per period) at a
/// jumping point: the largest error and the slip's timing error converge at
/// first order (observed 0.95 and 0.96; the onset of contact falls between steps).
#[test]
fn history_series_finds_first_order_in_the_jumping_regime() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-hseries-").tempdir().unwrap();
    let dir = scratch.path().to_path_buf();
    let mut args: Vec<String> =
        ["validate", "--series", "--history", "--vbar", "0.3", "--amp", "1.5", "--format", "json"]
            .map(String::from)
            .to_vec();
    for m in [250usize, 500, 1000, 2000, 4000, 8000, 16000] {
        let h = fricosc::history::stepped_history(&fricosc::Conditions::vbar(0.3, 1.5).unwrap(), 2, m).unwrap();
        let text: String = std::iter::once("tau,tangential\n".to_string())
            .chain(h.samples.iter().map(|s| format!("{:?},{:?}\n", s.tau, s.tangential)))
            .collect();
        let f = dir.join(format!("h@{m}.csv"));
        std::fs::write(&f, text).unwrap();
        args.push(f.display().to_string());
    }
    let out = Command::new(env!("CARGO_BIN_EXE_fricosc")).args(&args).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let order = doc["order"].as_f64().unwrap();
    assert!((0.6..1.4).contains(&order), "{doc}");
    let slip = doc["events"].as_array().unwrap().iter().find(|e| e["kind"] == "slip").unwrap();
    assert!((0.6..1.4).contains(&slip["order"].as_f64().unwrap()), "{slip}");
}

/// A planted convention: its name, how it reads a row, the name it should get.
type Planted = (&'static str, fn([f64; 4]) -> [f64; 4], Option<&'static str>);

/// A combined table computed with a convention other than fricosc's: the
/// rows' exact values at the convention's inputs, labelled with fricosc's.
/// Each convention is named (a table with -phase passed with a largest error
/// of 1.39, no finding, exit 0); a table off by a model bug gets
/// `large_errors`; the correct table gets nothing.
#[test]
fn conventions_of_a_combined_table_are_named() {
    use fricosc::validation::{compare_oscillation, OscillationInput};
    let shape = Shape::parabolic();
    let exact = |v: f64, a: f64, t: f64, p: f64| {
        let c = fricosc::Conditions::vhat(v, a).unwrap().with_tangential(t, p).unwrap();
        shape.ratio(&c).unwrap().mu_ratio
    };
    let inputs: Vec<[f64; 4]> =
        [0.5, 1.5].iter().flat_map(|&a| [0.5, 1.2, 2.5, 4.0].map(|p| [0.3, a, 2.0, p])).collect();
    let planted: [Planted; 6] = [
        ("correct", |x| x, None),
        ("-phase", |[v, a, t, p]| [v, a, t, -p], Some("the phase's sign reversed")),
        ("from the maximum", |[v, a, t, p]| [v, a, t, p + std::f64::consts::PI], Some("normal force's maximum")),
        ("peak to peak", |[v, a, t, p]| [v, a, 0.5 * t, p], Some("peak to peak")),
        ("no tangential oscillation", |[v, a, _, p]| [v, a, 0.0, p], None),
        ("half the velocity", |[v, a, t, p]| [0.5 * v, a, t, p], None),
    ];
    for (what, read, named) in planted {
        let rows: Vec<OscillationInput> = inputs
            .iter()
            .map(|&x| {
                let [v, a, t, p] = read(x);
                OscillationInput::new(x[0], x[1], exact(v, a, t, p)).with_tangential(x[2], x[3])
            })
            .collect();
        let r = compare_oscillation(&shape, &rows, &Check::default()).unwrap();
        let kinds: Vec<FindingKind> = r.findings.iter().map(|f| f.kind).collect();
        match (what, named) {
            ("correct", _) => assert!(kinds.is_empty(), "{what}: {kinds:?}"),
            (_, Some(name)) => {
                assert_eq!(kinds, [FindingKind::Convention], "{what}");
                assert!(r.findings[0].hint.contains(name), "{what}: {}", r.findings[0].hint);
            }
            (_, None) => assert!(kinds == [FindingKind::LargeErrors], "{what}: {kinds:?}, {}", r.summary.max_abs_error),
        }
    }
    // Degrees: phases written as 30, 90, 150.
    let rows: Vec<OscillationInput> = [30.0f64, 90.0, 150.0]
        .iter()
        .map(|&d| OscillationInput::new(0.3, 1.5, exact(0.3, 1.5, 2.0, d.to_radians())).with_tangential(2.0, d))
        .collect();
    let r = compare_oscillation(&shape, &rows, &Check::default()).unwrap();
    assert!(
        r.findings.iter().any(|f| f.kind == FindingKind::Convention && f.hint.contains("degrees")),
        "{:?}",
        r.findings
    );
}

/// A table of the seed's problem whose values are off by O(1) inside [0, 1]
/// (no other finding fires: 0.6 mu at every row below vbar 1) is not passed
/// silently.
#[test]
fn errors_of_order_one_always_get_a_finding() {
    let rows: Vec<(f64, f64, f64)> = [0.1, 0.3, 0.5, 0.8]
        .iter()
        .map(|&v| {
            (v, 0.5, 0.6 * fricosc::Shape::flat().ratio(&fricosc::Conditions::vbar(v, 0.5).unwrap()).unwrap().mu_ratio)
        })
        .collect();
    assert_eq!(kinds(&rows, AtRest::Sliding), [FindingKind::LargeErrors]);
}

/// A converged run at `amp = 1.2` whose errors are a first-order scheme's:
/// 6e-5 at the stick-first rows of low `vbar`, 1e-7 elsewhere, whatever the
/// number of periods (every spring loses contact and enters it relaxed:
/// steady from the first period). Not `not_steady` (it was, exit 1); at `amp
/// = 0.5`, where the spring never lets go, the same pattern still is.
#[test]
fn a_converged_run_where_contact_is_lost_is_not_called_unsteady() {
    let rows = |amp: f64| -> Vec<(f64, f64, f64)> {
        VBAR.iter()
            .map(|&v| {
                let exact = Shape::flat().ratio(&fricosc::Conditions::vbar(v, amp).unwrap()).unwrap().mu_ratio;
                (v, amp, exact + if v > 0.0 && v < 0.3 { 6e-5 } else { 1e-7 })
            })
            .collect()
    };
    assert!(!kinds(&rows(1.2), AtRest::Sliding).contains(&FindingKind::NotSteady));
    assert!(kinds(&rows(0.5), AtRest::Sliding).contains(&FindingKind::NotSteady));
}

/// A series whose row is exact but for rounding (errors 2.5e-15, 0, 9.7e-15,
/// 2.2e-16, 3.8e-14, 9.4e-16 at resolutions 100 to 3200) is `exact`, needs no
/// more resolution and gets no finding (it was `not_converging`,
/// `unreachable`, exit 1); a converging row beside it keeps its order.
#[test]
fn rounding_level_errors_in_a_series_are_exact() {
    use fricosc::validation::{convergence, Needed, RowStatus};
    let res = [100.0, 200.0, 400.0, 800.0, 1600.0, 3200.0];
    let noise = [2.5e-15, 0.0, 9.7e-15, 2.2e-16, 3.8e-14, 9.4e-16];
    let exact = |v: f64| Shape::flat().ratio(&fricosc::Conditions::vbar(v, 0.5).unwrap()).unwrap().mu_ratio;
    let tables: Vec<Vec<(f64, f64, f64)>> = res
        .iter()
        .zip(noise)
        .map(|(&m, e)| vec![(0.3, 0.5, exact(0.3) + e), (0.6, 0.5, exact(0.6) + 1.0 / m)])
        .collect();
    let c = convergence(&Shape::flat(), &res, &tables, &Check::default(), Some(1e-6)).unwrap();
    assert_eq!(c.rows[0].status, RowStatus::Exact, "{:?}", c.rows[0]);
    assert_eq!(c.rows[0].needed_resolution, Some(Needed::Resolution(100.0)));
    assert_eq!(c.rows[1].status, RowStatus::Converging);
    assert!((c.rows[1].order.unwrap() - 1.0).abs() < 1e-6);
    assert!(c.findings.is_empty(), "{:?}", c.findings);
}

/// A history at `amp = 1.5` (the contact opens each period) whose stepper
/// never lets the contact open (the normal force down to -0.5 of F0, the
/// force kept) gets `negative_normal`, not `normal_scale`; one whose spring
/// keeps its tangential force out of contact gets `force_out_of_contact`, not
/// `above_bound`; the correct one neither.
#[test]
fn contact_loss_bugs_in_a_history_are_named() {
    let (v, a, m) = (0.3, 1.5, 2000usize);
    let step = std::f64::consts::TAU / m as f64;
    let s = 1.0 / a;
    let run = |clip: bool, relax: bool| {
        let mut f: f64 = 0.0;
        let (mut t, mut ft, mut nn) = (vec![], vec![], vec![]);
        for k in 0..=20 * m {
            let tau = step * k as f64;
            let raw = s - tau.cos();
            let b = if clip { raw.max(0.0) } else { raw };
            if k > 0 {
                f = if b > 0.0 {
                    (f + v * step).min(b)
                } else if relax {
                    0.0
                } else {
                    f
                };
            }
            t.push(tau);
            ft.push(f * a);
            nn.push(b * a);
        }
        let h = compare_history(&Shape::flat(), v, a, &t, &ft, Some(&nn));
        h.findings.iter().map(|f| f.kind).collect::<Vec<_>>()
    };
    assert!(run(true, true).is_empty(), "{:?}", run(true, true));
    let no_loss = run(false, false);
    assert!(no_loss.contains(&FindingKind::NegativeNormal), "{no_loss:?}");
    assert!(!no_loss.contains(&FindingKind::NormalScale), "{no_loss:?}");
    let kept = run(true, false);
    assert!(kept.contains(&FindingKind::ForceOutOfContact), "{kept:?}");
    assert!(!kept.contains(&FindingKind::AboveBound), "{kept:?}");
}
