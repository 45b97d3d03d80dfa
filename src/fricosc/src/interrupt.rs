//! Stopping long solves from outside: a caller that is asked to stop (Python
//! on Ctrl-C) calls [`request`]; every solve of a body on a system then
//! returns [`crate::Error::Interrupted`] at its next period, and the caller
//! calls [`clear`] once they have returned. The request is process-wide, as
//! the signal that causes it is. The stiff solvers answer a point in
//! microseconds and are not checked: their callers check between chunks.

use std::sync::atomic::{AtomicBool, Ordering};

static REQUESTED: AtomicBool = AtomicBool::new(false);

/// Ask every running solve on a system to stop at its next period.
pub fn request() {
    REQUESTED.store(true, Ordering::Relaxed);
}

/// Let solves run again (after the interrupted ones have returned).
pub fn clear() {
    REQUESTED.store(false, Ordering::Relaxed);
}

/// [`crate::Error::Interrupted`] where a stop was requested.
pub(crate) fn check() -> crate::Result<()> {
    match REQUESTED.load(Ordering::Relaxed) {
        true => Err(crate::Error::Interrupted),
        false => Ok(()),
    }
}
