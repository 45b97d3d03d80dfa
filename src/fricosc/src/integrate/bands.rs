//! A curved contact's bands: the pieces of `[0, z_max]` on which its
//! springs' steady states are one sequence of phases, so that their means
//! are smooth in `z` there (for [`crate::integrate::cosine_pass`]).
//!
//! Edges: the ends, where a spring starts to lose contact (`G = 1 - amp`,
//! closed form), where `G` itself is not smooth
//! ([`crate::contact::Contact::breakpoints`]), and where the sequence changes
//! (an event appears or disappears: found by bisection, to rounding or to
//! a width the caller sets, between [`SCAN`] samples of each piece). What a
//! sequence is, is the caller's. Found edges within [`MERGE`] such widths
//! of each other are one edge (their middle), and those that near a cut are
//! the cut: a band that narrow is a sliver between two thresholds that all
//! but coincide (a caller's sequence that omits a phase shorter than some
//! length, for instance, changes both where the phase appears and where it
//! reaches that length); its neighbours' rules take it in, at the cost of an
//! edge off by at most half the merged width (two resolutions: the caller
//! sets what that costs).

use crate::error::Result;

/// Samples of the phase sequence per piece before bisecting for its changes.
pub(crate) const SCAN: usize = 32;

/// Found edges closer than this many resolutions are one (module docs).
const MERGE: f64 = 4.0;

/// Springs one piece's bisections may solve: 16 changes of the phase
/// sequence, each to rounding.
const BISECTION_BUDGET: usize = 16 * 64;

/// The bands' edges over `[0, zmax]` (module docs), `sequence(z)` the phase
/// sequence of the spring at `z`, each change found to rounding or to
/// `resolution` times `zmax` (a sequence known only that well: a band's edge
/// that far off leaves the quadrature a sliver of the neighbouring band's
/// means, whose difference vanishes at the edge).
pub(crate) fn edges<S: PartialEq + Send>(
    c: &dyn crate::contact::Contact,
    (amp, zmax): (f64, f64),
    resolution: f64,
    sequence: &(dyn Fn(f64) -> Result<S> + Sync),
) -> Result<Vec<f64>> {
    let mut cuts = vec![0.0, zmax];
    if amp > 0.0 && amp < 1.0 {
        cuts.push(c.level(1.0 - amp));
    }
    cuts.extend(c.breakpoints().into_iter().filter(|&z| z > 0.0 && z < zmax));
    cuts.retain(|&z| z <= zmax);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut found = vec![];
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let zs: Vec<f64> = (0..=SCAN).map(|k| a + (b - a) * k as f64 / SCAN as f64).collect();
        // Just inside the ends: the ends themselves may sit on a threshold.
        let inside = |z: f64| z.clamp(a + (b - a) * 1e-12, b - (b - a) * 1e-12);
        let seqs = crate::numerics::par::map(&zs, |&z| sequence(inside(z))).into_iter().collect::<Result<Vec<S>>>()?;
        let (mut budget, before) = (BISECTION_BUDGET, found.len());
        for k in 0..SCAN {
            let (lo, hi) = ((inside(zs[k]), &seqs[k]), (inside(zs[k + 1]), &seqs[k + 1]));
            changes(sequence, lo, hi, &mut found, (&mut budget, resolution * zmax))?;
        }
        if budget == 0 {
            // Changes everywhere are ties of rounding, not regimes: one band.
            found.truncate(before);
        }
    }
    Ok(merged(cuts, found, MERGE * resolution * zmax))
}

/// The cuts and the found edges, sorted, the found ones within `width` of
/// each other replaced by the middle of their cluster, and dropped within
/// `width` of a cut (module docs).
fn merged(mut cuts: Vec<f64>, mut found: Vec<f64>, width: f64) -> Vec<f64> {
    found.sort_by(f64::total_cmp);
    let mut clusters: Vec<(f64, f64)> = vec![];
    for z in found {
        match clusters.last_mut() {
            Some(c) if z - c.1 <= width => c.1 = z,
            _ => clusters.push((z, z)),
        }
    }
    let near_a_cut = |z: f64| cuts.iter().any(|&c| (z - c).abs() <= width);
    let middles: Vec<f64> = clusters.iter().map(|&(lo, hi)| 0.5 * (lo + hi)).filter(|&z| !near_a_cut(z)).collect();
    cuts.extend(middles);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    cuts
}

/// Every change of the sequence between `a` (sequence `sa`) and `b`, by
/// bisection to rounding or to the width `stop` (both halves, so that a
/// band between two samples of the same sequence at the ends is still found
/// if the midpoint falls in it).
///
/// Where the sequence is decided by ties of rounding at every `z` (the drive
/// and the bound moving together, `X' = -B'` for instance, where the spring
/// follows `-B` whichever way it is named), the bisection would branch at every
/// level: `budget` caps its springs, and a piece that spends it is taken as
/// one band (each sequence's means agree there, so the bands need no edges);
/// the quadrature's own convergence check covers what a missed edge would cost.
fn changes<S: PartialEq>(
    sequence: &dyn Fn(f64) -> Result<S>,
    (a, sa): (f64, &S),
    (b, sb): (f64, &S),
    out: &mut Vec<f64>,
    (budget, stop): (&mut usize, f64),
) -> Result<()> {
    if sa == sb {
        return Ok(());
    }
    let m = 0.5 * (a + b);
    if m <= a || m >= b || b - a <= (4.0 * f64::EPSILON * b.abs()).max(stop) || *budget == 0 {
        out.push(m);
        return Ok(());
    }
    *budget -= 1;
    let sm = sequence(m)?;
    changes(sequence, (a, sa), (m, &sm), out, (&mut *budget, stop))?;
    changes(sequence, (m, &sm), (b, sb), out, (budget, stop))
}

#[cfg(test)]
mod tests {
    use super::merged;

    /// Two found edges `1e-7` apart are one at their middle, one `2e-7`
    /// from a cut is the cut, one farther from both stays; without a width
    /// every edge stays (as `contact::combined` asks).
    #[test]
    fn edges_closer_than_the_width_are_one() {
        let (cuts, found) = (vec![0.0, 0.5, 1.0], vec![0.7, 0.2000001, 0.2, 0.5000002, 0.5000025]);
        let m = merged(cuts.clone(), found.clone(), 1e-6);
        assert_eq!(m, vec![0.0, 0.5 * (0.2 + 0.2000001), 0.5, 0.5000025, 0.7, 1.0]);
        let all = merged(cuts, found, 0.0);
        assert_eq!(all, vec![0.0, 0.2, 0.2000001, 0.5, 0.5000002, 0.5000025, 0.7, 1.0]);
    }
}
