//! Reading rows of JSON input without building value trees: each row stays as
//! its raw text (`serde_json::value::RawValue`, borrowed from the input), and
//! only the fields a command needs are picked out. Duplicate keys in a row are
//! refused (a row with two `vbar`s is ambiguous). Used by `batch` and `validate`.

use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, Visitor};
use serde_json::value::RawValue;
use std::borrow::Cow;
use std::fmt;

/// The raw values of the wanted fields of one JSON object, in the order asked.
pub struct Picked<'a>(pub Vec<Option<&'a RawValue>>);

/// Pick `names` out of one JSON object (raw text); the error is one line.
pub fn pick<'a>(row: &'a RawValue, names: &[&str]) -> Result<Picked<'a>, String> {
    let t = row.get();
    if !t.starts_with('{') {
        return Err("expected an object".into());
    }
    let mut de = serde_json::Deserializer::from_str(t);
    Pick(names).deserialize(&mut de).map_err(|e| {
        // serde_json appends " at line L column C" of the row: the row index says where.
        let m = e.to_string();
        m.split(" at line ").next().unwrap_or(&m).to_string()
    })
}

/// The array of raw rows of `text` (a JSON array), or why not.
pub fn raw_array(text: &str) -> Result<Vec<&RawValue>, String> {
    match text.trim_start().chars().next() {
        None => return Err("empty input (expected a JSON array)".into()),
        Some('[') => {}
        Some(_) => return Err("expected a JSON array of objects".into()),
    }
    serde_json::from_str(text).map_err(|e| format!("malformed JSON: {e}"))
}

/// A finite number from a raw JSON value ([`crate::cli::scan::number_of`]).
pub fn number(raw: &RawValue, name: &str) -> Result<f64, String> {
    crate::cli::scan::number_of(raw.get(), name)
}

/// A string from a raw JSON value, escapes resolved ([`crate::cli::scan::string_of`]).
pub fn string<'a>(raw: &'a RawValue, name: &str) -> Result<Cow<'a, str>, String> {
    crate::cli::scan::string_of(raw.get(), name)
}

struct Pick<'n>(&'n [&'n str]);

impl<'de> DeserializeSeed<'de> for Pick<'_> {
    type Value = Picked<'de>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for Pick<'_> {
    type Value = Picked<'de>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an object")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        let mut out = vec![None; self.0.len()];
        let mut seen: Vec<Cow<'de, str>> = Vec::with_capacity(8);
        while let Some(Key(key)) = map.next_key::<Key<'de>>()? {
            if seen.contains(&key) {
                return Err(de::Error::custom(format!("duplicate key '{key}'")));
            }
            let v: &'de RawValue = map.next_value()?;
            if let Some(i) = self.0.iter().position(|n| *n == key) {
                out[i] = Some(v);
            }
            seen.push(key);
        }
        Ok(Picked(out))
    }
}

/// A string that borrows from the input when it has no escapes.
struct Key<'a>(Cow<'a, str>);

impl<'de> serde::Deserialize<'de> for Key<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Key<'de>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a string")
            }
            fn visit_borrowed_str<E: de::Error>(self, s: &'de str) -> Result<Key<'de>, E> {
                Ok(Key(Cow::Borrowed(s)))
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<Key<'de>, E> {
                Ok(Key(Cow::Owned(s.to_owned())))
            }
        }
        d.deserialize_str(V)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn picks_fields_refuses_duplicates_and_keeps_raw_text() {
        let rows = raw_array(r#"[{"a": 1, "b": "x\"y", "c": [1, 2]}, {"a": 1, "a": 2}, 3]"#).unwrap();
        let p = pick(rows[0], &["c", "b", "z"]).unwrap();
        assert_eq!(p.0[0].unwrap().get(), "[1, 2]");
        assert_eq!(string(p.0[1].unwrap(), "b").unwrap(), "x\"y");
        assert!(p.0[2].is_none());
        assert_eq!(pick(rows[1], &["a"]).err().unwrap(), "duplicate key 'a'");
        assert_eq!(pick(rows[2], &["a"]).err().unwrap(), "expected an object");
        assert_eq!(number(p.0[0].unwrap(), "c").err().unwrap(), "'c' must be a number");
        assert!(raw_array("{}").is_err() && raw_array(" ").is_err() && raw_array("[1,").is_err());
    }
}
