//! A curved body on a system: the MDR foundation as `N` springs, each with
//! its exact events. Spring `i` (weight `w_i`, its share of the contact's
//! tangential stiffness) has the bound `B_i = (b_i - amp cos tau)_+`,
//! `b_i = 1 - G(z_i)`. In a phase where the sets of stuck, forward- and
//! backward-slipping and free springs are fixed, the total force
//!
//! `F = sum_stuck w_i (x - y_i) + sum_fwd w_i B_i - sum_bwd w_i B_i`
//!
//! is linear in `(x, 1, cos tau)`, so the phase is the flat punch's linear
//! system ([`super::phase`]) with other coefficients, advanced in closed
//! form. A stuck spring slips forward where `x + amp cos tau` reaches its
//! level `l_i = y_i + b_i`, backward where `x - amp cos tau` falls to
//! `m_i = y_i - b_i`: only the extreme level of the stuck set is an event
//! function. All forward-slipping springs stick again together, where the
//! contact point stops (`x' = B_i' = amp sin tau`, the same for every
//! spring), with the common level `x + amp cos tau` (kept as one number, so
//! the group slips again as one); likewise backward. Contact is gained and
//! lost at the closed-form zeros of `B_i`.

use super::period::{first_event, Event, MAX_EVENTS_IN_A_STEP};
use super::phase::{advance, series, Generator, Linear, Params, State, COS, INT_F, ONE, SIN, TAU, V, X};
use nalgebra::SMatrix;
use std::cell::RefCell;
use std::collections::{BTreeSet, HashMap};
use std::f64::consts::TAU as TWO_PI;

/// Most transitions of zero length in a row before a phase is held for a step.
const MAX_FLIPS: usize = 8;

/// What one spring does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Spring {
    /// Holding: it slips forward where `x + amp cos tau = l`, backward where
    /// `x - amp cos tau = m` (`l - m = 2 b`).
    Stuck { l: f64, m: f64 },
    /// Slipping forward (`f = B`).
    Forward,
    /// Slipping backward (`f = -B`).
    Backward,
    /// Out of contact.
    Free,
}

/// The transitions inside a phase.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Transition {
    /// The stuck springs at the lowest level `l` slip forward.
    SlipForward(f64),
    /// Those at the highest `m` slip backward.
    SlipBackward(f64),
    /// The forward-slipping springs stick.
    StopForward,
    /// The backward-slipping ones stick.
    StopBackward,
}

/// The springs of one discretisation and the drive.
pub(crate) struct Foundation {
    pub(crate) p: Params,
    /// Weights and base bounds `b_i = 1 - G(z_i)`.
    pub(crate) w: Vec<f64>,
    pub(crate) b: Vec<f64>,
    /// Contact gains and losses in a period: `(tau, spring, gained)`, by `tau`.
    contacts: Vec<(f64, usize, bool)>,
    /// `sum w_i <B_i>`: the mean normal force.
    pub(crate) mean_b: f64,
    /// The sampling step and its exponential of each set of springs met ([`Foundation::step_of`]).
    steps: RefCell<HashMap<[u64; 3], (f64, Generator)>>,
    /// Whether a step ran out of events ([`Foundation::chattered`]).
    chattered: std::cell::Cell<bool>,
    /// Sampling steps (and parts of steps) run so far ([`Foundation::steps_run`]).
    steps_run: std::cell::Cell<u64>,
}

impl Foundation {
    /// Springs `(w_i, b_i)` (each `b_i > -amp`: it touches in a period).
    pub(crate) fn new(p: Params, springs: &[(f64, f64)]) -> Foundation {
        let (w, b): (Vec<f64>, Vec<f64>) = springs.iter().copied().unzip();
        let mut contacts = vec![];
        for (i, &bi) in b.iter().enumerate() {
            if p.amp > 0.0 && bi < p.amp {
                let gain = (bi / p.amp).clamp(-1.0, 1.0).acos();
                contacts.push((gain, i, true));
                contacts.push((TWO_PI - gain, i, false));
            }
        }
        contacts.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mean = |bi: f64| if p.amp == 0.0 { bi } else { p.amp * crate::model::spring::mean_normal(bi / p.amp) };
        let mean_b = w.iter().zip(&b).map(|(wi, &bi)| wi * mean(bi)).sum();
        let (steps, chattered, steps_run) = (RefCell::default(), std::cell::Cell::new(false), std::cell::Cell::new(0));
        Foundation { p, w, b, contacts, mean_b, steps, chattered, steps_run }
    }

