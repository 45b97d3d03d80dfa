//! Reading a file a caller names, with a size limit: the one capped reader of
//! the command line and the Python package (the library itself reads no files;
//! tabulated shapes and scenes take a reader, [`crate::shape::Shape::parse_with`]).

use std::io::{self, Read};

/// Largest scene file or tabulated profile read (`profile:FILE@U0`, `gx:FILE@U0`).
pub const MAX_FILE_BYTES: u64 = 64 << 20;

/// The UTF-8 text of at most `limit` bytes from `reader`, counted as they are
/// read (so `/dev/zero` or an endless pipe stops at the limit): an error of
/// kind [`io::ErrorKind::FileTooLarge`] beyond it, [`io::ErrorKind::InvalidData`]
/// for text that is not UTF-8. A UTF-8 byte-order mark is dropped.
///
/// # Errors
/// The reader's errors; [`io::ErrorKind::FileTooLarge`] beyond `limit`;
/// [`io::ErrorKind::InvalidData`] for text that is not UTF-8.
pub fn read_text(reader: impl Read, limit: u64) -> io::Result<String> {
    let mut buf = Vec::new();
    let n = reader.take(limit.saturating_add(1)).read_to_end(&mut buf)?;
    if n as u64 > limit {
        return Err(io::Error::new(
            io::ErrorKind::FileTooLarge,
            format!("its size is more than the limit of {limit} bytes"),
        ));
    }
    let bytes = buf.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&buf);
    String::from_utf8(bytes.to_vec())
        .map_err(|e| io::Error::new(io::ErrorKind::InvalidData, format!("not UTF-8 text ({e})")))
}

/// [`read_text`] of the file at `path`. A regular file larger than `limit` is
/// refused before it is read.
///
/// # Errors
/// As [`read_text`], and the errors of opening the file.
pub fn read_capped(path: &str, limit: u64) -> io::Result<String> {
    let file = std::fs::File::open(path)?;
    if let Ok(m) = file.metadata() {
        if m.is_file() && m.len() > limit {
            return Err(io::Error::new(
                io::ErrorKind::FileTooLarge,
                format!("its size, {} bytes, is more than the limit of {limit}", m.len()),
            ));
        }
    }
    read_text(file, limit)
}
