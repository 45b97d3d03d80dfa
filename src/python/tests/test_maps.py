"""Maps: the system in the vectorised functions (against ``fricosc batch``,
bit for bit) and the same functions on dask arrays, on a ``LocalCluster`` of
two worker processes (against the in-process values, bit for bit). The Dask
tests are skipped, with the reason, where Dask is not installed (``.ci/run``
installs the ``dask`` extra)."""

from __future__ import annotations

import csv
import importlib
import io
import os
import pathlib
import signal
import threading
from typing import Any, Iterator

import numpy as np
import pytest

import fricosc
from test_fricosc import _interrupted_after, cli

SYSTEM = dict(system_stiffness=[[0.5], [1.0], [4.0]], frequency_ratio=[0.3, 0.8, 1.4], damping=0.05)


def test_a_system_map_is_batch_bit_for_bit() -> None:
    """A 3 x 3 broadcast of systems at two velocities and a tangential drive,
    flat and parabolic (32 springs): every value is ``fricosc batch``'s on the
    same rows (one convention, one solver)."""
    for shape, extra, springs in (("flat", {}, None), ("parabolic", {"tangential_amp": 0.4, "phase": 0.3}, 32)):
        got = np.asarray(fricosc.mu_ratio(shape, vhat=np.array([[[0.2]], [[0.6]]]), amp=0.5, springs=springs, **extra, **SYSTEM))  # type: ignore[arg-type]
        assert got.shape == (2, 3, 3)
        rows = io.StringIO()
        w = csv.writer(rows)
        w.writerow(["shape", "vhat", "amp", "tangential_amp", "phase", "system_stiffness", "frequency_ratio", "damping"])
        for i, v in enumerate((0.2, 0.6)):
            for j, k in enumerate((0.5, 1.0, 4.0)):
                for m, om in enumerate((0.3, 0.8, 1.4)):
                    w.writerow([shape, v, 0.5, extra.get("tangential_amp", 0), extra.get("phase", 0), k, om, 0.05])
        path = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"fricosc-map-{os.getpid()}.csv")
        with open(path, "w") as f:
            f.write(rows.getvalue())
        try:
            args = ["batch", path, "--format", "csv"] + ([] if springs is None else ["--springs", str(springs)])
            out = list(csv.DictReader(io.StringIO(cli(*args))))
        finally:
            os.remove(path)
        assert [float(r["mu_ratio"]) for r in out] == got.ravel().tolist()


def test_a_row_that_cannot_settle_is_named_or_nan() -> None:
    """A drive too slow for a soft system to reach steady sliding in the
    periods run: an ``InputError`` naming the element's index and the reason,
    or NaN there with ``errors="nan"`` (the rest unchanged)."""
    v = [0.3, 1e-7, 0.5]
    with pytest.raises(fricosc.InputError, match=r"steady sliding only after .* \(at index 1\)$"):
        fricosc.mu_ratio("flat", v, 0.5, system_stiffness=0.1, frequency_ratio=0.5)
    got = np.asarray(fricosc.mu_ratio("flat", v, 0.5, system_stiffness=0.1, frequency_ratio=0.5, errors="nan"))
    assert np.isnan(got[1]) and got[[0, 2]].tolist() == [
        fricosc.mu_ratio("flat", x, 0.5, system_stiffness=0.1, frequency_ratio=0.5) for x in (0.3, 0.5)
    ]


def test_keywords_that_do_not_apply_are_refused() -> None:
    for kw in ({"frequency_ratio": 0.5}, {"damping": 0.1}, {"springs": 64}, {"errors": "nan"}):
        with pytest.raises(fricosc.InputError, match="applies only with system_stiffness"):
            fricosc.mu_ratio("flat", 0.3, 0.5, **kw)
    for stiffness in (None, 1.0):
        with pytest.raises(fricosc.InputError, match="errors must be 'raise' or 'nan'"):
            fricosc.mu_ratio("flat", 0.3, 0.5, system_stiffness=stiffness, errors="ignore")
    with pytest.raises(fricosc.InputError, match=r"system-stiffness.* \(at index \(1, 0\)\)$"):
        fricosc.mu_ratio("flat", 0.3, 0.5, system_stiffness=[[1.0], [-1.0]])


def test_ctrl_c_interrupts_a_map_on_a_system() -> None:
    """SIGINT while a map of curved points on a system is computed (4,096 of
    them at 1,024 springs: minutes): answered within the poll."""
    code = "fricosc.mu_ratio('parabolic', np.linspace(0.2, 1.2, 4096), 0.5, system_stiffness=1.0, frequency_ratio=0.5, springs=1024)"
    assert _interrupted_after(code) < 1.0


