"""Throughput of the Python path (a benchmark, not a test): random flat points
(vbar in [0, 1.2], amp in [0, 3]) and parabolic points per call, best of 5.

    python src/python/examples/bench.py
"""

from __future__ import annotations

import time

import numpy as np

import fricosc


def best(f: "object", repeat: int = 5) -> float:
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()  # type: ignore[operator]
        times.append(time.perf_counter() - t)
    return min(times)


def main() -> None:
    rng = np.random.default_rng(1)
    for shape, n in (("flat", 1_000_000), ("parabolic", 100_000)):
        v = rng.uniform(0.0, 1.2, n)
        a = rng.uniform(0.0, 3.0, n)
        t = best(lambda: fricosc.mu_ratio(shape, v, a))
        print(f"{shape}: {n} points in {t:.3f} s, {t / n * 1e6:.3f} us per point")


if __name__ == "__main__":
    main()
