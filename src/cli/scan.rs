//! A strict JSON scanner for rows of flat objects, in one pass over the bytes:
//! each row stays as its raw text, and only the wanted fields' raw values are
//! picked out. It accepts exactly the JSON that `serde_json` accepts when it
//! reads an array of raw values (RFC 8259: no comments, no trailing commas,
//! no `NaN`; escapes checked), which a differential test checks
//! (`tests/scan.rs`), except that nesting within a row deeper than 128 levels
//! is refused (the scanner recurses; `serde_json` skips raw values with an
//! explicit stack).
//! Object keys are decoded (with `serde_json`, only when they hold escapes) and
//! duplicate keys are refused.
//!
//! Why not `serde_json`'s raw values: those scan each row twice (once to
//! capture it, once to pick its fields), about 3,500 instructions of a batch
//! row of 7,600; this scanner reads the row once.

use std::borrow::Cow;

/// Nesting deeper than this is refused (as `serde_json` does).
pub const MAX_DEPTH: usize = 128;

/// Where scanning stopped, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ScanError {
    /// Byte offset of the problem.
    pub at: usize,
    /// What is wrong (one line).
    pub what: String,
    /// Malformed JSON (else well-formed but refused: a duplicate key).
    pub malformed: bool,
}

impl ScanError {
    fn new(at: usize, what: &str) -> ScanError {
        ScanError { at, what: what.into(), malformed: true }
    }

    /// The message for a reader: malformed JSON with its line and column in
    /// `text`, else the reason alone.
    pub fn describe(&self, text: &str) -> String {
        if self.malformed {
            format!("malformed JSON: {}", self.located(text))
        } else {
            self.what.clone()
        }
    }

    /// The message with the 1-based line and column of `at` in `text`.
    pub fn located(&self, text: &str) -> String {
        let at = self.at.min(text.len());
        let before = &text.as_bytes()[..at];
        let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
        let col = at - before.iter().rposition(|&b| b == b'\n').map_or(0, |p| p + 1) + 1;
        format!("{} at line {line} column {col}", self.what)
    }
}

type Scan<T> = Result<T, ScanError>;

/// One row: its raw text and the raw values of the wanted fields (in the order asked).
#[derive(Debug, Clone, Copy)]
pub struct Row<'a, const N: usize> {
    /// The row's text, from `{` to `}`.
    pub raw: &'a str,
    /// The wanted fields' raw values (`None` where absent).
    pub fields: [Option<&'a str>; N],
}

fn ws(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && matches!(b[i], b' ' | b'\t' | b'\n' | b'\r') {
        i += 1;
    }
    i
}

/// The end of the string starting at `b[i] == '"'`, and whether it has escapes.
fn string(b: &[u8], mut i: usize) -> Scan<(usize, bool)> {
    let start = i;
    i += 1;
    let mut escaped = false;
    loop {
        // The plain run: everything but a quote, a backslash or a control character.
        i += b[i..].iter().position(|&c| c == b'"' || c == b'\\' || c < 0x20).unwrap_or(b.len() - i);
        match b.get(i) {
            None => return Err(ScanError::new(start, "EOF while parsing a string")),
            Some(b'"') => return Ok((i + 1, escaped)),
            Some(b'\\') => {
                escaped = true;
                match b.get(i + 1) {
                    Some(b'"' | b'\\' | b'/' | b'b' | b'f' | b'n' | b'r' | b't') => i += 2,
                    Some(b'u') => {
                        if b.len() < i + 6 {
                            return Err(ScanError::new(i, "EOF while parsing a string"));
                        }
                        if !b[i + 2..i + 6].iter().all(u8::is_ascii_hexdigit) {
                            return Err(ScanError::new(i, "invalid escape"));
                        }
                        i += 6;
                    }
                    None => return Err(ScanError::new(i, "EOF while parsing a string")),
                    Some(_) => return Err(ScanError::new(i, "invalid escape")),
                }
            }
            Some(_) => {
                return Err(ScanError::new(i, "control character (\\u0000-\\u001F) found while parsing a string"))
            }
        }
    }
}

