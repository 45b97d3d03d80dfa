//! Curved contacts in the plane: the MDR foundation's springs, each the
//! flat punch's spring in the plane at its own level (the bound `(1 - G(z) -
//! amp cos tau)_+`) under the same drive, so that `mu = int <f_x> dz / int
//! <B> dz` and the transverse ratio `int <f_y> dz / int <B> dz`.
//!
//! # Bands
//! As under an oscillation in the sliding direction (`contact::combined`):
//! edges where a spring's sequence of events changes
//! ([`crate::integrate::bands`]), each band by Gauss-Legendre in `theta`
//! (`z = a + (b - a)(1 - cos theta)/2`, which absorbs the square root at
//! the edges) with the order doubled until two orders agree to the
//! tolerance relative to the contact's normal force, from 8, or from 16
//! below a tolerance of `1e-9` (where a pass of 8 nodes is seldom within
//! the tolerance of the next, which a band of order 16 needs: its nodes, a
//! period's walk each, would mostly be spent for nothing); a pass's error is its
//! difference from the one before (an event that appears between two
//! samples of the band search leaves a kink that the coefficients' decay
//! would not see). A pass's nodes, and the search's samples, are solved on
//! every core (`parallel`; the same bits). The search's orbits are coarse
//! (`Precision::Coarse`), and so are the nodes' from a tolerance of
//! [`COARSE_TOL`]; a node's search starts between the starts the passes
//! before found on either side of it.
//!
//! # The edge of the contact
//! A spring whose bound is small against the drive slips along a direction
//! that relaxes at the rate `|X'|/B`: its period takes about `int
//! |X'|/(4 B) dtau` Taylor steps. The springs beyond some number of such
//! steps (at the edge of the contact, `z` up to `z_max`) are not walked:
//! their `int <B> dz` is in the normal force, their forces are the rigid
//! body's plus a correction fitted to walked springs, checked on one more
//! ([`Tail`]). That number is the least (from [`FIRST_TAIL_STEPS`], doubled)
//! whose tail meets [`TAIL_SHARE`] of the tolerance, at most
//! [`SPRING_STEPS`] ([`tail_of`]). Where the last walked spring is in
//! contact all period, the band below it clusters its nodes at its lower
//! end only ([`Ends::Lower`]): the means are analytic across its upper end,
//! and the springs there cost the most.
//!
//! # Error estimate
//! The ladder's last differences (`|dF| + |dN|` over `N`), the tail, the
//! springs' own estimates integrated by the same rule, and rounding.

use super::drive::{Bound, Drive};
use super::spring::{Spring, Start};
use super::tail::Tail;
use super::{checked, orbit_to, period_steps, PlaneEvaluation, Precision};
use crate::contact::Contact;
use crate::error::{Error, Result};
use crate::integrate::{bands, cosine_pass_parallel, Ends, Ladder, Sums};
use crate::spring::EventKind;
use std::f64::consts::TAU;
use std::sync::Mutex;

/// Taylor steps a period one spring may take at most (estimated before its
/// walk); the springs beyond, at the contact's edge, are the tail
/// (or from fewer steps: [`tail_of`]).
pub(crate) const SPRING_STEPS: f64 = 5000.0;

/// Smallest peak of a walked spring's bound, `level + amp`: a spring that
/// touches for a moment about `tau = pi` has a slip whose events did not
/// isolate from a peak of 1e-6 down (its estimate grows like 1/peak: 2e-11
/// of its `<B>` at 1e-5), and [`period_steps`] does not count where the
/// bound is below its floor.
const MIN_PEAK: f64 = 1e-5;
/// Largest Gauss-Legendre order of a band.
const MAX_ORDER: usize = 1024;
/// The tolerance from which the springs are walked coarsely
/// ([`Precision::Coarse`]: each spring's means within about `1e-9` of its
/// `<B>`, and estimated).
const COARSE_TOL: f64 = 1e-7;
/// The finest resolution (relative to `z_max`) a band's edge is found to
/// ([`edge_search`]).
const FINEST_EDGE: f64 = 1e-7;
/// The share of the tolerance an edge off by its resolution may cost
/// ([`edge_search`]).
const EDGE_SHARE: f64 = 0.1;
/// Samples of the band search per piece at a tolerance of
/// [`crate::integrate::LOOSE_TOL`] or looser ([`edge_search`]).
const LOOSE_SCAN: usize = 8;
/// The share of the tolerance (times the contact's mean normal force) the
/// tail's forces may be off ([`Tail::of`]).
const TAIL_SHARE: f64 = 0.1;
/// Rounding of one spring's means, in eps of its bound's scale.
const SPRING_ROUNDING: f64 = 8.0;

