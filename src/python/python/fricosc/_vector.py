"""The vectorised functions :func:`mu_ratio` and :func:`reduction`: numpy
arrays in process (chunked, with the GIL released, on every core), dask
arrays lazily on a Dask cluster, chunk by chunk on the workers."""

from __future__ import annotations

import importlib
from typing import Any, Dict, Optional, Tuple

import numpy as np
import numpy.typing as npt

from . import _fricosc
from ._api import FloatOrArray, InputError, InternalError, ShapeLike, _core, _floats, _tol, _velocity

_ERRORS = ("raise", "nan")


def _is_dask(x: Any) -> bool:
    return type(x).__module__.partition(".")[0] == "dask"


def _inputs(
    v: Any,
    is_vhat: bool,
    amp: Any,
    tangential_amp: Any,
    phase: Any,
    system: Optional[Tuple[Any, Any, Any]],
    transverse: Tuple[Any, Any] = (None, None),
) -> Dict[str, Any]:
    """The named inputs (not yet converted), in the order they broadcast."""
    if amp is None:
        raise TypeError("amp (du/u0) is required")
    if phase is not None and tangential_amp is None:
        raise TypeError("phase needs tangential_amp")
    if tangential_amp is not None and not is_vhat:
        raise TypeError("tangential_amp needs the velocity as vhat= (eq. 15), not vbar")
    named: Dict[str, Any] = {"vhat" if is_vhat else "vbar": v, "amp": amp}
    if tangential_amp is not None:
        named.update(tangential_amp=tangential_amp, phase=0.0 if phase is None else phase)
    if system is not None:
        named.update(system_stiffness=system[0], frequency_ratio=system[1], damping=system[2])
    if transverse[1] is not None and transverse[0] is None:
        raise TypeError("transverse_phase needs transverse_amp")
    if transverse[0] is not None:
        if system is not None:
            raise InputError("transverse_amp does not apply with system_stiffness (the plane on a stiff system only)")
        named.update(transverse_amp=transverse[0], transverse_phase=0.0 if transverse[1] is None else transverse[1])
    return named


def _flat_index_error(e: Exception) -> Optional[Tuple[str, int]]:
    """``(message, flat index)`` of an error on an array element, else None."""
    if isinstance(e, (InputError, InternalError)) and len(e.args) == 2 and isinstance(e.args[1], int):
        return str(e.args[0]), int(e.args[1])
    return None


def _compute(
    core: _fricosc.CoreShape,
    named: Dict[str, npt.NDArray[np.float64]],
    tol: float,
    reduction: bool,
    springs: Optional[int],
    nan: bool,
) -> npt.NDArray[np.float64]:
    """The values over the broadcast of ``named`` (numpy arrays); an error
    on an element keeps its flat index (``(message, index)``)."""
    names = list(named)
    arrays = np.broadcast_arrays(*(_floats(named[n], n) for n in names))
    is_vhat = names[0] == "vhat"
    if "transverse_amp" in named:
        by = dict(zip(names, arrays))
        zero = np.broadcast_to(np.float64(0.0), arrays[0].shape)  # a view: no memory an element
        t, p = (by["tangential_amp"], by["phase"]) if "tangential_amp" in by else (zero, zero)
        x = [arrays[0], by["amp"], t, p, by["transverse_amp"], by["transverse_phase"]]
        return _fricosc.evaluate_plane(core, x, is_vhat, "tangential_amp" in by, tol, reduction)
    if "system_stiffness" in named:
        by = dict(zip(names, arrays))
        zero = np.broadcast_to(np.float64(0.0), arrays[0].shape)  # a view: no memory an element
        t, p = (by["tangential_amp"], by["phase"]) if "tangential_amp" in by else (zero, zero)
        x = [arrays[0], by["amp"], t, p, by["system_stiffness"], by["frequency_ratio"], by["damping"]]
        return _fricosc.evaluate_system(core, x, is_vhat, "tangential_amp" in by, springs, tol, reduction, nan)
    if "tangential_amp" in named:
        return _fricosc.evaluate_oscillation(core, arrays[0], arrays[1], arrays[2], arrays[3], tol, reduction)
    return _fricosc.evaluate(core, arrays[0], arrays[1], is_vhat, tol, reduction)


def _with_index(e: Exception, shape: Tuple[int, ...], offset: Tuple[int, ...]) -> Exception:
    """``e`` with its element's index in the whole array (``offset`` the
    block's origin within it) at the end of its message."""
    got = _flat_index_error(e)
    if got is None or not shape:
        return e
    message, index = got
    where = tuple(int(i) + o for i, o in zip(np.unravel_index(index, shape), offset))
    return type(e)(f"{message} (at index {where[0] if len(where) == 1 else where})")