fn digits(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    i
}

/// The end of the number starting at `i` (JSON's grammar).
fn number(b: &[u8], mut i: usize) -> Scan<usize> {
    let start = i;
    if b.get(i) == Some(&b'-') {
        i += 1;
    }
    match b.get(i) {
        Some(b'0') => {
            i += 1;
            if b.get(i).is_some_and(u8::is_ascii_digit) {
                return Err(ScanError::new(start, "invalid number"));
            }
        }
        Some(b'1'..=b'9') => i = digits(b, i),
        _ => return Err(ScanError::new(start, "invalid number")),
    }
    if b.get(i) == Some(&b'.') {
        let j = digits(b, i + 1);
        if j == i + 1 {
            return Err(ScanError::new(i, "invalid number"));
        }
        i = j;
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        i += 1;
        if matches!(b.get(i), Some(b'+' | b'-')) {
            i += 1;
        }
        let j = digits(b, i);
        if j == i {
            return Err(ScanError::new(i, "invalid number"));
        }
        i = j;
    }
    Ok(i)
}

/// The end of the value starting at `i` (after whitespace).
fn value(b: &[u8], i: usize, depth: usize) -> Scan<usize> {
    match b.get(i) {
        None => Err(ScanError::new(i, "EOF while parsing a value")),
        Some(b'"') => string(b, i).map(|(e, _)| e),
        Some(b'{') => object(b, i, depth + 1, &mut |_, _, _| Ok(())),
        Some(b'[') => array(b, i, depth + 1),
        Some(b'-' | b'0'..=b'9') => number(b, i),
        Some(b't') => literal(b, i, b"true"),
        Some(b'f') => literal(b, i, b"false"),
        Some(b'n') => literal(b, i, b"null"),
        Some(_) => Err(ScanError::new(i, "expected value")),
    }
}

fn literal(b: &[u8], i: usize, word: &[u8]) -> Scan<usize> {
    if b.len() >= i + word.len() && &b[i..i + word.len()] == word {
        Ok(i + word.len())
    } else {
        Err(ScanError::new(i, "expected value"))
    }
}

fn array(b: &[u8], i: usize, depth: usize) -> Scan<usize> {
    if depth > MAX_DEPTH {
        return Err(ScanError::new(i, "recursion limit exceeded"));
    }
    let mut j = ws(b, i + 1);
    if b.get(j) == Some(&b']') {
        return Ok(j + 1);
    }
    loop {
        j = ws(b, value(b, j, depth)?);
        match b.get(j) {
            Some(b',') => j = ws(b, j + 1),
            Some(b']') => return Ok(j + 1),
            None => return Err(ScanError::new(j, "EOF while parsing a list")),
            Some(_) => return Err(ScanError::new(j, "expected `,` or `]`")),
        }
    }
}

/// Scan the object starting at `b[i] == '{'`, calling `field(key, key_has_escapes,
/// value_start..value_end)` for each member; returns the end.
fn object<'b>(
    b: &'b [u8],
    i: usize,
    depth: usize,
    field: &mut dyn FnMut(&'b [u8], bool, (usize, usize)) -> Scan<()>,
) -> Scan<usize> {
    if depth > MAX_DEPTH {
        return Err(ScanError::new(i, "recursion limit exceeded"));
    }
    let mut j = ws(b, i + 1);
    if b.get(j) == Some(&b'}') {
        return Ok(j + 1);
    }
    loop {
        match b.get(j) {
            Some(b'"') => {}
            None => return Err(ScanError::new(j, "EOF while parsing an object")),
            Some(_) => return Err(ScanError::new(j, "key must be a string")),
        }
        let (kend, escaped) = string(b, j)?;
        let key = &b[j + 1..kend - 1];
        j = ws(b, kend);
        match b.get(j) {
            Some(b':') => {}
            None => return Err(ScanError::new(j, "EOF while parsing an object")),
            Some(_) => return Err(ScanError::new(j, "expected `:`")),
        }
        let vstart = ws(b, j + 1);
        let vend = value(b, vstart, depth)?;
        field(key, escaped, (vstart, vend))?;
        j = ws(b, vend);
        match b.get(j) {
            Some(b',') => j = ws(b, j + 1),
            Some(b'}') => return Ok(j + 1),
            None => return Err(ScanError::new(j, "EOF while parsing an object")),
            Some(_) => return Err(ScanError::new(j, "expected `,` or `}`")),
        }
    }
}

