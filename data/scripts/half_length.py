"""40-digit values of a stick-first spring given by its stick's half-length h,
the reference of `Velocity::stick_first_by_half_length` (src/fricosc/src/model/spring/velocity.rs).

Independently of the closed forms there: for each (vbar, h) the stick's start
beta is found by mpmath's root finder on the gap H(L) = sin(beta) - sin(beta - L)
- vbar L = 0 at L = 2h (as a function of beta, from the bracket (-alpha, alpha)),
the deficit is the integral of H over the stick (mp.quad), the tangential mean
is <B> - D with <B> = (s (pi - u) + sin u)/pi the mean normal force of the
spring (s = sin beta, contact phase u = pi/2 - beta), and |du/dh| is mp.diff of
u(h); u itself is written too, and the phase of the spring rho = (1 - fraction)
L_t/2 below the exact top (near the top at small vbar it is small, and
`Foundation::pass_length` takes it from the top, rho below the top). h runs
over fractions of the tangent start's half-length L_t/2 (itself a root at 50
digits). Velocities from 0.001 (the lower limit of that form's use)
to 0.9999, each taken as the double the test passes (0.9999 as a decimal
differs in w = 1 - vbar by 5e-14 relatively).

Run: python3 data/scripts/half_length.py > data/half-length.json   (needs mpmath)
"""
import json
import sys

from mpmath import mp, mpf, sin, cos, asin, acos, pi, findroot, quad, diff, nstr

mp.dps = 50
VBARS = ["0.001", "0.003", "0.02", "0.1", "0.3", "0.5", "0.7", "0.9", "0.99", "0.9999"]
FRACTIONS = ["0.001", "0.05", "0.3", "0.7", "0.999", "1"]


def gap(beta, length, v):
    return sin(beta) - sin(beta - length) - v * length


def beta_of(h, v, alpha):
    # H(2h) as a function of beta rises from beta = -alpha (where sticks vanish) on.
    f = lambda b: gap(b, 2 * h, v)
    lo, hi = -alpha, alpha
    for _ in range(400):
        mid = (lo + hi) / 2
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
        if hi - lo < mpf(10) ** -48:
            break
    return findroot(f, (lo + hi) / 2, tol=mpf(10) ** -45)


def tangent_half_length(v, alpha):
    # The stick from the tangent start (beta = alpha) ends where H, positive
    # after its maximum at L = 2 alpha, falls through 0: scan for the sign
    # change, then refine.
    f = lambda length: gap(alpha, length, v)
    lo, hi = 2 * alpha * 0.999, 2 * pi
    xs = [lo + (hi - lo) * k / 2000 for k in range(2001)]
    for a, b in zip(xs, xs[1:]):
        if f(a) > 0 and f(b) <= 0:
            return findroot(f, (a, b), solver="anderson", tol=mpf(10) ** -45) / 2
    raise SystemExit(f"no tangent stick at vbar {v}")


cases = []
for vs in VBARS:
    v = mpf(float(vs))  # the double the test passes
    alpha = acos(v)
    h_t = tangent_half_length(v, alpha)
    for fs in FRACTIONS:
        h = mpf(fs) * h_t
        h = mpf(float(h))  # the double the test passes
        beta = beta_of(h, v, alpha)
        length = 2 * h
        deficit = quad(lambda x: gap(beta, x, v), [0, length]) / (2 * pi)
        u = pi / 2 - beta
        s = sin(beta)
        normal = (s * (pi - u) + sin(u)) / pi
        du_dh = abs(diff(lambda hh: pi / 2 - beta_of(hh, v, alpha), h))
        # The spring rho below the exact top (rho as the double the test
        # passes): its phase, which a band's nodes take from the top.
        rho = mpf(float((1 - mpf(fs)) * h_t))
        u_below_top = pi / 2 - beta_of(h_t - rho, v, alpha) if rho > 0 else pi / 2 - alpha
        cases.append({
            "vbar": float(v),
            "h": float(h),
            "beta": nstr(beta, 40),
            "deficit": nstr(deficit, 40),
            "tangential": nstr(normal - deficit, 40),
            "du_dh": nstr(du_dh, 40),
            "u": nstr(u, 40),
            "rho": float(rho),
            "u_below_top": nstr(u_below_top, 40),
        })
        print(f"vbar {vs} h {fs}: done", file=sys.stderr)

json.dump({"source": "data/scripts/half_length.py", "cases": cases}, sys.stdout, indent=0)
print()
