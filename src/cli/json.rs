//! JSON read as raw values borrowed from the input (`serde_json`'s
//! `RawValue`): no value trees, so that a table of 10^7 rows is its text
//! plus a few words a row. Objects keep their members in order and refuse
//! duplicate keys; messages drop `serde_json`'s position within a value
//! (the caller names the row).

use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_json::value::RawValue;
use std::borrow::Cow;
use std::fmt;

/// A JSON string, borrowed from the input where it has no escapes.
pub struct Text<'a>(pub Cow<'a, str>);

impl<'de> serde::Deserialize<'de> for Text<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Text<'de>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a string")
            }
            fn visit_borrowed_str<E: de::Error>(self, s: &'de str) -> Result<Text<'de>, E> {
                Ok(Text(Cow::Borrowed(s)))
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<Text<'de>, E> {
                Ok(Text(Cow::Owned(s.to_owned())))
            }
        }
        d.deserialize_str(V)
    }
}

/// The seed of a finite number of the field named by it (`-0` is 0),
/// deserialized without its raw text; anything else is an error naming it.
pub struct NumberOf<'n>(pub &'n str);

impl<'de> DeserializeSeed<'de> for NumberOf<'_> {
    type Value = f64;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<f64, D::Error> {
        let name = self.0;
        // serde_json's own refusals, in the words of the others.
        d.deserialize_f64(self).map_err(|e| {
            let m = e.to_string();
            if m.starts_with("number out of range") {
                de::Error::custom(format!("'{name}' is not a finite number"))
            } else if m.starts_with("invalid type: null") {
                de::Error::custom(format!("'{name}' is null (pandas writes NaN and missing values as null)"))
            } else if m.starts_with("invalid type") {
                de::Error::custom(format!("'{name}' must be a number"))
            } else {
                e
            }
        })
    }
}

impl<'de> Visitor<'de> for NumberOf<'_> {
    type Value = f64;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "'{}' as a number", self.0)
    }
    fn visit_f64<E: de::Error>(self, x: f64) -> Result<f64, E> {
        if x.is_finite() {
            Ok(x + 0.0)
        } else {
            Err(E::custom(format!("'{}' is not a finite number", self.0)))
        }
    }
    fn visit_u64<E: de::Error>(self, x: u64) -> Result<f64, E> {
        Ok(x as f64)
    }
    fn visit_i64<E: de::Error>(self, x: i64) -> Result<f64, E> {
        Ok(x as f64 + 0.0)
    }
    fn visit_unit<E: de::Error>(self) -> Result<f64, E> {
        Err(E::custom(format!("'{}' is null (pandas writes NaN and missing values as null)", self.0)))
    }
    fn visit_str<E: de::Error>(self, _: &str) -> Result<f64, E> {
        Err(E::custom(format!("'{}' must be a number", self.0)))
    }
    fn visit_bool<E: de::Error>(self, _: bool) -> Result<f64, E> {
        self.visit_str("")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, _: A) -> Result<f64, A::Error> {
        self.visit_str("")
    }
    fn visit_map<A: MapAccess<'de>>(self, _: A) -> Result<f64, A::Error> {
        self.visit_str("")
    }
}

/// The seed of a string of the field named by it, borrowed where it has no
/// escapes; anything else is an error naming it.
pub struct StringOf<'n>(pub &'n str);

impl<'de> DeserializeSeed<'de> for StringOf<'_> {
    type Value = Cow<'de, str>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for StringOf<'_> {
    type Value = Cow<'de, str>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "'{}' as a string", self.0)
    }
    fn visit_borrowed_str<E: de::Error>(self, s: &'de str) -> Result<Self::Value, E> {
        Ok(Cow::Borrowed(s))
    }
    fn visit_str<E: de::Error>(self, s: &str) -> Result<Self::Value, E> {
        Ok(Cow::Owned(s.to_owned()))
    }
    fn visit_f64<E: de::Error>(self, _: f64) -> Result<Self::Value, E> {
        Err(E::custom(format!("'{}' must be a string", self.0)))
    }
    fn visit_u64<E: de::Error>(self, _: u64) -> Result<Self::Value, E> {
        self.visit_f64(0.0)
    }
    fn visit_i64<E: de::Error>(self, _: i64) -> Result<Self::Value, E> {
        self.visit_f64(0.0)
    }
    fn visit_unit<E: de::Error>(self) -> Result<Self::Value, E> {
        self.visit_f64(0.0)
    }
    fn visit_bool<E: de::Error>(self, _: bool) -> Result<Self::Value, E> {
        self.visit_f64(0.0)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, _: A) -> Result<Self::Value, A::Error> {
        self.visit_f64(0.0)
    }
    fn visit_map<A: MapAccess<'de>>(self, _: A) -> Result<Self::Value, A::Error> {
        self.visit_f64(0.0)
    }
}