/// A key's text: borrowed, or decoded where it has escapes.
fn key_text<'a>(text: &'a str, raw: &'a [u8], escaped: bool, at: usize) -> Scan<Cow<'a, str>> {
    // `raw` lies inside `text` between quotes, on character boundaries (quotes are ASCII).
    let start = raw.as_ptr() as usize - text.as_ptr() as usize;
    let s = &text[start..start + raw.len()];
    if !escaped {
        return Ok(Cow::Borrowed(s));
    }
    serde_json::from_str::<String>(&text[start - 1..start + raw.len() + 1]).map(Cow::Owned).map_err(|e| {
        let m = e.to_string();
        ScanError::new(at, m.split(" at line ").next().unwrap_or(&m))
    })
}

/// Scan the object at `text[i..]` (after whitespace): the row and its wanted
/// fields (duplicate keys refused), and the end offset.
pub fn row<'a, const N: usize>(text: &'a str, i: usize, names: &[&str; N]) -> Scan<(Row<'a, N>, usize)> {
    let b = text.as_bytes();
    if b.get(i) != Some(&b'{') {
        return Err(ScanError::new(i, "expected an object"));
    }
    let mut fields = [None; N];
    // The fast path compares raw keys (a row has a handful); a key with escapes
    // sends the row to the slow path, which compares decoded keys.
    let mut seen: Vec<&[u8]> = Vec::with_capacity(8);
    let mut escapes = false;
    let end = object(b, i, 1, &mut |key, escaped, (vs, ve)| {
        if escaped {
            escapes = true;
        } else if !escapes {
            if seen.contains(&key) {
                let at = key.as_ptr() as usize - b.as_ptr() as usize;
                let k = String::from_utf8_lossy(key);
                return Err(ScanError { at, what: format!("duplicate key '{k}'"), malformed: false });
            }
            seen.push(key);
            if let Some(p) = names.iter().position(|n| n.as_bytes() == key) {
                fields[p] = Some(&text[vs..ve]);
            }
        }
        Ok(())
    })?;
    if escapes {
        fields = decoded_fields(text, i, names)?;
    }
    Ok((Row { raw: &text[i..end], fields }, end))
}

/// The wanted fields of a well-formed object whose keys have escapes: keys
/// compared decoded.
fn decoded_fields<'a, const N: usize>(text: &'a str, i: usize, names: &[&str; N]) -> Scan<[Option<&'a str>; N]> {
    let b = text.as_bytes();
    let mut fields = [None; N];
    let mut seen: Vec<Cow<'a, str>> = Vec::with_capacity(8);
    object(b, i, 1, &mut |key, escaped, (vs, ve)| {
        let at = key.as_ptr() as usize - b.as_ptr() as usize;
        let k = key_text(text, key, escaped, at)?;
        if seen.contains(&k) {
            return Err(ScanError { at, what: format!("duplicate key '{k}'"), malformed: false });
        }
        if let Some(p) = names.iter().position(|n| *n == k) {
            fields[p] = Some(&text[vs..ve]);
        }
        seen.push(k);
        Ok(())
    })?;
    Ok(fields)
}

