//! Load control: a dead-weight rig holds each row's mean normal force
//! (`load`, N), so a row's mean indentation follows the shape's force law
//! rather than staying one `u0` for all rows.
//!
//! For a self-similar shape (the flat punch, the power laws: the static force
//! `S(d) = S(1) d^q`) the mean force at mean indentation `u` and amplitude
//! `du` is that at unit depth scaled, `u^q M(du/u)`, `M` the period-averaged
//! force at unit depth ([`crate::contact::Contact::mean_normal`]). With the
//! fitted `u0` the static indentation at the reference load `L_ref` (the
//! rows' median), a row's `u = x u0` solves
//!
//! `h(x) = x^q M(du/(x u0)) / S(1) - L/L_ref = 0`.
//!
//! `h` grows with `x` (from `(du/u0)^q lim M(a)/(a^q S(1)) - L/L_ref` to
//! infinity): one root. It lies at or below `(L/L_ref)^(1/q)`, where `M >=
//! S(1)` (`(d)_+^q` is convex for `q >= 1`: Jensen) makes `h >= 0`; below,
//! the bracket is halved until `h < 0`. Where it never is, the oscillation's
//! mean force exceeds the load at any indentation: the row is refused.

use super::Measurement;
use crate::error::{Error, Result};
use crate::shape::Shape;

/// The exponent `q` of a self-similar shape's force law `S(d) = S(1) d^q`;
/// any other shape is refused (load control needs the law at every depth).
pub(super) fn exponent(shape: &Shape) -> Result<f64> {
    let s = |d: f64| shape.contact().static_force(d);
    let q = (s(2.0) / s(1.0)).log2();
    let same = [(0.25, 0.5), (2.0, 4.0), (8.0, 16.0)].iter().all(|&(a, b)| ((s(b) / s(a)).log2() - q).abs() <= 1e-12);
    if !(same && q.is_finite() && q >= 1.0) {
        let reason = "load control needs a self-similar shape (flat, parabolic, cone, power:n), whose force law \
                      holds at every depth; leave the load column out to fit one u0 for all rows";
        return Err(Error::Parse { context: format!("load (shape {})", shape.name()), reason: reason.into() });
    }
    Ok(q)
}

/// The rows with their loads over the reference load (the median), and that
/// reference; the rows unchanged and `None` without loads. Loads are on every
/// row or on none, each finite and `> 0`.
pub(super) fn relative(rows: &[Measurement]) -> Result<(Vec<Measurement>, Option<f64>)> {
    if rows.iter().all(|r| r.load.is_none()) {
        return Ok((rows.to_vec(), None));
    }
    let mut loads = vec![];
    for (i, r) in rows.iter().enumerate() {
        match r.load {
            Some(l) if l.is_finite() && l > 0.0 && l <= 1e100 => loads.push(l),
            Some(l) => return Err(Error::param("load", l, &format!("row {i}: a load must be finite and > 0 (N)"))),
            None => return Err(Error::param("load", f64::NAN, &format!("row {i}: give a load on every row or none"))),
        }
    }
    let mut sorted = loads.clone();
    sorted.sort_by(f64::total_cmp);
    let reference = sorted[sorted.len() / 2];
    let out = rows.iter().zip(loads).map(|(r, l)| Measurement { load: Some(l / reference), ..*r }).collect();
    Ok((out, Some(reference)))
}

/// A row's mean indentation (m) at the relative load `load` and amplitude
/// `du` (m), `u0` the static indentation at the reference load, `q` the
/// shape's exponent (module docs); `None` where the oscillation's mean force
/// exceeds the load at any indentation (no such `u0` is a fit's answer).
pub(super) fn indentation(shape: &Shape, q: f64, u0: f64, load: f64, du: f64) -> Result<Option<f64>> {
    let s1 = shape.contact().static_force(1.0);
    let h = |x: f64| -> Result<f64> { Ok(x.powf(q) * shape.contact().mean_normal(du / (x * u0))? / s1 - load) };
    let hi = load.powf(1.0 / q);
    if h(hi)? <= 0.0 {
        return Ok(Some(hi * u0));
    }
    let mut lo = hi;
    for _ in 0..200 {
        lo *= 0.5;
        if h(lo)? < 0.0 {
            let f = |x: f64| h(x).unwrap_or(f64::NAN);
            return Ok(Some(crate::numerics::root::bracketed(f, lo, 2.0 * lo, 4.0 * f64::EPSILON).x * u0));
        }
    }
    Ok(None)
}

/// The error of a fit whose every `u0` leaves some row's load below the mean
/// force of its oscillation.
pub(super) fn unheld() -> Error {
    let reason = "no u0 holds every row's load: at the largest amplitudes the oscillation's mean normal force \
                  exceeds the smallest loads at any indentation (check the load column's units, N)";
    Error::param("load", f64::NAN, reason)
}
