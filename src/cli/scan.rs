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
//!
//! A plain row (keys and strings without escapes, scalar values, no duplicate
//! key, at most eight keys besides the wanted ones) takes a quick path: one
//! loop, strings eight bytes at a time, keys compared with the wanted names'
//! first eight bytes as one word ([`Keys`]). Anything else, faults included,
//! goes to the general scan, which decides and words the error: the quick
//! path is only a faster way to the same result (a unit test compares the
//! two). It reads the plain row's numbers on its way ([`Row::numbers`]): a
//! random flat batch row's scan and numbers take ~1,100 instructions where
//! the general scan and `str::parse` took ~1,620 (measured). An array's
//! reader first tries each row with the last row's layout (`Layout`: the
//! bytes between its values, compared a word at a time; the random flat row
//! read in ~940 instructions where the quick path took ~1,110, measured), and
//! only then the quick path.

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
    /// The wanted fields' values where the scan read them as numbers on its
    /// way ([`crate::float`]'s fast path: `str::parse`'s value), NaN
    /// elsewhere (absent, not a number, or a number to read from its raw text).
    pub numbers: [f64; N],
}

impl<const N: usize> Row<'_, N> {
    /// The wanted field `k` as a finite number: as read by the scan, else
    /// from its raw text ([`number_of`], whose messages name `name`); `None`
    /// where absent.
    pub fn number(&self, k: usize, name: &str) -> Result<Option<f64>, String> {
        self.fields[k].map(|raw| self.number_in(k, raw, name)).transpose()
    }

    /// The wanted field `k`, present with the raw value `raw`, as a finite number.
    pub fn number_in(&self, k: usize, raw: &str, name: &str) -> Result<f64, String> {
        let x = self.numbers[k];
        if x.is_nan() {
            number_of(raw, name)
        } else {
            Ok(x + 0.0)
        }
    }
}

fn ws(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && matches!(b[i], b' ' | b'\t' | b'\n' | b'\r') {
        i += 1;
    }
    i
}

/// The bytes that end a string's plain run: a quote, a backslash, a control character.
static STRING_STOP: [bool; 256] = {
    let mut t = [false; 256];
    let mut c = 0;
    while c < 0x20 {
        t[c] = true;
        c += 1;
    }
    t[b'"' as usize] = true;
    t[b'\\' as usize] = true;
    t
};

/// The end of the string starting at `b[i] == '"'`, and whether it has escapes.
fn string(b: &[u8], mut i: usize) -> Scan<(usize, bool)> {
    let start = i;
    i += 1;
    let mut escaped = false;
    loop {
        // The plain run: everything but a quote, a backslash or a control character.
        while i < b.len() && !STRING_STOP[b[i] as usize] {
            i += 1;
        }
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

/// The end of the run of ASCII digits at `i`: eight bytes at a time while all
/// eight are digits (a number's mantissa has up to 17), then byte by byte.
fn digits(b: &[u8], mut i: usize) -> usize {
    while let Some(w) = b.get(i..i + 8) {
        let x = u64::from_le_bytes([w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]]);
        if !crate::float::all_digits(x) {
            break;
        }
        i += 8;
    }
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
    field: &mut impl FnMut(&'b [u8], bool, (usize, usize)) -> Scan<()>,
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

/// The names a row is read for, each with its first eight bytes as one
/// little-endian word (zero-padded), which the quick path compares a key with.
#[derive(Debug, Clone, Copy)]
pub struct Keys<'n, const N: usize> {
    names: &'n [&'n str; N],
    heads: [u64; N],
}

impl<'n, const N: usize> Keys<'n, N> {
    /// The keys `names` (a `const` where the names are).
    pub const fn new(names: &'n [&'n str; N]) -> Self {
        let mut heads = [0u64; N];
        let mut p = 0;
        while p < N {
            let b = names[p].as_bytes();
            let mut k = 0;
            while k < b.len() && k < 8 {
                heads[p] |= (b[k] as u64) << (8 * k);
                k += 1;
            }
            p += 1;
        }
        Keys { names, heads }
    }

    /// The place of the key `b[start..start + len]` (no escapes) among the names.
    #[inline]
    fn find(&self, b: &[u8], start: usize, len: usize) -> Option<usize> {
        let head = match b.get(start..start + 8) {
            Some(w) => {
                let x = u64::from_le_bytes([w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]]);
                if len >= 8 {
                    x
                } else {
                    x & ((1u64 << (8 * len)) - 1)
                }
            }
            None => b[start..start + len.min(8)].iter().rev().fold(0, |h, &c| (h << 8) | c as u64),
        };
        let key = &b[start..start + len];
        (0..N).find(|&p| {
            self.heads[p] == head
                && self.names[p].len() == len
                && (len <= 8 || self.names[p].as_bytes()[8..] == key[8..])
        })
    }
}

/// Bytes of `x` (eight, little-endian) equal to `c`: the high bit of each set
/// (and possibly of bytes above the first such: only the lowest is exact).
#[inline]
fn bytes_equal(x: u64, c: u8) -> u64 {
    const ONES: u64 = 0x0101_0101_0101_0101;
    let y = x ^ (ONES * c as u64);
    y.wrapping_sub(ONES) & !y & (ONES << 7)
}

