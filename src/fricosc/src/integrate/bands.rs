//! A curved contact's bands: the pieces of `[0, z_max]` on which its
//! springs' steady states are one sequence of phases, so that their means
//! are smooth in `z` there (for [`crate::integrate::cosine_pass`]).
//!
//! Edges: the ends, where a spring starts to lose contact (`G = 1 - amp`,
//! closed form), where `G` itself is not smooth
//! ([`crate::contact::Contact::breakpoints`]), and where the sequence changes
//! (an event appears or disappears: found by bisection, to rounding or to
//! a width the caller sets, between samples of each piece, [`SCAN`] or as
//! many as the caller sets, [`Search`]). What a
//! sequence is, is the caller's. Found edges within [`MERGE`] such widths
//! of each other are one edge (their middle), and those that near a cut are
//! the cut: a band that narrow is a sliver between two thresholds that all
//! but coincide (a caller's sequence that omits a phase shorter than some
//! length, for instance, changes both where the phase appears and where it
//! reaches that length); its neighbours' rules take it in, at the cost of an
//! edge off by at most half the merged width (two resolutions: the caller
//! sets what that costs).

use crate::error::Result;

/// Samples of the phase sequence per piece before bisecting for its changes
/// (where the caller does not set fewer).
pub(crate) const SCAN: usize = 32;

/// How a piece is searched for the changes of its sequence: `scan` samples
/// (equal intervals, at least 1: the callers' constants), each change bisected to `resolution` times `z_max` (or
/// to rounding, at 0).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Search {
    pub(crate) scan: usize,
    pub(crate) resolution: f64,
}

/// Found edges closer than this many resolutions are one (module docs).
const MERGE: f64 = 4.0;

/// Springs one piece's bisections may solve: 16 changes of the phase
/// sequence, each to rounding.
const BISECTION_BUDGET: usize = 16 * 64;

