"""Independent values of mu_macro/mu0 for the flat punch on a tribometer with
mass and system stiffness (README.md, "The system's mass and stiffness"):
the body x obeys

    Omega^2 x'' = kappa (X_d - x) - 2 zeta sqrt(kappa) Omega (x' - X_d') - f,

X_d = vhat tau + T sin(tau + phase), the contact force f the stop operator
of x with the bound B = (1 - amp cos tau)_+ (stick: f' = x'; slip: f = +-B
while the contact point y = x - f moves on; out of contact: f = 0, relaxed).
Units: tau = omega t, lengths in l = mu0 kz u0/kx, forces in mu0 kz u0.

Method (independent of fricosc's solver, src/fricosc/src/system/): each
phase is the linear autonomous system z' = A z of the augmented state
z = (x, x', int f, y0, 1, tau, cos tau, sin tau) (y0 the contact point while
it sticks), so z(tau0 + h) = expm(A h) z(tau0), at 40 digits (mpmath). The
powers expm(A dt 2^-k), k = 0..140, are made once per kind of phase; a phase
is followed in steps dt = 2 pi / 512 (every event function is checked for a
sign change at each step and, against a grazing event, at four points
inside it), and an event is located by bisection to 2^-140 dt, composing
those powers. Contact is lost and regained at the closed-form zeros of B.
The start is the stated one: at tau = 0 the body at the drive's position
with its velocity, the spring relaxed. The state (x - 2 pi vhat n, x', f,
phase) is iterated period after period until it repeats to 1e-30 (a period-1
attractor; a point that does not settle within 3000 periods is reported as
such); mu = int f / int B over the last period.

Run: python3 data/scripts/system_reference.py > data/system-reference.json
(needs mpmath; about six minutes). Inputs are taken exactly (the shortest
decimal text of each double).
"""

import json
import sys

import mpmath as mp

mp.mp.dps = 40
LEVELS = 140
STEPS = 512
TWO_PI = 2 * mp.pi

STICK, FORWARD, BACKWARD, FREE = "stick", "forward", "backward", "free"


def matrix(kind, p):
    """A of the augmented state (x, v, I, y0, 1, tau, c, s) for one kind of phase."""
    kappa, om, zeta, vhat, t, ph, amp = (p[k] for k in ("kappa", "omega", "zeta", "vhat", "t", "phase", "amp"))
    damp = 2 * zeta * mp.sqrt(kappa) * om
    a = mp.zeros(8, 8)
    a[0, 1] = 1
    # Omega^2 v' = kappa X_d + damp X_d' - damp v - k x (+ y0 in stick, -+ B in slip).
    k = kappa + 1 if kind == STICK else kappa
    row = [mp.mpf(0)] * 8
    row[0] = -k
    row[1] = -damp
    row[4] = damp * vhat  # constant part of damp X_d'
    row[5] = kappa * vhat  # kappa vhat tau
    row[6] = kappa * t * mp.sin(ph) + damp * t * mp.cos(ph)  # cos tau
    row[7] = kappa * t * mp.cos(ph) - damp * t * mp.sin(ph)  # sin tau
    if kind == STICK:
        row[3] = 1
    elif kind == FORWARD:
        row[4] -= 1
        row[6] += amp
    elif kind == BACKWARD:
        row[4] += 1
        row[6] -= amp
    for j in range(8):
        a[1, j] = row[j] / om**2
    # (int f)' = f.
    if kind == STICK:
        a[2, 0], a[2, 3] = 1, -1
    elif kind == FORWARD:
        a[2, 4], a[2, 6] = 1, -amp
    elif kind == BACKWARD:
        a[2, 4], a[2, 6] = -1, amp
    a[5, 4] = 1
    a[6, 7] = -1
    a[7, 6] = 1
    return a


