//! A sphere worn flat at its tip ("a curved body with a flat end (e.g. due to
//! wear)", seed section 3): `flat-tip:E`.
//!
//! # MDR profile
//! The body is a paraboloid of radius `R` cut flat at radius `a`:
//! `f(r) = 0` for `r <= a`, `(r^2 - a^2)/(2R)` beyond. Its MDR equivalent
//! profile is `g(x) = |x| int_0^|x| f'(r)/sqrt(x^2 - r^2) dr =
//! (|x|/R) int_a^|x| r/sqrt(x^2 - r^2) dr = |x| sqrt(x^2 - a^2)/R` for `|x| > a`,
//! and 0 inside the flat. With the contact radius `x_c` at the mean indentation
//! (`g(x_c) = u0`), `z = x/x_c` and `E = a/x_c` in `[0, 1)`:
//! `G(z) = g/u0 = z sqrt(z^2 - E^2)/sqrt(1 - E^2)` for `z >= E`, 0 below.
//! `E = 0` is the paraboloid (`G = z^2`, Hertz), `E -> 1` the flat punch.
//!
//! # Integration
//! By the banded integrator over the geometry ([`integrate::mdr`]), along
//! `p = z` on the flat and `p = E + t` beyond it, `t = sqrt(G)`, in which
//! `z^2 = (E^2 + sqrt(E^4 + 4 t^4 (1 - E^2)))/2` and
//! `dz/dt = 2 t^3 (1 - E^2) / (z sqrt(E^4 + 4 t^4 (1 - E^2)))` are smooth for
//! every `E` (`dz/dt = 1` at `E = 0`); `z(t)` turns from `E` to `t` around
//! `t ~ E`, where the bands beyond a thin flat are graded towards it.

use super::Contact;
use crate::error::{Error, Result};
use crate::integrate;
use crate::shape::Evaluation;
use std::sync::Arc;

/// A sphere worn flat at its tip; `flat_ratio = a/x_c`, the flat's radius over
/// the contact radius at the mean indentation, in `[0, 1)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatTip {
    /// `E = a/x_c`.
    pub flat_ratio: f64,
}

/// The curved part in (possibly scaled) lengths: `e` the flat's radius, `k = 1 - E^2`.
#[derive(Debug, Clone, Copy)]
struct Curved {
    e: f64,
    k: f64,
}

/// Parse the `E` of `flat-tip:E`.
pub(crate) fn parse(rest: &str) -> Result<Arc<dyn Contact>> {
    let bad = |reason: &str| Error::InvalidShape { spec: format!("flat-tip:{rest}"), reason: reason.into() };
    let e: f64 = rest.trim().parse().map_err(|_| bad("E (flat radius / contact radius) is not a number"))?;
    if !(0.0..1.0).contains(&e) {
        return Err(bad("E = a/x_c must be in [0, 1): the flat inside the contact"));
    }
    Ok(Arc::new(FlatTip { flat_ratio: e + 0.0 }))
}

impl Curved {
    /// `(z, dz/dt)` at `t = sqrt(G)` on the curved part.
    fn z_of_t(&self, t: f64) -> (f64, f64) {
        let (e2, k) = (self.e * self.e, self.k);
        if t == 0.0 {
            return (self.e, if self.e > 0.0 { 0.0 } else { 1.0 });
        }
        if t < self.e {
            // Inside the flat's scale, in r = t/E (t^2 may underflow where r
            // does not): sqrt(E^4 + 4 t^4 k) = E^2 w with w = sqrt(1 + 4 r^4 k),
            // z = E sqrt((1 + w)/2), dz/dt = 2 t^3 k/(z E^2 w) = 2 k r^3 E/(z w).
            let r = t / self.e;
            let r2 = r * r;
            let w = (1.0 + 4.0 * r2 * r2 * k).sqrt();
            let z = self.e * (0.5 * (1.0 + w)).sqrt();
            return (z, 2.0 * k * r2 * r * (self.e / z) / w);
        }
        // sqrt(E^4 + 4 t^4 k) = 2 t^2 root, root = sqrt(k + (E^2/(2 t^2))^2): no t^4
        // (overflow), and t >= E keeps t^2 as normal as E^2 is.
        let t2 = t * t;
        let q = 0.5 * e2 / t2;
        let root = (k + q * q).sqrt();
        let z = (0.5 * e2 + t2 * root).sqrt();
        // dz/dt = 2 t^3 k / (z 2 t^2 root) = k (t/z) / root.
        (z, k * (t / z) / root)
    }
}

impl FlatTip {
    fn curved(&self) -> Curved {
        Curved { e: self.flat(), k: (1.0 - self.flat_ratio) * (1.0 + self.flat_ratio) }
    }

    /// The flat's radius as the quadrature takes it: a flat whose square is
    /// not a normal double (below 1e-154) weighs less than 1e-154 of the
    /// contact and is dropped (near it `t^2` would underflow where `t` does not).
    fn flat(&self) -> f64 {
        let e = self.flat_ratio;
        if (e * e).is_normal() {
            e
        } else {
            0.0
        }
    }
}

