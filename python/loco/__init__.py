"""loco: railway vehicle dynamics toolkit (Rust core, Python front end).

The native module ``loco._loco`` is private; use the submodules of this package:
``loco.profiles``, ``loco.contact``, ``loco.track``, ``loco.metrics``, ``loco.dampers``, and the
vehicle API re-exported here: :class:`Locomotive`, :class:`Scenario`, :func:`simulate`,
:func:`run_batch`.
"""

# The submodules, so that `import loco` is enough for `loco.contact.…`, `loco.metrics.…`
# (`loco.studies` pulls in the study dependencies and is imported on its own).
from loco import (
    assessment,
    batch,
    channels,
    conicity,
    contact,
    creep,
    dampers,
    metrics,
    modes,
    profiles,
    schema,
    simulation,
    stability,
    track,
    track_response,
    uncertainty,
    vehicle,
)
from loco._loco import (
    ContactError,
    DerailmentError,
    DivergenceError,
    EquilibriumError,
    FileFormatError,
    InternalError,
    LocoError,
    LocoIOError,
    ParameterError,
    ParameterRangeError,
    ProfileFormatError,
    SimulationError,
    TrackFormatError,
    VehicleFormatError,
    __version__,
)
from loco.assessment import Assessment, assess
from loco.batch import BatchResult, run_batch
from loco.channels import ChannelKind, Metric
from loco.schema import ParameterSpec, parameter_schema, retired_parameters
from loco.simulation import Scenario, SimulationResult, simulate
from loco.stability import critical_speed, eigen
from loco.track_response import (
    FrequencyResponse,
    ResponsePsd,
    frequency_response,
    response_psd,
)
from loco.vehicle import Locomotive

__all__ = [
    "Assessment",
    "BatchResult",
    "ChannelKind",
    "ContactError",
    "DerailmentError",
    "DivergenceError",
    "EquilibriumError",
    "FileFormatError",
    "FrequencyResponse",
    "InternalError",
    "LocoError",
    "LocoIOError",
    "Locomotive",
    "Metric",
    "ParameterError",
    "ParameterRangeError",
    "ParameterSpec",
    "ProfileFormatError",
    "ResponsePsd",
    "Scenario",
    "SimulationError",
    "SimulationResult",
    "TrackFormatError",
    "VehicleFormatError",
    "__version__",
    "assess",
    "assessment",
    "batch",
    "channels",
    "conicity",
    "contact",
    "creep",
    "critical_speed",
    "dampers",
    "eigen",
    "frequency_response",
    "metrics",
    "modes",
    "parameter_schema",
    "profiles",
    "response_psd",
    "retired_parameters",
    "run_batch",
    "schema",
    "simulate",
    "simulation",
    "stability",
    "track",
    "track_response",
    "uncertainty",
    "vehicle",
]
