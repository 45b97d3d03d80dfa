//! Bounded reads of input files and stdin: every input has a documented size
//! limit, checked while reading, so `/dev/zero` or an endless pipe is an error
//! instead of an out-of-memory abort. The reading itself is the library's one
//! capped reader ([`fricosc::io`]); here its errors get the command line's words.

use crate::error::{Error, Result};

/// Largest `batch` or `validate` input read whole: 10^7 rows of about 100 bytes.
pub const MAX_TABLE_BYTES: u64 = 1 << 30;
/// Largest scene file or tabulated profile (`profile:`/`gx:`).
pub const MAX_SMALL_BYTES: u64 = fricosc::io::MAX_FILE_BYTES;

/// The command line's error for a failed capped read of `name`.
pub fn read_error(name: &str, limit: u64, e: std::io::Error) -> Error {
    if e.kind() == std::io::ErrorKind::FileTooLarge {
        // The size, where the file states it; else "more than the limit".
        let count = std::fs::metadata(name).ok().filter(|m| m.is_file()).map_or(limit as u128 + 1, |m| m.len() as u128);
        Error::TooLarge { what: format!("bytes of {name}"), count, limit: limit as u128 }
    } else {
        Error::read(name, e)
    }
}

/// Read `path` (`-` is stdin) as UTF-8 text of at most `limit` bytes.
pub fn read_capped(path: &str, limit: u64) -> Result<String> {
    if path == "-" {
        fricosc::io::read_text(std::io::stdin().lock(), limit).map_err(|e| read_error("stdin", limit, e))
    } else {
        fricosc::io::read_capped(path, limit).map_err(|e| read_error(path, limit, e))
    }
}

/// The reader of the files a shape or scene names, with the [`MAX_SMALL_BYTES`] cap.
pub fn small_file(path: &str) -> std::io::Result<String> {
    fricosc::io::read_capped(path, MAX_SMALL_BYTES)
}

/// Parse a shape as the command line writes it, reading a tabulated shape's
/// file (`profile:FILE@U0`, `gx:FILE@U0`) with the [`MAX_SMALL_BYTES`] cap.
pub fn parse_shape(spec: &str) -> Result<fricosc::Shape> {
    Ok(fricosc::Shape::parse_with(spec, &small_file)?)
}
