"""Exact synthetic measurements for `fricosc fit`: the flat punch's mu_macro at
chosen (mu0, kx/kz, u0), from the independent 50-digit steady state of
`flat_events.py` (bisection on the stick's gap, mpmath quadratures), not from
fricosc.

Each row's v0, du and frequency are written as given (6 significant digits);
mu = mu0 * mu_ratio(vbar, du/u0) with vbar = (kx/kz) v0 / (mu0 omega du), omega
= 2 pi frequency, computed at exactly those values and printed to 17 digits.

Run: python3 data/scripts/fit_synthetic.py > data/fit-synthetic-flat.csv   (needs mpmath; a second)
     python3 data/scripts/fit_synthetic.py --noisy > data/fit-example.csv
     python3 data/scripts/fit_synthetic.py --load > data/fit-synthetic-load.csv
The second is measured-style: each mu with Gaussian noise of standard deviation
0.004 (Python's random, seed 2026) and that sigma as a column. The third is a
dead-weight rig (load control): each row's load L (N; 0.5, 1 and 2 N in turn,
their median 1 N) holds the mean normal force kz u <(1 - (du/u) cos tau)_+> of
a flat punch of kz = 1e6 N/m, so each row's mean indentation u solves
u (pi - t0 + sqrt(a^2 - 1))/pi = L/kz for a = du/u > 1 (t0 = acos(1/a); u =
L/kz for a <= 1), found by mpmath's findroot; u0 = 1e-6 m is the static
indentation at the median load.
"""
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from flat_events import state  # noqa: E402
from mpmath import mp, mpf, pi, nstr  # noqa: E402

mp.dps = 50
MU0, RATIO, U0, FREQUENCY = mpf("0.35"), mpf("0.8"), mpf("1e-6"), mpf(200)


def mu_at(v0, du):
    vbar = RATIO * v0 / (MU0 * 2 * pi * FREQUENCY * du)
    if vbar >= 1:
        return MU0
    mu, _ = state(vbar, du / U0)
    return MU0 * mu


KZ = mpf("1e6")


def mean_indentation(load, du):
    """The flat punch's mean indentation under `load` (N) at amplitude `du`."""
    def mean_force(u):
        a = du / u
        if a <= 1:
            return KZ * u
        t0 = mp.acos(1 / a)
        return KZ * u * (pi - t0 + mp.sqrt(a * a - 1)) / pi
    u = load / KZ
    if du / u <= 1:
        return u
    return mp.findroot(lambda x: mean_force(x) - load, (u / 4, u), solver="anderson")


if "--load" in sys.argv:
    print("v0,du,frequency,load,mu")
    k = 0
    for du in ("3e-7", "6e-7", "1.2e-6"):
        for vbar in (0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.75, 0.9, 1.1):
            load = ("0.5", "1", "2")[k % 3]
            k += 1
            v0 = float(nstr(mpf(vbar) * MU0 * 2 * pi * FREQUENCY * mpf(du) / RATIO, 6))
            vb = RATIO * mpf(repr(v0)) / (MU0 * 2 * pi * FREQUENCY * mpf(du))
            u = mean_indentation(mpf(load), mpf(du))
            mu = MU0 if vb >= 1 else MU0 * state(vb, mpf(du) / u)[0]
            print(f"{v0!r},{du},{int(FREQUENCY)},{load},{nstr(mu, 17)}")
    sys.exit(0)

NOISY = "--noisy" in sys.argv
SIGMA = 0.004
noise = random.Random(2026)
print("v0,du,frequency,mu" + (",sigma" if NOISY else ""))
for du in ("3e-7", "6e-7", "1.2e-6"):
    for vbar in (0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.75, 0.9, 1.1):
        v0 = float(nstr(mpf(vbar) * MU0 * 2 * pi * FREQUENCY * mpf(du) / RATIO, 6))
        mu = mu_at(mpf(repr(v0)), mpf(du))
        if NOISY:
            print(f"{v0!r},{du},{int(FREQUENCY)},{float(mu) + noise.gauss(0, SIGMA):.5f},{SIGMA}")
        else:
            print(f"{v0!r},{du},{int(FREQUENCY)},{nstr(mu, 17)}")
