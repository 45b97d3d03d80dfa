"""The fitted Halley start for the stick length L(vbar) of a tangent start.

A spring in permanent contact (and a jumping one that slips first) starts to
stick at tau_s = arcsin vbar; its stick length L is the root in (2 alpha, 2 pi)
of H(x) = S(alpha - x) - S(alpha) + (1 - vbar) x, S(y) = y - sin y,
alpha = arccos vbar (src/fricosc/src/model/spring/stick.rs). It depends on vbar alone, so a fit
good to 1e-9 makes Halley's first step the last one at the means' tolerance.

Two regions, polynomials of degree 10 fitted on 60 Chebyshev points of 40-digit
roots (mpmath) and checked on 2,000 others:
- vbar <= 0.35: the tail e = 2 pi - L = 2 sqrt(pi vbar) g(t), g a polynomial in
  t = sqrt(vbar) (the tail's expansion is in powers of sqrt(vbar));
- vbar > 0.35: L = alpha h(alpha^2), h(0) = 3 (L ~ 3 alpha as vbar -> 1).
Prints the coefficients (highest power first, for Horner) pasted into
`tangent_length_guess`, and the largest relative error of the guess.
Run: python3 data/scripts/tangent_guess.py   (needs mpmath and numpy)
"""
import numpy as np
from mpmath import mp, mpf, acos, cos, sin, sqrt, pi, findroot

mp.dps = 40
SPLIT = 0.35
DEGREE = 10


def stick_length(v):
    v = mpf(v)
    a, w = acos(v), 1 - v
    s = lambda y: y - sin(y)
    h = lambda x: s(a - x) - s(a) + w * x
    # H > 0 just above 2 alpha and < 0 at 2 pi: bisection, then polish.
    lo, hi = 2 * a + (2 * pi - 2 * a) * mpf("1e-6"), 2 * pi
    for _ in range(60):
        m = (lo + hi) / 2
        lo, hi = (m, hi) if h(m) > 0 else (lo, m)
    return findroot(h, (lo + hi) / 2)


def cheb(lo, hi, n):
    return 0.5 * (hi + lo) + 0.5 * (hi - lo) * np.cos(np.pi * (np.arange(n) + 0.5) / n)


def tail_g(t):
    return float((2 * pi - stick_length(mpf(t) ** 2)) / (2 * sqrt(pi) * mpf(t)))


def ratio_h(x):
    a = sqrt(mpf(x))
    return float(stick_length(cos(a)) / a)


t_max = np.sqrt(SPLIT)
x_max = float(acos(mpf(SPLIT)) ** 2)
ts = cheb(0.0, t_max, 60)
xs = cheb(0.0, x_max, 60)
c_tail = np.polyfit(ts, [tail_g(t) for t in ts], DEGREE)
c_ratio = np.polyfit(xs, [ratio_h(x) for x in xs], DEGREE)


def guess(v):
    if v <= SPLIT:
        t = np.sqrt(v)
        return 2 * np.pi - 2 * np.sqrt(np.pi) * t * np.polyval(c_tail, t)
    a = float(acos(mpf(v)))
    return a * np.polyval(c_ratio, a * a)


worst = 0.0
for v in np.linspace(1e-6, 1 - 1e-6, 2000):
    exact = stick_length(v)
    worst = max(worst, abs(float(mpf(guess(v)) / exact - 1)))
print("tail (t = sqrt(vbar)):", ", ".join(repr(float(c)) for c in c_tail))
print("ratio (x = alpha^2):", ", ".join(repr(float(c)) for c in c_ratio))
print(f"largest relative error on 2,000 velocities: {worst:.2e}")
