//! Numerics: bracketed root finding, Gauss-Jacobi rules, cancellation-free
//! elementary functions.
pub(crate) mod decimal;
pub(crate) mod par;
pub(crate) mod quad;
pub(crate) mod root;
pub(crate) mod special;
