#![no_main]
//! The CSV/JSON table reader of `validate` on arbitrary bytes.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = fricosc_cli::validate::read_table(text, "fuzz");
    }
});