    /// The state at the stated start: springs in contact at `tau = 0` (their
    /// bound `b_i - amp >= 0`: at 0 a spring touches there) stuck and relaxed
    /// at the body's position `x`, the others free.
    pub(crate) fn start(&self, x: f64) -> Vec<Spring> {
        self.b
            .iter()
            .map(|&bi| if bi - self.p.amp >= 0.0 { Spring::Stuck { l: x + bi, m: x - bi } } else { Spring::Free })
            .collect()
    }

    /// The phase of the springs `ix` indexes: their total force as a linear
    /// form, and the event functions ([`Foundation::events`]).
    fn phase(&self, ix: &Index) -> (Linear, Vec<Event<Transition>>) {
        let f = ix.force(self.p.amp);
        let (lo, hi) = ix.levels();
        (f, self.events(lo, hi, !ix.forward.is_empty(), !ix.backward.is_empty()))
    }

    /// The sampling step of the phase whose force is `f` (its generator
    /// `a`), and `exp(a0 step)`, `a0` the generator without its column of the
    /// constant state `1`. That column is the only one the springs' levels
    /// enter (`f.one`); the others depend on which springs stick and which
    /// slip, a set met again and again (on a paraboloid of 64 springs 221 sets
    /// in 5,021 phases), so each set's exponential is made once. A full step
    /// is then `z -> exp(a0 h) z + z_1 Phi u` ([`Foundation::constant_response`]).
    fn step_of(&self, f: Linear, a: &Generator) -> (f64, Generator) {
        let key = [f.x.to_bits(), f.y0.to_bits(), f.cos.to_bits()];
        let mut steps = self.steps.borrow_mut();
        if steps.len() > MAX_CACHED_SETS {
            steps.clear();
        }
        *steps.entry(key).or_insert_with(|| {
            let step = sampling_step(a);
            (step, (without_constant(a) * step).exp())
        })
    }

    /// `Phi u = int_0^h exp(a0 s) ds u = h phi_1(a0 h) u` for `u` the column
    /// of `1` in `a` (`a0` that generator without it). Beyond the series it is
    /// `exp(a h) e_1 - e_1`, the same by the Pade exponential of `a`.
    fn constant_response(a: &Generator, h: f64) -> State {
        let u = a.column(ONE).into_owned();
        series(&without_constant(a), &(u * h), h, 1).unwrap_or_else(|| {
            let mut d = (a * h).exp().column(ONE).into_owned();
            d[ONE] -= 1.0;
            d
        })
    }

    /// Sampling steps run by every period so far (a step cut short by an
    /// event counts as one): the work budget of a search.
    pub(crate) fn steps_run(&self) -> u64 {
        self.steps_run.get()
    }

    /// Whether a step run so far held more events in a row than
    /// [`MAX_EVENTS_IN_A_STEP`] and that many a spring allow: then its events
    /// were dropped to finish it, and its answer is not to be trusted.
    pub(crate) fn chattered(&self) -> bool {
        self.chattered.get()
    }

    /// The event functions of a phase whose stuck springs' levels span
    /// `[lo, hi]` (none stuck: infinite), and which has springs slipping
    /// `forward` or `backward`: the lowest stuck one slips forward where the
    /// body reaches `lo - amp cos tau`, the highest backward where it reaches
    /// `hi + amp cos tau`; a slipping group stops where `x' = amp sin tau`.
    fn events(&self, lo: f64, hi: f64, forward: bool, backward: bool) -> Vec<Event<Transition>> {
        let amp = self.p.amp;
        let mut out = vec![];
        let row = |entries: &[(usize, f64)]| {
            let mut w = SMatrix::<f64, 1, 8>::zeros();
            for &(j, v) in entries {
                w[j] = v;
            }
            w
        };
        if lo.is_finite() {
            out.push((row(&[(ONE, lo), (X, -1.0), (COS, -amp)]), Transition::SlipForward(lo)));
            out.push((row(&[(ONE, -hi), (X, 1.0), (COS, -amp)]), Transition::SlipBackward(hi)));
        }
        if forward {
            out.push((row(&[(V, 1.0), (SIN, -amp)]), Transition::StopForward));
        }
        if backward {
            out.push((row(&[(V, -1.0), (SIN, -amp)]), Transition::StopBackward));
        }
        out
    }

