//! An input read twice, as streamed batches read theirs (check every row, then
//! compute and write), so that the second pass sees exactly the bytes the
//! first one checked:
//!
//! - a regular file: the first pass counts its bytes; the second reads that
//!   many and no more (a file that grows in between is read as it was), and a
//!   file that shrank is an error;
//! - anything else (stdin, `/dev/stdin`, a pipe from `<(...)`, a named FIFO): it
//!   is opened once, and the first pass copies what it reads into a spool file
//!   that the second reads. The spool has no name in the directory (only the
//!   open handle keeps it), so that nothing is left behind whatever ends the
//!   process; at most
//!   [`MAX_SPOOL_BYTES`] bytes, and the reader's own checks (the line cap)
//!   apply while it is being written.

use crate::error::{Error, Result};
use std::cell::{Cell, RefCell};
use std::fs::File;
use std::io::{self, BufRead, BufReader, Read, Seek, Write};
use std::rc::Rc;

/// Most bytes a non-seekable input may bring (the spool's size).
pub const MAX_SPOOL_BYTES: u64 = 16 << 30;

/// Buffer of each pass.
const BUFFER: usize = 1 << 16;

/// An input to be read twice.
pub struct TwoPass {
    source: String,
    kind: Kind,
    pass: Cell<u8>,
    /// Bytes the first pass read.
    length: Rc<Cell<u64>>,
}

enum Kind {
    /// A regular file, opened anew for each pass.
    Regular(String),
    /// Stdin or another non-seekable input (taken by the first pass), and the spool.
    Spooled(RefCell<Option<Box<dyn Read>>>, File),
}

impl TwoPass {
    /// The input `path` (`-` is stdin); `source` names it in messages.
    pub fn open(path: &str) -> Result<TwoPass> {
        let source = if path == "-" { "stdin".to_string() } else { path.to_string() };
        let cannot = |e: io::Error| Error::read(&source, e);
        let kind = if path == "-" {
            Kind::Spooled(RefCell::new(Some(Box::new(io::stdin()))), spool_file()?)
        } else {
            let meta = std::fs::metadata(path).map_err(cannot)?;
            if meta.is_dir() {
                return Err(Error::read(&source, io::Error::new(io::ErrorKind::IsADirectory, "a directory")));
            }
            if meta.is_file() {
                Kind::Regular(path.to_string())
            } else {
                let f = File::open(path).map_err(cannot)?;
                Kind::Spooled(RefCell::new(Some(Box::new(f))), spool_file()?)
            }
        };
        Ok(TwoPass { source, kind, pass: Cell::new(0), length: Rc::new(Cell::new(0)) })
    }

    /// The name of the input in messages.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The reader of the next pass (the first, then the second).
    pub fn next_pass(&self) -> Result<Box<dyn BufRead>> {
        let pass = self.pass.get() + 1;
        self.pass.set(pass);
        let cannot = |e: io::Error| Error::read(&self.source, e);
        match (&self.kind, pass) {
            (Kind::Regular(path), 1) => {
                let f = File::open(path).map_err(cannot)?;
                Ok(Box::new(BufReader::with_capacity(BUFFER, Counting { inner: f, count: self.length.clone() })))
            }
            (Kind::Regular(path), 2) => {
                let f = File::open(path).map_err(cannot)?;
                let n = self.length.get();
                Ok(Box::new(BufReader::with_capacity(BUFFER, Exact { inner: f.take(n), expected: n, read: 0 })))
            }
            (Kind::Spooled(input, spool), 1) => {
                let inner = input.borrow_mut().take().ok_or_else(|| cannot(io::ErrorKind::UnexpectedEof.into()))?;
                let spool = spool.try_clone().map_err(cannot)?;
                let tee = Tee { inner, spool, count: self.length.clone() };
                Ok(Box::new(BufReader::with_capacity(BUFFER, tee)))
            }
            (Kind::Spooled(_, spool), 2) => {
                let mut f = spool.try_clone().map_err(cannot)?;
                f.flush().map_err(cannot)?;
                f.rewind().map_err(cannot)?;
                let n = self.length.get();
                Ok(Box::new(BufReader::with_capacity(BUFFER, Exact { inner: f.take(n), expected: n, read: 0 })))
            }
            _ => Err(Error::Internal { what: format!("{}: a third pass", self.source) }),
        }
    }
}

/// A new spool file in the temporary directory, without a name from the
/// moment it exists (`tempfile::tempfile`: `O_TMPFILE`, or unlinked at once).
fn spool_file() -> Result<File> {
    tempfile::tempfile().map_err(|e| Error::write(&std::env::temp_dir().display().to_string(), e))
}

