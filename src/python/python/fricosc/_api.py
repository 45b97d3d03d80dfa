"""The implementation of the ``fricosc`` package (its API is re-exported by ``fricosc``)."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _fricosc

__version__: str = _fricosc.__version__

#: Bad input: a value, a shape or a table fricosc refuses (a ``ValueError``).
InputError = _fricosc.InputError
#: A bug of fricosc (a ``RuntimeError``): please report it.
InternalError = _fricosc.InternalError

#: Relative quadrature tolerance of curved shapes when ``tol`` is not given.
DEFAULT_TOL: float = _fricosc.default_tol()

FloatOrArray = Union[float, npt.NDArray[np.float64]]


class Shape:
    """A contact geometry, parsed from its command-line name.

    >>> Shape("parabolic").name
    'parabolic'
    """

    _core: _fricosc.CoreShape
    #: What the shape is made from: pickled so (a worker of a Dask cluster
    #: makes it again; a file a spec names is read there).
    _args: Tuple[Any, ...]

    def __init__(self, spec: str) -> None:
        if not isinstance(spec, str):
            raise TypeError(f"a shape is a string or a fricosc.Shape, not {type(spec).__name__}")
        self._core = _fricosc.CoreShape.parse(spec)
        self._args = (spec,)

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        return (type(self), self._args)

    @property
    def name(self) -> str:
        """The canonical name (it parses back to the same shape)."""
        return self._core.name

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name!r})"


class Flat(Shape):
    """The flat cylindrical punch: one spring (the seed's section 2)."""

    def __init__(self) -> None:
        super().__init__("flat")
        self._args = ()


class PowerLaw(Shape):
    """An MDR power-law profile ``g ~ |x|^n`` (``n = 1`` cone, ``n = 2`` paraboloid)."""

    def __init__(self, n: float) -> None:
        super().__init__(f"power:{float(n)!r}")
        self._args = (n,)


class FlatTip(Shape):
    """A sphere worn flat at its tip; ``e`` = flat radius / contact radius, in [0, 1)."""

    def __init__(self, e: float) -> None:
        super().__init__(f"flat-tip:{float(e)!r}")
        self._args = (e,)


def _column(values: npt.ArrayLike, what: str) -> npt.NDArray[np.float64]:
    array = np.ascontiguousarray(np.asarray(values, dtype=np.float64))
    if array.ndim != 1:
        raise ValueError(f"{what} must be one-dimensional, got shape {array.shape}")
    return array


class Profile(Shape):
    """A tabulated axisymmetric profile ``f(r)`` (from the axis outwards, nondecreasing)
    at mean indentation ``u0`` (in the columns' length unit), MDR-transformed;
    the same checks and limits as a ``profile:FILE@U0`` file."""

    def __init__(self, r: npt.ArrayLike, f: npt.ArrayLike, u0: float, name: str = "profile") -> None:
        self._core = _fricosc.CoreShape.from_table(_column(r, "r"), _column(f, "f"), float(u0), True, name)
        self._args = (r, f, u0, name)


class EquivalentProfile(Shape):
    """A tabulated MDR equivalent profile ``g(x)`` at mean indentation ``u0``
    (as ``gx:FILE@U0``)."""

    def __init__(self, x: npt.ArrayLike, g: npt.ArrayLike, u0: float, name: str = "gx") -> None:
        self._core = _fricosc.CoreShape.from_table(_column(x, "x"), _column(g, "g"), float(u0), False, name)
        self._args = (x, g, u0, name)


ShapeLike = Union[str, Shape]


def _core(shape: ShapeLike) -> _fricosc.CoreShape:
    if isinstance(shape, Shape):
        return shape._core
    return Shape(shape)._core


def _velocity(vbar: Optional[npt.ArrayLike], vhat: Optional[npt.ArrayLike]) -> Tuple[npt.ArrayLike, bool]:
    if vbar is not None and vhat is None:
        return vbar, False
    if vbar is None and vhat is not None:
        return vhat, True
    raise TypeError("give exactly one of vbar (eq. 3) and vhat (eq. 15, vbar = vhat / amp)")


def _floats(x: npt.ArrayLike, what: str) -> npt.NDArray[np.float64]:
    """``x`` as float64, from real numbers only: integers and floats (of any
    width) are taken; strings, bytes, booleans, complex numbers, objects and
    masked arrays (whose mask would be ignored) are refused with ``TypeError``."""
    if isinstance(x, np.ma.MaskedArray):
        raise TypeError(f"{what}: masked arrays are not accepted (fill or compress them first)")
    if isinstance(x, (str, bytes, bool, np.bool_)):
        raise TypeError(f"{what} must be a real number or an array of real numbers, not {type(x).__name__}")
    try:
        array = np.asarray(x)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what} must be a real number or an array of real numbers ({e})") from None
    if array.dtype.kind not in "iuf":
        raise TypeError(
            f"{what} must be a real number or an array of real numbers, not an array of dtype {array.dtype}"
        )
    return array.astype(np.float64, copy=False)