def test_readme_maps_session_works_as_printed() -> None:
    """README's Dask session (its own ``LocalCluster``), run as a doctest:
    every output as printed, the progress bar Dask's own. Before the
    module's cluster exists: with two clients in one process the progress
    bar waits on the other's loop."""
    import doctest

    pytest.importorskip("dask.distributed", reason="Dask is not installed: pip install './src/python[dask]'")
    text = (pathlib.Path(__file__).resolve().parents[3] / "README.md").read_text()
    start = text.index("```python\n>>> import numpy as np, dask.array as da, fricosc") + len("```python\n")
    block = text[start : text.index("```", start)]
    test = doctest.DocTestParser().get_doctest(block, {}, "README", "README.md", 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS)
    runner.run(test)
    assert runner.failures == 0 and runner.tries >= 7


@pytest.fixture(scope="module")
def client() -> Iterator[Any]:
    distributed = pytest.importorskip(
        "dask.distributed", reason="Dask is not installed: pip install './src/python[dask]' (the dask extra)"
    )
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c


def test_dask_maps_are_lazy_and_bit_for_bit(client: Any) -> None:
    """A 10^6-element stiff map, a 200 x 200 curved one, a 40 x 40 flat map on
    a system and a 80 x 80 curved one on a system (a cone of 32 springs over
    vhat and amp, about 13 ms a point), each a lazy dask array
    computed on the two workers: equal to the in-process values bit for bit."""
    da: Any = importlib.import_module("dask.array")
    v = np.linspace(0.0, 1.2, 1_000_000)
    lazy = fricosc.mu_ratio("flat", da.from_array(v, chunks=250_000), 0.5)
    assert isinstance(lazy, da.Array) and lazy.shape == (1_000_000,)
    assert np.array_equal(client.compute(lazy).result(), fricosc.mu_ratio("flat", v, 0.5))
    vv, aa = np.meshgrid(np.linspace(0.01, 1.1, 200), np.linspace(0.1, 2.0, 200))
    lazy = fricosc.reduction("parabolic", da.from_array(vv, chunks=50), aa)
    assert np.array_equal(client.compute(lazy).result(), fricosc.reduction("parabolic", vv, aa))
    vv, kk = np.meshgrid(np.linspace(0.05, 1.0, 40), np.geomspace(0.3, 10.0, 40))
    lazy = fricosc.mu_ratio("flat", da.from_array(vv, chunks=20), 0.7, system_stiffness=kk, frequency_ratio=0.6, damping=0.05)
    want = fricosc.mu_ratio("flat", vv, 0.7, system_stiffness=kk, frequency_ratio=0.6, damping=0.05)
    assert np.array_equal(client.compute(lazy).result(), want)
    vv, aa = np.meshgrid(np.linspace(0.05, 1.1, 80), np.linspace(0.1, 2.0, 80))
    system = {"system_stiffness": 2.0, "frequency_ratio": 0.5, "damping": 0.3, "springs": 32}
    lazy = fricosc.mu_ratio("cone", vhat=da.from_array(vv, chunks=50), amp=aa, **system)  # type: ignore[arg-type]
    assert np.shape(lazy) == (80, 80)
    want = fricosc.mu_ratio("cone", vhat=vv, amp=aa, **system)  # type: ignore[arg-type]
    assert np.array_equal(client.compute(lazy).result(), want)


def test_a_killed_worker_is_survived(client: Any) -> None:
    """One worker process killed while a map on a system is computed: Dask
    reschedules its blocks, and the values are the in-process ones."""
    da: Any = importlib.import_module("dask.array")
    vv, kk = np.meshgrid(np.linspace(0.05, 1.0, 60), np.geomspace(0.3, 10.0, 60))
    lazy = fricosc.mu_ratio("flat", da.from_array(vv, chunks=10), 0.7, system_stiffness=kk, frequency_ratio=0.6, damping=0.05)
    pids = set(client.run(os.getpid).values())
    killed = threading.Event()

    def kill() -> None:
        os.kill(min(pids), signal.SIGKILL)
        killed.set()

    future = client.compute(lazy)
    threading.Timer(0.5, kill).start()
    got = future.result(timeout=300)
    assert killed.is_set() and future.status == "finished"
    assert np.array_equal(got, fricosc.mu_ratio("flat", vv, 0.7, system_stiffness=kk, frequency_ratio=0.6, damping=0.05))
    client.wait_for_workers(2, timeout=60)
    assert set(client.run(os.getpid).values()) != pids, "no worker was restarted"


def test_a_bad_element_raises_on_the_client(client: Any) -> None:
    """A bad element in a block on a worker: the same ``InputError`` on the
    client as in process, its index in the whole array."""
    da: Any = importlib.import_module("dask.array")
    v = np.full((4, 6), 0.3)
    v[2, 5] = -1.0
    with pytest.raises(fricosc.InputError) as in_process:
        fricosc.mu_ratio("flat", v, 0.5)
    with pytest.raises(fricosc.InputError) as on_cluster:
        client.compute(fricosc.mu_ratio("flat", da.from_array(v, chunks=2), 0.5)).result()
    assert str(on_cluster.value) == str(in_process.value) and str(in_process.value).endswith("(at index (2, 5))")