/// The bands' edges over `[0, zmax]` (module docs), `sequence(z)` the phase
/// sequence of the spring at `z`, each change found between `search.scan`
/// samples to rounding or to `search.resolution` times `zmax` (a sequence
/// known only that well, or a tolerance that allows it: a band's edge that
/// far off leaves the quadrature a sliver of the neighbouring band's means,
/// whose difference vanishes at the edge).
pub(crate) fn edges<S: PartialEq + Send>(
    c: &dyn crate::contact::Contact,
    (amp, zmax): (f64, f64),
    search: Search,
    sequence: &(dyn Fn(f64) -> Result<S> + Sync),
) -> Result<Vec<f64>> {
    let (scan, resolution) = (search.scan, search.resolution);
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
        let zs: Vec<f64> = (0..=scan).map(|k| a + (b - a) * k as f64 / scan as f64).collect();
        // Just inside the ends: the ends themselves may sit on a threshold.
        let inside = |z: f64| z.clamp(a + (b - a) * 1e-12, b - (b - a) * 1e-12);
        let seqs = crate::numerics::par::map(&zs, |&z| sequence(inside(z))).into_iter().collect::<Result<Vec<S>>>()?;
        let (mut budget, before) = (BISECTION_BUDGET, found.len());
        for k in 0..scan {
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
    use super::{edges, merged, Search};
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// The edges of the paraboloid at `amp` up to `zmax` by `search` for the
    /// sequence `f`, and the springs (sequences) the search asked for.
    fn counted(amp: f64, zmax: f64, search: Search, f: &(dyn Fn(f64) -> u64 + Sync)) -> (Vec<f64>, usize) {
        let shape = crate::Shape::parse("parabolic").unwrap();
        let calls = AtomicUsize::new(0);
        let sequence = |z: f64| {
            calls.fetch_add(1, Ordering::Relaxed);
            Ok(f(z))
        };
        let e = edges(shape.contact(), (amp, zmax), search, &sequence).unwrap();
        (e, calls.load(Ordering::Relaxed))
    }

    /// A search takes its samples, then bisects a change to its resolution:
    /// one change at `z = 0.3` of `[0, 1]` costs `scan + 1` samples and
    /// `ceil(log2(1/(scan resolution)))` bisections, and is found within half
    /// the resolution (8 samples to `1e-3`: 9 + 7 springs; 32 to `1e-7`: 33 +
    /// 19; to rounding, 33 + 47).
    #[test]
    fn a_search_samples_then_bisects_to_its_resolution() {
        let step = |z: f64| u64::from(z > 0.3);
        for (scan, resolution, springs) in [(8, 1e-3, 16), (32, 1e-7, 52), (32, 0.0, 33 + 47)] {
            let (e, n) = counted(0.0, 1.0, Search { scan, resolution }, &step);
            assert_eq!(n, springs, "{scan}");
            assert_eq!(e.len(), 3, "{e:?}");
            assert!((e[1] - 0.3).abs() <= (0.5 * resolution).max(1e-16), "{e:?}");
        }
    }

    /// A piece away from 0 on a contact of `z_max` 2 (the paraboloid at amp
    /// 0.5: pieces `[0, sqrt(1/2)]` and `[sqrt(1/2), 2]`, 8 samples each): a
    /// change at 1.3 bisected to `1e-3` of `z_max` (7 bisections) and found
    /// within `1e-3`; a change exactly at the cut is the cut (no bisection: the
    /// samples sit just inside their piece); two changes `3e-3` apart, within
    /// 4 resolutions, are one edge at their middle.
    #[test]
    fn a_change_is_found_in_its_piece_and_merged_with_its_neighbours() {
        let loss = 0.5f64.sqrt();
        let shape = crate::Shape::parse("parabolic").unwrap();
        assert!((shape.contact().level(0.5) - loss).abs() < 1e-15);
        let search = Search { scan: 8, resolution: 1e-3 };
        let (e, n) = counted(0.5, 2.0, search, &|z| u64::from(z > 1.3));
        assert!(n == 18 + 7 && e.len() == 4 && (e[1] - loss).abs() < 1e-15 && (e[2] - 1.3).abs() <= 1e-3, "{n} {e:?}");
        for at_the_cut in [|z: f64| u64::from(z >= 0.5f64.sqrt()), |z: f64| u64::from(z > 0.5f64.sqrt())] {
            let (e, n) = counted(0.5, 2.0, search, &at_the_cut);
            assert!(n == 18 && e.len() == 3 && (e[1] - loss).abs() < 1e-15, "{n} {e:?}");
        }
        let (e, _) = counted(0.5, 2.0, search, &|z| u64::from(z > 1.3) + u64::from(z > 1.303));
        assert!(e.len() == 4 && (e[2] - 1.3015).abs() <= 1e-3, "{e:?}");
    }

    /// The cuts: the ends, the level where springs start to lose contact
    /// (`0 < amp < 1` only, and below `z_max`), the profile's breakpoints
    /// inside; a sequence that never changes adds no edge.
    #[test]
    fn the_cuts_are_the_ends_the_loss_and_the_breakpoints() {
        let shape = crate::Shape::parse("flat-tip:0.2").unwrap();
        let c = shape.contact();
        let same = |_: f64| Ok(0u8);
        let search = Search { scan: 4, resolution: 0.0 };
        let flat = c.breakpoints()[0];
        let loss = c.level(0.5);
        assert!(flat > 0.0 && loss > flat, "{flat} {loss}");
        for (amp, zmax, mut want) in [
            (0.5, 2.0 * loss, vec![0.0, flat, loss, 2.0 * loss]),
            (0.5, 0.5 * (flat + loss), vec![0.0, flat, 0.5 * (flat + loss)]),
            (0.0, 2.0 * loss, vec![0.0, flat, 2.0 * loss]),
            (1.0, 2.0 * loss, vec![0.0, flat, 2.0 * loss]),
            (0.5, 0.5 * flat, vec![0.0, 0.5 * flat]),
        ] {
            want.sort_by(f64::total_cmp);
            assert_eq!(edges(c, (amp, zmax), search, &same).unwrap(), want, "{amp} {zmax}");
        }
    }

    /// A sequence that changes from one double to the next (ties of rounding, not
    /// regimes) spends the piece's budget of bisections, [`BISECTION_BUDGET`] (1024),
    /// and leaves the piece one band.
    #[test]
    fn changes_everywhere_are_one_band() {
        let (e, n) = counted(0.0, 1.0, Search { scan: 32, resolution: 0.0 }, &|z| z.to_bits() % 3);
        assert_eq!(e, vec![0.0, 1.0]);
        assert_eq!(n, 33 + 16 * 64);
    }

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
