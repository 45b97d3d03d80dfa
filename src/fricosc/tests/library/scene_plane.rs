//! Physical scenes with oscillations in the plane: their amplitudes in
//! pre-slip lengths, the rows against the point solver at conditions
//! converted here from the SI inputs, the refusals (the CSV's columns:
//! `tests/tool/scene_plane.rs`).
use fricosc::plane::Transverse;
use fricosc::scene::{Scene, SceneResult};
use fricosc::{Conditions, Shape};
use std::f64::consts::PI;

/// A scene from JSON text (as `fricosc scene` reads it), named `s.json`.
fn parse(text: &str, _source: &str) -> fricosc::Result<Scene> {
    serde_json::from_str(text).map_err(|e| fricosc::Error::Parse { context: "s.json".into(), reason: e.to_string() })
}

/// Its answers; it names no file.
fn solve(s: &Scene, source: &str) -> fricosc::Result<Vec<SceneResult>> {
    fricosc::scene::solve_with(s, source, &|_| Err(std::io::Error::other("no files")), &|_| {})
}

/// A scene of steel on aluminium (`nu` 0.3 and 0.33) at `u0` = 1 um, `du/u0`
/// = `amp`, 100 Hz, mu0 0.3, the indenter `indenter`, the velocities `v`
/// and the oscillations in the plane `extra` (JSON fields of `oscillation`).
fn scene(indenter: &str, amp: f64, extra: &str, v: &[f64]) -> String {
    format!(
        r#"{{"materials": {{"e1_pa": 2.1e11, "nu1": 0.3, "e2_pa": 7e10, "nu2": 0.33}}, "mu0": 0.3,
            "indenter": {indenter}, "loading": {{"mean_indentation_m": 1e-6}},
            "oscillation": {{"amplitude_fraction": {amp:?}, "frequency_hz": 100{extra}}},
            "velocity": {{"values_m_per_s": {v:?}}}}}"#
    )
}

/// The pre-slip length `l = mu0 u0 kz/kx = mu0 u0 E*/G*` of these materials
/// (eqs. 23-24, `G = E/(2(1 + nu))`), written out here.
fn pre_slip_length() -> f64 {
    let e_star = 1.0 / ((1.0 - 0.09) / 2.1e11 + (1.0 - 0.33 * 0.33) / 7e10);
    let (g1, g2) = (2.1e11 / 2.6, 7e10 / 2.66);
    let g_star = 1.0 / ((2.0 - 0.3) / (4.0 * g1) + (2.0 - 0.33) / (4.0 * g2));
    0.3 * 1e-6 * e_star / g_star
}

