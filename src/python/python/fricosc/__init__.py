"""Exact friction reduction by normal oscillation (Popov, Popov, Popov 2017).

``fricosc`` computes ``mu_macro / mu0`` of a contact whose normal load
oscillates while it slides, as a function of the dimensionless velocity
``vbar`` (eq. 3) and the amplitude ``amp = du/u0``, with the event-driven
exact solver of the ``fricosc`` command line (the same Rust library, in process).

>>> import fricosc
>>> float(fricosc.mu_ratio("flat", 0.2, 0.5))
0.7145191049466342

Arrays broadcast like numpy's own functions; the result has the broadcast
shape (a float for scalar inputs). Shapes are strings exactly as on the
command line (``"flat"``, ``"parabolic"``, ``"cone"``, ``"power:2.5"``,
``"flat-tip:0.5"``, ``"profile:file.csv@1e-6"``, ``"gx:file.csv@1"``) or the
classes :class:`Flat`, :class:`PowerLaw`, :class:`FlatTip`, :class:`Profile`
and :class:`EquivalentProfile` (tables from arrays, no file needed).

Bad input raises :class:`InputError` (a ``ValueError``) with the command line's
message (for an array element the message ends with its index), a wrong type
``TypeError``, and a bug of fricosc :class:`InternalError` (a ``RuntimeError``).
"""

from ._fit import FitResult, fit
from ._vector import mu_ratio, reduction
from ._api import (
    DEFAULT_TOL,
    EquivalentProfile,
    Flat,
    FlatTip,
    InputError,
    InternalError,
    PowerLaw,
    Profile,
    Shape,
    __version__,
    history,
    point,
    scene,
    validate,
    validate_history,
    validate_series,
)

__all__ = [
    "Shape",
    "Flat",
    "PowerLaw",
    "FlatTip",
    "Profile",
    "EquivalentProfile",
    "mu_ratio",
    "reduction",
    "point",
    "history",
    "validate",
    "validate_history",
    "validate_series",
    "scene",
    "fit",
    "FitResult",
    "InputError",
    "InternalError",
    "DEFAULT_TOL",
    "__version__",
]
