//! Numerics: bracketed root finding, Gauss-Jacobi rules, cancellation-free
//! elementary functions.
pub mod decimal;
pub(crate) mod par;
pub mod quad;
pub mod root;
pub mod special;
