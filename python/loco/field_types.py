"""The Python types of user settings, checked before they reach the core.

The core checks every value (finite, in range, consistent); these functions check the *type*
first, so that a wrong type is a :class:`loco.ParameterError` naming the field instead of a raw
``TypeError``, ``ValueError`` or ``OverflowError`` from ``float()``/``int()`` or PyO3, or a silent
conversion (``True`` read as 1, ``"200"`` as 200.0, ``1.5`` rounded to 1, a complex number losing
its imaginary part).
"""

from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np
import numpy.typing as npt

from loco import _loco

__all__ = ["flag", "names", "pair", "real", "real_array", "text", "whole", "wrong_type"]

#: Largest whole number a setting takes: the largest TOML integer (64-bit signed), the form in
#: which settings reach the core, as the study file's do.
MAX_WHOLE = 2**63 - 1


def wrong_type(name: str, expected: str, value: Any) -> _loco.ParameterError:
    """The error for ``value`` of the field ``name`` not being ``expected``."""
    return _loco.ParameterError(
        f"invalid parameter `{name}`: expected {expected}, got {type(value).__name__} {value!r}"
    )


def real(name: str, value: Any) -> float:
    """``value`` as a float: a real number (int, float, numpy scalar), not a bool, a string or a
    complex number. NaN and infinities pass: the core refuses them with their range."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise wrong_type(name, "a real number", value)
    return float(value)


def whole(name: str, value: Any, low: int = 0, high: int = MAX_WHOLE) -> int:
    """``value`` as an int in ``[low, high]``: an integer, or a float with no fractional part
    (``2.0``), not a bool, ``1.5``, NaN or infinity."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise wrong_type(name, "a whole number", value)
    if isinstance(value, numbers.Integral):
        n = int(value)
    else:
        x = float(value)
        if not math.isfinite(x) or x != math.floor(x):
            raise _loco.ParameterError(
                f"invalid parameter `{name}`: must be a whole number, got {value!r}"
            )
        n = int(x)
    if not low <= n <= high:
        raise _loco.ParameterError(
            f"invalid parameter `{name}`: must be in [{low}, {high}], got {n}"
        )
    return n


def pair(name: str, value: Any) -> tuple[Any, Any]:
    """``value`` as a pair (tuple, list or array of two), not a string."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 2:
        raise wrong_type(name, "a pair of two numbers", value)
    return value[0], value[1]


def text(name: str, value: Any) -> str:
    """``value``, which must be a string (a name)."""
    if not isinstance(value, str):
        raise wrong_type(name, "a name (str)", value)
    return value


def flag(name: str, value: Any) -> bool:
    """``value``, which must be a bool (or numpy bool), not a number or a string."""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return bool(value)
    raise wrong_type(name, "True or False", value)


def real_array(name: str, value: Any) -> npt.NDArray[np.float64]:
    """``value`` as a float64 array: numbers (int, float), not strings, complex numbers, bools,
    objects or ragged lists, which numpy would convert (a complex part dropped, ``"1"`` read as
    1.0) or refuse with a raw error."""
    try:
        array = np.asarray(value)
    except (ValueError, TypeError) as e:
        raise wrong_type(name, "an array of real numbers", value) from e
    if array.dtype.kind not in "iuf":
        raise _loco.ParameterError(
            f"invalid input `{name}`: expected an array of real numbers, got dtype "
            f"{array.dtype} ({_KIND_NAMES.get(array.dtype.kind, 'not numbers')})"
        )
    return np.asarray(array, dtype=np.float64)


#: What a numpy dtype kind that is not a real number holds, for messages.
_KIND_NAMES = {
    "b": "booleans",
    "c": "complex numbers: their imaginary parts would be dropped",
    "U": "strings",
    "S": "bytes",
    "O": "Python objects (mixed types, None, or rows of different lengths)",
    "M": "dates",
    "m": "time spans",
    "V": "records",
}


def names(name: str, value: Any) -> list[str]:
    """``value`` as a list of names: a sequence of strings, not one string (which would be read
    as its characters)."""
    if isinstance(value, (str, bytes)):
        raise _loco.ParameterError(
            f"invalid parameter `{name}`: expected a sequence of names, got the single string "
            f"{value!r} (write [{value!r}] for one)"
        )
    try:
        items = list(value)
    except TypeError:
        raise wrong_type(name, "a sequence of names (str)", value) from None
    for item in items:
        if not isinstance(item, str):
            raise wrong_type(name, "a sequence of names (str)", item)
    return items
