#![no_main]
//! The batch reader on arbitrary bytes (mirrored by tests/fuzz_mirror.rs).
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = fricosc::batch::run(text, "fuzz", None);
    }
});