/// The offset of the closing quote of a string whose text starts at `i`, if
/// the string has no escapes and no control characters (else `None`): eight
/// bytes at a time, the lowest byte that is a quote, a backslash or below
/// `0x20` ends the run.
#[inline]
fn plain_string_end(b: &[u8], mut i: usize) -> Option<usize> {
    const ONES: u64 = 0x0101_0101_0101_0101;
    while let Some(w) = b.get(i..i + 8) {
        let x = u64::from_le_bytes([w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]]);
        // Bytes below 0x20 (bytes >= 0x80 have their high bit set in x, not in !x).
        let control = x.wrapping_sub(ONES * 0x20) & !x & (ONES << 7);
        let stop = bytes_equal(x, b'"') | bytes_equal(x, b'\\') | control;
        if stop != 0 {
            let k = i + (stop.trailing_zeros() / 8) as usize;
            return (b[k] == b'"').then_some(k);
        }
        i += 8;
    }
    while i < b.len() && !STRING_STOP[b[i] as usize] {
        i += 1;
    }
    (b.get(i) == Some(&b'"')).then_some(i)
}

/// Whitespace skipped from `i`, the common case (none) first.
#[inline]
fn skip(b: &[u8], i: usize) -> usize {
    match b.get(i) {
        Some(&c) if c > b' ' => i,
        _ => ws(b, i),
    }
}

/// The row at `b[i] == '{'` when it is plain: keys and string values without
/// escapes, scalar values only, no duplicate key, at most eight keys besides
/// the wanted ones. `None` otherwise, for [`row`]'s general scan to accept or
/// refuse (with its message): this path is only ever a faster way to the
/// same result.
#[inline]
fn quick_row<'a, const N: usize>(text: &'a str, i: usize, keys: &Keys<N>) -> Option<(Row<'a, N>, usize)> {
    let b = text.as_bytes();
    let mut fields: [Option<&'a str>; N] = [None; N];
    let mut numbers = [f64::NAN; N];
    const OTHERS: usize = 8;
    let mut others: [&[u8]; OTHERS] = [&[]; OTHERS];
    let mut n_others = 0;
    let mut j = skip(b, i + 1);
    if b.get(j) == Some(&b'}') {
        return Some((Row { raw: &text[i..j + 1], fields, numbers }, j + 1));
    }
    loop {
        if b.get(j) != Some(&b'"') {
            return None;
        }
        let kend = plain_string_end(b, j + 1)?;
        let (kstart, klen) = (j + 1, kend - j - 1);
        j = skip(b, kend + 1);
        if b.get(j) != Some(&b':') {
            return None;
        }
        let vs = skip(b, j + 1);
        let mut x = f64::NAN;
        let ve = match b.get(vs)? {
            b'"' => plain_string_end(b, vs + 1)? + 1,
            b'-' | b'0'..=b'9' => {
                let end;
                (end, x) = crate::float::json_number(b, vs)?;
                end
            }
            b't' => literal(b, vs, b"true").ok()?,
            b'f' => literal(b, vs, b"false").ok()?,
            b'n' => literal(b, vs, b"null").ok()?,
            _ => return None,
        };
        match keys.find(b, kstart, klen) {
            Some(p) => {
                if fields[p].replace(&text[vs..ve]).is_some() {
                    return None;
                }
                numbers[p] = x;
            }
            None => {
                let key = &b[kstart..kend];
                if n_others == OTHERS || others[..n_others].contains(&key) {
                    return None;
                }
                others[n_others] = key;
                n_others += 1;
            }
        }
        j = skip(b, ve);
        match b.get(j)? {
            b',' => j = skip(b, j + 1),
            b'}' => return Some((Row { raw: &text[i..j + 1], fields, numbers }, j + 1)),
            _ => return None,
        }
    }
}

/// Most values a [`Layout`] holds.
const LAYOUT_VALUES: usize = 8;

/// The bytes between two values of a row (or before the first, or after the
/// last), with their first 32 bytes as four little-endian words for a
/// comparison a word at a time.
#[derive(Debug, Clone, Copy)]
struct Piece<'a> {
    bytes: &'a [u8],
    words: [u64; 4],
    masks: [u64; 4],
}

impl<'a> Piece<'a> {
    fn new(bytes: &'a [u8]) -> Self {
        let (mut words, mut masks) = ([0u64; 4], [0u64; 4]);
        for (k, &c) in bytes.iter().take(32).enumerate() {
            words[k / 8] |= (c as u64) << (8 * (k % 8));
            masks[k / 8] |= 0xFF << (8 * (k % 8));
        }
        Piece { bytes, words, masks }
    }

    /// True when `b[j..]` starts with these bytes.
    #[inline]
    fn at(&self, b: &[u8], j: usize) -> bool {
        let n = self.bytes.len();
        if n <= 32 {
            // Whole words while the text has them (the masks keep the piece's bytes).
            if let Some(w) = b.get(j..j + n.div_ceil(8) * 8) {
                let mut diff = 0;
                for (k, c) in w.chunks_exact(8).enumerate() {
                    let x = u64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]);
                    diff |= (x ^ self.words[k]) & self.masks[k];
                }
                return diff == 0;
            }
        }
        b.get(j..j + n) == Some(self.bytes)
    }
}

