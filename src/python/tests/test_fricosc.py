"""The Python package against independent values and against the command line.

Run from the repository: ``pytest src/python/tests`` after
``pip install ./src/python``. The comparisons with the command line need
the release binary (``cargo build --release``); they are skipped without it,
unless ``FRICOSC_REQUIRE_BIN=1`` (CI) makes its absence a failure.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import pathlib
import subprocess
import tempfile
from decimal import Decimal
from typing import Any, Callable, Dict, List, Tuple

import numpy as np
import numpy.typing as npt
import pytest

import fricosc

ROOT = pathlib.Path(__file__).resolve().parents[3]
BIN = ROOT / "target" / "release" / "fricosc"


def cli(*args: str, status: int = 0) -> str:
    """The command's stdout; its exit status must be ``status`` (``validate``
    exits 1 on findings)."""
    if not BIN.exists():
        if os.environ.get("FRICOSC_REQUIRE_BIN") == "1":
            pytest.fail(f"{BIN} missing: run cargo build --release")
        pytest.skip(f"{BIN} missing: run cargo build --release")
    out = subprocess.run([str(BIN), *args], capture_output=True, text=True)
    assert out.returncode == status, out.stderr
    return out.stdout


def csv_rows(text: str) -> List[Dict[str, str]]:
    """The rows of a CSV text, past its ``#`` lines (a history's units)."""
    return list(csv.DictReader(line for line in io.StringIO(text) if not line.startswith("#")))


def cli_error(*args: str) -> str:
    if not BIN.exists():
        if os.environ.get("FRICOSC_REQUIRE_BIN") == "1":
            pytest.fail(f"{BIN} missing: run cargo build --release")
        pytest.skip(f"{BIN} missing: run cargo build --release")
    out = subprocess.run([str(BIN), *args], capture_output=True, text=True)
    assert out.returncode == 2 and out.stdout == ""
    return out.stderr.strip().removeprefix("error: ")


def reference_cases() -> List[Dict[str, Any]]:
    data = json.loads((ROOT / "data" / "reference-values.json").read_text())
    cases: List[Dict[str, Any]] = data["cases"]
    return cases


def test_reference_values_through_the_numpy_path() -> None:
    """Every 40-digit reference value, all of one shape in one array call."""
    cases = reference_cases()
    for shape in sorted({c["shape"] for c in cases}):
        mine = [c for c in cases if c["shape"] == shape]
        vbar = np.array([c["vbar"] for c in mine])
        amp = np.array([c["amp"] for c in mine])
        mu = fricosc.mu_ratio(shape, vbar, amp)
        red = fricosc.reduction(shape, vbar, amp)
        assert isinstance(mu, np.ndarray) and isinstance(red, np.ndarray)
        for c, m, r in zip(mine, mu, red):
            assert abs(Decimal(float(m)) - Decimal(c["mu_ratio"])) < Decimal("1e-14"), (c, m)
            assert abs(Decimal(float(r)) - Decimal(c["reduction"])) < Decimal("1e-14"), (c, r)


def test_bit_identical_to_the_command_line() -> None:
    """The same inputs through `fricosc table` and through numpy give the same doubles."""
    vbar = [0.0, 1e-9, 0.1, 0.3, 0.5, 0.7, 0.9, 0.999999, 1.0, 1.2]
    amps = [0.0, 0.3, 0.999, 1.0, 1.5, 4.0]
    for shape in ["flat", "parabolic", "cone", "power:3.7", "flat-tip:0.4"]:
        text = cli("table", "--shape", shape, "--vbar", ",".join(map(repr, vbar)),
                   "--amp", ",".join(map(repr, amps)), "--format", "csv")
        rows = list(csv.DictReader(io.StringIO(text)))
        v = np.array([float(r["vbar"]) for r in rows])
        a = np.array([float(r["amp"]) for r in rows])
        mu = fricosc.mu_ratio(shape, v, a)
        red = fricosc.reduction(shape, v, a)
        assert isinstance(mu, np.ndarray) and isinstance(red, np.ndarray)
        assert mu.tolist() == [float(r["mu_ratio"]) for r in rows], shape
        assert red.tolist() == [float(r["reduction"]) for r in rows], shape


def test_point_is_the_command_lines_json() -> None:
    for shape, v, a in [("flat", 0.3, 0.5), ("parabolic", 0.2, 1.4), ("flat-tip:0.5", 0.3, 0.4)]:
        # Pairs (a band's x_range) are tuples in Python, lists in JSON.
        got = json.loads(json.dumps(fricosc.point(shape, v, a)))
        assert got == json.loads(cli("point", "--shape", shape, "--vbar", repr(v), "--amp", repr(a)))
    # Key order too: shape, vbar, amp first.
    assert list(fricosc.point("flat", 0.3, 0.5))[:3] == ["shape", "vbar", "amp"]


def test_history_is_the_command_lines() -> None:
    for shape, extra in [("flat", []), ("parabolic", ["--springs", "300", "--spring-at", "0.2,0.9"])]:
        doc = json.loads(cli("history", "--shape", shape, "--vbar", "0.3", "--amp", "1.3", "--samples", "40", *extra))
        h = fricosc.history(shape, 0.3, 1.3, samples=40, springs=300 if extra else 4000,
                            spring_at=[0.2, 0.9] if extra else [])
        assert h["tau"].tolist() == [s["tau"] for s in doc["samples"]]
        assert h["normal"].tolist() == [s["normal"] for s in doc["samples"]]
        assert h["tangential"].tolist() == [s["tangential"] for s in doc["samples"]]
        assert h["event"] == [s.get("event") for s in doc["samples"]]
        if extra:
            assert h["springs"].tolist() == [s["springs"] for s in doc["samples"]]
    flat = fricosc.history("flat", 0.3, 1.3, samples=40)
    assert {"contact", "loss_of_contact", "stick"} <= {e for e in flat["event"] if e}