    /// The transition `t` at the state `z`: the springs it concerns found
    /// through the index `ix` (the stuck ones at a level, or a slipping
    /// group), each changed in `springs` and in `ix`.
    fn apply(&self, t: Transition, springs: &mut [Spring], z: &State, ix: &mut Index) {
        let amp = self.p.amp;
        let moved = match t {
            Transition::SlipForward(level) => ix.stuck_at_or_below(level),
            Transition::SlipBackward(level) => ix.stuck_at_or_above(level),
            Transition::StopForward => ix.forward.clone(),
            Transition::StopBackward => ix.backward.clone(),
        };
        for i in moved {
            let bi = self.b[i];
            let new = match t {
                Transition::SlipForward(_) => Spring::Forward,
                Transition::SlipBackward(_) => Spring::Backward,
                Transition::StopForward => {
                    let l = z[X] + amp * z[COS];
                    Spring::Stuck { l, m: l - 2.0 * bi }
                }
                Transition::StopBackward => {
                    let m = z[X] - amp * z[COS];
                    Spring::Stuck { l: m + 2.0 * bi, m }
                }
            };
            ix.change(i, springs[i], new);
            springs[i] = new;
        }
    }

    /// Spring `i` touches (`gained`) or leaves: a spring touching is stuck at
    /// `f = 0`, unless the body outruns the bound's growth `amp sin tau`.
    fn contact(&self, i: usize, gained: bool, spring: &mut Spring, z: &State) {
        let rise = self.p.amp * z[SIN];
        *spring = if !gained {
            Spring::Free
        } else if z[V] > rise {
            Spring::Forward
        } else if z[V] < -rise {
            Spring::Backward
        } else {
            Spring::Stuck { l: z[X] + self.b[i], m: z[X] - self.b[i] }
        };
    }

    /// Each spring's force at `tau = 0` of the state `(x, springs)`, with its kind.
    pub(crate) fn forces_at_start(&self, x: f64, springs: &[Spring]) -> Vec<(u8, f64)> {
        let amp = self.p.amp;
        springs
            .iter()
            .zip(&self.b)
            .map(|(s, &bi)| match *s {
                Spring::Stuck { l, .. } => (0, x - l + bi),
                Spring::Forward => (1, bi - amp),
                Spring::Backward => (2, amp - bi),
                Spring::Free => (3, 0.0),
            })
            .collect()
    }

    /// One period from `tau = 0` of the body `(x, x')` and `springs`
    /// (updated): the body's state at `2 pi` shifted back by a period of the
    /// drive, `int F` over the period, and `F`, the body's position and
    /// velocity at each of `samples` (ascending in `[0, 2 pi)`).
    pub(crate) fn period(
        &self,
        x: f64,
        v: f64,
        springs: &mut [Spring],
        samples: &[f64],
    ) -> (f64, f64, f64, Vec<[f64; 3]>) {
        let mut z = self.p.start();
        (z[X], z[V], z[INT_F]) = (x, v, 0.0);
        // `int f` summed step by step, compensated (`super::period`'s reason).
        let mut int_f = crate::special::Kahan::default();
        let mut forces = Vec::with_capacity(samples.len());
        let (mut tau, mut next, mut flips, mut in_step) = (0.0, 0, 0, 0);
        // The time summed compensated (`super::period`'s reason).
        let mut clock = crate::special::Kahan::default();
        let limit = MAX_EVENTS_IN_A_STEP * (springs.len() + 1);
        let mut ix = Index::new(&self.w, &self.b, springs);
        while tau < TWO_PI {
            let (f, events) = self.phase(&ix);
            let a = self.p.generator_of(f);
            let (step, e0) = self.step_of(f, &a);
            // Made at the phase's first full step.
            let mut response = None;
            let events = super::period::with_slopes(&a, events);
            loop {
                self.steps_run.set(self.steps_run.get() + 1);
                let rest = TWO_PI - tau;
                let mut h = step.min(rest);
                let contact = self.contacts.get(next).map(|c| c.0).filter(|&t| t <= tau + h);
                if let Some(t) = contact {
                    h = (t - tau).max(0.0);
                }
                let end = if h == step {
                    e0 * z + *response.get_or_insert_with(|| Self::constant_response(&a, step)) * z[ONE]
                } else {
                    advance(&a, &z, h)
                };
                let budget = in_step < limit;
                self.chattered.set(self.chattered.get() || !budget);
                let event = if flips < MAX_FLIPS && budget { first_event(&a, &events, &z, h, &end) } else { None };
                let reach = tau + event.map_or(h, |e| e.0);
                while let Some(&at) = samples.get(forces.len()).filter(|&&at| at <= reach) {
                    let zs = advance(&a, &z, (at - tau).max(0.0));
                    forces.push([f.x * zs[X] + f.one + f.cos * zs[COS], zs[X], zs[V]]);
                }
                if let Some((d, t)) = event {
                    in_step += 1;
                    flips = if d == 0.0 { flips + 1 } else { 0 };
                    z = advance(&a, &z, d);
                    int_f.add(std::mem::take(&mut z[INT_F]));
                    clock.add(d);
                    (tau, z[TAU]) = (clock.sum, clock.sum);
                    self.apply(t, springs, &z, &mut ix);
                    break;
                }
                (flips, in_step) = (0, 0);
                clock.add(h);
                (z, tau) = (end, if h == rest { TWO_PI } else { clock.sum });
                z[TAU] = tau;
                int_f.add(std::mem::take(&mut z[INT_F]));
                if let Some(t) = contact {
                    while let Some(&(_, i, gained)) = self.contacts.get(next).filter(|c| c.0 == t) {
                        let old = springs[i];
                        self.contact(i, gained, &mut springs[i], &z);
                        ix.change(i, old, springs[i]);
                        next += 1;
                    }
                    break;
                }
                if tau >= TWO_PI {
                    break;
                }
            }
        }
        let shift = TWO_PI * self.p.vhat;
        for s in springs.iter_mut() {
            if let Spring::Stuck { l, m } = s {
                (*l, *m) = (*l - shift, *m - shift);
            }
        }
        (z[X] - shift, z[V], int_f.sum, forces)
    }
}