def _tol(tol: Optional[float]) -> float:
    if tol is None:
        return DEFAULT_TOL
    if isinstance(tol, (bool, np.bool_)) or not isinstance(tol, (int, float, np.integer, np.floating)):
        raise TypeError(f"tol must be a real number, not {type(tol).__name__}")
    return float(tol)


def point(
    shape: ShapeLike,
    vbar: Optional[float] = None,
    amp: Optional[float] = None,
    *,
    vhat: Optional[float] = None,
    tol: Optional[float] = None,
    tangential_amp: Optional[float] = None,
    phase: Optional[float] = None,
    system_stiffness: Optional[float] = None,
    frequency_ratio: Optional[float] = None,
    damping: Optional[float] = None,
    springs: Optional[int] = None,
    transverse_amp: Optional[float] = None,
    transverse_phase: Optional[float] = None,
) -> Dict[str, Any]:
    """Everything the solver reports at one point, as ``fricosc point`` prints it:
    the regime and events of the flat punch, the bands of a power law, the
    error estimates. With ``tangential_amp`` (and ``phase``, ``vhat``) as
    ``fricosc point --tangential-amp``: the spring's phases and events of one
    period (flat punch) or the bands. With ``system_stiffness`` (and
    ``frequency_ratio``, ``damping``) as ``fricosc point --system-stiffness``:
    the body on a system with mass and stiffness, its attractor (a curved
    body's as ``springs`` springs, default 256, with an error estimate). With
    ``transverse_amp`` (and ``transverse_phase``) as ``fricosc point
    --transverse-amp``: the flat punch under an oscillation across the sliding
    direction, ``mu_ratio``, ``transverse_ratio`` (the mean sideways force),
    the period's events and the period map's multiplier (``transverse_amp=0``
    is the point without it).

    >>> p = point("flat", 0.3, 0.5)
    >>> p["regime"], p["mu_ratio"], [e["kind"] for e in p["events"]]
    ('permanent_stick_slip', 0.7896790737003746, ['stick', 'slip'])
    >>> q = point("flat", vhat=0.6, amp=2.0, tangential_amp=3.0, phase=1.0)
    >>> q["spring"]["regime"], [e["kind"] for e in q["spring"]["events"]]
    ('jumping: stick, backward, stick, forward', ['contact', 'backward', 'stick', 'forward', 'loss_of_contact'])
    >>> r = point("flat", vhat=0.3, amp=0.5, transverse_amp=1.2, transverse_phase=0.7)
    >>> round(r["mu_ratio"], 12), round(r["transverse_ratio"], 12), [e["kind"] for e in r["events"]]
    (0.614622340126, -0.246652132766, ['stick', 'slip'])
    """
    if amp is None:
        raise TypeError("amp (du/u0) is required")
    v, is_vhat = _velocity(vbar, vhat)
    if transverse_phase is not None and transverse_amp is None:
        raise TypeError("transverse_phase needs transverse_amp")
    if transverse_amp is not None and _scalar(transverse_amp, "transverse_amp") != 0.0:
        if system_stiffness is not None or springs is not None or tol is not None:
            what = "system_stiffness" if system_stiffness is not None else "springs" if springs is not None else "tol"
            raise InputError(f"{what} does not apply with transverse_amp (the flat punch on a stiff system, exact)")
        plane: Dict[str, Any] = _fricosc.point_plane(
            _core(shape), _scalar(v, "vhat" if is_vhat else "vbar"), _scalar(amp, "amp"), is_vhat,
            _tangential(tangential_amp, phase, is_vhat), _scalar(transverse_amp, "transverse_amp"),
            _scalar(0.0 if transverse_phase is None else transverse_phase, "transverse_phase"),
        )
        return plane
    system = _system(system_stiffness, frequency_ratio, damping)
    if system is not None:
        if tol is not None:
            raise InputError("tol does not apply on a system (a curved body's springs set its accuracy)")
        t, ph = _tangential(tangential_amp, phase, is_vhat) or (0.0, 0.0)
        a = _scalar(amp, "amp")
        vh = _scalar(v, "vhat") if is_vhat else _scalar(v, "vbar") * a
        sys_point: Dict[str, Any] = _fricosc.point_system(
            _core(shape), vh, a, t, ph, *system, None if springs is None else _whole(springs, "springs"),
        )
        return sys_point
    if springs is not None:
        raise InputError("springs applies only with system_stiffness (a curved body on a system)")
    tangential = _tangential(tangential_amp, phase, is_vhat)
    if tangential is not None:
        osc: Dict[str, Any] = _fricosc.point_oscillation(
            _core(shape), _scalar(v, "vhat"), _scalar(amp, "amp"), tangential[0], tangential[1], _tol(tol)
        )
        return osc
    result: Dict[str, Any] = _fricosc.point(_core(shape), _scalar(v, "vbar"), _scalar(amp, "amp"), is_vhat, _tol(tol))
    return result


