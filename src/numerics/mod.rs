//! Numerics: bracketed root finding, Gauss-Jacobi rules, cancellation-free
//! elementary functions.
pub(crate) mod decimal;
pub(crate) mod par;
pub(crate) mod quad;
pub(crate) mod root;
pub(crate) mod special;

/// `worst.max(x)` for the tests' running maxima, failing on a NaN `x`:
/// `f64::max` returns the other operand, so a NaN error would vanish and the
/// test's bar would pass (a wrong interpolant derivative did that to the MDR
/// transform's quadrature check).
#[cfg(test)]
pub(crate) fn worst_of(worst: f64, x: f64) -> f64 {
    assert!(!x.is_nan(), "a NaN error");
    worst.max(x)
}
