"""Independent 40-digit values of the flat punch at small velocities and near
amp = 1: event phases, event forces and mu_macro/mu0 (issue: events and small
values to full precision).

Independent of fricosc's formulas: the steady state is built from the seed's
description (slip on the bound B = s - cos tau, stick line F0 + vbar (tau - t0)),
the stick end is found by bisection on the plain gap B(t0 + x) - B(t0) - vbar x
in 50-digit arithmetic, and the means are mpmath quadratures of B and of the
stick line over their phases (not closed forms). The inputs are the f64 values
the test passes, taken exactly.

Run: python3 data/scripts/flat_events.py > data/flat-events.json   (needs mpmath)
     python3 data/scripts/flat_events.py --near-one > data/flat-near-one.json
The second: mu_macro/mu0 on a log grid of vbar 1e-16..1e-2 at amp = 1, just
below it (1 - amp = 1e-12 .. 1e-2) and above it, where mu is small and must keep its
relative accuracy.
"""
import json
import sys
from mpmath import mp, mpf, asin, acos, cos, pi, quad, nstr

mp.dps = 50


def state(vbar, amp):
    v, a = mpf(vbar), mpf(amp)
    s = 1 / a
    B = lambda t: s - cos(t)
    delta = asin(v)
    c = cos(delta)
    theta = acos(s) if s < 1 else None
    if s >= c:  # tangent start (eq. 4)
        t0, f0 = delta, s - c
        xmax = 2 * pi if s >= 1 else 2 * pi - theta - delta
    else:  # stick from the moment of contact (eq. 18)
        t0, f0 = theta, mpf(0)
        xmax = 2 * pi - 2 * theta
    gap = lambda x: B(t0 + x) - f0 - v * x
    # Bracket: the gap peaks where the bound's slope is vbar again (t0 + x = pi - delta)
    # and is negative at xmax.
    lo = max(pi - t0 - delta, mpf(0))
    hi = xmax
    assert gap(lo) > 0 > gap(hi), (vbar, amp)
    for _ in range(200):
        m = (lo + hi) / 2
        if gap(m) > 0:
            lo = m
        else:
            hi = m
    L = (lo + hi) / 2
    t1 = t0 + L
    stick = quad(lambda t: f0 + v * (t - t0), [t0, t1])
    if s >= 1:
        slip = quad(B, [t1, t0 + 2 * pi])
        normal = s * 2 * pi
    else:
        # Contact from theta to 2 pi - theta; slip wherever not stuck.
        slip = quad(B, [t1, 2 * pi - theta])
        if s >= c:
            slip += quad(B, [theta, t0])
        normal = quad(B, [theta, 2 * pi - theta])
    mu = (stick + slip) / normal
    events = []
    if theta is not None:
        events.append(("contact", theta, mpf(0)))
        events.append(("loss_of_contact", 2 * pi - theta, mpf(0)))
    events.append(("stick", t0, a * f0))
    events.append(("slip", t1 % (2 * pi), a * (f0 + v * L)))
    events.sort(key=lambda e: e[1])
    return mu, events


def main():
    if "--near-one" in sys.argv:
        cases = []
        vbars = [10.0 ** -k for k in range(16, 1, -1)] + [3e-16, 3e-13, 3e-9, 3e-5]
        amps = [1.0] + [1.0 - 10.0 ** -k for k in (12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2)] + [1.0 + 10.0 ** -k for k in (12, 8, 4)]
        for amp in amps:
            for vbar in sorted(vbars):
                mu, _ = state(vbar, amp)
                cases.append({"vbar": vbar, "amp": amp, "mu_ratio": nstr(mu, 40), "reduction": nstr(1 - mu, 40)})
        print(json.dumps({"source": "data/scripts/flat_events.py --near-one (mpmath, 50 digits)", "cases": cases}, indent=1))
        return

    cases = []
    vbars = [1e-15, 1.719072201858571e-16, 1e-13, 1e-12, 1e-10, 1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 0.1, 0.5]
    amps = [0.5, 1.0, 1.0000000075128732, 1 + 1e-9, 1 + 1e-6, 1.01, 1.5, 2.0, 10.0, 1e3]
    for amp in amps:
        for vbar in vbars:
            mu, ev = state(vbar, amp)
            cases.append({
                "vbar": vbar,
                "amp": amp,
                "mu_ratio": nstr(mu, 40),
                "reduction": nstr(1 - mu, 40),
                "events": [{"kind": k, "tau": nstr(t, 40), "force": nstr(f, 40)} for k, t, f in ev],
            })
    print(json.dumps({"source": "data/scripts/flat_events.py (mpmath, 50 digits)", "cases": cases}, indent=1))


if __name__ == "__main__":
    main()
