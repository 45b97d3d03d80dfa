//! One period of the flat punch on a system: the phases from `tau = 0` to
//! `2 pi`, each advanced in closed form ([`super::phase`]), every event the
//! first sign change of its function. Functions are sampled at steps of at
//! most a quarter of the fastest time scale of the phase (the drive's
//! `2 pi / 256`, the inverse of the body's largest rate `|lambda|`), so a
//! step holds at most one extremum of each; a sign change is bracketed by
//! its step, and a minimum that dips below 0 between two positive samples
//! (a grazing event) is found from the derivative's sign change. A function
//! already below 0 where a step starts (a force a rounding beyond its bound
//! after a switch) ends its phase at once. Contact is lost and regained at
//! the closed-form zeros of `B`.

use super::phase::{advance, Generator, Kind, Params, State, COS, INT_F, SIN, TAU, V, X, Y0};
use super::tangent::Tangent;
use crate::numerics::root::bracketed;
use nalgebra::SMatrix;
use std::f64::consts::TAU as TWO_PI;

/// The flat punch's longest sampling step, a 64th of the drive's period
/// (the springs of a curved body keep a 256th): each event function of a
/// phase then still has at most one extremum a step (the drive's terms
/// `cos tau`, `sin tau` have theirs `pi` apart).
const DRIVE_STEP: f64 = TWO_PI / 64.0;

/// Most phases of zero length in a row before a phase is held for a step.
const MAX_FLIPS: usize = 8;
/// Most events in a row within one sampling step, and per spring of a
/// curved body. In a step each event function has at most one extremum, so
/// it changes sign at most twice: a correct phase machine meets a few events
/// a step. More is a phase chattering at a switch (a defect): the step is
/// finished without events and the solve refused ([`Phases::chattered`]),
/// never left to run on.
pub(crate) const MAX_EVENTS_IN_A_STEP: usize = 64;

/// A transition inside a period.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SystemEvent {
    /// The phase that starts.
    pub kind: Kind,
    /// Where, in `[0, 2 pi)`.
    pub tau: f64,
    /// The contact force there (units `mu0 kz u0`).
    pub force: f64,
}

/// The generators of the four kinds of phase and their sampling steps.
pub(crate) struct Phases {
    pub(crate) p: Params,
    gens: [Generator; 4],
    /// Each kind's sampling step, and its exponential, made where first used
    /// (a period rarely meets all four kinds).
    steps: [(f64, std::cell::OnceCell<Generator>); 4],
    /// Each kind's event functions (made once: they are checked every step).
    events: [Vec<Sloped<Kind>>; 4],
    /// Whether a step ran out of events ([`MAX_EVENTS_IN_A_STEP`]).
    chattered: std::cell::Cell<bool>,
    /// Sampling steps (and parts of steps) run so far: the work budget.
    steps_run: std::cell::Cell<u64>,
    /// Steps in which a phase was held ([`MAX_FLIPS`]), so far.
    held: std::cell::Cell<u64>,
}

fn index(kind: Kind) -> usize {
    match kind {
        Kind::Stick => 0,
        Kind::Forward => 1,
        Kind::Backward => 2,
        Kind::Free => 3,
    }
}

impl Phases {
    /// Sampling steps a period takes at most (the finest kind's).
    pub(crate) fn steps_per_period(&self) -> f64 {
        self.steps.iter().map(|(h, _)| TWO_PI / h).fold(0.0, f64::max)
    }

    pub(crate) fn new(p: Params) -> Phases {
        Phases::with_step_scale(p, 1.0)
    }

    /// The phases with every sampling step scaled by `scale` (at most 1):
    /// the same exact map, rounded along other steps (the orbit's rounding
    /// estimate, `super::orbit`).
    pub(crate) fn with_step_scale(p: Params, scale: f64) -> Phases {
        let kinds = [Kind::Stick, Kind::Forward, Kind::Backward, Kind::Free];
        let gens = kinds.map(|k| p.generator(k));
        let steps = kinds.map(|k| {
            let a = gens[index(k)];
            (scale * super::springs::step_within(&a, DRIVE_STEP), std::cell::OnceCell::new())
        });
        let events = kinds.map(|k| with_slopes(&gens[index(k)], p.events(k)));
        let (chattered, steps_run, held) =
            (std::cell::Cell::new(false), std::cell::Cell::new(0), std::cell::Cell::new(0));
        Phases { p, gens, steps, events, chattered, steps_run, held }
    }

