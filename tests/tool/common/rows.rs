//! The tests' oracle of the JSON row scanner (`fricosc_cli::scan`): rows of a
//! JSON array read by `serde_json` (each row's raw text borrowed from the
//! input, only the wanted fields picked out, duplicate keys refused), the way
//! the command line read them before it had its own one-pass scanner.
//! `batch_rows.rs` and the fuzz target `batch_json` compare the two.
#![allow(dead_code)]

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
            // The fields `batch` reads may not come twice; others may.
            if seen.contains(&key) && self.0.contains(&key.as_ref()) {
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
