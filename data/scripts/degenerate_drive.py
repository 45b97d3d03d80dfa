"""Independent values of mu_macro/mu0 on and near the degenerate drive of the
combined oscillation (README.md, "Oscillation in the sliding direction"):
vhat ~ 0, T ~ amp and phase ~ 3 pi/2 (X' = B': every spring rides on +B, mu = 1)
or phase ~ pi/2 (X' = -B': every spring that enters contact relaxed rides on
-B, mu = -1), for the flat punch and curved contacts.

Method (independent of fricosc's phase-by-phase solver, src/fricosc/src/model/stop.rs):
near the family a spring's force stays within O(r) of its bound, r the
amplitude of w = X' - B' (forward family) or -(X' + B') (backward family).
The distance to the bound, P = B - f or f + B, obeys P' = -w where P > 0 and
is held at 0 where w > 0 (the slip): the reflection of Q = -int w at 0,
    P(tau) = Q(tau) - min(0, min_{s <= tau} Q(s)),
from P = 0 where a jumping spring enters contact (relaxed, f = B = 0), and
periodic for a spring always in contact (the minimum over the last period;
vhat -> 0+ as the limit). P does not depend on the spring's level c, only on
where its window starts. int P is exact here: Q is monotone between the zeros
of w (closed form), and the running minimum changes only on pieces where Q
falls, from the root of Q = min (bisection at 50 digits). What this leaves out
is where P would exceed 2B (the other bound, only within O(r) of where B
vanishes): O(r^2) in mu, below 1e-23 for r <= 1e-11.

mu = 1 - int <P> dz / int <B> dz (forward), -1 + int <P> dz / int <B> dz
(backward, every spring jumping: amp >= 1), the foundation's springs at
z in [0, z_max] with bound (1 - G(z) - amp cos tau)_+, by mpmath quadrature
(tanh-sinh) split where a spring's window starts or ends at a zero of w.

Run: python3 data/scripts/degenerate_drive.py > data/degenerate-drive.json
(needs mpmath; about a minute). The inputs are the f64 values the test
passes, taken exactly (the shortest decimal text of each double).
"""
import json
import math
import sys
from mpmath import mp, mpf, cos, sin, acos, atan2, hypot, pi, quad, sqrt, nstr

mp.dps = 30


def shapes():
    """G(z), its inverse, and each shape's name (fricosc's dimensionless forms)."""
    def power(n):
        return (lambda z: z ** n, lambda g: g ** (1 / mpf(n)))

    def flat_tip(e):
        e = mpf(e)
        k = (1 - e) * (1 + e)
        g = lambda z: 0 if z <= e else z * sqrt((z - e) * (z + e)) / sqrt(k)
        inv = lambda g: sqrt((e * e + sqrt(e ** 4 + 4 * g * g * k)) / 2)
        return (g, inv, e)

    return {
        "parabolic": power(2) + (0,),
        "cone": power(1) + (0,),
        "power:8": power(8) + (0,),
        "flat-tip:0.9": flat_tip("0.9"),
    }


class Wave:
    """w(tau) = a0 + R cos(tau + psi) and the reflected P of Q = -int w."""

    def __init__(self, a0, x, y):
        # x cos tau - y sin tau = R cos(tau + psi)
        self.a0, self.r, self.psi = a0, hypot(x, y), atan2(y, x)

    def w(self, t):
        return self.a0 + self.r * cos(t + self.psi)

    def q(self, s, t):
        """Q(t) - Q(s) = -int_s^t w."""
        return -(self.a0 * (t - s) + self.r * (sin(t + self.psi) - sin(s + self.psi)))

    def int_q(self, s, a, b):
        """int_a^b (Q(t) - Q(s)) dt."""
        return (-self.a0 * ((b - s) ** 2 - (a - s) ** 2) / 2
                + self.r * (cos(b + self.psi) - cos(a + self.psi))
                + self.r * sin(s + self.psi) * (b - a))

    def zeros(self, a, b):
        """Zeros of w in (a, b), sorted."""
        if self.r == 0 or abs(self.a0) >= self.r:
            return []
        c = acos(-self.a0 / self.r)
        out = []
        for base in (c - self.psi, -c - self.psi):
            k = int(mp.floor((a - base) / (2 * pi))) - 1
            t = base + 2 * pi * k
            while t < b:
                if t > a:
                    out.append(t)
                t += 2 * pi
        return sorted(out)

    def pieces(self, a, b):
        cuts = [a] + self.zeros(a, b) + [b]
        return [(cuts[i], cuts[i + 1]) for i in range(len(cuts) - 1) if cuts[i + 1] > cuts[i]]

    def running(self, s, a, b, m0):
        """(int_a^b m, the minimum at b) for m = min(m0, min_[a,t] Q), Q from s."""
        total = mpf(0)
        for (p, e) in self.pieces(a, b):
            falling = self.w((p + e) / 2) > 0
            qe = self.q(s, e)
            if not falling or qe >= m0:
                total += m0 * (e - p)
                continue
            lo, hi = p, e
            if self.q(s, lo) > m0:
                for _ in range(110):
                    mid = (lo + hi) / 2
                    if self.q(s, mid) > m0:
                        lo = mid
                    else:
                        hi = mid
            total += m0 * (lo - p) + self.int_q(s, lo, e)
            m0 = qe
        return total, m0

    def mean_jumping(self, tc):
        """<P> over the period for a spring in contact on [tc, 2 pi - tc]."""
        a, b = tc, 2 * pi - tc
        if b <= a:
            return mpf(0)
        int_m, _ = self.running(a, a, b, mpf(0))
        return (self.int_q(a, a, b) - int_m) / (2 * pi)

    def mean_permanent(self):
        """<P> for a spring always in contact (periodic; vhat -> 0+ included)."""
        _, m0 = self.running(mpf(0), -2 * pi, mpf(0), self.q(mpf(0), -2 * pi))
        m0 = min(m0, mpf(0))
        int_m, _ = self.running(mpf(0), mpf(0), 2 * pi, m0)
        return (self.int_q(mpf(0), mpf(0), 2 * pi) - int_m) / (2 * pi)


