#![no_main]
//! The batch reader on arbitrary bytes (mirrored by tests/fuzz_mirror.rs), and
//! the one-pass row scanner against serde_json (mirrored by tests/scan.rs): both
//! accept the same inputs and pick the same rows and fields, and the numbers
//! the scanner reads on its way are the fields' values.
use libfuzzer_sys::fuzz_target;

#[path = "../../tool/common/rows.rs"]
mod rows;

const NAMES: [&str; 3] = ["shape", "vbar", "amp"];

type Rows = Option<Vec<(String, Vec<Option<String>>)>>;

fn by_serde(text: &str) -> Rows {
    let rows = rows::raw_array(text).ok()?;
    rows.iter()
        .map(|r| {
            let p = rows::pick(r, &NAMES).ok()?;
            Some((r.get().to_string(), p.0.iter().map(|v| v.map(|v| v.get().to_string())).collect()))
        })
        .collect()
}

fn by_scan(text: &str) -> Rows {
    let mut out = vec![];
    fricosc_cli::scan::array_rows(text, &NAMES, |_, r| {
        // A number read on the scan's way (quick path or a row's layout) is its field's value.
        for (x, f) in r.numbers.iter().zip(r.fields) {
            if !x.is_nan() {
                assert_eq!(Some(x.to_bits()), f.and_then(|f| f.parse::<f64>().ok()).map(f64::to_bits), "{f:?}");
            }
        }
        out.push((r.raw.to_string(), r.fields.iter().map(|v| v.map(String::from)).collect()));
        Ok(())
    })
    .ok()?;
    Some(out)
}

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = fricosc_cli::batch::run(text, "fuzz", None);
        // Nesting beyond the scanner's depth limit is refused on purpose.
        if text.matches(['[', '{']).count() < fricosc_cli::scan::MAX_DEPTH {
            assert_eq!(by_scan(text), by_serde(text), "{text:?}");
        }
    }
});
