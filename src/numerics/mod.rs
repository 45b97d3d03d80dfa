//! Numerics: bracketed root finding, Gauss-Jacobi rules, cancellation-free
//! elementary functions.
pub mod decimal;
pub mod quad;
pub mod root;
pub mod special;
