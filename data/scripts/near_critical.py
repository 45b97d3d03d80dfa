"""Independent 50-digit values of the flat-punch reduction near vbar = 1.

Uses the seed's own form of the stick phase (eqs. 4, 8 with the sign corrected,
eq. 9), not fricosc's rearranged one: tau1 = asin v, tau2 the root of
cos tau2 = sqrt(1 - v^2) - v (tau2 - tau1) in (pi - tau1, 2 pi + tau1), and the
deficit (1/2pi) [ (tau2 - tau1) cos tau1 - (sin tau2 - sin tau1) - v (tau2 - tau1)^2 / 2 ].
Run: python3 data/scripts/near_critical.py   (needs mpmath)
"""
from mpmath import mp, mpf, asin, sqrt, cos, sin, pi, acos, findroot

mp.dps = 60


def deficit(v):
    v = mpf(v)
    t1 = asin(v)
    g = lambda t: cos(t) - (sqrt(1 - v * v) - v * (t - t1))
    # Bisection on the bracket, then polish (tiny root near the tangency).
    lo, hi = pi - t1, 2 * pi + t1
    for _ in range(400):
        m = (lo + hi) / 2
        if g(m) > 0:
            hi = m
        else:
            lo = m
    t2 = (lo + hi) / 2
    L = t2 - t1
    return (L * cos(t1) - (sin(t2) - sin(t1)) - v * L * L / 2) / (2 * pi)


def mean_normal(s):
    s = mpf(s)
    if s >= 1:
        return s
    th = acos(s)
    return (s * (pi - th) + sin(th)) / pi


for amp in (0.6, 2.0):
    for w in (1e-3, 1e-6, 1e-9, 1e-12):
        v = 1.0 - w  # the f64 that the test passes
        red = deficit(v) / mean_normal(1 / mpf(amp))
        print(f"({amp!r}, {v!r}, {mp.nstr(red, 25)}),")
