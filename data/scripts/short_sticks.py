"""Independent 40-digit values of single springs that stick from contact just
above s = -sqrt(1 - vbar^2), where sticks vanish: the stick is short (about
twice the distance eps = arcsin(vbar) - arccos(-s) from that edge, in phase)
and its deficit tiny (about eps^3), so that a form summing order-one terms
loses it (issue "Trust, round three": small values to full precision).

Independent of fricosc's formulas: the spring's steady state is built from the
seed's description (the bound B = s - cos t while in contact from
theta = arccos s to 2 pi - theta; the stick starts at contact with zero force
and follows vbar (t - theta); its end is the root of the plain gap
B(theta + x) - vbar x, found by bisection at the working precision), and the
means are mpmath quadratures: of the gap (the deficit, which the difference
of the means would cancel) and of B and the stick line (the tangential
force). Each value is computed at 80 and 120 digits (the gap's terms are of
order one where it is 1e-30); the two agree to the digits written (checked here). The
inputs are f64 values (printed exactly as their shortest representation), and
taken exactly.

Run: python3 data/scripts/short_sticks.py > data/short-sticks.json   (needs mpmath)
"""
import json
import math
from mpmath import mp, mpf, acos, asin, cos, pi, quad, nstr


def spring(s, v):
    """(deficit, mean tangential force, slip phase) of the spring s at vbar v."""
    theta = acos(s)
    gap = lambda x: s - cos(theta + x) - v * x
    # The gap rises from 0 while the bound's slope sin(theta + x) exceeds v,
    # to its maximum at x_top = pi - asin(v) - theta, then falls; the root lies
    # between x_top and the end of contact.
    lo, hi = pi - asin(v) - theta, 2 * pi - 2 * theta
    assert gap(lo) > 0 > gap(hi)
    for _ in range(mp.prec + 20):
        mid = (lo + hi) / 2
        if gap(mid) > 0:
            lo = mid
        else:
            hi = mid
    length = (lo + hi) / 2
    end = theta + length
    # The deficit as the quadrature of the gap itself (the difference of the
    # means would cancel), the tangential force as that of the stick line and
    # of the bound.
    deficit = quad(gap, [0, length]) / (2 * pi)
    tangential = (quad(lambda t: v * (t - theta), [theta, end]) + quad(lambda t: s - cos(t), [end, 2 * pi - theta])) / (2 * pi)
    return deficit, tangential, end


def cases():
    for v in [1e-4, 0.01, 0.3, 0.6, 0.9, 0.9999]:
        c = math.sqrt((1.0 - v) * (1.0 + v))
        for k in [0.3, 0.25, 0.2, 0.1, 1e-2, 1e-4, 1e-6, 1e-9, 1e-12]:
            s = -c + k * c * max(math.sqrt(1.0 - v), 1e-3)
            yield v, s


out = []
for v, s in cases():
    values = []
    for dps in (80, 120):
        mp.dps = dps
        values.append(spring(mpf(s), mpf(v)))
    for a, b in zip(*values):
        assert abs(a - b) <= abs(b) * mpf(10) ** -42, (v, s, a, b)
    d, f, t = values[1]
    mp.dps = 120
    out.append({"vbar": repr(v), "s": repr(s), "deficit": nstr(d, 40), "mean_tangential": nstr(f, 40), "slip_phase": nstr(t, 40)})
print(json.dumps({"cases": out}, indent=1))
