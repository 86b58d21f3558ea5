"""The six suspension parameters of the reference study (SPEC §6.2), with their ranges.

The study states its ranges in engineering units (kN/mm, kN·s/m); the simulator and every array
of :mod:`loco.studies` work in SI (N/m, N·s/m). A :class:`StudyParameter` carries both: ``low``
and ``high`` in the study's unit and the factor ``to_si`` that converts them.

The same type describes any other box of inputs (an analytic test function, for instance), so
sampling, sensitivity, surrogate and optimisation code is one code path for the simulator and for
the tests.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd

__all__ = [
    "STUDY_PARAMETERS",
    "StudyParameter",
    "bounds_si",
    "names",
    "parameter_table",
    "salib_problem",
    "to_si",
    "to_study_units",
]

FloatArray = npt.NDArray[np.float64]

#: kN/mm → N/m.
KN_PER_MM = 1.0e6
#: kN·s/m → N·s/m.
KN_S_PER_M = 1.0e3


@dataclass(frozen=True)
class StudyParameter:
    """One input of a study: its name, range in its own unit and the factor to SI.

    Parameters
    ----------
    name : str
        Name as the simulator knows it (``loco.run_batch`` column name), e.g. ``"K_px"``.
    low, high : float
        Range in ``unit``; ``low < high``.
    unit : str
        Unit of ``low`` and ``high`` (the study's engineering unit), e.g. ``"kN/mm"``.
    si_unit : str
        The SI unit, e.g. ``"N/m"``.
    to_si : float
        Multiply a value in ``unit`` by this to get SI.
    description : str
        One line for tables and figure captions.
    """

    name: str
    low: float
    high: float
    unit: str
    si_unit: str
    to_si: float
    description: str = ""

    def __post_init__(self) -> None:
        if not (np.isfinite(self.low) and np.isfinite(self.high) and self.low < self.high):
            raise ValueError(f"parameter {self.name}: need low < high, got {self.low}, {self.high}")
        if not (np.isfinite(self.to_si) and self.to_si > 0):
            raise ValueError(f"parameter {self.name}: to_si must be > 0, got {self.to_si}")

    @property
    def low_si(self) -> float:
        """Lower bound in SI."""
        return self.low * self.to_si

    @property
    def high_si(self) -> float:
        """Upper bound in SI."""
        return self.high * self.to_si


#: The six parameters of SPEC §6.2, in the order of the spec's table.
STUDY_PARAMETERS: tuple[StudyParameter, ...] = (
    StudyParameter("K_px", 10, 50, "kN/mm", "N/m", KN_PER_MM, "primary longitudinal stiffness"),
    StudyParameter("K_py", 2, 10, "kN/mm", "N/m", KN_PER_MM, "primary lateral stiffness"),
    StudyParameter("C_sx", 200, 1200, "kN·s/m", "N·s/m", KN_S_PER_M, "yaw damper damping"),
    StudyParameter(
        "C_sy", 10, 60, "kN·s/m", "N·s/m", KN_S_PER_M, "secondary lateral damper damping"
    ),
    StudyParameter("K_ncsx", 10, 50, "kN/mm", "N/m", KN_PER_MM, "yaw damper series stiffness"),
    StudyParameter(
        "K_ncsy", 10, 50, "kN/mm", "N/m", KN_PER_MM, "secondary lateral damper series stiffness"
    ),
)


def names(parameters: Sequence[StudyParameter] = STUDY_PARAMETERS) -> list[str]:
    """The parameter names, in order."""
    return [p.name for p in parameters]


def bounds_si(parameters: Sequence[StudyParameter] = STUDY_PARAMETERS) -> FloatArray:
    """A (k, 2) array of [low, high] in SI."""
    return np.array([[p.low_si, p.high_si] for p in parameters], dtype=np.float64)


def _factors(parameters: Sequence[StudyParameter]) -> FloatArray:
    return np.array([p.to_si for p in parameters], dtype=np.float64)


def to_si(
    values: npt.ArrayLike, parameters: Sequence[StudyParameter] = STUDY_PARAMETERS
) -> FloatArray:
    """Values in the study's units, shape (..., k), converted to SI."""
    return np.asarray(values, dtype=np.float64) * _factors(parameters)


def to_study_units(
    values: npt.ArrayLike, parameters: Sequence[StudyParameter] = STUDY_PARAMETERS
) -> FloatArray:
    """SI values, shape (..., k), converted to the study's units."""
    return np.asarray(values, dtype=np.float64) / _factors(parameters)


def salib_problem(parameters: Sequence[StudyParameter] = STUDY_PARAMETERS) -> dict[str, Any]:
    """The SALib problem dict (``num_vars``, ``names``, ``bounds``) with bounds in SI."""
    return {
        "num_vars": len(parameters),
        "names": names(parameters),
        "bounds": bounds_si(parameters).tolist(),
    }


def parameter_table(parameters: Sequence[StudyParameter] = STUDY_PARAMETERS) -> pd.DataFrame:
    """One row per parameter: name, description, range in the study's unit and in SI."""
    return pd.DataFrame(
        {
            "name": [p.name for p in parameters],
            "description": [p.description for p in parameters],
            "low": [p.low for p in parameters],
            "high": [p.high for p in parameters],
            "unit": [p.unit for p in parameters],
            "low_si": [p.low_si for p in parameters],
            "high_si": [p.high_si for p in parameters],
            "si_unit": [p.si_unit for p in parameters],
        }
    )
