//! The springs' kinds as a phase needs them ([`Index`]), kept through each
//! change of a spring.

use super::phase::Linear;
use super::springs::Spring;
use std::collections::BTreeSet;

/// The springs' kinds as the phases need them, kept through each change of
/// a spring (a period's events touch each spring a few times, so a period
/// costs `N log N`, not `N` per event): the stuck ones ordered by their
/// levels `l` and `m`, the slipping groups, and the sums the total force is
/// made of ([`Index::force`]). The sums are exact, integers in units of
/// [`UNIT`] of each spring's term (rounded once), so a set of springs gives
/// the same force however it was reached, as a sum made afresh would.
pub(super) struct Index<'a> {
    w: &'a [f64],
    b: &'a [f64],
    by_l: BTreeSet<(i64, usize)>,
    by_m: BTreeSet<(i64, usize)>,
    pub(super) forward: Vec<usize>,
    pub(super) backward: Vec<usize>,
    /// Each slipping spring's place in its group.
    place: Vec<usize>,
    /// `sum w_i` over the stuck, forward and backward springs, and the
    /// constant term `sum_stuck w_i (b_i - l_i) + sum_fwd w_i b_i - sum_bwd w_i b_i`.
    stuck: i128,
    fwd: i128,
    bwd: i128,
    one: i128,
}

/// The unit of [`Index`]'s sums: terms up to `2^66` (a body `10^19`
/// spring lengths away) are held to `2^-60`.
const UNIT: f64 = 1.0 / (1u64 << 60) as f64;

/// `x` in units of [`UNIT`], rounded.
fn fixed(x: f64) -> i128 {
    (x / UNIT).round() as i128
}

fn float(n: i128) -> f64 {
    n as f64 * UNIT
}

/// A level's key in the total order of `f64` (`-0` taken as `0`); the map is
/// its own inverse on the bits.
fn key(x: f64) -> i64 {
    let b = (x + 0.0).to_bits() as i64;
    b ^ (((b >> 63) as u64) >> 1) as i64
}

fn level(k: i64) -> f64 {
    f64::from_bits((k ^ (((k >> 63) as u64) >> 1) as i64) as u64)
}

impl<'a> Index<'a> {
    pub(super) fn new(w: &'a [f64], b: &'a [f64], springs: &[Spring]) -> Index<'a> {
        let (by_l, by_m) = (BTreeSet::new(), BTreeSet::new());
        let place = vec![0; springs.len()];
        let mut ix =
            Index { w, b, by_l, by_m, forward: vec![], backward: vec![], place, stuck: 0, fwd: 0, bwd: 0, one: 0 };
        for (i, &s) in springs.iter().enumerate() {
            ix.add(i, s, 1);
        }
        ix
    }

    /// Spring `i` changed from `old` to `new`.
    pub(super) fn change(&mut self, i: usize, old: Spring, new: Spring) {
        self.add(i, old, -1);
        self.add(i, new, 1);
    }

    /// Spring `i` in the state `s` added (`sign` 1) or taken out (-1).
    fn add(&mut self, i: usize, s: Spring, sign: i128) {
        let (wi, bi) = (self.w[i], self.b[i]);
        match s {
            Spring::Stuck { l, m } => {
                if sign == 1 {
                    self.by_l.insert((key(l), i));
                    self.by_m.insert((key(m), i));
                } else {
                    self.by_l.remove(&(key(l), i));
                    self.by_m.remove(&(key(m), i));
                }
                self.stuck += sign * fixed(wi);
                self.one += sign * fixed(wi * (bi - l));
            }
            Spring::Forward => {
                self.fwd += sign * fixed(wi);
                self.one += sign * fixed(wi * bi);
                group(&mut self.forward, &mut self.place, i, sign == 1);
            }
            Spring::Backward => {
                self.bwd += sign * fixed(wi);
                self.one -= sign * fixed(wi * bi);
                group(&mut self.backward, &mut self.place, i, sign == 1);
            }
            Spring::Free => {}
        }
    }

    /// The total force `F = sum_stuck w_i (x - l_i + b_i) + sum_fwd w_i B_i -
    /// sum_bwd w_i B_i` as a linear form in `(x, 1, cos tau)`.
    pub(super) fn force(&self, amp: f64) -> Linear {
        Linear {
            x: float(self.stuck),
            one: float(self.one),
            cos: amp * float(self.bwd - self.fwd),
            ..Linear::default()
        }
    }

    /// The lowest `l` and the highest `m` of the stuck springs (none: infinite).
    pub(super) fn levels(&self) -> (f64, f64) {
        let lo = self.by_l.first().map_or(f64::INFINITY, |k| level(k.0));
        let hi = self.by_m.last().map_or(f64::NEG_INFINITY, |k| level(k.0));
        (lo, hi)
    }

    /// The stuck springs with `l <= at`.
    pub(super) fn stuck_at_or_below(&self, at: f64) -> Vec<usize> {
        self.by_l.range(..=(key(at), usize::MAX)).map(|k| k.1).collect()
    }

    /// The stuck springs with `m >= at`.
    pub(super) fn stuck_at_or_above(&self, at: f64) -> Vec<usize> {
        self.by_m.range((key(at), 0)..).map(|k| k.1).collect()
    }
}

