//! Bounded reads of input files and stdin: every input has a documented size
//! limit, checked while reading, so `/dev/zero` or an endless pipe is an error
//! instead of an out-of-memory abort.

use crate::error::{Error, Result};
use std::io::Read;

/// Largest `batch` or `validate` input: 10^7 rows of about 100 bytes.
pub const MAX_TABLE_BYTES: u64 = 1 << 30;
/// Largest scene file or tabulated profile (`profile:`/`gx:`).
pub const MAX_SMALL_BYTES: u64 = 64 << 20;

/// Read `path` (`-` is stdin) as UTF-8 text of at most `limit` bytes.
pub fn read_capped(path: &str, limit: u64) -> Result<String> {
    let name = if path == "-" { "stdin" } else { path };
    let too_large =
        |n: u64| Error::TooLarge { what: format!("bytes of {name}"), count: n as u128, limit: limit as u128 };
    // A regular file states its size: refuse before reading it.
    if path != "-" {
        if let Ok(m) = std::fs::metadata(path) {
            if m.is_file() && m.len() > limit {
                return Err(too_large(m.len()));
            }
        }
    }
    let mut buf = Vec::new();
    let n = if path == "-" {
        std::io::stdin().lock().take(limit + 1).read_to_end(&mut buf)
    } else {
        std::fs::File::open(path).and_then(|f| f.take(limit + 1).read_to_end(&mut buf))
    }
    .map_err(|e| Error::read(name, e))?;
    if n as u64 > limit {
        return Err(too_large(n as u64));
    }
    // A UTF-8 byte-order mark (spreadsheets write one) is not part of the text.
    let bytes = buf.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&buf);
    String::from_utf8(bytes.to_vec()).map_err(|e| {
        Error::read(name, std::io::Error::new(std::io::ErrorKind::InvalidData, format!("not UTF-8 text ({e})")))
    })
}

/// Parse a shape as the command line writes it, reading a tabulated shape's
/// file (`profile:FILE@U0`, `gx:FILE@U0`) with the [`MAX_SMALL_BYTES`] cap.
pub fn parse_shape(spec: &str) -> Result<crate::shape::Shape> {
    crate::shape::Shape::parse_with(spec, &|path| read_capped(path, MAX_SMALL_BYTES))
}
