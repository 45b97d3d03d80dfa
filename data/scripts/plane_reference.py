"""Independent 20-digit values of the flat punch under an oscillation across the
sliding direction (README.md, "Oscillation across the sliding direction"):
mu_macro/mu0 = <f_x>/<B>, the transverse ratio <f_y>/<B>, and the events of one
period, for the body at X(tau) = (vhat tau + T sin(tau + phase), W sin(tau + psi))
and the bound B = (1 - amp cos tau)_+.

Independent of fricosc's solver (src/fricosc/src/plane/):
- a slip is the angle equation th' = (cos th X'_y - sin th X'_x)/B, integrated
  by mpmath.odefun (its own Taylor method) at 24 digits; fricosc integrates
  the linear half-angle equation y' = M y by its own series;
- an event is a sign change on a grid of GRID points a period (|f|^2 - B^2 in
  stick, the slip rate X'.e - B' in slip), refined by bisection; fricosc
  isolates the roots of its series by exclusion;
- the steady state: periods from the relaxed start (f = 0 at tau = 0, or at
  first contact; for a drift too slow for that, a start given to 9 digits)
  until the force at the period's start repeats to 21 digits; where the
  orbit contracts too slowly for that (the map's multiplier within 1e-3 of
  1), Newton on the period map from a given start, its Jacobian by
  differences at 32 digits, until the residual is below 1e-28;
  fricosc uses Newton with the period map's variational derivative;
- the means are mpmath quadratures over each phase.
Where contact is regained into slip (a regular singular point) the slip starts
at DELTA after contact along X'; where it is lost, the slip stops DELTA before
(the parts left out are below 1e-40 of <B>).

Run: python3 data/scripts/plane_reference.py > data/plane-reference.json
(needs mpmath; about 25 minutes; `... plane_reference.py 0 2` runs cases 0 and 2 only.) Inputs are the f64 values the test passes.
"""
import json
import sys
from mpmath import mp, mpf, cos, sin, pi, quad, nstr, atan2, sqrt, acos, odefun

mp.dps = 24
GRID = 1024
DELTA = mpf("1e-24")

CASES = [
    # vhat, amp, T, phase, W, psi
    (0.3, 0.5, 0.0, 0.0, 1.2, 0.7),
    (0.3, 1.5, 0.0, 0.0, 1.2, 0.7),
    (0.1, 0.8, 1.0, 0.3, 0.8, 2.0),
    (0.3, 1.5, 1.5, 0.7, 1.2, 4.0),
    (0.05, 0.0, 0.0, 0.0, 2.0, 0.0),
    (1.0, 0.3, 0.0, 0.0, 0.5, 1.0),
    (0.2, 1.2, 0.0, 0.0, 3.0, 1.5),
    # A slip that reaches the loss of contact slower than the bound closes (|X'| < B').
    (0.47192399278273217, 1.991211363583415, 0.0, 0.0, 1.2836110893577237, 2.009461847020906),
    # A force on its bound at tau = 0 with a slip rate 0 to rounding (X' along y).
    (0.034864029987338035, 0.06651488676441611, 0.0, 0.0, 0.0014911485989938318, 1.5707963267948966),
    # Slow sliding, psi = pi/2: the body rests at tau = 0, out of contact,
    # and moves fast at the edges of contact, where the layer is.
    (0.0001897527803131793, 1.830260786990638, 0.0, 0.0, 2.0, 1.5707963267948966),
    # A drift too slow to relax from rest (about 1e9 periods, 2e-10 a period
    # near the orbit): relaxed from the force on its bound at the angle
    # 0.192923867 (9 digits), the reference checks the orbit, not the way to it.
    (1.31439828865443e-10, 1.0322297640969256e-06, 0.0, 0.0, 0.19173451864957627, 1.5707963267948966,
     ("0.9814468269604643728498", "0.1917291354770411702053")),
    # Contact regained where the body moves fast, and at tau = 0 slowly: the
    # thin layer at the edges of contact is set by the speed there.
    (0.09570414317035912, 1.6531710215547686, 0.0, -0.23240803896986684, 1.3943611366611741, 2.270458130923907),
    # A slow contraction (the period map's multiplier 0.69): 131 periods from rest.
    (0.0325026, 0.039, 0.0, 0.0, 0.3244, 4.5526),
    # The transverse drive alone, as in `figures` (directions-flat, W = 0.5 0.8/0.3).
    (0.1103030303030303, 0.0, 0.0, 0.0, 1.3333333333333335, 0.0),
    # Slow contractions (multipliers 1 - 1.1e-5 and 1 - 3.2e-4), by Newton:
    # small drives at a constant bound, the force near the x axis; and a
    # normal oscillation with the drive across, the force far from the axes.
    (1.7441358384264266e-06, 0.0, 0.0016171876476415883, 3.7652110076019483, 0.0006958643998562922,
     5.7596193737003345, ("0.9974422383331742", "-0.00011131248603770319"), "newton"),
    (2.059814337579708e-05, 0.38730156972940577, 0.0, 2.047812812301635, 0.5284214289510268,
     2.1360749029854107, ("0.6126859569948747", "-0.003909546946226635"), "newton"),
]