    /// Whether a step run so far held more events than [`MAX_EVENTS_IN_A_STEP`]
    /// (its answer is not to be trusted).
    pub(crate) fn chattered(&self) -> bool {
        self.chattered.get()
    }

    /// Sampling steps run so far by every period (a step cut short by an
    /// event counts as one), those counted in by [`Phases::count`] included.
    pub(crate) fn steps_run(&self) -> u64 {
        self.steps_run.get()
    }

    /// Steps in which a phase was held so far (`SystemReport::held_steps`).
    pub(crate) fn held(&self) -> u64 {
        self.held.get()
    }

    /// Count `steps` run elsewhere (the same map along other steps) in.
    pub(crate) fn count(&self, steps: u64) {
        self.steps_run.set(self.steps_run.get() + steps);
    }

    /// The first event of `kind` within `h` of `z` (inputs: the start of a
    /// step, the step's end state): offset, the kind that follows.
    fn event_in(&self, kind: Kind, z: &State, h: f64, end: &State) -> Option<(f64, Kind)> {
        first_event(&self.gens[index(kind)], &self.events[index(kind)], z, h, end)
    }

    /// One period from `tau = 0` in phase `kind` (the state's `tau` 0):
    /// the kind at `2 pi`, the state there shifted back by a period of the
    /// drive (`tau` 0, positions less `2 pi vhat`; `int f` over the period
    /// kept), and the events.
    pub(crate) fn period(&self, kind: Kind, z: State) -> (Kind, State, Vec<SystemEvent>) {
        let (kind, z, events, _) = self.sampled(kind, z, &[], None);
        (kind, z, events)
    }

    /// [`Phases::period`]'s kind and state, with the derivative of the state
    /// at its end by that at its start accumulated in `tangent`.
    pub(crate) fn period_tangent(&self, kind: Kind, z: State, tangent: &mut Tangent) -> (Kind, State) {
        let (kind, z, _, _) = self.sampled(kind, z, &[], Some(tangent));
        (kind, z)
    }

    /// [`Phases::period`], and the contact force, the body's position and
    /// velocity at each of `samples` (ascending, in `[0, 2 pi)`).
    pub(crate) fn sampled(
        &self,
        mut kind: Kind,
        mut z: State,
        samples: &[f64],
        mut tangent: Option<&mut Tangent>,
    ) -> (Kind, State, Vec<SystemEvent>, Vec<[f64; 3]>) {
        let mut forces = Vec::with_capacity(samples.len());
        let contact = (self.p.amp > 1.0).then(|| {
            let a = (1.0 / self.p.amp).acos();
            (a, TWO_PI - a)
        });
        let mut events = vec![];
        let mut in_step = 0;
        // `int f` step by step, compensated: no row of the generator reads
        // it, so each step starts it at 0 and its increment is summed here.
        // Added in the state, thousands of nearly equal increments a period
        // rounded alike (a heavily damped body's 8,500 steps put it 7e-14
        // beyond its exact value, relative).
        let mut int_f = crate::special::Kahan::default();
        z[INT_F] = 0.0;
        let mut tau = 0.0;
        // The time summed compensated (and the state's own clock set to it):
        // summed plainly, hundreds of steps a period put the period's end
        // 5e-14 off, and its `int f` with it.
        let mut clock = crate::special::Kahan::default();
        // Phases of zero length in a row at one instant (a force grazing its
        // bound as the contact point turns): after MAX_FLIPS the phase holds
        // for a step.
        let mut flips = 0;
        while tau < TWO_PI {
            self.count(1);
            let (step, e) = &self.steps[index(kind)];
            let e = e.get_or_init(|| (self.gens[index(kind)] * *step).exp());
            let rest = TWO_PI - tau;
            let (h, stop) = to_contact(contact, tau, step.min(rest));
            let a = &self.gens[index(kind)];
            let end = if h == *step { e * z } else { advance(a, &z, h) };
            let budget = in_step < MAX_EVENTS_IN_A_STEP;
            self.chattered.set(self.chattered.get() || !budget);
            if flips >= MAX_FLIPS {
                self.held.set(self.held.get() + 1);
                tangent.as_deref_mut().map(Tangent::lose);
            }
            let event = if flips < MAX_FLIPS && budget { self.event_in(kind, &z, h, &end) } else { None };
            let reach = tau + event.map_or(h, |e| e.0);
            while let Some(&at) = samples.get(forces.len()).filter(|&&at| at <= reach) {
                let zs = advance(a, &z, (at - tau).max(0.0));
                forces.push([self.p.force(kind, &zs), zs[X], zs[V]]);
            }
            if let Some((d, next)) = event {
                in_step += 1;
                flips = if d == 0.0 { flips + 1 } else { 0 };
                z = advance(a, &z, d);
                if let Some(t) = tangent.as_deref_mut() {
                    t.step(a, d, None, next == Kind::Stick);
                }
                int_f.add(std::mem::take(&mut z[INT_F]));
                clock.add(d);
                (tau, z[TAU]) = (clock.sum, clock.sum);
                if next == Kind::Stick {
                    z[Y0] = z[X] - self.p.force(kind, &z);
                }
                events.push(SystemEvent { kind: next, tau, force: self.p.force(kind, &z) });
                kind = next;
                continue;
            }
            in_step = 0;
            flips = 0;
            if let Some(t) = tangent.as_deref_mut() {
                t.step(a, h, (h == *step).then_some(e), stop == Some(true));
            }
            clock.add(h);
            (z, tau) = (end, if h == rest { TWO_PI } else { clock.sum });
            z[TAU] = tau;
            int_f.add(std::mem::take(&mut z[INT_F]));
            match stop {
                Some(false) => {
                    kind = Kind::Free;
                    events.push(SystemEvent { kind, tau, force: 0.0 });
                }
                Some(true) => {
                    kind = self.p.on_contact(&z);
                    z[Y0] = z[X];
                    events.push(SystemEvent { kind, tau, force: 0.0 });
                }
                None => {}
            }
        }
        z[INT_F] = int_f.sum;
        let shift = TWO_PI * self.p.vhat;
        z[X] -= shift;
        z[Y0] -= shift;
        (z[TAU], z[COS], z[SIN]) = (0.0, 1.0, 0.0);
        (kind, z, events, forces)
    }
}

