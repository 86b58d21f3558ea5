"""Type stubs of the private native module ``loco._loco`` (checked by ``mypy.stubtest``).

Each section belongs to one binding file of ``crates/loco-py/src``; keep them in that order.
"""

import os
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any, ClassVar, final

import numpy as _np
import numpy as np
import numpy.typing as npt
from numpy.typing import NDArray
from numpy.typing import NDArray as _NDArray

__version__: str
__all__ = ["__version__"]

# --- errors (errors.rs) -------------------------------------------------------------------------

__all__ += [
    "ContactError",
    "DerailmentError",
    "DivergenceError",
    "EquilibriumError",
    "FileFormatError",
    "InternalError",
    "LocoError",
    "LocoIOError",
    "ParameterError",
    "ParameterRangeError",
    "ProfileFormatError",
    "SimulationError",
    "TrackFormatError",
    "VehicleFormatError",
]

class LocoError(Exception): ...
class ParameterError(LocoError): ...
class ParameterRangeError(ParameterError): ...
class FileFormatError(LocoError): ...
class ProfileFormatError(FileFormatError): ...
class VehicleFormatError(FileFormatError): ...
class TrackFormatError(FileFormatError): ...
class LocoIOError(LocoError): ...
class ContactError(LocoError): ...
class SimulationError(LocoError): ...
class DivergenceError(SimulationError): ...
class DerailmentError(SimulationError): ...
class EquilibriumError(SimulationError): ...
class InternalError(LocoError): ...

# --- contact (contact.rs) -----------------------------------------------------------------------