/// A reader that counts its bytes.
struct Counting<R> {
    inner: R,
    count: Rc<Cell<u64>>,
}

impl<R: Read> Read for Counting<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.count.set(self.count.get() + n as u64);
        Ok(n)
    }
}

/// A reader that copies what it reads into the spool, counting (at most
/// [`MAX_SPOOL_BYTES`]).
struct Tee {
    inner: Box<dyn Read>,
    spool: File,
    count: Rc<Cell<u64>>,
}

impl Read for Tee {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.inner.read(buf)?;
        let total = self.count.get() + n as u64;
        if total > MAX_SPOOL_BYTES {
            return Err(io::Error::new(
                io::ErrorKind::FileTooLarge,
                format!("more than {MAX_SPOOL_BYTES} bytes from a pipe (give a regular file instead)"),
            ));
        }
        self.spool.write_all(&buf[..n]).map_err(|e| io::Error::new(e.kind(), SpoolFull(e)))?;
        self.count.set(total);
        Ok(n)
    }
}

/// The spool file could not take what the input brought (a full temporary
/// folder): a failed write of ours, not a failed read of the input.
#[derive(Debug)]
pub struct SpoolFull(io::Error);

impl std::fmt::Display for SpoolFull {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} is full or not writable ({}): give a regular file, or set TMPDIR to a folder with room",
            std::env::temp_dir().display(),
            self.0
        )
    }
}

impl std::error::Error for SpoolFull {}

/// The second pass: exactly the bytes of the first, an error if fewer arrive.
struct Exact<R> {
    inner: R,
    expected: u64,
    read: u64,
}

impl<R: Read> Read for Exact<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.read += n as u64;
        if n == 0 && !buf.is_empty() && self.read < self.expected {
            return Err(io::Error::new(
                io::ErrorKind::UnexpectedEof,
                format!(
                    "the input changed while it was read: {} bytes were checked, only {} came back",
                    self.expected, self.read
                ),
            ));
        }
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(mut r: Box<dyn BufRead>) -> io::Result<String> {
        let mut s = String::new();
        r.read_to_string(&mut s).map(|_| s)
    }

    /// A file that grows between the passes is read as it was checked; one that
    /// shrinks is an error, never fewer rows in silence.
    #[test]
    fn the_second_pass_reads_exactly_what_the_first_checked() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("rows.csv");
        std::fs::write(&path, "a\n1\n2\n").unwrap();
        let p = path.to_str().unwrap();
        let input = TwoPass::open(p).unwrap();
        assert_eq!(all(input.next_pass().unwrap()).unwrap(), "a\n1\n2\n");
        std::fs::write(&path, "a\n1\n2\nbad row appended\n").unwrap();
        assert_eq!(all(input.next_pass().unwrap()).unwrap(), "a\n1\n2\n");
        let input = TwoPass::open(p).unwrap();
        all(input.next_pass().unwrap()).unwrap();
        std::fs::write(&path, "a\n").unwrap();
        let e = all(input.next_pass().unwrap()).unwrap_err();
        assert!(e.to_string().contains("changed while it was read"), "{e}");
        assert!(input.next_pass().is_err(), "no third pass");
    }

    /// A non-seekable input is opened once: the second pass reads the spool.
    #[test]
    fn a_pipe_is_read_once_and_spooled() {
        let (mut reader, mut writer) = io::pipe().unwrap();
        writer.write_all(b"x\ny\n").unwrap();
        drop(writer);
        let mut buf = vec![];
        reader.read_to_end(&mut buf).unwrap();
        let kind = Kind::Spooled(RefCell::new(Some(Box::new(io::Cursor::new(buf)))), spool_file().unwrap());
        let input = TwoPass { source: "pipe".into(), kind, pass: Cell::new(0), length: Rc::new(Cell::new(0)) };
        assert_eq!(all(input.next_pass().unwrap()).unwrap(), "x\ny\n");
        assert_eq!(all(input.next_pass().unwrap()).unwrap(), "x\ny\n");
    }

    /// A spool that cannot be written (`/dev/full`: a full temporary folder)
    /// is a failed write of a copy of the input, naming TMPDIR, not "cannot
    /// read stdin".
    #[test]
    fn a_full_spool_is_named_as_such() {
        let spool = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let mut tee = Tee { inner: Box::new(io::Cursor::new(b"x\n".to_vec())), spool, count: Rc::new(Cell::new(0)) };
        let e = Error::read("stdin", tee.read(&mut [0; 16]).unwrap_err()).to_string();
        assert!(e.starts_with("cannot write a copy of the input: ") && e.contains("TMPDIR"), "{e}");
    }
}
