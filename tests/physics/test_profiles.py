"""Profiles from Python: loading (SIMPACK, text), errors, evaluation, built-ins."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import loco
from loco import profiles


def crown(radius: float = 0.3) -> loco.profiles.Profile:
    y = np.linspace(-0.03, 0.03, 601)
    z = np.sqrt(radius**2 - y**2) - radius
    return profiles.Profile("crown", "rail", y, z)


def test_profile_evaluation_of_a_circular_crown() -> None:
    p = crown()
    assert p.kind == "rail" and p.name == "crown"
    assert p.y.shape == (601,) and p.z.dtype == np.float64
    y = np.array([-0.01, 0.0, 0.012])
    np.testing.assert_allclose(p.height(y), np.sqrt(0.09 - y**2) - 0.3, atol=1e-12)
    np.testing.assert_allclose(p.slope(y), -y / np.sqrt(0.09 - y**2), atol=1e-7)
    np.testing.assert_allclose(p.curvature(y), -1 / 0.3, rtol=1e-3)
    with pytest.raises(loco.ParameterError, match="outside"):
        p.height([0.5])


def test_bad_points_raise_parameter_errors() -> None:
    with pytest.raises(loco.ParameterError, match="at least"):
        profiles.Profile("p", "wheel", [0.0, 1.0], [0.0, 0.0])
    with pytest.raises(loco.ParameterError, match="kind"):
        profiles.Profile("p", "axle", np.arange(6.0), np.zeros(6))
    with pytest.raises(loco.ParameterError, match="not finite"):
        profiles.Profile("p", "wheel", np.arange(6.0), [0, 1, np.nan, 3, 4, 5])


def test_text_files_errors_name_file_and_line(tmp_path: Path) -> None:
    jm3 = profiles.builtin("jm3-new")
    points = "".join(f"{y * 1e3:.6f} {z * 1e3:.6f}\n" for y, z in zip(jm3.y, jm3.z, strict=True))
    good = tmp_path / "wheel.txt"
    good.write_text("# y z in mm\n" + points)
    p = profiles.load(good, "wheel")
    assert p.name == "wheel" and p.y[0] == pytest.approx(jm3.y[0], abs=1e-9)
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0\n1 1\n1,5 x\n3 3\n4 4\n")
    with pytest.raises(loco.ProfileFormatError, match=r"bad.txt:3"):
        profiles.load(bad, "wheel")
    cn60 = profiles.builtin("cn60")
    rows = [f"{y * 1e3:.6f} {z * 1e3:.6f}" for y, z in zip(cn60.y, cn60.z, strict=True)]
    rows.insert(2, rows[0])  # a point that goes back in y, on line 3
    unsorted = tmp_path / "unsorted.txt"
    unsorted.write_text("\n".join(rows) + "\n")
    with pytest.raises(loco.ProfileFormatError, match=r"unsorted.txt:3"):
        profiles.load(unsorted, "rail")
    assert len(profiles.load(unsorted, "rail", drop_backtracking=True).y) == len(cn60.y)
    with pytest.raises(loco.ParameterError, match="kind"):
        profiles.load(good)
    with pytest.raises(loco.LocoIOError):
        profiles.load(tmp_path / "missing.txt", "wheel")


def test_simpack_files(shared_data: Path) -> None:
    wheel = profiles.load(shared_data / "profiles" / "MBench_S1002_v3.prw")
    rail = profiles.load(shared_data / "profiles" / "MBench_UIC60_v3.prr", "rail")
    assert wheel.kind == "wheel" and rail.kind == "rail"
    # S1002: flange on the low-y side, about 28 mm below the taping line (z up, m).
    assert wheel.z.min() == pytest.approx(-0.028, abs=5e-4)
    assert wheel.y[np.argmin(wheel.z)] < -0.04
    assert abs(float(wheel.height([0.0])[0])) < 1e-4
    with pytest.raises(loco.ProfileFormatError, match="rail profile was passed"):
        profiles.load(shared_data / "profiles" / "MBench_UIC60_v3.prr", "wheel")


def test_en15302_reference_profiles_load(shared_data: Path) -> None:
    wheel = profiles.load(shared_data / "en15302" / "RUIC519A.dat", "wheel")
    rail = profiles.load(shared_data / "en15302" / "SUIC519A.dat", "rail")
    assert wheel.y[0] == pytest.approx(-0.070)
    assert rail.kind == "rail"


def test_every_reference_profile_is_plausible_as_its_kind_only(shared_data: Path) -> None:
    """The standards' and the benchmark's measured-style profiles pass the plausibility checks as
    what they are and are refused, with the reason, as the other kind."""
    en15302 = shared_data / "en15302"
    wheels = [en15302 / f"RUIC519{c}.dat" for c in "ABHI"]
    for path, kind, other in [
        *((w, "wheel", "rail") for w in wheels),
        (en15302 / "SUIC519A.dat", "rail", "wheel"),
    ]:
        assert profiles.load(path, kind).kind == kind
        reason = "is it a wheel profile" if other == "rail" else "has no flange"
        with pytest.raises(loco.ProfileFormatError, match=f"{path.stem}.*{reason}"):
            profiles.load(path, other)
    # A file that is no profile (a conicity table, three millimetres wide) is named as such.
    with pytest.raises(loco.ProfileFormatError, match="1000 times off"):
        profiles.load(en15302 / "ben_E1.dat", "wheel")


def test_builtin_unknown_name_lists_the_available_ones() -> None:
    assert isinstance(profiles.builtin_names(), list)
    with pytest.raises(loco.ParameterError, match="available"):
        profiles.builtin("no-such-profile")


def test_smoothing_recovers_the_curvature_of_a_rounded_crown() -> None:
    y = np.arange(-222, 223) * 1.35e-4
    z = np.round((np.sqrt(0.09 - y**2) - 0.3) * 1e8) * 1e-8  # rounded to 1e-5 mm
    rough = profiles.Profile("crown", "rail", y, z)
    smooth = rough.smoothed(2e-3)
    probe = np.linspace(-0.01, 0.01, 201)
    assert np.max(np.abs(rough.curvature(probe) + 1 / 0.3)) > 0.5
    np.testing.assert_allclose(smooth.curvature(probe), -1 / 0.3, atol=0.1)
    with pytest.raises(loco.ParameterError, match="smoothing"):
        rough.smoothed(-1.0)