class Phases:
    def __init__(self, p):
        self.p = p
        self.dt = TWO_PI / STEPS
        self.pow = {}
        for kind in (STICK, FORWARD, BACKWARD, FREE):
            e = mp.expm(matrix(kind, p) * self.dt)
            levels = [e]
            for _ in range(LEVELS):
                e = mp.expm(matrix(kind, p) * (self.dt / 2 ** len(levels)))
                levels.append(e)
            self.pow[kind] = levels

    def advance(self, kind, z, h):
        """z after h (0 <= h <= dt) in phase `kind`, composed from the powers."""
        levels = self.pow[kind]
        rest = h / self.dt
        for k in range(LEVELS + 1):
            if rest >= mp.mpf(2) ** -k:
                z = levels[k] * z
                rest -= mp.mpf(2) ** -k
        return z

    def force(self, kind, z):
        amp = self.p["amp"]
        bound = 1 - amp * z[6]
        return {STICK: z[0] - z[3], FORWARD: bound, BACKWARD: -bound, FREE: mp.mpf(0)}[kind]

    def events(self, kind, z):
        """The event functions of a phase: (value, the kind that follows), a
        sign change from + to - (or 0) marks the event."""
        amp = self.p["amp"]
        bound = 1 - amp * z[6]
        v, s = z[1], z[7]
        if kind == STICK:
            return [(bound - (z[0] - z[3]), FORWARD), ((z[0] - z[3]) + bound, BACKWARD)]
        if kind == FORWARD:
            return [(v - amp * s, STICK)]
        if kind == BACKWARD:
            return [(-(v + amp * s), STICK)]
        return []


def contact_times(amp):
    """(regained, lost) in [0, 2 pi) where B = 1 - amp cos tau crosses 0, or None."""
    if amp <= 1:
        return None
    a = mp.acos(1 / amp)
    return a, TWO_PI - a


def on_contact(ph, z):
    """The phase a relaxed spring enters at contact (f = B = 0): stick unless
    the body outruns the bound's growth B' = amp sin tau."""
    amp = ph.p["amp"]
    if z[1] > amp * z[7]:
        return FORWARD
    if z[1] < -amp * z[7]:
        return BACKWARD
    return STICK


def first_crossing(ph, kind, z, h):
    """The first event of `kind` within h of the state z: (index, the kind
    that follows, tau offset, state there), or None. A sign change from >= 0
    to < 0 at one of four points of the step is bisected on the powers."""
    quarter = [ph.advance(kind, z, h * j / 4) for j in (1, 2, 3, 4)] if h < ph.dt else None
    if quarter is None:
        q = ph.pow[kind][2]
        quarter = [q * z]
        for _ in range(3):
            quarter.append(q * quarter[-1])
    start = ph.events(kind, z)
    for i, (g0, nxt) in enumerate(start):
        prev_z, prev_g = z, g0
        for j, zp in enumerate(quarter):
            g = ph.events(kind, zp)[i][0]
            if prev_g >= 0 and g < 0:
                # Bisect on [j h/4, (j+1) h/4] with the powers dt 2^-k.
                lo, z_lo = h * j / 4, prev_z
                width = h / 4
                for k in range(LEVELS + 1):
                    step = ph.dt / mp.mpf(2) ** k
                    if step >= width:
                        continue
                    cand = ph.pow[kind][k] * z_lo
                    if ph.events(kind, cand)[i][0] >= 0:
                        z_lo, lo, width = cand, lo + step, width - step
                return i, nxt, lo, z_lo
            prev_z, prev_g = zp, g
    return None


def period(ph, kind, z):
    """One period from tau = 0 (z[5] = 0): the kind and state at 2 pi."""
    times = contact_times(ph.p["amp"])
    tau = mp.mpf(0)
    while TWO_PI - tau > mp.mpf(2) ** -(LEVELS - 4) * ph.dt:
        h = min(ph.dt, TWO_PI - tau)
        stop = None
        if times is not None:
            for when, what in ((times[0], "gain"), (times[1], "loss")):
                if tau < when <= tau + h:
                    h, stop = when - tau, what
        hit = first_crossing(ph, kind, z, h)
        if hit is not None:
            _, nxt, dtau, z = hit
            tau += dtau
            if nxt == STICK:
                z[3] = z[0] - ph.force(kind, z)
            kind = nxt
            continue
        z, tau = ph.advance(kind, z, h) if h < ph.dt else ph.pow[kind][0] * z, tau + h
        if stop == "loss":
            kind = FREE
        elif stop == "gain":
            kind = on_contact(ph, z)
            z[3] = z[0]
    return kind, z


