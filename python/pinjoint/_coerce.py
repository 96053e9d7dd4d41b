"""Argument coercion shared by Joint and simulate_cycle."""

from __future__ import annotations

import numbers
import os
from typing import Any, Mapping, Union

import numpy as np

from ._native import Params

ParamsLike = Union[Params, Mapping[str, Any], str, "os.PathLike[str]", None]


def as_params(params: ParamsLike) -> Params:
    """A Params from None (the defaults), a Params, a mapping or a TOML file path."""
    if params is None:
        return Params()
    if isinstance(params, Params):
        return params
    if isinstance(params, (str, os.PathLike)):
        return Params.from_toml(params)
    if isinstance(params, Mapping):
        return Params(params)
    raise TypeError(
        f"params must be a pinjoint.Params, a mapping or a TOML file path, not {type(params).__name__}"
    )


def as_float_array(name: str, unit: str, value: Any) -> np.ndarray:
    """A float64 array from a real scalar, list or array.

    Integer and floating dtypes are accepted (converted to float64: exact for float16/32 and
    for integers up to 2**53); bool, complex, string and object data are a TypeError.
    """
    try:
        arr = np.asarray(value)
    except Exception as e:  # ragged lists and the like
        raise ValueError(f"{name} ({unit}) cannot be made into an array: {e}") from None
    kind = arr.dtype.kind
    if kind == "O":
        # E.g. Python numbers mixed with Fractions: real numbers only (None would become NaN).
        bad = [x for x in arr.flat if isinstance(x, (bool, np.bool_)) or not isinstance(x, numbers.Real)]
        if bad:
            raise TypeError(f"{name} ({unit}) must hold real numbers, got {bad[0]!r}")
        arr = arr.astype(np.float64)
        kind = "f"
    if kind == "b":
        raise TypeError(f"{name} ({unit}) must hold real numbers, not booleans")
    if kind not in "iuf":
        raise TypeError(f"{name} ({unit}) must hold real numbers, got dtype {arr.dtype}")
    return arr.astype(np.float64, copy=False)
