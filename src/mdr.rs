//! Curved indenters by the method of dimensionality reduction (seed section 3).
//!
//! The contact is an elastic foundation of independent springs along `x`; with
//! `z = x/x_c` (`x_c` the contact radius at the mean indentation) and an
//! equivalent profile `g(z) = z^n` (normalised so that `g(1) = 1`), the spring
//! at `z` has `s(z) = (1 - z^n)/amp`, and all springs share `vbar`. Then
//! `mu_macro/mu0 = int <F>(s(z)) dz / int <B>(s(z)) dz`, and the reduction is
//! `int D(s(z)) dz / int <B>(s(z)) dz` with the per-spring deficit `D` of [`crate::spring`].
//!
//! # Bands
//! With `c = sqrt(1 - vbar^2)`, the single-spring regime changes at `s = 1`,
//! `s = +-c` and `s = -1`, and only `s > -1`, i.e. `z < (1 + amp)^(1/n)`, ever
//! touches. The bands (clipped to the springs present, `s <= 1/amp`):
//! - permanent contact `s >= 1`: normal force in closed form, deficit `D(vbar)`
//!   per spring, so its share is `D(vbar)` times the band length;
//! - slip first `c <= s < 1`: the same constant deficit, normal force by quadrature;
//! - stick first `|s| < c`: both by quadrature;
//! - slip only `-1 < s <= -c`: no deficit, normal force by quadrature.
//!
//! # Quadrature
//! In the variable `y = z^n = 1 - amp s` the integrands are analytic functions
//! of `y` inside each band times `dz = y^(1/n - 1) dy / n`. At `s = +-1` they
//! behave like `(distance)^(3/2)` (contact-loss thresholds); the substitution
//! `y = p + (q - p)(1 - cos t)/2` makes them analytic in `t`, and Gauss-Legendre
//! in `t` converges geometrically. A band starting at the centre `y = 0` carries
//! the weight `y^(1/n - 1)`, which becomes `t^(2/n - 1)` after the substitution:
//! Gauss-Jacobi. A band starting at a small `p > 0` (the branch point `y = 0` close
//! by, e.g. `amp -> 1`) is split geometrically at `p, 2p, 4p, ...`. Each piece is
//! integrated at orders `m, 2m, 4m, ...` from `m = 4` until the error predicted
//! from the last two differences is within the relative tolerance (see `piece`).

use crate::flat::Ratio;
use crate::quad;
use crate::spring::{mean_normal, Spring};
use serde::Serialize;
use std::f64::consts::PI;

/// Highest Gauss order tried per piece.
pub const MAX_ORDER: usize = 256;
/// First order tried per piece.
pub const MIN_ORDER: usize = 4;
/// Default relative tolerance: about what f64 allows.
pub const DEFAULT_TOL: f64 = 4e-15;
/// Rounding floor added to every error estimate.
const ROUNDING_FLOOR: f64 = 8.0 * f64::EPSILON;

/// The regime of a band of springs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BandKind {
    /// `s >= 1`: springs never lose contact.
    PermanentContact,
    /// `sqrt(1 - vbar^2) <= s < 1`: contact lost; slip before the stick.
    SlipFirst,
    /// `|s| < sqrt(1 - vbar^2)`: stick from the moment of contact.
    StickFirst,
    /// `-1 < s <= -sqrt(1 - vbar^2)` (or any `|s| < 1` when `vbar >= 1`): no stick.
    SlipOnly,
}

/// One band: its extent and its share of the mean forces.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Band {
    /// Regime of the springs in the band.
    pub kind: BandKind,
    /// Extent in `x / x_c` (from the centre outwards).
    pub x_range: [f64; 2],
    /// Fraction of the mean normal force carried by the band.
    pub normal_share: f64,
    /// Fraction of the mean tangential force carried by the band.
    pub tangential_share: f64,
    /// Quadrature nodes spent on the band (0: closed form).
    pub nodes: usize,
}

/// Result of an MDR evaluation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MdrResult {
    /// Ratio and reduction.
    #[serde(flatten)]
    pub ratio: Ratio,
    /// Estimated absolute error of `mu_ratio` (an upper bound in all tests).
    pub error_estimate: f64,
    /// The bands, from the centre outwards (empty ones left out).
    pub bands: Vec<Band>,
    /// Springs (quadrature nodes) evaluated in all.
    pub nodes: usize,
}

/// Integrals over one piece: `(int amp <B> dz, int amp D dz)`, error estimates, nodes.
#[derive(Debug, Clone, Copy, Default)]
struct Sums {
    normal: f64,
    deficit: f64,
    err_normal: f64,
    err_deficit: f64,
    nodes: usize,
}

