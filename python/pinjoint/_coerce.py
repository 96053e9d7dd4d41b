"""Argument coercion shared by Joint and simulate_cycle."""

from __future__ import annotations

import numbers
import os
from typing import Any, Mapping, Union

import numpy as np

from ._native import Params

ParamsLike = Union[Params, Mapping[str, Any], str, "os.PathLike[str]", None]

#: The most characters of an input that a message quotes (as the library's
#: ``pinjoint_numfmt::EXCERPT_CHARS``).
EXCERPT_CHARS = 200


def short(value: Any) -> str:
    """``repr(value)`` as a message may quote it: at most EXCERPT_CHARS characters, then how
    many were left out (an int too large to print shows its size instead)."""
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 64:
        return f"(an int of about {int(value.bit_length() * 0.30103) + 1} digits)"
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 - a repr that raises is shown as such
        return f"(a {type(value).__name__} without repr)"
    if len(text) <= EXCERPT_CHARS:
        return text
    return f"{text[:EXCERPT_CHARS]}... ({len(text) - EXCERPT_CHARS} more characters)"


def magnitude(load: Any) -> Any:
    """The load as the model takes it: a real number's magnitude (a signed reaction
    component -P gives the answer at +P); anything else unchanged, for the library to name."""
    if isinstance(load, numbers.Real) and not isinstance(load, bool):
        return abs(load)
    return load


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
            raise TypeError(f"{name} ({unit}) must hold real numbers, got {short(bad[0])}")
        arr = arr.astype(np.float64)
        kind = "f"
    if kind == "b":
        raise TypeError(f"{name} ({unit}) must hold real numbers, not booleans")
    if kind not in "iuf":
        raise TypeError(f"{name} ({unit}) must hold real numbers, got dtype {arr.dtype}")
    return arr.astype(np.float64, copy=False)