/// What the nodes of a quadrature learned besides their means (from every
/// core): the first error recorded, the largest multiplier, the periods
/// walked, the orbits' starts (a pass's nodes start from those of the
/// passes before it in their band: not from its own, whose order across
/// cores would make the bits depend on timing).
#[derive(Default)]
struct Springs(Mutex<Learned>);

#[derive(Default)]
struct Learned {
    error: Option<Error>,
    multiplier: f64,
    periods: usize,
    /// Each solved spring's `z` and its orbit's force at `tau = 0`.
    starts: Vec<(f64, [f64; 2])>,
}

/// A start for the spring at `z` from those recorded (none where none is):
/// between the nearest on either side, linear (within about the square of
/// their distance of the orbit's start, where Newton is near), else the
/// nearest.
fn nearest(starts: &[(f64, [f64; 2])], z: f64) -> Option<[f64; 2]> {
    let below = starts.iter().filter(|s| s.0 <= z).max_by(|a, b| a.0.total_cmp(&b.0));
    let above = starts.iter().filter(|s| s.0 > z).min_by(|a, b| a.0.total_cmp(&b.0));
    match (below, above) {
        (Some(&(a, fa)), Some(&(b, fb))) => {
            let t = (z - a) / (b - a);
            Some([fa[0] + t * (fb[0] - fa[0]), fa[1] + t * (fb[1] - fa[1])])
        }
        (Some(s), None) | (None, Some(s)) => Some(s.1),
        (None, None) => None,
    }
}

impl Springs {
    /// The ratios `(mu, transverse)`, the reduction and the estimate of the spring at `z`,
    /// its search from `from`, recorded with its start; `None` after the
    /// first error.
    fn solve(&self, z: f64, spring: &Spring, precision: Precision, from: Option<[f64; 2]>) -> Option<[f64; 4]> {
        if self.learned().error.is_some() {
            return None;
        }
        let solved = orbit_to(spring, precision, from);
        let mut learned = self.learned();
        match solved {
            Ok((e, start)) => {
                learned.multiplier = learned.multiplier.max(e.multiplier);
                learned.periods += e.periods;
                if let Start::Force(_, f) = start {
                    learned.starts.push((z, f));
                }
                Some([e.ratio.mu_ratio, e.transverse_ratio, e.ratio.reduction, e.error_estimate])
            }
            Err(err) => {
                learned.error.get_or_insert(err);
                None
            }
        }
    }

    /// The starts recorded so far in `[a, b]`.
    fn starts_within(&self, a: f64, b: f64) -> Vec<(f64, [f64; 2])> {
        self.learned().starts.iter().copied().filter(|&(z, _)| a <= z && z <= b).collect()
    }

    /// The record (a panic elsewhere that poisoned it left it whole: each
    /// update is one assignment).
    fn learned(&self) -> std::sync::MutexGuard<'_, Learned> {
        self.0.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }
}

/// The shortest phase a spring's sequence names ([`sequence_of`]).
const SHORT: f64 = 1e-6;

