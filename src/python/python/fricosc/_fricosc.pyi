"""Type stub of the Rust extension (src/python/src/lib.rs)."""

from typing import Any, Dict, List, Optional, Tuple, final

import numpy as np
import numpy.typing as npt

__all__ = ["CoreShape", "InputError", "InternalError", "evaluate", "point", "evaluate_oscillation", "evaluate_system", "evaluate_plane", "point_oscillation", "point_plane", "point_system", "history", "validate", "scene", "validate_history", "validate_series", "default_tol", "fit", "__version__"]
__version__: str

class InputError(ValueError): ...
class InternalError(RuntimeError): ...

@final
class CoreShape:
    @staticmethod
    def parse(spec: str) -> CoreShape: ...
    @staticmethod
    def from_table(
        x: npt.NDArray[np.float64], v: npt.NDArray[np.float64], u0: float, profile: bool, name: str
    ) -> CoreShape: ...
    @property
    def name(self) -> str: ...

def evaluate(
    shape: CoreShape, v: npt.NDArray[np.float64], a: npt.NDArray[np.float64], vhat: bool, tol: float, reduction: bool
) -> npt.NDArray[np.float64]: ...
def point(shape: CoreShape, v: float, a: float, vhat: bool, tol: float) -> Dict[str, Any]: ...
def evaluate_oscillation(
    shape: CoreShape,
    vhat: npt.NDArray[np.float64],
    amp: npt.NDArray[np.float64],
    t: npt.NDArray[np.float64],
    phase: npt.NDArray[np.float64],
    tol: float,
    reduction: bool,
) -> npt.NDArray[np.float64]: ...
def evaluate_system(
    shape: CoreShape,
    x: List[npt.NDArray[np.float64]],
    vhat: bool,
    tangential: bool,
    springs: Optional[int],
    tol: float,
    reduction: bool,
    nan: bool,
) -> npt.NDArray[np.float64]: ...
def evaluate_plane(
    shape: CoreShape,
    x: List[npt.NDArray[np.float64]],
    vhat: bool,
    tangential: bool,
    tol: float,
    reduction: bool,
) -> npt.NDArray[np.float64]: ...
def point_oscillation(
    shape: CoreShape, vhat: float, amp: float, t: float, phase: float, tol: float
) -> Dict[str, Any]: ...
def point_plane(
    shape: CoreShape,
    v: float,
    amp: float,
    vhat: bool,
    tangential: Optional[Tuple[float, float]],
    w: float,
    psi: float,
) -> Dict[str, Any]: ...
def history(
    shape: CoreShape,
    v: float,
    a: float,
    vhat: bool,
    tangential: Optional[Tuple[float, float]],
    periods: int,
    samples: int,
    springs: int,
    spring_at: List[float],
    system: Optional[Tuple[float, float, float]] = None,
    transverse: Optional[Tuple[float, float]] = None,
) -> Dict[str, Any]: ...
def point_system(
    shape: CoreShape,
    vhat: float,
    amp: float,
    t: float,
    phase: float,
    stiffness: float,
    frequency_ratio: float,
    damping: float,
    springs: Optional[int] = None,
) -> Dict[str, Any]: ...
def validate(
    shape: CoreShape,
    names: List[str],
    columns: List[Tuple[str, npt.NDArray[np.float64]]],
    mu0: Optional[float],
    at_rest: str,
    tolerance: float,
    peer: Optional[int],
    peer_springs: Optional[int],
    system: Optional[Tuple[float, float, float]] = None,
    max_error: Optional[float] = None,
) -> Dict[str, Any]: ...
def validate_series(
    shape: CoreShape,
    resolutions: List[float],
    tables: List[Tuple[List[str], List[Tuple[str, npt.NDArray[np.float64]]]]],
    mu0: Optional[float],
    at_rest: str,
    tolerance: float,
    target: Optional[float],
    system: Optional[Tuple[float, float, float]] = None,
) -> Dict[str, Any]: ...
def scene(text: Optional[str], source: str) -> List[Dict[str, Any]]: ...
def validate_history(
    shape: CoreShape,
    time: npt.NDArray[np.float64],
    is_tau: bool,
    tangential: npt.NDArray[np.float64],
    normal: Optional[npt.NDArray[np.float64]],
    v: float,
    a: float,
    vhat: bool,
    oscillation: Optional[Tuple[float, float]],
    omega: Optional[float],
    tolerance: float,
    static_force: float,
    mu0: float,
    system: Optional[Tuple[float, float, float]],
    body: Optional[Tuple[npt.NDArray[np.float64], ...]],
    transverse: Optional[Tuple[float, float]] = None,
    across: Optional[npt.NDArray[np.float64]] = None,
) -> Dict[str, Any]: ...
def default_tol() -> float: ...
def fit(
    shape: CoreShape,
    v0: npt.NDArray[np.float64],
    du: npt.NDArray[np.float64],
    omega: npt.NDArray[np.float64],
    mu: npt.NDArray[np.float64],
    sigma: Optional[npt.NDArray[np.float64]],
    fixed: Tuple[Optional[float], Optional[float], Optional[float]],
    system: Optional[Tuple[float, float, float]] = None,
    load: Optional[npt.NDArray[np.float64]] = None,
    fit_system_stiffness: bool = False,
    bounds: Optional[Tuple[Optional[Tuple[float, float]], ...]] = None,
) -> Dict[str, Any]: ...