def _system(
    stiffness: Optional[float], frequency_ratio: Optional[float], damping: Optional[float]
) -> Optional[Tuple[float, float, float]]:
    """``(kappa, Omega, zeta)`` of a system with mass and stiffness, if ``stiffness`` is given
    (``frequency_ratio`` and ``damping`` default to 0; without it they are refused, not ignored)."""
    if stiffness is None:
        for name, value in (("frequency_ratio", frequency_ratio), ("damping", damping)):
            if value is not None:
                raise InputError(f"{name} applies only with system_stiffness")
        return None
    return (
        _scalar(stiffness, "system_stiffness"),
        0.0 if frequency_ratio is None else _scalar(frequency_ratio, "frequency_ratio"),
        0.0 if damping is None else _scalar(damping, "damping"),
    )


def _whole(value: Any, name: str) -> int:
    """A count >= 1 (an integer, not a bool)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, not {type(value).__name__}")
    if value < 1:
        raise ValueError(f"invalid {name} = {value}: must be >= 1")
    return int(value)


def _tangential(tangential_amp: Optional[float], phase: Optional[float], is_vhat: bool) -> Optional[Tuple[float, float]]:
    """``(T, phase)`` of a single point's tangential oscillation, if given; it needs ``vhat``."""
    if phase is not None and tangential_amp is None:
        raise TypeError("phase needs tangential_amp")
    if tangential_amp is None:
        return None
    if not is_vhat:
        raise TypeError("tangential_amp needs the velocity as vhat= (eq. 15), not vbar")
    return _scalar(tangential_amp, "tangential_amp"), _scalar(0.0 if phase is None else phase, "phase")


def _scalar(x: Any, what: str) -> float:
    if isinstance(x, (bool, str, bytes)) or not np.isscalar(x) and np.ndim(x) != 0:
        raise TypeError(f"{what} must be a real number, not {type(x).__name__}")
    try:
        return float(x)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what} must be a real number ({e})") from None


