//! Two or three of [`Series`]' products in one pass, for the slip step:
//! each result's operations, in their order, are those of the single
//! product ([`Series::div`], [`Series::square`], `Mul`), and so are its
//! bits; the passes interleave their chains of dependent operations.

use super::series::{Series, LEN};

impl Series {
    /// `[a / d, b / d]` for `[a, b] = num` by [`Series::div`], the two in one
    /// pass (each quotient's operations, and so its bits, are `div`'s: two
    /// chains of dependent operations interleaved).
    pub(crate) fn div_pair(num: &[Series; 2], d: &Series) -> [Series; 2] {
        let d = &d.0;
        let (mut na, mut nb, mut qa, mut qb) = (num[0].0, num[1].0, [0.0; LEN], [0.0; LEN]);
        let inv = 1.0 / d[0];
        for k in 0..LEN {
            let (ak, bk) = (na[k] * inv, nb[k] * inv);
            (qa[k], qb[k]) = (ak, bk);
            for ((x, y), &dj) in na[k + 1..].iter_mut().zip(&mut nb[k + 1..]).zip(&d[1..]) {
                *x -= dj * ak;
                *y -= dj * bk;
            }
        }
        [Series(qa), Series(qb)]
    }

    /// `[a^2, b^2, a b]` for `[a, b] = y` by [`Series::square`] and [`Mul`],
    /// in one pass (each result's operations, and so its bits, theirs).
    pub(crate) fn squares_and_product(y: &[Series; 2]) -> [Series; 3] {
        let (a, b) = (&y[0].0, &y[1].0);
        let (mut sa, mut sb, mut p) = ([0.0; LEN], [0.0; LEN], [0.0; LEN]);
        for i in 0..LEN {
            if 2 * i < LEN {
                sa[2 * i] += a[i] * a[i];
                sb[2 * i] += b[i] * b[i];
            }
            let (ta, tb) = (2.0 * a[i], 2.0 * b[i]);
            if 2 * i + 1 < LEN {
                for ((x, y), (&u, &v)) in
                    sa[2 * i + 1..].iter_mut().zip(&mut sb[2 * i + 1..]).zip(a[i + 1..].iter().zip(&b[i + 1..]))
                {
                    *x += ta * u;
                    *y += tb * v;
                }
            }
            let ai = a[i];
            for (r, &v) in p[i..].iter_mut().zip(b) {
                *r += ai * v;
            }
        }
        [Series(sa), Series(sb), Series(p)]
    }

    /// `self * o` for each `o` of `others` by [`Mul`], in one pass (the same bits).
    pub(crate) fn mul_each<const K: usize>(&self, others: [&Series; K]) -> [Series; K] {
        let mut r = [Series([0.0; LEN]); K];
        for (i, &s) in self.0.iter().enumerate() {
            for j in i..LEN {
                for (rk, o) in r.iter_mut().zip(&others) {
                    rk.0[j] += s * o.0[j - i];
                }
            }
        }
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A series with coefficients of both signs and decaying sizes (`seed` picks them).
    fn series(seed: u64) -> Series {
        let mut x = seed;
        let mut a = [0.0; LEN];
        for (k, c) in a.iter_mut().enumerate() {
            x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            *c = ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.7f64.powi(k as i32);
        }
        Series(a)
    }

    /// Each fused result is the single product's, bit for bit.
    #[test]
    fn fused_products_are_the_single_ones_bit_for_bit() {
        for seed in 1..50 {
            let (a, b, mut d) = (series(seed), series(seed + 100), series(seed + 200));
            d.0[0] += 1.0;
            assert_eq!(Series::div_pair(&[a, b], &d), [a.div(&d), b.div(&d)]);
            assert_eq!(Series::squares_and_product(&[a, b]), [a.square(), b.square(), a * b]);
            assert_eq!(d.mul_each([&a, &b]), [d * a, d * b]);
            assert_eq!(d.mul_each([&a, &b, &d]), [d * a, d * b, d * d]);
        }
    }
}