def _evaluate(
    shape: ShapeLike,
    vbar: Optional[npt.ArrayLike],
    amp: Optional[npt.ArrayLike],
    vhat: Optional[npt.ArrayLike],
    tol: Optional[float],
    reduction: bool,
    tangential_amp: Optional[npt.ArrayLike],
    phase: Optional[npt.ArrayLike],
    system: Tuple[Any, Any, Any, Any],
    errors: str,
    transverse: Tuple[Any, Any] = (None, None),
) -> Any:
    """``mu_ratio`` (or the reduction) over the broadcast inputs: numpy in
    process, or a lazy dask array where any input is one."""
    core = _core(shape)
    v, is_vhat = _velocity(vbar, vhat)
    stiffness, frequency_ratio, damping, springs = system
    if errors not in _ERRORS:
        raise InputError(f"errors must be 'raise' or 'nan', not {errors!r}")
    if stiffness is None:
        given = [n for n, x in (("frequency_ratio", frequency_ratio), ("damping", damping), ("springs", springs)) if x is not None]
        if given:
            raise InputError(f"{given[0]} applies only with system_stiffness")
        if errors != "raise":
            raise InputError("errors='nan' applies only with system_stiffness (nothing else is refused as it solves)")
    if springs is not None and (isinstance(springs, bool) or not isinstance(springs, (int, np.integer))):
        raise TypeError(f"springs must be an integer, not {type(springs).__name__}")
    triple = None if stiffness is None else (stiffness, 0.0 if frequency_ratio is None else frequency_ratio, 0.0 if damping is None else damping)
    named = _inputs(v, is_vhat, amp, tangential_amp, phase, triple, transverse)
    how = dict(tol=_tol(tol), reduction=reduction, springs=None if springs is None else int(springs), nan=errors == "nan")
    if any(_is_dask(x) for x in named.values()):
        return _lazy(shape, named, how)
    try:
        out = _compute(core, named, **how)  # type: ignore[arg-type]
    except (InputError, InternalError) as e:
        shape_out = np.broadcast_shapes(*(np.shape(x) for x in named.values()))
        raise _with_index(e, shape_out, (0,) * len(shape_out)) from None
    return float(out) if out.ndim == 0 else out


def _lazy(shape: ShapeLike, named: Dict[str, Any], how: Dict[str, Any]) -> Any:
    """A lazy dask array of the values: each block computed where it lies
    (nothing at graph build, nothing gathered on the client); an element's
    error raised on the client with its index in the whole array."""
    # Dask is an optional extra, untyped here (`Any`).
    da: Any = importlib.import_module("dask.array")
    names = list(named)
    arrays = da.broadcast_arrays(*(da.asarray(named[n]) for n in names))

    def block(*blocks: npt.NDArray[Any], block_info: Optional[Dict[Any, Any]] = None) -> npt.NDArray[np.float64]:
        offset = tuple(lo for lo, _ in block_info[None]["array-location"]) if block_info else ()
        try:
            out = _compute(_core(shape), dict(zip(names, blocks)), **how)
        except (InputError, InternalError) as e:
            raise _with_index(e, np.broadcast_shapes(*(np.shape(b) for b in blocks)), offset) from None
        return np.asarray(out, dtype=np.float64)

    meta = np.empty((0,) * arrays[0].ndim, dtype=np.float64)
    return da.map_blocks(block, *arrays, dtype=np.float64, meta=meta)