def test_broadcasting_shapes() -> None:
    v = np.linspace(0.0, 1.2, 5)
    a = np.array([0.2, 0.8, 1.6])
    out = fricosc.mu_ratio("parabolic", v[:, None], a[None, :])
    assert isinstance(out, np.ndarray) and out.shape == (5, 3) and out.dtype == np.float64
    for i in range(5):
        for j in range(3):
            assert out[i, j] == fricosc.mu_ratio("parabolic", float(v[i]), float(a[j]))
    assert np.asarray(fricosc.mu_ratio("flat", v, 0.5)).shape == (5,)
    assert np.asarray(fricosc.mu_ratio("flat", 0.5, a.reshape(3, 1, 1))).shape == (3, 1, 1)
    assert np.asarray(fricosc.mu_ratio("flat", np.zeros((0, 4)), 0.5)).shape == (0, 4)
    scalar = fricosc.mu_ratio("flat", 0.2, 0.5)
    # The 40-digit value, within 2 ulp (the published digits may move within that).
    assert type(scalar) is float and abs(scalar - 0.7145191049466343399) <= 2.3e-16
    # A 0-d array is a scalar too; lists and tuples are arrays.
    assert type(fricosc.mu_ratio("flat", np.float64(0.2), np.array(0.5))) is float
    assert np.asarray(fricosc.reduction("flat", (0.2, 0.3), [0.5])).shape == (2,)
    with pytest.raises(ValueError, match="broadcast"):
        fricosc.mu_ratio("flat", [0.1, 0.2], [0.1, 0.2, 0.3])


def test_vhat_and_tolerance() -> None:
    a = np.array([0.5, 2.0, 4.0])
    assert np.array_equal(np.asarray(fricosc.mu_ratio("flat", vhat=0.6, amp=a)),
                          np.asarray(fricosc.mu_ratio("flat", 0.6 / a, a)))
    loose = fricosc.mu_ratio("parabolic", 0.3, 0.4, tol=1e-6)
    tight = fricosc.mu_ratio("parabolic", 0.3, 0.4)
    assert isinstance(loose, float) and isinstance(tight, float) and abs(loose - tight) < 1e-6
    assert fricosc.DEFAULT_TOL > 0


def test_shape_classes_equal_their_strings(tmp_path: pathlib.Path) -> None:
    pairs = [(fricosc.Flat(), "flat"), (fricosc.PowerLaw(2), "parabolic"), (fricosc.PowerLaw(2.5), "power:2.5"),
             (fricosc.FlatTip(0.5), "flat-tip:0.5")]
    for cls, spec in pairs:
        assert cls.name == spec
        assert fricosc.mu_ratio(cls, 0.3, 0.7) == fricosc.mu_ratio(spec, 0.3, 0.7)
    # A tabulated sphere from arrays equals the same table from a file.
    r = np.linspace(0.0, 0.3, 301)
    f = 1.0 - np.sqrt(1.0 - r * r)
    path = tmp_path / "sphere.csv"
    path.write_text("r,f\n" + "".join(f"{x!r},{y!r}\n" for x, y in zip(r.tolist(), f.tolist())))
    arrays = fricosc.Profile(r, f, 1e-3)
    from_file = fricosc.Shape(f"profile:{path}@1e-3")
    v, a = np.array([0.0, 0.3, 0.8]), np.array([0.4, 1.2, 0.9])
    assert np.array_equal(np.asarray(fricosc.mu_ratio(arrays, v, a)), np.asarray(fricosc.mu_ratio(from_file, v, a)))
    # ... and reproduces the paraboloid to the table's accuracy.
    diff = np.asarray(fricosc.mu_ratio(arrays, v, a)) - np.asarray(fricosc.mu_ratio("parabolic", v, a))
    assert float(np.max(np.abs(diff))) < 1e-3
    x = np.linspace(0.0, 2.0, 201)
    g = fricosc.EquivalentProfile(x, x * x, 1.0)
    assert abs(float(fricosc.mu_ratio(g, 0.3, 0.4)) - float(fricosc.mu_ratio("parabolic", 0.3, 0.4))) < 1e-9


