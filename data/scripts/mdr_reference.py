"""Independent 40-digit values of mu_macro/mu0 for MDR power-law contacts
g = |z|^n (the paraboloid n = 2, the cone n = 1, ...), for the tests of the
solver's values and of its error estimate (issue "Trust, round three").

Independent of fricosc's formulas: every spring's steady state is built from
the seed's description (the bound B = s - cos t while in contact; the stick
starts where the bound's slope falls to vbar, or at the contact with zero
force; its end is the root of the plain gap B(t0 + x) - F0 - vbar x, found by a
bracketing solver in 60-digit arithmetic), and the period means are the
elementary integrals of B and of the stick line over those phases. The foundation
is integrated over z = x/x_c with tanh-sinh quadrature between the regime edges
s(z) = (1 - z^n)/amp = 1, +-sqrt(1 - vbar^2), -1, at two working precisions;
the two agree to the digits written (checked here, the difference printed).

Run: python3 data/scripts/mdr_reference.py > data/mdr-reference.json   (needs mpmath;
about ten minutes)
     python3 data/scripts/mdr_reference.py --sphere > data/sphere-reference.json
     python3 data/scripts/mdr_reference.py --flat-tip > data/flat-tip-reference.json
     python3 data/scripts/mdr_reference.py --amp-one > data/mdr-amp-one.json
     python3 data/scripts/mdr_reference.py --small-vbar > data/mdr-small-vbar.json
The second: the exact sphere of radius 1 (MDR profile (x/2) ln((1 + x)/(1 - x)))
at a mean indentation of 1e-6, at sampled rows of the suite's tabulated sphere.
The third: the sphere worn flat at its tip (`flat-tip:E`, E = 0.3 and 0.7).
The fourth: power laws n = 2, 3.7, 8 at amp = 1 and vbar 1e-12, 1e-16, and
n = 8, 20 at vbar 1e-30.
"""
import json
import sys
from mpmath import mp, mpf, asin, acos, cos, sin, sqrt, pi, quad, nstr


def root(f, a, b):
    """The sign change of f in [a, b] (f(a) > 0 > f(b)): Illinois regula falsi
    to the working precision, bisection steps where it stalls."""
    fa, fb = f(a), f(b)
    assert fa > 0 > fb, (a, b, fa, fb)
    tol = abs(b) * mpf(10) ** (-mp.dps + 3)
    side = 0
    for _ in range(2000):
        if b - a <= tol:
            break
        m = (a * fb - b * fa) / (fb - fa)
        if not (a < m < b) or side == 3:
            m, side = (a + b) / 2, 0
        fm = f(m)
        if fm == 0:
            return m
        if fm > 0:
            a, fa = m, fm
            if side < 0:
                fb /= 2
            side = side - 1 if side < 0 else -1
        else:
            b, fb = m, fm
            if side > 0:
                fa /= 2
            side = side + 1 if side > 0 else 1
        if abs(side) >= 3:
            side = 3
    return (a + b) / 2


def spring(s, v):
    """(<B>, <F>) of one spring, units kz du, at velocity v < 1 (exact inputs)."""
    if s <= -1:
        return mpf(0), mpf(0)
    c = sqrt(1 - v * v)
    theta = acos(s) if s < 1 else None  # contact from theta to 2 pi - theta
    if s >= 1:
        normal = s
    else:
        normal = (s * (pi - theta) + sin(theta)) / pi
    if s <= -c:  # never sticks
        return normal, normal
    B_int = lambda a, b: s * (b - a) - (sin(b) - sin(a))  # integral of s - cos t
    delta = asin(v)
    if s >= c:  # tangent start
        t0, f0 = delta, s - c
        xmax = 2 * pi if s >= 1 else 2 * pi - theta - delta
    else:  # stick from the moment of contact
        t0, f0 = theta, mpf(0)
        xmax = 2 * pi - 2 * theta
    gap = lambda x: s - cos(t0 + x) - f0 - v * x
    lo = max(pi - t0 - delta, mpf(0))  # the gap's maximum, where the bound's slope is v again
    if gap(lo) <= 0:  # vbar -> 1 or a stick of zero length: the root is at the maximum
        L = lo
    else:
        L = root(gap, lo, xmax)
    t1 = t0 + L
    stick = f0 * L + v * L * L / 2
    if s >= 1:
        slip = B_int(t1, t0 + 2 * pi)
    else:
        slip = B_int(t1, 2 * pi - theta)
        if s >= c:
            slip += B_int(theta, t0)
    return normal, (stick + slip) / (2 * pi)