/// The kinds of the events of a spring's period, without those that start
/// a phase shorter than [`SHORT`] (a stick for an instant where the body
/// turns as the contact is lost: its share of the mean is of the order of
/// its length squared, and at the threshold where it appears the phases
/// tie to rounding, which a bisection would chase), as a cycle: from its
/// least rotation (the kinds' order), not from `tau = 0` (an event that
/// passes through `tau = 0` moves the means smoothly: no band's edge).
fn sequence_of(e: &PlaneEvaluation) -> Vec<EventKind> {
    let n = e.events.len();
    let length = |i: usize| {
        let next = e.events[(i + 1) % n].tau;
        (next - e.events[i].tau).rem_euclid(TAU)
    };
    let kinds: Vec<EventKind> = (0..n).filter(|&i| n == 1 || length(i) >= SHORT).map(|i| e.events[i].kind).collect();
    let rotated = |r: usize| -> Vec<EventKind> { kinds[r..].iter().chain(&kinds[..r]).copied().collect() };
    (0..kinds.len()).map(rotated).min_by_key(|v| v.iter().map(|&k| k as u8).collect::<Vec<u8>>()).unwrap_or_default()
}

/// `mu_macro/mu0` and the transverse ratio of the contact `c` under the
/// drive `d` and the normal amplitude `amp`, to the relative tolerance `tol`
/// (module docs).
pub(crate) fn solve(c: &dyn Contact, d: Drive, amp: f64, tol: f64) -> Result<PlaneEvaluation> {
    crate::error::check_nonneg("tol", tol)?;
    let zmax = c.reach(amp)?;
    let spring = |z: f64| Spring::new(d, Bound::new(1.0 - c.equivalent_profile(z), amp));
    let precision = if tol >= COARSE_TOL { Precision::Coarse } else { Precision::Means };
    let scale = c.mean_normal(amp)?;
    let (zcap, tail) = tail_of(c, &spring, (amp, zmax), (precision, TAIL_SHARE * tol * scale))?;
    let springs = Springs::default();
    // A sequence of events needs no exact means: its thresholds move by
    // about the coarse walks' error, far below [`FINEST_EDGE`].
    let sequence =
        |z: f64| -> Result<Vec<EventKind>> { Ok(sequence_of(&orbit_to(&spring(z), Precision::Coarse, None)?.0)) };
    let edges = bands::edges(c, (amp, zcap), edge_search(tol), &sequence)?;
    let node = |z: f64, from: Option<[f64; 2]>| {
        let sp = spring(z);
        let b = sp.bound.period_integral() / TAU;
        let scale = sp.bound.level.abs() + amp;
        match springs.solve(z, &sp, precision, from) {
            Some([mu, tr, red, err]) => ([mu * b, tr * b, red * b, b, err * b], scale),
            None => ([0.0; 5], scale),
        }
    };
    let ladder = Ladder { tol, max_order: MAX_ORDER, noise: SPRING_ROUNDING * f64::EPSILON, difference: true };
    let (mut total, mut truncation) = (Sums::<5>::default(), 0.0);
    // Where the walked springs end below the contact's edge at a spring in
    // contact all period, the band's end is no edge of the integrand (a
    // spring's means are analytic in its level while it stays in contact):
    // its nodes, the dearest of all, are not clustered there ([`Ends`]).
    let analytic_cap = zcap < zmax && spring(zcap).bound.edge.is_none();
    // The integrands: `<f_x>`, `<f_y>`, `<B - f_x>` (the reduction's, to its
    // relative accuracy), `<B>`; the fifth, the springs' own errors, is
    // summed by the same rule (positive weights: a bound of their share)
    // and not converged.
    for w in edges.windows(2).filter(|w| w[1] > w[0]) {
        let ends = if w[1] == zcap && analytic_cap { Ends::Lower } else { Ends::Both };
        let r = ladder.run(
            ladder.first_order(),
            |m| {
                let known = springs.starts_within(w[0], w[1]);
                cosine_pass_parallel((w[0], w[1], ends), m, [true; 5], &|z| node(z, nearest(&known, z)))
            },
            [scale, scale, scale, scale, f64::INFINITY],
        );
        truncation += r.error[0].max(r.error[1]) + r.error[3];
        total += r;
    }
    let learned = springs.0.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some(e) = learned.error {
        return Err(e);
    }
    let normal = total.value[3] + tail.bound;
    if !(normal > 0.0 && normal.is_finite()) {
        return Err(Error::Internal { what: format!("mean normal force {normal:?} in the plane ({})", c.name()) });
    }
    let (mu, tr) = ((total.value[0] + tail.force[0]) / normal, (total.value[1] + tail.force[1]) / normal);
    let rounding = SPRING_ROUNDING * f64::EPSILON * total.magnitude / normal;
    let error_estimate = (truncation + tail.error + total.value[4]) / normal + rounding;
    checked(tr, error_estimate, &c.name())?;
    Ok(PlaneEvaluation {
        ratio: crate::Ratio::signed(mu, (total.value[2] + tail.deficit) / normal, error_estimate, &c.name())?,
        transverse_ratio: tr,
        error_estimate,
        multiplier: learned.multiplier,
        events: vec![],
        periods: learned.periods,
    })
}

