"""Independent 40-digit values of one spring (the flat punch) under oscillation
in the sliding direction, alone or with the normal oscillation
(README.md, "Oscillation in the sliding direction"): mu_macro/mu0 = <f>/<B>, the reduction
<B - f>/<B>, and the events of one period.

Independent of fricosc's solver (src/fricosc/src/model/stop.rs):
- the periodic steady state is found by running the stop operator period after
  period from a sliding start (f = B at tau = 0) until the force at the period's
  start repeats to 45 digits (fricosc instead starts from a state it proves);
- an event is found by scanning the phase for a sign change on a grid of 4096
  points a period (in doubles), then refined by bisection in 60-digit
  arithmetic (fricosc brackets on closed-form monotone pieces);
- slip ends are found the same way from X' -+ B' (not from their closed-form zeros);
- the means are mpmath quadratures of f and B over each phase (not closed forms).

Run: python3 data/scripts/combined_reference.py > data/combined-reference.json
(needs mpmath; about a minute.) The inputs are the f64 values the test passes,
taken exactly (decimal text of short doubles).
"""
import json
import sys
from mpmath import mp, mpf, cos, sin, pi, quad, nstr

mp.dps = 60
GRID = 4096


def spring(c, amp, vhat, t, phase):
    c, amp, vhat, t, phase = map(mpf, (c, amp, vhat, t, phase))
    X = lambda x: vhat * x + t * sin(x + phase)
    V = lambda x: vhat + t * cos(x + phase)
    B = lambda x: max(c - amp * cos(x), mpf(0))
    dB = lambda x: amp * sin(x) if c - amp * cos(x) > 0 else mpf(0)

    def bisect(g, lo, hi):
        glo = g(lo)
        for _ in range(240):
            m = (lo + hi) / 2
            if (g(m) > 0) == (glo > 0):
                lo = m
            else:
                hi = m
        return (lo + hi) / 2

    def first(g, lo, hi, want_positive):
        """First point in (lo, hi] where g reaches the wanted side (scan, then bisect)."""
        n = max(2, int(GRID * float(hi - lo) / float(2 * pi)) + 2)
        prev = lo
        for k in range(1, n + 1):
            x = lo + (hi - lo) * k / n
            gx = g(x)
            if (gx > 0) if want_positive else (gx < 0):
                return bisect(g, prev, x)
            prev = x
        return None

    def period(tau, f, hi):
        """Run the stop operator from (tau, f) to hi; phases and the end force."""
        phases = []
        kind = None
        b = B(tau)
        if b <= 0:
            kind, f = "none", mpf(0)
        elif f >= b and V(tau) >= dB(tau):
            kind = "forward"
        elif f <= -b and V(tau) <= -dB(tau):
            kind = "backward"
        else:
            kind = "stick"
        while tau < hi:
            if kind == "none":
                end = first(lambda x: c - amp * cos(x), tau, hi, True)
                end = hi if end is None else end
                phases.append(("none", tau, end, mpf(0)))
                tau, f, kind = end, mpf(0), "contact"
                continue
            if kind == "contact":
                # Out of contact the spring relaxed: it starts at f = 0 = B.
                v, db = V(tau + mpf(10) ** -40), dB(tau + mpf(10) ** -40)
                kind = "forward" if v > db else ("backward" if v < -db else "stick")
                continue
            loss = first(lambda x: c - amp * cos(x), tau + mpf(10) ** -45, hi, False)
            stop = hi if loss is None else loss
            if kind == "forward":
                end = first(lambda x: V(x) - amp * sin(x), tau, stop, False)
            elif kind == "backward":
                end = first(lambda x: V(x) + amp * sin(x), tau, stop, True)
            else:
                f0, t0 = f, tau
                up = first(lambda x: f0 + X(x) - X(t0) - (c - amp * cos(x)), tau, stop, True)
                down = first(lambda x: f0 + X(x) - X(t0) + (c - amp * cos(x)), tau, stop, False)
                cands = [(e, k) for e, k in ((up, "forward"), (down, "backward")) if e is not None]
                end, nxt = min(cands) if cands else (stop, None)
            end = stop if end is None else end
            phases.append((kind, tau, end, f))
            if kind == "stick":
                f = f + X(end) - X(tau)
            else:
                f = B(end) if kind == "forward" else -B(end)
            if loss is not None and end >= loss:
                tau, f, kind = end, mpf(0), "none"
                continue
            if kind == "stick":
                kind = nxt if nxt is not None else "stick"
                f = B(end) if kind == "forward" else (-B(end) if kind == "backward" else f)
            else:
                kind = "stick"
            tau = end
        return phases, f

    f = B(0)
    for _ in range(200):
        phases, f1 = period(mpf(0), f, 2 * pi)
        if abs(f1 - f) < mpf(10) ** -45:
            break
        f = f1
    else:
        raise RuntimeError("no periodic state")

    def force(kind, t0, f0):
        if kind == "stick":
            return lambda x: f0 + X(x) - X(t0)
        if kind == "forward":
            return B
        if kind == "backward":
            return lambda x: -B(x)
        return lambda x: mpf(0)

    mean_f = sum(quad(force(k, a, f0), [a, e]) for k, a, e, f0 in phases if e > a) / (2 * pi)
    mean_d = sum(quad(lambda x, k=k, a=a, f0=f0: B(x) - force(k, a, f0)(x), [a, e]) for k, a, e, f0 in phases if e > a)
    mean_d /= 2 * pi
    mean_b = quad(B, [0, pi, 2 * pi]) / (2 * pi) if amp <= c or amp == 0 else quad(B, [mp.acos(c / amp), 2 * pi - mp.acos(c / amp)]) / (2 * pi)
    events = []
    for (k, a, e, f0), (k2, _, _, _) in zip(phases, phases[1:] + phases[:1]):
        if e - a > 0 and k != k2:
            events.append({"ends": k, "starts": k2, "tau": nstr(e % (2 * pi), 40)})
    return mean_f, mean_b, mean_d, events


