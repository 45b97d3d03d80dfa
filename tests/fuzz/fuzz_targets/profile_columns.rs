#![no_main]
//! Tabulated contacts from arbitrary columns (the path of `Table::from_columns`,
//! which the Python package uses): the checks, the MDR transform of up to a few
//! hundred rows (through its hierarchical sum), and a point. No panic; a result
//! whenever the table is accepted lies in [0, 1]; never an internal error.
use fricosc::contact::Table;
use fricosc::{Conditions, Shape};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: (Vec<(f64, f64)>, bool, f64, f64, f64)| {
    let (rows, profile, u0, v, a) = data;
    let (x, f): (Vec<f64>, Vec<f64>) = rows.into_iter().unzip();
    let Ok(table) = Table::from_columns(x, f, profile, "fuzz") else { return };
    let Ok(contact) = table.at(u0) else { return };
    let shape = Shape::from_contact(std::sync::Arc::new(contact));
    match Conditions::vbar(v, a).and_then(|c| shape.evaluate(&c)) {
        Ok(e) => assert!((0.0..=1.0).contains(&e.ratio.mu_ratio), "{v} {a}: {}", e.ratio.mu_ratio),
        Err(e) => assert!(!matches!(e, fricosc::Error::Internal { .. }), "{e}"),
    }
});