def history(
    shape: ShapeLike,
    vbar: Optional[float] = None,
    amp: Optional[float] = None,
    *,
    vhat: Optional[float] = None,
    tangential_amp: Optional[float] = None,
    phase: Optional[float] = None,
    periods: int = 1,
    samples: int = 400,
    springs: Optional[int] = None,
    spring_at: Sequence[float] = (),
    system_stiffness: Optional[float] = None,
    frequency_ratio: Optional[float] = None,
    damping: Optional[float] = None,
    transverse_amp: Optional[float] = None,
    transverse_phase: Optional[float] = None,
) -> Dict[str, Any]:
    """The normal force (times mu0) and the tangential force over ``periods``
    periods (the seed's Fig. 2), as ``fricosc history`` computes them: exact,
    with every event time among the samples (flat punch).

    Returns a dict with ``tau`` (phase), ``normal``, ``tangential`` (float64
    arrays), ``event`` (a list: the event at each sample or None), ``units``,
    and for ``spring_at`` positions ``x/x_c`` the chosen springs' forces
    ``springs`` (shape ``(samples, len(spring_at), 2)``: normal, tangential).
    With ``tangential_amp`` (and ``phase``, ``vhat``) as ``fricosc history
    --tangential-amp``: the body also oscillates in the sliding direction, and
    the force slips both ways (events ``slip`` and ``backward_slip``). With
    ``system_stiffness`` (``frequency_ratio``, ``damping``): the body on a
    system with mass and stiffness, one period of its attractor (a curved
    body's as its springs), with the body's ``body_lag`` behind the drive,
    ``body_velocity`` and the ``system_force`` on it (a body with mass). ``springs``: a curved body's, default 4000 (256
    on a system). With ``transverse_amp`` (and ``transverse_phase``) as ``fricosc history --transverse-amp``: an
    oscillation across the sliding direction, the force across it ``transverse`` beside ``tangential`` (along it), the
    flat punch's every event of the orbit among the samples (``transverse_amp=0`` is the history without it).

    >>> h = history("flat", vhat=0.2, amp=0.5, tangential_amp=1.5, phase=1.3, samples=100)
    >>> [e for e in h["event"] if e]
    ['stick', 'backward_slip', 'stick', 'slip']
    >>> h = history("flat", vhat=0.2, amp=1.4, transverse_amp=0.8, transverse_phase=2.0, samples=100)
    >>> [e for e in h["event"] if e], round(float(min(h["transverse"])), 6)
    (['contact', 'slip', 'loss_of_contact'], -1.08656)
    """
    if transverse_phase is not None and transverse_amp is None:
        raise TypeError("transverse_phase needs transverse_amp")
    if amp is None:
        raise TypeError("amp (du/u0) is required")
    v, is_vhat = _velocity(vbar, vhat)
    tangential = _tangential(tangential_amp, phase, is_vhat)
    if springs is None:
        springs = 4000 if system_stiffness is None else 256
    for name, value in (("periods", periods), ("samples", samples), ("springs", springs)):
        _whole(value, name)
    positions = [_scalar(x, "spring_at") for x in spring_at]
    result: Dict[str, Any] = _fricosc.history(
        _core(shape),
        _scalar(v, "vbar"),
        _scalar(amp, "amp"),
        is_vhat,
        tangential,
        int(periods),
        int(samples),
        int(springs),
        positions,
        _system(system_stiffness, frequency_ratio, damping),
        None if transverse_amp is None else (
            _scalar(transverse_amp, "transverse_amp"),
            _scalar(0.0 if transverse_phase is None else transverse_phase, "transverse_phase"),
        ),
    )
    return result


_READ = (
    "vbar", "vhat", "amp", "mu_ratio", "mu", "tangential_amp", "phase",
    "transverse_amp", "transverse_phase", "transverse_ratio",
)


def _table(table: Any) -> Tuple[List[str], List[Tuple[str, npt.NDArray[np.float64]]]]:
    """A table (a mapping of columns) as the extension reads it: every column's name, and the
    numeric columns fricosc reads (it checks them as the command line checks a file's)."""
    try:
        names = [str(c) for c in table.keys()]
    except AttributeError:
        raise TypeError(f"a table is a mapping of columns (a dict of arrays, a DataFrame), not {type(table).__name__}") from None
    return names, [(n, _column(_floats(table[n], n), n)) for n in _READ if n in names]


