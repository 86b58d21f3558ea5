"""The package imports, exposes its exception hierarchy and runs its CLI."""

import subprocess
import sys

import loco


def test_version_matches_native_module() -> None:
    assert isinstance(loco.__version__, str)
    assert loco.__version__.count(".") == 2


def test_exception_hierarchy() -> None:
    assert issubclass(loco.ParameterError, loco.LocoError)
    assert issubclass(loco.DivergenceError, loco.SimulationError)
    assert issubclass(loco.DerailmentError, loco.SimulationError)
    assert issubclass(loco.LocoError, Exception)


def test_cli_info() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "loco.cli", "info"], capture_output=True, text=True, check=True
    )
    assert out.stdout.startswith(f"loco {loco.__version__}")