CASES = [
    # (amp, vhat, T, phase): pure tangential, combined, jumping, backward slips.
    (0.0, 0.1, 0.5, 0.0),
    (0.0, 0.3, 2.0, 0.0),
    (0.0, 0.05, 20.0, 0.0),
    (0.0, 1.9, 2.0, 0.0),
    (0.5, 0.2, 0.3, 0.0),
    (0.5, 0.2, 0.3, 1.5707963267948966),
    (0.5, 0.2, 0.3, 3.141592653589793),
    (0.5, 0.2, 1.5, -1.0),
    (0.9, 0.05, 0.8, 2.0),
    (1.0, 0.3, 0.4, 0.5),
    (1.5, 0.3, 0.4, 0.0),
    (1.5, 0.3, 0.4, 2.5),
    (2.0, 0.1, 1.2, 4.0),
    (2.0, 0.6, 3.0, 1.0),
    (0.3, 0.0, 0.5, 0.7),
    (0.8, 0.01, 0.02, 5.5),
]

# Single springs of a curved contact: (c, amp, vhat, T, phase) with the level
# c = 1 - G(z) != 1 (jumping with c < amp and c < 0, c = amp, permanent, amp = 0).
SPRINGS = [
    (0.4, 0.5, 0.2, 1.0, 0.3),
    (-0.3, 0.5, 0.2, 0.6, 2.0),
    (0.7, 0.3, 0.1, 2.0, 1.0),
    (0.2, 0.2, 0.05, 0.3, 4.0),
    (0.05, 0.0, 0.02, 0.5, 0.0),
    (0.01, 0.9, 0.3, 0.05, 1.2),
]


def main():
    springs = []
    for c, amp, vhat, t, phase in SPRINGS:
        mf, mb, md, ev = spring(c, amp, vhat, t, phase)
        springs.append({
            "c": c, "amp": amp, "vhat": vhat, "tangential_amp": t, "phase": phase,
            "mean_force": nstr(mf, 40), "mean_bound": nstr(mb, 40), "mean_deficit": nstr(md, 40), "events": ev,
        })
        print(f"spring {c} {amp} {vhat} {t} {phase}: {nstr(mf, 20)}", file=sys.stderr)
    out = []
    for amp, vhat, t, phase in CASES:
        mf, mb, md, ev = spring(1, amp, vhat, t, phase)
        out.append({
            "amp": amp, "vhat": vhat, "tangential_amp": t, "phase": phase,
            "mu_ratio": nstr(mf / mb, 40), "reduction": nstr(md / mb, 40), "events": ev,
        })
        print(f"done {amp} {vhat} {t} {phase}: {nstr(mf / mb, 20)}", file=sys.stderr)
    json.dump({"about": __doc__.strip().splitlines()[0], "digits": 40, "cases": out, "springs": springs}, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
