#![no_main]
//! Tabulated contacts from arbitrary columns (the path of `Table::from_columns`,
//! which the Python package uses): the checks, the MDR transform of up to a few
//! hundred rows (through its hierarchical sum), and a point. No panic; a result
//! whenever the table is accepted lies in [0, 1]; never an internal error.
use fricosc::profile::Table;
use fricosc::Shape;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: (Vec<(f64, f64)>, bool, f64, f64, f64)| {
    let (rows, profile, u0, v, a) = data;
    let (x, f): (Vec<f64>, Vec<f64>) = rows.into_iter().unzip();
    let Ok(table) = Table::from_columns(x, f, profile, "fuzz") else { return };
    let Ok(contact) = table.at(u0) else { return };
    match Shape::from_contact(std::sync::Arc::new(contact)).evaluate(v, a) {
        Ok(e) => assert!((0.0..=1.0).contains(&e.ratio.mu_ratio), "{v} {a}: {}", e.ratio.mu_ratio),
        Err(e) => assert!(!matches!(e, fricosc::Error::Internal { .. }), "{e}"),
    }
});
