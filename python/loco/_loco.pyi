"""Type stubs of the private native module ``loco._loco`` (checked by ``mypy.stubtest``).

Each section belongs to one binding file of ``crates/loco-py/src``; keep them in that order.
"""

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

# --- metrics (metrics.rs) -----------------------------------------------------------------------

# --- dampers (dampers.rs) -----------------------------------------------------------------------
