"""A small explicit time stepper for the flat punch with planted bugs, for the
README's walk-through "Validating your code" (pure Python, no numpy):

    python3 src/python/examples/buggy_stepper.py [--fixed] > run.csv
    fricosc validate run.csv --format summary

The bugs (each one is named by a finding of `fricosc validate`):
1. the tangential force is divided by the static normal force kz u0 instead of
   its period average, which is larger once the punch jumps (amp > 1)
   (`above_one`, `not_one_above_critical`);
2. the spring starts relaxed (F = 0), which at vbar = 0 stays 0
   (`at_rest_convention`);
3. only 3 periods are run, too few at low velocity (`not_steady`).
`--fixed` removes all three.
"""

from __future__ import annotations

import math
import sys


def mu_ratio(vbar: float, amp: float, steps: int, periods: int, relaxed: bool, static_norm: bool) -> float:
    """The seed's scheme for one spring, in units of mu0 kz du: the bound is
    (1/amp - cos tau)_+, the force grows by vbar h per step and is capped by it."""
    h = 2.0 * math.pi / steps
    force = 0.0 if relaxed else max(1.0 / amp - 1.0, 0.0)
    tangential = normal = 0.0
    for k in range(1, periods * steps + 1):
        bound = max(1.0 / amp - math.cos(h * k), 0.0)
        force = min(force + vbar * h, bound) if bound > 0.0 else 0.0
        if k > (periods - 1) * steps:  # average the last period
            tangential += force
            normal += bound
    if static_norm:  # bug 1: divided by the static normal force kz u0 (1/amp here), not the mean
        return tangential / steps / (1.0 / amp)
    return tangential / normal


def main() -> None:
    fixed = "--fixed" in sys.argv[1:]
    print("shape,vbar,amp,mu_ratio")
    for amp in (0.5, 1.5):
        for vbar in (0.0, 0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 1.1):
            mu = mu_ratio(vbar, amp, steps=2000, periods=40 if fixed else 3, relaxed=not fixed, static_norm=not fixed)
            print(f"flat,{vbar!r},{amp!r},{mu!r}")


if __name__ == "__main__":
    main()