@pytest.mark.parametrize(
    "call, error, message",
    [
        (lambda: fricosc.mu_ratio("flat", float("nan"), 0.5), ValueError, "invalid vbar = NaN: must be finite"),
        (lambda: fricosc.mu_ratio("flat", [0.1, 0.2, float("inf")], 0.5), ValueError, r"invalid vbar = inf.*\(at index 2\)"),
        (lambda: fricosc.mu_ratio("flat", 0.1, [[0.1, 0.2], [0.3, -1.0]]), ValueError, r"invalid amp = -1.0.*\(at index \(1, 1\)\)"),
        (lambda: fricosc.mu_ratio("flat", -0.0 - 1e-300, 0.5), ValueError, "must be >= 0"),
        (lambda: fricosc.mu_ratio("nonsense", 0.1, 0.5), ValueError, "invalid shape 'nonsense'"),
        (lambda: fricosc.mu_ratio("power:-1", 0.1, 0.5), ValueError, "exponent must be finite and > 0"),
        (lambda: fricosc.mu_ratio("profile:/nonexistent.csv@1", 0.1, 0.5), ValueError, "cannot read /nonexistent.csv"),
        (lambda: fricosc.mu_ratio("flat", 0.1, 0.5, tol=0.0), ValueError, "invalid tol = 0.0"),
        (lambda: fricosc.mu_ratio("flat", vhat=0.3, amp=0.0), ValueError, "vhat needs amp > 0"),
        (lambda: fricosc.mu_ratio("flat", vhat=1e308, amp=1e-10), ValueError, "overflows double precision"),
        (lambda: fricosc.mu_ratio("flat", 0.1, vhat=0.1, amp=0.5), TypeError, "exactly one of vbar"),
        (lambda: fricosc.mu_ratio("flat", 0.1), TypeError, "amp"),
        (lambda: fricosc.mu_ratio("flat", "0.1", 0.5), TypeError, "vbar must be a real number"),
        (lambda: fricosc.mu_ratio("flat", [0.1, "x"], 0.5), TypeError, "vbar must be a real number"),  # type: ignore[arg-type]
        (lambda: fricosc.mu_ratio("flat", 0.1, {"a": 1}), TypeError, "amp must be a real number"),  # type: ignore[arg-type]
        (lambda: fricosc.mu_ratio(3, 0.1, 0.5), TypeError, "a shape is a string"),  # type: ignore[arg-type]
        (lambda: fricosc.Profile([0.0, 1.0, 2.0], [0.0, 2.0, 1.0], 0.5), ValueError, "must not decrease"),
        (lambda: fricosc.Profile([0.0, 1.0], [0.0, 1.0], 0.5), ValueError, "at least 3 rows"),
        (lambda: fricosc.Profile([[0.0, 1.0]], [0.0, 1.0], 0.5), ValueError, "one-dimensional"),
        (lambda: fricosc.Profile([0.0, 1.0, float("nan")], [0.0, 1.0, 2.0], 0.5), ValueError, "finite"),
        (lambda: fricosc.point("flat", [0.1, 0.2], 0.5), TypeError, "vbar must be a real number"),  # type: ignore[arg-type]
        (lambda: fricosc.history("flat", 0.1, 0.5, samples=0), ValueError, "invalid samples = 0"),
        (lambda: fricosc.history("flat", 0.1, 0.5, samples=1.5), TypeError, "samples must be an integer"),  # type: ignore[arg-type]
        (lambda: fricosc.history("parabolic", 0.1, 0.5, springs=2_000_000), ValueError, "more than the limit"),
        # Real numeric dtypes only: strings, bytes, booleans, complex, masked arrays and a string tol are refused.
        (lambda: fricosc.mu_ratio("flat", ["0.3"], 0.5), TypeError, "vbar must be a real number"),
        (lambda: fricosc.mu_ratio("flat", np.array([b"0.3"]), 0.5), TypeError, "vbar must be a real number"),
        (lambda: fricosc.mu_ratio("flat", True, 0.5), TypeError, "vbar must be a real number"),
        (lambda: fricosc.mu_ratio("flat", np.array([True, False]), 0.5), TypeError, "dtype bool"),
        (lambda: fricosc.mu_ratio("flat", np.array([0.3 + 1j]), 0.5), TypeError, "dtype complex128"),
        (lambda: fricosc.mu_ratio("flat", np.ma.masked_array([0.3, 0.4], mask=np.array([False, True])), 0.5), TypeError, "masked"),
        (lambda: fricosc.mu_ratio("flat", 0.3, 0.5, tol="1e-3"), TypeError, "tol must be a real number"),  # type: ignore[arg-type]
        (lambda: fricosc.point("flat", 0.3 + 0j, 0.5), TypeError, "vbar must be a real number"),  # type: ignore[arg-type]
        # Files are read with the command line's cap, counted as they are read.
        (lambda: fricosc.mu_ratio("profile:/dev/zero@1", 0.3, 0.5), fricosc.InputError, "more than the limit"),
        (lambda: fricosc.scene("/dev/zero"), fricosc.InputError, "more than the limit"),
    ],
)
def test_bad_input(call: Callable[[], object], error: type, message: str) -> None:
    with pytest.raises(error, match=message):
        call()


def _child(code: str) -> "subprocess.Popen[bytes]":
    import sys

    return subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def test_memory_is_the_output_array() -> None:
    """10^7 flat points: the peak memory of a fresh interpreter is its inputs
    and the output (8 bytes an element each), not ~107 bytes an element."""
    import resource
    import sys

    code = (
        "import numpy as np, fricosc, resource\n"
        "v = np.linspace(0.0, 1.2, 10_000_000)\n"
        "base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss\n"
        "out = fricosc.mu_ratio('flat', v, 0.5)\n"
        "peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss\n"
        "print(peak - base)\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    grown_kib = int(r.stdout.strip())
    # The output is 80 MB; before, the call added 1.07 GB.
    assert grown_kib < 160_000, f"mu_ratio over 10^7 points grew the peak by {grown_kib} KiB"
    del resource


def test_ctrl_c_interrupts_a_long_call() -> None:
    """SIGINT during a long evaluation raises KeyboardInterrupt between chunks,
    well before the call would end (2 * 10^6 parabolic points: about 10 s)."""
    assert _interrupted_after("fricosc.mu_ratio('parabolic', np.linspace(0.01, 0.99, 2_000_000), 0.7)") < 1.0


def _interrupted_after(code: str) -> float:
    """Seconds from SIGINT to KeyboardInterrupt in a child running ``code``
    (after it prints ``ready``)."""
    import signal
    import time

    # Python's own SIGINT handler, also where the test runs with SIGINT
    # ignored (a shell's background job: Python then installs none).
    p = _child(
        "import numpy as np, fricosc, signal, sys\n"
        "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "print('ready', flush=True)\n"
        "try:\n" + "".join(f"    {line}\n" for line in code.splitlines()) + "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "    sys.exit(3)\n"
    )
    assert p.stdout is not None
    assert p.stdout.readline().strip() == b"ready"
    time.sleep(0.5)
    t0 = time.monotonic()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=300)
    assert p.returncode == 3 and b"interrupted" in out, (p.returncode, out)
    return time.monotonic() - t0


