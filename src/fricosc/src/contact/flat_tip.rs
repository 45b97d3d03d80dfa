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
//! The flat part `z < E` is `E` springs of the flat punch (`s = 1/amp`). The
//! curved part is integrated in `t = sqrt(G)`, in which
//! `z^2 = (E^2 + sqrt(E^4 + 4 t^4 (1 - E^2)))/2` and
//! `dz/dt = 2 t^3 (1 - E^2) / (z sqrt(E^4 + 4 t^4 (1 - E^2)))` is smooth for
//! every `E` (it is 1 at `E = 0`) and turns from `z ~ E` to `z ~ t` around
//! `t ~ E` (cuts at `E 2^k`, `|k| <= 4`, keep each piece smooth on its scale).
//! For `amp > 1`, lengths are divided by `sqrt(amp)` (`t`, `z` and `E` alike,
//! which leaves the form of `z(t)` unchanged and `s = 1/amp - t^2`), so that
//! huge amplitudes cannot overflow; the ratio is unaffected. It is split at the regime thresholds
//! `s = (1 - t^2)/amp = 1, +-sqrt(1 - vbar^2), -1`, and each band is integrated
//! with `t = p + (q - p)(1 - cos theta)/2` (which absorbs the square-root
//! behaviour of the means at `s = +-1`) by Gauss-Legendre at orders 8, 16, 32,
//! ... until two successive orders agree to the tolerance (each of the mean
//! normal force, the deficit and the mean tangential force); their difference
//! is the band's error estimate. `mu` is the quotient of the tangential and the
//! normal force where it is the small one (`amp` near or above 1, `vbar -> 0`),
//! else `1 - ` that of the deficit (`ratio::from_sums`).

use super::Contact;
use crate::error::{Error, Result};
use crate::ratio::Ratio;
use crate::shape::Evaluation;
use std::sync::Arc;

/// First Gauss order per band (then doubled).
const FIRST_ORDER: usize = 8;
/// Highest Gauss order tried per band.
const MAX_ORDER: usize = 512;

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

    /// `[int <B> dz, int D dz, int <F> dz]` over the band `t` in `[p, q]` at
    /// Gauss order `m`, in units of `kz du` times `unit` (`amp` for `amp <= 1`,
    /// else 1); `s(t)` is the springs' `s`.
    fn band(&self, p: f64, q: f64, vbar: f64, s_of: &dyn Fn(f64) -> f64, unit: f64, m: usize) -> [f64; 3] {
        super::cosine_band(p, q, m, vbar, unit, &|t| (s_of(t), self.z_of_t(t).1))
    }
}

impl FlatTip {
    fn curved(&self) -> Curved {
        Curved { e: self.flat_ratio, k: (1.0 - self.flat_ratio) * (1.0 + self.flat_ratio) }
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

    fn evaluate(&self, vbar: f64, amp: f64, tol: f64) -> Result<Evaluation> {
        crate::error::check_nonneg("vbar", vbar)?;
        crate::error::check_nonneg("amp", amp)?;
        if amp == 0.0 || vbar >= 1.0 {
            let ratio = Ratio { mu_ratio: 1.0, reduction: 0.0 };
            return Ok(Evaluation { ratio, error_estimate: 0.0, interpolation_error: None });
        }
        if vbar == 0.0 && amp >= 1.0 {
            // Every spring loses contact and sticks from contact to loss: none
            // slides (exactly 0, not 1 minus a rounded reduction).
            let ratio = Ratio { mu_ratio: 0.0, reduction: 1.0 };
            return Ok(Evaluation { ratio, error_estimate: 0.0, interpolation_error: None });
        }
        let at = crate::contact::VelocityScale::of(vbar, amp);
        if at.vbar != vbar {
            let e = self.evaluate(at.vbar, amp, tol)?;
            let (ratio, error_estimate) = at.back(e.ratio, e.error_estimate);
            return Ok(Evaluation { ratio, error_estimate, interpolation_error: None });
        }
        if amp < crate::contact::AMP_LINEAR {
            let at = self.evaluate(vbar, crate::contact::AMP_LINEAR, tol)?;
            let k = amp / crate::contact::AMP_LINEAR;
            let ratio = at.ratio.scaled(k);
            return Ok(Evaluation { ratio, error_estimate: at.error_estimate * k, interpolation_error: None });
        }
        let tol = tol.max(crate::DEFAULT_TOL);
        // Forces in units of kz u0 (amp <= 1) or kz du (amp > 1): both finite.
        let unit = if amp <= 1.0 { amp } else { 1.0 };
        let flat = crate::flat::spring(vbar, amp, crate::model::spring::Precision::Means);
        // Lengths scaled by sqrt(amp) for amp > 1 (module docs).
        let big = amp > 1.0;
        let scale = if big { amp.sqrt() } else { 1.0 };
        // A scaled flat below 1e-154 (amp above 1e307) weighs less than 1e-154 of
        // the contact, and its square would be subnormal: it is dropped.
        let e = Some(self.flat_ratio / scale).filter(|e| (e * e).is_normal()).unwrap_or(0.0);
        let curved = Curved { e, k: (1.0 - self.flat_ratio) * (1.0 + self.flat_ratio) };
        // The flat's <F> as the flat punch's mu times its <B>: for amp <= 1 its
        // s = 1/amp is rounded, and <F> = s - c + ... would cancel as vbar -> 0.
        let flat_mu = crate::flat::ratio_of(&flat, amp)?.mu_ratio;
        let mut sums = [flat.mean_normal, flat.deficit, flat.mean_normal * flat_mu].map(|x| e * unit * x);
        let c = ((1.0 - vbar) * (1.0 + vbar)).sqrt();
        // s(t) = (1 - t^2)/amp, or 1/amp - t^2 in scaled lengths; 1 - t^2 = (1 - t)(1 + t).
        let s_of = move |t: f64| if big { 1.0 / amp - t * t } else { (1.0 - t) * (1.0 + t) / amp };
        let t_of = |s: f64| if big { (1.0 / amp - s).max(0.0).sqrt() } else { (1.0 - amp * s).max(0.0).sqrt() };
        let t_max = t_of(-1.0);
        let mut cuts = vec![0.0, t_of(1.0), t_of(c), t_of(-c), t_max];
        if e > 0.0 {
            cuts.extend((-4..=4).map(|k| e * 2f64.powi(k)).filter(|&g| g < t_max));
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        let (mut errors, mut nodes) = ([0.0; 3], 0usize);
        for w in cuts.windows(2) {
            let (p, q) = (w[0], w[1]);
            if q <= p {
                continue;
            }
            let mut m = FIRST_ORDER;
            let mut prev = curved.band(p, q, vbar, &s_of, unit, m);
            nodes += m;
            loop {
                m *= 2;
                let cur = curved.band(p, q, vbar, &s_of, unit, m);
                nodes += m;
                let d: [f64; 3] = std::array::from_fn(|k| (cur[k] - prev[k]).abs());
                // Each of the three sums to the tolerance relative to its total
                // so far (the tangential force too: it gives mu where mu is small).
                let done = (0..3).all(|k| d[k] <= tol * (sums[k].abs() + cur[k].abs()));
                if done || m >= MAX_ORDER {
                    for k in 0..3 {
                        sums[k] += cur[k];
                        errors[k] += d[k];
                    }
                    break;
                }
                prev = cur;
            }
        }
        let (ratio, estimate) = crate::ratio::from_sums(sums, errors, nodes, "flat-tip contact")?;
        Ok(Evaluation { ratio, error_estimate: estimate, interpolation_error: None })
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
