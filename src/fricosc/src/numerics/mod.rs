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

/// The `cases` of a reference file in `data/` (`name` relative to it), for
/// the unit tests that check against 25- or 40-digit values.
#[cfg(test)]
pub(crate) fn reference_cases(name: &str) -> Vec<serde_json::Value> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data").join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let v: serde_json::Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    v["cases"].as_array().cloned().unwrap_or_default()
}
