"""Type stubs of the private native module ``loco._loco`` (checked by ``mypy.stubtest``).

Each section belongs to one binding file of ``crates/loco-py/src``; keep them in that order.
"""

from typing import Any, final

import numpy as np
from numpy.typing import NDArray

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

# --- track (track.rs) ---------------------------------------------------------------------------

__all__ += [
    "Track",
    "load_track",
    "synthesize_track",
    "track_spectrum_psd",
    "track_spectrum_variance",
]

@final
class Track:
    @property
    def length(self) -> float: ...
    @property
    def step(self) -> float: ...
    @property
    def run_in(self) -> float: ...
    @property
    def spectrum(self) -> str | None: ...
    def distance(self) -> NDArray[np.float64]: ...
    def channel(self, name: str) -> NDArray[np.float64]: ...
    def rail(self, name: str) -> NDArray[np.float64]: ...
    def at(
        self, s: float
    ) -> tuple[tuple[float, float, float, float], tuple[float, float, float, float]]: ...

def synthesize_track(
    spectrum: str,
    length: float,
    seed: int,
    stream: int,
    wavelength_min: float,
    wavelength_max: float,
    step: float,
    run_in: float,
) -> Track: ...
def load_track(
    path: str,
    step: float | None = None,
    run_in: float = 30.0,
    required_length: float | None = None,
) -> Track: ...
def track_spectrum_psd(
    spectrum: str, channel: str, f: NDArray[np.float64]
) -> NDArray[np.float64]: ...
def track_spectrum_variance(spectrum: str, channel: str, f_lo: float, f_hi: float) -> float: ...

# --- metrics (metrics.rs) -----------------------------------------------------------------------

__all__ += [
    "bogie_stability",
    "comfort_nmv",
    "dominant_frequency",
    "locomotive_ride_rating",
    "run_metric_names",
    "run_metrics",
    "sperling",
    "weighted_rms",
    "welch_psd",
]

def welch_psd(
    x: NDArray[np.float64], fs: float, segment_len: int | None = None, overlap: float = 0.5
) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...
def dominant_frequency(
    x: NDArray[np.float64],
    fs: float,
    f_min: float,
    f_max: float,
    segment_len: int | None = None,
    overlap: float = 0.5,
) -> tuple[float, float]: ...
def sperling(
    acc: NDArray[np.float64],
    fs: float,
    direction: str,
    segment_duration: float = 5.0,
    f_min: float = 0.5,
    f_max: float = 40.0,
) -> tuple[NDArray[np.float64], float, float]: ...
def locomotive_ride_rating(w: float) -> str: ...
def bogie_stability(
    acc: NDArray[np.float64], fs: float, speed: float, bogie_mass: float
) -> dict[str, Any]: ...
def weighted_rms(
    acc: NDArray[np.float64], fs: float, weighting: str
) -> tuple[NDArray[np.float64], float, float]: ...
def comfort_nmv(
    fs: float,
    ax: NDArray[np.float64] | None = None,
    ay: NDArray[np.float64] | None = None,
    az: NDArray[np.float64] | None = None,
) -> float: ...
def run_metric_names() -> list[str]: ...
def run_metrics(
    fs: float,
    speed: float,
    carbody_lateral: NDArray[np.float64],
    bogie_lateral: NDArray[np.float64],
    bogie_mass: float,
    carbody_vertical: NDArray[np.float64] | None = None,
) -> NDArray[np.float64]: ...

# --- dampers (dampers.rs) -----------------------------------------------------------------------