def mu_profile(G, Ginv, vbar, amp, extra_cuts=()):
    """mu of the foundation with profile G (G(1) = 1, increasing; Ginv its
    inverse) at the working precision; extra_cuts: where G is not smooth."""
    v, a = mpf(vbar), mpf(amp)
    if a == 0 or v >= 1:
        return mpf(1)
    c = sqrt(1 - v * v)
    zmax = Ginv(1 + a)
    z_of = lambda s: Ginv(1 - a * s) if 1 - a * s > 0 else mpf(0)
    cuts = sorted({mpf(0), zmax} | {z_of(s) for s in (1, c, -c, -1) if 0 < 1 - a * s < 1 + a} | {mpf(x) for x in extra_cuts if 0 < x < zmax})
    tot_n, tot_t = mpf(0), mpf(0)
    for p, q in zip(cuts, cuts[1:]):
        if q <= p:
            continue
        tot_n += quad(lambda z: a * spring((1 - G(z)) / a, v)[0], [p, q])
        tot_t += quad(lambda z: a * spring((1 - G(z)) / a, v)[1], [p, q])
    return tot_t / tot_n


def mu(n, vbar, amp, dps):
    mp.dps = dps
    n = mpf(n)
    return mu_profile(lambda z: z ** n, lambda y: y ** (1 / n), vbar, amp)


def sphere(u0, vbar, amp, dps):
    """The true sphere of radius 1 at mean indentation u0: MDR profile
    g(x) = (x/2) ln((1 + x)/(1 - x)), normalised G(z) = g(x_c z)/u0."""
    mp.dps = dps
    from mpmath import log, findroot
    u0 = mpf(u0)
    g = lambda x: x / 2 * log((1 + x) / (1 - x))
    inv = lambda y: findroot(lambda x: g(x) - y, sqrt(y), tol=mpf(10) ** (-dps + 5))
    xc = inv(u0)
    return mu_profile(lambda z: g(xc * z) / u0, lambda y: inv(y * u0) / xc, vbar, amp)


def flat_tip(e, vbar, amp, dps):
    """The sphere worn flat at its tip, E = a/x_c: G(z) = 0 on the flat z <= E,
    z sqrt(z^2 - E^2)/sqrt(1 - E^2) beyond (the MDR transform of the
    paraboloid cut flat; derived in src/fricosc/src/contact/flat_tip.rs, checked there
    against a tabulated profile's numerical transform)."""
    mp.dps = dps
    e = mpf(e)
    k = 1 - e * e
    G = lambda z: z * sqrt(z * z - e * e) / sqrt(k) if z > e else mpf(0)
    # z^2 (z^2 - E^2) = y^2 k.
    Ginv = lambda y: sqrt((e * e + sqrt(e ** 4 + 4 * y * y * k)) / 2)
    return mu_profile(G, Ginv, vbar, amp, extra_cuts=(e,))


