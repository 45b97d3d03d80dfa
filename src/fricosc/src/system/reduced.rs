//! The period map in its reduced state, the state Newton refines
//! (`super::orbit`): the springs' foundation ([`Foundation`]) seen at `tau =
//! 0` as each spring's phase and `(x, x', f_1, ..., f_N)`. A stuck spring's
//! level is `l_i = x - f_i + b_i`; a slipping or free spring's force is
//! fixed by the drive (its component of the map's derivative is 0).

use super::events::SystemEvent;
use super::phase::{Kind, Params, INT_F, V, X};
use super::springs::{Foundation, Record, Spring};
use super::tangent::Tangent;
use nalgebra::{DMatrix, DVector, RowDVector};

/// The reduced state of the period map: each spring's phase at `tau = 0`,
/// and `(x, x', f_1, ..., f_N)` there.
pub(crate) type Reduced = (Vec<Kind>, DVector<f64>);

/// The Jacobian of a period map `P^k` at a state and the gradient of `int F` over it.
pub(crate) type Derivatives = (DMatrix<f64>, DVector<f64>);

/// The flat punch as springs: one, of weight 1 and base bound 1.
pub(crate) const FLAT: [(f64, f64); 1] = [(1.0, 1.0)];

/// The flat punch's foundation on the system `p`.
pub(crate) fn foundation(p: Params) -> Foundation {
    Foundation::new(p, &FLAT)
}

/// The body and the springs of the state `r`.
pub(crate) fn expand(fd: &Foundation, (kinds, s): &Reduced) -> (f64, f64, Vec<Spring>) {
    let springs = kinds
        .iter()
        .zip(&fd.b)
        .enumerate()
        .map(|(i, (kind, &b))| match kind {
            Kind::Stick => {
                let l = s[0] - s[2 + i] + b;
                Spring::Stuck { l, m: l - 2.0 * b }
            }
            Kind::Forward => Spring::Forward,
            Kind::Backward => Spring::Backward,
            Kind::Free => Spring::Free,
        })
        .collect();
    (s[0], s[1], springs)
}

fn reduce(fd: &Foundation, x: f64, v: f64, springs: &[Spring]) -> Reduced {
    let kinds = springs.iter().map(Spring::kind).collect();
    let forces = fd.forces_at_start(x, springs);
    let s = DVector::from_iterator(2 + springs.len(), [x, v].into_iter().chain(forces.iter().map(|f| f.1)));
    (kinds, s)
}

/// `k` periods of the map from `s`: the state after them and `int F` over them.
pub(crate) fn map_k(fd: &Foundation, s: &Reduced, k: usize) -> (Reduced, f64) {
    map_k_recorded(fd, s, k, &mut Record::default())
}

/// [`map_k`] recording into `rec`.
fn map_k_recorded(fd: &Foundation, s: &Reduced, k: usize, rec: &mut Record) -> (Reduced, f64) {
    let (mut x, mut v, mut springs) = expand(fd, s);
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

/// [`map_k`] with the derivatives of its state and `int F` by `s`'s
/// (`None` where the map is not differentiable along the way,
/// [`Tangent`]): the springs' derivative by `(x, x', l_i of the springs
/// stuck at the start)`, composed with `l_i = x - f_i + b_i` at both ends.
pub(crate) fn map_k_tangent(fd: &Foundation, s: &Reduced, k: usize) -> ((Reduced, f64), Option<Derivatives>) {
    let springs = expand(fd, s).2;
    let mut rec = Record { tangent: Some(Tangent::new(&fd.w, &springs)), ..Record::default() };
    let mapped = map_k_recorded(fd, s, k, &mut rec);
    let n = 2 + springs.len();
    // The start's columns: x, x', then the stuck springs' levels in order.
    let stuck: Vec<usize> = (0..springs.len()).filter(|&i| s.0[i] == Kind::Stick).collect();
    // d/d(x, x', f_1..f_N) of a row by (x, x', l of the stuck): dl_i = dx - df_i.
    let by_reduced = |r: &RowDVector<f64>| {
        let mut out = RowDVector::zeros(n);
        (out[0], out[1]) = (r[0], r[1]);
        for (c, &i) in stuck.iter().enumerate() {
            out[0] += r[2 + c];
            out[2 + i] = -r[2 + c];
        }
        out
    };
    let derivatives = rec.tangent.as_ref().and_then(Tangent::get).map(|(body, levels)| {
        let rows = |i: usize| by_reduced(&body.row(i).into_owned());
        let (x, v, int_f) = (rows(X), rows(V), rows(INT_F));
        let mut jac = DMatrix::zeros(n, n);
        jac.set_row(0, &x);
        jac.set_row(1, &v);
        // f_i = x - l_i + b_i at the end where spring i sticks there.
        for (i, level) in levels.iter().enumerate() {
            if let (Kind::Stick, Some(l)) = (mapped.0 .0[i], level) {
                jac.set_row(2 + i, &(&x - by_reduced(l)));
            }
        }
        (jac, int_f.transpose())
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

/// The stated start (the system's module docs) as the period map's state:
/// the body at the drive's position with its velocity; springs in contact
/// at `tau = 0` stuck and relaxed, one touching there (its bound 0) as at a
/// regain of contact, the others free.
pub(crate) fn stated_start(fd: &Foundation) -> Reduced {
    let start = fd.p.start();
    let springs = fd.start(&start);
    reduce(fd, start[X], start[V], &springs)
}
