"""A Dask scheduler's address, checked, and a client connected to it within a bound: the part of
:class:`loco.executors.DaskExecutor` that meets the network. ``distributed`` is optional
(``pip install 'loco[distributed]'``); :func:`require_distributed` names the extra when it is
missing.
"""

from __future__ import annotations

from typing import Any

from loco import _loco
from loco.field_types import wrong_type

__all__ = [
    "CONNECT_TIMEOUT",
    "SCHEDULER_ENV",
    "check_scheduler_address",
    "connect",
    "require_distributed",
]

#: Environment variable naming a running Dask scheduler (the ``distributed`` convention).
SCHEDULER_ENV = "DASK_SCHEDULER_ADDRESS"


def require_distributed() -> Any:
    """The ``distributed`` module, or an :class:`ImportError` naming the extra that installs it."""
    try:
        import distributed
    except ImportError as e:
        raise ImportError(
            "running on a Dask cluster needs the optional dependency `distributed`: "
            "pip install 'loco[distributed]'"
        ) from e
    return distributed


#: How long a connection to a Dask scheduler may take, s: a scheduler on a network answers in
#: well under a second, so a few seconds tell "unreachable" without the client's 30 s default.
CONNECT_TIMEOUT = 5.0


def check_scheduler_address(address: str, origin: str = "scheduler") -> str:
    """``address`` if it is a Dask scheduler address (``tcp://host:port``, ``host:port``, or
    another protocol Dask knows, ``tls://``, ``inproc://``, ...), else a
    :class:`loco.ParameterError` naming ``origin`` (the option or environment variable)."""
    require_distributed()
    from distributed.comm import parse_address
    from distributed.comm.addressing import parse_host_port
    from distributed.comm.registry import backends

    if not isinstance(address, str) or not address.strip():
        raise wrong_type(origin, "a scheduler address such as tcp://host:8786", address)

    def refuse(why: str) -> _loco.ParameterError:
        return _loco.ParameterError(
            f"invalid parameter `{origin}`: {address!r} is not a scheduler address ({why}); "
            "expected e.g. tcp://host:8786"
        )

    try:
        protocol, location = parse_address(address)
        if protocol not in backends:
            raise refuse(f"unknown protocol {protocol!r}; known: {', '.join(sorted(backends))}")
        if protocol != "inproc":
            host, port = parse_host_port(location)
            if not host or any(c.isspace() for c in host) or not 0 < port < 65536:
                raise refuse("a host and a port 1-65535 are needed")
    except (ValueError, TypeError) as e:
        raise refuse(str(e)) from None
    return address


def connect(distributed: Any, address: str) -> Any:
    """A client of the scheduler at ``address``, or a :class:`loco.LocoError` within
    :data:`CONNECT_TIMEOUT` s when it cannot be reached, or when what answers there is not a
    Dask scheduler (a web server's reply read as Dask's frames asks for exabytes)."""
    check_scheduler_address(address)
    try:
        return distributed.Client(address, timeout=f"{CONNECT_TIMEOUT}s")
    except (OSError, TimeoutError) as e:
        raise _loco.LocoError(
            f"cannot reach the Dask scheduler at {address} within {CONNECT_TIMEOUT:g} s: {e}"
        ) from None
    except Exception as e:  # any other failure of the handshake is the address's
        raise _loco.LocoError(
            f"cannot reach the Dask scheduler at {address}: what answers there is not a Dask "
            f"scheduler ({type(e).__name__}: {e})"
        ) from None
