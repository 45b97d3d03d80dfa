//! The levels where a spring's sequence of phases over the orbit changes
//! (`super::curved` cuts its cells there). Springs of no weight at equal
//! steps of the level `b` ride along one orbit of the attractor (they add
//! no force, so the body's motion is the attractor's); each records the
//! kinds it enters, read as a cyclic sequence. Where two neighbours'
//! sequences differ, the bracket is bisected (a round of probes per
//! halving, all brackets at once) down to [`SAME`] of the range.

use super::phase::{Kind, V, X};
use super::springs::{Foundation, Record, Spring};
use crate::error::Result;

/// The body `(x, x')` and its springs' states at `tau = 0`.
pub(crate) type Body = (f64, f64, Vec<Spring>);

/// Most rounds of bisection (each halves every bracket).
const MAX_ROUNDS: usize = 64;
/// Most changes found (each cuts a piece: at most 8 springs more at the finest level).
const MAX_CHANGES: usize = 256;
/// Changes nearer than this (relative to the range of levels) are one; a
/// bracket is not split below it.
pub(crate) const SAME: f64 = 1e-7;

fn code(k: Kind) -> u8 {
    match k {
        Kind::Stick => 0,
        Kind::Forward => 1,
        Kind::Backward => 2,
        Kind::Free => 3,
    }
}

/// A cyclic sequence of phases from its first and the kinds entered, as its
/// least rotation.
fn canonical(first: Kind, entered: &[Kind]) -> Vec<u8> {
    let mut s = vec![code(first)];
    for &k in entered {
        let c = code(k);
        if s.last() != Some(&c) {
            s.push(c);
        }
    }
    if s.len() > 1 && s.first() == s.last() {
        s.pop();
    }
    (0..s.len())
        .map(|r| {
            let mut t = s.clone();
            t.rotate_left(r);
            t
        })
        .min()
        .unwrap_or_default()
}

/// The sequences of phases of springs of no weight at `levels` driven by the
/// orbit of `fd` (`period` periods from `body`), after one orbit to settle.
fn sequences(fd: &Foundation, body: &Body, period: usize, levels: &[f64]) -> Result<Vec<Vec<u8>>> {
    let n = fd.w.len();
    let mut all: Vec<(f64, f64)> = fd.w.iter().copied().zip(fd.b.iter().copied()).collect();
    all.extend(levels.iter().map(|&b| (0.0, b)));
    let probe = Foundation::new(fd.p, &all);
    let (mut x, mut v) = (body.0, body.1);
    let mut z = fd.p.start();
    (z[X], z[V]) = (x, v);
    let mut springs = body.2.clone();
    springs.extend_from_slice(&probe.start(&z)[n..]);
    for _ in 0..period {
        crate::interrupt::check()?;
        (x, v, _) = probe.period(x, v, &mut springs, &mut Record::default());
    }
    let first: Vec<Kind> = springs.iter().map(Spring::kind).collect();
    let mut rec = Record { kinds: Some(vec![vec![]; all.len()]), ..Record::default() };
    for _ in 0..period {
        crate::interrupt::check()?;
        (x, v, _) = probe.period(x, v, &mut springs, &mut rec);
    }
    let kinds = rec.kinds.unwrap_or_default();
    Ok((n..all.len()).map(|i| canonical(first[i], &kinds[i])).collect())
}

/// The levels in `(lo, hi)` where the sequence of phases of a spring driven
/// by the orbit changes, from `probes` equal steps bisected.
pub(crate) fn changes(
    fd: &Foundation,
    body: &Body,
    period: usize,
    lo: f64,
    hi: f64,
    probes: usize,
) -> Result<Vec<f64>> {
    let levels: Vec<f64> = (1..=probes).map(|j| lo + (hi - lo) * j as f64 / probes as f64).collect();
    let seqs = sequences(fd, body, period, &levels)?;
    let mut open: Vec<(f64, f64, Vec<u8>, Vec<u8>)> = (0..levels.len() - 1)
        .filter(|&j| seqs[j] != seqs[j + 1])
        .map(|j| (levels[j], levels[j + 1], seqs[j].clone(), seqs[j + 1].clone()))
        .collect();
    // Rounding makes a sequence flicker within a few ulps of its change:
    // a bracket is not split below the resolution `SAME`.
    let mut found = vec![];
    for _ in 0..MAX_ROUNDS {
        let (done, rest): (Vec<_>, Vec<_>) = open.into_iter().partition(|o| o.1 - o.0 <= SAME * (hi - lo));
        found.extend(done.iter().map(|o| 0.5 * (o.0 + o.1)));
        if rest.is_empty() {
            break;
        }
        let mids: Vec<f64> = rest.iter().map(|o| 0.5 * (o.0 + o.1)).collect();
        let got = sequences(fd, body, period, &mids)?;
        open = vec![];
        for ((a, b, sa, sb), (m, s)) in rest.into_iter().zip(mids.into_iter().zip(got)) {
            if s != sa {
                open.push((a, m, sa.clone(), s.clone()));
            }
            if s != sb {
                open.push((m, b, s, sb));
            }
        }
        open.truncate(MAX_CHANGES.saturating_sub(found.len()));
    }
    found.sort_by(f64::total_cmp);
    found.dedup_by(|later, earlier| *later - *earlier <= SAME * (hi - lo));
    Ok(found)
}

#[cfg(test)]
mod tests {
    use super::super::phase::Params;
    use super::*;

    /// A cyclic sequence is the same from whichever phase it is read, and
    /// two sequences that differ in one phase are not.
    #[test]
    fn a_sequence_is_read_the_same_from_any_phase() {
        use Kind::{Backward, Forward, Free, Stick};
        let a = canonical(Forward, &[Stick, Free, Stick, Forward]);
        assert_eq!(a, canonical(Free, &[Stick, Forward, Forward, Stick, Free]));
        assert_eq!(a, vec![0, 1, 0, 3]);
        assert_ne!(a, canonical(Forward, &[Stick, Free, Backward, Forward]));
        assert_eq!(canonical(Stick, &[]), vec![0]);
    }

    /// A spring above `b = amp` stays in contact, one below leaves it once a
    /// period: whatever the orbit, the sequence changes at `b = amp`, found
    /// to the bisection's resolution (`SAME` of the range).
    #[test]
    fn a_change_is_found_where_contact_is_first_lost() {
        for (amp, kappa) in [(0.5, 1.0), (0.8, 0.3)] {
            let p = Params { kappa, omega: 0.5, zeta: 0.05, vhat: 0.3 * amp, amp, t: 0.0, phase: 0.0 };
            let springs = crate::system::springs(&crate::Shape::parabolic(), amp, 64).unwrap();
            let fd = Foundation::new(p, &springs);
            let (r, state) = crate::system::search::attractor(&fd, 600).unwrap();
            let body = crate::system::reduced::expand(&fd, &state);
            let found = changes(&fd, &body, r.period.unwrap(), -amp, 1.0, 512).unwrap();
            let range = 1.0 + amp;
            assert!(found.iter().any(|b| (b - amp).abs() <= SAME * range), "{amp}: {found:?}");
        }
    }
}
