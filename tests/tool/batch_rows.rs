//! The batch reader (`fricosc_cli::batch`, on serde_json's raw values)
//! against the tests' own reading of the same text (`common/rows.rs`, a
//! visitor of their own): on random JSON-like arrays, valid and broken,
//! `batch` accepts exactly the arrays whose rows are objects without duplicate
//! keys that name a known shape and finite `vbar`, `amp` >= 0; in a
//! well-formed array it names the first row at fault, as a serial reading
//! finds it; and it writes each row's own text back with the library's two
//! results spliced in.
use crate::common::rows;

use fricosc::Shape;
use proptest::prelude::*;
use rows::{pick, raw_array};

const NAMES: [&str; 3] = ["shape", "vbar", "amp"];

/// A number as JSON writes it, or why the row is refused.
fn number(v: Option<&serde_json::value::RawValue>) -> Result<f64, ()> {
    let t = v.ok_or(())?.get();
    let x: f64 = t.parse().map_err(|_| ())?;
    let json = t.starts_with(|c: char| c == '-' || c.is_ascii_digit());
    if json && x.is_finite() && x >= 0.0 {
        Ok(x + 0.0)
    } else {
        Err(())
    }
}

/// What a serial reading makes of `text`: each row's text and its results,
/// or the row at fault (`None`: the array itself is malformed).
fn serial(text: &str) -> Result<Vec<(String, fricosc::Ratio)>, Option<usize>> {
    let rows = raw_array(text).map_err(|_| None)?;
    let mut out = vec![];
    for (i, r) in rows.iter().enumerate() {
        let fault = Some(i);
        let p = pick(r, &NAMES).map_err(|_| fault)?;
        let shape: String = serde_json::from_str(p.0[0].ok_or(fault)?.get()).map_err(|_| fault)?;
        let shape = Shape::parse(&shape).map_err(|_| fault)?;
        let (vbar, amp) = (number(p.0[1]).map_err(|()| fault)?, number(p.0[2]).map_err(|()| fault)?);
        out.push((r.get().to_string(), crate::common::eval(&shape, vbar, amp).map(|e| e.ratio).map_err(|_| fault)?));
    }
    Ok(out)
}

/// The array `batch` writes for rows and results.
fn written(rows: &[(String, fricosc::Ratio)]) -> String {
    let num = |x: f64| serde_json::to_string(&x).unwrap();
    let rows: Vec<String> = rows
        .iter()
        .map(|(raw, r)| {
            format!("{},\"mu_ratio\":{},\"reduction\":{}}}", &raw[..raw.len() - 1], num(r.mu_ratio), num(r.reduction))
        })
        .collect();
    if rows.is_empty() {
        "[\n]\n".into()
    } else {
        format!("[\n{}\n]\n", rows.join(",\n"))
    }
}

/// `batch` on `text` agrees with the serial reading: the same rows written
/// back, or the same row at fault.
fn agrees(text: &str) -> Result<(), TestCaseError> {
    let got = fricosc_cli::batch::evaluate(text, "t", fricosc_cli::batch::Method::default());
    match (serial(text), got) {
        (Ok(rows), Ok(batch)) => {
            let mut out = vec![];
            batch.write(&mut out).unwrap();
            prop_assert_eq!(String::from_utf8(out).unwrap(), written(&rows), "{}", text);
        }
        (Err(Some(k)), Err(e)) => {
            let e = e.to_string();
            prop_assert!(e.starts_with(&format!("t: row {k}:")), "{}: {}", text, e);
        }
        // A malformed array: refused (the row it names, if any, is where the
        // reader stopped, or an earlier bad row: both are the reader's to say).
        (Err(None), Err(_)) => {}
        (want, got) => prop_assert!(false, "{}: want {:?}, got {:?}", text, want.err(), got.err()),
    }
    Ok(())
}

fn ws() -> impl Strategy<Value = String> {
    prop::sample::select(vec!["", "", " ", "\n", "\t", "\r\n", "  "]).prop_map(String::from)
}

fn key() -> impl Strategy<Value = String> {
    prop::sample::select(vec![
        "\"shape\"",
        "\"vbar\"",
        "\"amp\"",
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

/// A row with a shape, velocity and amplitude good or bad, and a random field.
fn batch_row() -> impl Strategy<Value = String> {
    let shape = prop::sample::select(vec!["\"flat\"", "\"flat\"", "\"parabolic\"", "\"nope\"", "1", ""]);
    let num = prop::sample::select(vec!["0.5", "0", "-0", "1.5e-3", "-1", "\"x\"", "1e999", ""]);
    (shape, num.clone(), num, ws(), value()).prop_map(|(s, v, a, w, x)| {
        let mut f = vec![];
        for (k, y) in [("shape", s), ("vbar", v), ("amp", a)] {
            if !y.is_empty() {
                f.push(format!("{w}\"{k}\":{y}"));
            }
        }
        f.push(format!("\"x\":{x}"));
        format!("{{{}}}", f.join(","))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn batch_agrees_with_a_serial_reading_on_arrays(text in array()) {
        agrees(&text)?;
    }

    #[test]
    fn batch_agrees_with_a_serial_reading_on_broken_arrays(
        rows in prop::collection::vec(prop_oneof![6 => batch_row(), 1 => row()], 0..12),
        at in any::<usize>(),
        op in any::<u8>(),
        byte in prop::sample::select(vec!['[', ']', '{', '}', ',', ':', '"', '\\', '-', '.', 'e', '0', '1', ' ', '\u{1}', 'x', 'n', 't', 'u']),
        broken in any::<bool>(),
    ) {
        let text = format!("[{}]", rows.join(","));
        let text = if broken { mutate(&text, at, op, byte) } else { text };
        agrees(&text)?;
    }
}

/// Hand-picked edges of the grammar.
#[test]
fn edges_agree() {
    let good = r#"{"shape":"flat","vbar":0.5,"amp":1}"#;
    for text in [
        "[]",
        " [ ] ",
        "[{}]",
        &format!("[{good},]"),
        &format!("[,{good}]"),
        &format!("[{good}{good}]"),
        "[{\"shape\":\"flat\",\"vbar\":01,\"amp\":1}]",
        "[{\"shape\":\"flat\",\"vbar\":1.,\"amp\":1}]",
        "[{\"shape\":\"flat\",\"vbar\":.5,\"amp\":1}]",
        "[{\"shape\":\"flat\",\"vbar\":NaN,\"amp\":1}]",
        "[{\"shape\":\"fl\\u0061t\",\"vbar\":0.5,\"amp\":1,\"x\":\"\\ud800\"}]",
        &format!("[{good}] x"),
        &format!("[{good}]\n\n"),
        "[{\"shape\":\"flat\",\"sh\\u0061pe\":\"flat\",\"vbar\":0.5,\"amp\":1}]",
        &format!("\u{feff}[{good}]"),
        "[{'a':1}]",
        "[1]",
        &format!("[{good}, [1, 2,]]"),
        &format!("[{}]", [good; 3].join(" , ")),
    ] {
        agrees(text).unwrap();
    }
}