/// A value's kind in a [`Layout`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    String,
    Number,
}

/// The layout of a plain row whose values are strings and numbers: the bytes
/// between its values (its keys, with the `{`, `,`, `:` and whitespace around
/// them), and each value's kind and wanted field. A row of a batch usually
/// has the layout of the row before it: [`ArrayReader`] then checks it by
/// comparing those bytes a word at a time and reading only the values, where
/// [`quick_row`] scans every key and looks it up (measured on a random flat
/// batch row: 3,051 -> 2,862 instructions a row in all). A row that differs
/// anywhere goes to the quick path (and the general scan), which decides it:
/// the layout only ever accepts a row the quick path accepts with the same
/// fields and numbers, since its keys are byte for byte those of a row the
/// quick path accepted, and its values are read by the same functions.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Layout<'a, const N: usize> {
    /// `pieces[k]` precedes value `k`; `pieces[values]` closes the row.
    pieces: [Piece<'a>; LAYOUT_VALUES + 1],
    /// Each value's kind and its place among the wanted fields (`None`: not wanted).
    kinds: [(Kind, Option<usize>); LAYOUT_VALUES],
    values: usize,
}

impl<'a, const N: usize> Layout<'a, N> {
    /// The layout of the row `text[i..]` (at `{`) that [`quick_row`] accepted;
    /// `None` for a row this path does not take (no value, a literal value,
    /// more than [`LAYOUT_VALUES`] values).
    fn of(text: &'a str, i: usize, keys: &Keys<N>) -> Option<Self> {
        let b = text.as_bytes();
        let empty = Piece::new(&[]);
        let mut l =
            Layout { pieces: [empty; LAYOUT_VALUES + 1], kinds: [(Kind::String, None); LAYOUT_VALUES], values: 0 };
        let (mut start, mut j) = (i, skip(b, i + 1));
        loop {
            if b.get(j) != Some(&b'"') || l.values == LAYOUT_VALUES {
                return None;
            }
            let kend = plain_string_end(b, j + 1)?;
            let colon = skip(b, kend + 1);
            if b.get(colon) != Some(&b':') {
                return None;
            }
            let vs = skip(b, colon + 1);
            let (kind, ve) = match b.get(vs)? {
                b'"' => (Kind::String, plain_string_end(b, vs + 1)? + 1),
                b'-' | b'0'..=b'9' => (Kind::Number, crate::float::json_number(b, vs)?.0),
                _ => return None,
            };
            l.pieces[l.values] = Piece::new(&b[start..vs]);
            l.kinds[l.values] = (kind, keys.find(b, j + 1, kend - j - 1));
            l.values += 1;
            let k = skip(b, ve);
            match b.get(k)? {
                b',' => (start, j) = (ve, skip(b, k + 1)),
                b'}' => {
                    l.pieces[l.values] = Piece::new(&b[ve..k + 1]);
                    return Some(l);
                }
                _ => return None,
            }
        }
    }

    /// The row at `text[i..]` (at `{`) when it has this layout: as
    /// [`quick_row`] reads it, and its end; `None` otherwise.
    #[inline(always)]
    fn row(&self, text: &'a str, i: usize) -> Option<(Row<'a, N>, usize)> {
        let b = text.as_bytes();
        let mut fields: [Option<&'a str>; N] = [None; N];
        let mut numbers = [f64::NAN; N];
        let mut j = i;
        for (piece, &(kind, place)) in self.pieces.iter().zip(&self.kinds).take(self.values) {
            if !piece.at(b, j) {
                return None;
            }
            let vs = j + piece.bytes.len();
            let (ve, x) = match (kind, b.get(vs)?) {
                (Kind::String, b'"') => (plain_string_end(b, vs + 1)? + 1, f64::NAN),
                (Kind::Number, b'-' | b'0'..=b'9') => crate::float::json_number(b, vs)?,
                _ => return None,
            };
            if let Some(p) = place {
                fields[p] = Some(&text[vs..ve]);
                numbers[p] = x;
            }
            j = ve;
        }
        let last = &self.pieces[self.values];
        if !last.at(b, j) {
            return None;
        }
        let end = j + last.bytes.len();
        Some((Row { raw: &text[i..end], fields, numbers }, end))
    }
}

/// Misses a reader's layouts may have at first, whatever the rows (see
/// [`Layouts`]): rows whose layouts keep changing are then read by the quick
/// path alone, but for one layout tried every 64 rows.
const LAYOUT_MISSES: usize = 64;

/// The last row's layout, which the next row is tried with first. A row that
/// misses it sets a new one while the misses stay fewer than
/// [`LAYOUT_MISSES`] plus a 64th of the rows, and none beyond: a row is then
/// not compared in vain with a layout that keeps missing, and a new layout
/// (which costs ~4,000 instructions with the row that misses it) is tried
/// every 64 rows. Measured on 10,000 random flat JSON rows (instructions a
/// row, the whole batch): rows of one layout 2,858 (the quick path alone
/// 3,068); rows of two alternating layouts 3,164 when they differ in their
/// first key and 3,189 in their last byte, where a budget of an eighth of
/// the rows took 3,368 and 3,474, and keeping the stale layout 3,290 and 3,702.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Layouts<'a, const N: usize> {
    last: Option<Layout<'a, N>>,
    misses: usize,
    rows: usize,
}

