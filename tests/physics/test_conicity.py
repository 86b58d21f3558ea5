"""Equivalent conicity from Python: closed forms, the EN 15302 benchmark, the JM3/CN60 scenarios
and the ``loco contact-report`` command."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

import loco
from loco import conicity
from loco.cli import main
from verification_records import record

#: EN 15302 benchmark Δr grids: first lateral point (mm), step 0.1 mm (shared data README).
GRID_START_MM = {1: -6.8, 2: -6.8, 3: -6.8, 4: -7.1, 5: -6.8, 6: -6.9, 7: -6.8, 8: -7.1, 9: -6.8}

#: The study's scenarios (SPEC §2): wheel, nominal tan γe at 3 mm.
SCENARIOS = [("jm3-thin-flange", 0.04), ("jm3-new", 0.10), ("jm3-worn", 0.70)]


def test_conical_wheelset_gives_its_cone_angle_by_both_methods() -> None:
    y = np.linspace(-0.01, 0.01, 201)
    for method in ("nonlinear", "harmonic"):
        tan = conicity.conicity_from_delta_r(y, 2 * 0.15 * y, [1e-3, 3e-3, 7e-3], method)
        np.testing.assert_allclose(tan, 0.15, rtol=1e-9)


def test_bad_inputs_raise_parameter_errors_naming_the_field() -> None:
    y = np.linspace(-0.005, 0.005, 101)
    with pytest.raises(loco.ParameterError, match="amplitude"):
        conicity.conicity_from_delta_r(y, 0.2 * y, [0.006])
    with pytest.raises(loco.ParameterError, match="method"):
        conicity.conicity_from_delta_r(y, 0.2 * y, [0.001], "fourier")
    with pytest.raises(loco.ParameterError, match="dr"):
        conicity.conicity_from_delta_r(y, 0.2 * y[:-1], [0.001])
    with pytest.raises(loco.ParameterError, match="y"):
        conicity.conicity_from_delta_r(y[::-1], 0.2 * y, [0.001])


@pytest.mark.parametrize("case", sorted(GRID_START_MM))
def test_en15302_benchmark_case(shared_data: Path, case: int) -> None:
    """Every amplitude of ``ben_E*.dat`` within both pairs of tolerance limits, from the given
    Δr; amplitudes whose swing leaves the sampled Δr (flange contact) are refused."""
    dr = np.loadtxt(shared_data / "en15302" / f"dr_E{case}.dat").ravel() * 1e-3
    y = (GRID_START_MM[case] + 0.1 * np.arange(dr.size)) * 1e-3
    ref = np.loadtxt(shared_data / "en15302" / f"ben_E{case}.dat")
    checked, worst = 0, 0.0
    for amplitude_mm, tan_ref, hi1, lo1, hi2, lo2 in ref:
        try:
            tan = conicity.conicity_from_delta_r(y, dr, [amplitude_mm * 1e-3])[0]
        except loco.ParameterError as err:
            assert "beyond the Δr samples" in str(err)
            continue
        assert max(lo1, lo2) <= tan <= min(hi1, hi2), (amplitude_mm, tan)
        checked += 1
        worst = max(worst, abs(tan - tan_ref))
    # Every case is covered at least up to 5 mm (50 % of the table and more).
    assert checked >= 41
    (
        record(f"conicity_given_dr_e{case}", __file__)
        .count("amplitudes", checked)
        .value("largest_deviation", worst, "", 2)
        .check()
    )


def test_jm3_states_on_cn60_match_the_scenarios() -> None:
    """EN 15302 at 3 mm within ± min(0.05, 0.5·tan γe) of the study's values. ``jm3-new`` is
    untuned; the thin-flange tread slope and the worn band radius and slope were tuned (see
    ``loco_core::contact::builtin::jm3``)."""
    for wheel, target in SCENARIOS:
        tan = conicity.equivalent_conicity(wheel, "cn60", 0.003)
        assert abs(tan - target) <= min(0.05, 0.5 * target), (wheel, tan)


def test_conicity_curve_has_both_methods_and_agrees_at_3_mm() -> None:
    curve = conicity.conicity_curve("jm3-new", "cn60", [0.001, 0.003, 0.005])
    assert curve.y.shape == curve.delta_r.shape
    assert np.all(np.diff(curve.y) > 0)
    assert curve.nonlinear.shape == curve.harmonic.shape == (3,)
    tan = conicity.equivalent_conicity(loco.profiles.builtin("jm3-new"), "cn60", 0.003)
    # Same Δr up to the contact solver's tolerance (the two grids differ in extent).
    assert curve.at(0.003) == pytest.approx(tan, rel=1e-6)
    # Near-conical tread: both methods close to each other.
    assert curve.at(0.003, "harmonic") == pytest.approx(tan, abs=0.02)


def test_contact_report_writes_figures_and_table(tmp_path: Path) -> None:
    out = tmp_path / "report"
    assert main(["contact-report", "--out", str(out)]) == 0
    for name in ("profiles.png", "delta_r.png", "contact_angle.png", "conicity.png"):
        assert (out / name).stat().st_size > 1000, name
    with (out / "conicity.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert [r["wheel"] for r in rows] == [w for w, _ in SCENARIOS]
    for row, (_, target) in zip(rows, SCENARIOS, strict=True):
        tan = float(row["tan_gamma_e_3mm"])
        assert abs(tan - target) <= min(0.05, 0.5 * target)
        assert row["loco_version"] == loco.__version__
    assert "jm3-worn" in (out / "conicity.md").read_text()
