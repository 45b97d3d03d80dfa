//! Gauss-Legendre nodes and weights by Newton's method on the Legendre
//! polynomial (the classical construction, independent of the library's
//! Golub-Welsch rules): reference quadratures for the tests.

/// The `n`-point Gauss-Legendre rule on `[-1, 1]`: `(nodes, weights)`.
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let (mut x, mut w) = (vec![0.0; n], vec![0.0; n]);
    for i in 0..n {
        // Tricomi's initial guess, then Newton on P_n.
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let kf = k as f64;
                let p2 = ((2.0 * kf - 1.0) * z * p1 - (kf - 1.0) * p0) / kf;
                p0 = p1;
                p1 = p2;
            }
            let pn = if n == 0 { 1.0 } else { p1 };
            let pm = if n == 0 { 0.0 } else { p0 };
            dp = n as f64 * (z * pn - pm) / (z * z - 1.0);
            let dz = pn / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

/// `int_a^b f` by the `n`-point rule with `x = a + (b - a)(1 - cos theta)/2`
/// (grades both ends: square-root behaviour there is integrated smoothly).
pub fn graded(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let (x, w) = gauss_legendre(n);
    let h = 0.5 * (b - a);
    let q = 0.5 * std::f64::consts::PI;
    x.iter()
        .zip(&w)
        .map(|(&u, &wi)| {
            let (st, ct) = (q * (1.0 + u)).sin_cos();
            wi * h * st * q * f(a + h * (1.0 - ct))
        })
        .sum()
}

/// The `n`-point Gauss-Jacobi rule for the weight `(1 + x)^beta` on `[-1, 1]`
/// (`beta > -1`): nodes by Newton's method on the Jacobi polynomial
/// `P_n^(0, beta)` (three-term recurrence), weights by the classical formula
/// (Numerical Recipes' `gaujac`). Independent of the library's Golub-Welsch rules.
pub fn gauss_jacobi(n: usize, beta: f64) -> (Vec<f64>, Vec<f64>) {
    let alf = 0.0;
    let bet = beta;
    let nf = n as f64;
    let (mut x, mut w) = (vec![0.0; n], vec![0.0; n]);
    // P_n and P_{n-1} at z, and the derivative of P_n.
    let eval = |z: f64| {
        let alfbet = alf + bet;
        let mut p1 = (alf - bet + (2.0 + alfbet) * z) / 2.0;
        let mut p2 = 1.0;
        for j in 2..=n {
            let jf = j as f64;
            let p3 = p2;
            p2 = p1;
            let temp = 2.0 * jf + alfbet;
            let a = 2.0 * jf * (jf + alfbet) * (temp - 2.0);
            let b = (temp - 1.0) * (alf * alf - bet * bet + temp * (temp - 2.0) * z);
            let c = 2.0 * (jf - 1.0 + alf) * (jf - 1.0 + bet) * temp;
            p1 = (b * p2 - c * p3) / a;
        }
        let temp = 2.0 * nf + alfbet;
        let pp = (nf * (alf - bet - temp * z) * p1 + 2.0 * (nf + alf) * (nf + bet) * p2) / (temp * (1.0 - z * z));
        (p1, pp)
    };
    // Nodes descending from Newton on initial guesses spread like Chebyshev points.
    let mut prev: Vec<f64> = vec![];
    for i in 0..n {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
        for _ in 0..200 {
            let (p1, pp) = eval(z);
            // Deflate the roots already found.
            let s: f64 = prev.iter().map(|r| 1.0 / (z - r)).sum();
            let dz = p1 / (pp - p1 * s);
            z -= dz;
            if dz.abs() <= 1e-16 * z.abs().max(1e-3) {
                break;
            }
        }
        prev.push(z);
        x[i] = z;
        let (_, pp) = eval(z);
        let alfbet = alf + bet;
        let lg = libm::lgamma;
        let temp = 2.0 * nf + alfbet;
        // w = Gamma(n+a+1) Gamma(n+b+1) / (Gamma(n+1) Gamma(n+a+b+1)) 2^(a+b+1) / ((1 - z^2) P'^2)
        let _ = temp;
        let c = (lg(nf + alf + 1.0) + lg(nf + bet + 1.0) - lg(nf + 1.0) - lg(nf + alfbet + 1.0)).exp();
        w[i] = c * 2f64.powf(alfbet + 1.0) / ((1.0 - z * z) * pp * pp);
    }
    (x, w)
}

/// Tanh-sinh over [a, b] at step h: `(int f, int g)` for a pair of integrands.
pub fn tanh_sinh(a: f64, b: f64, h: f64, f: &dyn Fn(f64) -> (f64, f64)) -> (f64, f64) {
    let half = 0.5 * (b - a);
    let (mut sf, mut sg) = (0.0, 0.0);
    let kmax = (3.5 / h) as i64;
    for k in -kmax..=kmax {
        let t = k as f64 * h;
        let u = 0.5 * std::f64::consts::PI * t.sinh();
        let cu = u.cosh();
        let w = half * 0.5 * std::f64::consts::PI * t.cosh() / (cu * cu);
        // Distance to the nearer end without rounding: (b - a) / (1 + e^{2|u|}).
        let d = (b - a) / (1.0 + (2.0 * u.abs()).exp());
        let x = if t < 0.0 { a + d } else { b - d };
        if d <= 0.0 || w == 0.0 {
            continue;
        }
        let (p, q) = f(x);
        sf += w * p;
        sg += w * q;
    }
    (h * sf, h * sg)
}
