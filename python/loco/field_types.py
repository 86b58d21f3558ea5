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

from loco import _loco

__all__ = ["flag", "pair", "real", "text", "whole", "wrong_type"]

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
