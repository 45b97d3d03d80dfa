//! The CSV of physical scenes with oscillations in the plane (the rows
//! themselves: `src/fricosc/tests/library/scene_plane.rs`).

/// A flat punch scene (steel on aluminium, `u0` = 1 um, `du/u0` = 0.5, 100
/// Hz) at 1e-4 m/s with the oscillation fields `extra`.
fn scene(extra: &str) -> String {
    format!(
        r#"{{"materials": {{"e1_pa": 2.1e11, "nu1": 0.3, "e2_pa": 7e10, "nu2": 0.33}}, "mu0": 0.3,
            "indenter": {{"flat_punch": {{"radius_m": 0.001}}}}, "loading": {{"mean_indentation_m": 1e-6}},
            "oscillation": {{"amplitude_fraction": 0.5, "frequency_hz": 100{extra}}},
            "velocity": {{"values_m_per_s": [1e-4]}}}}"#
    )
}

/// The CSV of a scene in the plane has the plane's columns (and an empty
/// `mu_static`); a scene without them has none of them.
#[test]
fn the_csv_has_the_plane_s_columns_where_a_scene_has_them() {
    use std::process::Command;
    let dir = tempfile::tempdir().unwrap();
    let header = |extra: &str| {
        let p = dir.path().join("s.json");
        std::fs::write(&p, scene(extra)).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_fricosc"))
            .args(["scene", p.to_str().unwrap(), "--format", "csv"])
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let text = String::from_utf8(out.stdout).unwrap();
        let mut rd = csv::Reader::from_reader(text.as_bytes());
        let h: Vec<String> = rd.headers().unwrap().iter().map(String::from).collect();
        let row: Vec<String> = rd.records().next().unwrap().unwrap().iter().map(String::from).collect();
        h.into_iter().zip(row).collect::<std::collections::BTreeMap<_, _>>()
    };
    let plane = header(r#", "transverse_amplitude_m": 1e-6, "tangential_amplitude_m": 1e-7"#);
    for c in ["tangential_amp", "phase", "transverse_amp", "transverse_phase", "transverse_ratio"] {
        assert!(plane[c].parse::<f64>().is_ok(), "{c}: {plane:?}");
    }
    let f = plane["mean_transverse_force_n"].parse::<f64>().unwrap();
    assert!(f.is_finite() && f != 0.0);
    assert_eq!(plane["mu_static"], "");
    let plain = header("");
    assert!(!plain.contains_key("transverse_ratio") && !plain.contains_key("tangential_amp"), "{plain:?}");
    assert!(plain["mu_static"].parse::<f64>().is_ok());
}
