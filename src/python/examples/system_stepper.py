"""A time stepper of the pin on a tribometer's system spring (the body with
mass, README: the system's mass and stiffness), in numpy, every row at once,
with the mistakes researchers make planted one at a time:

    python3 src/python/examples/system_stepper.py [BUG] > run.csv
    fricosc validate run.csv --system-stiffness 1 --frequency-ratio 0.8 --damping 0.05
    python3 src/python/examples/system_stepper.py history [BUG] 0.3 0.5 > h.csv
    fricosc validate --history h.csv --vbar 0.3 --amp 0.5 --system-stiffness 1 --frequency-ratio 0.8 --damping 0.05

In the seed's units (tau = omega t, lengths in pre-slip lengths, forces in
mu0 kz u0) the body obeys

    Omega^2 x'' = kappa (vhat tau - x) - 2 zeta sqrt(kappa) Omega (x' - vhat) - f,

and the contact force f follows the body, held within its Coulomb bound
B = (1 - amp cos tau)_+ (0 out of contact); mu/mu0 = <f>/<B> over the last
period. Semi-implicit Euler: the velocity, then the position, then f.

BUG is one of: none (the default), no_damping (zeta left out), omega
(Omega where Omega^2 belongs), norm_by_one (<f> divided by 1, not <B>),
few_periods (15 periods instead of 100), spring_sign (the system spring's
sign reversed: the run diverges). Each is named by `fricosc validate`
(src/python/tests/test_system_bugs.py).
"""

from __future__ import annotations

import math
import sys
from typing import Dict

import numpy as np
import numpy.typing as npt

TAU = 2 * math.pi
Array = npt.NDArray[np.float64]

KAPPA, OMEGA, ZETA = 1.0, 0.8, 0.05
VBARS = (0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 1.2, 1.6, 2.0, 2.5, 3.0, 4.0, 5.0)
AMPS = (0.5, 1.5)
BUGS = ("none", "no_damping", "omega", "norm_by_one", "few_periods", "spring_sign")


def step_table(vbar: Array, amp: Array, bug: str = "none", *, steps: int = 500, periods: int = 100) -> Array:
    """mu/mu0 of the flat punch on the system (KAPPA, OMEGA, ZETA) at every
    row ``(vbar, amp)``, from the body at rest on the drive's line, moving
    with it, the contact spring relaxed."""
    kappa = -KAPPA if bug == "spring_sign" else KAPPA
    mass = OMEGA if bug == "omega" else OMEGA**2
    damp = 0.0 if bug == "no_damping" else 2 * ZETA * math.sqrt(KAPPA) * OMEGA
    periods = 15 if bug == "few_periods" else periods
    vhat = vbar * amp
    h = TAU / steps
    x, v, f = np.zeros_like(vhat), vhat.copy(), np.zeros_like(vhat)
    sum_f, sum_b = np.zeros_like(vhat), np.zeros_like(vhat)
    with np.errstate(over="ignore", invalid="ignore"):
        for k in range(1, steps * periods + 1):
            tau = h * (k - 1)
            v = v + h * (kappa * (vhat * tau - x) - damp * (v - vhat) - f) / mass
            x_new = x + h * v
            bound = np.maximum(1 - amp * math.cos(h * k), 0)
            f = np.clip(f + (x_new - x), -bound, bound)
            x = x_new
            if k > steps * (periods - 1):
                sum_f += f
                sum_b += bound
    return np.asarray(sum_f / (steps if bug == "norm_by_one" else sum_b))


def step_history(vbar: float, amp: float, bug: str = "none", *, steps: int = 2000, periods: int = 100) -> Dict[str, Array]:
    """The last two periods of one row as ``fricosc history`` writes them:
    the phase ``tau``, the normal force (units F0 = kz u0), the tangential
    force (mu0 F0), the body's lag ``vhat tau - x`` and velocity ``dx/dtau``
    (pre-slip lengths), sampled after each step, by the same scheme."""
    kappa = -KAPPA if bug == "spring_sign" else KAPPA
    mass = OMEGA if bug == "omega" else OMEGA**2
    damp = 0.0 if bug == "no_damping" else 2 * ZETA * math.sqrt(KAPPA) * OMEGA
    vhat, h = vbar * amp, TAU / steps
    x, v, f = 0.0, vhat, 0.0
    rows = []
    for k in range(1, steps * periods + 1):
        tau = h * (k - 1)
        v = v + h * (kappa * (vhat * tau - x) - damp * (v - vhat) - f) / mass
        x_new = x + h * v
        bound = max(1 - amp * math.cos(h * k), 0.0)
        f = min(max(f + (x_new - x), -bound), bound)
        x = x_new
        if k > steps * (periods - 2):
            rows.append((h * k, bound, f, vhat * h * k - x, v))
    return {name: np.array(col) for name, col in zip(HISTORY_COLUMNS, zip(*rows))}


HISTORY_COLUMNS = ("tau", "normal", "tangential", "body_lag", "body_velocity")


def main() -> None:
    bug = sys.argv[1] if len(sys.argv) > 1 else "none"
    if bug == "history":
        # A history of one row: history [BUG] VBAR AMP.
        h = step_history(float(sys.argv[3]), float(sys.argv[4]), sys.argv[2])
        print(",".join(HISTORY_COLUMNS))
        for row in zip(*(h[c] for c in HISTORY_COLUMNS)):
            print(",".join(repr(float(x)) for x in row))
        return
    if bug not in BUGS:
        sys.exit(f"unknown bug {bug!r}: one of {', '.join(BUGS)}")
    vbar, amp = (np.array(x, dtype=float) for x in zip(*[(v, a) for a in AMPS for v in VBARS]))
    print("shape,vbar,amp,mu_ratio")
    for v, a, mu in zip(vbar, amp, step_table(vbar, amp, bug)):
        print(f"flat,{float(v)!r},{float(a)!r},{float(mu)!r}")


if __name__ == "__main__":
    main()