def test_ctrl_c_interrupts_the_check_and_slow_elements() -> None:
    """SIGINT while 2 * 10^8 broadcast elements are checked (about 11 s
    without a look at the signals), and while curved points under a
    tangential oscillation near the degenerate drive are evaluated (a first
    chunk of 4,096 of them took 12.9 s): answered at once."""
    check = "a = np.broadcast_to(np.float64(0.3), (20000, 10000))\nfricosc.mu_ratio('flat', a, np.float64(0.5))"
    assert _interrupted_after(check) < 1.0
    slow = (
        "ph = 4.71238898038469 + np.linspace(-1e-2, 1e-2, 200000)\n"
        "fricosc.mu_ratio('parabolic', vhat=0.01, amp=1.5, tangential_amp=1.3, phase=ph)"
    )
    assert _interrupted_after(slow) < 1.0


def test_ctrl_c_interrupts_a_solve_on_a_system() -> None:
    """SIGINT during one long solve on a system (a paraboloid of 16,384
    springs: about 10 s each) raises KeyboardInterrupt at once: the point
    answered only when done (7 s after the signal), the history with a
    PanicException from numpy's import, validate not within 120 s."""
    system = "system_stiffness=1.0, frequency_ratio=0.5, springs=16384"
    assert _interrupted_after(f"fricosc.point('parabolic', vhat=0.3, amp=0.5, {system})") < 1.0
    assert _interrupted_after(f"fricosc.history('parabolic', vhat=0.3, amp=0.5, samples=8, {system})") < 1.0
    table = "{'vbar': [0.3] * 40, 'amp': [0.5] * 40, 'mu_ratio': [0.8] * 40}"
    validate = f"fricosc.validate({table}, 'parabolic', system_stiffness=1.0, frequency_ratio=0.5)"
    assert _interrupted_after(validate) < 1.0


def test_an_output_beyond_memory_is_a_memory_error() -> None:
    """A broadcast whose output cannot be allocated (300 GB) raises MemoryError
    at once, before its inputs are checked (it was a PanicException)."""
    a = np.broadcast_to(np.float64(0.3), (200_000, 200_000))
    with pytest.raises(MemoryError):
        fricosc.mu_ratio("flat", a, 0.5)
    with pytest.raises(MemoryError):
        fricosc.mu_ratio("flat", vhat=a, amp=0.5, tangential_amp=1.0)


def test_an_empty_table_is_named() -> None:
    with pytest.raises(fricosc.InputError, match="^table: the table has no rows"):
        fricosc.validate({"vbar": [], "amp": [], "mu_ratio": []}, "flat")


def test_one_version() -> None:
    """The package and the command line carry one version (the workspace's)."""
    assert cli("--version").strip() == f"fricosc {fricosc.__version__}"


def test_messages_are_the_command_lines() -> None:
    cases: List[Tuple[List[str], Callable[[], object]]] = [
        (["point", "--shape", "nonsense", "--vbar", "0.1", "--amp", "0.5"], lambda: fricosc.point("nonsense", 0.1, 0.5)),
        (["point", "--vbar", "0.1", "--amp", "-1"], lambda: fricosc.point("flat", 0.1, -1.0)),
        (["point", "--vhat", "1e308", "--amp", "1e-10"], lambda: fricosc.point("flat", vhat=1e308, amp=1e-10)),
        (["point", "--shape", "power:0.01", "--vbar", "0.1", "--amp", "0.5"], lambda: fricosc.point("power:0.01", 0.1, 0.5)),
        # The same wording for a tangential amplitude (the command line's own parser used to word it).
        (
            ["point", "--vhat", "0.3", "--amp", "1", "--tangential-amp", "-1"],
            lambda: fricosc.point("flat", vhat=0.3, amp=1.0, tangential_amp=-1.0),
        ),
        (
            ["point", "--shape", "power:0.05", "--vhat", "0.3", "--amp", "1e15", "--tangential-amp", "1"],
            lambda: fricosc.point("power:0.05", vhat=0.3, amp=1e15, tangential_amp=1.0),
        ),
    ]
    for args, py in cases:
        with pytest.raises(ValueError) as e:
            py()
        assert str(e.value) == cli_error(*args)


def test_a_million_points() -> None:
    """10^6 random flat points in one call (in parallel, the GIL released):
    every value in range and equal to the same point computed alone."""
    rng = np.random.default_rng(7)
    v = rng.uniform(0.0, 1.2, 1_000_000)
    a = rng.uniform(0.0, 3.0, 1_000_000)
    mu = np.asarray(fricosc.mu_ratio("flat", v, a))
    red = np.asarray(fricosc.reduction("flat", v, a))
    assert mu.shape == (1_000_000,) and np.all((mu >= 0) & (mu <= 1)) and np.all(np.isfinite(red))
    assert np.all(mu[v >= 1.0] == 1.0)
    for i in rng.integers(0, 1_000_000, 50):
        assert mu[i] == fricosc.mu_ratio("flat", float(v[i]), float(a[i]))
        assert red[i] == fricosc.reduction("flat", float(v[i]), float(a[i]))
    # Parallel (>= 256 elements) and sequential evaluation agree bit for bit.
    small = np.asarray(fricosc.mu_ratio("parabolic", v[:100], a[:100]))
    large = np.asarray(fricosc.mu_ratio("parabolic", v[:1000], a[:1000]))
    assert np.array_equal(small, large[:100])


