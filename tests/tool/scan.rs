//! The one-pass row scanner (`fricosc_cli::scan`) against `serde_json`: on random
//! JSON-like arrays, valid and broken, it accepts exactly what `serde_json`
//! accepts (an array of raw values whose objects have no duplicate keys) and
//! picks the same raw rows and fields.
use crate::common::rows;

use fricosc_cli::scan::array_rows;
use proptest::prelude::*;
use rows::{pick, raw_array};

const NAMES: [&str; 3] = ["shape", "vbar", "amp"];

/// What `serde_json` makes of `text`: the rows' raw text and picked fields, or `None`.
fn by_serde(text: &str) -> Option<Vec<(String, Vec<Option<String>>)>> {
    let rows = raw_array(text).ok()?;
    rows.iter()
        .map(|r| {
            let p = pick(r, &NAMES).ok()?;
            Some((r.get().to_string(), p.0.iter().map(|v| v.map(|v| v.get().to_string())).collect()))
        })
        .collect()
}

/// What the scanner makes of it; each number it read on its way must be its
/// field's value as `str::parse` reads it, bit for bit.
fn by_scan(text: &str) -> Option<Vec<(String, Vec<Option<String>>)>> {
    let mut out = vec![];
    array_rows(text, &NAMES, |_, r| {
        for (x, f) in r.numbers.iter().zip(r.fields) {
            if !x.is_nan() {
                let y = f.and_then(|f| f.parse::<f64>().ok());
                assert_eq!(Some(x.to_bits()), y.map(f64::to_bits), "{f:?} read as {x:?}");
            }
        }
        out.push((r.raw.to_string(), r.fields.iter().map(|v| v.map(String::from)).collect()));
        Ok(())
    })
    .ok()?;
    Some(out)
}

fn ws() -> impl Strategy<Value = String> {
    prop::sample::select(vec!["", "", " ", "\n", "\t", "\r\n", "  "]).prop_map(String::from)
}

fn key() -> impl Strategy<Value = String> {
    prop::sample::select(vec![
        "\"shape\"",
        "\"vbar\"",
        "\"amp\"",
        "\"x\"",
        "\"s\\u0068ape\"",
        "\"v\\\"q\"",
        "\"\\ud800\"",
        "\"é\"",
    ])
    .prop_map(String::from)
}

fn scalar() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<f64>().prop_map(|x| format!("{x:?}")),
        any::<i64>().prop_map(|x| x.to_string()),
        prop::sample::select(vec![
            "0",
            "-0",
            "1e5",
            "1E-5",
            "0.5e+3",
            "true",
            "false",
            "null",
            "\"flat\"",
            "\"a\\nb\"",
            "\"\\u00e9\"",
            "\"\\ud800\"",
            "[]",
            "{}",
            "[1, [2, {\"a\": null}]]",
        ])
        .prop_map(String::from),
    ]
}

fn value() -> impl Strategy<Value = String> {
    scalar().prop_recursive(3, 16, 4, |inner| {
        prop_oneof![
            prop::collection::vec((ws(), inner.clone()), 0..4)
                .prop_map(|v| format!("[{}]", v.into_iter().map(|(w, x)| w + &x).collect::<Vec<_>>().join(","))),
            prop::collection::vec((key(), ws(), inner), 0..4).prop_map(|v| format!(
                "{{{}}}",
                v.into_iter().map(|(k, w, x)| format!("{k}{w}:{x}")).collect::<Vec<_>>().join(",")
            )),
        ]
    })
}

fn row() -> impl Strategy<Value = String> {
    prop::collection::vec((ws(), key(), ws(), value(), ws()), 0..5).prop_map(|v| {
        format!(
            "{{{}}}",
            v.into_iter().map(|(a, k, b, x, c)| format!("{a}{k}{b}:{x}{c}")).collect::<Vec<_>>().join(",")
        )
    })
}

fn array() -> impl Strategy<Value = String> {
    (ws(), prop::collection::vec((ws(), prop_oneof![9 => row(), 1 => value()], ws()), 0..5), ws()).prop_map(
        |(a, rows, b)| {
            format!("{a}[{}]{b}", rows.into_iter().map(|(x, r, y)| x + &r + &y).collect::<Vec<_>>().join(","))
        },
    )
}

/// One byte changed, inserted or deleted at `at` (on a character boundary).
fn mutate(text: &str, at: usize, op: u8, byte: char) -> String {
    let mut at = at % (text.len() + 1);
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    let mut s = text.to_string();
    match op % 3 {
        0 => s.insert(at, byte),
        1 if at < s.len() => {
            s.remove(at);
        }
        _ if at < s.len() => {
            s.remove(at);
            s.insert(at, byte);
        }
        _ => s.push(byte),
    }
    s
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn the_scanner_agrees_with_serde_json_on_valid_arrays(text in array()) {
        prop_assert_eq!(by_scan(&text), by_serde(&text), "{}", text);
    }

    #[test]
    fn the_scanner_agrees_with_serde_json_on_broken_arrays(
        text in array(),
        at in any::<usize>(),
        op in any::<u8>(),
        byte in prop::sample::select(vec!['[', ']', '{', '}', ',', ':', '"', '\\', '-', '.', 'e', '0', '1', ' ', '\u{1}', 'x', 'n', 't', 'u']),
    ) {
        let broken = mutate(&text, at, op, byte);
        prop_assert_eq!(by_scan(&broken), by_serde(&broken), "{}", broken);
    }
}

