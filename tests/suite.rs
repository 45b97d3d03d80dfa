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
            // Exact (0) where no spring sticks.
            assert!((0.0..1e-13).contains(&bound) && (bound > 0.0 || v >= 1.0), "{line}");
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
    let dir = std::env::temp_dir().join(format!("fricosc-suite-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let d = dir.to_str().unwrap();
    assert_eq!(fricosc(&["suite", "--out", d]).status.code(), Some(0));
    let flat = dir.join("tables/flat.csv");
    let text = std::fs::read_to_string(&flat).unwrap().replacen("0.7145191049466343", "0.7145191049466344", 1);
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
    let _ = std::fs::remove_dir_all(&dir);
}