def test_threads_share_the_module() -> None:
    """Calls from several Python threads at once (the GIL is released inside)."""
    from concurrent.futures import ThreadPoolExecutor

    v = np.linspace(0.0, 1.0, 2000)
    expected = np.asarray(fricosc.mu_ratio("cone", v, 0.7))
    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(lambda _: np.asarray(fricosc.mu_ratio("cone", v, 0.7)), range(8)))
    assert all(np.array_equal(r, expected) for r in results)


def test_fig7_example_runs(tmp_path: pathlib.Path) -> None:
    """The example script draws Fig. 7 (only where matplotlib is installed)."""
    pytest.importorskip("matplotlib")
    import runpy
    import sys

    out = tmp_path / "fig7.png"
    argv = sys.argv
    sys.argv = ["plot_fig7.py", str(out)]
    try:
        runpy.run_path(str(ROOT / "src" / "python" / "examples" / "plot_fig7.py"), run_name="__main__")
    finally:
        sys.argv = argv
    assert out.stat().st_size > 10_000


def test_readme_session_works_as_printed() -> None:
    """README's Python session, run as a doctest: every output as printed."""
    import doctest

    text = (ROOT / "README.md").read_text()
    start = text.index("```python\n>>> import numpy as np, fricosc") + len("```python\n")
    block = text[start : text.index("```", start)]
    test = doctest.DocTestParser().get_doctest(block, {}, "README", "README.md", 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.failures == 0 and runner.tries >= 8


def test_validate_is_the_command_lines() -> None:
    """The README walk-through's buggy table: the same report (findings, errors,
    regimes) through Python as through `fricosc validate`."""
    script = ROOT / "src" / "python" / "examples" / "buggy_stepper.py"
    import sys

    text = subprocess.run([sys.executable, str(script)], check=True, capture_output=True, text=True).stdout
    path = ROOT / "target" / "py-buggy-run.csv"
    path.parent.mkdir(exist_ok=True)
    path.write_text(text)
    expected = json.loads(cli("validate", str(path), "--format", "json", status=1))
    rows = csv_rows(text)
    table: Dict[str, Any] = {k: [float(r[k]) for r in rows] for k in ("vbar", "amp", "mu_ratio")}
    table["shape"] = [r["shape"] for r in rows]
    got = fricosc.validate(table)
    assert expected.pop("format") == "CSV (',' delimited)"  # how the command read the file
    assert json.loads(json.dumps(got)) == expected
    assert [f["kind"] for f in got["findings"]] == ["above_one", "not_one_above_critical", "not_steady", "at_rest_convention"]
    relaxed = fricosc.validate(table, at_rest="relaxed")
    assert "at_rest_convention" not in [f["kind"] for f in relaxed["findings"]]
    # vhat and mu with mu0; a conflicting shape; a missing mu0.
    vh = {"vhat": [0.15, 0.6], "amp": [0.5, 2.0], "mu": [0.4 * float(fricosc.mu_ratio("cone", 0.3, 0.5)),
                                                          0.4 * float(fricosc.mu_ratio("cone", 0.3, 2.0))]}
    assert fricosc.validate(vh, "cone", mu0=0.4)["max_abs_error"] < 1e-15
    with pytest.raises(ValueError, match="mu0 is needed"):
        fricosc.validate(vh, "cone")
    with pytest.raises(ValueError, match="shape= says 'cone'"):
        fricosc.validate(table, "cone")
    with pytest.raises(TypeError, match="mapping of columns"):
        fricosc.validate([1, 2, 3])


def test_validate_reads_a_combined_table_as_the_command_line() -> None:
    """A table under oscillation in the sliding direction (``tangential_amp``,
    ``phase``), correct to 1e-7: Python compares it as the command line does
    (it compared the seed's problem instead: max error 1.23, a ``negative``
    finding), with the same report; a series of such tables is refused alike."""
    exact = json.loads(cli("table", "--shape", "parabolic", "--vhat", "0.3", "--amp", "0.5,1.5",
                           "--tangential-amp", "2", "--phase", "0,1.2,4.2", "--format", "json"))["rows"]
    rows = {k: [float(r[k]) for r in exact] for k in ("vhat", "amp", "tangential_amp", "phase")}
    rows["mu_ratio"] = [float(r["mu_ratio"]) + 1e-7 * (-1) ** i for i, r in enumerate(exact)]
    path = ROOT / "target" / "py-combined-ok.csv"
    path.parent.mkdir(exist_ok=True)
    names = list(rows)
    path.write_text(",".join(names) + "\n" + "".join(",".join(repr(rows[n][i]) for n in names) + "\n" for i in range(len(exact))))
    expected = json.loads(cli("validate", "--shape", "parabolic", str(path), "--format", "json"))
    expected.pop("format")
    got = fricosc.validate(rows, "parabolic")
    assert json.loads(json.dumps(got)) == expected
    assert 0.9e-7 < got["max_abs_error"] < 1.1e-7 and got["findings"] == []
    with pytest.raises(fricosc.InputError, match="only a single table's validate compares it"):
        fricosc.validate_series({100: rows, 200: rows}, "parabolic")
    cli_message = cli_error("validate", "--series", "--shape", "parabolic", f"{path}@100", f"{path}@200")
    assert "only a single table's validate compares it" in cli_message


def test_scene_is_the_command_lines() -> None:
    """Every example scene through Python (from its path, and as a dict where it
    names no file) gives `fricosc scene`'s JSON."""
    for path in sorted((ROOT / "data" / "scenes").glob("*.json")):
        expected = json.loads(cli("scene", str(path), "--format", "json"))
        assert fricosc.scene(str(path)) == expected, path.name
        spec = json.loads(path.read_text())
        if "profile" not in spec["indenter"]:
            assert fricosc.scene(spec) == expected, path.name
    with pytest.raises(ValueError, match="unknown field"):
        fricosc.scene({"mu0": 0.4, "colour": "red"})
    with pytest.raises(ValueError, match="cannot read"):
        fricosc.scene("/nonexistent/scene.json")
    with pytest.raises(TypeError, match="a scene is a dict"):
        fricosc.scene(42)  # type: ignore[arg-type]


def test_validate_history_is_the_command_lines() -> None:
    """A stepped history (the built-in peer) through Python and through
    `fricosc validate --history`: the same report; a time column with the period
    found from the normal force gives the same events."""
    text = cli("history", "--method", "stepping", "--steps-per-period", "500", "--periods", "3",
               "--vbar", "0.3", "--amp", "1.5", "--format", "csv")
    path = ROOT / "target" / "py-stepped-history.csv"
    path.parent.mkdir(exist_ok=True)
    path.write_text(text)
    expected = json.loads(cli("validate", "--history", str(path), "--vbar", "0.3", "--amp", "1.5", "--format", "json"))
    rows = csv_rows(text)
    cols = {k: np.array([float(r[k]) for r in rows]) for k in ("tau", "normal", "tangential")}
    got = fricosc.validate_history(cols, 0.3, 1.5)
    assert json.loads(json.dumps(got)) == json.loads(json.dumps(expected))
    assert [e["kind"] for e in got["events"]] == ["contact", "stick", "slip", "loss_of_contact"]
    timed = fricosc.validate_history({"t": cols["tau"] / 100.0, "normal": cols["normal"], "tangential": cols["tangential"]},
                                     vhat=0.45, amp=1.5)
    assert [e["kind"] for e in timed["events"]] == [e["kind"] for e in got["events"]]
    with pytest.raises(ValueError, match="one time column"):
        fricosc.validate_history({"tangential": [0.0]}, 0.3, 1.5)


USER = ROOT / "data" / "user-stepper"


def test_user_stepper_files_are_what_the_script_writes(tmp_path: pathlib.Path) -> None:
    """data/user-stepper/ is the output of examples/user_stepper.py (its numbers
    to 1e-12: numpy's cosine may differ in the last bits between machines)."""
    import sys

    script = ROOT / "src" / "python" / "examples" / "user_stepper.py"
    subprocess.run([sys.executable, str(script), "--out", str(tmp_path)], check=True, capture_output=True)
    for committed in sorted(USER.iterdir()):
        fresh = tmp_path / committed.name
        if committed.suffix == ".json":
            a, b = json.loads(committed.read_text()), json.loads(fresh.read_text())
            assert a.keys() == b.keys()
            for k in a:
                assert np.allclose(list(a[k].values()), list(b[k].values()), rtol=1e-12, atol=0), committed.name
        else:
            x = np.loadtxt(committed, delimiter=",", comments="#", skiprows=0 if committed.read_text().startswith("#") else 1)
            y = np.loadtxt(fresh, delimiter=",", comments="#", skiprows=0 if fresh.read_text().startswith("#") else 1)
            assert np.allclose(x, y, rtol=1e-12, atol=1e-300), committed.name


def test_validate_series_is_the_command_lines() -> None:
    """The cut-off springs' series through Python (tables read by numpy) and
    through `fricosc validate --series`: the same report, the same findings."""
    files = [USER / f"parabolic-cutoff@{m}.csv" for m in (250, 500, 1000)]
    expected = json.loads(cli("validate", "--series", "--shape", "parabolic", "--target", "1e-6", "--format", "json",
                              *map(str, files), status=1))
    tables = {}
    for m, f in zip((250, 500, 1000), files):
        d = np.loadtxt(f, delimiter=",")
        tables[m] = {"vbar": d[:, 0], "amp": d[:, 1], "mu_ratio": d[:, 2]}
    got = fricosc.validate_series(tables, "parabolic", target=1e-6)
    assert json.loads(json.dumps(got)) == expected
    assert "resolution_independent" in [f["kind"] for f in got["findings"]]
    with pytest.raises(TypeError, match="mapping from each resolution"):
        fricosc.validate_series([1, 2])  # type: ignore[arg-type]


def test_validate_history_in_your_units_is_the_command_lines() -> None:
    """The numpy stepper's history in newtons (written u0 + du cos(omega t)):
    static_force and mu0 as --static-force and --mu0; the offset pi found."""
    omega = 2 * np.pi * 20e3
    path = USER / "history-flat.csv"
    expected = json.loads(cli("validate", "--history", str(path), "--vbar", "0.3", "--amp", "1.5", "--static-force", "2",
                              "--mu0", "0.3", "--omega", repr(omega), "--format", "json"))
    d = np.loadtxt(path, delimiter=",", skiprows=1)
    got = fricosc.validate_history({"t": d[:, 0], "normal": d[:, 1], "tangential": d[:, 2]}, 0.3, 1.5, omega=omega,
                                   static_force=2.0, mu0=0.3)
    assert json.loads(json.dumps(got)) == expected
    assert got["time_origin"]["offset"] == np.pi
    with pytest.raises(ValueError, match="static-force"):
        fricosc.validate_history({"t": d[:, 0], "tangential": d[:, 2]}, 0.3, 1.5, omega=omega, static_force=-1.0)


def test_oscillation_in_the_sliding_direction_is_the_command_lines() -> None:
    """``tangential_amp`` and ``phase``: the table's values bit for bit, the
    point's JSON, the 40-digit references, and T = 0 as the seed's problem."""
    text = cli(
        "table", "--shape", "parabolic", "--vhat", "0.1,0.6", "--amp", "0,1.5",
        "--tangential-amp", "0.5,3", "--phase", "0,2", "--format", "csv",
    )
    rows = csv_rows(text)
    assert len(rows) == 16
    v, a, t, p = (np.array([float(r[k]) for r in rows]) for k in ("vhat", "amp", "tangential_amp", "phase"))
    got = np.asarray(fricosc.mu_ratio("parabolic", vhat=v, amp=a, tangential_amp=t, phase=p))
    assert got.tolist() == [float(r["mu_ratio"]) for r in rows]
    red = np.asarray(fricosc.reduction("parabolic", vhat=v, amp=a, tangential_amp=t, phase=p))
    assert red.tolist() == [float(r["reduction"]) for r in rows]
    assert got.min() < 0 and red.max() > 1  # the ratchet, allowed
    point = json.loads(cli("point", "--vhat", "0.6", "--amp", "2", "--tangential-amp", "3", "--phase", "1"))
    assert fricosc.point("flat", vhat=0.6, amp=2.0, tangential_amp=3.0, phase=1.0) == point
    reference = json.loads((ROOT / "data" / "combined-reference.json").read_text())
    for case in reference["cases"]:
        mu = float(
            fricosc.mu_ratio(
                "flat", vhat=case["vhat"], amp=case["amp"], tangential_amp=case["tangential_amp"], phase=case["phase"]
            )
        )
        assert abs(Decimal(mu) - Decimal(case["mu_ratio"])) < Decimal("1e-14"), case
    # No tangential oscillation: the seed's problem, bit for bit.
    assert fricosc.mu_ratio("cone", vhat=0.3, amp=0.7, tangential_amp=0.0, phase=2.0) == fricosc.mu_ratio(
        "cone", vhat=0.3, amp=0.7
    )


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: fricosc.mu_ratio("flat", 0.3, 0.5, tangential_amp=1.0), "tangential_amp needs the velocity as vhat"),
        (lambda: fricosc.mu_ratio("flat", vhat=0.3, amp=0.5, phase=1.0), "phase needs tangential_amp"),
        (lambda: fricosc.mu_ratio("flat", vhat=0.3, amp=0.5, tangential_amp=math.nan), "tangential-amp"),
        (lambda: fricosc.mu_ratio("flat", vhat=0.3, amp=0.5, tangential_amp=-1.0), "tangential-amp"),
        (lambda: fricosc.mu_ratio("flat", vhat=0.3, amp=0.5, tangential_amp=1.0, phase=math.inf), "phase"),
        (lambda: fricosc.point("flat", vhat=0.3, amp=0.5, tangential_amp=2e6), "1e6"),
    ],
)
def test_bad_oscillation_input(call: Callable[[], object], message: str) -> None:
    with pytest.raises((TypeError, fricosc.InputError), match=message):
        call()