/// How the band search looks for the bands' edges at the tolerance `tol`:
/// each edge to `(EDGE_SHARE tol)^0.4` of `z_max`, at least [`FINEST_EDGE`],
/// and between [`LOOSE_SCAN`] samples a piece from
/// [`crate::integrate::LOOSE_TOL`] on ([`bands::SCAN`] below).
///
/// A phase that appears at an edge lasts like the square root of the
/// distance from it (a touch that becomes a crossing) and changes the means
/// like its cube, so an edge off by `d` leaves the integral at most about
/// `d^2.5` off: the resolution keeps that within [`EDGE_SHARE`] of the
/// tolerance for an edge found (half a resolution off at most), and within
/// 0.6 of it for one merged with a neighbour ([`bands`]: up to two
/// resolutions off; measured far below, next). A band that holds an
/// edge unfound (a missed or merged one) holds a kink, which slows its
/// ladder and shows in its last difference. Measured on the paraboloid
/// (`vhat` 0.3, amp 0.5, `W` 1.2, `psi` 0.7, default tolerance): edges
/// found to `1e-5`, `1e-4`, `1e-2` of `z_max` move the answer by `1e-16`,
/// `2e-15`, `6e-15` within estimates of `1.3e-14` to `2.4e-14`; with no
/// edge found at all, `2e-11` within `1.2e-10`. The search's springs, a
/// coarse orbit each, are most of a loose tolerance's work.
fn edge_search(tol: f64) -> bands::Search {
    let scan = if tol >= crate::integrate::LOOSE_TOL { LOOSE_SCAN } else { bands::SCAN };
    bands::Search { scan, resolution: (EDGE_SHARE * tol).powf(0.4).max(FINEST_EDGE) }
}

/// The Taylor steps a period of the first try of [`tail_of`].
const FIRST_TAIL_STEPS: f64 = SPRING_STEPS / 16.0;
/// How much a tail's error may fall at most as its walked springs' steps
/// double ([`tail_of`]). Its model's misfit grows like `P^3` and the tail's
/// `int <B> dz` like `P^2` or faster: about 64 (55 to 63 measured on a
/// paraboloid and a cone without normal oscillation).
const FASTEST_FALL: f64 = 128.0;

/// Where the walked springs end, and the tail beyond ([`Tail`]): from the
/// fewest steps a period ([`FIRST_TAIL_STEPS`], doubled each try) whose
/// tail's model meets `accuracy`, else from [`SPRING_STEPS`] as it is
/// (at once where the tries' errors, falling as measured or at most by
/// [`FASTEST_FALL`] a doubling, would not meet it there). The model is good
/// where the springs follow the rigid body closely (the tail's own measure
/// of it); a try costs a few springs at its start, and the springs it
/// spares cost the most of all.
fn tail_of(
    c: &dyn Contact,
    spring: &dyn Fn(f64) -> Spring,
    (amp, zmax): (f64, f64),
    (precision, accuracy): (Precision, f64),
) -> Result<(f64, Tail)> {
    let (mut steps, mut before) = (FIRST_TAIL_STEPS, None::<f64>);
    loop {
        let last = steps >= SPRING_STEPS;
        let zcap = walked_within(spring, zmax, steps);
        let tail = Tail::of(c, spring, amp, (zcap, zmax), (precision, accuracy, last))?;
        match tail {
            Some(tail) if last || tail.error <= accuracy => return Ok((zcap, tail)),
            Some(tail) => {
                let fall = before.map_or(FASTEST_FALL, |b| b / tail.error).min(FASTEST_FALL);
                let within = tail.error <= accuracy * fall.powf((SPRING_STEPS / steps).log2());
                steps = if fall > 1.0 && within { 2.0 * steps } else { SPRING_STEPS };
                before = Some(tail.error);
            }
            None => steps *= 2.0,
        }
        steps = steps.min(SPRING_STEPS);
    }
}