def mu_ratio(
    shape: ShapeLike,
    vbar: Optional[npt.ArrayLike] = None,
    amp: Optional[npt.ArrayLike] = None,
    *,
    vhat: Optional[npt.ArrayLike] = None,
    tol: Optional[float] = None,
    tangential_amp: Optional[npt.ArrayLike] = None,
    phase: Optional[npt.ArrayLike] = None,
    system_stiffness: Optional[npt.ArrayLike] = None,
    frequency_ratio: Optional[npt.ArrayLike] = None,
    damping: Optional[npt.ArrayLike] = None,
    springs: Optional[int] = None,
    errors: str = "raise",
    transverse_amp: Optional[npt.ArrayLike] = None,
    transverse_phase: Optional[npt.ArrayLike] = None,
) -> FloatOrArray:
    """``mu_macro / mu0`` of ``shape`` at velocity ``vbar`` (or ``vhat``) and amplitude ``amp``.

    ``vbar`` and ``amp`` (or ``vhat`` and ``amp``, with ``vbar = vhat / amp``)
    are numbers or arrays and broadcast against each other; the result is a
    float for scalar inputs, else a float64 array of the broadcast shape.
    ``tol`` is the relative quadrature tolerance of curved shapes (default
    :data:`DEFAULT_TOL`). Arrays are evaluated in chunks of about 40 ms, on
    every core where a chunk is worth it, with the GIL released; Ctrl-C
    raises ``KeyboardInterrupt`` within about 0.1 s.

    With ``tangential_amp`` (``dx/l``, pre-slip lengths ``l = mu0 u0 kz/kx``)
    the body also oscillates in the sliding direction, ``phase`` radians
    (default 0) against the normal oscillation (``vhat`` then; all four
    broadcast); the result lies in ``[-1, 1]``: below 0 the oscillations push
    the body forward. ``tangential_amp = 0`` is the seed's problem, bit for bit.

    With ``system_stiffness`` (``kappa = K/kx``; and ``frequency_ratio``
    ``Omega``, ``damping`` ``zeta``, default 0, numbers or arrays broadcast
    with the rest) the body has mass on a system spring, as ``fricosc batch``
    rows with those columns (its values bit for bit); ``springs`` (an
    integer) discretises a curved body as ``--springs``. An element the
    solver refuses as it solves (a body that cannot settle in the periods
    run, one too light to resolve) raises :class:`InputError` with its index,
    or is NaN with ``errors="nan"``.

    With ``transverse_amp`` (``dy/l``; and ``transverse_phase``, radians,
    default 0, both broadcast with the rest) the body also oscillates across
    the sliding direction, as ``fricosc point --transverse-amp`` (every shape,
    on a stiff system; ``transverse_amp = 0`` is the problem without it).

    Any dask array among the inputs makes the result a lazy dask array of the
    broadcast shape and chunks, computed block by block where the blocks lie
    (``pip install "./src/python[dask]"``; README: maps beyond one machine).

    >>> mu_ratio("flat", [0.0, 0.5, 1.0], 0.5).tolist()
    [0.5, 0.8992738983331656, 1.0]
    >>> mu_ratio("flat", vhat=0.6, amp=2.0, tangential_amp=3.0, phase=1.0)
    -0.9271222646980088
    >>> mu_ratio("flat", 0.3, 0.5, system_stiffness=1.0, frequency_ratio=[0.5, 1.0], damping=0.05).round(12).tolist()
    [0.631146223864, 0.661542318254]
    >>> mu_ratio("flat", vhat=0.3, amp=0.5, transverse_amp=[0.0, 1.2], transverse_phase=0.7).round(12).tolist()
    [0.937263340948, 0.614622340126]
    """
    system = (system_stiffness, frequency_ratio, damping, springs)
    transverse = (transverse_amp, transverse_phase)
    result: FloatOrArray = _evaluate(shape, vbar, amp, vhat, tol, False, tangential_amp, phase, system, errors, transverse)
    return result


def reduction(
    shape: ShapeLike,
    vbar: Optional[npt.ArrayLike] = None,
    amp: Optional[npt.ArrayLike] = None,
    *,
    vhat: Optional[npt.ArrayLike] = None,
    tol: Optional[float] = None,
    tangential_amp: Optional[npt.ArrayLike] = None,
    phase: Optional[npt.ArrayLike] = None,
    system_stiffness: Optional[npt.ArrayLike] = None,
    frequency_ratio: Optional[npt.ArrayLike] = None,
    damping: Optional[npt.ArrayLike] = None,
    springs: Optional[int] = None,
    errors: str = "raise",
    transverse_amp: Optional[npt.ArrayLike] = None,
    transverse_phase: Optional[npt.ArrayLike] = None,
) -> FloatOrArray:
    """``1 - mu_macro / mu0``, computed with its own relative accuracy (not as a
    difference): the friction that the oscillation removes (up to 2 under
    oscillation in the sliding direction). Arguments as in :func:`mu_ratio`.

    >>> reduction("flat", 1 - 1e-6, 0.5)  # 1 - mu_ratio would keep 3 digits
    3.580986935971103e-13
    """
    system = (system_stiffness, frequency_ratio, damping, springs)
    transverse = (transverse_amp, transverse_phase)
    result: FloatOrArray = _evaluate(shape, vbar, amp, vhat, tol, True, tangential_amp, phase, system, errors, transverse)
    return result