impl<const N: usize> Default for Layouts<'_, N> {
    fn default() -> Self {
        Layouts { last: None, misses: 0, rows: 0 }
    }
}

impl<'a, const N: usize> Layouts<'a, N> {
    /// The plain row at `text[i..]` (at `{`) and its end: by the last row's
    /// layout, else by [`quick_row`]; `None` where the quick path leaves it
    /// to the general scan.
    #[inline(always)]
    fn quick(&mut self, text: &'a str, i: usize, keys: &Keys<N>) -> Option<(Row<'a, N>, usize)> {
        self.rows += 1;
        match self.last.as_ref().and_then(|l| l.row(text, i)) {
            Some(r) => Some(r),
            None => self.miss(text, i, keys),
        }
    }

    /// [`Layouts::quick`] for a row that missed the layout (a call of its
    /// own: the layout's path stays short).
    #[inline(never)]
    fn miss(&mut self, text: &'a str, i: usize, keys: &Keys<N>) -> Option<(Row<'a, N>, usize)> {
        let r = quick_row(text, i, keys)?;
        if self.misses < LAYOUT_MISSES + self.rows / 64 {
            self.misses += 1;
            self.last = Layout::of(text, i, keys);
        } else {
            self.last = None;
        }
        Some(r)
    }
}

/// Scan the object at `text[i..]` (after whitespace): the row and its wanted
/// fields (duplicate keys refused), and the end offset. A plain row takes
/// the quick path; any other (or a fault) the general scan.
pub fn row<'a, const N: usize>(text: &'a str, i: usize, keys: &Keys<N>) -> Scan<(Row<'a, N>, usize)> {
    let b = text.as_bytes();
    if b.get(i) != Some(&b'{') {
        return Err(ScanError::new(i, "expected an object"));
    }
    match quick_row(text, i, keys) {
        Some(r) => Ok(r),
        None => general_row(text, i, keys.names),
    }
}

/// [`row`]'s general scan (`b[i] == '{'`).
fn general_row<'a, const N: usize>(text: &'a str, i: usize, names: &[&str; N]) -> Scan<(Row<'a, N>, usize)> {
    let b = text.as_bytes();
    let mut fields = [None; N];
    // The fast path compares raw keys: a wanted key is a duplicate when its
    // field is already set; the others (a row has a handful) are kept on the
    // stack, and only beyond `OTHERS` in a vector. A key with escapes sends the
    // row to the slow path, which compares decoded keys.
    const OTHERS: usize = 8;
    let mut others: [&[u8]; OTHERS] = [&[]; OTHERS];
    let mut more: Vec<&[u8]> = vec![];
    let mut n_others = 0;
    let mut escapes = false;
    let end = object(b, i, 1, &mut |key, escaped, (vs, ve)| {
        if escaped {
            escapes = true;
        } else if !escapes {
            // Byte by byte: keys are short, and a call to `memcmp` costs more.
            let wanted = names.iter().position(|n| n.len() == key.len() && n.bytes().zip(key).all(|(x, &y)| x == y));
            let duplicate = match wanted {
                Some(p) => fields[p].replace(&text[vs..ve]).is_some(),
                None if n_others < OTHERS => {
                    let d = others[..n_others].contains(&key);
                    others[n_others] = key;
                    n_others += 1;
                    d
                }
                None => {
                    let d = others.contains(&key) || more.contains(&key);
                    more.push(key);
                    d
                }
            };
            if duplicate {
                let at = key.as_ptr() as usize - b.as_ptr() as usize;
                let k = String::from_utf8_lossy(key);
                return Err(ScanError { at, what: format!("duplicate key '{k}'"), malformed: false });
            }
        }
        Ok(())
    })?;
    if escapes {
        fields = decoded_fields(text, i, names)?;
    }
    Ok((Row { raw: &text[i..end], fields, numbers: [f64::NAN; N] }, end))
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
/// returns the number of rows. (`batch` reads the rows with [`ArrayReader`]
/// a chunk at a time and checks each chunk in parallel, with the same result.)
pub fn array_rows<'a, const N: usize>(
    text: &'a str,
    names: &[&str; N],
    mut each: impl FnMut(usize, Row<'a, N>) -> Result<(), String>,
) -> Result<usize, RowsError> {
    let mut reader = ArrayReader::new(text, names);
    let mut rows = vec![];
    loop {
        let first = reader.rows_read();
        let fault = reader.chunk(1 << 12, &mut rows).err();
        for (j, r) in rows.drain(..).enumerate() {
            each(first + j, r).map_err(|reason| RowsError::Row { row: first + j, reason })?;
        }
        if let Some(e) = fault {
            return Err(e);
        }
        if reader.is_done() {
            return Ok(reader.rows_read());
        }
    }
}

/// Where an [`ArrayReader`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum At {
    /// Before the array's `[`.
    Start,
    /// At the next element (whitespace skipped; `]` there for an empty array).
    Element,
    /// The array was read to its end, or refused.
    Done,
}

