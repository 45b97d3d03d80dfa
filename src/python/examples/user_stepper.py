"""A time stepper as a tribologist writes one from the seed: numpy, SI units,
the oscillation written ``u_z = u0 + du cos(omega t)`` (the seed writes
``u0 - du cos``), started sliding, the mean taken over the last period. It
writes the files ``tests/tool/users.rs`` validates (``data/user-stepper/``), and
plants the bugs ``fricosc validate`` is meant to name:

    python3 src/python/examples/user_stepper.py --out data/user-stepper

needs numpy and pandas. Files written:

- ``flat@M.csv``: the flat punch at M steps per period, written by
  ``np.savetxt(..., header="vbar,amp,mu_ratio", delimiter=",")`` (a
  ``# vbar,amp,mu_ratio`` header); M = 250, 500, 1000, 2000: a series that
  converges;
- ``flat.json``: the table at M = 1000 as pandas writes it by default
  (``DataFrame.to_json()``: the ``columns`` orient);
- ``flat-window95@M.csv``: bug, the mean taken over 0.95 of the last period;
- ``parabolic@M.csv``: an MDR paraboloid, M steps per period and M springs
  (M = 250, 500, 1000);
- ``parabolic-cutoff@M.csv``: bug, the springs cut off at the mean contact
  radius ``sqrt(R u0)`` (those that touch only near the deepest point are lost);
- ``history-flat.csv``: the forces (N) over the last two periods at
  ``vbar = 0.3``, ``du/u0 = 1.5``, 1000 steps per period, times ``t`` (s) from one
  step past a period boundary;
- ``history-parabolic.csv``: the same for the paraboloid (1000 springs).
"""

from __future__ import annotations

import argparse
import os
from typing import Any, List, Optional, Sequence

import numpy as np
import numpy.typing as npt
import pandas as pd

MU0 = 0.3
U0 = 1e-6  # mean indentation, m
OMEGA = 2 * np.pi * 20e3  # rad/s
# Flat punch: normal and tangential stiffness (N/m); kz u0 = 2 N.
KZ, KX = 2e6, 1.6e6
# Paraboloid: radius (m), effective moduli (Pa); the MDR foundation g(x) = x^2 / R.
RADIUS, E_STAR, G_STAR = 1e-2, 1e9, 0.8e9
VBARS = [0.0, 0.05, 0.1, 0.2, 0.4, 0.6, 0.8, 0.95, 1.1]
AMPS = [0.5, 1.5]
PERIODS = 6


def run(
    vbar: Sequence[float] | npt.NDArray[np.float64],
    amp: Sequence[float] | npt.NDArray[np.float64],
    steps: int,
    springs: Optional[int] = None,
    cutoff: bool = False,
    window: float = 1.0,
    history: bool = False,
) -> npt.NDArray[np.float64]:
    """Forces of every row (arrays over rows) by the seed's scheme: the
    tangential force of each spring grows by kx v0 dt and is capped by mu0 N."""
    v_col, a_col = np.asarray(vbar, float)[:, None], np.asarray(amp, float)[:, None]
    du = a_col * U0
    if springs is None:  # flat punch: one spring
        kz, kx, g = np.array([KZ]), np.array([KX]), np.array([0.0])
    else:
        reach = np.sqrt(RADIUS * (U0 + du.max())) if not cutoff else np.sqrt(RADIUS * U0)
        dx = 2 * reach / springs
        x = -reach + dx * (np.arange(springs) + 0.5)
        kz, kx, g = E_STAR * dx * np.ones(springs), G_STAR * dx * np.ones(springs), x * x / RADIUS
    # eq. 3: vbar = (kx / kz) v0 / (mu0 omega du)
    v0 = v_col * MU0 * OMEGA * du * kz[0] / kx[0]
    dt = 2 * np.pi / OMEGA / steps

    def normal(t: float) -> npt.NDArray[np.float64]:
        return kz * np.maximum(U0 + du * np.cos(OMEGA * t) - g, 0.0)  # type: ignore[no-any-return]

    force = MU0 * normal(0.0)  # started sliding
    last = (PERIODS - 1) * steps
    kept = int(round(window * steps))
    sum_t = np.zeros(len(v_col))
    sum_n = np.zeros(len(v_col))
    hist: List[Any] = []
    for k in range(1, PERIODS * steps + 1):
        t = k * dt
        n = normal(t)
        force = np.where(n > 0, np.minimum(force + kx * v0 * dt, MU0 * n), 0.0)
        if k > last and k - last <= kept:
            sum_t += force.sum(axis=1)
            sum_n += n.sum(axis=1)
        if history and k > (PERIODS - 2) * steps:
            hist.append((t, n.sum(axis=1)[0], force.sum(axis=1)[0]))
    if history:
        return np.array(hist)
    return sum_t / (MU0 * sum_n)


def table(steps: int, **kw: Any) -> npt.NDArray[np.float64]:
    grid_v, grid_a = np.meshgrid(VBARS, AMPS)
    v, a = grid_v.ravel(), grid_a.ravel()
    return np.column_stack([v, a, run(v, a, steps, **kw)])


def savetxt(path: str, rows: npt.NDArray[np.float64]) -> None:
    np.savetxt(path, rows, header="vbar,amp,mu_ratio", delimiter=",", fmt="%.17g")


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--out", required=True)
    out = p.parse_args().out
    os.makedirs(out, exist_ok=True)
    for m in (250, 500, 1000, 2000):
        rows = table(m)
        savetxt(os.path.join(out, f"flat@{m}.csv"), rows)
        if m == 1000:
            pd.DataFrame(rows, columns=["vbar", "amp", "mu_ratio"]).to_json(os.path.join(out, "flat.json"))
        savetxt(os.path.join(out, f"flat-window95@{m}.csv"), table(m, window=0.95))
    for m in (250, 500, 1000):
        savetxt(os.path.join(out, f"parabolic@{m}.csv"), table(m, springs=m))
        savetxt(os.path.join(out, f"parabolic-cutoff@{m}.csv"), table(m, springs=m, cutoff=True))
    for name, springs in (("flat", None), ("parabolic", 1000)):
        h = run([0.3], [1.5], 1000, springs=springs, history=True)
        np.savetxt(os.path.join(out, f"history-{name}.csv"), h, header="t,normal,tangential", delimiter=",",
                   fmt="%.17g", comments="")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
