"""A researcher's own numpy time stepper, with the bugs researchers make
planted one at a time, validated through the Python package and through the
command line: each bug must be named (its finding, exit 1), the correct
stepper must pass (no finding, exit 0), and both ways in must agree.

The stepper is the seed's scheme (the force moves with the body, is held
within its Coulomb bound, and is 0 out of contact), written here in numpy
independently of fricosc, for the normal oscillation and for both
oscillations with a phase (the body at ``vhat tau + T sin(tau + phase)``).
"""

from __future__ import annotations

import csv
import json
import math
import pathlib
from typing import Any, Dict, List, Optional

import numpy as np
import numpy.typing as npt
import pytest

import fricosc
from test_fricosc import cli

TAU = 2 * math.pi
Array = npt.NDArray[np.float64]


def step_table(
    vhat: Array,
    amp: Array,
    t: float = 0.0,
    phase: float = 0.0,
    *,
    steps: int = 1000,
    periods: int = 3,
    contact_loss: bool = True,
) -> Array:
    """mu_macro/mu0 of the flat punch by time stepping, every row at once:
    the last of ``periods`` periods, started sliding (the force on its bound).
    ``contact_loss=False`` plants the bug: the normal force may go negative."""
    h = TAU / steps
    bound0 = 1 - amp
    f = np.maximum(bound0, 0) if contact_loss else bound0.copy()
    for _ in range(periods):
        sum_f, sum_n = np.zeros_like(f), np.zeros_like(f)
        for k in range(1, steps + 1):
            a, b = h * (k - 1), h * k
            dx = vhat * h + 2 * t * math.cos(0.5 * (a + b) + phase) * math.sin(0.5 * h)
            bound = 1 - amp * math.cos(b)
            if contact_loss:
                bound = np.maximum(bound, 0)
            f = np.clip(f + dx, -np.abs(bound), bound) if t > 0 else np.minimum(f + dx, bound)
            sum_f += f
            sum_n += bound
    return np.asarray(sum_f / sum_n)


def step_history(
    vbar: float, amp: float, *, steps: int = 1000, periods: int = 3, relax: bool = True, contact_loss: bool = True
) -> Dict[str, Array]:
    """The flat punch's force history by the same scheme: columns ``tau``,
    ``normal``, ``tangential`` (units ``F0``, ``mu0 F0``). ``relax=False``
    plants a spring that keeps its force out of contact; ``contact_loss=False``
    one that never leaves contact."""
    h = TAU / steps
    n = steps * periods + 1
    tau = h * np.arange(n)
    normal = 1 - amp * np.cos(tau)
    if contact_loss:
        normal = np.maximum(normal, 0)
    tangential = np.empty(n)
    f = normal[0]
    for k in range(n):
        if k > 0:
            if normal[k] > 0 or not contact_loss:
                f = min(f + amp * vbar * h, normal[k])
            elif relax:
                f = 0.0
        tangential[k] = f
    return {"tau": tau, "normal": normal, "tangential": tangential}


def write_csv(path: pathlib.Path, columns: Dict[str, Any]) -> str:
    names = list(columns)
    with path.open("w", newline="") as out:
        w = csv.writer(out)
        w.writerow(names)
        for row in zip(*(np.asarray(columns[c]) for c in names)):
            w.writerow([repr(float(x)) for x in row])
    return str(path)


def kinds(report: Dict[str, Any]) -> List[str]:
    return [f["kind"] for f in report["findings"]]


def both(
    tmp_path: pathlib.Path, columns: Dict[str, Any], *args: str, history: Optional[Dict[str, Any]] = None
) -> Dict[str, Any]:
    """The report of the Python package, checked against the command line's
    (the same findings and largest error, exit 1 exactly when it has findings)."""
    if history is None:
        mine = fricosc.validate(columns)
    else:
        mine = fricosc.validate_history(columns, **history)
    path = write_csv(tmp_path / "run.csv", columns)
    theirs = json.loads(cli("validate", path, *args, "--format", "json", status=1 if mine["findings"] else 0))
    assert kinds(theirs) == kinds(mine)
    assert theirs["max_abs_error"] == mine["max_abs_error"]
    return mine


VBAR = np.array([0.1, 0.3, 0.6, 0.9] * 4)
AMP = np.repeat([0.5, 0.8, 1.2, 1.5], 4)


def test_the_correct_stepper_passes(tmp_path: pathlib.Path) -> None:
    table = {"vbar": VBAR, "amp": AMP, "mu_ratio": step_table(VBAR * AMP, AMP)}
    r = both(tmp_path, table)
    assert kinds(r) == [] and r["max_abs_error"] < 1e-3


def test_a_contact_never_opened_is_named(tmp_path: pathlib.Path) -> None:
    table = {"vbar": VBAR, "amp": AMP, "mu_ratio": step_table(VBAR * AMP, AMP, contact_loss=False)}
    r = both(tmp_path, table)
    assert "contact_loss" in kinds(r), kinds(r)
    # Only the rows where the contact opens (du/u0 > 1) are named.
    loss = next(f for f in r["findings"] if f["kind"] == "contact_loss")
    assert all(AMP[i] > 1 for i in loss["rows"])


