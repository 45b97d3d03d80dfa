"""The plane from Python: ``point(..., transverse_amp=, transverse_phase=)``
is ``fricosc point --transverse-amp`` bit for bit, ``transverse_amp=0`` the
point without it, and bad input is refused by name."""
import json
from typing import Any, Dict

import numpy as np
import pytest

import fricosc
from test_fricosc import cli


def _cli(*args: str) -> Dict[str, Any]:
    result: Dict[str, Any] = json.loads(cli("point", *args))
    return result


def test_point_is_the_command_lines() -> None:
    p = fricosc.point("flat", vhat=0.1, amp=0.8, tangential_amp=1.0, phase=0.3, transverse_amp=0.8, transverse_phase=2.0)
    q = _cli("--vhat", "0.1", "--amp", "0.8", "--tangential-amp", "1", "--phase", "0.3",
             "--transverse-amp", "0.8", "--transverse-phase", "2")
    for key in ["mu_ratio", "transverse_ratio", "error_estimate", "multiplier", "events", "transverse_amp"]:
        assert p[key] == q[key], key
    # The transverse drive alone, at vbar = 0 of no normal oscillation: vhat.
    alone = fricosc.point("flat", vhat=0.05, amp=0.0, transverse_amp=2.0)
    assert abs(alone["transverse_ratio"]) < 1e-15 and 0.0 < alone["mu_ratio"] < 1.0


def test_history_is_the_command_lines() -> None:
    h = fricosc.history("flat", vhat=0.2, amp=1.4, transverse_amp=0.8, transverse_phase=2.0, samples=50, periods=2)
    q = json.loads(cli("history", "--vhat", "0.2", "--amp", "1.4", "--transverse-amp", "0.8",
                       "--transverse-phase", "2", "--samples", "50", "--periods", "2"))
    assert [s["transverse"] for s in q["samples"]] == list(h["transverse"])
    assert [s["tangential"] for s in q["samples"]] == list(h["tangential"])
    assert [s.get("event") for s in q["samples"]] == h["event"]
    assert (h["transverse_amp"], h["transverse_phase"]) == (0.8, 2.0)
    plain = fricosc.history("flat", 0.3, 0.5, samples=20)
    zero = fricosc.history("flat", 0.3, 0.5, samples=20, transverse_amp=0.0)
    assert "transverse" not in zero and list(zero["tangential"]) == list(plain["tangential"])
    cone = fricosc.history("cone", vhat=0.2, amp=0.5, transverse_amp=1.0, samples=10, springs=50)
    q = json.loads(cli("history", "--shape", "cone", "--vhat", "0.2", "--amp", "0.5", "--transverse-amp", "1",
                       "--samples", "10", "--springs", "50"))
    assert [s["transverse"] for s in q["samples"]] == list(cone["transverse"])
    with pytest.raises(fricosc.InputError, match="spring-at"):
        fricosc.history("parabolic", vhat=0.2, amp=0.5, transverse_amp=1.0, spring_at=(0.5,))


def test_no_transverse_amplitude_is_the_point_without_it() -> None:
    assert fricosc.point("flat", 0.3, 0.5, transverse_amp=0.0) == fricosc.point("flat", 0.3, 0.5)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"transverse_amp": -1.0}, "transverse-amp"),
        ({"transverse_amp": float("nan")}, "transverse-amp"),
        ({"transverse_amp": 1.0, "transverse_phase": 2e6}, "transverse-phase"),
        ({"transverse_amp": 1.0, "system_stiffness": 1.0}, "system_stiffness"),
    ],
)
def test_bad_input_is_named(kwargs: Dict[str, Any], name: str) -> None:
    with pytest.raises(fricosc.InputError, match=name):
        fricosc.point("flat", vhat=0.3, amp=0.5, **kwargs)
    with pytest.raises(TypeError, match="transverse_phase needs transverse_amp"):
        fricosc.point("flat", vhat=0.3, amp=0.5, transverse_phase=1.0)


def test_curved_shapes_are_the_command_lines() -> None:
    p = fricosc.point("cone", vhat=0.3, amp=1.5, transverse_amp=1.0, transverse_phase=0.7)
    q = _cli("--shape", "cone", "--vhat", "0.3", "--amp", "1.5", "--transverse-amp", "1", "--transverse-phase", "0.7")
    for key in ["mu_ratio", "transverse_ratio", "error_estimate"]:
        assert p[key] == q[key], key


