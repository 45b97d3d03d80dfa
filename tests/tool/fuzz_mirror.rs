//! Stable mirrors of the cargo-fuzz targets in `tests/fuzz/`: the readers and the
//! solver entry points never panic, whatever they are given.
use fricosc::stepper::Stepping;
use fricosc::Shape;

use proptest::prelude::*;

fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>(),
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(-0.0),
        Just(1e-300),
        Just(5e-324),
        Just(2.1219957905e-314),
        Just(1e300),
        Just(1.0),
        Just(1.0 - f64::EPSILON),
        0.0f64..3.0,
    ]
}

/// Valid documents of every reader, to be mutated: random text fails at its
/// first byte, while a mutated valid document reaches every state of a reader.
const SEEDS: &[&str] = &[
    r#"[{"shape":"flat","vbar":0.3,"amp":0.5},{"shape":"parabolic","vbar":1e-3,"amp":1.5,"id":"x"}]"#,
    r#"{"shape":"flat","rows":[{"vbar":0.3,"amp":0.5,"mu_ratio":0.79},{"vhat":0.2,"amp":2,"mu_ratio":0.4}]}"#,
    "shape,vbar,amp,mu_ratio\nflat,0.3,0.5,0.79\ncone,\"1e-2\",1.5,0.2\n",
    "vbar;amp;mu\n0.3;0.5;0.3\n",
    "# vbar,amp,mu_ratio\n0.3,0.5,0.79\n",
];

/// A seed document with up to eight byte edits (replace, insert, delete).
fn mutated() -> impl Strategy<Value = String> {
    (0..SEEDS.len(), prop::collection::vec((0usize..256, any::<u8>(), 0u8..3), 0..8)).prop_map(|(k, edits)| {
        let mut b = SEEDS[k].as_bytes().to_vec();
        for (pos, byte, op) in edits {
            let i = pos % (b.len() + 1);
            match op {
                0 if i < b.len() => b[i] = byte,
                1 => b.insert(i, byte),
                _ if i < b.len() => {
                    b.remove(i);
                }
                _ => {}
            }
        }
        String::from_utf8_lossy(&b).into_owned()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn batch_reader_never_panics(text in mutated()) {
        let _ = fricosc_cli::batch::evaluate(&text, "fuzz", fricosc_cli::batch::Method::default());
    }

    #[test]
    fn batch_reader_on_json_like_input(rows in prop::collection::vec((".{0,12}", any_f64(), any_f64()), 0..5)) {
        let body: Vec<String> = rows.iter().map(|(s, v, a)| format!(r#"{{"shape":{:?},"vbar":{v:?},"amp":{a:?}}}"#, s)).collect();
        let _ = fricosc_cli::batch::evaluate(&format!("[{}]", body.join(",")), "fuzz", fricosc_cli::batch::Method::default());
    }

    #[test]
    fn validate_reader_never_panics(text in mutated()) {
        let _ = fricosc_cli::validate::read_table(&text, "fuzz");
        let _ = fricosc_cli::validate::read_table(&format!("vbar,amp,mu_ratio\n{text}"), "fuzz");
    }

    #[test]
    fn value_lists_never_panic(text in ".{0,40}") {
        let _ = fricosc_cli::grid::values(&text);
    }

    #[test]
    fn shape_specs_never_panic(text in ".{0,40}") {
        let _ = fricosc_cli::input::parse_shape(&text);
    }

    #[test]
    fn profile_tables_never_panic(text in "[0-9eE.,;+\\- \n#a-z]{0,120}", v in any_f64(), a in any_f64()) {
        // Removed when dropped, also when the test fails.
        let scratch = tempfile::Builder::new().prefix("fricosc-fuzz-").tempdir().unwrap();
        let dir = scratch.path().to_path_buf();
        let path = dir.join("t.csv");
        std::fs::write(&path, &text).unwrap();
        if let Ok(shape) = fricosc_cli::input::parse_shape(&format!("profile:{}@1", path.display())) {
            match crate::common::eval(&shape, v, a) {
                Ok(e) => prop_assert!((0.0..=1.0).contains(&e.ratio.mu_ratio)),
                // Bad input or a table that cannot carry the contact, never an internal failure.
                Err(e) => prop_assert!(!matches!(e, fricosc::Error::Internal { .. }), "{e}"),
            }
        }
    }

    /// Mirror of `tests/fuzz/fuzz_targets/profile_columns.rs`, on nondecreasing columns
    /// (the ones that pass the checks and reach the transform) of up to 300 rows.
    #[test]
    fn profile_columns_never_panic(
        steps in prop::collection::vec((1e-6f64..1.0, 0.0f64..2.0), 2..300),
        profile in any::<bool>(), u0 in any_f64(), v in any_f64(), a in any_f64(),
    ) {
        let (mut x, mut f) = (vec![0.0], vec![0.0]);
        for (dx, df) in steps {
            x.push(x[x.len() - 1] + dx);
            f.push(f[f.len() - 1] + df * df * df);
        }
        if let Ok(table) = fricosc::contact::Table::from_columns(x, f, profile, "mirror") {
            if let Ok(contact) = table.at(u0) {
                match crate::common::eval(&fricosc::Shape::from_contact(std::sync::Arc::new(contact)), v, a) {
                    Ok(e) => prop_assert!((0.0..=1.0).contains(&e.ratio.mu_ratio)),
                    Err(e) => prop_assert!(!matches!(e, fricosc::Error::Internal { .. }), "{e}"),
                }
            }
        }
    }

    #[test]
    fn solvers_never_panic_and_stay_in_range(v in any_f64(), a in any_f64(), k in 0usize..6, n in any_f64()) {
        let shape = match k {
            0 => Shape::flat(),
            1 => Shape::parabolic(),
            2 => Shape::cone(),
            3 => Shape::power(0.7).unwrap(),
            // A worn tip (flat-tip:E, E in [0, 1)), through the registry's parser.
            4 => match Shape::parse(&format!("flat-tip:{:?}", n.fract().abs())) {
                Ok(s) => s,
                Err(_) => return Ok(()),
            },
            // The exponent through the parser, as users give it (the fuzz target found power:6.5e91).
            _ => match Shape::parse(&format!("power:{n:?}")) {
                Ok(s) => s,
                Err(_) => return Ok(()),
            },
        };
        match crate::common::eval(&shape, v, a) {
            Ok(e) => {
                prop_assert!((0.0..=1.0).contains(&e.ratio.mu_ratio));
                prop_assert!(e.ratio.reduction >= 0.0);
            }
            Err(_) => prop_assert!(!(v.is_finite() && a.is_finite() && v >= 0.0 && a >= 0.0)),
        }
        let _ = crate::common::at::stepped(&shape, v, a, Stepping { steps_per_period: 16, springs: 8 });
    }
}