/// Rows at `vhat = v0/(omega l)`, `T = dx/l`, `W = dy/l` equal the point
/// solver's there (the flat punch and a sphere; a velocity above the normal
/// oscillation's critical one, where without the plane nothing is computed);
/// the mean force across is `transverse_ratio mu0 F`.
#[test]
fn a_scene_in_the_plane_is_the_point_at_its_pre_slip_amplitudes() {
    let (dx, dy, phase, psi) = (5e-7, 1e-6, 1.1, 0.7);
    let extra = format!(
        r#", "tangential_amplitude_m": {dx:?}, "tangential_phase_rad": {phase:?},
           "transverse_amplitude_m": {dy:?}, "transverse_phase_rad": {psi:?}"#
    );
    let l = pre_slip_length();
    let omega = 2.0 * PI * 100.0;
    for (indenter, shape, v, amp, tol) in [
        (r#"{"flat_punch": {"radius_m": 0.001}}"#, Shape::flat(), vec![0.0, 1e-4, 1e-3], 0.5, 1e-15),
        (r#"{"sphere": {"radius_m": 0.005}}"#, Shape::parabolic(), vec![2e-4], 1.5, 3e-15),
    ] {
        let mut r = solve(&parse(&scene(indenter, amp, &extra, &v), "s.json").unwrap(), "s.json").unwrap();
        let r = r.remove(0);
        assert!((r.pre_slip_length_m.unwrap() / l - 1.0).abs() < 4e-16, "{:?} vs {l}", r.pre_slip_length_m);
        assert!((r.in_plane.tangential_amp.unwrap() / (dx / l) - 1.0).abs() < 1e-15);
        assert!((r.in_plane.transverse_amp.unwrap() / (dy / l) - 1.0).abs() < 1e-15);
        assert_eq!((r.in_plane.phase, r.in_plane.transverse_phase), (Some(phase), Some(psi)));
        assert_eq!(r.mu_static, None, "at rest the contact slips under the oscillations in the plane");
        for (row, &v0) in r.rows.iter().zip(&v) {
            let c = Conditions::vhat(v0 / (omega * l), amp)
                .unwrap()
                .with_tangential(dx / l, phase)
                .unwrap()
                .with_transverse(Transverse::new(dy / l, psi).unwrap());
            let e = shape.evaluate(&c).unwrap();
            let across = e.transverse_ratio.unwrap();
            assert!((row.mu_ratio - e.ratio.mu_ratio).abs() < tol, "v0 {v0}: {} vs {}", row.mu_ratio, e.ratio.mu_ratio);
            assert!((row.transverse_ratio.unwrap() - across).abs() < tol, "v0 {v0}");
            let f = row.mean_transverse_force_n.unwrap() / (0.3 * r.mean_normal_force_n);
            assert!((f - across).abs() < tol, "v0 {v0}: {f} vs {across}");
            assert!(across.abs() > 0.01 && row.mu_ratio < 0.95, "a scene that tests nothing: {across}");
            let regime = if shape.is_flat() { "permanent_contact" } else { "jumping" };
            assert_eq!(row.regime.name(), regime);
        }
    }
}

/// Each drive alone (the flat punch): the other's fields absent, the rows the
/// point's with that drive only (a velocity above the normal oscillation's critical one among them).
#[test]
fn each_oscillation_in_the_plane_alone_is_the_point_with_it_alone() {
    let (l, omega, flat) = (pre_slip_length(), 2.0 * PI * 100.0, r#"{"flat_punch": {"radius_m": 0.001}}"#);
    let v = [0.0, 1e-4, 2.5e-4];
    for along in [true, false] {
        let extra = if along {
            r#", "tangential_amplitude_m": 5e-7, "tangential_phase_rad": 1.1"#
        } else {
            r#", "transverse_amplitude_m": 1e-6, "transverse_phase_rad": 0.7"#
        };
        let r = solve(&parse(&scene(flat, 0.5, extra, &v), "s.json").unwrap(), "s.json").unwrap().remove(0);
        assert_eq!((r.in_plane.tangential_amp.is_some(), r.in_plane.transverse_amp.is_some()), (along, !along));
        for (row, &v0) in r.rows.iter().zip(&v) {
            let c = Conditions::vhat(v0 / (omega * l), 0.5).unwrap();
            let c = if along {
                c.with_tangential(5e-7 / l, 1.1).unwrap()
            } else {
                c.with_transverse(Transverse::new(1e-6 / l, 0.7).unwrap())
            };
            let e = Shape::flat().evaluate(&c).unwrap();
            assert!((row.mu_ratio - e.ratio.mu_ratio).abs() < 1e-15, "{along} {v0}: {}", row.mu_ratio);
            assert_eq!(row.transverse_ratio.is_some(), !along);
            assert!((row.transverse_ratio.unwrap_or(0.0) - e.transverse_ratio.unwrap_or(0.0)).abs() < 1e-15);
            assert!(row.mu_ratio < 0.95, "{along} {v0}: a row that tests nothing");
        }
    }
}

/// Amplitudes of zero in the plane are the scene without them, bit for bit.
#[test]
fn zero_amplitudes_in_the_plane_are_the_scene_without_them() {
    let flat = r#"{"flat_punch": {"radius_m": 0.001}}"#;
    let v = [0.0, 3e-5, 1e-4, 2e-4];
    let plain = solve(&parse(&scene(flat, 0.5, "", &v), "s.json").unwrap(), "s.json").unwrap();
    let zero = r#", "tangential_amplitude_m": 0.0, "transverse_amplitude_m": 0.0, "transverse_phase_rad": 2.0"#;
    let zeros = solve(&parse(&scene(flat, 0.5, zero, &v), "s.json").unwrap(), "s.json").unwrap();
    assert_eq!(plain[0].rows, zeros[0].rows);
    assert_eq!(plain[0].mu_static, zeros[0].mu_static);
    assert!(zeros[0].pre_slip_length_m.is_none() && zeros[0].in_plane.transverse_amp.is_none());
}

/// Bad amplitudes and phases in the plane, and the plane on a system, are
/// refused naming the field.
#[test]
fn bad_oscillations_in_the_plane_name_their_field() {
    let flat = r#"{"flat_punch": {"radius_m": 0.001}}"#;
    let cases = [
        (r#", "tangential_amplitude_m": -1e-7"#, "oscillation.tangential_amplitude_m"),
        (r#", "tangential_amplitude_m": 1.0"#, "oscillation.tangential_amplitude_m"),
        (r#", "transverse_amplitude_m": 1.0"#, "oscillation.transverse_amplitude_m"),
        (r#", "transverse_amplitude_m": 1e-7, "transverse_phase_rad": 2e6"#, "oscillation.transverse_phase_rad"),
        (r#", "tangential_amplitude_m": 1e-7, "tangential_phase_rad": 1e400"#, "number out of range"),
    ];
    // vhat = v0/(omega l) beyond 1e6 pre-slip lengths, at 1e3 m/s.
    let e = parse(&scene(flat, 0.5, r#", "tangential_amplitude_m": 1e-7"#, &[1e-4, 1e3]), "s.json")
        .and_then(|s| solve(&s, "s.json"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("s.json: velocity") && e.contains("vhat"), "{e}");
    for (extra, frag) in cases {
        let e = parse(&scene(flat, 0.5, extra, &[1e-4]), "s.json").and_then(|s| solve(&s, "s.json"));
        let e = e.unwrap_err().to_string();
        assert!(e.contains("s.json") && e.contains(frag), "{frag}: {e}");
    }
    // Across the sliding direction on a system.
    let text = scene(flat, 0.5, r#", "transverse_amplitude_m": 1e-7"#, &[1e-4]);
    let system = r#""system": {"mass_kg": 0.1, "stiffness_n_per_m": 1e6}, "velocity""#;
    let text = text.replacen(r#""velocity""#, system, 1);
    let e = solve(&parse(&text, "s.json").unwrap(), "s.json").unwrap_err().to_string();
    assert!(e.contains("oscillation.transverse_amplitude_m") && e.contains("system"), "{e}");
}
