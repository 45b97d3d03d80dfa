//! The flat punch's period map in its reduced state: the one spring's
//! foundation ([`Foundation`]) seen at `tau = 0` as `(x, x', f)` and the
//! spring's phase, the state Newton refines (`super::orbit`). A stuck
//! spring's level is `l = x - f + 1`; a slipping or free spring's force is
//! fixed by the drive.

use super::events::SystemEvent;
use super::phase::{Kind, Params};
use super::springs::{Foundation, Record, Spring};
use super::tangent::Tangent;
use nalgebra::{Matrix3, RowDVector, RowVector3, Vector3};

/// The reduced state of the period map: `(x, x', f)` at `tau = 0` and the phase.
pub(crate) type Reduced = (Kind, Vector3<f64>);

/// The Jacobian of a period map `P^k` at a state and the gradient of `int f` over it.
pub(crate) type Derivatives = (Matrix3<f64>, Vector3<f64>);

/// The flat punch as springs: one, of weight 1 and base bound 1.
pub(crate) const FLAT: [(f64, f64); 1] = [(1.0, 1.0)];

/// The flat punch's foundation on the system `p`.
pub(crate) fn foundation(p: Params) -> Foundation {
    Foundation::new(p, &FLAT)
}

fn expand((kind, s): &Reduced) -> (f64, f64, [Spring; 1]) {
    let spring = match kind {
        Kind::Stick => {
            let l = s[0] - s[2] + 1.0;
            Spring::Stuck { l, m: l - 2.0 }
        }
        Kind::Forward => Spring::Forward,
        Kind::Backward => Spring::Backward,
        Kind::Free => Spring::Free,
    };
    (s[0], s[1], [spring])
}

fn reduce(fd: &Foundation, x: f64, v: f64, springs: &[Spring; 1]) -> Reduced {
    let f = fd.forces_at_start(x, springs)[0].1;
    (springs[0].kind(), Vector3::new(x, v, f))
}

/// `k` periods of the map from `s`: the state after them and `int f` over them.
pub(crate) fn map_k(fd: &Foundation, s: &Reduced, k: usize) -> (Reduced, f64) {
    map_k_recorded(fd, s, k, &mut Record::default())
}

/// [`map_k`] recording into `rec`.
fn map_k_recorded(fd: &Foundation, s: &Reduced, k: usize, rec: &mut Record) -> (Reduced, f64) {
    let (mut x, mut v, mut springs) = expand(s);
    let mut int_f = 0.0;
    for _ in 0..k {
        let f;
        (x, v, f) = fd.period(x, v, &mut springs, rec);
        int_f += f;
    }
    (reduce(fd, x, v, &springs), int_f)
}

/// [`map_k`], with the events of its first period and the steps held in it.
pub(crate) fn map_k_events(fd: &Foundation, s: &Reduced, k: usize) -> ((Reduced, f64), Vec<SystemEvent>, u64) {
    let held = fd.held();
    let mut rec = Record { events: Some(vec![]), ..Record::default() };
    let first = map_k_recorded(fd, s, 1, &mut rec);
    let (events, held) = (rec.events.unwrap_or_default(), fd.held() - held);
    if k <= 1 {
        return (first, events, held);
    }
    let (end, rest) = map_k(fd, &first.0, k - 1);
    ((end, first.1 + rest), events, held)
}

/// [`map_k`] with the derivatives of its state and `int f` by `s`'s
/// (`None` where the map is not differentiable along the way,
/// [`Tangent`]): the springs' derivative by `(x, x', l)` at the start (`l`
/// where the spring sticks there), composed with `l = x - f + 1` at both ends.
pub(crate) fn map_k_tangent(fd: &Foundation, s: &Reduced, k: usize) -> ((Reduced, f64), Option<Derivatives>) {
    let springs = expand(s).2;
    let mut rec = Record { tangent: Some(Tangent::new(&fd.w, &springs)), ..Record::default() };
    let mapped = map_k_recorded(fd, s, k, &mut rec);
    let stuck = s.0 == Kind::Stick;
    // d/d(x, x', f) of a row by (x, x'[, l]): dl = dx - df.
    let by_reduced = |r: &RowDVector<f64>| {
        let mut out = RowVector3::new(r[0], r[1], 0.0);
        if stuck {
            (out[0], out[2]) = (out[0] + r[2], -r[2]);
        }
        out
    };
    let derivatives = rec.tangent.as_ref().and_then(Tangent::get).map(|(body, levels)| {
        let rows = |i: usize| by_reduced(&body.row(i).into_owned());
        let (x, v, int_f) = (rows(super::phase::X), rows(super::phase::V), rows(super::phase::INT_F));
        // f = x - l + 1 at the end where the spring sticks there.
        let f = match (mapped.0 .0, &levels[0]) {
            (Kind::Stick, Some(l)) => x - by_reduced(l),
            _ => RowVector3::zeros(),
        };
        (Matrix3::from_rows(&[x, v, f]), int_f.transpose())
    });
    (mapped, derivatives)
}

/// The contact force, the body's position and velocity at `taus`
/// (ascending, in `[0, 2 pi)`) over one period from the state `s` at `tau = 0`.
pub(crate) fn sample((fd, s): &(Foundation, Reduced), taus: &[f64]) -> Vec<[f64; 3]> {
    let mut rec = Record { samples: taus, ..Record::default() };
    map_k_recorded(fd, s, 1, &mut rec);
    rec.forces
}

/// The stated start (the system's module docs) as the period map's state.
pub(crate) fn stated_start(p: &Params) -> Reduced {
    let start = p.start();
    // In contact at the start where `amp < 1`; at `amp = 1` the bound is 0
    // there: the spring touches as at a regain of contact.
    let kind = match p.amp.partial_cmp(&1.0) {
        Some(std::cmp::Ordering::Less) => Kind::Stick,
        Some(std::cmp::Ordering::Equal) => p.on_contact(&start),
        _ => Kind::Free,
    };
    // A stuck spring relaxed; a slipping one at its bound `+-(1 - amp)`.
    let f = match kind {
        Kind::Stick | Kind::Free => 0.0,
        Kind::Forward => 1.0 - p.amp,
        Kind::Backward => p.amp - 1.0,
    };
    (kind, Vector3::new(start[super::phase::X], start[super::phase::V], f))
}