impl std::ops::AddAssign for Sums {
    fn add_assign(&mut self, o: Sums) {
        self.normal += o.normal;
        self.deficit += o.deficit;
        self.err_normal += o.err_normal;
        self.err_deficit += o.err_deficit;
        self.nodes += o.nodes;
    }
}

struct Problem {
    n: f64,
    amp: f64,
    vbar: f64,
    tol: f64,
    /// Whether the band has a deficit to integrate.
    stick: bool,
}

impl Problem {
    /// `amp <B>(s)` and `amp D(s)` at `y`, times `dz/dy = y^(1/n-1)/n` unless `weighted`.
    fn integrand(&self, y: f64) -> (f64, f64) {
        let s = (1.0 - y) / self.amp;
        if self.stick {
            let sp = Spring::new(s, self.vbar);
            (self.amp * sp.mean_normal, self.amp * sp.deficit)
        } else {
            (self.amp * mean_normal(s), 0.0)
        }
    }

    /// One Gauss pass of order `m` over `[p, q]` in `t` (see module docs).
    fn pass(&self, p: f64, q: f64, m: usize) -> (f64, f64) {
        let inv_n = 1.0 / self.n;
        let (mut sn, mut sd) = (0.0, 0.0);
        if p == 0.0 {
            // y = q sin^2(t/2); y^(1/n-1) dy = q^(1/n) sin(t/2)^(2/n-1) cos(t/2) dt; weight t^(2/n-1).
            let beta = 2.0 * inv_n - 1.0;
            let r = quad::rule(m, beta);
            let scale = (0.5 * PI).powf(beta + 1.0) * q.powf(inv_n) * inv_n;
            for (&x, &w) in r.nodes.iter().zip(&r.weights) {
                let t = 0.5 * PI * (1.0 + x);
                let h = (0.5 * t).sin();
                let y = q * h * h;
                let jac = if beta == 0.0 { 1.0 } else { (h / t).powf(beta) } * (0.5 * t).cos();
                let (fb, fd) = self.integrand(y);
                sn += w * jac * fb;
                sd += w * jac * fd;
            }
            (scale * sn, scale * sd)
        } else {
            let r = quad::rule(m, 0.0);
            let half = 0.5 * (q - p);
            for (&x, &w) in r.nodes.iter().zip(&r.weights) {
                let t = 0.5 * PI * (1.0 + x);
                let (st, ct) = t.sin_cos();
                let y = p + half * (1.0 - ct);
                let jac = half * st * y.powf(inv_n - 1.0) * inv_n;
                let (fb, fd) = self.integrand(y);
                sn += w * jac * fb;
                sd += w * jac * fd;
            }
            (0.5 * PI * sn, 0.5 * PI * sd)
        }
    }

    /// Integrate one piece, doubling the order from [`MIN_ORDER`].
    ///
    /// With `d_m = |Q_2m - Q_m|` (about the error of `Q_m`), geometric
    /// convergence predicts the error of `Q_4m` as `d_2m^2 / d_m`. `Q_4m` is
    /// accepted when that prediction, times a safety factor of 10, is within the
    /// relative tolerance and the differences are decreasing; the reported
    /// error is that product (never below the rounding floor of the caller).
    fn piece(&self, p: f64, q: f64) -> Sums {
        let mut m = MIN_ORDER;
        let q1 = self.pass(p, q, m);
        let q2 = self.pass(p, q, 2 * m);
        let mut cur = q2;
        let mut d_prev = ((q2.0 - q1.0).abs(), (q2.1 - q1.1).abs());
        let mut nodes = 3 * m;
        loop {
            m *= 2;
            let next = self.pass(p, q, 2 * m);
            nodes += 2 * m;
            let d = ((next.0 - cur.0).abs(), (next.1 - cur.1).abs());
            let predict = |dc: f64, dp: f64| {
                if dc == 0.0 {
                    0.0
                } else if dc < dp {
                    10.0 * dc * dc / dp
                } else {
                    dc
                }
            };
            let (en, ed) = (predict(d.0, d_prev.0), predict(d.1, d_prev.1));
            cur = next;
            if (en <= self.tol * cur.0.abs() && ed <= self.tol * cur.1.abs()) || 2 * m >= MAX_ORDER {
                return Sums {
                    normal: cur.0,
                    deficit: cur.1,
                    err_normal: en,
                    err_deficit: ed,
                    nodes,
                };
            }
            d_prev = d;
        }
    }

    /// Integrate the band `[p, q]` in `y`, split geometrically near the branch point 0.
    fn band(&self, p: f64, q: f64) -> Sums {
        let mut total = Sums::default();
        if q <= p {
            return total;
        }
        let singular = self.n != 1.0;
        let mut lo = p;
        if singular && p > 0.0 {
            while 4.0 * lo < q - lo {
                total += self.piece(lo, 2.0 * lo);
                lo *= 2.0;
            }
        }
        total += self.piece(lo, q);
        total
    }
}

