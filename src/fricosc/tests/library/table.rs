//! [`fricosc::validation::Table`]: named columns as the command line and
//! Python hand them over, against rows written out by hand.

use fricosc::validation::{Column, OscillationInput, Table};

fn names(n: &[&str]) -> Vec<String> {
    n.iter().map(|s| s.to_string()).collect()
}

fn numbers(v: &[f64]) -> Column {
    Column::Numbers(v.to_vec())
}

#[test]
fn vhat_and_mu_columns_become_vbar_and_mu_ratio_rows() {
    let cols = vec![("vhat", numbers(&[0.2, 0.6])), ("amp", numbers(&[0.5, 2.0])), ("mu", numbers(&[0.3, 0.15]))];
    let t = Table::from_columns(&names(&["vhat", "amp", "mu", "note"]), cols, "test", "t.csv").unwrap();
    assert_eq!(t.ignored_columns(), ["note"]);
    assert!(!t.is_oscillation());
    assert_eq!(t.rows(Some(0.6), "t.csv").unwrap(), vec![(0.4, 0.5, 0.5), (0.3, 2.0, 0.25)]);
    // mu needs mu0; mu0 with mu_ratio is refused.
    assert!(t.rows(None, "t.csv").is_err());
}

#[test]
fn a_tangential_table_gives_five_columns_with_phase_zero_where_missing() {
    let cols = vec![
        ("vhat", numbers(&[0.2, 0.6])),
        ("amp", numbers(&[0.5, 2.0])),
        ("mu_ratio", numbers(&[0.3, 0.15])),
        ("tangential_amp", numbers(&[1.0, 0.0])),
        ("shape", Column::Labels(vec!["flat".into()])),
    ];
    let all = names(&["vhat", "amp", "mu_ratio", "tangential_amp", "shape"]);
    let t = Table::from_columns(&all, cols, "test", "t.csv").unwrap();
    assert_eq!(t.shape(), Some("flat"));
    assert!(t.is_oscillation());
    let row = |v, a, t, m| OscillationInput::new(v, a, m).with_tangential(t, 0.0);
    assert_eq!(t.oscillation_rows(None, "t.csv").unwrap(), vec![row(0.2, 0.5, 1.0, 0.3), row(0.6, 2.0, 0.0, 0.15)]);
    assert!(t.rows(None, "t.csv").unwrap_err().to_string().contains("tangential_amp"));
}

/// Across the sliding direction: `transverse_amp`, its phase (0 where
/// missing) and the force across, divided by `mu0` like the force along.
#[test]
fn a_transverse_table_gives_the_oscillation_across_and_its_force() {
    let cols = vec![
        ("vhat", numbers(&[0.2, 0.6])),
        ("amp", numbers(&[0.5, 2.0])),
        ("mu", numbers(&[0.3, 0.15])),
        ("transverse_amp", numbers(&[1.0, 0.5])),
        ("transverse_ratio", numbers(&[-0.06, 0.03])),
    ];
    let all = names(&["vhat", "amp", "mu", "transverse_amp", "transverse_ratio"]);
    let t = Table::from_columns(&all, cols, "test", "t.csv").unwrap();
    assert!(t.is_oscillation() && t.ignored_columns().is_empty());
    let row = |v, a, m, w, r| OscillationInput::new(v, a, m).with_transverse(w, 0.0, Some(r));
    let expected = vec![row(0.2, 0.5, 1.0, 1.0, -0.2), row(0.6, 2.0, 0.5, 0.5, 0.1)];
    let rows = t.oscillation_rows(Some(0.3), "t.csv").unwrap();
    for (r, e) in rows.iter().zip(&expected) {
        assert!((r.mu_ratio - e.mu_ratio).abs() < 1e-15 && r.transverse_amp == e.transverse_amp);
        assert!((r.transverse_ratio.unwrap() - e.transverse_ratio.unwrap()).abs() < 1e-15);
    }
    let err = |extra: (&str, Column)| {
        let cols = vec![("vhat", numbers(&[0.2])), ("amp", numbers(&[0.5])), ("mu_ratio", numbers(&[0.3])), extra];
        Table::from_columns(&[], cols, "test", "t.csv").unwrap_err().to_string()
    };
    assert!(err(("transverse_ratio", numbers(&[0.1]))).contains("'transverse_ratio' without 'transverse_amp'"));
    assert!(err(("transverse_phase", numbers(&[0.1]))).contains("'transverse_phase' without 'transverse_amp'"));
    let vbar = vec![("vbar", numbers(&[0.2])), ("amp", numbers(&[0.5])), ("mu_ratio", numbers(&[0.3]))];
    let vbar = [vbar, vec![("transverse_amp", numbers(&[1.0]))]].concat();
    let e = Table::from_columns(&[], vbar, "test", "t.csv").unwrap_err().to_string();
    assert!(e.contains("'transverse_amp' needs its velocities as 'vhat'"), "{e}");
}

#[test]
fn missing_doubled_and_uneven_columns_are_refused_naming_the_source() {
    let amp = || ("amp", numbers(&[0.5]));
    let err = |cols: Vec<(&str, Column)>| Table::from_columns(&[], cols, "test", "t.csv").unwrap_err().to_string();
    let both = err(vec![("vbar", numbers(&[0.1])), ("vhat", numbers(&[0.1])), amp(), ("mu_ratio", numbers(&[1.0]))]);
    assert!(both.starts_with("t.csv: both 'vbar' and 'vhat'"), "{both}");
    assert!(err(vec![("vbar", numbers(&[0.1])), amp()]).contains("no column 'mu_ratio' (or 'mu')"));
    let uneven = err(vec![("vbar", numbers(&[0.1, 0.2])), amp(), ("mu_ratio", numbers(&[1.0]))]);
    assert!(uneven.contains("differ in length"), "{uneven}");
    let two = err(vec![
        ("vbar", numbers(&[0.1])),
        amp(),
        ("mu_ratio", numbers(&[1.0])),
        ("shape", Column::Labels(vec!["flat".into(), "cone".into()])),
    ]);
    assert!(two.contains("more than one shape"), "{two}");
    let phase = err(vec![("vhat", numbers(&[0.1])), amp(), ("mu_ratio", numbers(&[1.0])), ("phase", numbers(&[1.0]))]);
    assert!(phase.contains("'phase' without 'tangential_amp'"), "{phase}");
}