__all__ += [
    "LINEAR_PARAMETERS_AMPLITUDE",
    "Profile",
    "WheelsetContact",
    "builtin_profile_named",
    "builtin_profile_names",
    "conical_profiles",
    "contact_setup_defaults",
    "jm3_builtin_states",
    "jm3_tread_profile",
    "load_profile_file",
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
    def smoothed(self, length: float) -> Profile: ...

def load_profile_file(
    path: str, kind: str | None = None, drop_backtracking: bool = False
) -> Profile: ...
def builtin_profile_named(name: str) -> Profile: ...
def builtin_profile_names() -> list[str]: ...
def conical_profiles(conicity: float) -> tuple[Profile, Profile]: ...
def jm3_builtin_states() -> list[tuple[str, float, float, float]]: ...
def jm3_tread_profile(
    tread_slope: float, band_radius: float, flange_thickness: float
) -> Profile: ...
def contact_setup_defaults() -> list[tuple[str, float]]: ...

LINEAR_PARAMETERS_AMPLITUDE: float

@final
class WheelsetContact:
    def __new__(
        cls,
        left_wheel: Profile,
        right_wheel: Profile,
        left_rail: Profile,
        right_rail: Profile,
        *,
        gauge: float,
        gauge_height: float,
        rail_inclination: float,
        back_to_back: float,
        flange_back_offset: float,
        nominal_radius_left: float,
        nominal_radius_right: float,
    ) -> WheelsetContact: ...
    def solve(self, ys: npt.ArrayLike) -> dict[str, npt.NDArray[np.float64]]: ...
    def rolling_radius_difference(self, ys: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def linear_parameters(
        self, amplitude: float = ..., axle_load: float | None = ...
    ) -> list[tuple[str, float]]: ...

# --- conicity (conicity.rs) ---------------------------------------------------------------------

__all__ += ["conicity_from_delta_r", "kinematic_swing"]

def conicity_from_delta_r(
    y: npt.ArrayLike, dr: npt.ArrayLike, amplitudes: npt.ArrayLike, method: str = "nonlinear"
) -> npt.NDArray[np.float64]: ...
def kinematic_swing(
    y: npt.ArrayLike, dr: npt.ArrayLike, amplitude: float
) -> tuple[float, float, float]: ...

# --- creep (creep.rs) ---------------------------------------------------------------------------

__all__ += [
    "CreepSolver",
    "hertz_contact",
    "hertz_stiffness",
    "kalker_coefficients",
    "linear_creep_forces",
    "wheelset_creepages",
]

def hertz_contact(
    normal_force: float,
    r_wheel_rolling: float,
    r_wheel_transverse: float,
    r_rail_transverse: float,
    youngs_modulus: float,
    poisson_ratio: float,
) -> tuple[float, float, float, float]: ...
def hertz_stiffness(
    r_wheel_rolling: float,
    r_wheel_transverse: float,
    r_rail_transverse: float,
    youngs_modulus: float,
    poisson_ratio: float,
) -> float: ...
def kalker_coefficients(a_over_b: float, nu: float) -> tuple[float, float, float, float]: ...
def linear_creep_forces(
    a: float,
    b: float,
    creepage_long: float,
    creepage_lat: float,
    spin: float,
    nu: float,
    shear_modulus: float,
) -> tuple[float, float, float]: ...

@final
class CreepSolver:
    @staticmethod
    def fastsim(
        nu: float,
        shear_modulus: float,
        grid: tuple[int, int],
        bound: str,
        kalker_factor: float,
    ) -> CreepSolver: ...
    @staticmethod
    def fastrip(
        nu: float, shear_modulus: float, grid: tuple[int, int], kalker_factor: float
    ) -> CreepSolver: ...
    def creep_forces(
        self,
        a: float,
        b: float,
        normal_force: float,
        creepages: tuple[float, float, float],
        mu: float,
    ) -> tuple[float, float, float]: ...

def wheelset_creepages(
    speed: float,
    lateral_velocity: float,
    yaw: float,
    yaw_rate: float,
    roll_rate: float,
    spin_rate: float,
    side: str,
    lateral_position: float,
    rolling_radius: float,
    contact_angle: float,
) -> tuple[float, float, float]: ...

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

# --- names (names.rs) ---------------------------------------------------------------------------

__all__ += ["ChannelKind", "Metric", "channel_kinds", "channel_table", "metric_table"]

@final
class Metric:
    """The run metric names as constants, generated from the core's metric table."""

    WY_MEAN: ClassVar[str]
    WY_MAX: ClassVar[str]
    WZ_MEAN: ClassVar[str]
    WZ_MAX: ClassVar[str]
    AYC_RMS: ClassVar[str]
    AYC_PEAK: ClassVar[str]
    AYC_DOMINANT_HZ: ClassVar[str]
    AYC_PSD_PEAK: ClassVar[str]
    AYC_WD_P95: ClassVar[str]
    AZC_WB_P95: ClassVar[str]
    NMV: ClassVar[str]
    AYB_RMS: ClassVar[str]
    AYB_PEAK_LP: ClassVar[str]
    AYB_GBT_CYCLES: ClassVar[str]
    AYB_GBT_UNSTABLE: ClassVar[str]
    AYB_F0_HZ: ClassVar[str]
    AYB_PSD_PEAK: ClassVar[str]
    AYB_EN_RMS: ClassVar[str]
    AYB_EN_LIMIT: ClassVar[str]
    AYB_EN_UNSTABLE: ClassVar[str]
    AYB_LIMIT_CYCLE: ClassVar[str]
    AYB_CYCLE_HZ: ClassVar[str]
    AYB_CYCLE_AMPLITUDE: ClassVar[str]
    AYC_LIMIT_CYCLE: ClassVar[str]
    AYC_CYCLE_HZ: ClassVar[str]
    AYC_CYCLE_AMPLITUDE: ClassVar[str]

@final
class ChannelKind:
    """The kinds of output channels as constants."""

    ACCELERATION: ClassVar[str]
    WHEELSET_MOTION: ClassVar[str]
    WHEEL: ClassVar[str]
    GUIDING_FORCE: ClassVar[str]
    DAMPER_FORCE: ClassVar[str]
    DAMPER_VALVE: ClassVar[str]
    DAMPER_STROKE: ClassVar[str]
    ACCELEROMETER: ClassVar[str]

def channel_kinds() -> list[str]: ...
def metric_table() -> list[tuple[str, str, str, bool]]: ...
def channel_table(vehicle: Vehicle) -> list[tuple[str, str, str]]: ...

# --- dampers (dampers.rs) -----------------------------------------------------------------------

__all__ += [
    "Damper",
    "damper_bench_recorded",
    "damper_bench_sine",
    "damper_bench_sweep",
    "damper_fsd",
    "damper_hydraulic",
    "damper_hydraulic_defaults",
    "damper_maxwell",
    "fsd_reference_stroke_amplitude",
    "fsd_trigger_names",
    "fsd_valve_opening_band",
]

_F64 = _NDArray[_np.float64]
_BenchTuple = tuple[
    _F64, _F64, _F64, _F64, _F64, _F64, tuple[float, float, float] | None, float, _F64
]

@final
class Damper:
    """A validated damper (immutable)."""

    @property
    def kind(self) -> str: ...
    @property
    def n_states(self) -> int: ...
    @property
    def fastest_rate(self) -> float: ...
    def parameters(self) -> dict[str, float | bool | str | None]: ...

def damper_maxwell(
    damping: float,
    series_stiffness: float,
    knee_velocity: float | None = None,
    blow_off_damping: float | None = None,
) -> Damper: ...
def damper_fsd(
    low_damping: float,
    high_damping: float,
    equivalent_mass: float,
    equivalent_stiffness: float,
    cutoff_frequency: float,
    switching_delay: float,
    start_closed: bool,
    hysteresis_ratio: float,
    highpass_corner: float,
    averaging_time: float,
    min_stroke_rms: float,
    warmup_time: float,
    trigger: str,
    reference_stroke_amplitude: float | None,
    orifice_area: float | None,
    aux_piston_area: float | None,
    opening_stroke: float | None,
    spring_stiffness: float | None,
) -> Damper: ...
def fsd_trigger_names() -> list[str]: ...
def fsd_reference_stroke_amplitude() -> float: ...
def fsd_valve_opening_band(damper: Damper, amplitudes: _F64) -> tuple[_F64, _F64]: ...
def damper_hydraulic(
    piston_area: float,
    rod_area: float,
    rebound_orifice_area: float,
    compression_orifice_area: float,
    bottom_valve_area: float,
    oil_density: float,
    oil_kinematic_viscosity: float,
    flow_coefficient: float,
    series_stiffness: float,
    open_area_ratio: float | None,
    cutoff_frequency: float,
    switching_delay: float,
    start_closed: bool,
) -> Damper: ...
def damper_hydraulic_defaults() -> dict[str, float | bool | str | None]: ...
def damper_bench_sine(
    damper: Damper,
    frequency: float,
    amplitude: float,
    cycles: int,
    steps_per_cycle: int,
    samples_per_cycle: int,
    equivalent_cycles: int,
) -> _BenchTuple: ...
def damper_bench_sweep(
    damper: Damper,
    start_frequency: float,
    end_frequency: float,
    amplitude: float,
    duration: float,
    steps_per_cycle: int,
    samples_per_cycle: int,
) -> _BenchTuple: ...
def damper_bench_recorded(damper: Damper, time: _F64, displacement: _F64) -> _BenchTuple: ...

# --- scenario (scenario.rs) -----------------------------------------------------------------------

__all__ += [
    "RunScenario",
    "creep_model_names",
    "integrator_names",
    "integrator_steps",
    "scenario_defaults",
    "scenario_presets",
]

def creep_model_names() -> list[str]: ...
def integrator_names() -> list[str]: ...
def integrator_steps() -> list[tuple[str, float]]: ...
def scenario_defaults() -> dict[
    str, bool | int | float | str | tuple[float, float] | tuple[int, int]
]: ...
def scenario_presets() -> list[tuple[str, str, str]]: ...

@final
class RunScenario:
    """A checked run scenario (SI units)."""

    def __new__(
        cls,
        settings: dict[
            str,
            bool
            | int
            | float
            | str
            | tuple[float, float]
            | tuple[int, int]
            | Sequence[Mapping[str, float | str]],
        ]
        | None = None,
        *,
        wheel: Profile | None = None,
        rail: Profile | None = None,
        track: Track | None = None,
        yaw_damper: Damper | None = None,
    ) -> RunScenario: ...
    @property
    def speed(self) -> float: ...
    @property
    def distance(self) -> float: ...
    @property
    def output_rate(self) -> float: ...

# --- damper presets (damper_presets.rs) -------------------------------------------------------

__all__ += ["compared_dampers", "damper_preset", "damper_preset_names"]

def damper_preset(name: str, trigger: str | None = None) -> Damper: ...
def damper_preset_names() -> list[str]: ...
def compared_dampers() -> list[tuple[str, Damper]]: ...

# --- mode rules (mode_rules.rs) -----------------------------------------------------------------

__all__ += ["least_damped_mode", "mode_rules", "oscillatory_modes", "select_mode"]

def mode_rules() -> list[
    tuple[str, tuple[float, float], tuple[float, float], float, float, float]
]: ...
def select_mode(
    rule: str,
    kinds: list[str],
    frequencies: NDArray[np.float64],
    damping_ratios: NDArray[np.float64],
    shares: NDArray[np.float64],
    motions: NDArray[np.float64],
) -> int | None: ...
def oscillatory_modes(
    re: NDArray[np.float64], im: NDArray[np.float64]
) -> tuple[list[int], list[float], list[float]]: ...
def least_damped_mode(
    frequencies: NDArray[np.float64],
    damping_ratios: NDArray[np.float64],
    band: tuple[float, float],
) -> int | None: ...

# --- input ranges (input_ranges.rs) -------------------------------------------------------------

__all__ += ["default_uncertainty_toml", "input_ranges"]

def default_uncertainty_toml() -> str: ...
def input_ranges(
    vehicle: Vehicle, text: str | None = None, origin: str | None = None
) -> list[tuple[str, float, float, float, str, str, str, str]]: ...

# --- vehicle (vehicle.rs) -----------------------------------------------------------------------

__all__ += [
    "Vehicle",
    "body_motion_names",
    "body_names",
    "default_vehicle_toml",
    "dof_names",
    "flange_contact_angle",
    "linear_critical_speed",
    "linearise",
    "metric_channels",
    "mode_energies",
    "ramp_down",
    "simulate",
    "study_parameters",
    "wheel_channels",
    "wheelset_channels",
]

@final
class Vehicle:
    """A built vehicle: parameter file, overrides and the model built from them."""

    def __new__(
        cls,
        toml_text: str | None = None,
        origin: str = ...,
        overrides: dict[str, float] = ...,
    ) -> Vehicle: ...
    def replace(self, overrides: dict[str, float]) -> Vehicle: ...
    @property
    def toml_text(self) -> str | None: ...
    @property
    def origin(self) -> str: ...
    @property
    def overrides(self) -> dict[str, float]: ...
    def parameters_table(self) -> list[tuple[str, float, str, str]]: ...
    def __getitem__(self, key: str, /) -> float: ...
    def total_mass(self) -> float: ...
    def en14363_bogie_mass(self) -> float: ...
    def mean_axle_load(self) -> float: ...
    def mass_matrix(self) -> NDArray[np.float64]: ...
    def __reduce__(self) -> tuple[type[Vehicle], tuple[str | None, str, dict[str, float]]]: ...

def default_vehicle_toml() -> str: ...
def study_parameters() -> list[tuple[str, str]]: ...
def dof_names() -> list[str]: ...
def body_names() -> list[str]: ...
def metric_channels() -> dict[str, str]: ...
def wheel_channels() -> dict[str, list[str]]: ...
def wheelset_channels() -> dict[str, list[str]]: ...
def flange_contact_angle() -> float: ...
def body_motion_names() -> list[str]: ...
def mode_energies(
    vehicle: Vehicle,
    real: NDArray[np.float64],
    imag: NDArray[np.float64],
) -> tuple[list[str], list[str], NDArray[np.float64], NDArray[np.float64]]: ...
def simulate(
    vehicle: Vehicle,
    scenario: RunScenario,
) -> tuple[
    NDArray[np.float64],
    list[str],
    NDArray[np.float64],
    list[str],
    NDArray[np.float64],
    list[tuple[str, float]],
]: ...
def linearise(
    vehicle: Vehicle,
    scenario: RunScenario,
) -> NDArray[np.float64]: ...
def linear_critical_speed(
    vehicle: Vehicle,
    scenario: RunScenario,
    *,
    low: float | None = None,
    high: float | None = None,
    tolerance: float | None = None,
    band: tuple[float, float] | None = None,
    guess: float | None = None,
) -> tuple[float, str, float, float]: ...
def ramp_down(
    vehicle: Vehicle,
    scenario: RunScenario,
    *,
    end_speed: float | None = None,
    deceleration: float | None = None,
    hold: float | None = None,
    max_hold: float | None = None,
    disturbance: float | None = None,
    window: float | None = None,
    threshold: float | None = None,
) -> tuple[float, str, NDArray[np.float64], NDArray[np.float64]]: ...

# --- parameter schema (schema.rs) ------------------------------------------------------------

__all__ += ["parameter_schema", "retired_parameters"]

def parameter_schema() -> list[tuple[str, str, str, float, float, list[str], str, str, bool]]: ...
def retired_parameters() -> list[tuple[str, str]]: ...

# --- batch (batch.rs) -----------------------------------------------------------------------------

__all__ += ["batch_status_names", "run_batch", "run_statistics_names", "run_study_file"]

def run_batch(
    vehicle: Vehicle,
    scenario: RunScenario,
    params: NDArray[np.float64],
    names: list[str],
    *,
    threads: int = 0,
    per_sample_track: bool = False,
    track_streams: list[int] | None = None,
    histories: list[int] = ...,
    progress: Callable[[int, int], object] | None = None,
) -> tuple[
    list[str],
    NDArray[np.float64],
    NDArray[np.int32],
    list[str],
    list[tuple[int, NDArray[np.float64], list[str], NDArray[np.float64]]],
    NDArray[np.float64],
]: ...
def run_study_file(
    study: str | os.PathLike[str],
    samples: str | os.PathLike[str],
    output: str | os.PathLike[str],
    *,
    threads: int = 0,
    progress: Callable[[int, int, int], object] | None = None,
) -> tuple[int, list[tuple[str, int]], Path, list[Path]]: ...
def batch_status_names() -> list[str]: ...
def run_statistics_names() -> list[str]: ...

# --- frequency response (frequency_response.rs) --------------------------------------------------

__all__ += ["frequency_response", "irregularity_channels", "response_psd"]

def irregularity_channels() -> list[str]: ...
def frequency_response(
    vehicle: Vehicle,
    scenario: RunScenario,
    inputs: list[str],
    outputs: list[str],
    frequencies: NDArray[np.float64],
) -> tuple[NDArray[np.complex128], float, list[float]]: ...
def response_psd(
    vehicle: Vehicle,
    scenario: RunScenario,
    outputs: list[str],
    frequencies: NDArray[np.float64],
    *,
    spectrum: str = ...,
    band: tuple[float, float] = ...,
    amplitude_scale: float = 1.0,
) -> tuple[NDArray[np.float64], NDArray[np.float64], float, float]: ...

# --- input files (text_file.rs) -----------------------------------------------------------------

__all__ += ["read_text_file"]

def read_text_file(path: str, kind: str) -> str: ...