/// `mu_macro/mu0` of the power-law profile `g = z^n` at `(vbar, amp)`.
///
/// `n > 0`, `vbar, amp` finite and `>= 0` (checked by [`crate::shape`]); `tol`
/// is the relative quadrature tolerance; `bands` asks for the per-band report.
pub fn power_law(n: f64, vbar: f64, amp: f64, tol: f64, bands: bool) -> MdrResult {
    let tol = tol.max(DEFAULT_TOL);
    let unit = MdrResult {
        ratio: Ratio {
            mu_ratio: 1.0,
            reduction: 0.0,
        },
        error_estimate: 0.0,
        bands: vec![],
        nodes: 0,
    };
    if amp == 0.0 || (vbar >= 1.0 && !bands) {
        return unit;
    }
    let c = if vbar < 1.0 { (1.0 - vbar * vbar).sqrt() } else { 0.0 };
    let d_perm = if vbar < 1.0 {
        Spring::new(f64::MAX, vbar).deficit
    } else {
        0.0
    };
    // Band limits in y = 1 - amp s, clipped to [0, 1 + amp].
    let y_of = |s: f64| (1.0 - amp * s).clamp(0.0, 1.0 + amp);
    let (y1, yc, ymc, yend) = (y_of(1.0), y_of(c), y_of(-c), 1.0 + amp);
    let z_of = |y: f64| y.powf(1.0 / n);
    let mk = |stick: bool| Problem {
        n,
        amp,
        vbar,
        tol,
        stick,
    };

    // Permanent contact: int_0^{z1} (1 - z^n) dz, deficit D(vbar) z1 (scaled by amp).
    let z1 = z_of(y1);
    let perm = Sums {
        normal: z1 - z1 * y1 / (n + 1.0),
        deficit: amp * d_perm * z1,
        ..Default::default()
    };
    let mut slip_first = mk(false).band(y1, yc);
    slip_first.deficit = amp * d_perm * (z_of(yc) - z1);
    let stick_first = mk(vbar < 1.0).band(yc, ymc);
    let slip_only = mk(false).band(ymc, yend);

    let parts = [
        (BandKind::PermanentContact, 0.0, y1, perm),
        (BandKind::SlipFirst, y1, yc, slip_first),
        (BandKind::StickFirst, yc, ymc, stick_first),
        (BandKind::SlipOnly, ymc, yend, slip_only),
    ];
    let mut total = Sums::default();
    for p in &parts {
        total += p.3;
    }
    let ratio = Ratio::from_deficit(total.deficit, total.normal);
    let (nn, dd) = (total.normal, total.deficit);
    let error_estimate = if nn > 0.0 {
        total.err_deficit / nn + dd * total.err_normal / (nn * nn) + ROUNDING_FLOOR
    } else {
        ROUNDING_FLOOR
    };
    let tangential = nn - dd;
    let band_list = if bands {
        parts
            .iter()
            .filter(|p| p.2 > p.1)
            .map(|&(kind, ya, yb, s)| Band {
                kind,
                x_range: [z_of(ya), z_of(yb)],
                normal_share: if nn > 0.0 { s.normal / nn } else { 0.0 },
                tangential_share: if tangential > 0.0 {
                    (s.normal - s.deficit) / tangential
                } else {
                    0.0
                },
                nodes: s.nodes,
            })
            .collect()
    } else {
        vec![]
    };
    MdrResult {
        ratio,
        error_estimate,
        bands: band_list,
        nodes: total.nodes,
    }
}

/// A full MDR point: the result plus the static limit, for `fricosc point`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MdrPoint {
    /// Dimensionless velocity (eq. 3).
    pub vbar: f64,
    /// Amplitude `du/u0`.
    pub amp: f64,
    /// Result at `(vbar, amp)` with bands.
    #[serde(flatten)]
    pub result: MdrResult,
    /// `mu_static/mu0`, the limit `vbar -> 0+`: minimum over mean normal force.
    pub mu_static_ratio: f64,
}

/// [`power_law`] with the bands and the static limit; inputs are checked.
pub fn point(n: f64, vbar: f64, amp: f64, tol: f64) -> crate::Result<MdrPoint> {
    crate::error::check_nonneg("vbar", vbar)?;
    crate::error::check_nonneg("amp", amp)?;
    crate::shape::check_tol(tol)?;
    let result = power_law(n, vbar, amp, tol, true);
    let mu_static_ratio = power_law(n, 0.0, amp, tol, false).ratio.mu_ratio;
    Ok(MdrPoint {
        vbar,
        amp,
        result,
        mu_static_ratio,
    })
}
