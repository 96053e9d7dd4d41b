"""Type stubs of pinjoint._native, the Rust half of the package (use `pinjoint` itself)."""

from __future__ import annotations

import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

RESULT_COLUMNS: List[str]
CYCLE_COLUMNS: List[str]
REGIMES: List[str]
VALIDITIES: List[str]
MU_C: str

class Params:
    """Model parameters (SI units), validated; the parameter file's keys and messages."""

    def __init__(self, values: Optional[Union["Params", Mapping[str, Any]]] = None) -> None: ...
    @staticmethod
    def from_toml(path: Union[str, "os.PathLike[str]"]) -> Params:
        """Read a parameter file (TOML, SI units, any subset of keys)."""
    @staticmethod
    def from_toml_str(text: str) -> Params:
        """Parse the text of a parameter file."""
    def to_toml(self) -> str:
        """The complete parameter file; reads back unchanged."""
    def to_dict(self) -> Dict[str, Dict[str, float]]:
        """{section: {key: value}}."""
    def with_values(self, values: Mapping[str, Any]) -> Params:
        """A validated copy with some values changed."""
    @staticmethod
    def keys() -> List[str]:
        """The `section.key` names in file order."""
    def __getitem__(self, name: str) -> float: ...
    def __len__(self) -> int: ...
    def __contains__(self, name: object) -> bool: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[Dict[str, Dict[str, float]]]]: ...

class _Joint:
    def __init__(self, params: Params, fidelity: str, tolerance: float, envelope: Tuple[float, float, float, float]) -> None: ...
    def evaluate_flat(
        self, load: npt.NDArray[np.float64], speed: npt.NDArray[np.float64], shape: Sequence[int]
    ) -> Tuple[Dict[str, npt.NDArray[np.float64]], npt.NDArray[np.uint8]]: ...
    def at_temperature(self, temperature: float) -> "_Joint": ...
    @property
    def chosen(self) -> str: ...
    @property
    def error_bound(self) -> float: ...
    @property
    def fallbacks(self) -> int: ...
    @property
    def capacity(self) -> float: ...
    @property
    def load_edge(self) -> float: ...

def _simulate_cycle(
    params: Union[Params, Mapping[str, Any], str, None],
    rig: Dict[str, Any],
    cycles: int,
    samples_per_cycle: int,
    fidelity: str,
    tolerance: float,
) -> Dict[str, np.ndarray]: ...
def _calibrate(
    records: List[Tuple[str, np.ndarray, Optional[np.ndarray], Optional[np.ndarray], np.ndarray, np.ndarray]],
    params: Union[Params, Mapping[str, Any], str, None],
    fit_keys: List[str],
    inertia: Optional[float],
    fit_offset: bool,
    speed_fraction: Optional[float],
    settle_time: Optional[float],
    half_width: Optional[int],
    resamples: Optional[int],
    seed: Optional[int],
    max_samples: Optional[int] = None,
) -> Tuple[Dict[str, Any], Params]: ...
def param_table() -> List[Dict[str, Any]]:
    """name, symbol, unit, range, default, description, source of every model parameter."""
def rig_param_table() -> List[Dict[str, Any]]:
    """name, unit, range, default, description of every numeric [rig] parameter."""
