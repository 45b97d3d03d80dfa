//! The seed's problem over an MDR foundation described by its geometry
//! alone: the equivalent profile `G` (`G(1) = 1`) along a parameter `p` of
//! the geometry's choice (`z` itself, or one in which `G` is smooth: a worn
//! tip's `sqrt(G)`), with `dz/dp`; where it takes a given level; and where it
//! is not smooth. Every spring has `s = (1 - G)/amp` and the steady state of
//! [`Spring`]; the foundation's means are integrals over `z` in `[0, reach]`,
//! taken over `p`.
//!
//! # Bands
//! A spring's regime changes where `s = 1` (contact starts to be lost),
//! `s = +-sqrt(1 - vbar^2)` (slip first / stick first / slip only) and
//! `s = -1` (never touches): the levels `G = 1 - amp s`. Between those edges
//! and the geometry's breakpoints the means are smooth in `z` and vanish or
//! turn like a square root at the edges: each band runs [`cosine_pass`]es on
//! the [`Ladder`] (the widest band first; each next one's tolerance is
//! relative to the bands before it too).
//!
//! # Units
//! The sums are `[int <B> dz, int D dz, int <F> dz]` times `unit` (`amp` for
//! `amp <= 1`, then forces are in `kz u0`; 1 beyond, in `kz du`, so that a
//! huge amplitude cannot overflow); `mu` is the quotient of the tangential and
//! the normal force where it is the small one, else `1 -` that of the deficit
//! ([`crate::ratio::from_sums`]), each from its own cancellation-free mean.

use super::{cosine_pass, Ladder, Sums};
use crate::contact::{VelocityScale, AMP_LINEAR};
use crate::error::{Error, Result};
use crate::model::spring::{Precision, Spring};
use crate::ratio::Ratio;

/// An equivalent profile as the integrator sees it, along its parameter `p`
/// (`p = 0` at the axis, increasing with `z`).
pub(crate) trait Profile {
    /// `(G, dz/dp)` at `p`; `G` nondecreasing from 0.
    fn at(&self, p: f64) -> (f64, f64);
    /// `p` where `G = level` (a level no deeper than the contact reaches).
    fn level(&self, level: f64) -> f64;
    /// Where `G` is not smooth in `p` (or changes its scale), in `(0, reach)`.
    fn breakpoints(&self) -> Vec<f64>;
}

/// What the bands give: the ratio with its estimate and the sums (normal
/// force, deficit, tangential force, in the units of [`unit`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Integrated {
    pub(crate) ratio: Ratio,
    pub(crate) estimate: f64,
    pub(crate) sums: [f64; 3],
}

/// `mu_macro/mu0` and its error estimate of the foundation of `p` at
/// `(vbar, amp)`, both finite and `>= 0`, to the relative tolerance `tol`:
/// 1 without oscillation or at `vbar >= 1`; exactly 0 at `vbar = 0` once
/// every spring loses contact (`amp >= 1`: each sticks from contact to
/// loss); below `VBAR_LINEAR` (at `amp >= 1`, where `mu` is linear in
/// `vbar`) and [`AMP_LINEAR`] (where the reduction is linear in `amp`)
/// solved at those and scaled; else [`springs`].
///
/// # Errors
/// [`Error::Internal`] for a ratio out of range (a bug).
pub(crate) fn evaluate(p: &dyn Profile, vbar: f64, amp: f64, tol: f64, context: &str) -> Result<(Ratio, f64)> {
    if amp == 0.0 || vbar >= 1.0 {
        return Ok((Ratio::default(), 0.0));
    }
    if vbar == 0.0 && amp >= 1.0 {
        return Ok((Ratio { mu_ratio: 0.0, reduction: 1.0 }, 0.0));
    }
    let at = VelocityScale::of(vbar, amp);
    if at.vbar != vbar {
        let (ratio, estimate) = evaluate(p, at.vbar, amp, tol, context)?;
        return Ok(at.back(ratio, estimate));
    }
    if amp < AMP_LINEAR {
        let (ratio, estimate) = evaluate(p, vbar, AMP_LINEAR, tol, context)?;
        let k = amp / AMP_LINEAR;
        return Ok((ratio.scaled(k), estimate * k));
    }
    let r = springs(p, vbar, amp, tol, context)?;
    Ok((r.ratio, r.estimate))
}

/// The unit of the sums at `amp`: `amp` (forces in `kz u0`) up to 1, else 1.
pub(crate) fn unit(amp: f64) -> f64 {
    amp.min(1.0)
}