/// Why a JSON array of rows was refused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum RowsError {
    /// Malformed JSON (`row`: the row at fault, where inside one).
    Syntax {
        /// The row at fault.
        row: Option<usize>,
        /// Where and why.
        error: ScanError,
    },
    /// A well-formed row that `each` refused.
    Row {
        /// The row.
        row: usize,
        /// Why.
        reason: String,
    },
}

/// Call `each(k, row)` for every row of a JSON array of objects, in order;
/// returns the number of rows. (Serial; `batch` scans the rows of
/// [`row_starts`] in parallel, with the same result.)
pub fn array_rows<'a, const N: usize>(
    text: &'a str,
    names: &[&str; N],
    mut each: impl FnMut(usize, Row<'a, N>) -> Result<(), String>,
) -> Result<usize, RowsError> {
    let (starts, tail) = row_starts(text);
    for (k, &i) in starts.iter().enumerate() {
        let (r, _) = row(text, i, names).map_err(|error| RowsError::Syntax { row: Some(k), error })?;
        each(k, r).map_err(|reason| RowsError::Row { row: k, reason })?;
    }
    match tail_error(text, tail) {
        Some(e) => Err(e),
        None => Ok(starts.len()),
    }
}

/// What ends the top level of a JSON array after its rows' starts were found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Tail {
    /// The array closed properly.
    Closed,
    /// A malformed top level at this offset.
    Syntax(ScanError),
    /// An element that is not an object starts here (row index, offset).
    NotAnObject(usize, usize),
}

/// The end of the object starting at `b[i] == '{'`, found leniently: strings
/// and nesting are tracked, nothing else is checked. On well-formed JSON it is
/// the object's true end; `None` at the end of the input.
fn lenient_end(b: &[u8], mut i: usize) -> Option<usize> {
    let mut depth = 0usize;
    while i < b.len() {
        match b[i] {
            b'"' => {
                i += 1;
                loop {
                    i += b.get(i..)?.iter().position(|&c| c == b'"' || c == b'\\')?;
                    if b[i] == b'"' {
                        break;
                    }
                    i += 2;
                }
            }
            b'{' | b'[' => depth += 1,
            b'}' | b']' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i + 1);
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// The starts of the rows of a JSON array, found in one cheap pass that does
/// not check the rows themselves (each is then scanned with [`row`], in
/// parallel), and how the top level ends. Errors of the top level are reported
/// only after every row before them has been checked, as a serial scan would.
pub fn row_starts(text: &str) -> (Vec<usize>, Tail) {
    let b = text.as_bytes();
    let mut starts = vec![];
    let mut i = ws(b, 0);
    let syntax = |at: usize, what: &str| Tail::Syntax(ScanError::new(at, what));
    match b.get(i) {
        None => return (starts, syntax(i, "empty input (expected a JSON array)")),
        Some(b'[') => {}
        Some(_) => return (starts, syntax(i, "expected a JSON array of objects")),
    }
    i = ws(b, i + 1);
    if b.get(i) == Some(&b']') {
        i += 1;
    } else {
        loop {
            if b.get(i) != Some(&b'{') {
                return (starts.clone(), Tail::NotAnObject(starts.len(), i));
            }
            starts.push(i);
            let Some(end) = lenient_end(b, i) else {
                return (starts, syntax(b.len(), "EOF while parsing a list"));
            };
            i = ws(b, end);
            match b.get(i) {
                Some(b',') => i = ws(b, i + 1),
                Some(b']') => {
                    i += 1;
                    break;
                }
                None => return (starts, syntax(i, "EOF while parsing a list")),
                Some(_) => return (starts, syntax(i, "expected `,` or `]`")),
            }
        }
    }
    let end = ws(b, i);
    if end < b.len() {
        return (starts, syntax(end, "trailing characters"));
    }
    (starts, Tail::Closed)
}

/// The error a [`Tail`] stands for, once every row before it was found good.
pub fn tail_error(text: &str, tail: Tail) -> Option<RowsError> {
    match tail {
        Tail::Closed => None,
        Tail::Syntax(error) => Some(RowsError::Syntax { row: None, error }),
        Tail::NotAnObject(row, at) => Some(match value(text.as_bytes(), at, 1) {
            Err(error) => RowsError::Syntax { row: None, error },
            Ok(_) => RowsError::Row { row, reason: "expected an object".into() },
        }),
    }
}

/// The one object of a line of JSON Lines (whitespace around it allowed).
pub fn line_row<'a, const N: usize>(line: &'a str, names: &[&str; N]) -> Scan<Row<'a, N>> {
    let b = line.as_bytes();
    let i = ws(b, 0);
    if b.get(i) != Some(&b'{') {
        value(b, i, 1)?;
        return Err(ScanError::new(i, "expected an object"));
    }
    let (r, end) = row(line, i, names)?;
    let end = ws(b, end);
    if end < b.len() {
        return Err(ScanError::new(end, "trailing characters"));
    }
    Ok(r)
}