/// An object's members in order: each key and its raw value.
pub type Members<'a> = Vec<(Cow<'a, str>, &'a RawValue)>;

struct MembersOf<'a>(Members<'a>);

impl<'de> serde::Deserialize<'de> for MembersOf<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = MembersOf<'de>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("an object")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<MembersOf<'de>, A::Error> {
                let mut out: Members<'de> = Vec::new();
                while let Some(Text(key)) = map.next_key::<Text<'de>>()? {
                    if out.iter().any(|(k, _)| *k == key) {
                        return Err(de::Error::custom(format!("duplicate key '{key}'")));
                    }
                    out.push((key, map.next_value()?));
                }
                Ok(MembersOf(out))
            }
        }
        d.deserialize_map(V)
    }
}

/// `serde_json`'s message without its position (`... at line 1 column 9`),
/// prefixed `malformed JSON: ` where the text is not JSON.
pub fn message(e: &serde_json::Error) -> String {
    let m = e.to_string();
    let m = m.split(" at line ").next().unwrap_or(&m);
    if e.is_syntax() || e.is_eof() {
        format!("malformed JSON: {m}")
    } else {
        m.to_string()
    }
}

/// The members of the object `text`.
pub fn members(text: &str) -> Result<Members<'_>, String> {
    serde_json::from_str::<MembersOf>(text).map(|m| m.0).map_err(|e| message(&e))
}

/// The elements of the array `text`.
pub fn elements(text: &str) -> Result<Vec<&RawValue>, String> {
    serde_json::from_str::<Vec<&RawValue>>(text).map_err(|e| message(&e))
}

/// The value `text` (any JSON value, nothing but whitespace around it).
pub fn value(text: &str) -> Result<&RawValue, serde_json::Error> {
    serde_json::from_str(text)
}

/// A string from a raw JSON value (escapes resolved; borrowed where it has none).
pub fn string<'a>(raw: &'a RawValue, name: &str) -> Result<Cow<'a, str>, String> {
    serde_json::from_str::<Text>(raw.get()).map(|t| t.0).map_err(|_| format!("'{name}' must be a string"))
}

/// A finite number from a raw JSON value (`-0` is 0).
pub fn number(raw: &RawValue, name: &str) -> Result<f64, String> {
    let t = raw.get();
    if t == "null" {
        return Err(format!("'{name}' is null (pandas writes NaN and missing values as null)"));
    }
    if !t.starts_with(|c: char| c == '-' || c.is_ascii_digit()) {
        return Err(format!("'{name}' must be a number"));
    }
    match t.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x + 0.0),
        _ => Err(format!("'{name}' is not a finite number")),
    }
}

/// A computed value as text: a number, `nan` or `inf` (any case, signed,
/// as numpy and Rust print them): a value that is not finite is kept.
pub fn computed(text: &str) -> Result<f64, String> {
    let t = text.trim();
    t.parse::<f64>().map(|x| x + 0.0).map_err(|_| format!("'{t}' is not a number"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn members_keep_order_and_refuse_duplicates() {
        let m = members(r#"{"b":[1, 2], "a\u0062":"x", "c":{"d":null}}"#).unwrap();
        let keys: Vec<&str> = m.iter().map(|(k, _)| k.as_ref()).collect();
        assert_eq!(keys, ["b", "ab", "c"]);
        assert_eq!(m[0].1.get(), "[1, 2]");
        assert_eq!(members(r#"{"a":1,"\u0061":2}"#).unwrap_err(), "duplicate key 'a'");
        assert!(members(r#"{"a":1,}"#).unwrap_err().starts_with("malformed JSON: trailing comma"));
        assert_eq!(
            elements("[1, \"x\" ,{}]").unwrap().iter().map(|v| v.get()).collect::<Vec<_>>(),
            ["1", "\"x\"", "{}"]
        );
    }

    #[test]
    fn strings_and_numbers() {
        let v = |t: &'static str| value(t).unwrap();
        assert_eq!(string(v("\"fl\\u0061t\""), "shape").unwrap(), "flat");
        assert!(matches!(string(v("\"flat\""), "shape").unwrap(), Cow::Borrowed("flat")));
        assert_eq!(string(v("1"), "shape").unwrap_err(), "'shape' must be a string");
        assert_eq!(number(v("-0"), "x").map(f64::to_bits), Ok(0));
        assert_eq!(number(v("1e999"), "x").unwrap_err(), "'x' is not a finite number");
        assert_eq!(number(v("\"1\""), "x").unwrap_err(), "'x' must be a number");
        assert!(number(v("null"), "x").unwrap_err().contains("null"));
    }
}
