"""The example stepper of the pin on its system spring
(``examples/system_stepper.py``, numpy, written from the model's equation
alone) with each of its planted mistakes, validated through the Python
package and the command line on the system it was meant to solve: each
mistake named by its finding (exit 1), the correct stepper passing (no
finding, exit 0), the table without the system flags hinted at the system,
and both ways in giving the same report.
"""

from __future__ import annotations

import importlib.util
import json
import pathlib
from typing import Any, Dict, List

import numpy as np
import pytest

import fricosc
from test_fricosc import ROOT, cli

SPEC = importlib.util.spec_from_file_location("system_stepper", ROOT / "src/python/examples/system_stepper.py")
assert SPEC is not None and SPEC.loader is not None
STEPPER: Any = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(STEPPER)
SYSTEM = {"system_stiffness": STEPPER.KAPPA, "frequency_ratio": STEPPER.OMEGA, "damping": STEPPER.ZETA}
FLAGS = ["--system-stiffness", "1", "--frequency-ratio", "0.8", "--damping", "0.05"]


def table(bug: str) -> Dict[str, Any]:
    vbar, amp = (np.array(x, dtype=float) for x in zip(*[(v, a) for a in STEPPER.AMPS for v in STEPPER.VBARS]))
    return {"vbar": vbar, "amp": amp, "mu_ratio": STEPPER.step_table(vbar, amp, bug)}


def both(tmp_path: pathlib.Path, columns: Dict[str, Any], system: bool = True) -> Dict[str, Any]:
    """The package's report, checked against the command line's: the same
    findings with the same rows and hints, the same largest error, exit 1
    exactly on findings."""
    mine = fricosc.validate(columns, **(SYSTEM if system else {}))
    path = tmp_path / "run.csv"
    rows = zip(*(np.asarray(columns[c]) for c in columns))
    path.write_text(",".join(columns) + "\n" + "".join(",".join(repr(float(x)) for x in r) + "\n" for r in rows))
    args = FLAGS if system else []
    theirs = json.loads(cli("validate", str(path), *args, "--format", "json", status=1 if mine["findings"] else 0))
    assert theirs["findings"] == mine["findings"]
    assert theirs["max_abs_error"] == mine["max_abs_error"] or np.isnan(mine["max_abs_error"])
    return mine


def kinds(report: Dict[str, Any]) -> List[str]:
    return [f["kind"] for f in report["findings"]]


def test_the_correct_system_stepper_passes(tmp_path: pathlib.Path) -> None:
    r = both(tmp_path, table("none"))
    assert kinds(r) == [] and r["max_abs_error"] < 1e-3, r["findings"]
    assert r["system"]["stiffness"] == 1.0 and all("period" in row for row in r["rows"])


@pytest.mark.parametrize(
    "bug, names",
    [
        ("no_damping", "the damping left out (zeta = 0)"),
        ("omega", "Omega where Omega^2 belongs in the mass term"),
        ("norm_by_one", "the static normal force"),
        ("few_periods", "a run of 15 periods"),
    ],
)
def test_each_planted_mistake_is_named(tmp_path: pathlib.Path, bug: str, names: str) -> None:
    r = both(tmp_path, table(bug))
    named = [f for f in r["findings"] if f["kind"] == "convention"]
    assert len(named) == 1 and names in named[0]["hint"], r["findings"]


def test_a_diverged_run_is_a_finding_on_its_rows(tmp_path: pathlib.Path) -> None:
    columns = table("spring_sign")
    assert np.isnan(columns["mu_ratio"]).all()
    r = both(tmp_path, columns)
    assert kinds(r) == ["diverged"] and r["findings"][0]["count"] == len(columns["vbar"])
    # One diverged row among good ones: the others are compared as usual.
    good = table("none")
    good["mu_ratio"][3] = np.inf
    r = both(tmp_path, good)
    assert kinds(r) == ["diverged"] and r["findings"][0]["rows"] == [3] and r["max_abs_error"] < 1e-3


def test_the_system_left_out_is_hinted(tmp_path: pathlib.Path) -> None:
    r = both(tmp_path, table("none"), system=False)
    hint = next(f["hint"] for f in r["findings"] if f["kind"] == "not_one_above_critical")
    assert "--system-stiffness" in hint
    # --damping forgotten (it is 0 unless given): errors of 5e-2 named, not silent.
    r = fricosc.validate(table("none"), system_stiffness=1.0, frequency_ratio=0.8)
    assert kinds(r) == ["large_errors"] and "--damping are 0 unless given" in r["findings"][0]["hint"]


def test_beyond_max_error_is_a_finding(tmp_path: pathlib.Path) -> None:
    columns = table("none")
    r = fricosc.validate(columns, max_error=1e-4, **SYSTEM)
    beyond = [f for f in r["findings"] if f["kind"] == "max_error"]
    assert len(beyond) == 1 and beyond[0]["count"] == sum(abs(x["error"]) > 1e-4 for x in r["rows"])
    assert beyond[0]["count"] > 0