/// The offset of the first non-whitespace byte at or after `i`.
pub fn skip_ws(text: &str, i: usize) -> usize {
    ws(text.as_bytes(), i)
}

/// The end of the JSON value starting at `text[i..]` (after whitespace).
pub fn value_end(text: &str, i: usize) -> Scan<usize> {
    value(text.as_bytes(), ws(text.as_bytes(), i), 0)
}

/// Call `each(key, value_start..value_end)` for every member of the object at
/// `text[i..]` (`{` there), in order, keys decoded; returns the object's end.
pub fn each_member<'a>(
    text: &'a str,
    i: usize,
    each: &mut dyn FnMut(Cow<'a, str>, (usize, usize)) -> Scan<()>,
) -> Scan<usize> {
    let b = text.as_bytes();
    if b.get(i) != Some(&b'{') {
        return Err(ScanError::new(i, "expected an object"));
    }
    object(b, i, 1, &mut |key, escaped, span| {
        let at = key.as_ptr() as usize - b.as_ptr() as usize;
        each(key_text(text, key, escaped, at)?, span)
    })
}

/// An object's member: its key (decoded) and its value's span.
pub type Member<'a> = (Cow<'a, str>, (usize, usize));

/// The members of the object at `text[i..]`, in order (duplicate keys refused).
pub fn members(text: &str, i: usize) -> Scan<Vec<Member<'_>>> {
    let mut out: Vec<Member> = vec![];
    each_member(text, i, &mut |k, span| {
        if out.iter().any(|(x, _)| *x == k) {
            return Err(ScanError { at: span.0, what: format!("duplicate key '{k}'"), malformed: false });
        }
        out.push((k, span));
        Ok(())
    })?;
    Ok(out)
}

/// Call `each(value_start..value_end)` for every element of the array at
/// `text[i..]` (`[` there), in order; returns the array's end.
pub fn each_element(text: &str, i: usize, each: &mut dyn FnMut((usize, usize)) -> Scan<()>) -> Scan<usize> {
    let b = text.as_bytes();
    if b.get(i) != Some(&b'[') {
        return Err(ScanError::new(i, "expected an array"));
    }
    let mut j = ws(b, i + 1);
    if b.get(j) == Some(&b']') {
        return Ok(j + 1);
    }
    loop {
        let end = value(b, j, 1)?;
        each((j, end))?;
        j = ws(b, end);
        match b.get(j) {
            Some(b',') => j = ws(b, j + 1),
            Some(b']') => return Ok(j + 1),
            None => return Err(ScanError::new(j, "EOF while parsing a list")),
            Some(_) => return Err(ScanError::new(j, "expected `,` or `]`")),
        }
    }
}

