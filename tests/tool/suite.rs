//! The reference suite in `data/suite`: current, reproducible by the commands
//! its manifest names, bounded by its error bounds against independent values,
//! and its check catches a changed or missing file.
use std::process::Command;

fn fricosc(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_fricosc")).args(args).current_dir(env!("CARGO_MANIFEST_DIR")).output().unwrap()
}

fn suite_dir() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/suite")
}

#[test]
fn the_committed_suite_is_current() {
    let out = fricosc(&["suite", "--check", "data/suite"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
}

/// Each table's values are what its manifest command prints (`fricosc table`),
/// and each history is byte for byte `fricosc history`'s CSV.
#[test]
fn the_manifest_commands_reproduce_the_files() {
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(suite_dir().join("manifest.json")).unwrap()).unwrap();
    let mut checked = 0;
    for f in manifest["files"].as_array().unwrap() {
        let (path, command) = (f["path"].as_str().unwrap(), f["command"].as_str().unwrap());
        let Some(args) = command.strip_prefix("fricosc ") else { continue };
        if args.contains('(') {
            continue; // one command per row or a part of point's output
        }
        let args: Vec<&str> = args.split_whitespace().collect();
        let printed = String::from_utf8(fricosc(&args).stdout).unwrap();
        let file = std::fs::read_to_string(suite_dir().join(path)).unwrap();
        if path.starts_with("tables/") && path.ends_with(".csv") {
            // The suite adds the error bound as a last column.
            let strip = |l: &str| l.rsplit_once(',').map(|x| x.0.to_string()).unwrap();
            let lines: Vec<String> = file.lines().map(strip).collect();
            assert_eq!(lines, printed.lines().collect::<Vec<_>>(), "{path}");
        } else if path.ends_with(".json") {
            // ... and as a last field of every JSON row.
            let strip = |l: &str| match l.split_once(",\"error_bound\":") {
                Some((head, tail)) => format!("{head}{}", &tail[tail.find('}').unwrap()..]),
                None => l.to_string(),
            };
            let lines: Vec<String> = file.lines().map(strip).collect();
            assert_eq!(lines, printed.lines().collect::<Vec<_>>(), "{path}");
        } else {
            assert_eq!(file, printed, "{path}");
        }
        checked += 1;
    }
    assert_eq!(checked, 10);
}

/// The suite's values against the 40-digit reference values where the grids
/// meet, each within its row's error bound.
#[test]
fn values_are_within_their_bounds_of_the_reference() {
    let reference: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/reference-values.json"))
            .unwrap(),
    )
    .unwrap();
    let mut met = 0;
    for shape in ["flat", "parabolic", "cone"] {
        let text = std::fs::read_to_string(suite_dir().join(format!("tables/{shape}.csv"))).unwrap();
        for line in text.lines().skip(1) {
            let f: Vec<&str> = line.split(',').collect();
            let (v, a, mu, bound): (f64, f64, f64, f64) =
                (f[1].parse().unwrap(), f[2].parse().unwrap(), f[3].parse().unwrap(), f[5].parse().unwrap());
            // Exact (bound 0) where no spring sticks, and at vbar -> 0+ of a jumping
            // contact (mu = 0: every spring sticks from contact to loss of contact).
            let exact_case = v >= 1.0 || (v == 0.0 && a >= 1.0 && mu == 0.0);
            assert!((0.0..1e-13).contains(&bound) && (bound > 0.0 || exact_case), "{line}");
            for c in reference["cases"].as_array().unwrap() {
                if c["shape"] == shape && c["vbar"].as_f64() == Some(v) && c["amp"].as_f64() == Some(a) {
                    let exact: f64 = c["mu_ratio"].as_str().unwrap().parse().unwrap();
                    // The 40-digit value rounded to f64 is within half an ulp of exact.
                    assert!((mu - exact).abs() <= bound + 1.2e-16, "{line}: exact {exact}");
                    met += 1;
                }
            }
        }
    }
    assert!(met >= 8, "only {met} reference points on the suite's grid");
}

/// A changed digit and a missing file are reported, with exit code 1; the
/// manifest's hashes are the files' SHA-256 (checked with sha256sum where present).
#[test]
fn the_check_catches_changes() {
    // Removed when dropped, also when the test fails.
    let scratch = tempfile::Builder::new().prefix("fricosc-suite-").tempdir().unwrap();
    let dir = scratch.path().join("suite");
    let d = dir.to_str().unwrap();
    assert_eq!(fricosc(&["suite", "--out", d]).status.code(), Some(0));
    let flat = dir.join("tables/flat.csv");
    // One value moved by an ulp (whatever the published digits are).
    let text = std::fs::read_to_string(&flat).unwrap();
    let row = text.lines().find(|l| l.starts_with("flat,0.2,0.5,")).unwrap();
    let mu = row.split(',').nth(3).unwrap();
    let moved = format!("{:?}", mu.parse::<f64>().unwrap().next_up());
    let text = text.replacen(&format!("flat,0.2,0.5,{mu},"), &format!("flat,0.2,0.5,{moved},"), 1);
    std::fs::write(&flat, text).unwrap();
    std::fs::remove_file(dir.join("limits.csv")).unwrap();
    let out = fricosc(&["suite", "--check", d]);
    let msg = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{msg}");
    assert!(msg.contains("tables/flat.csv differs") && msg.contains("limits.csv is missing"), "{msg}");
    if let Ok(sum) = Command::new("sha256sum").arg(suite_dir().join("tables/cone.csv")).output() {
        let manifest = std::fs::read_to_string(suite_dir().join("manifest.json")).unwrap();
        let hash = String::from_utf8_lossy(&sum.stdout).split_whitespace().next().unwrap_or("").to_string();
        assert!(hash.len() == 64 && manifest.contains(&hash), "{hash}");
    }
}

/// The suite's tabulated sphere against the true sphere (its MDR profile
/// `(x/2) ln((1 + x)/(1 - x))` at a mean indentation of 1e-6, 30 digits:
/// `data/scripts/mdr_reference.py --sphere` -> `data/sphere-reference.json`):
/// every sampled row lies within its `error_bound` (before, with the table's
/// `1 - sqrt(1 - r^2)` rounded near the axis, 6 of 12 did not).
#[test]
fn the_tabulated_sphere_rows_are_within_their_bounds_of_the_true_sphere() {
    let refs: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/data/sphere-reference.json")).unwrap(),
    )
    .unwrap();
    let table = std::fs::read_to_string(suite_dir().join("tables/tabulated-sphere.csv")).unwrap();
    let rows: Vec<Vec<String>> = table.lines().skip(1).map(|l| l.split(',').map(String::from).collect()).collect();
    let mut checked = 0;
    for c in refs["cases"].as_array().unwrap() {
        let (vbar, amp) = (c["vbar"].as_f64().unwrap(), c["amp"].as_f64().unwrap());
        let row = rows
            .iter()
            .find(|r| r[1].parse::<f64>().unwrap() == vbar && r[2].parse::<f64>().unwrap() == amp)
            .unwrap_or_else(|| panic!("the suite has no row at vbar {vbar}, amp {amp}"));
        let (mu, bound): (f64, f64) = (row[3].parse().unwrap(), row[5].parse().unwrap());
        let exact: f64 = c["mu_ratio"].as_str().unwrap().parse().unwrap();
        let err = (mu - exact).abs();
        assert!(err <= bound, "vbar {vbar} amp {amp}: |{mu} - {exact}| = {err:e} > bound {bound:e}");
        checked += 1;
    }
    assert!(checked >= 15);
}