def test_point_on_a_system_is_the_command_lines() -> None:
    """``point(system_stiffness=...)``: the same attractor as ``fricosc point --system-stiffness``."""
    mine = fricosc.point("flat", vhat=0.3, amp=0.5, system_stiffness=1.0, frequency_ratio=0.5, damping=0.3)
    theirs = json.loads(cli("point", "--vhat", "0.3", "--amp", "0.5", "--system-stiffness", "1",
                            "--frequency-ratio", "0.5", "--damping", "0.3"))
    assert mine["mu_ratio"] == theirs["mu_ratio"] and mine["period"] == theirs["period"] == 1
    assert mine["regime"] == theirs["regime"] == "period 1" and mine["reduction"] == theirs["reduction"]
    assert mine["error_estimate"] == theirs["error_estimate"]
    assert [list(m) for m in mine["multipliers"]] == theirs["multipliers"]
    cone = fricosc.point("cone", vhat=0.3, amp=0.5, system_stiffness=1.0, frequency_ratio=0.5, springs=32)
    theirs = json.loads(cli("point", "--shape", "cone", "--vhat", "0.3", "--amp", "0.5", "--system-stiffness", "1",
                            "--frequency-ratio", "0.5", "--springs", "32"))
    assert cone["mu_ratio"] == theirs["mu_ratio"] and cone["error_estimate"] == theirs["error_estimate"]
    with pytest.raises(fricosc.InputError, match="massless"):
        fricosc.point("parabolic", vhat=0.3, amp=0.5, system_stiffness=1.0)
    # Keywords that do not apply are refused, not ignored.
    with pytest.raises(fricosc.InputError, match="frequency_ratio applies only with system_stiffness"):
        fricosc.point("flat", 0.3, 0.5, frequency_ratio=0.5)
    with pytest.raises(fricosc.InputError, match="damping applies only with system_stiffness"):
        fricosc.history("flat", 0.3, 0.5, damping=0.1)
    with pytest.raises(fricosc.InputError, match="frequency_ratio applies only"):
        fricosc.validate({"vbar": [0.3], "amp": [0.5], "mu_ratio": [0.8]}, frequency_ratio=0.5)
    with pytest.raises(fricosc.InputError, match="springs applies only with system_stiffness"):
        fricosc.point("cone", 0.3, 0.5, springs=64)
    with pytest.raises(fricosc.InputError, match="tol does not apply on a system"):
        fricosc.point("cone", 0.3, 0.5, system_stiffness=1.0, frequency_ratio=0.5, tol=1e-6)
    table = {"vbar": [0.1, 0.5], "amp": [0.5, 0.5], "mu_ratio": [0.6, 0.9]}
    mine_v = fricosc.validate(table, system_stiffness=1.0, frequency_ratio=0.5, damping=0.3)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "t.csv")
        with open(path, "w") as f:
            f.write("vbar,amp,mu_ratio\n0.1,0.5,0.6\n0.5,0.5,0.9\n")
        theirs_v = json.loads(cli("validate", path, "--system-stiffness", "1", "--frequency-ratio", "0.5",
                                  "--damping", "0.3", "--format", "json", "--report-only"))
    assert [r["exact"] for r in mine_v["rows"]] == [r["exact"] for r in theirs_v["rows"]]
    assert mine_v["system"]["stiffness"] == 1.0 and [r["period"] for r in mine_v["rows"]] == [1, 1]
    assert mine_v["by_regime"][0]["regime"] == "permanent_contact"
    curved = fricosc.history("cone", vhat=0.3, amp=0.5, system_stiffness=1.0, frequency_ratio=0.5, samples=8)
    body = json.loads(cli("history", "--shape", "cone", "--vhat", "0.3", "--amp", "0.5", "--system-stiffness", "1",
                          "--frequency-ratio", "0.5", "--samples", "8"))
    for key in ("body_lag", "body_velocity", "system_force"):
        assert curved[key].tolist() == [s[key] for s in body["samples"]], key
    csv_text = cli("history", "--shape", "cone", "--vhat", "0.3", "--amp", "0.5", "--system-stiffness", "1",
                   "--frequency-ratio", "0.5", "--samples", "8", "--format", "csv")
    assert [float(r["tangential"]) for r in csv_rows(csv_text)] == list(curved["tangential"])
    h = fricosc.history("flat", vhat=0.3, amp=0.5, system_stiffness=1.0, frequency_ratio=0.5, damping=0.3, samples=8)
    csv_text = cli("history", "--vhat", "0.3", "--amp", "0.5", "--system-stiffness", "1", "--frequency-ratio", "0.5",
                   "--damping", "0.3", "--samples", "8", "--format", "csv")
    assert [float(r["tangential"]) for r in csv_rows(csv_text)] == list(h["tangential"])