/// A finite number from a raw JSON value.
pub fn number_of(raw: &str, name: &str) -> Result<f64, String> {
    if raw == "null" {
        return Err(format!("'{name}' is null (pandas writes NaN and missing values as null)"));
    }
    if !raw.starts_with(|c: char| c == '-' || c.is_ascii_digit()) {
        return Err(format!("'{name}' must be a number"));
    }
    match raw.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x + 0.0),
        _ => Err(format!("'{name}' is not a finite number")),
    }
}

/// A string from a raw JSON value (escapes resolved; borrowed where it has none).
pub fn string_of<'a>(raw: &'a str, name: &str) -> Result<Cow<'a, str>, String> {
    if !raw.starts_with('"') {
        return Err(format!("'{name}' must be a string"));
    }
    let inner = &raw[1..raw.len() - 1];
    if !inner.contains('\\') {
        return Ok(Cow::Borrowed(inner));
    }
    serde_json::from_str::<String>(raw).map(Cow::Owned).map_err(|e| {
        let m = e.to_string();
        format!("'{name}': {}", m.split(" at line ").next().unwrap_or(&m))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows<'a>(t: &'a str, names: &[&str; 4]) -> Result<Vec<Row<'a, 4>>, RowsError> {
        let mut v = vec![];
        array_rows(t, names, |_, r| {
            v.push(r);
            Ok(())
        })?;
        Ok(v)
    }

    fn what(e: RowsError) -> (Option<usize>, String) {
        match e {
            RowsError::Syntax { row, error } => (row, error.what),
            RowsError::Row { row, reason } => (Some(row), reason),
        }
    }

    #[test]
    fn rows_fields_and_errors() {
        let t = r#" [ {"a": 1, "b": "x\"y", "c": [1, {"d": null}]} ,{"a":-0.5e-3}] "#;
        let names = ["c", "b", "z", "a"];
        let r = rows(t, &names).unwrap();
        assert_eq!(r[0].fields[0], Some(r#"[1, {"d": null}]"#));
        assert_eq!(string_of(r[0].fields[1].unwrap(), "b").unwrap(), "x\"y");
        assert_eq!(r[0].fields[2], None);
        assert_eq!(r[1].raw, r#"{"a":-0.5e-3}"#);
        assert_eq!(number_of(r[1].fields[3].unwrap(), "a").unwrap(), -0.5e-3);
        let err = |t: &str| what(rows(t, &names).unwrap_err());
        assert_eq!(err(r#"[{"a":1,"a":2}]"#), (Some(0), "duplicate key 'a'".into()));
        // Keys compare decoded: "\u0061" is "a".
        assert_eq!(err(r#"[{"a":1,"\u0061":2}]"#), (Some(0), "duplicate key 'a'".into()));
        assert_eq!(err(r#"[{"a":1}, 3]"#), (Some(1), "expected an object".into()));
        assert_eq!(err(r#"[{"a":01}]"#).1, "invalid number");
        assert_eq!(err(r#"[{"a":1,}]"#).1, "key must be a string");
        match rows("[{\"a\":1}", &names).unwrap_err() {
            RowsError::Syntax { error, .. } => {
                assert_eq!(error.located("[{\"a\":1}"), "EOF while parsing a list at line 1 column 9")
            }
            e => panic!("{e:?}"),
        }
        assert_eq!(err("[] x").1, "trailing characters");
        assert_eq!(err("").1, "empty input (expected a JSON array)");
        assert!(rows("[]", &names).unwrap().is_empty());
        let deep = format!("[{{\"a\":{}{}}}]", "[".repeat(200), "]".repeat(200));
        assert_eq!(err(&deep).1, "recursion limit exceeded");
        // JSON Lines: one object, whitespace around it.
        assert_eq!(line_row(" {\"a\": 2} \r", &names).unwrap().fields[3], Some("2"));
        assert_eq!(line_row("{} {}", &names).unwrap_err().what, "trailing characters");
        assert_eq!(line_row("[1]", &names).unwrap_err().what, "expected an object");
    }
}
