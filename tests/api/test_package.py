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
    assert issubclass(loco.EquilibriumError, loco.SimulationError)
    assert not issubclass(loco.EquilibriumError, loco.DivergenceError)
    assert issubclass(loco.LocoError, Exception)


def test_cli_info() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "loco.cli", "info"], capture_output=True, text=True, check=True
    )
    assert out.stdout.startswith(f"loco {loco.__version__}")


def test_bare_import_gives_the_submodules() -> None:
    # A fresh interpreter: the README's `loco.contact...` and `loco.metrics...` after `import loco`.
    code = (
        "import loco, numpy as np; "
        "c = loco.contact.equivalent_conicity('jm3-worn', 'cn60'); "
        "t = np.arange(0, 10, 1 / 500); "
        "w = loco.metrics.sperling(0.1 * np.sin(2 * np.pi * 2 * t), fs=500.0); "
        "print(type(c).__name__, type(w).__name__, loco.dampers.YD1, loco.track.__name__)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "Damper(maxwell" in out.stdout, out.stdout


def test_objects_print_readably() -> None:
    yd2 = repr(loco.dampers.YD2)
    assert yd2 == "Damper(maxwell, c=800 kN·s/m, k_series=22.5 kN/mm)", yd2
    fsd = repr(loco.dampers.FSD)
    assert fsd.startswith("Damper(fsd, c1=200 kN·s/m, c2=800 kN·s/m, f_p=2 Hz"), fsd
    scenario = loco.Scenario(name="S_high", speed=50.0, yaw_damper=loco.dampers.YD2)
    assert repr(scenario) == f"Scenario(name='S_high', speed=50.0, yaw_damper={yd2})"
    assert repr(loco.Scenario()) == "Scenario()"
    assert repr(loco.Locomotive.default()) == "Locomotive(default vehicle)"
    assert repr(loco.Locomotive.default().replace(C_sx=2e5)) == (
        "Locomotive(default vehicle, overrides={'C_sx': 200000.0})"
    )


def test_the_studies_package_names_every_module_it_has() -> None:
    """Each module of ``loco.studies`` is in its ``__all__`` and named in its docstring (which
    says which stage it belongs to), so a new module cannot be left out of the map."""
    from pathlib import Path

    import loco.studies as studies

    folder = Path(studies.__file__).parent
    modules = sorted(p.stem for p in folder.glob("*.py") if p.stem != "__init__")
    assert sorted(studies.__all__) == modules
    doc = studies.__doc__ or ""
    missing = [m for m in modules if f"loco.studies.{m}`" not in doc.replace("\n  ", "")]
    assert not missing, f"modules the loco.studies docstring does not name: {missing}"