def spring(vhat, amp, t, phase, w, psi):
    vhat, amp, t, phase, w, psi = map(mpf, (vhat, amp, t, phase, w, psi))
    X = lambda x: (vhat * x + t * sin(x + phase), w * sin(x + psi))
    V = lambda x: (vhat + t * cos(x + phase), w * cos(x + psi))
    Bs = lambda x: 1 - amp * cos(x)  # analytic, signed
    dB = lambda x: amp * sin(x)
    edge = acos(1 / amp) if amp > 1 else None

    def bisect(g, lo, hi):
        glo = g(lo)
        for _ in range(150):
            m = (lo + hi) / 2
            if (g(m) > 0) == (glo > 0):
                lo = m
            else:
                hi = m
        return (lo + hi) / 2

    def first_change(g, a, b, skip_start):
        """First tau in (a, b] where g changes sign from its value just after a."""
        n = max(4, int(GRID * (b - a) / (2 * pi)) + 1)
        h = (b - a) / n
        x0 = a + (h * mpf("1e-6") if skip_start else 0)
        g0 = g(x0)
        for k in range(1, n + 1):
            x = a + h * k
            gx = g(x)
            if (gx > 0) != (g0 > 0):
                return bisect(g, x0, x)
            x0, g0 = x, gx
        return None

    return X, V, Bs, dB, edge, bisect, first_change


def period(case, start_tau, f0, end_tau, events):
    vhat, amp, t, phase, w, psi = case
    X, V, Bs, dB, edge, bisect, first_change = spring(*case)
    tau, state = mpf(start_tau), ("stick", f0) if f0 is not None else ("out", None)
    if f0 is not None and sqrt(f0[0] ** 2 + f0[1] ** 2) >= Bs(tau) * (1 - mpf(10) ** (8 - mp.dps)):
        # On the circle: a slip if the slip rate is positive.
        th = atan2(f0[1], f0[0])
        if V(tau)[0] * cos(th) + V(tau)[1] * sin(th) - dB(tau) > 0:
            state = ("slip", th)
    end_tau = mpf(end_tau)
    sums = [mpf(0), mpf(0)]
    loss = (2 * pi - edge) + 2 * pi * mp.floor((start_tau + edge) / (2 * pi)) if edge is not None else None
    while tau < end_tau:
        kind, val = state[0], state[1]
        if kind == "out":
            tc = edge + 2 * pi * mp.ceil((tau - edge) / (2 * pi))
            if tc >= end_tau:
                break
            events.append((tc, "contact"))
            v = V(tc)
            loss = tc + 2 * (pi - edge)
            if sqrt(v[0] ** 2 + v[1] ** 2) > dB(tc):
                tau, state = tc + DELTA, ("slip", atan2(v[1], v[0]))
            else:
                tau, state = tc, ("stick", (mpf(0), mpf(0)), True)
            continue
        stop = min(end_tau, loss - DELTA) if loss is not None else end_tau
        if kind == "stick":
            f0 = val
            skip = len(state) > 2
            x0 = X(tau)
            F = lambda x: (f0[0] + X(x)[0] - x0[0], f0[1] + X(x)[1] - x0[1])
            g = lambda x: F(x)[0] ** 2 + F(x)[1] ** 2 - Bs(x) ** 2
            te = first_change(g, tau, stop, skip)
            te = stop if te is None else te
            for i in range(2):
                sums[i] += quad(lambda x: F(x)[i], [tau, te])
            fe = F(te)
            if te < stop:
                events.append((te, "slip"))
                state = ("slip", atan2(fe[1], fe[0]))
            else:
                state = ("stick", fe)
            tau = te
        else:
            th0 = val
            sol = odefun(lambda x, th: (cos(th) * V(x)[1] - sin(th) * V(x)[0]) / Bs(x), tau, th0)
            lam = lambda x: V(x)[0] * cos(sol(x)) + V(x)[1] * sin(sol(x)) - dB(x)
            te = first_change(lam, tau, stop, False)
            te = stop if te is None else te
            sums[0] += quad(lambda x: Bs(x) * cos(sol(x)), [tau, te])
            sums[1] += quad(lambda x: Bs(x) * sin(sol(x)), [tau, te])
            th = sol(te)
            if te < stop:
                events.append((te, "stick"))
                state = ("stick", (Bs(te) * cos(th), Bs(te) * sin(th)), True)
            elif loss is not None and te == loss - DELTA:
                events.append((loss, "loss_of_contact"))
                state = ("out", None)
                te = loss
                loss = None
            else:
                state = ("slip", th)
            tau = te
    kind, val = state[0], state[1]
    if kind == "stick":
        f_end = val
    elif kind == "slip":
        f_end = (Bs(tau) * cos(val), Bs(tau) * sin(val))
    else:
        f_end = (mpf(0), mpf(0))
    return sums, f_end