if "--amp-one" in sys.argv:
    # Steep power laws at amp = 1 and small vbar: the slip-first band is
    # vbar^(2/n) wide, far wider than the O(vbar) force it carries.
    cases = []
    points = [(n, vbar, (45, 60)) for n in (2.0, 3.7, 8.0) for vbar in (1e-12, 1e-16)]
    # Where the stick-first band's top (arcsin vbar) is far closer to the
    # Jacobian's branch point than 2^-90 of its width; 1 - sqrt(1 - vbar^2)
    # is 5e-61 here: 90 and 110 digits.
    points += [(n, 1e-30, (90, 110)) for n in (8.0, 20.0)]
    for n, vbar, (low, high) in points:
        lo, hi = mu(n, vbar, 1.0, low), mu(n, vbar, 1.0, high)
        mp.dps = high
        print(f"n={n} vbar={vbar}: {nstr(hi, 25)} (two precisions differ by {nstr(abs(hi - lo) / hi, 3)})", file=sys.stderr)
        cases.append({"n": n, "vbar": vbar, "amp": 1.0, "mu_ratio": nstr(hi, 40)})
    source = "data/scripts/mdr_reference.py --amp-one (mpmath, tanh-sinh at 45 and 60 digits; 90 and 110 at vbar 1e-30)"
    print(json.dumps({"source": source, "cases": cases}, indent=1))
    sys.exit(0)
if "--flat-tip" in sys.argv:
    cases = []
    for e in ("0.3", "0.7"):
        # The last seven: small mu near and above amp = 1 (relative accuracy).
        for vbar, amp in ((0.3, 0.4), (0.05, 0.95), (0.6, 1.0), (0.2, 1.5), (0.9, 3.0), (1e-3, 1.2),
                          (1e-2, 0.999), (1e-6, 0.999), (1e-4, 1.0), (1e-6, 1.0), (1e-8, 1.0), (1e-12, 1.0), (1e-8, 2.0)):
            lo, hi = flat_tip(e, vbar, amp, 30), flat_tip(e, vbar, amp, 40)
            diff = abs(hi - lo) / hi
            assert diff < mpf(10) ** -20, (e, vbar, amp, diff)
            print(f"flat-tip:{e} vbar={vbar} amp={amp}: {nstr(hi, 25)} (differ by {nstr(diff, 3)})", file=sys.stderr)
            cases.append({"flat_ratio": e, "vbar": vbar, "amp": amp, "mu_ratio": nstr(hi, 22), "reduction": nstr(1 - hi, 22)})
        # amp = 1 at smaller velocities, where mu/vbar converges like vbar^(1/2)
        # and 1 - sqrt(1 - vbar^2) ~ vbar^2/2 needs twice the digits of vbar
        # (and 1e-130, below the 2^-400 where fricosc solves at a scaled vbar).
        for vbar, (low, high) in ((1e-16, (60, 80)), (1e-20, (70, 90)), (1e-30, (90, 110)), (1e-130, (290, 310))):
            amp = 1.0
            lo, hi = flat_tip(e, vbar, amp, low), flat_tip(e, vbar, amp, high)
            diff = abs(hi - lo) / hi
            assert diff < mpf(10) ** -20, (e, vbar, amp, diff)
            print(f"flat-tip:{e} vbar={vbar} amp={amp}: {nstr(hi, 25)} (differ by {nstr(diff, 3)})", file=sys.stderr)
            cases.append({"flat_ratio": e, "vbar": vbar, "amp": amp, "mu_ratio": nstr(hi, 22), "reduction": nstr(1 - hi, 22)})
    print(json.dumps({"source": "data/scripts/mdr_reference.py --flat-tip (mpmath, tanh-sinh at 30 and 40 digits, which agree to 1e-20 or better; at amp 1 below vbar 1e-12 at up to 290 and 310; 22 digits written)", "cases": cases}, indent=1))
    sys.exit(0)

