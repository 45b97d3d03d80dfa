//! One phase of the flat punch on a system with mass and stiffness, in
//! closed form: the augmented state `z = (x, x', int f, y0, 1, tau, cos tau,
//! sin tau)` obeys `z' = A z` with `A` constant within a phase, so
//! `z(tau0 + h) = exp(A h) z(tau0)`: a full sampling step by the step's
//! matrix exponential (nalgebra's Pade, to a few ulps of its entries), a
//! part of one by the exponential's Taylor series applied to `z` ([`advance`]).
//! The body's equation
//!
//! `Omega^2 x'' = kappa (X_d - x) - 2 zeta sqrt(kappa) Omega (x' - X_d') - f`,
//!
//! `X_d = vhat tau + T sin(tau + phase)`, is linear in `z` in every phase:
//! stick `f = x - y0`, slip `f = +-B = +-(1 - amp cos tau)`, out of contact
//! `f = 0`; so is `(int f)' = f`.

use nalgebra::{SMatrix, SVector};

/// The augmented state.
pub(crate) type State = SVector<f64, 8>;
/// Its generator in one phase.
pub(crate) type Generator = SMatrix<f64, 8, 8>;

/// Components of [`State`].
pub(crate) const X: usize = 0;
pub(crate) const V: usize = 1;
pub(crate) const INT_F: usize = 2;
pub(crate) const Y0: usize = 3;
pub(crate) const ONE: usize = 4;
pub(crate) const TAU: usize = 5;
pub(crate) const COS: usize = 6;
pub(crate) const SIN: usize = 7;

/// What the contact spring does in a phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Kind {
    /// The contact point holds (`|f| < B`).
    Stick,
    /// It slips forward (`f = B`).
    Forward,
    /// It slips backward (`f = -B`).
    Backward,
    /// Out of contact (`B = 0`, the spring relaxed).
    Free,
}

/// A contact force linear in the state: `x x + y0 y0 + one + cos cos tau`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Linear {
    pub(crate) x: f64,
    pub(crate) y0: f64,
    pub(crate) one: f64,
    pub(crate) cos: f64,
}

/// The parameters of the body and the drive (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Params {
    pub(crate) kappa: f64,
    pub(crate) omega: f64,
    pub(crate) zeta: f64,
    pub(crate) vhat: f64,
    pub(crate) amp: f64,
    pub(crate) t: f64,
    pub(crate) phase: f64,
}

impl Params {
    /// `A` of a phase whose contact force is `f`: the body's row
    /// `Omega^2 x'' = kappa X_d + damp X_d' - damp x' - kappa x - f`, and
    /// `(int f)' = f`.
    pub(crate) fn generator_of(&self, f: Linear) -> Generator {
        let (kappa, om2) = (self.kappa, self.omega * self.omega);
        let damp = dashpot(kappa, self.omega, self.zeta);
        let (sp, cp) = self.phase.sin_cos();
        let mut a = Generator::zeros();
        a[(X, V)] = 1.0;
        let mut row = [0.0; 8];
        row[X] = -kappa - f.x;
        row[V] = -damp;
        row[Y0] = -f.y0;
        row[ONE] = damp * self.vhat - f.one;
        row[TAU] = kappa * self.vhat;
        row[COS] = self.t * (kappa * sp + damp * cp) - f.cos;
        row[SIN] = self.t * (kappa * cp - damp * sp);
        for (j, r) in row.iter().enumerate() {
            a[(V, j)] = r / om2;
        }
        (a[(INT_F, X)], a[(INT_F, Y0)], a[(INT_F, ONE)], a[(INT_F, COS)]) = (f.x, f.y0, f.one, f.cos);
        a[(TAU, ONE)] = 1.0;
        a[(COS, SIN)] = -1.0;
        a[(SIN, COS)] = 1.0;
        a
    }

    /// The state at the stated start (`tau = 0`): the body at the drive's
    /// position with its velocity, the spring relaxed (`y0 = x`).
    pub(crate) fn start(&self) -> State {
        let (sp, cp) = self.phase.sin_cos();
        let x = self.t * sp;
        State::from([x, self.vhat + self.t * cp, 0.0, x, 1.0, 0.0, 1.0, 0.0])
    }
}

/// The dashpot's coefficient in the seed's units, `c/(m omega) Omega^2 =
/// 2 zeta sqrt(kappa) Omega` (`zeta = c/(2 sqrt(K m))`).
pub(crate) fn dashpot(kappa: f64, omega: f64, zeta: f64) -> f64 {
    2.0 * zeta * kappa.sqrt() * omega
}

/// Most terms of [`series`] (`None` beyond).
const MAX_TERMS: usize = 40;

/// `sum_k (a h)^k z j!/(k + j)!`, summed until a term is below `2^-60` of
/// the sum: for `j = 0` it is `exp(a h) z`, for `j = 1` `phi_1(a h) z`, where
/// `phi_1(x) = (e^x - 1)/x`. Within a sampling step (a quarter of the fastest
/// time scale) the terms fall at least like `4^-k/k!`: about 20 terms, each a
/// product of the 8 x 8 generator with a vector, where the matrix exponential
/// costs about six products of matrices. `None` if [`MAX_TERMS`] do not do.
pub(crate) fn series(a: &Generator, z: &State, h: f64, j: usize) -> Option<State> {
    let (mut term, mut sum) = (*z, *z);
    for k in 1..=MAX_TERMS {
        term = a * term * (h / (k + j) as f64);
        sum += term;
        if term.amax() <= sum.amax() * f64::EPSILON / 256.0 {
            return Some(sum);
        }
    }
    None
}

/// `exp(m)` by nalgebra's Pade exponential with the generator's structural
/// zeros kept exact: an entry `(i, j)` of `exp(m)` is 0 wherever no chain of
/// nonzero entries of `m` leads from `i` to `j` (the row of `int f` in a
/// slip reads only the drive, `cos tau`, never the body, and so does its
/// exponential's). Pade's solve mixes the body's large rows (`kappa/Omega^2`)
/// into such entries: 1e-17 of a position of 20 a step, 2.4e-14 of `mu` over
/// a period's 436 steps of a pure slip (an internal error: `mu` beyond 1 by
/// more than its estimate).
pub(crate) fn exp_structured(m: &Generator) -> Generator {
    // Row i's reach as bits; the transitive closure by Warshall's rule.
    let mut reach = [0u8; 8];
    for (i, row) in reach.iter_mut().enumerate() {
        *row = (0..8).filter(|&j| i == j || m[(i, j)] != 0.0).fold(0, |r, j| r | 1 << j);
    }
    for k in 0..8 {
        for i in 0..8 {
            if reach[i] & 1 << k != 0 {
                reach[i] |= reach[k];
            }
        }
    }
    let mut e = m.exp();
    for (i, row) in reach.iter().enumerate() {
        for j in (0..8).filter(|&j| row & 1 << j == 0) {
            e[(i, j)] = 0.0;
        }
    }
    e
}

/// `exp(a h) z`: its [`series`], or beyond it (a longer step) nalgebra's Pade
/// exponential.
pub(crate) fn advance(a: &Generator, z: &State, h: f64) -> State {
    series(a, z, h, 0).unwrap_or_else(|| (a * h).exp() * z)
}