def mean_b(amp):
    amp = mpf(amp)
    return quad(lambda x: max(1 - amp * cos(x), 0), [0, acos(1 / amp) if amp > 1 else 0, 2 * pi - (acos(1 / amp) if amp > 1 else 0), 2 * pi]) if amp > 1 else 2 * pi


def newton(case, f):
    """The period map's fixed point from f by Newton, its Jacobian by
    differences of 1e-12, at 32 digits: the sums, events and iterations."""
    h = mpf("1e-12")
    for periods in range(1, 12):
        events = []
        sums, fe = period(case, 0, f, 2 * pi, events)
        r = (fe[0] - f[0], fe[1] - f[1])
        print(case, periods, nstr(abs(r[0]) + abs(r[1]), 5), file=sys.stderr)
        if abs(r[0]) + abs(r[1]) < mpf("1e-28"):
            return sums, events, periods
        cols = []
        for k in range(2):
            g = (f[0] + (h if k == 0 else 0), f[1] + (h if k == 1 else 0))
            _, ge = period(case, 0, g, 2 * pi, [])
            cols.append(((ge[0] - g[0] - r[0]) / h, (ge[1] - g[1] - r[1]) / h))
        # (P - I) columns: solve (P - I) dx = -r.
        a, c, b, d = cols[0][0], cols[0][1], cols[1][0], cols[1][1]
        det = a * d - b * c
        f = (f[0] - (d * r[0] - b * r[1]) / det, f[1] - (-c * r[0] + a * r[1]) / det)
    raise RuntimeError("Newton did not close")


def solve(case):
    global DELTA
    method = case[7] if len(case) > 7 else "relax"
    case, start = case[:6], case[6] if len(case) > 6 else ("0", "0")
    vhat, amp, t, phase, w, psi = case
    events = []
    if method == "newton":
        mp.dps, DELTA = 32, mpf("1e-32")
        sums, events, periods = newton(case, (mpf(start[0]), mpf(start[1])))
        mp.dps, DELTA = 24, mpf("1e-24")
    elif amp > 1:
        sums, _ = period(case, 0, None, 2 * pi, events)
        periods = 1
    else:
        f = (mpf(start[0]), mpf(start[1]))
        for periods in range(1, 400):
            events = []
            sums, f_end = period(case, 0, f, 2 * pi, events)
            change = abs(f_end[0] - f[0]) + abs(f_end[1] - f[1])
            f = f_end
            print(case, periods, nstr(change, 5), file=sys.stderr)
            if change < mpf("1e-21"):
                break
    total = mean_b(amp)
    return {
        "vhat": vhat, "amp": amp, "tangential_amp": t, "phase": phase,
        "transverse_amp": w, "transverse_phase": psi,
        "mu_ratio": nstr(sums[0] / total, 20),
        "transverse_ratio": nstr(sums[1] / total, 20),
        "events": [[nstr(x % (2 * pi), 20), k] for x, k in events],
        "periods": periods,
    }


if __name__ == "__main__":
    only = [int(a) for a in sys.argv[1:]]
    cases = [c for i, c in enumerate(CASES) if not only or i in only]
    out = {"source": "data/scripts/plane_reference.py", "cases": [solve(c) for c in cases]}
    json.dump(out, sys.stdout, indent=1)
    print()