/// Spring `i` joins its slipping group (`join`) or leaves it (the last one
/// taking its place).
fn group(list: &mut Vec<usize>, place: &mut [usize], i: usize, join: bool) {
    if join {
        place[i] = list.len();
        list.push(i);
    } else {
        let k = place[i];
        list.swap_remove(k);
        if let Some(&moved) = list.get(k) {
            place[moved] = k;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// After any sequence of changes the index is what a scan of the
    /// springs gives: the same force to the bit as an index made afresh (the
    /// sums are exact), within rounding of a plain sum, the extreme levels,
    /// and the springs at or beyond a level.
    #[test]
    fn the_index_is_a_scan_of_the_springs() {
        let n = 200;
        let w: Vec<f64> = (0..n).map(|i| 1.0 / (3.0 + i as f64)).collect();
        let b: Vec<f64> = (0..n).map(|i| 1.0 - 1.7 * i as f64 / n as f64).collect();
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut rand = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut springs = vec![Spring::Free; n];
        let mut ix = Index::new(&w, &b, &springs);
        for step in 0..5000 {
            let i = (rand() % n as u64) as usize;
            // Levels from a few values, so that springs share them (a group
            // stuck together), both zeros among them (one level).
            let l = [-0.0, 0.0, 0.25, -1.5, 1.5][(rand() % 5) as usize] * (1 + rand() % 3) as f64;
            let new = match rand() % 4 {
                0 => Spring::Stuck { l, m: l - 2.0 * b[i] },
                1 => Spring::Forward,
                2 => Spring::Backward,
                _ => Spring::Free,
            };
            ix.change(i, springs[i], new);
            springs[i] = new;
            if step % 97 != 0 {
                continue;
            }
            let (f, fresh) = (ix.force(0.7), Index::new(&w, &b, &springs).force(0.7));
            assert_eq!((f.x, f.one, f.cos), (fresh.x, fresh.one, fresh.cos), "step {step}");
            let (mut x, mut one, mut cos, mut lo, mut hi) = (0.0, 0.0, 0.0, f64::INFINITY, f64::NEG_INFINITY);
            for (k, s) in springs.iter().enumerate() {
                match *s {
                    Spring::Stuck { l, m } => {
                        (x, one, lo, hi) = (x + w[k], one + w[k] * (b[k] - l), lo.min(l), hi.max(m));
                    }
                    Spring::Forward => (one, cos) = (one + w[k] * b[k], cos - 0.7 * w[k]),
                    Spring::Backward => (one, cos) = (one - w[k] * b[k], cos + 0.7 * w[k]),
                    Spring::Free => {}
                }
            }
            let near = |a: f64, e: f64| (a - e).abs() <= 1e-13 * (1.0 + e.abs());
            assert!(near(f.x, x) && near(f.one, one) && near(f.cos, cos), "step {step}: {f:?} {x} {one} {cos}");
            assert_eq!(ix.levels(), (lo, hi), "step {step}");
            let scan = |p: &dyn Fn(f64, f64) -> bool| -> Vec<usize> {
                let stuck = springs.iter().enumerate();
                let mut v: Vec<usize> =
                    stuck.filter_map(|(k, s)| matches!(*s, Spring::Stuck { l, m } if p(l, m)).then_some(k)).collect();
                v.sort_unstable();
                v
            };
            let sorted = |mut v: Vec<usize>| {
                v.sort_unstable();
                v
            };
            assert_eq!(sorted(ix.stuck_at_or_below(lo)), scan(&|l, _| l <= lo), "step {step}");
            assert_eq!(sorted(ix.stuck_at_or_above(hi)), scan(&|_, m| m >= hi), "step {step}");
            assert_eq!(sorted(ix.stuck_at_or_below(1.25)), scan(&|l, _| l <= 1.25), "step {step}");
            assert_eq!(sorted(ix.stuck_at_or_below(-0.0)), scan(&|l, _| l <= 0.0), "step {step}");
            assert_eq!(sorted(ix.stuck_at_or_above(0.0)), scan(&|_, m| m >= 0.0), "step {step}");
            let group = |kind: Spring| springs.iter().enumerate().filter(move |(_, s)| **s == kind).map(|(k, _)| k);
            assert_eq!(sorted(ix.forward.clone()), group(Spring::Forward).collect::<Vec<_>>(), "step {step}");
            assert_eq!(sorted(ix.backward.clone()), group(Spring::Backward).collect::<Vec<_>>(), "step {step}");
        }
    }
}
