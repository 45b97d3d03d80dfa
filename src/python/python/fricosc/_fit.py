"""``fricosc.fit``: the model fitted to measured friction (as ``fricosc fit``)."""

from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Tuple

import numpy as np
import numpy.typing as npt

from . import _fricosc
from ._api import InputError, ShapeLike, _column, _core, _floats, _scalar, _system


class FitResult:
    """The model fitted to measured friction (:func:`fit`): ``params`` and
    ``stderr`` (dicts by ``mu0``, ``stiffness_ratio``, ``u0`` and, on a
    system, ``system_stiffness``; a fixed parameter's stderr is 0, an
    undetermined one's None), ``names`` (their order), ``cov`` and
    ``correlation`` (arrays in that order), ``chi2``, ``dof``,
    ``reduced_chi2``, ``p_value`` (with sigma), ``residuals`` (``mu - model``
    per row), ``outliers`` (rows beyond ``outlier_threshold`` standard
    uncertainties: 3.5 up to 21 rows, growing to 5.7 at 10^6 rows),
    ``verdicts`` (what is wrong: a model that does not fit and its likely
    cause, what the rows cannot determine, no convergence), ``notes``,
    ``converged``, ``reference_load`` (N, under load control: where ``u0``
    is the static indentation) and ``report`` (the library's report as a dict)."""

    def __init__(self, report: Dict[str, Any]) -> None:
        self.report = report
        self.names: List[str] = [str(p["name"]) for p in report["parameters"]]
        self.params: Dict[str, float] = {p["name"]: float(p["value"]) for p in report["parameters"]}
        self.stderr: Dict[str, Optional[float]] = {p["name"]: p["stderr"] for p in report["parameters"]}
        self.cov: npt.NDArray[np.float64] = np.asarray(report["covariance"], dtype=np.float64)
        self.correlation: npt.NDArray[np.float64] = np.asarray(report["correlation"], dtype=np.float64)
        self.chi2: float = float(report["chi2"])
        self.dof: int = int(report["dof"])
        self.reduced_chi2: float = float(report["reduced_chi2"])
        self.residuals: npt.NDArray[np.float64] = np.asarray(report["residuals"], dtype=np.float64)
        self.verdicts: List[str] = list(report["verdicts"])
        self.notes: List[str] = list(report["notes"])
        self.p_value: Optional[float] = report["p_value"]
        self.outliers: List[int] = list(report["outliers"])
        self.outlier_threshold: float = float(report["outlier_threshold"])
        self.converged: bool = bool(report["converged"])
        self.reference_load: Optional[float] = report["reference_load"]

    def __repr__(self) -> str:
        return f"FitResult(params={self.params}, stderr={self.stderr}, reduced_chi2={self.reduced_chi2:.4g})"


def fit(
    table: Any,
    shape: ShapeLike = "flat",
    *,
    mu0: Optional[float] = None,
    stiffness_ratio: Optional[float] = None,
    u0: Optional[float] = None,
    system_stiffness: Optional[float] = None,
    frequency_ratio: Optional[float] = None,
    damping: Optional[float] = None,
    fit_system_stiffness: bool = False,
    bounds: Optional[Mapping[str, Tuple[float, float]]] = None,
) -> FitResult:
    """Fit the model to measured friction, as ``fricosc fit`` does: ``table``
    (a dict of arrays or a DataFrame) has the columns ``v0`` (m/s), ``du`` (m),
    ``frequency`` (Hz) or ``omega`` (rad/s), ``mu`` and optionally ``sigma``
    and ``load`` (N: load control, ``u0`` then the static indentation at the
    rows' median load, ``reference_load``, each row's from the shape's force law);
    ``mu0``, ``stiffness_ratio`` (kx/kz) and ``u0`` (m) are fitted unless given;
    ``system_stiffness`` (``frequency_ratio``, ``damping``): the rig's system, held;
    with ``fit_system_stiffness`` its stiffness is fitted from ``system_stiffness``.
    ``bounds``: ``{name: (lo, hi)}`` keeps a fitted parameter within them
    (``fricosc fit --bound``; ``hi`` may be ``inf``); one that ends on its
    bound is named in a verdict and has no standard error.

    >>> rows = {"v0": [1e-5, 2e-5, 4e-5, 6e-5, 2e-4], "du": [5e-7] * 5, "frequency": [100] * 5,
    ...         "mu": [0.21, 0.245, 0.28, 0.295, 0.3]}
    >>> r = fit(rows, "flat", u0=1e-6)
    >>> round(r.params["mu0"], 2), r.stderr["u0"]
    (0.3, 0.0)
    """
    try:
        names = [str(c) for c in table.keys()]
    except AttributeError:
        raise TypeError(f"a table is a mapping of columns (a dict of arrays, a DataFrame), not {type(table).__name__}") from None
    for need in ("v0", "du", "mu"):
        if need not in names:
            raise InputError(f"fit: no column '{need}'")
    known = ("v0", "du", "frequency", "omega", "mu", "sigma", "load")
    for name in (n for n in names if n not in known):
        like = next((f" (did you mean '{k}'?)" for k in known if k.lower() == name.strip().lower()), "")
        raise InputError(f"fit: unknown column '{name}'{like}: fit reads {', '.join(known)}")

    def col(n: str) -> npt.NDArray[np.float64]:
        return _column(_floats(table[n], n), n)

    if ("frequency" in names) == ("omega" in names):
        raise InputError("fit: give one of the columns 'frequency' (Hz) and 'omega' (rad/s)")
    omega = col("omega") if "omega" in names else 2 * np.pi * col("frequency")

    def held(x: Optional[float], n: str) -> Optional[float]:
        return None if x is None else _scalar(x, n)

    fixed = (held(mu0, "mu0"), held(stiffness_ratio, "stiffness_ratio"), held(u0, "u0"))
    order = ("mu0", "stiffness_ratio", "u0", "system_stiffness")
    for name in bounds or {}:
        if name not in order:
            raise InputError(f"fit: bounds for '{name}': fit's parameters are {', '.join(order)}")
    given = dict(bounds or {})
    ranges = tuple((float(given[n][0]), float(given[n][1])) if n in given else None for n in order)
    report: Dict[str, Any] = _fricosc.fit(
        _core(shape), col("v0"), col("du"), np.ascontiguousarray(omega), col("mu"),
        col("sigma") if "sigma" in names else None, fixed, _system(system_stiffness, frequency_ratio, damping),
        col("load") if "load" in names else None, bool(fit_system_stiffness), ranges,
    )
    return FitResult(report)