def mean_bound(c, amp):
    if amp == 0 or c >= amp:
        return c
    if c <= -amp:
        return mpf(0)
    tc = acos(c / amp)
    return (c * (pi - tc) + amp * sin(tc)) / pi


def point(shape, vhat, amp, t, phase):
    vhat, amp, t, phase = map(mpf, (vhat, amp, t, phase))
    forward = sin(phase) < 0  # phase near 3 pi/2
    # X' -+ B' = vhat + T cos(tau + phase) -+ amp sin tau
    k = -amp if forward else amp
    x, y = t * cos(phase), t * sin(phase) - k
    wave = Wave(vhat, x, y) if forward else Wave(-vhat, -x, -y)
    tc_of = lambda c: acos(max(min(c / amp, mpf(1)), mpf(-1)))

    def spring(c):
        """(<P>, <B>) of the spring at level c."""
        if c > amp:
            return wave.mean_permanent(), mean_bound(c, amp)
        return wave.mean_jumping(tc_of(c)), mean_bound(c, amp)

    if shape == "flat":
        p, b = spring(mpf(1))
    else:
        g, inv, flat = shapes()[shape]
        zmax = inv(1 + amp)
        cuts = {mpf(flat), zmax}
        if amp < 1:
            cuts.add(inv(1 - amp))
        for t0 in wave.zeros(mpf(0), 2 * pi):
            for tc in (t0, 2 * pi - t0):
                if 0 < tc < pi and 1 - amp * cos(tc) > 0:
                    z = inv(1 - amp * cos(tc))
                    if flat < z < zmax:
                        cuts.add(z)
        cuts = sorted(cuts)
        p = b = mpf(0)
        if flat > 0:
            p0, b0 = spring(mpf(1))
            p, b = p0 * flat, b0 * flat
        for i in range(len(cuts) - 1):
            lo, hi = cuts[i], cuts[i + 1]
            p += quad(lambda z: spring(1 - g(z))[0], [lo, hi], maxdegree=7)
            b += quad(lambda z: spring(1 - g(z))[1], [lo, hi])
    ratio = p / b
    return (1 - ratio, ratio) if forward else (-1 + ratio, 2 - ratio)


def neighbourhood(amp, p0):
    """(vhat, T, phase) on the family, within a few ulps of it, and at 1e-12."""
    up, down = (lambda x, k=1: x if k == 0 else up(math.nextafter(x, math.inf), k - 1),
                lambda x, k=1: x if k == 0 else down(math.nextafter(x, -math.inf), k - 1))
    pts = [(0.0, amp, p0), (0.0, up(amp), p0), (0.0, amp, up(p0, 2)), (0.0, down(amp), down(p0)),
           (5e-324, amp, p0), (1e-15, up(amp, 3), down(p0, 3))]
    for vhat, dt, dp in [(1e-12, 1e-12, 0.0), (0.0, 1e-12, 1e-12), (1e-12, -1e-12, -1e-12),
                         (3e-13, 0.0, 1e-12), (0.0, -1e-12, 0.0), (1e-12, 0.0, 0.0)]:
        pts.append((vhat, amp * (1 + dt), p0 + dp))
    return pts


def main():
    three_half, half = 4.71238898038469, 1.5707963267948966
    rows = []
    for shape in ["flat", "parabolic", "cone", "power:8", "flat-tip:0.9"]:
        for family, p0, amps in (("forward", three_half, [0.3, 1.0, 2.0]), ("backward", half, [1.0, 2.0])):
            for amp in amps:
                for vhat, t, phase in neighbourhood(amp, p0):
                    mu, red = point(shape, vhat, amp, t, phase)
                    rows.append({"shape": shape, "family": family, "vhat": vhat, "amp": amp,
                                 "tangential_amp": t, "phase": phase,
                                 "mu_ratio": nstr(mu, 25), "reduction": nstr(red, 25)})
                    print(shape, family, amp, vhat, t, phase, nstr(red, 12), file=sys.stderr)
    json.dump({"source": "data/scripts/degenerate_drive.py", "cases": rows}, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