/// Whether a spring of a curved contact is walked: its bound's peak is at
/// least [`MIN_PEAK`] and its period takes at most `steps` Taylor steps
/// (both fail towards the contact's edge).
fn walked(sp: &Spring, steps: f64) -> bool {
    sp.bound.level + sp.bound.amp >= MIN_PEAK && period_steps(sp) <= steps
}

/// The largest `z` up to `zmax` whose spring takes at most [`SPRING_STEPS`]
/// Taylor steps a period and whose bound's peak is at least [`MIN_PEAK`]
/// (both fall towards the edge): `zmax` itself, or the bisection's.
pub(super) fn walked_up_to(spring: &dyn Fn(f64) -> Spring, zmax: f64) -> f64 {
    walked_within(spring, zmax, SPRING_STEPS)
}

/// [`walked_up_to`] with at most `steps` Taylor steps a period.
fn walked_within(spring: &dyn Fn(f64) -> Spring, zmax: f64, steps: f64) -> f64 {
    let walked = |z: f64| walked(&spring(z), steps);
    let edge = zmax * (1.0 - 1e-12);
    if walked(edge) {
        return zmax;
    }
    let (mut lo, mut hi) = (0.0, edge);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if walked(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plane::PlaneEvent;

    /// The tail starts at the fewest steps a period whose model meets the
    /// accuracy, and is within it there: a paraboloid at `vhat` 0.3, `W` 1
    /// (its tail's error 7e-12 from 312 steps, falling about 60x a doubling)
    /// from 2500 steps, after 4 tries; at `vhat` 3, `W` 100 (from 312 steps
    /// no spring at `4 P0` inside the contact; 4e-6 from 625, which 3
    /// doublings could not bring to the accuracy) from [`SPRING_STEPS`] after
    /// two tries. A try is counted by the springs it makes: the search for
    /// its start (61) and its quadrature (32) make 93, the springs it walks
    /// a few more.
    #[test]
    fn the_tail_starts_where_its_model_meets_the_accuracy() {
        let shape = crate::Shape::parse("parabolic").unwrap();
        let c = shape.contact();
        let zmax = c.reach(0.0).unwrap();
        for ((vhat, w), steps, tries) in [((0.3, 1.0), 2500.0, 4), ((3.0, 100.0), SPRING_STEPS, 3)] {
            let d = Drive::sliding(vhat, 0.0, 0.0, w, 0.0);
            let made = std::sync::atomic::AtomicUsize::new(0);
            let spring = |z: f64| {
                made.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                Spring::new(d, Bound::new(1.0 - c.equivalent_profile(z), 0.0))
            };
            let (zcap, tail) = tail_of(c, &spring, (0.0, zmax), (Precision::Means, 5e-16)).unwrap();
            let made = made.load(std::sync::atomic::Ordering::Relaxed);
            assert!(made >= 93 * tries && made < 93 * (tries + 1), "{vhat}: {made}");
            assert_eq!(zcap, walked_within(&spring, zmax, steps), "{vhat}");
            assert!(steps == SPRING_STEPS || tail.error <= 5e-16, "{vhat} {:e}", tail.error);
        }
    }

    /// The walked springs end where a spring first takes more than the
    /// steps allowed: a flat punch as a curved contact (every bound's peak
    /// 1.5) walks every spring up to `z_max` itself, exactly, where the
    /// steps are not limited; a paraboloid at [`SPRING_STEPS`] stops short of
    /// its edge, walking the spring there and not one `1e-6` beyond.
    /// (cargo-mutants: `walked_up_to`'s constants and the edge just inside
    /// `z_max` lived under the plane's unit tests.)
    #[test]
    fn the_walked_springs_end_where_their_steps_exceed_the_limit() {
        let (d, amp) = (Drive::sliding(0.3, 0.0, 0.0, 1.2, 0.7), 0.5);
        let [flat, paraboloid] = ["flat", "parabolic"].map(|s| crate::Shape::parse(s).unwrap());
        let (f, c) = (flat.contact(), paraboloid.contact());
        let punch = |z: f64| Spring::new(d, Bound::new(1.0 - f.equivalent_profile(z), amp));
        let fmax = f.reach(amp).unwrap();
        assert_eq!(walked_within(&punch, fmax, f64::INFINITY), fmax);
        let spring = |z: f64| Spring::new(d, Bound::new(1.0 - c.equivalent_profile(z), amp));
        let zmax = c.reach(amp).unwrap();
        let zcap = walked_up_to(&spring, zmax);
        assert!(zcap > 0.9 * zmax && zcap < zmax, "{zcap} {zmax}");
        assert!(walked(&spring(zcap), SPRING_STEPS) && !walked(&spring(zcap + 1e-6), SPRING_STEPS), "{zcap}");
    }

    /// A node's start from those recorded: on the line between its two
    /// neighbours (`t = 1/4` of the way from `z = 1` to `z = 3`), the
    /// recorded one at a `z` recorded (not `0/0` from a neighbour on
    /// either side at the same `z`), the nearest beyond the ends, none
    /// from none; and from a band's own starts only. The search converges
    /// from any start, so only this test sees them (cargo-mutants: the
    /// quotient's and difference's mutants, `>=` for the upper neighbour
    /// and the band's `||` lived).
    #[test]
    fn a_start_is_on_the_line_between_its_neighbours() {
        let starts = [(3.0, [3.0, 5.0]), (1.0, [1.0, 1.0])];
        assert_eq!(nearest(&starts, 1.5), Some([1.5, 2.0]));
        assert_eq!(nearest(&starts, 1.0), Some([1.0, 1.0]));
        assert_eq!(nearest(&starts, 3.0), Some([3.0, 5.0]));
        assert_eq!(nearest(&starts, 0.5), Some([1.0, 1.0]));
        assert_eq!(nearest(&starts, 4.0), Some([3.0, 5.0]));
        assert_eq!(nearest(&[], 1.0), None);
        let springs = Springs::default();
        springs.learned().starts.extend([(0.5, [1.0, 0.0]), (1.5, [2.0, 0.0]), (2.0, [3.0, 0.0]), (2.5, [4.0, 0.0])]);
        assert_eq!(springs.starts_within(1.0, 2.0), vec![(1.5, [2.0, 0.0]), (2.0, [3.0, 0.0])]);
    }

    /// A spring's events as a cycle: the same phases with `tau = 0` in a
    /// different one are one sequence, a phase shorter than [`SHORT`] is
    /// not named, and another order is another sequence.
    #[test]
    fn a_sequence_is_a_cycle_of_its_phases() {
        let of = |events: &[(EventKind, f64)]| {
            let events = events.iter().map(|&(kind, tau)| PlaneEvent { kind, tau }).collect();
            let ratio = crate::Ratio::signed(0.5, 0.5, 0.0, "test").unwrap();
            let e = PlaneEvaluation {
                ratio,
                transverse_ratio: 0.0,
                error_estimate: 0.0,
                multiplier: 0.0,
                events,
                periods: 1,
            };
            sequence_of(&e)
        };
        use EventKind::{Contact, LossOfContact as Loss, Slip, Stick};
        let a = of(&[(Stick, 0.1), (Slip, 2.0), (Loss, 5.0), (Contact, 5.5)]);
        let b = of(&[(Contact, 0.2), (Stick, 0.3), (Slip, 2.0), (Loss, 5.0)]);
        let short = of(&[(Contact, 0.3 - 0.5 * SHORT), (Stick, 0.3), (Slip, 2.0), (Loss, 5.0)]);
        assert_eq!(a, vec![Contact, Stick, Slip, Loss]);
        assert_eq!(b, a);
        assert_eq!(short, vec![Loss, Stick, Slip]);
        assert_ne!(of(&[(Stick, 0.1), (Contact, 2.0), (Slip, 3.0), (Loss, 5.0)]), a);
    }
}
