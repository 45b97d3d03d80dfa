//! A curved contact's bands: the pieces of `[0, z_max]` on which its
//! springs' steady states are one sequence of phases, so that their means
//! are smooth in `z` there (for [`crate::integrate::cosine_pass`]).
//!
//! Edges: the ends, where a spring starts to lose contact (`G = 1 - amp`,
//! closed form), where `G` itself is not smooth
//! ([`crate::contact::Contact::breakpoints`]), and where the sequence changes
//! (an event appears or disappears: found by bisection, to rounding or to
//! a width the caller sets, between [`SCAN`] samples of each piece). What a
//! sequence is, is the caller's.

use crate::error::Result;

/// Samples of the phase sequence per piece before bisecting for its changes.
pub(crate) const SCAN: usize = 32;

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
    let mut edges = vec![];
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let zs: Vec<f64> = (0..=SCAN).map(|k| a + (b - a) * k as f64 / SCAN as f64).collect();
        // Just inside the ends: the ends themselves may sit on a threshold.
        let inside = |z: f64| z.clamp(a + (b - a) * 1e-12, b - (b - a) * 1e-12);
        let seqs = crate::numerics::par::map(&zs, |&z| sequence(inside(z))).into_iter().collect::<Result<Vec<S>>>()?;
        edges.push(a);
        let (mut budget, found) = (BISECTION_BUDGET, edges.len());
        for k in 0..SCAN {
            let (lo, hi) = ((inside(zs[k]), &seqs[k]), (inside(zs[k + 1]), &seqs[k + 1]));
            changes(sequence, lo, hi, &mut edges, (&mut budget, resolution * zmax))?;
        }
        if budget == 0 {
            // Changes everywhere are ties of rounding, not regimes: one band.
            edges.truncate(found);
        }
    }
    edges.push(zmax);
    edges.sort_by(f64::total_cmp);
    edges.dedup();
    Ok(edges)
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
