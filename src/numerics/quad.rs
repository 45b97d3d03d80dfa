//! Gauss-Jacobi rules by Golub-Welsch (eigenvalues of the Jacobi matrix, nalgebra),
//! cached per thread: at most [`MAX_CACHED`] rules, the least recently used
//! evicted (a batch of many power-law exponents would otherwise keep a rule per
//! exponent and order for ever).
//!
//! The rule of order `m` integrates `int_{-1}^{1} (1 + x)^beta p(x) dx` exactly for
//! polynomials `p` of degree `< 2m` (`beta = 0`: Gauss-Legendre). The Jacobi
//! matrix of the monic Jacobi polynomials for weight `(1 + x)^beta` (alpha = 0) has
//! diagonal `a_k = beta^2 / ((2k + beta)(2k + beta + 2))` and off-diagonal
//! `b_k = sqrt(4 k^2 (k + beta)^2 / ((2k + beta)^2 (2k + beta + 1)(2k + beta - 1)))`;
//! the weights are `mu0 v_0^2` with `mu0 = 2^(beta + 1) / (beta + 1)`.

use nalgebra::DMatrix;
use std::cell::RefCell;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::rc::Rc;

/// Nodes (ascending) and weights on `[-1, 1]` for the weight `(1 + x)^beta`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Rule {
    /// Nodes, ascending.
    pub nodes: Vec<f64>,
    /// Weights (positive, summing to `mu0`).
    pub weights: Vec<f64>,
}

/// Compute the `m`-point rule for weight `(1 + x)^beta`, `beta > -1`, `m >= 1`.
pub(crate) fn gauss_jacobi(m: usize, beta: f64) -> Rule {
    assert!(m >= 1 && beta > -1.0);
    let mut j = DMatrix::<f64>::zeros(m, m);
    for k in 0..m {
        let kf = k as f64;
        let d = 2.0 * kf + beta;
        j[(k, k)] = if k == 0 { beta / (beta + 2.0) } else { beta * beta / (d * (d + 2.0)) };
        if k + 1 < m {
            let k1 = kf + 1.0;
            let d1 = 2.0 * k1 + beta;
            let b = (4.0 * k1 * k1 * (k1 + beta) * (k1 + beta) / (d1 * d1 * (d1 + 1.0) * (d1 - 1.0))).sqrt();
            j[(k, k + 1)] = b;
            j[(k + 1, k)] = b;
        }
    }
    let mu0 = 2f64.powf(beta + 1.0) / (beta + 1.0);
    let eig = j.symmetric_eigen();
    let mut pairs: Vec<(f64, f64)> =
        (0..m).map(|i| (eig.eigenvalues[i], mu0 * eig.eigenvectors[(0, i)].powi(2))).collect();
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    Rule { nodes: pairs.iter().map(|p| p.0).collect(), weights: pairs.iter().map(|p| p.1).collect() }
}

/// Most rules one thread keeps: every order of a power law's three weights
/// (Legendre, and two Jacobi exponents: 9 orders each) for a few dozen exponents.
pub(crate) const MAX_CACHED: usize = 512;

/// The rules of one thread, each with the tick of its last use.
#[derive(Default)]
struct Cache {
    rules: HashMap<(usize, u64), (Rc<Rule>, u64), WordHash>,
    tick: u64,
}

type WordHash = BuildHasherDefault<WordHasher>;

/// A multiply-rotate hash of whole words (FxHash's step) for the cache's keys,
/// an order and a weight's bits: ~5 instructions a lookup where the standard
/// SipHash took ~170 (a curved point looks up ~20 rules). The keys are the
/// program's own, so nothing needs SipHash's resistance to chosen collisions.
#[derive(Default)]
struct WordHasher(u64);

impl Hasher for WordHasher {
    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.write_u64(u64::from(*b));
        }
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
    fn write_usize(&mut self, x: usize) {
        self.write_u64(x as u64);
    }
    fn finish(&self) -> u64 {
        self.0
    }
}

thread_local! {
    static CACHE: RefCell<Cache> = RefCell::new(Cache::default());
}

/// The cached rule of order `m` for weight `(1 + x)^beta`.
pub(crate) fn rule(m: usize, beta: f64) -> Rc<Rule> {
    CACHE.with(|c| {
        let mut c = c.borrow_mut();
        c.tick += 1;
        let tick = c.tick;
        let key = (m, beta.to_bits());
        if let Some(entry) = c.rules.get_mut(&key) {
            entry.1 = tick;
            return entry.0.clone();
        }
        if c.rules.len() >= MAX_CACHED {
            // Evict the least recently used (a scan, on a miss only: the miss
            // itself costs an eigenproblem).
            if let Some(&old) = c.rules.iter().min_by_key(|(_, v)| v.1).map(|(k, _)| k) {
                c.rules.remove(&old);
            }
        }
        let r = Rc::new(gauss_jacobi(m, beta));
        c.rules.insert(key, (r.clone(), tick));
        r
    })
}

/// Rules held by this thread's cache.
#[cfg(test)]
fn cached() -> usize {
    CACHE.with(|c| c.borrow().rules.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn legendre_integrates_polynomials_exactly() {
        let r = gauss_jacobi(8, 0.0);
        for p in 0..16 {
            let q: f64 = r.nodes.iter().zip(&r.weights).map(|(x, w)| w * x.powi(p)).sum();
            let exact = if p % 2 == 1 { 0.0 } else { 2.0 / (p as f64 + 1.0) };
            assert!((q - exact).abs() < 1e-14, "x^{p}: {q} vs {exact}");
        }
    }

    #[test]
    fn the_cache_stays_bounded_and_keeps_what_is_used() {
        let legendre = rule(8, 0.0);
        for k in 0..(2 * MAX_CACHED) {
            let _ = rule(2, -0.5 + k as f64 * 1e-6);
            // The rule in use is touched on every round and never evicted.
            assert!(Rc::ptr_eq(&rule(8, 0.0), &legendre));
        }
        assert!(cached() <= MAX_CACHED, "{}", cached());
    }

    #[test]
    fn jacobi_integrates_the_weighted_moments() {
        // int_{-1}^{1} (1+x)^beta (1+x)^p dx = 2^(beta+p+1) / (beta+p+1).
        for beta in [-0.5, 0.3, 1.0] {
            let r = gauss_jacobi(10, beta);
            for p in 0..20 {
                let q: f64 = r.nodes.iter().zip(&r.weights).map(|(x, w)| w * (1.0 + x).powi(p)).sum();
                let exact = 2f64.powf(beta + p as f64 + 1.0) / (beta + p as f64 + 1.0);
                assert!((q / exact - 1.0).abs() < 1e-13, "beta {beta} p {p}: {q} vs {exact}");
            }
        }
    }
}