/// A JSON array of objects read strictly in one serial pass, a chunk of rows
/// at a time: each row scanned by [`row`] as it is met (no separate pass to
/// find the rows), then the top level's `,`, `]` and trailing whitespace.
pub struct ArrayReader<'a, 'n, const N: usize> {
    text: &'a str,
    keys: Keys<'n, N>,
    at: usize,
    state: At,
    rows: usize,
    /// The rows' layouts.
    layouts: Layouts<'a, N>,
}

impl<'a, 'n, const N: usize> ArrayReader<'a, 'n, N> {
    /// A reader of `text`, picking the fields `names` of each row.
    pub fn new(text: &'a str, names: &'n [&'n str; N]) -> Self {
        ArrayReader { text, keys: Keys::new(names), at: 0, state: At::Start, rows: 0, layouts: Layouts::default() }
    }

    /// Rows read so far.
    pub fn rows_read(&self) -> usize {
        self.rows
    }

    /// True once the array was read to its end (or refused).
    pub fn is_done(&self) -> bool {
        self.state == At::Done
    }

    /// Read up to `n` more rows into `out` (emptied first). Fewer than `n`
    /// only at the end of the array. On an error `out` holds the rows before
    /// it, and the reader is done.
    pub fn chunk(&mut self, n: usize, out: &mut Vec<Row<'a, N>>) -> Result<(), RowsError> {
        out.clear();
        let r = self.read(n, out);
        if r.is_err() {
            self.state = At::Done;
        }
        r
    }

    fn read(&mut self, n: usize, out: &mut Vec<Row<'a, N>>) -> Result<(), RowsError> {
        let b = self.text.as_bytes();
        let syntax = |at: usize, what: &str| RowsError::Syntax { row: None, error: ScanError::new(at, what) };
        if self.state == At::Start {
            let i = ws(b, 0);
            match b.get(i) {
                None => return Err(syntax(i, "empty input (expected a JSON array)")),
                Some(b'[') => {}
                Some(_) => return Err(syntax(i, "expected a JSON array of objects")),
            }
            self.at = ws(b, i + 1);
            self.state = At::Element;
            if b.get(self.at) == Some(&b']') {
                return self.close(self.at + 1);
            }
        }
        while self.state == At::Element && out.len() < n {
            let i = self.at;
            if b.get(i) != Some(&b'{') {
                return Err(match value(b, i, 1) {
                    Err(error) => RowsError::Syntax { row: None, error },
                    Ok(_) => RowsError::Row { row: self.rows, reason: "expected an object".into() },
                });
            }
            // As `row`, with the quick path's row moved straight into `out`
            // (a row is 208 bytes: ~90 instructions a row fewer, measured),
            // and the last row's layout tried first.
            let end = match self.layouts.quick(self.text, i, &self.keys) {
                Some((r, end)) => {
                    out.push(r);
                    end
                }
                None => {
                    let (r, end) = general_row(self.text, i, self.keys.names)
                        .map_err(|error| RowsError::Syntax { row: Some(self.rows), error })?;
                    out.push(r);
                    end
                }
            };
            self.rows += 1;
            let j = ws(b, end);
            match b.get(j) {
                Some(b',') => self.at = ws(b, j + 1),
                Some(b']') => return self.close(j + 1),
                None => return Err(syntax(j, "EOF while parsing a list")),
                Some(_) => return Err(syntax(j, "expected `,` or `]`")),
            }
        }
        Ok(())
    }

    /// The array closed at `end`: only whitespace may follow.
    fn close(&mut self, end: usize) -> Result<(), RowsError> {
        self.state = At::Done;
        let end = ws(self.text.as_bytes(), end);
        if end < self.text.len() {
            return Err(RowsError::Syntax { row: None, error: ScanError::new(end, "trailing characters") });
        }
        Ok(())
    }
}

/// The one object of a line of JSON Lines (whitespace around it allowed).
pub fn line_row<'a, const N: usize>(line: &'a str, keys: &Keys<N>) -> Scan<Row<'a, N>> {
    line_row_with(line, keys, &mut Layouts::default())
}