/// The springs' kinds as the phases need them, kept through each change of
/// a spring (a period's events touch each spring a few times, so a period
/// costs `N log N`, not `N` per event): the stuck ones ordered by their
/// levels `l` and `m`, the slipping groups, and the sums the total force is
/// made of ([`Index::force`]). The sums are exact, integers in units of
/// [`UNIT`] of each spring's term (rounded once), so a set of springs gives
/// the same force however it was reached, as a sum made afresh would.
struct Index<'a> {
    w: &'a [f64],
    b: &'a [f64],
    by_l: BTreeSet<(i64, usize)>,
    by_m: BTreeSet<(i64, usize)>,
    forward: Vec<usize>,
    backward: Vec<usize>,
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
    fn new(w: &'a [f64], b: &'a [f64], springs: &[Spring]) -> Index<'a> {
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
    fn change(&mut self, i: usize, old: Spring, new: Spring) {
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
    fn force(&self, amp: f64) -> Linear {
        Linear {
            x: float(self.stuck),
            one: float(self.one),
            cos: amp * float(self.bwd - self.fwd),
            ..Linear::default()
        }
    }

    /// The lowest `l` and the highest `m` of the stuck springs (none: infinite).
    fn levels(&self) -> (f64, f64) {
        let lo = self.by_l.first().map_or(f64::INFINITY, |k| level(k.0));
        let hi = self.by_m.last().map_or(f64::NEG_INFINITY, |k| level(k.0));
        (lo, hi)
    }

    /// The stuck springs with `l <= at`.
    fn stuck_at_or_below(&self, at: f64) -> Vec<usize> {
        self.by_l.range(..=(key(at), usize::MAX)).map(|k| k.1).collect()
    }

    /// The stuck springs with `m >= at`.
    fn stuck_at_or_above(&self, at: f64) -> Vec<usize> {
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

/// Most sets of springs whose step is kept (beyond, the cache starts anew).
const MAX_CACHED_SETS: usize = 1 << 14;
/// `a` with its column of the constant state `1` zeroed.
fn without_constant(a: &Generator) -> Generator {
    let mut a0 = *a;
    a0.set_column(ONE, &State::zeros());
    a0
}

/// A quarter of the fastest time scale of the phase `a` (at most the
/// drive's `2 pi/256`): the body's rates are the roots of
/// `Omega^2 r^2 + damp r + k = 0`.
pub(crate) fn sampling_step(a: &Generator) -> f64 {
    step_within(a, TWO_PI / 256.0)
}

/// A quarter of the fastest time scale of the phase `a`, at most `cap`.
pub(crate) fn step_within(a: &Generator, cap: f64) -> f64 {
    let (c, k2) = (-a[(V, V)], -a[(V, X)]);
    let fastest = 0.5 * (c + (c * c + 4.0 * k2.abs()).sqrt());
    cap.min(0.25 / fastest.max(1e-300))
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