def _table_shape(tables: List[Any], shape: Optional[ShapeLike]) -> Tuple[ShapeLike, str]:
    """The shape the tables name (one), else ``shape=``, else the flat punch; and where it came from."""
    named = sorted({str(s) for t in tables if "shape" in t for s in np.asarray(t["shape"]).reshape(-1).tolist()})
    if len(named) > 1:
        raise ValueError(f"the table names more than one shape ({', '.join(repr(s) for s in named)}): validate one shape at a time")
    if named and shape is not None and Shape(named[0]).name != (shape if isinstance(shape, Shape) else Shape(shape)).name:
        raise ValueError(f"the table is for shape '{named[0]}', shape= says '{shape if isinstance(shape, str) else shape.name}'")
    if named:
        return named[0], "file"
    return (shape, "option") if shape is not None else ("flat", "default")


def validate(
    table: Any,
    shape: Optional[ShapeLike] = None,
    *,
    at_rest: str = "sliding",
    mu0: Optional[float] = None,
    tolerance: float = 1e-9,
    peer: Optional[int] = None,
    peer_springs: Optional[int] = None,
    system_stiffness: Optional[float] = None,
    frequency_ratio: Optional[float] = None,
    damping: Optional[float] = None,
    max_error: Optional[float] = None,
) -> Dict[str, Any]:
    """Compare another code's table with the exact values, as ``fricosc validate``
    does: the same JSON report as a dict (per-row errors and regimes, errors by
    regime and by amplitude, findings with hints; a finding means something is
    wrong).

    ``table`` is a mapping of columns (a dict of arrays, a pandas DataFrame),
    read as ``fricosc validate`` reads a file's: ``vbar`` or ``vhat``, ``amp``,
    ``mu_ratio`` or ``mu`` (then ``mu0`` is required), under oscillation in the
    sliding direction ``tangential_amp`` and ``phase`` (with ``vhat``; the
    report is then the oscillation's), across it ``transverse_amp``,
    ``transverse_phase`` and, if your code gives the mean force across,
    ``transverse_ratio`` (compared too: ``transverse_error`` per row, the
    summary ``transverse``), and optionally ``shape`` (one value for the whole table; ``shape=``
    only where the table names none, an error where they disagree; the flat
    punch by default). ``at_rest``: ``"sliding"`` or ``"relaxed"`` (what a
    ``vbar = 0`` row is compared with). ``peer=M``: run fricosc's stepping peer
    at ``M`` steps per period (and ``peer_springs`` springs, default ``M``) on
    every row and set its error beside yours (``peer_error``).
    ``system_stiffness`` (``frequency_ratio``, ``damping``): on a system with mass and stiffness,
    against its attractors (``fricosc validate --system-stiffness``). Findings ``max_error``: rows
    beyond ``max_error``; ``diverged``: values not finite (the other rows are compared).

    >>> r = validate({"vbar": [0.2, 1.1], "amp": [0.5, 0.5], "mu_ratio": [0.7145, 1.2]})
    >>> r["max_abs_error"] > 0.19, [f["kind"] for f in r["findings"]]
    (True, ['above_one', 'not_one_above_critical'])
    """
    names, columns = _table(table)
    chosen, source = _table_shape([table], shape)
    result: Dict[str, Any] = _fricosc.validate(
        _core(chosen),
        names,
        columns,
        None if mu0 is None else float(mu0),
        at_rest,
        float(tolerance),
        None if peer is None else _count(peer, "peer"),
        None if peer_springs is None else _count(peer_springs, "peer_springs"),
        _system(system_stiffness, frequency_ratio, damping),
        None if max_error is None else float(max_error),
    )
    result["shape_source"] = source
    return result


def _count(x: Any, what: str) -> int:
    if isinstance(x, bool) or not isinstance(x, (int, np.integer)) or not 1 <= int(x) <= 100_000_000:
        raise ValueError(f"{what} must be a whole number from 1 to 1e8, not {x!r}")
    return int(x)


