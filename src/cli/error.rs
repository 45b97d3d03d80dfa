//! The command line's errors: the library's, plus reading and writing files and
//! streams, usage mistakes and size limits of the inputs. Each maps to an exit
//! code in one place ([`Error::exit_code`]).

use thiserror::Error;

/// What can go wrong in a command.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum Error {
    /// The library refused the request or failed.
    #[error(transparent)]
    Core(#[from] fricosc::Error),
    /// Malformed input text or options.
    #[error("{context}: {reason}")]
    Parse {
        /// Where: a file name, `stdin`, or an option name.
        context: String,
        /// What is wrong.
        reason: String,
    },
    /// A file or stream could not be read.
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
    /// An input beyond the documented size limits.
    #[error("{what}: {count} is more than the limit of {limit}")]
    TooLarge {
        /// What is counted, and in what (`bytes of stdin`, `table rows`).
        what: String,
        /// Its size.
        count: u128,
        /// The limit.
        limit: u128,
    },
    /// A bug of fricosc (exit code 3).
    #[error("internal error: {what} (please report this with the command that caused it)")]
    Internal {
        /// What went wrong.
        what: String,
    },
}

/// Result alias of the command line.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// An [`Error::Write`] for `path` from an I/O error.
    pub fn write(path: &str, source: std::io::Error) -> Self {
        Error::Write { path: path.into(), source }
    }

    /// An [`Error::Io`] (a failed read) for `path`; a spool file that could
    /// not be written while `path` was read is an [`Error::Write`] of it.
    pub fn read(path: &str, source: std::io::Error) -> Self {
        if source.get_ref().is_some_and(|e| e.is::<crate::twopass::SpoolFull>()) {
            return Error::Write { path: "a copy of the input".into(), source };
        }
        Error::Io { path: path.into(), source }
    }

    /// An [`Error::Parse`] of `context` (a file, a flag) for `reason`.
    pub fn parse(context: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::Parse { context: context.into(), reason: reason.into() }
    }

    /// Shorthand for the library's [`fricosc::Error::InvalidParameter`].
    pub fn param(name: &'static str, value: f64, reason: &str) -> Self {
        Error::Core(fricosc::Error::param(name, value, reason))
    }

    /// True for a write to a closed pipe (the reader went away: not an error).
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, Error::Write { source, .. } if source.kind() == std::io::ErrorKind::BrokenPipe)
    }

    /// The exit code: 3 for an internal error (a bug), 2 for everything else
    /// (bad input, a failed read or write).
    pub fn exit_code(&self) -> u8 {
        match self {
            Error::Internal { .. } => 3,
            Error::Core(e) if e.is_internal() => 3,
            _ => 2,
        }
    }

    /// As a boxed error for the library's file readers ([`fricosc::Error::File`]).
    pub fn boxed(self) -> Box<dyn std::error::Error + Send + Sync> {
        Box::new(self)
    }
}