def test_mu_ratio_in_the_plane_is_the_point_at_every_element() -> None:
    ws = np.array([0.0, 0.5, 1.2, 3.0])
    got = np.asarray(fricosc.mu_ratio("flat", vhat=0.3, amp=0.5, tangential_amp=0.4, phase=0.2, transverse_amp=ws, transverse_phase=[[0.7], [2.0]]))
    assert got.shape == (2, 4)
    for i, psi in enumerate([0.7, 2.0]):
        for j, w in enumerate(ws):
            p = fricosc.point("flat", vhat=0.3, amp=0.5, tangential_amp=0.4, phase=0.2, transverse_amp=float(w), transverse_phase=psi)
            assert got[i, j] == p["mu_ratio"], (psi, w)
    red = fricosc.reduction("cone", vhat=0.3, amp=1.5, transverse_amp=1.0, transverse_phase=0.7)
    assert red == fricosc.point("cone", vhat=0.3, amp=1.5, transverse_amp=1.0, transverse_phase=0.7)["reduction"]
    with pytest.raises(fricosc.InputError, match="transverse-amp"):
        fricosc.mu_ratio("flat", vhat=0.3, amp=0.5, transverse_amp=[1.0, -1.0])
    with pytest.raises(fricosc.InputError, match="system_stiffness"):
        fricosc.mu_ratio("flat", vhat=0.3, amp=0.5, transverse_amp=1.0, system_stiffness=1.0)
    with pytest.raises(TypeError, match="transverse_phase needs transverse_amp"):
        fricosc.mu_ratio("flat", vhat=0.3, amp=0.5, transverse_phase=1.0)


def test_validate_reads_a_table_in_the_plane_as_the_command_line(tmp_path: Any) -> None:
    """A table in the plane (``transverse_amp``, ``transverse_phase``,
    ``transverse_ratio``) off across by 1e-6: Python reads and compares it as
    ``fricosc validate`` does (the same report), the force across compared."""
    p = fricosc.point("flat", vhat=0.3, amp=1.5, transverse_amp=1.2, transverse_phase=0.7)
    rows = {"vhat": [0.3], "amp": [1.5], "transverse_amp": [1.2], "transverse_phase": [0.7],
            "mu_ratio": [p["mu_ratio"]], "transverse_ratio": [p["transverse_ratio"] + 1e-6]}
    path = tmp_path / "plane.csv"
    path.write_text(",".join(rows) + "\n" + ",".join(repr(v[0]) for v in rows.values()) + "\n")
    expected = json.loads(cli("validate", str(path), "--format", "json"))
    expected.pop("format")
    got = fricosc.validate(rows)
    assert json.loads(json.dumps(got)) == expected
    assert 0.99e-6 < got["transverse"]["max_abs_error"] < 1.01e-6 and got["max_abs_error"] == 0.0


def test_validate_history_in_the_plane_is_the_command_lines(tmp_path: Any) -> None:
    """A history in the plane with its force across negated: Python's report is ``fricosc validate --history
    --transverse-amp``'s, the force across compared; its ``transverse``
    column without ``transverse_amp`` is refused by name."""
    h = fricosc.history("flat", vhat=0.3, amp=0.5, transverse_amp=1.2, transverse_phase=0.7, samples=100, periods=2)
    cols = {k: np.asarray(h[k]) for k in ("tau", "normal", "tangential", "transverse")}
    cols["transverse"] = -cols["transverse"]
    path = tmp_path / "plane-history.csv"
    path.write_text("tau,normal,tangential,transverse\n" + "".join(
        f"{t!r},{n!r},{x!r},{y!r}\n" for t, n, x, y in zip(*(cols[k].tolist() for k in cols))))
    expected = json.loads(cli("validate", "--history", str(path), "--vhat", "0.3", "--amp", "0.5",
                              "--transverse-amp", "1.2", "--transverse-phase", "0.7", "--format", "json", status=1))
    got = fricosc.validate_history(cols, vhat=0.3, amp=0.5, transverse_amp=1.2, transverse_phase=0.7)
    assert json.loads(json.dumps(got)) == expected
    assert got["transverse"]["max_abs_error"] > 0.1 and got["findings"]
    with pytest.raises(fricosc.InputError, match="transverse"):
        fricosc.validate_history(cols, vhat=0.3, amp=0.5)