/// A step of length `h` from `tau` cut short where contact is gained or lost
/// (`contact`: their times), and which of the two (`true`: gained).
fn to_contact(contact: Option<(f64, f64)>, tau: f64, mut h: f64) -> (f64, Option<bool>) {
    let mut stop = None;
    if let Some((gain, loss)) = contact {
        for (when, what) in [(gain, true), (loss, false)] {
            if tau < when && when <= tau + h {
                (h, stop) = (when - tau, Some(what));
            }
        }
    }
    (h, stop)
}

/// An event function: the row `w` (the function is `w z`, positive inside
/// the phase) and what its zero means.
pub(crate) type Event<T> = (SMatrix<f64, 1, 8>, T);

/// An event function with the row of its derivative in the phase (`w A`).
pub(crate) type Sloped<T> = (SMatrix<f64, 1, 8>, SMatrix<f64, 1, 8>, T);

/// `events` of the phase with generator `a`, each with its derivative's row.
pub(crate) fn with_slopes<T>(a: &Generator, events: Vec<Event<T>>) -> Vec<Sloped<T>> {
    events.into_iter().map(|(w, tag)| (w, w * a, tag)).collect()
}

/// The first zero within `h` of `z` among `events` of the phase with
/// generator `a` (`end` the state after `h`): its offset and tag. A
/// function below 0 at the step's end has a zero in the step (bracketed),
/// or is already below 0 at its start (a force a rounding beyond its bound
/// after a switch, a contact point a rounding past turning): the phase ends
/// at once. A minimum inside the step that dips below 0 between positive
/// ends (a grazing event) is found from the derivative's sign change. The
/// roots are sought on the step's Taylor polynomial ([`Taylor`]).
pub(crate) fn first_event<T: Copy>(
    a: &Generator,
    events: &[Sloped<T>],
    z: &State,
    h: f64,
    end: &State,
) -> Option<(f64, T)> {
    let mut first: Option<(f64, T)> = None;
    let mut taylor: Option<Taylor> = None;
    for &(w, wa, next) in events {
        let (g0, g1) = (w.dot(&z.transpose()), w.dot(&end.transpose()));
        let s0 = wa.dot(&z.transpose());
        // Below 0 at the start, or at 0 and falling (a spring touching at
        // `tau = 0` with `amp = 1`, its bound and force both 0): at once.
        let below = g1 < 0.0;
        if below && g0 < 0.0 {
            first = Some((0.0, next));
            continue;
        }
        let grazing = !below && g0 > 0.0 && s0 < 0.0 && wa.dot(&end.transpose()) > 0.0;
        if !(below || grazing) {
            continue;
        }
        let c = taylor.get_or_insert_with(|| Taylor::new(a, z, h)).row(&w);
        let g = |d: f64| horner(&c, d);
        let root = if below {
            Some(bracketed(g, 0.0, h, 4.0 * f64::EPSILON).x)
        } else {
            let slope: Vec<f64> = c.iter().enumerate().skip(1).map(|(k, ck)| k as f64 * ck).collect();
            let m = bracketed(|d| horner(&slope, d), 0.0, h, 4.0 * f64::EPSILON).x;
            (g(m) < 0.0).then(|| bracketed(g, 0.0, m, 4.0 * f64::EPSILON).x)
        };
        if let Some(d) = root {
            if first.as_ref().is_none_or(|f| d < f.0) {
                first = Some((d, next));
            }
        }
    }
    first
}