def validate_series(
    tables: Mapping[Any, Any],
    shape: Optional[ShapeLike] = None,
    *,
    at_rest: str = "sliding",
    mu0: Optional[float] = None,
    tolerance: float = 1e-9,
    target: Optional[float] = None,
    system_stiffness: Optional[float] = None,
    frequency_ratio: Optional[float] = None,
    damping: Optional[float] = None,
) -> Dict[str, Any]:
    """A convergence study, as ``fricosc validate --series`` does: ``tables``
    maps each resolution (e.g. steps per period) to the table computed at it
    (each a mapping of columns, as :func:`validate` takes). Per row: the
    observed order, error constant, Richardson value, status (``converging``,
    ``not_converging``, ``resolution_independent``, ``exact``) and, with
    ``target``, the resolution needed (or ``"unreachable"``); per regime the
    median order; findings (rows that do not converge, errors that do not depend
    on the resolution, the finest table's own findings) and cautions; on a system
    (``system_stiffness=``, as :func:`validate`) against its attractors.

    >>> from fricosc import mu_ratio
    >>> exact = float(mu_ratio("flat", 0.5, 0.5))
    >>> t = {m: {"vbar": [0.5], "amp": [0.5], "mu_ratio": [exact + 1 / m ** 2]} for m in (100, 200, 400)}
    >>> r = validate_series(t)
    >>> round(r["rows"][0]["order"], 1), r["rows"][0]["status"]
    (2.0, 'converging')
    """
    try:
        items = sorted((float(k), v) for k, v in tables.items())
    except (AttributeError, TypeError, ValueError):
        raise TypeError("tables is a mapping from each resolution (a number) to its table") from None
    read = [_table(t) for _, t in items]
    chosen, source = _table_shape([t for _, t in items], shape)
    result: Dict[str, Any] = _fricosc.validate_series(
        _core(chosen),
        [r for r, _ in items],
        read,
        None if mu0 is None else float(mu0),
        at_rest,
        float(tolerance),
        None if target is None else float(target),
        _system(system_stiffness, frequency_ratio, damping),
    )
    result["shape_source"] = source
    return result


def scene(spec: Union[Dict[str, Any], str, "os.PathLike[str]"]) -> List[Dict[str, Any]]:
    """Solve a physical scene (SI units), as ``fricosc scene`` does: ``spec`` is
    the scene as a dict (the JSON file's content) or the path of its file (a
    tabulated profile's file is then found relative to it). Returns a list with
    one dict per amplitude (``oscillation.amplitude_m`` may be a list or a
    sweep): ``rows`` of velocity, ``mu_ratio``, friction force, ...

    >>> r = scene({"materials": {"e1_pa": 2e11, "nu1": 0.3, "e2_pa": 2e11, "nu2": 0.3}, "mu0": 0.4,
    ...            "indenter": {"sphere": {"radius_m": 5e-3}}, "loading": {"mean_indentation_m": 1e-6},
    ...            "oscillation": {"amplitude_m": [5e-7, 1e-6], "frequency_hz": 1e3},
    ...            "velocity": {"values_m_per_s": [1e-3]}})
    >>> [round(a["rows"][0]["mu_ratio"], 12) for a in r]
    [0.936881842762, 0.588043871144]
    """
    text: Optional[str]
    if isinstance(spec, dict):
        text, source = json.dumps(spec), "scene"
    elif isinstance(spec, (str, os.PathLike)):
        text, source = None, os.fspath(spec)  # read by the extension, with the command line's size cap
    else:
        raise TypeError(f"a scene is a dict or the path of a JSON file, not {type(spec).__name__}")
    result: List[Dict[str, Any]] = _fricosc.scene(text, source)
    return result