def test_fit_is_the_command_lines() -> None:
    """``fit(table)``: the exact synthetic rows' parameters back (as ``fricosc fit``, bit for bit),
    a DataFrame as a dict, a held parameter, a missing column named."""
    pd = pytest.importorskip("pandas")
    path = ROOT / "data" / "fit-synthetic-flat.csv"
    frame = pd.read_csv(path)
    mine = fricosc.fit(frame)
    theirs = json.loads(cli("fit", str(path), "--format", "json"))
    for name in mine.names:
        assert mine.params[name] == theirs["parameters"][name]["value"]
        assert mine.stderr[name] == theirs["parameters"][name]["stderr"]
    assert abs(mine.params["stiffness_ratio"] / 0.8 - 1) < 1e-7 and mine.dof == 24 and mine.cov.shape == (3, 3)
    held = fricosc.fit({k: frame[k].to_numpy() for k in frame.columns}, "flat", mu0=0.35)
    assert held.stderr["mu0"] == 0.0 and held.dof == 25
    with pytest.raises(fricosc.InputError, match="'du'"):
        fricosc.fit({"v0": [1.0], "frequency": [1.0], "mu": [0.3]})
    example = pd.read_csv(ROOT / "data" / "fit-example.csv")
    wrong = fricosc.fit(example, mu0=0.3)
    theirs = json.loads(cli("fit", str(ROOT / "data" / "fit-example.csv"), "--mu0", "0.3", "--format", "json", status=1))
    assert wrong.verdicts == theirs["verdicts"]
    assert wrong.p_value == theirs["p_value"] and wrong.p_value is not None and wrong.p_value < 0.01
    assert "likely: the held mu0 = 0.3" in wrong.verdicts[0] and wrong.converged and wrong.notes == []
    # The outlier threshold of 27 rows (mpmath: sqrt(2) erfinv(1 - 0.01/27)), as the command line's.
    assert wrong.outlier_threshold == theirs["outlier_threshold"] and abs(wrong.outlier_threshold - 3.5603432) < 1e-7
    with pytest.raises(fricosc.InputError, match="did you mean 'sigma'"):
        fricosc.fit(example.rename(columns={"sigma": "Sigma"}))
    rig = fricosc.fit(frame, system_stiffness=1.0, frequency_ratio=0.5, damping=0.3)
    theirs = json.loads(cli("fit", str(path), "--system-stiffness", "1", "--frequency-ratio", "0.5", "--damping", "0.3",
                            "--format", "json", status=1 if rig.verdicts else 0))
    assert rig.params["mu0"] == theirs["parameters"]["mu0"]["value"] and rig.chi2 == theirs["chi2"]
    assert rig.names == ["mu0", "stiffness_ratio", "u0", "system_stiffness"] and rig.stderr["system_stiffness"] == 0.0
    # Load control: a load column (N); u0 at the median load, as the command line's.
    loaded = ROOT / "data" / "fit-synthetic-load.csv"
    mine = fricosc.fit(pd.read_csv(loaded))
    theirs = json.loads(cli("fit", str(loaded), "--format", "json"))
    assert mine.reference_load == theirs["reference_load"] == 1.0
    assert all(mine.params[k] == theirs["parameters"][k]["value"] for k in mine.names)
    assert abs(mine.params["u0"] / 1e-6 - 1) < 1e-7 and frame.shape[0] == 27
    # Bounds, as --bound: mu0 kept below its truth rests on the bound, named.
    bound = fricosc.fit(frame, bounds={"mu0": (0.1, 0.3)})
    theirs = json.loads(cli("fit", str(path), "--bound", "mu0=0.1:0.3", "--format", "json", status=1))
    assert bound.verdicts == theirs["verdicts"] and bound.params["mu0"] == 0.3 and bound.stderr["mu0"] is None
    with pytest.raises(fricosc.InputError, match="fit's parameters are"):
        fricosc.fit(frame, bounds={"mu": (0.1, 0.3)})