def test_a_converged_first_order_run_is_not_called_unsteady(tmp_path: pathlib.Path) -> None:
    """amp 1.2 at 10 and 100 periods: the same first-order errors (stick-first
    springs), not a transient."""
    v = np.array([0.02, 0.05, 0.1, 0.3, 0.6, 0.9])
    a = np.full_like(v, 1.2)
    runs = [step_table(v * a, a, steps=500, periods=p) for p in (10, 100)]
    assert np.max(np.abs(runs[0] - runs[1])) < 1e-12
    for peer in (None, 500):
        r = fricosc.validate({"vbar": v, "amp": a, "mu_ratio": runs[1]}, peer=peer)
        assert kinds(r) == [], r["findings"]
    both(tmp_path, {"vbar": v, "amp": a, "mu_ratio": runs[1]})


def combined(phase: float) -> Dict[str, Any]:
    """A combined table at vhat 0.05 to 1, amp 0.5, T 1.5, phase 1.3, stepped with ``phase``."""
    v = np.array([0.05, 0.2, 0.5, 1.0])
    n = len(v)
    amp = np.full(n, 0.5)
    mu = step_table(v, amp, 1.5, phase, steps=2000)
    return {"vhat": v, "amp": amp, "tangential_amp": np.full(n, 1.5), "phase": np.full(n, 1.3), "mu_ratio": mu}


def test_a_combined_stepper_validates_and_its_phase_sign_bug_is_named(tmp_path: pathlib.Path) -> None:
    good = both(tmp_path, combined(1.3))
    assert kinds(good) == [] and good["max_abs_error"] < 1e-3
    bad = both(tmp_path, combined(-1.3))
    assert kinds(bad) == ["convention"] and "-phase" in bad["findings"][0]["hint"]


def test_history_bugs_are_named_by_what_the_data_shows(tmp_path: pathlib.Path) -> None:
    at = {"vbar": 0.3, "amp": 1.5}
    args = ("--history", "--vbar", "0.3", "--amp", "1.5")
    assert kinds(both(tmp_path, step_history(0.3, 1.5), *args, history=at)) == []
    assert "force_out_of_contact" in kinds(both(tmp_path, step_history(0.3, 1.5, relax=False), *args, history=at))
    assert "negative_normal" in kinds(both(tmp_path, step_history(0.3, 1.5, contact_loss=False), *args, history=at))


def test_a_combined_history_is_validated_and_its_phase_sign_bug_named(tmp_path: pathlib.Path) -> None:
    """The command line's own stepped history (``history --method stepping``)
    is the researcher's file here; with ``-phase`` it is the bug."""
    osc = {"vhat": 0.2, "amp": 0.5, "tangential_amp": 1.5, "phase": 1.3}
    args = ("--history", "--vhat", "0.2", "--amp", "0.5", "--tangential-amp", "1.5", "--phase", "1.3")
    for phase, expected in ((1.3, []), (-1.3, ["convention"])):
        step = ("--method", "stepping", "--steps-per-period", "2000", "--periods", "3", "--format", "json")
        h = json.loads(cli("history", "--vhat", "0.2", "--amp", "0.5", "--tangential-amp", "1.5", "--phase", str(phase), *step))
        columns = {k: np.array([s[k] for s in h["samples"]]) for k in ("tau", "normal", "tangential")}
        r = both(tmp_path, columns, *args, history=osc)
        assert kinds(r) == expected, r["findings"]
    exact = fricosc.history("flat", vhat=0.2, amp=0.5, tangential_amp=1.5, phase=1.3, samples=2000, periods=2)
    columns = {k: exact[k] for k in ("tau", "normal", "tangential")}
    r = fricosc.validate_history(columns, vhat=0.2, amp=0.5, tangential_amp=1.5, phase=1.3)
    assert kinds(r) == [] and r["max_abs_error"] < 1e-14


def test_a_series_with_an_exact_row_converges(tmp_path: pathlib.Path) -> None:
    """A row exact at every resolution (vbar >= 1: mu = 1) beside converging
    rows: not ``not_converging``."""
    v = np.array([1.2, 0.3, 0.6])
    a = np.full_like(v, 0.5)
    tables = {m: {"vbar": v, "amp": a, "mu_ratio": step_table(v * a, a, steps=m)} for m in (100, 200, 400, 800)}
    r = fricosc.validate_series(tables)
    assert "not_converging" not in kinds(r), r["findings"]
    paths = [f"{write_csv(tmp_path / f'run{m}.csv', t)}@{m}" for m, t in tables.items()]
    theirs = json.loads(cli("validate", "--series", *paths, "--format", "json", status=1 if r["findings"] else 0))
    assert kinds(theirs) == kinds(r)