/// [`line_row`], trying the line with the last line's layout first (`layouts`
/// kept from line to line, of lines of one text).
pub(crate) fn line_row_with<'a, const N: usize>(
    line: &'a str,
    keys: &Keys<N>,
    layouts: &mut Layouts<'a, N>,
) -> Scan<Row<'a, N>> {
    let b = line.as_bytes();
    let i = ws(b, 0);
    if b.get(i) != Some(&b'{') {
        value(b, i, 1)?;
        return Err(ScanError::new(i, "expected an object"));
    }
    let (r, end) = match layouts.quick(line, i, keys) {
        Some(r) => r,
        None => general_row(line, i, keys.names)?,
    };
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
    match crate::float::f64_of(raw) {
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

    /// Rows read a chunk at a time: the same rows whatever the chunk's size,
    /// and an error after the rows before it, with the reader then done.
    #[test]
    fn chunks_of_any_size_read_the_same_rows() {
        let names = ["a"];
        type Read = (Vec<Option<String>>, Option<(Option<usize>, String)>);
        let all = |t: &str, n: usize| -> Read {
            let mut r = ArrayReader::new(t, &names);
            let (mut got, mut chunk) = (vec![], vec![]);
            loop {
                let e = r.chunk(n, &mut chunk).err();
                assert!(chunk.len() <= n);
                got.extend(chunk.iter().map(|x| x.fields[0].map(String::from)));
                if e.is_some() || r.is_done() {
                    assert!(r.is_done());
                    assert_eq!(r.rows_read(), got.len());
                    return (got, e.map(what));
                }
                assert_eq!(chunk.len(), n, "a short chunk only at the end");
            }
        };
        for t in [
            "[]",
            "[{\"a\":1}]",
            "[{\"a\":1},{\"a\":2},{},{\"a\":4}] ",
            "[{\"a\":1},{\"a\":2},{\"a\":3} x",
            "[{\"a\":1},{\"a\"}]",
            "[{},{},7]",
        ] {
            let one = all(t, 1 << 12);
            for n in 1..5 {
                assert_eq!(all(t, n), one, "{t} in chunks of {n}");
            }
        }
        assert_eq!(
            all("[{\"a\":1},{\"a\":2},{},{\"a\":4}]", 3).0,
            [Some("1".into()), Some("2".into()), None, Some("4".into())]
        );
        assert_eq!(all("[{\"a\":1},{\"a\"}]", 1), (vec![Some("1".into())], Some((Some(1), "expected `:`".into()))));
        assert_eq!(all("[{},{},7]", 2), (vec![None, None], Some((Some(2), "expected an object".into()))));
        assert_eq!(all("[{}] x", 1).1, Some((None, "trailing characters".into())));
    }

    /// The quick path gives the general scan's row wherever it decides, and
    /// decides the plain rows (only): the rows below, each also inside a
    /// longer text (the 8-byte loads near the end and away from it).
    #[test]
    fn the_quick_path_reads_plain_rows_as_the_general_scan_does() {
        let names = ["shape", "vbar", "amp", "mu_ratio", "reduction", "vhat", "tangential_amp", "phase"];
        let keys = Keys::new(&names);
        let others = |n: usize| (0..n).map(|k| format!("\"x{k}\":{k}")).collect::<Vec<_>>().join(",");
        let plain = [
            r#"{"shape":"flat","vbar":0.16123709293488145,"amp":2.542301210811698}"#.to_string(),
            r#"{ "amp" : 1e-3 , "vbar":0, "shape" : "power:2.5", "note": "a long plain string, more than eight bytes", "ok": true, "no": false, "x": null }"#.into(),
            r#"{"tangential_amp":-0.5E+2,"phase":3,"reduction":1,"mu_ratio":0.5,"vhat":2,"é":"ü"}"#.into(),
            r#"{}"#.into(),
            format!("{{{},\"vbar\":1}}", others(8)),
        ];
        let other = [
            r#"{"shape":"fl\"at","vbar":1,"amp":1}"#.to_string(),
            r#"{"sh\u0061pe":"flat","vbar":1,"amp":1}"#.into(),
            r#"{"shape":"flat","vbar":1,"amp":1,"vbar":2}"#.into(),
            r#"{"a":1,"b":2,"a":3}"#.into(),
            r#"{"shape":"flat","vbar":[1],"amp":{"a":1}}"#.into(),
            format!("{{{},\"vbar\":1}}", others(9)),
            r#"{"shape":"flat","vbar":01}"#.into(),
            r#"{"shape":"flat","vbar":1,}"#.into(),
            r#"{"shape":"flat" "vbar":1}"#.into(),
            r#"{"shape":"flat","vbar":tru}"#.into(),
            "{\"shape\":\"fl\tat\"}".into(),
            r#"{"shape":"flat""#.into(),
        ];
        for (t, is_plain) in plain.iter().map(|t| (t, true)).chain(other.iter().map(|t| (t, false))) {
            for text in [t.clone(), format!("{t}        , more text")] {
                let quick = quick_row(&text, 0, &keys);
                assert_eq!(quick.is_some(), is_plain, "{text}");
                let general = general_row(&text, 0, &names);
                if let Some((r, end)) = quick {
                    let (g, gend) = general.unwrap();
                    assert_eq!((r.raw, r.fields, end), (g.raw, g.fields, gend), "{text}");
                    numbers_are_the_fields(&r);
                }
            }
        }
        let r = row(&plain[0], 0, &keys).unwrap().0;
        assert_eq!(r.fields[..3], [Some("\"flat\""), Some("0.16123709293488145"), Some("2.542301210811698")]);
        assert_eq!(r.fields[3..], [None; 5]);
        assert_eq!(r.numbers[1..3], [0.16123709293488145, 2.542301210811698]);
        // Numbers the fast path leaves to the raw text: NaN, and read from it.
        let t = r#"{"vbar":1.00000000000000000001,"amp":1e-30,"phase":-0,"vhat":2E+3}"#;
        let r = row(t, 0, &keys).unwrap().0;
        assert!(r.numbers[1].is_nan() && r.numbers[2].is_nan());
        assert_eq!((r.numbers[5], r.numbers[7].to_bits()), (2000.0, (-0.0f64).to_bits()));
        assert_eq!(
            (r.number(1, "vbar"), r.number(2, "amp"), r.number(0, "shape")),
            (Ok(Some(1.0)), Ok(Some(1e-30)), Ok(None))
        );
        assert_eq!(r.number(7, "phase").map(|x| x.map(f64::to_bits)), Ok(Some(0)), "-0 read as 0");
    }

    /// A row and what `row` reads of it, numbers as bits (NaN's bits are one).
    type Read<'a> = (&'a str, [Option<&'a str>; 8], [u64; 8], usize);

    fn read_of<'a>(r: (Row<'a, 8>, usize)) -> Read<'a> {
        (r.0.raw, r.0.fields, r.0.numbers.map(f64::to_bits), r.1)
    }

    /// A layout taken from a plain row accepts exactly the rows with the same
    /// bytes between their values and values of the same kinds, and reads them
    /// as the quick path does (fields, numbers, end); every other row is left
    /// to the quick path. Each row alone (the words near the end fall back to
    /// slices) and inside a longer text.
    #[test]
    fn a_layout_reads_its_rows_as_the_quick_path_does() {
        let names = ["shape", "vbar", "amp", "mu_ratio", "reduction", "vhat", "tangential_amp", "phase"];
        let keys = Keys::new(&names);
        let long = "a_key_longer_than_the_thirty_two_bytes_of_a_piece";
        // (template, rows with its layout, rows without it)
        let cases: Vec<(String, Vec<String>, Vec<String>)> = vec![
            (
                r#"{"shape":"flat","vbar":0.16123709293488145,"amp":2.542301210811698}"#.into(),
                vec![
                    r#"{"shape":"parabolic","vbar":1e-3,"amp":-0}"#.into(),
                    r#"{"shape":"","vbar":1.00000000000000000001,"amp":2E+3}"#.into(),
                    r#"{"shape":"é","vbar":-12345678901234567890,"amp":0.5}"#.into(),
                ],
                vec![
                    r#"{"shape": "flat","vbar":1,"amp":2}"#.into(),
                    r#"{"shapf":"flat","vbar":1,"amp":2}"#.into(),
                    r#"{"shape":1,"vbar":1,"amp":2}"#.into(),
                    r#"{"shape":"flat","vbar":"1","amp":2}"#.into(),
                    r#"{"shape":"fl\"at","vbar":1,"amp":2}"#.into(),
                    "{\"shape\":\"fl\tat\",\"vbar\":1,\"amp\":2}".into(),
                    r#"{"shape":"flat","vbar":01,"amp":2}"#.into(),
                    r#"{"shape":"flat","vbar":1.,"amp":2}"#.into(),
                    r#"{"shape":"flat","vbar":1x,"amp":2}"#.into(),
                    r#"{"shape":"flat","vbar":true,"amp":2}"#.into(),
                    r#"{"shape":"flat","vbar":1,"amp":2,"x":3}"#.into(),
                    r#"{"shape":"flat","vbar":1,"amp":2 }"#.into(),
                    r#"{"shape":"flat","vbar":1,"amp":2"#.into(),
                    r#"{"shape":"flat","vbar":1}"#.into(),
                ],
            ),
            (
                r#"{ "amp" : 1e-3 , "é": "ü", "vbar":0, "note": "a plain string", "phase": -1 }"#.into(),
                vec![r#"{ "amp" : 7 , "é": "", "vbar":1e300, "note": "", "phase": 0.5 }"#.into()],
                vec![
                    r#"{ "amp" : 7 , "é": "", "vbar":1e300, "note": "", "phase": 0.5}"#.into(),
                    r#"{ "amp" : 7 , "e": "", "vbar":1e300, "note": "", "phase": 0.5 }"#.into(),
                ],
            ),
            (
                // Pieces of 9 to 32 bytes differ in their second to fourth words.
                r#"{"shape":"flat","tangential_amp":1,"a_key_of_twenty_nine_bytes_":2}"#.into(),
                vec![r#"{"shape":"cone","tangential_amp":-1e-9,"a_key_of_twenty_nine_bytes_":0}"#.into()],
                vec![
                    r#"{"shape":"flat","tangential_amq":1,"a_key_of_twenty_nine_bytes_":2}"#.into(),
                    r#"{"shape":"flat","tangential_amp":1,"a_key_of_twenty_nine_bytes_!":2}"#.into(),
                    r#"{"shape":"flat","tangential_amp":1,"a_key_of_twenty_nine_bytes!":2}"#.into(),
                ],
            ),
            (
                format!(r#"{{"{long}":"x","vbar":2}}"#),
                vec![format!(r#"{{"{long}":"yy","vbar":-3.5}}"#)],
                vec![
                    format!(r#"{{"{}X":"x","vbar":2}}"#, &long[..long.len() - 1]),
                    format!(r#"{{"{long}":"x","vbar":2,"amp":1}}"#),
                ],
            ),
        ];
        for (template, same, different) in &cases {
            let layout = Layout::of(template, 0, &keys).expect(template);
            for (t, laid_out) in same.iter().map(|t| (t, true)).chain(different.iter().map(|t| (t, false))) {
                for text in [t.clone(), format!("{t}        , more text")] {
                    let by_layout = layout.row(&text, 0);
                    assert_eq!(by_layout.is_some(), laid_out, "{template} then {text}");
                    if let Some(r) = by_layout {
                        assert_eq!(read_of(r), read_of(quick_row(&text, 0, &keys).expect(&text)), "{text}");
                    }
                }
            }
        }
        // No layout for a row with a literal, with no value, with too many values.
        let many = format!(
            r#"{{"shape":"a","vbar":1,"amp":2,{}}}"#,
            (0..6).map(|k| format!("\"x{k}\":{k}")).collect::<Vec<_>>().join(",")
        );
        for t in [r#"{"shape":"flat","ok":true}"#, "{}", &many] {
            assert!(quick_row::<8>(t, 0, &keys).is_some() && Layout::of(t, 0, &keys).is_none(), "{t}");
        }
    }

    /// A reader's layouts: one miss for rows of one layout; for rows whose
    /// layouts alternate, a new layout at each miss while the misses stay
    /// below `LAYOUT_MISSES` plus a 64th of the rows, and none beyond (a model
    /// of that rule counts them).
    #[test]
    fn layouts_are_rebuilt_within_their_budget() {
        let names = ["a", "b"];
        let misses = |row: &dyn Fn(usize) -> String| {
            let text = format!("[{}]", (0..1000).map(row).collect::<Vec<_>>().join(","));
            let mut reader = ArrayReader::new(&text, &names);
            let mut rows = vec![];
            reader.chunk(2000, &mut rows).unwrap();
            assert_eq!(rows.len(), 1000);
            reader.layouts.misses
        };
        assert_eq!(misses(&|i| format!(r#"{{"a":{i},"b":"x{i}"}}"#)), 1);
        let alternate = |i: usize| {
            if i.is_multiple_of(2) {
                format!(r#"{{"a":{i},"b":2}}"#)
            } else {
                format!(r#"{{"b":2,"a":{i}}}"#)
            }
        };
        // The rule, row by row: row r (from 1) misses unless the layout set
        // is its own; a miss sets its layout while misses < 64 + r/64, and
        // clears the layout beyond.
        let rows: Vec<String> = (0..1000).map(alternate).collect();
        let text = rows.join(",");
        let keys = Keys::new(&names);
        let mut layouts = Layouts::default();
        let (mut model, mut last, mut at) = (0, None, 0);
        for (i, row) in rows.iter().enumerate() {
            let r = i + 1;
            if last != Some(i % 2) {
                if model < LAYOUT_MISSES + r / 64 {
                    model += 1;
                    last = Some(i % 2);
                } else {
                    last = None;
                }
            }
            assert_eq!(layouts.quick(&text, at, &keys).map(|(r, _)| r.raw), Some(row.as_str()));
            assert_eq!((layouts.misses, layouts.last.is_some()), (model, last.is_some()), "row {r}");
            at += row.len() + 1;
        }
        assert!(model > 64 + 1000 / 64 - 3 && model <= 64 + 1000 / 64, "{model}");
        assert_eq!(misses(&alternate), model);
    }

    /// A reader tries each row with the last row's layout: every row of an
    /// array whose layouts change (in runs, and at every row, beyond the
    /// misses allowed) reads as `row` reads it alone.
    #[test]
    fn the_reader_reads_every_row_as_row_does() {
        let names = ["shape", "vbar", "amp", "mu_ratio", "reduction", "vhat", "tangential_amp", "phase"];
        let keys = Keys::new(&names);
        let kinds = [
            |i: usize| format!(r#"{{"shape":"flat","vbar":0.{i},"amp":{i}e-2}}"#),
            |i: usize| format!(r#"{{"vbar":{i},"shape":"parabolic","amp":1}}"#),
            |i: usize| format!(r#"{{"shape":"flat","vbar":0.{i},"amp":{i},"id":"r{i}"}}"#),
            |i: usize| format!(r#"{{"shape":"fl\u0061t","vbar":{i},"amp":1}}"#),
            |i: usize| format!(r#"{{ "shape" : "flat", "vbar" : {i}, "amp" : [1] }}"#),
        ];
        for period in [1, 2, 7, 50] {
            let rows: Vec<String> = (0..400).map(|i| kinds[(i / period + i % 3 / 2) % kinds.len()](i)).collect();
            let text = format!("[{}]", rows.join(",\n"));
            let mut reader = ArrayReader::new(&text, &names);
            let mut got = vec![];
            reader.chunk(1000, &mut got).unwrap();
            assert!(reader.is_done() && got.len() == rows.len());
            for r in &got {
                let at = r.raw.as_ptr() as usize - text.as_ptr() as usize;
                let end = at + r.raw.len();
                assert_eq!(read_of((*r, end)), read_of(row(&text, at, &keys).unwrap()), "period {period}: {}", r.raw);
            }
        }
    }

    /// Each number the scan read is its field's `str::parse` value, bit for bit.
    fn numbers_are_the_fields<const N: usize>(r: &Row<N>) {
        for (x, f) in r.numbers.iter().zip(r.fields) {
            if !x.is_nan() {
                assert_eq!(Some(x.to_bits()), f.and_then(|f| f.parse::<f64>().ok()).map(f64::to_bits), "{f:?}");
            }
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
        assert_eq!(line_row(" {\"a\": 2} \r", &Keys::new(&names)).unwrap().fields[3], Some("2"));
        assert_eq!(line_row("{} {}", &Keys::new(&names)).unwrap_err().what, "trailing characters");
        assert_eq!(line_row("[1]", &Keys::new(&names)).unwrap_err().what, "expected an object");
    }
}