if "--small-vbar" in sys.argv:
    # Between vbar 0.001 and 0.1 the stick-first band is integrated in the
    # stick's half-length, its springs near a small top phase (arcsin vbar,
    # or u* near it) with their phase taken from the top.
    cases = []
    for n in (0.5, 1.0, 2.0, 3.0):
        for vbar in (0.001, 0.003, 0.0101, 0.02, 0.05):
            for amp in (0.3, 0.55, 0.75, 0.95, 1.2, 2.0, 3.0):
                lo, hi = mu(n, vbar, amp, 30), mu(n, vbar, amp, 40)
                mp.dps = 40
                diff = abs(hi - lo) / hi
                assert diff < mpf(10) ** -20, (n, vbar, amp, diff)
                print(f"n={n} vbar={vbar} amp={amp}: {nstr(hi, 25)} (differ by {nstr(diff, 3)})", file=sys.stderr)
                cases.append({"n": n, "vbar": vbar, "amp": amp, "mu_ratio": nstr(hi, 25), "reduction": nstr(1 - hi, 25)})
    source = "data/scripts/mdr_reference.py --small-vbar (mpmath, tanh-sinh at 30 and 40 digits, which agree to 1e-20 or better; 25 digits written)"
    print(json.dumps({"source": source, "cases": cases}, indent=1))
    sys.exit(0)

if "--sphere" in sys.argv:
    # Sampled rows of the suite's tabulated sphere (data/profiles/sphere.csv @ 1e-6).
    cases = []
    for amp in (0.2, 0.8, 1.0, 1.5, 3.0):
        for vbar in (0.01, 0.3, 0.9):
            lo, hi = sphere(1e-6, vbar, amp, 30), sphere(1e-6, vbar, amp, 40)
            print(f"sphere vbar={vbar} amp={amp}: {nstr(hi, 25)} (differ by {nstr(abs(hi - lo) / hi, 3)})", file=sys.stderr)
            cases.append({"vbar": vbar, "amp": amp, "mu_ratio": nstr(hi, 30), "reduction": nstr(1 - hi, 30)})
    print(json.dumps({"source": "data/scripts/mdr_reference.py --sphere (mpmath, the exact sphere of radius 1 at u0 = 1e-6)", "cases": cases}, indent=1))
    sys.exit(0)

points = []
for n in (1.0, 2.0):
    for amp in (0.999, 1.0, 1.001, 1.5):
        for vbar in (1e-6, 1e-4, 1e-3, 0.003, 0.01, 0.1, 0.3):
            points.append((n, vbar, amp))
for n in (1.0, 2.0, 3.0):
    for amp in (0.3, 0.8, 2.0, 5.0):
        for vbar in (0.2, 0.6, 0.95, 0.999):
            points.append((n, vbar, amp))
# Where amp sqrt(1 - vbar^2) = 1 the stick-first band starts at the contact
# centre's threshold u* (within an ulp): a piece there once saw its Jacobian
# jitter with the rounding of its nodes (fricosc missed by 1e-11).
for n in (1.0, 2.0, 3.0):
    for vbar, amp in ((0.8, 5 / 3), (0.6, 1.25), (0.8, 5 / 3 * (1 + 1e-9)), (0.8, 5 / 3 * (1 - 1e-9))):
        points.append((n, vbar, amp))

cases = []
worst = mpf(0)
for n, vbar, amp in points:
    lo = mu(n, vbar, amp, 45)
    hi = mu(n, vbar, amp, 60)
    mp.dps = 60
    diff = abs(hi - lo) / hi
    worst = max(worst, diff)
    print(f"n={n} vbar={vbar} amp={amp}: {nstr(hi, 25)} (two precisions differ by {nstr(diff, 3)})", file=sys.stderr)
    cases.append({"n": n, "vbar": vbar, "amp": amp, "mu_ratio": nstr(hi, 40), "reduction": nstr(1 - hi, 40)})
print(f"largest relative difference of the two precisions: {nstr(worst, 3)}", file=sys.stderr)
print(json.dumps({"source": "data/scripts/mdr_reference.py (mpmath, tanh-sinh at 45 and 60 digits)", "cases": cases}, indent=1))
