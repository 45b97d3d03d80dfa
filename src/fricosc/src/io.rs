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
    read_text_sized(reader, limit, 0)
}

/// [`read_text`] into a buffer made for `size` bytes (a file's length), so
/// that reading it neither grows nor copies the buffer.
fn read_text_sized(reader: impl Read, limit: u64, size: u64) -> io::Result<String> {
    // One byte more than the size, so that the end is seen without growing.
    let mut buf = Vec::with_capacity(usize::try_from(size.min(limit).saturating_add(1)).unwrap_or(0));
    let n = reader.take(limit.saturating_add(1)).read_to_end(&mut buf)?;
    if n as u64 > limit {
        return Err(io::Error::new(
            io::ErrorKind::FileTooLarge,
            format!("its size is more than the limit of {limit} bytes"),
        ));
    }
    if buf.starts_with(b"\xEF\xBB\xBF") {
        buf.drain(..3);
    }
    String::from_utf8(buf).map_err(|e| io::Error::new(io::ErrorKind::InvalidData, format!("not UTF-8 text ({e})")))
}

/// [`read_text`] of the file at `path`. A regular file larger than `limit` is
/// refused before it is read.
///
/// # Errors
/// As [`read_text`], and the errors of opening the file.
pub fn read_capped(path: &str, limit: u64) -> io::Result<String> {
    let file = std::fs::File::open(path)?;
    let mut size = 0;
    if let Ok(m) = file.metadata() {
        if m.is_file() {
            size = m.len();
        }
        if m.is_file() && m.len() > limit {
            return Err(io::Error::new(
                io::ErrorKind::FileTooLarge,
                format!("its size, {} bytes, is more than the limit of {limit}", m.len()),
            ));
        }
    }
    read_text_sized(file, limit, size)
}