def solve(p, max_periods=3000, tol=mp.mpf("1e-30")):
    ph = Phases(p)
    vhat, t, phase, amp = p["vhat"], p["t"], p["phase"], p["amp"]
    z = mp.matrix([t * mp.sin(phase), vhat + t * mp.cos(phase), 0, t * mp.sin(phase), 1, 0, 1, 0])
    # In contact at the start where amp <= 1 (at amp = 1 the bound and the
    # force are 0 there, and the first sign change is found at once).
    kind = STICK if amp <= 1 else FREE
    mean_b = mp.quad(lambda x: max(0, 1 - amp * mp.cos(x)), [0, mp.acos(1 / amp) if amp > 1 else 1, 2 * mp.pi - (mp.acos(1 / amp) if amp > 1 else 1), TWO_PI]) / TWO_PI
    prev = None
    for n in range(1, max_periods + 1):
        z[2] = 0
        kind, z = period(ph, kind, z)
        mu = z[2] / TWO_PI / mean_b
        # Shift back by one period of the drive: tau to 0, positions by 2 pi vhat.
        shift = TWO_PI * vhat
        z[0] -= shift
        z[3] -= shift
        z[5] = 0
        z[6], z[7] = 1, 0
        state = (kind, z[0], z[1], z[0] - z[3] if kind == STICK else ph.force(kind, z))
        if prev is not None and prev[0] == kind and all(abs(a - b) < tol for a, b in zip(prev[1:], state[1:])):
            return {"mu_ratio": mp.nstr(mu, 25), "periods": n, "period": 1}
        prev = state
    return {"mu_ratio": None, "periods": max_periods, "period": None}


CASES = [
    # kappa, Omega, zeta, vhat, amp, T, phase
    (1.0, 0.5, 0.3, 0.3, 0.5, 0.0, 0.0),
    (1.0, 0.5, 0.3, 0.3, 1.5, 0.0, 0.0),
    (4.0, 1.0, 0.2, 0.5, 0.8, 0.0, 0.0),
    (0.5, 0.3, 0.5, 0.2, 1.2, 0.0, 0.0),
    (2.0, 0.7, 0.4, 0.2, 0.5, 1.5, 1.3),
    (10.0, 0.2, 0.3, 0.4, 2.0, 0.0, 0.0),
    # amp = 1 exactly: contact touches at tau = 0 only.
    (1.0, 0.5, 0.05, 0.3, 1.0, 0.0, 0.0),
    (1.0, 0.5, 0.05, 0.3, 1.0, 0.5, 0.7),
    # Contact regained as fast as the bound grows (f = B = 0, x' = B'): a
    # solver may hold the phase a step there (SystemReport::held_steps).
    (0.3378207896487312, 0.16841951380861625, 0.1, 0.06119254081987559, 1.1240005969640734, 0.0, 0.0),
    # The same backward (f = -B = 0, x' = -B'): the spring sticks, then slips.
    (0.33021488477370675, 0.1259278817532588, 0.1, 0.7735123238909791, 2.156987056873848, 0.0, 0.0),
    # Regained a little slower than the bound grows: a short stick, then a
    # forward slip (a solver that slips at once finds another orbit).
    (1.0, 0.5, 0.05, 2.3159145299145294, 2.033333333333333, 0.0, 0.0),
    (1.0, 0.5, 0.05, 2.439534516765286, 2.9256410256410255, 0.0, 0.0),
    (0.8312071448914433, 0.2813462875420833, 0.05, 0.6092661644757312, 1.275028612678914, 0.0, 0.0),
]


def main():
    out = []
    for kappa, om, zeta, vhat, amp, t, phase in CASES:
        p = {k: mp.mpf(repr(v)) for k, v in
             dict(kappa=kappa, omega=om, zeta=zeta, vhat=vhat, amp=amp, t=t, phase=phase).items()}
        r = solve(p)
        r.update(dict(kappa=kappa, frequency_ratio=om, damping=zeta, vhat=vhat, amp=amp, tangential_amp=t, phase=phase))
        print(r, file=sys.stderr)
        out.append(r)
    json.dump({"source": "data/scripts/system_reference.py", "cases": out}, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
