//! Typed errors of the library. Every message is one line and names the problem.

use thiserror::Error;

/// Everything that can go wrong in fricosc, with the context to act on it.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum Error {
    /// A numeric parameter is NaN, infinite or outside its domain.
    #[error("invalid {name} = {value}: {reason}")]
    InvalidParameter {
        /// Parameter name as the user wrote it (`vbar`, `amp`, ...).
        name: String,
        /// The offending value, as text.
        value: String,
        /// What is wrong with it.
        reason: String,
    },
    /// A shape specification could not be understood.
    #[error("invalid shape '{spec}': {reason}")]
    InvalidShape {
        /// The specification as given.
        spec: String,
        /// What is wrong with it.
        reason: String,
    },
    /// Malformed input text (JSON, CSV, a number list).
    #[error("{context}: {reason}")]
    Parse {
        /// Where: a file name, `stdin`, or an option name.
        context: String,
        /// What is wrong.
        reason: String,
    },
    /// A file could not be read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The path (or `stdin`).
        path: String,
        /// The operating system's reason.
        #[source]
        source: std::io::Error,
    },
    /// A file or stream could not be written.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The path (or `stdout`).
        path: String,
        /// The operating system's reason.
        #[source]
        source: std::io::Error,
    },
    /// An internal result is not finite or outside its mathematical range: a bug
    /// of fricosc (or an input at the edge of what f64 can represent), never
    /// reported as a number. The CLI exits with code 3.
    #[error("internal error: {what} (please report this with the command that caused it)")]
    Internal {
        /// What was computed and the value it had.
        what: String,
    },
    /// A request beyond the documented size limits.
    #[error("{what}: {count} is more than the limit of {limit}")]
    TooLarge {
        /// What is counted, and in what (`bytes of stdin`, `table rows`).
        what: String,
        /// Its size.
        count: u128,
        /// The limit.
        limit: u128,
    },
}

/// Result alias for fricosc.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// An [`Error::Write`] for `path` from an I/O error.
    pub fn write(path: &str, source: std::io::Error) -> Self {
        Error::Write { path: path.into(), source }
    }

    /// An [`Error::Io`] (a failed read) for `path`.
    pub fn read(path: &str, source: std::io::Error) -> Self {
        Error::Io { path: path.into(), source }
    }

    /// True for a write to a closed pipe (the reader went away: not an error).
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, Error::Write { source, .. } if source.kind() == std::io::ErrorKind::BrokenPipe)
    }

    /// Shorthand for [`Error::InvalidParameter`].
    pub fn param(name: &str, value: f64, reason: &str) -> Self {
        Error::InvalidParameter { name: name.into(), value: format!("{value:?}"), reason: reason.into() }
    }
}

/// Check that `x` is finite and `>= 0`.
pub fn check_nonneg(name: &str, x: f64) -> Result<f64> {
    if !x.is_finite() {
        Err(Error::param(name, x, "must be finite"))
    } else if x < 0.0 {
        Err(Error::param(name, x, "must be >= 0"))
    } else {
        Ok(x)
    }
}