/// The foundation of `p` at `(vbar, amp)`, `amp > 0`, `vbar < 1`, to the
/// relative tolerance `tol`.
///
/// # Errors
/// [`Error::Internal`] for a ratio out of range (a bug).
pub(crate) fn springs(p: &dyn Profile, vbar: f64, amp: f64, tol: f64, context: &str) -> Result<Integrated> {
    let edges = edges(p, vbar, amp);
    let ladder = Ladder::new(tol);
    let unit = unit(amp);
    // The springs of the band: s = (1 - G)/amp (as 1/amp - G/amp beyond
    // amp = 1, where 1 - G would lose the digits of a deep spring), its
    // complement 1 - s = ((amp - 1) + G)/amp (beyond amp = 1 as (1 - 1/amp)
    // + G/amp, which cannot overflow) and its margin s - c = (1 - c) -
    // (1 - s), 1 - c = vbar^2/(1 + c), without cancellation: near s = 1 (the
    // flat of a worn tip at amp -> 1) a stick's start force s - c is far
    // smaller than the rounding of s itself.
    let one_minus_c = vbar * vbar / (1.0 + ((1.0 - vbar) * (1.0 + vbar)).sqrt());
    let node = |q: f64| {
        let (g, dz) = p.at(q);
        let (s, one_minus_s) = if amp > 1.0 {
            (1.0 / amp - g / amp, (1.0 - 1.0 / amp) + g / amp)
        } else {
            ((1.0 - g) / amp, ((amp - 1.0) + g) / amp)
        };
        let margin = (s > 0.0).then_some(one_minus_c - one_minus_s);
        let sp = Spring::with_complement(s, one_minus_s, vbar, Precision::Means, margin);
        let w = unit * dz;
        ([sp.mean_normal * w, sp.deficit * w, sp.mean_tangential() * w], 0.0)
    };
    // The widest band first: its sums set the scale of the others.
    let mut bands: Vec<(f64, f64)> = edges.windows(2).map(|w| (w[0], w[1])).filter(|(a, b)| b > a).collect();
    bands.sort_by(|x, y| (y.1 - y.0).total_cmp(&(x.1 - x.0)));
    let mut total = Sums::<3>::default();
    for (a, b) in bands {
        let scale = total.value.map(f64::abs);
        total += ladder.run(ladder.first_order(), |m| cosine_pass(a, b, m, [true; 3], &node), scale);
    }
    let (ratio, estimate) = crate::ratio::from_sums(total.value, total.error, total.nodes, context)?;
    if !total.value[0].is_finite() || total.value[0] <= 0.0 {
        return Err(Error::Internal { what: format!("mean normal force {:?} ({context})", total.value[0]) });
    }
    Ok(Integrated { ratio, estimate, sums: total.value })
}

/// The bands' edges: `0`, the reach, the regime thresholds inside, and the
/// breakpoints, sorted and distinct.
fn edges(p: &dyn Profile, vbar: f64, amp: f64) -> Vec<f64> {
    let c = ((1.0 - vbar) * (1.0 + vbar)).sqrt();
    // The spring at the level G = 1 - amp s (none where that level is below
    // 0); at s = c as (1 - amp) + amp (1 - c), 1 - c = vbar^2/(1 + c): the
    // slip-first band is as thin as vbar^2 at amp = 1, and 1 - amp c would
    // round it away (with the singular points at its edge that the band
    // beside it must be graded towards).
    let z_of = |level: f64| if level <= 0.0 { 0.0 } else { p.level(level) };
    let zmax = z_of(1.0 + amp);
    let slip_first = (1.0 - amp) + amp * (vbar * vbar / (1.0 + c));
    let mut cuts = vec![0.0, zmax, z_of(1.0 - amp), z_of(slip_first), z_of(1.0 + amp * c)];
    cuts.extend(p.breakpoints().into_iter().filter(|&z| z > 0.0 && z < zmax));
    cuts.retain(|&z| (0.0..=zmax).contains(&z));
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    graded(cuts)
}

/// Bands graded towards their close neighbours: where a band is more than
/// [`GRADE_RATIO`] times wider than the band beside it, the edge between them
/// has singular points close on its other side (the thin band's ends), which
/// a rule over the wide band does not resolve, nor see in its estimate. The
/// wide band is cut at `d 2^k` from that edge (`d` the thin band's width),
/// until a quarter of its own width, so that every piece lies at least its
/// own width away from them.
fn graded(edges: Vec<f64>) -> Vec<f64> {
    let mut out = edges.clone();
    for w in edges.windows(3) {
        let (left, right, at) = (w[1] - w[0], w[2] - w[1], w[1]);
        for (thin, wide, sign) in [(left, right, 1.0), (right, left, -1.0)] {
            if thin > 0.0 && wide > GRADE_RATIO * thin {
                let mut d = thin;
                while d < 0.25 * wide {
                    out.push(at + sign * d);
                    d *= 2.0;
                }
            }
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup();
    out
}

/// A band this many times wider than its neighbour is graded towards it ([`graded`]).
const GRADE_RATIO: f64 = 4.0;