/// Hand-picked edges of the grammar.
#[test]
fn edges_agree() {
    for text in [
        "[]",
        " [ ] ",
        "[{}]",
        "[{},]",
        "[,{}]",
        "[{\"a\":1}{\"b\":2}]",
        "[{\"a\":01}]",
        "[{\"a\":1.}]",
        "[{\"a\":.5}]",
        "[{\"a\":-}]",
        "[{\"a\":1e}]",
        "[{\"a\":+1}]",
        "[{\"a\":NaN}]",
        "[{\"a\":tru}]",
        "[{\"a\":\"\\x\"}]",
        "[{\"a\":\"\\u12\"}]",
        "[{\"a\":\"\u{1}\"}]",
        "[{\"a\":1}] x",
        "[{\"a\":1}]\n\n",
        "[{\"shape\":1,\"sh\\u0061pe\":2}]",
        "[{\"\\ud800\":1}]",
        "[{\"a\":\"\\ud800\"}]",
        "\u{feff}[]",
        "[{'a':1}]",
        "[{\"a\" 1}]",
        "[{\"a\":1 \"b\":2}]",
        "[1]",
        "[\"x\"]",
        "[{\"a\":[1,2,]}]",
        "[{\"a\":{\"b\":}}]",
    ] {
        assert_eq!(by_scan(text), by_serde(text), "{text:?}");
    }
}

/// The row at fault as a serial reading finds it: the first row that is
/// malformed, lacks a field, names an unknown shape or holds a bad number.
fn serial_fault(text: &str) -> Result<(), Option<usize>> {
    use fricosc_cli::scan::{number_of, string_of, RowsError};
    let r = array_rows(text, &NAMES, |_, r| {
        let spec = string_of(r.fields[0].ok_or("shape")?, "shape")?;
        fricosc_cli::input::parse_shape(&spec).map_err(|e| e.to_string())?;
        for k in [1, 2] {
            let x = number_of(r.fields[k].ok_or("field")?, "x")?;
            if !(x.is_finite() && x >= 0.0) {
                return Err(format!("invalid x = {x:?}"));
            }
        }
        Ok(())
    });
    match r {
        Ok(_) => Ok(()),
        Err(RowsError::Row { row, .. }) | Err(RowsError::Syntax { row: Some(row), .. }) => Err(Some(row)),
        Err(RowsError::Syntax { row: None, .. }) => Err(None),
    }
}

fn batch_row() -> impl Strategy<Value = String> {
    let shape = prop::sample::select(vec!["\"flat\"", "\"parabolic\"", "\"nope\"", "1", ""]);
    let num = prop::sample::select(vec!["0.5", "0", "-1", "\"x\"", "1e999", ""]);
    (shape, num.clone(), num).prop_map(|(s, v, a)| {
        let mut f = vec![];
        for (k, x) in [("shape", s), ("vbar", v), ("amp", a)] {
            if !x.is_empty() {
                f.push(format!("\"{k}\":{x}"));
            }
        }
        format!("{{{}}}", f.join(","))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// `batch` scans rows in parallel chunks: it finds the same row at fault
    /// as a serial reading, or none where there is none.
    #[test]
    fn batch_reports_the_first_row_at_fault(
        rows in prop::collection::vec(prop_oneof![8 => Just("{\"shape\":\"flat\",\"vbar\":0.5,\"amp\":1}".to_string()), 2 => batch_row()], 0..40),
        at in any::<usize>(),
        op in any::<u8>(),
        byte in prop::sample::select(vec![',', '}', '"', ' ']),
        broken in any::<bool>(),
    ) {
        let text = format!("[{}]", rows.join(","));
        let text = if broken { mutate(&text, at, op, byte) } else { text };
        let got = fricosc_cli::batch::run(&text, "t", None);
        match serial_fault(&text) {
            Ok(()) => prop_assert!(got.is_ok(), "{}: {:?}", text, got.err()),
            Err(row) => {
                let e = got.err().map(|e| e.to_string()).unwrap_or_default();
                match row {
                    Some(k) => prop_assert!(e.starts_with(&format!("t: row {k}:")), "{}: {}", text, e),
                    None => prop_assert!(!e.is_empty() && !e.contains(": row "), "{}: {}", text, e),
                }
            }
        }
    }
}
