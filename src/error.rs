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
    #[error("cannot read {path}: {reason}")]
    Io {
        /// The path.
        path: String,
        /// The operating system's reason.
        reason: String,
    },
    /// A file or stream could not be written.
    #[error("cannot write {path}: {reason}")]
    Write {
        /// The path (or `stdout`).
        path: String,
        /// The operating system's reason.
        reason: String,
    },
    /// A request beyond the documented size limits.
    #[error("{what} has {count} entries, more than the limit of {limit}")]
    TooLarge {
        /// What is too large.
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
