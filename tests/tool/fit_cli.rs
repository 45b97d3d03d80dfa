//! `fricosc fit`: the library's fit bit for bit from a file, fixed
//! parameters, and bad input named (one line, exit 2, nothing on stdout).
use crate::common::run::run as fricosc;

const SYNTHETIC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/fit-synthetic-flat.csv");

fn json(args: &[&str], stdin: Option<&str>) -> serde_json::Value {
    let out = fricosc(args, stdin);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The exact synthetic rows (`data/scripts/fit_synthetic.py`) give `mu0 =
/// 0.35`, `kx/kz = 0.8`, `u0 = 1e-6` back to 1e-7, as the library does; a
/// fixed parameter is reported fixed, with standard error 0.
#[test]
fn fit_gives_the_parameters_back() {
    let v = json(&["fit", SYNTHETIC, "--format", "json"], None);
    for (name, want) in [("mu0", 0.35), ("stiffness_ratio", 0.8), ("u0", 1e-6)] {
        let got = v["parameters"][name]["value"].as_f64().unwrap();
        assert!((got / want - 1.0).abs() < 1e-7, "{name}: {got}");
    }
    assert_eq!(v["rows"].as_array().unwrap().len(), 27);
    assert_eq!(v["dof"], 24);
    let v = json(&["fit", SYNTHETIC, "--format", "json", "--u0", "1e-6"], None);
    assert_eq!(
        v["parameters"]["u0"],
        serde_json::json!({"value": 1e-6, "stderr": 0.0, "fixed": true, "profile": null, "bounds": [0.0, null]})
    );
    let out = fricosc(&["fit", SYNTHETIC, "--format", "summary"], None);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("27 rows fitted with the flat model") && text.contains("kx/kz"), "{text}");
}

/// `--plot`: the data with their error bars, the fitted curves and the
/// residuals, one series each per amplitude (five per amplitude: the curve,
/// the points and their bars above, the residuals and their bars below), as
/// SVG or PNG; a plot of another kind is refused before the fit.
#[test]
fn fit_plot_draws_data_curves_and_residuals() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("fit.svg");
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/data/fit-example.csv");
    let out = fricosc(&["fit", example, "--format", "json", "--plot", svg.to_str().unwrap()], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(fricosc_cli::chart::parse_size(&text).is_ok());
    assert_eq!(text.matches("<g data-series=").count(), 15);
    assert!(text.contains("residual"));
    let out = fricosc(&["fit", example, "--plot", "fit.pdf"], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("must end in .svg or .png"));
}

/// Bad input: a missing column, both frequency and omega, a negative
/// velocity, fewer rows than parameters, a bad fixed value.
#[test]
fn bad_measurements_are_named() {
    let cases: [(&[&str], &str, &str); 6] = [
        (&["fit", "-"], "v0,du,mu\n1,1,0.3\n", "'frequency'"),
        (&["fit", "-"], "v0,frequency,mu\n1,100,0.3\n", "'du'"),
        (&["fit", "-"], "v0,du,frequency,omega,mu\n1,1e-6,100,628,0.3\n", "not both"),
        (&["fit", "-"], "v0,du,frequency,mu\n-1,1e-6,100,0.3\n1,1e-6,100,0.3\n2,1e-6,100,0.3\n3,1e-6,100,0.3\n", "v0"),
        (&["fit", "-"], "v0,du,frequency,mu\n1,1e-6,100,0.3\n2,1e-6,100,0.3\n", "rows"),
        (&["fit", "-", "--mu0", "-1"], "v0,du,frequency,mu\n1,1e-6,100,0.3\n", "mu0"),
    ];
    for (args, input, says) in cases {
        let out = fricosc(args, Some(input));
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{input}: {err}");
        assert!(out.stdout.is_empty() && err.lines().count() == 1 && err.contains(says), "{input}: {err}");
    }
}

/// What a referee looks at first: the summary rounds each value to its
/// error's second digit; a wrongly held `mu0` is a verdict (exit 1) naming
/// it; all three held is a model with its chi-square (it panicked); a
/// misspelled column is refused by name (it ran unweighted); a legend in kHz
/// from 1 kHz on, the error bars drawn over the markers.
#[test]
fn fit_reports_what_a_referee_reads() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/data/fit-example.csv");
    let out = fricosc(&["fit", example, "--format", "summary"], None);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(text.contains("mu0              0.3523 +- 0.0014") && text.contains("(9.72 +- 0.14)e-7"), "{text}");
    assert!(text.contains(", p 0.30 (weighted by sigma)"), "{text}");
    let out = fricosc(&["fit", example, "--format", "summary", "--mu0", "0.3"], None);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("verdict: the model does not fit") && text.contains("likely: the held mu0 = 0.3"), "{text}");
    let held = ["fit", example, "--format", "json", "--mu0", "0.35", "--stiffness-ratio", "0.8", "--u0", "1e-6"];
    let v = json(&held, None);
    assert_eq!((v["dof"].as_u64(), v["iterations"].as_u64(), &v["converged"]), (Some(27), Some(0), &true.into()));
    let csv = std::fs::read_to_string(example).unwrap();
    let out = fricosc(&["fit", "-"], Some(&csv.replacen("sigma", "Sigma", 1)));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(out.status.code() == Some(2) && out.stdout.is_empty(), "{err}");
    assert!(err.contains("unknown column 'Sigma' (did you mean 'sigma'?)"), "{err}");
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("khz.svg");
    let khz = csv.replace(",200,", ",20000,");
    let out = fricosc(&["fit", "-", "--plot", svg.to_str().unwrap(), "--format", "json"], Some(&khz));
    assert!(out.status.code().is_some_and(|c| c <= 1), "{}", String::from_utf8_lossy(&out.stderr));
    let drawn = std::fs::read_to_string(&svg).unwrap();
    assert!(drawn.contains("f = 20 kHz") && !drawn.contains("20000 Hz"), "legend");
    let (marker, bars) = (drawn.find("measured").unwrap(), drawn.find(", sigma").unwrap());
    assert!(marker < bars, "the bars are drawn after (over) the markers");
}