/// The worn tip along `p = z` on the flat (`G = 0`) and `p = E + t` beyond,
/// `t = sqrt(G)`, in which `z(t)` is smooth ([`Curved::z_of_t`]): in `z`,
/// `G` starts like `sqrt(z - E)` at the flat's edge, and the levels of the
/// regime thresholds crowd there (`z - E ~ G^2`), below the resolution of
/// `z` itself.
impl integrate::mdr::Profile for FlatTip {
    fn at(&self, p: f64) -> (f64, f64) {
        let e = self.flat();
        if p <= e {
            (0.0, 1.0)
        } else {
            let t = p - e;
            (t * t, self.curved().z_of_t(t).1)
        }
    }
    fn level(&self, level: f64) -> f64 {
        self.flat() + level.sqrt()
    }
    /// The flat's edge (the bands beyond it are graded towards it where the
    /// flat is thin: `z(t)` turns from `E` to `t` over a few `E`).
    fn breakpoints(&self) -> Vec<f64> {
        vec![self.flat()]
    }
}

impl Contact for FlatTip {
    fn name(&self) -> String {
        format!("flat-tip:{:?}", self.flat_ratio)
    }

    /// `G(z) = z sqrt(z^2 - E^2)/sqrt(1 - E^2)` beyond the flat, 0 on it.
    fn equivalent_profile(&self, z: f64) -> f64 {
        let (e, c) = (self.flat_ratio, self.curved());
        if z <= e {
            0.0
        } else {
            z * ((z - e) * (z + e)).sqrt() / c.k.sqrt()
        }
    }

    /// In closed form: `z(t)` at `t = sqrt(level)`.
    fn level(&self, level: f64) -> f64 {
        self.curved().z_of_t(level.sqrt()).0
    }

    fn reach(&self, amp: f64) -> Result<f64> {
        Ok(self.curved().z_of_t((1.0 + amp).sqrt()).0)
    }

    /// With `z_c` the contact's edge at depth `c` (`G(z_c) = c`) and
    /// `int z sqrt(z^2 - E^2) dz = (z^2 - E^2)^(3/2)/3`:
    /// `F = 2 (c z_c - (z_c^2 - E^2)^(3/2) / (3 sqrt(1 - E^2)))`, where
    /// `z_c^2 - E^2 = c^2 k / (c root + E^2/2)` (`t^2 = c`, `Curved::z_of_t`'s
    /// `root`) has no cancellation as `c -> 0`. `E = 0` gives Hertz, `(4/3) c^(3/2)`.
    fn static_force(&self, depth: f64) -> f64 {
        if depth <= 0.0 {
            return 0.0;
        }
        let c = self.curved();
        let (zc, _) = c.z_of_t(depth.sqrt());
        let q = 0.5 * c.e * c.e / depth;
        let root = (c.k + q * q).sqrt();
        let w = depth * depth * c.k / (depth * root + 0.5 * c.e * c.e);
        2.0 * (depth * zc - w * w.sqrt() / (3.0 * c.k.sqrt()))
    }

    /// The banded integrator over its geometry (`integrate::mdr`).
    fn evaluate(&self, vbar: f64, amp: f64, tol: f64) -> Result<Evaluation> {
        crate::error::check_nonneg("vbar", vbar)?;
        crate::error::check_nonneg("amp", amp)?;
        let (ratio, error_estimate) = integrate::mdr::evaluate(self, vbar, amp, tol, "flat-tip contact")?;
        Ok(Evaluation::of(ratio, error_estimate))
    }

    /// The edge of the flat, where `G` starts like a square root.
    fn breakpoints(&self) -> Vec<f64> {
        vec![self.flat_ratio]
    }
}

#[cfg(test)]
mod tests {
    use super::Curved;

    /// `z(t)` and `dz/dt` at the axis (the limits `z = E`, `dz/dt = 0` for a
    /// flat, 1 for the paraboloid, where the general form is 0/0), and the two
    /// forms (inside the flat's scale `t < E`, beyond it) meeting at `t = E`.
    #[test]
    fn the_map_at_the_axis_and_across_the_flat_scale() {
        for e in [0.0, 0.3, 0.9] {
            let c = Curved { e, k: (1.0 - e) * (1.0 + e) };
            assert_eq!(c.z_of_t(0.0), (e, if e > 0.0 { 0.0 } else { 1.0 }), "E = {e}");
            if e > 0.0 {
                let (below, above) = (c.z_of_t(e * (1.0 - 1e-12)), c.z_of_t(e * (1.0 + 1e-12)));
                assert!((below.0 / above.0 - 1.0).abs() < 1e-11 && (below.1 / above.1 - 1.0).abs() < 1e-11);
                // z^2 (z^2 - E^2) = t^4 (1 - E^2) on both sides.
                for t in [0.5 * e, e, 2.0 * e] {
                    let z = c.z_of_t(t).0;
                    assert!((z * z * (z * z - e * e) / (t.powi(4) * c.k) - 1.0).abs() < 1e-13, "E = {e}, t = {t}");
                }
            }
        }
    }
}
