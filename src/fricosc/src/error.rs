//! The library's errors: what was asked of the physics and could not be done.
//! Every message is one line and names the problem. Reading and writing files
//! and streams, and exit codes, are the caller's business (the command line's
//! own error type wraps this one).

use thiserror::Error;

/// Everything that can go wrong in a computation, with the context to act on it.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum Error {
    /// A numeric parameter is NaN, infinite or outside its domain.
    #[error("invalid {name} = {}: {reason}", Amount(*value))]
    InvalidParameter {
        /// Parameter name as the user writes it (`vbar`, `amp`, ...).
        name: &'static str,
        /// The offending value.
        value: f64,
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
    /// The file a tabulated shape or a scene names could not be read (by the
    /// reader the caller passed in; its error is kept as the source).
    #[error("cannot read {path}: {source}")]
    File {
        /// The path as the specification names it.
        path: String,
        /// The reader's reason.
        #[source]
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// Malformed input text or columns (a profile table, a scene, a table to validate).
    #[error("{context}: {reason}")]
    Parse {
        /// Where: a file name, a field, a row.
        context: String,
        /// What is wrong.
        reason: String,
    },
    /// An internal result is not finite or outside its mathematical range: a bug
    /// of fricosc (or an input at the edge of what f64 can represent), never
    /// reported as a number.
    #[error("internal error: {what} (please report this with the command that caused it)")]
    Internal {
        /// What was computed and the value it had.
        what: String,
    },
    /// The solve was asked to stop ([`crate::interrupt::request`]).
    #[error("interrupted")]
    Interrupted,
    /// A request beyond the documented size limits (checked before the work).
    #[error("{what}: {count} is more than the limit of {limit}")]
    TooLarge {
        /// What is counted (`history rows`, `profile rows`).
        what: String,
        /// Its size.
        count: u128,
        /// The limit.
        limit: u128,
    },
}

/// Result alias for fricosc.
pub type Result<T> = std::result::Result<T, Error>;

/// A number in a message: the shortest text that reads back to it, with an
/// exponent from 1e6 up and below 1e-4 (`1e15`, not `1000000000000000.0`).
pub(crate) struct Amount(pub(crate) f64);

impl std::fmt::Display for Amount {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let a = self.0.abs();
        if a.is_finite() && a != 0.0 && !(1e-4..1e6).contains(&a) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{:?}", self.0)
        }
    }
}

impl Error {
    /// Shorthand for [`Error::InvalidParameter`].
    #[must_use]
    pub fn param(name: &'static str, value: f64, reason: &str) -> Self {
        Error::InvalidParameter { name, value, reason: reason.into() }
    }

    /// True for an internal error (a bug to report, not bad input).
    #[must_use]
    pub fn is_internal(&self) -> bool {
        matches!(self, Error::Internal { .. })
    }
}

/// Check that `x` is finite and `>= 0`: the check (and message) of every
/// velocity and amplitude, for callers that check inputs before computing.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `name` otherwise.
pub(crate) fn check_nonneg(name: &'static str, x: f64) -> Result<f64> {
    if !x.is_finite() {
        Err(Error::param(name, x, "must be finite"))
    } else if x < 0.0 {
        Err(Error::param(name, x, "must be >= 0"))
    } else {
        Ok(x)
    }
}

#[cfg(test)]
mod tests {
    use super::Error;

    /// Numbers in messages: an exponent from 1e6 up and below 1e-4, the
    /// shortest text otherwise (`1e15` was `1000000000000000.0` beside `1e300`).
    #[test]
    fn amounts_print_alike() {
        for (x, text) in [
            (1e15, "1e15"),
            (1e300, "1e300"),
            (-1.0, "-1.0"),
            (0.3, "0.3"),
            (1e-7, "1e-7"),
            (0.0, "0.0"),
            (f64::NAN, "NaN"),
        ] {
            assert_eq!(Error::param("amp", x, "r").to_string(), format!("invalid amp = {text}: r"));
        }
    }
}