/// `--system-stiffness` (`--frequency-ratio`, `--damping`): the rig's system
/// held, the library's fit on it bit for bit; a frequency ratio with rows at
/// several frequencies is refused by name (Omega holds at one frequency).
#[test]
fn fit_on_the_rigs_system() {
    let args = ["fit", SYNTHETIC, "--format", "json", "--system-stiffness", "1", "--frequency-ratio", "0.5"];
    let out = fricosc(&[&args[..], &["--damping", "0.3"]].concat(), None);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let sys = fricosc::system::System::new(1.0, 0.5, 0.3).unwrap();
    let text = std::fs::read_to_string(SYNTHETIC).unwrap();
    let rows: Vec<fricosc::fit::Measurement> = text
        .lines()
        .skip(1)
        .map(|l| {
            let f: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            let omega = 2.0 * std::f64::consts::PI * f[2];
            fricosc::fit::Measurement {
                v0: f[0],
                du: f[1],
                omega,
                mu: f[3],
                sigma: None,
                system: Some(sys),
                load: None,
            }
        })
        .collect();
    let r = fricosc::fit::fit(&fricosc::Shape::flat(), &rows, &fricosc::fit::Fixed::default()).unwrap();
    assert_eq!(v["parameters"]["mu0"]["value"].as_f64(), Some(r.parameters[0].value), "{v}");
    assert_eq!(v["chi2"].as_f64(), Some(r.chi2));
    // The rig's stiffness is a parameter, held at the rig's value (or fitted:
    // `--fit-system-stiffness`, which needs the rig's system to start from).
    assert_eq!(v["order"], serde_json::json!(["mu0", "stiffness_ratio", "u0", "system_stiffness"]), "{v}");
    assert_eq!(v["parameters"]["system_stiffness"]["fixed"], serde_json::json!(true), "{v}");
    assert_eq!(v["covariance"].as_array().map(Vec::len), Some(4), "{v}");
    let out = fricosc(&["fit", SYNTHETIC, "--fit-system-stiffness"], None);
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(out.status.code() == Some(2) && out.stdout.is_empty() && err.contains("--system-stiffness"), "{err}");
    let mixed = text.replacen(",200,", ",300,", 1);
    let out = fricosc(&["fit", "-", "--system-stiffness", "1", "--frequency-ratio", "0.5"], Some(&mixed));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(out.status.code() == Some(2) && err.contains("invalid frequency-ratio = 0.5"), "{err}");
}

/// An outlier is named by its line in the file as an editor counts it
/// (comments, blank lines and the header counted): `data/fit-example.csv`'s
/// row 5 moved by 0.03 (7.5 sigma), behind a comment and a blank line and
/// with a blank line among the rows, is line 10.
#[test]
fn an_outlier_is_named_by_its_line() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/data/fit-example.csv")).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let mut cells: Vec<String> = lines[6].split(',').map(String::from).collect();
    cells[3] = format!("{}", cells[3].parse::<f64>().unwrap() + 0.03);
    lines[6] = cells.join(",");
    lines.insert(4, String::new());
    let file = format!("# a comment\n\n{}\n", lines.join("\n"));
    let out = fricosc(&["fit", "-", "--format", "summary"], Some(&file));
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("outliers beyond 3.56 standard uncertainties: row 5 (line 10)\n"), "{text}");
}

/// `--bound NAME=LO:HI`: a bound that excludes the truth leaves the
/// parameter on it, said in the summary and a verdict (exit 1), its bounds
/// in the JSON; a malformed, doubled or unknown bound, or one on a held
/// parameter, is refused (exit 2, one line, nothing on stdout).
#[test]
fn bounds_are_kept_and_named() {
    let out = fricosc(&["fit", SYNTHETIC, "--format", "summary", "--bound", "mu0=0.1:0.3"], None);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("0.3 (on its bound)") && text.contains("verdict: mu0 rests on its bound"), "{text}");
    let out = fricosc(&["fit", SYNTHETIC, "--format", "json", "--bound", "stiffness-ratio=0.5:inf"], None);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["parameters"]["stiffness_ratio"]["bounds"], serde_json::json!([0.5, null]));
    for (bound, says) in [
        ("mu0=0.3", "is not NAME=LO:HI"),
        ("mu=0.1:0.3", "is not NAME=LO:HI"),
        ("mu0=0.3:0.1", "above the lower bound"),
        ("u0=a:1", "is not NAME=LO:HI"),
    ] {
        let out = fricosc(&["fit", SYNTHETIC, "--bound", bound], None);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{bound}: {err}");
        assert!(out.stdout.is_empty() && err.lines().count() == 1 && err.contains(says), "{bound}: {err}");
    }
    let out = fricosc(&["fit", SYNTHETIC, "--bound", "mu0=0.1:0.5", "--bound", "mu0=0.2:0.4"], None);
    assert_eq!(out.status.code(), Some(2));
    let out = fricosc(&["fit", SYNTHETIC, "--bound", "mu0=0.1:0.5", "--mu0", "0.3"], None);
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a held one"));
}
