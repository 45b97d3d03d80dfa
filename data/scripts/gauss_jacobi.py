"""25-digit Gauss-Jacobi rules for the weight (1 + x)^beta on [-1, 1], the
reference of `numerics::quad::gauss_jacobi` (its nodes and weights, at every
order the MDR bands use between 1 and 256: the ladder's 8, 16, 24, 32, 48, ...;
and the exponents of the paraboloid, the cone, steep and near-singular power
laws).

Each rule is computed twice, at 60 digits:
- from the three-term recurrence of the Jacobi polynomials (the coefficients
  at 60 digits from their formula): every node refined by Newton on p_m from
  numpy's double-precision eigenvalues until the step is below 1e-55, each
  weight the Christoffel number 1 / sum_(k < m) p_k(x)^2 of the orthonormal
  polynomials; the weights must sum to mu0 = 2^(beta + 1)/(beta + 1) to 1e-40;
- for orders up to 32, independently by mpmath's own Golub-Welsch
  (`mp.gauss_quadrature(m, "jacobi", 0, beta)`, its Jacobi matrix and its
  eigensolver): the two must agree to 1e-35.

The exponents are doubles (a power law's gamma = 1/n - 1 is computed in
double precision), taken exactly: beta = -0.999999 means the double nearest
to it, whose beta + 1 differs from 1e-6 by 3e-11 relative.

Run: python3 data/scripts/gauss_jacobi.py > data/gauss-jacobi.json   (needs mpmath, numpy)
"""
import json
import sys

import numpy as np
from mpmath import mp, mpf, sqrt, nstr

mp.dps = 60
ORDERS = [1, 2, 8, 16, 24, 32, 48, 64, 96, 128, 192, 256]
BETAS = [0.0, -0.5, 1.0, -0.875, -0.99, 3.5, -0.999999]


def recurrence(m, b):
    a, o = [], []
    for k in range(m + 1):
        d = 2 * k + b
        a.append(b / (b + 2) if k == 0 else b * b / (d * (d + 2)))
        k1 = k + 1
        d1 = 2 * k1 + b
        o.append(sqrt(4 * k1 * k1 * (k1 + b) ** 2 / (d1 * d1 * (d1 + 1) * (d1 - 1))))
    return a, o


def rule_by_newton(m, b):
    a, o = recurrence(m, b)
    jac = np.zeros((m, m))
    for k in range(m):
        jac[k, k] = float(a[k])
        if k + 1 < m:
            jac[k, k + 1] = jac[k + 1, k] = float(o[k])
    mu0 = mpf(2) ** (b + 1) / (b + 1)
    rows = []
    for x0 in sorted(np.linalg.eigvalsh(jac)):
        x = mpf(x0)
        for _ in range(100):
            p0, p1, d0, d1 = mpf(0), mpf(1), mpf(0), mpf(0)
            for k in range(m):
                prev = o[k - 1] if k > 0 else 0
                p0, p1, d0, d1 = p1, ((x - a[k]) * p1 - prev * p0) / o[k], d1, ((x - a[k]) * d1 + p1 - prev * d0) / o[k]
            step = p1 / d1
            x -= step
            if abs(step) < mpf(10) ** -55:
                break
        else:
            raise SystemExit(f"Newton did not converge: m {m} beta {b}")
        p0, p1 = mpf(0), 1 / sqrt(mu0)
        s = p1 * p1
        for k in range(m - 1):
            prev = o[k - 1] if k > 0 else 0
            p0, p1 = p1, ((x - a[k]) * p1 - prev * p0) / o[k]
            s += p1 * p1
        rows.append((x, 1 / s))
    total = sum(w for _, w in rows)
    assert abs(total / mu0 - 1) < mpf(10) ** -40, (m, b, total, mu0)
    assert all(rows[i][0] < rows[i + 1][0] for i in range(m - 1)), (m, b)
    return rows


cases = []
for beta in BETAS:
    b = mpf(beta)
    for m in ORDERS:
        rows = rule_by_newton(m, b)
        if m <= 32:
            xs, ws = mp.gauss_quadrature(m, "jacobi", 0, b)
            other = sorted(zip(xs, ws))
            for (x, w), (y, v) in zip(rows, other):
                assert abs(x - y) < mpf(10) ** -35 and abs(w - v) < mpf(10) ** -35 * abs(w), (m, beta)
        cases.append({
            "m": m,
            "beta": beta,
            "nodes": [nstr(x, 25) for x, _ in rows],
            "weights": [nstr(w, 25) for _, w in rows],
        })
        print(f"m {m} beta {beta}: done", file=sys.stderr)

json.dump({"source": "data/scripts/gauss_jacobi.py", "cases": cases}, sys.stdout, indent=0)
print()