def validate_history(
    history: Any,
    vbar: Optional[float] = None,
    amp: Optional[float] = None,
    *,
    shape: ShapeLike = "flat",
    vhat: Optional[float] = None,
    tangential_amp: Optional[float] = None,
    phase: Optional[float] = None,
    omega: Optional[float] = None,
    static_force: Optional[float] = None,
    mu0: Optional[float] = None,
    tolerance: float = 1e-9,
    system_stiffness: Optional[float] = None,
    frequency_ratio: Optional[float] = None,
    damping: Optional[float] = None,
    transverse_amp: Optional[float] = None,
    transverse_phase: Optional[float] = None,
) -> Dict[str, Any]:
    """Compare a force history with the steady state of ``shape`` (exact for the
    flat punch; for curved shapes the normal force exact and the tangential one
    summed over 20,000 springs, without events), as
    ``fricosc validate --history`` does: the time origin found from the normal
    force (the seed writes the indentation ``u0 - du cos(omega t)``; a file
    written otherwise is aligned, and the offset reported), errors of both
    forces over the last period, whether it is periodic yet (and how many more
    periods it needs), the stick, slip and contact events found from the force
    against its Coulomb bound, each with its timing error, and findings.

    ``history`` is a mapping of columns: ``tau`` (the phase omega t) or ``t``
    (with ``omega``, or the period found from the normal force), ``tangential``
    and optionally ``normal``: forces in units of ``mu0 F0`` and ``F0``, where
    ``F0`` is the normal force at depth u0 without oscillation (``kz u0`` for
    the flat punch, Hertz's ``(4/3) E* R^1/2 u0^3/2`` for the paraboloid), or
    in yours with ``static_force`` (``F0`` in them) and ``mu0``. A history
    under a tangential oscillation is compared at ``vhat``, ``amp``,
    ``tangential_amp`` and ``phase``, as ``fricosc validate --history
    --tangential-amp``. With ``system_stiffness`` (``frequency_ratio``,
    ``damping``) the history is a body's on a system, compared with its
    period-1 attractor (any other is refused), and the columns ``body_lag``
    and ``body_velocity`` (as :func:`history` gives them), where present,
    with the exact body's. With ``transverse_amp`` (and ``transverse_phase``)
    the history is one in the plane, as ``fricosc validate --history
    --transverse-amp``: its column ``transverse`` (the force across the
    sliding direction), where present, compared too, and the events found
    from the force's magnitude.

    >>> h = history("flat", 0.3, 1.5, periods=2, samples=2000)
    >>> r = validate_history({"tau": h["tau"], "tangential": h["tangential"]}, 0.3, 1.5)
    >>> r["periodic"], [e["kind"] for e in r["events"]]
    (True, ['contact', 'stick', 'slip', 'loss_of_contact'])
    """
    try:
        columns = list(history.keys())
    except AttributeError:
        raise TypeError(f"a history is a mapping of columns, not {type(history).__name__}") from None
    if amp is None:
        raise TypeError("amp (du/u0) is required")
    v, is_vhat = _velocity(vbar, vhat)
    oscillation = _tangential(tangential_amp, phase, is_vhat)
    if transverse_phase is not None and transverse_amp is None:
        raise TypeError("transverse_phase needs transverse_amp")
    across = None if transverse_amp is None else (
        _scalar(transverse_amp, "transverse_amp"),
        _scalar(0.0 if transverse_phase is None else transverse_phase, "transverse_phase"),
    )
    if ("tau" in columns) == ("t" in columns):
        raise ValueError("give exactly one time column: 'tau' (phase) or 't' (time)")
    if "tangential" not in columns:
        raise ValueError("the history lacks column 'tangential'")
    time = _column(_floats(history["tau" if "tau" in columns else "t"], "time"), "time")
    normal = _column(_floats(history["normal"], "normal"), "normal") if "normal" in columns else None
    body = None
    if "body_lag" in columns or "body_velocity" in columns:
        if not ("body_lag" in columns and "body_velocity" in columns):
            raise ValueError("'body_lag' and 'body_velocity' are given together or not at all")
        body = tuple(_column(_floats(history[k], k), k) for k in ("body_lag", "body_velocity"))
    result: Dict[str, Any] = _fricosc.validate_history(
        _core(shape),
        time,
        "tau" in columns,
        _column(_floats(history["tangential"], "tangential"), "tangential"),
        normal,
        _scalar(v, "vbar"),
        _scalar(amp, "amp"),
        is_vhat,
        oscillation,
        None if omega is None else float(omega),
        float(tolerance),
        1.0 if static_force is None else _scalar(static_force, "static_force"),
        1.0 if mu0 is None else _scalar(mu0, "mu0"),
        _system(system_stiffness, frequency_ratio, damping),
        body,
        across,
        _column(_floats(history["transverse"], "transverse"), "transverse") if "transverse" in columns else None,
    )
    return result
