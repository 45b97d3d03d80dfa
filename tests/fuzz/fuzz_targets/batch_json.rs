#![no_main]
//! The batch reader on arbitrary bytes (mirrored by `tests/tool/fuzz_mirror.rs`,
//! and by `tests/tool/batch_rows.rs` against a serial reading): it never
//! panics, and an array it accepts is written back as an array of the same
//! number of objects.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(batch) = fricosc_cli::batch::evaluate(text, "fuzz", fricosc_cli::batch::Method::default()) {
            let mut out = vec![];
            batch.write(&mut out).unwrap();
            let rows: Vec<serde_json::Value> = serde_json::from_slice(&out).unwrap();
            assert_eq!(rows.len(), batch.len());
            assert!(rows.iter().all(|r| r["mu_ratio"].is_f64() && r["reduction"].is_f64()));
        }
    }
});
