"""Type stubs of the private native module ``loco._loco`` (checked by ``mypy.stubtest``).

Each section belongs to one binding file of ``crates/loco-py/src``; keep them in that order.
"""

from typing import final

import numpy as np
import numpy.typing as npt

__version__: str
__all__ = ["__version__"]

# --- errors (errors.rs) -------------------------------------------------------------------------

__all__ += [
    "ContactError",
    "DerailmentError",
    "DivergenceError",
    "InternalError",
    "LocoError",
    "LocoIOError",
    "ParameterError",
    "ProfileFormatError",
    "SimulationError",
]

class LocoError(Exception): ...
class ParameterError(LocoError): ...
class ProfileFormatError(LocoError): ...
class LocoIOError(LocoError): ...
class ContactError(LocoError): ...
class SimulationError(LocoError): ...
class DivergenceError(SimulationError): ...
class DerailmentError(SimulationError): ...
class InternalError(LocoError): ...

# --- contact (contact.rs) -----------------------------------------------------------------------

__all__ += [
    "Profile",
    "builtin_profile_named",
    "builtin_profile_names",
    "contact_geometry",
    "load_profile_file",
    "rolling_radius_difference",
]

@final
class Profile:
    def __new__(cls, name: str, kind: str, y: npt.ArrayLike, z: npt.ArrayLike) -> Profile: ...
    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def y(self) -> npt.NDArray[np.float64]: ...
    @property
    def z(self) -> npt.NDArray[np.float64]: ...
    def height(self, y: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def slope(self, y: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def curvature(self, y: npt.ArrayLike) -> npt.NDArray[np.float64]: ...

def load_profile_file(
    path: str, kind: str | None = None, drop_backtracking: bool = False
) -> Profile: ...
def builtin_profile_named(name: str) -> Profile: ...
def builtin_profile_names() -> list[str]: ...
def contact_geometry(
    left_wheel: Profile,
    right_wheel: Profile,
    left_rail: Profile,
    right_rail: Profile,
    ys: npt.ArrayLike,
    *,
    gauge: float,
    gauge_height: float,
    rail_inclination: float,
    back_to_back: float,
    flange_back_offset: float,
    nominal_radius_left: float,
    nominal_radius_right: float,
) -> dict[str, npt.NDArray[np.float64]]: ...
def rolling_radius_difference(
    left_wheel: Profile,
    right_wheel: Profile,
    left_rail: Profile,
    right_rail: Profile,
    ys: npt.ArrayLike,
    *,
    gauge: float,
    gauge_height: float,
    rail_inclination: float,
    back_to_back: float,
    flange_back_offset: float,
    nominal_radius_left: float,
    nominal_radius_right: float,
) -> npt.NDArray[np.float64]: ...

# --- conicity (conicity.rs) ---------------------------------------------------------------------

__all__ += ["conicity_from_delta_r", "kinematic_swing"]

def conicity_from_delta_r(
    y: npt.ArrayLike, dr: npt.ArrayLike, amplitudes: npt.ArrayLike, method: str = "nonlinear"
) -> npt.NDArray[np.float64]: ...
def kinematic_swing(
    y: npt.ArrayLike, dr: npt.ArrayLike, amplitude: float
) -> tuple[float, float, float]: ...

# --- track (track.rs) ---------------------------------------------------------------------------

# --- metrics (metrics.rs) -----------------------------------------------------------------------

# --- dampers (dampers.rs) -----------------------------------------------------------------------
