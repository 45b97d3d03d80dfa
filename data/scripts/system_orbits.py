"""Independent period-k orbits of the flat punch on a system with mass and
stiffness (the model and the period map of system_reference.py: each phase
by the matrix exponential of the augmented linear system at 40 digits,
events by bisection).

An orbit of period k is a fixed point of k periods of the map, shifted by
the drive's k periods of sliding: P^k(x, x') = (x + 2 pi vhat k, x'). The
cases here lose contact at tau = 0 (amp > 1: the spring is relaxed there,
f = 0), so the map's state is (x, x'). Newton at 40 digits (the Jacobian by
forward differences of 1e-20) closes the orbit to 1e-30 from a start near it
(the body's lag and velocity at tau = 0 as `fricosc history` prints them,
17 digits: Newton's fixed point does not depend on where it starts within
its basin). Then, independently of the solver:
- the least period: P^d moves the state by more than 1e-6 for every d < k;
- the multipliers, the eigenvalues of the 40-digit Jacobian (with the
  relaxed spring's 0): the orbit attracts if every modulus is below 1;
- mu = int f / int B over the k periods, 25 digits.
That this orbit is the one reached from the stated start is the solver's
claim, not checked here (the orbits contract slowly: a multiplier 0.9999).

Run: python3 data/scripts/system_orbits.py > data/system-orbits.json
(needs mpmath; about two minutes).
"""

import json
import sys

import mpmath as mp

from system_reference import FREE, TWO_PI, Phases, period

# kappa, Omega, zeta, vhat, amp, k, and the start: the body's lag X_d - x
# and velocity at tau = 0.
CASES = [
    (0.1868, 1.0362, 0.0, 0.2537, 2.9688, 1, "9.795876115704212", "0.18032761664610533"),
    (1.0, 1.5, 0.0, 0.3, 1.2, 3, "1.9999705348696248", "0.32575660780188553"),
]


def map_k(ph, x, v, k):
    """k periods from the relaxed spring's state (x, x') at tau = 0: the
    phase there after them, (x, x') shifted back by 2 pi vhat k, and int f."""
    z = mp.matrix([x, v, 0, x, 1, 0, 1, 0])
    kind = FREE
    for _ in range(k):
        kind, z = period(ph, kind, z)
        shift = TWO_PI * ph.p["vhat"]
        z[0] -= shift
        z[3] -= shift
        z[5] = 0
        z[6], z[7] = 1, 0
    return kind, z[0], z[1], z[2]


def jacobian(ph, x, v, k, base):
    h = mp.mpf("1e-20")
    cols = []
    for dx, dv in ((h, 0), (0, h)):
        _, x1, v1, _ = map_k(ph, x + dx, v + dv, k)
        cols.append(((x1 - base[1]) / h, (v1 - base[2]) / h))
    return mp.matrix([[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]])


def orbit(p, k, x, v):
    ph = Phases(p)
    for _ in range(20):
        base = map_k(ph, x, v, k)
        if base[0] != FREE:
            raise SystemExit("the orbit's state at tau = 0 is not out of contact")
        jac = jacobian(ph, x, v, k, base)
        r = mp.matrix([base[1] - x, base[2] - v])
        step = mp.lu_solve(jac - mp.eye(2), -r)
        x, v = x + step[0], v + step[1]
        print(f"  step {mp.nstr(max(abs(step[0]), abs(step[1])), 3)}", file=sys.stderr)
        if max(abs(step[0]), abs(step[1])) < mp.mpf("1e-33"):
            break
    kind, x1, v1, int_f = map_k(ph, x, v, k)
    closure = max(abs(x1 - x), abs(v1 - v))
    if closure > mp.mpf("1e-30"):
        raise SystemExit(f"Newton did not close the orbit: {closure}")
    for d in range(1, k):
        if k % d == 0:
            _, xd, vd, _ = map_k(ph, x, v, d)
            if max(abs(xd - x), abs(vd - v)) < mp.mpf("1e-6"):
                raise SystemExit(f"the least period is {d}, not {k}: {mp.nstr(max(abs(xd - x), abs(vd - v)), 5)}")
    jac = jacobian(ph, x, v, k, (kind, x1, v1, int_f))
    eig = mp.eig(jac)[0]
    amp = p["amp"]
    edge = mp.acos(1 / amp)
    mean_b = mp.quad(lambda t: 1 - amp * mp.cos(t), [edge, TWO_PI - edge]) / TWO_PI
    mu = int_f / (TWO_PI * k * mean_b)
    return {
        "mu_ratio": mp.nstr(mu, 25),
        "period": k,
        "multiplier_moduli": sorted([mp.nstr(abs(e), 12) for e in eig] + ["0"], key=float, reverse=True),
        "closure": mp.nstr(closure, 3),
    }


def main():
    mp.mp.dps = 40
    out = []
    for kappa, om, zeta, vhat, amp, k, lag, vel in CASES:
        p = {key: mp.mpf(repr(val)) for key, val in
             dict(kappa=kappa, omega=om, zeta=zeta, vhat=vhat, amp=amp, t=0.0, phase=0.0).items()}
        r = orbit(p, k, -mp.mpf(lag), mp.mpf(vel))
        r.update(dict(kappa=kappa, frequency_ratio=om, damping=zeta, vhat=vhat, amp=amp))
        print(r, file=sys.stderr)
        out.append(r)
    json.dump({"source": "data/scripts/system_orbits.py", "cases": out}, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