/// Most terms of a step's Taylor polynomial.
const MAX_TERMS: usize = 60;

/// `exp(A d) z` on `0 <= d <= h` as its Taylor polynomial `sum_k A^k z d^k/k!`,
/// summed until a term is below 1e-18 of the state (a sampling step is at
/// most a quarter of the fastest time scale, so the terms fall at least like
/// `4^-k/k!`): an event function along the step is a polynomial, its roots
/// cheap to bracket.
pub(crate) struct Taylor {
    terms: Vec<State>,
}

impl Taylor {
    pub(crate) fn new(a: &Generator, z: &State, h: f64) -> Taylor {
        let scale = 1.0 + z.amax();
        let mut terms = Vec::with_capacity(32);
        terms.push(*z);
        let mut t = *z;
        let mut hk = 1.0;
        for k in 1..=MAX_TERMS {
            t = a * t / k as f64;
            hk *= h;
            terms.push(t);
            if k >= 4 && t.amax() * hk <= 1e-18 * scale {
                break;
            }
        }
        Taylor { terms }
    }

    /// The polynomial's coefficients of the function `w z`.
    pub(crate) fn row(&self, w: &SMatrix<f64, 1, 8>) -> Vec<f64> {
        self.terms.iter().map(|t| (w * t)[0]).collect()
    }
}

/// `sum_k c_k d^k`.
fn horner(c: &[f64], d: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, ck| acc * d + ck)
}

#[cfg(test)]
mod tests {
    use super::{first_event, with_slopes, Kind, Params, State};
    use crate::system::phase::{advance, COS, ONE, SIN};
    use nalgebra::SMatrix;

    /// A grazing event: `g = 0.999 + cos tau` dips below 0 around `tau = pi`
    /// between two positive ends of a step (`pi -+ 0.05`: 2.5e-4). Its first
    /// zero, `pi - arccos 0.999`, is found from the derivative's sign change;
    /// a step checked only at its ends (grazing detection off) misses it, and
    /// a function positive throughout (`1.001 + cos tau`) has none.
    #[test]
    fn a_grazing_event_inside_a_step_is_found() {
        let p = Params { kappa: 1.0, omega: 0.5, zeta: 0.05, vhat: 0.3, amp: 0.5, t: 0.0, phase: 0.0 };
        let a = p.generator(Kind::Free);
        let start = std::f64::consts::PI - 0.05;
        let mut z = State::zeros();
        (z[ONE], z[COS], z[SIN]) = (1.0, start.cos(), start.sin());
        let end = advance(&a, &z, 0.1);
        for (c, want) in [(0.999, Some(std::f64::consts::PI - 0.999f64.acos())), (1.001, None)] {
            let mut w = SMatrix::<f64, 1, 8>::zeros();
            (w[ONE], w[COS]) = (c, 1.0);
            assert!((w * z)[0] > 0.0 && (w * end)[0] > 0.0);
            let got = first_event(&a, &with_slopes(&a, vec![(w, Kind::Stick)]), &z, 0.1, &end);
            match (got, want) {
                (Some((d, Kind::Stick)), Some(tau)) => assert!((start + d - tau).abs() < 1e-14, "{d} {tau}"),
                (None, None) => {}
                other => panic!("c {c}: {other:?}"),
            }
        }
    }
}
