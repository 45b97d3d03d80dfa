"""The speed of a map on a Dask cluster against one process on the same
machine: a 60 x 40 map of curved points on a system (the cone at 32
springs) computed in process (chunks on every core) and on a
``LocalCluster`` of one single-threaded worker per core; both bit for bit
the same values. Writes JSON (the machine, the times, the speed-up).

Run: python src/python/examples/dask_speedup.py > data/bench/dask-speedup.json
(needs ``pip install "./src/python[dask]"``; about a minute on two cores).
"""

from __future__ import annotations

import importlib
import json
import os
import sys
import time
from typing import Any

import numpy as np

import fricosc


def main() -> None:
    distributed: Any = importlib.import_module("dask.distributed")
    da: Any = importlib.import_module("dask.array")
    cores = os.cpu_count() or 1
    vbar, kappa = np.meshgrid(np.linspace(0.05, 1.0, 60), np.geomspace(0.3, 10.0, 40), indexing="ij")
    args = dict(system_stiffness=kappa, frequency_ratio=0.6, damping=0.05, springs=32)
    t0 = time.perf_counter()
    here = fricosc.mu_ratio("cone", vbar, 0.7, **args)  # type: ignore[arg-type]
    in_process = time.perf_counter() - t0
    with distributed.LocalCluster(n_workers=cores, threads_per_worker=1, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            lazy = fricosc.mu_ratio("cone", da.from_array(vbar, chunks=(15, 40)), 0.7, **args)  # type: ignore[arg-type]
            t0 = time.perf_counter()
            there = client.compute(lazy).result()
            on_cluster = time.perf_counter() - t0
    assert np.array_equal(here, there)
    json.dump(
        {
            "source": "src/python/examples/dask_speedup.py",
            "machine": {"cores": cores},
            "map": "cone, 32 springs, on a system (kappa 0.3-10, Omega 0.6, zeta 0.05), 60 x 40 points",
            "in_process_s": in_process,
            "local_cluster_s": on_cluster,
            "local_cluster_workers": cores,
            "speed_up": in_process / on_cluster,
            "bit_for_bit": True,
        },
        sys.stdout,
        indent=1,
    )
    print()


if __name__ == "__main__":
    main()