def test_a_series_on_a_system_gives_the_steppers_order(tmp_path: pathlib.Path) -> None:
    """Semi-implicit Euler is first order: the median order of every regime
    that sticks is within 0.25 of 1 (observed 1.03 and 1.06), the command
    line agrees; with the damping left out the errors do not fall (a finding)."""
    def series(bug: str) -> Dict[float, Dict[str, Any]]:
        out = {}
        for m in (250, 500, 1000):
            t = table("none")
            t["mu_ratio"] = STEPPER.step_table(t["vbar"], t["amp"], bug, steps=m)
            out[float(m)] = t
        return out

    good = series("none")
    r = fricosc.validate_series(good, **SYSTEM)
    orders = {g["regime"]: g["median_order"] for g in r["by_regime"]}
    assert set(orders) == {"permanent_contact", "jumping"} and all(abs(p - 1) < 0.25 for p in orders.values()), orders
    assert r["findings"] == [] and r["system"]["damping"] == 0.05
    paths = []
    for m, t in good.items():
        path = tmp_path / f"run@{int(m)}.csv"
        rows = zip(t["vbar"], t["amp"], t["mu_ratio"])
        path.write_text("vbar,amp,mu_ratio\n" + "".join(f"{float(v)!r},{float(a)!r},{float(x)!r}\n" for v, a, x in rows))
        paths.append(str(path))
    theirs = json.loads(cli("validate", "--series", *paths, *FLAGS, "--format", "json"))
    assert [x["order"] for x in theirs["rows"]] == [x["order"] for x in r["rows"]]
    bad = fricosc.validate_series(series("no_damping"), **SYSTEM)
    assert bad["findings"], bad["by_regime"]


def history_both(tmp_path: pathlib.Path, h: Dict[str, Any], status: int) -> Dict[str, Any]:
    """The package's report on a history of the stepper (vbar 0.3, du/u0 0.5),
    the command line's the same (findings, largest error), exit ``status``."""
    mine = fricosc.validate_history(h, 0.3, 0.5, **SYSTEM)
    path = tmp_path / "history.csv"
    path.write_text(",".join(h) + "\n" + "".join(",".join(repr(float(x)) for x in r) + "\n" for r in zip(*h.values())))
    out = cli("validate", "--history", str(path), "--vbar", "0.3", "--amp", "0.5", *FLAGS, "--format", "json", status=status)
    theirs = json.loads(out)
    assert theirs["findings"] == mine["findings"] and theirs["max_abs_error"] == mine["max_abs_error"]
    return mine


def test_a_history_on_a_system_converges_to_the_attractor_with_its_body(tmp_path: pathlib.Path) -> None:
    """The stepper's history (force, the body's lag and velocity) tends to the
    exact period-1 attractor at the scheme's first order: at 1,000 and 2,000
    steps a period the force errs by 1.7e-4 and 8.4e-5, the body's lag by
    1.7e-4 and 8.5e-5, its velocity by 1.9e-3 and 9.3e-4; no finding."""
    errors = []
    for steps in (1000, 2000):
        r = history_both(tmp_path, STEPPER.step_history(0.3, 0.5, steps=steps), 0)
        assert r["findings"] == [] and r["periodic"], r["findings"]
        errors.append((r["max_abs_error"], r["body"]["lag_max_abs_error"], r["body"]["velocity_max_abs_error"]))
    assert errors[1][0] < 1e-3 and errors[1][1] < 1e-3 and errors[1][2] < 1e-2, errors
    assert all(1.7 < a / b < 2.3 for a, b in zip(*errors)), errors


def test_a_history_with_a_planted_mistake_is_named(tmp_path: pathlib.Path) -> None:
    """Omega for Omega^2: the history matches that system's attractor (7e-5
    against 9.6e-2 as read), named; the damping left out: the body's errors
    (3.6e-2 of a lag's range of 0.49) and a history that does not settle."""
    r = history_both(tmp_path, STEPPER.step_history(0.3, 0.5, "omega"), 1)
    named = [f["hint"] for f in r["findings"] if f["kind"] == "convention"]
    assert len(named) == 1 and "Omega where Omega^2 belongs" in named[0], r["findings"]
    r = history_both(tmp_path, STEPPER.step_history(0.3, 0.5, "no_damping"), 1)
    assert {"not_periodic", "large_errors"} <= set(kinds(r)), r["findings"]


def test_body_columns_need_a_body_with_mass() -> None:
    h = STEPPER.step_history(0.3, 0.5, steps=200, periods=3)
    with pytest.raises(fricosc.InputError, match="body columns"):
        fricosc.validate_history(h, 0.3, 0.5)
