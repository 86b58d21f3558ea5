"""loco.dampers: constructors, validation, presets, the bench against closed forms, the FSD
regimes, and the ``loco damper-bench`` command."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import loco
from loco import dampers
from loco.cli import main
from verification_records import record


def test_presets_have_the_spec_values() -> None:
    assert dampers.YD1.kind == "maxwell"
    assert dampers.YD1.parameters()["damping"] == 200e3
    assert dampers.YD2.parameters()["damping"] == 800e3
    assert dampers.YD2.parameters()["series_stiffness"] == 22.5e6
    p = dampers.FSD.parameters()
    assert (p["low_damping"], p["high_damping"]) == (200e3, 800e3)
    assert (p["equivalent_mass"], p["equivalent_stiffness"]) == (15.0, 15e6)
    assert (p["cutoff_frequency"], p["switching_delay"]) == (2.0, 0.05)
    assert dampers.FSD.n_states == 2
    assert dampers.fsd(equivalent_mass=0.0).n_states == 1


@pytest.mark.parametrize(
    ("build", "field"),
    [
        (lambda: dampers.maxwell(-1.0, 22.5e6), "damping"),
        (lambda: dampers.maxwell(200e3, math.nan), "series_stiffness"),
        (lambda: dampers.maxwell(200e3, 22.5e6, knee_velocity=0.02), "knee_velocity"),
        (lambda: dampers.fsd(low_damping=900e3), "low_damping"),
        (lambda: dampers.fsd(cutoff_frequency=0.0), "cutoff_frequency"),
        (lambda: dampers.fsd(switching_delay=-0.1), "switching_delay"),
        (lambda: dampers.hydraulic(rod_area=1.0), "rod_area"),
        (lambda: dampers.hydraulic(open_area_ratio=0.5), "open_area_ratio"),
    ],
)
def test_bad_parameters_raise_a_named_parameter_error(build: object, field: str) -> None:
    with pytest.raises(loco.ParameterError, match=field):
        build()  # type: ignore[operator]


@pytest.mark.parametrize("frequency", [0.5, 1.0, 4.0])
@pytest.mark.parametrize("damper", [dampers.YD1, dampers.YD2], ids=["YD1", "YD2"])
def test_maxwell_bench_matches_closed_form(damper: dampers.Damper, frequency: float) -> None:
    amplitude = 3e-3
    result = dampers.bench(damper, frequency, amplitude, cycles=6)
    p = damper.parameters()
    c, k = float(p["damping"] or 0), float(p["series_stiffness"] or 0)
    ratio = 2 * np.pi * frequency * c / k
    c_closed = c / (1 + ratio**2)
    k_closed = k * ratio**2 / (1 + ratio**2)
    assert result.equivalent_damping == pytest.approx(c_closed, rel=0.01)
    assert result.equivalent_stiffness == pytest.approx(k_closed, rel=0.01)
    energy = np.pi * c_closed * 2 * np.pi * frequency * amplitude**2
    assert result.energy_per_cycle == pytest.approx(energy, rel=0.01)
    assert dampers.maxwell_closed_form(c, k, frequency) == pytest.approx((c_closed, k_closed))
    closed = dampers.maxwell_closed_form(c, k, frequency)
    function_error = max(abs(closed[0] / c_closed - 1), abs(closed[1] / k_closed - 1))
    name = "yd1" if damper is dampers.YD1 else "yd2"
    (
        record(f"maxwell_{name}_{str(frequency).replace('.', 'p')}_hz", __file__)
        .below("c_eff", abs(result.equivalent_damping / c_closed - 1), "", 1e-12, "<", 0.01)
        .below("k_eff", abs(result.equivalent_stiffness / k_closed - 1), "", 1e-12, "<", 0.01)
        .below("energy", abs(result.energy_per_cycle / energy - 1), "", 1e-12, "<", 0.01)
        .below("closed_form_function", function_error, "", 1e-12, "<", 1e-6)
        .check()
    )


def test_bench_returns_consistent_arrays() -> None:
    result = dampers.bench(dampers.YD1, 2.0, 1e-3, cycles=3, samples_per_cycle=100)
    n = 3 * 100 + 1
    for array in (result.time, result.displacement, result.velocity, result.force):
        assert array.shape == (n,) and array.dtype == np.float64
    assert result.time[-1] == pytest.approx(1.5)
    assert np.allclose(result.displacement, 1e-3 * np.sin(2 * np.pi * 2.0 * result.time))
    assert np.all(result.scale_factor == 1.0)  # no valve
    assert np.all(np.isnan(result.estimated_frequency))


@pytest.mark.parametrize(("frequency", "damping"), [(0.5, 200e3), (4.0, 800e3)])
def test_fsd_low_below_and_high_above_cutoff(frequency: float, damping: float) -> None:
    result = dampers.bench(dampers.FSD, frequency, 3e-3, cycles=10)
    c_closed, k_closed = dampers.maxwell_closed_form(damping, 15e6, frequency, 15.0)
    assert result.equivalent_damping == pytest.approx(c_closed, rel=0.01)
    assert result.equivalent_stiffness == pytest.approx(k_closed, rel=0.01)
    assert result.scale_factor[-1] == (1.0 if frequency > 2.0 else 0.0)


def test_fsd_sweep_switches_near_the_cutoff() -> None:
    duration = 40.0
    result = dampers.bench_sweep(dampers.FSD, 0.5, 4.0, 2e-3, duration)
    after = result.time > 2.0
    # The valve opened after the warm-up at low frequency, then closes once on the way up.
    moving = np.flatnonzero(after & (result.scale_factor > 0.0))
    f_switch = 0.5 + 3.5 * result.time[moving[0]] / duration
    assert 2.0 < f_switch < 2.4  # f_p (1 + 10 %) plus the trigger's averaging lag
    assert result.scale_factor[-1] == 1.0


def test_two_tone_cases() -> None:
    t = np.arange(0.0, 20.0, 1e-3)
    stroke = 3e-3 * np.sin(2 * np.pi * t) + 0.3e-3 * np.sin(2 * np.pi * 5.0 * t)
    open_valve = dampers.bench_recorded(dampers.FSD, t, stroke)
    assert np.all(open_valve.scale_factor[t > 2.0] == 0.0)
    drift = 1e-3 * np.sin(2 * np.pi * 5.0 * t) + 3e-3 * np.sin(2 * np.pi * 0.3 * t)
    closed_valve = dampers.bench_recorded(dampers.FSD, t, drift)
    assert np.all(closed_valve.scale_factor == 1.0)


def test_hydraulic_default_and_fsd_variant() -> None:
    plain = dampers.hydraulic()
    assert plain.kind == "hydraulic"
    low = dampers.bench(plain, 1.0, 5e-3, cycles=6)
    assert 5e5 < (low.equivalent_damping or 0) < 7.5e5
    frequency_selective = dampers.hydraulic(open_area_ratio=2.0)
    # Below f_p the valve opens: all flow areas doubled, the turbulent force divided by four.
    soft = dampers.bench(frequency_selective, 0.5, 5e-3, cycles=6)
    plain_soft = dampers.bench(plain, 0.5, 5e-3, cycles=6)
    assert soft.scale_factor[-1] == 0.0
    assert (soft.equivalent_damping or 0) < 0.4 * (plain_soft.equivalent_damping or 0)
    # Above f_p it stays closed and is the plain damper (up to the finer integration step that
    # the open valve's faster pole imposes).
    hard = dampers.bench(frequency_selective, 4.0, 2e-3, cycles=6)
    plain_hard = dampers.bench(plain, 4.0, 2e-3, cycles=6)
    assert np.all(hard.scale_factor == 1.0)
    assert hard.equivalent_damping == pytest.approx(plain_hard.equivalent_damping, rel=1e-5)


def test_bench_rejects_bad_input() -> None:
    with pytest.raises(loco.ParameterError, match="frequency_hz"):
        dampers.bench(dampers.YD1, -1.0, 1e-3)
    with pytest.raises(loco.ParameterError, match="cycles"):
        dampers.bench(dampers.YD1, 1.0, 1e-3, cycles=-2)
    with pytest.raises(loco.ParameterError, match="cycles"):
        dampers.bench(dampers.YD1, 1.0, 1e-3, cycles=2, equivalent_cycles=3)
    with pytest.raises(loco.ParameterError, match="time_s"):
        dampers.bench_recorded(dampers.YD1, [0.0, 1.0, 1.0], [0.0, 0.0, 0.0])


@pytest.mark.slow
def test_damper_bench_command(tmp_path: Path) -> None:
    assert main(["damper-bench", "--out", str(tmp_path)]) == 0
    assert (tmp_path / "damper_bench.png").stat().st_size > 10_000
    parameters = json.loads((tmp_path / "damper_bench_parameters.json").read_text())
    assert parameters["loco_version"] == loco.__version__
    assert set(parameters["dampers"]) == {"YD1", "YD2", "FSD", "FSD-H"}
    assert parameters["amplitude_m"] == 3e-3
    with open(tmp_path / "damper_bench_summary.csv") as f:
        rows = list(csv.DictReader(f))
    assert {(r["damper"], float(r["frequency_hz"])) for r in rows} == {
        (d, f) for d in ("YD1", "YD2", "FSD", "FSD-H") for f in (1.0, 4.0)
    }
    for row in rows:
        measured = float(row["equivalent_damping_nspm"])
        if row["damper"] != "FSD-H":
            assert measured == pytest.approx(float(row["closed_form_damping_nspm"]), rel=0.01)
            continue
        # The hydraulic valve opens for part of each stroke below its cut-off at the bench's
        # 3 mm (amplitude dependent: 8.9 Hz for the valve sized on the 0.26 mm sway stroke) and
        # stays closed above: between the open and closed modules' closed forms, or closed.
        f = float(row["frequency_hz"])
        c1, _ = dampers.maxwell_closed_form(200e3, 15e6, f, 15.0)
        c2, _ = dampers.maxwell_closed_form(800e3, 15e6, f, 15.0)
        _, (cutoff,) = dampers.valve_opening_band(dampers.FSD_HYDRAULIC, [3e-3])
        if f > cutoff:
            assert measured == pytest.approx(c2, rel=0.01)
        else:
            assert c1 * 0.99 < measured < c2 * 0.95
    with open(tmp_path / "damper_bench_loops.csv") as f:
        loops = list(csv.DictReader(f))
    assert {r["damper"] for r in loops} == {"YD1", "YD2", "FSD", "FSD-H"}
    with open(tmp_path / "valve_two_tone.csv") as f:
        two_tone = list(csv.DictReader(f))
    assert {r["trigger"] for r in two_tone} == set(dampers.TRIGGERS)
    assert (tmp_path / "valve_cutoff_vs_amplitude.png").stat().st_size > 10_000


@pytest.mark.slow
def test_the_valve_bench_gives_the_same_tables_on_any_number_of_threads(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # A smaller grid than the stage's: 2 triggers x 2 dither frequencies x 3 ratios, 4 amplitudes.
    from loco.studies import valve_bench

    monkeypatch.setattr(valve_bench, "DITHER_HZ", (5.0, 12.0))
    monkeypatch.setattr(valve_bench, "DITHER_RATIOS", (0.0, 0.1, 1.0))
    monkeypatch.setattr(valve_bench, "AMPLITUDES_M", (1e-5, 1e-4, 2.6e-4, 3e-3))
    one = valve_bench.run_valve_bench(threads=1)
    two = valve_bench.run_valve_bench(threads=2)
    for a, b in ((one.dither, two.dither), (one.band, two.band), (one.histories, two.histories)):
        pd.testing.assert_frame_equal(a, b, check_exact=True)
    assert list(one.dither["dither_ratio"]) == [0.0, 0.1, 1.0] * 4
    # The band is each amplitude's own: NaN where the valve opens nowhere, in order.
    lower, upper = dampers.valve_opening_band(dampers.FSD_HYDRAULIC, [2.6e-4])
    assert one.band["cutoff_hz"].iloc[2] == upper[0]
    assert one.band["lower_hz"].iloc[2] == lower[0]


def test_fsd_trigger_selection_and_valve_errors() -> None:
    assert dampers.TRIGGERS == ("rms-frequency", "hydraulic")
    assert dampers.FSD.parameters()["trigger"] == "rms-frequency"
    assert dampers.describe(dampers.fsd(trigger="hydraulic")) == dampers.describe(
        dampers.FSD_HYDRAULIC
    )
    assert dampers.label(dampers.FSD_HYDRAULIC) == "FSD-H"
    with pytest.raises(loco.ParameterError, match="trigger"):
        dampers.fsd(trigger="zero-crossing")
    with pytest.raises(loco.ParameterError, match="orifice_area"):
        dampers.fsd(trigger="hydraulic", orifice_area=0.0)
    with pytest.raises(loco.ParameterError, match="opening_stroke"):
        dampers.fsd(trigger="hydraulic", opening_stroke=-1e-3)
    with pytest.raises(loco.ParameterError, match="reference_stroke_amplitude"):
        dampers.fsd(trigger="hydraulic", reference_stroke_amplitude=0.0)
    # Derived at another amplitude: the cut-off is f_p there (orbit solver, 1 %).
    damper = dampers.fsd(trigger="hydraulic", reference_stroke_amplitude=1e-3)
    _, cutoff = dampers.valve_opening_band(damper, [1e-3])
    assert cutoff[0] == pytest.approx(2.0, rel=0.01)
    with pytest.raises(loco.ParameterError, match="damper"):
        dampers.valve_opening_band(dampers.FSD, [1e-3])


def test_hydraulic_valve_at_the_vehicle_step() -> None:
    """The vehicle runs the FSD without its mass at 1 ms steps, the valve advanced once per step;
    the bench integrates the full model at microsecond steps: same valve open fraction on the
    two-tone motion, pure sway and with an 8 Hz dither."""
    from loco.studies.valve_bench import open_fraction, two_tone

    full = dampers.FSD_HYDRAULIC
    massless = dampers.fsd(trigger="hydraulic", equivalent_mass=0.0)
    assert massless.fastest_rate * 1e-3 < 1.0  # one RK4 step per 1 ms sample on the bench
    for dither_hz, ratio in ((8.0, 0.0), (8.0, 0.3)):
        t, x = two_tone(dampers.REFERENCE_STROKE_AMPLITUDE, dither_hz, ratio, rate=1000.0)
        fine = open_fraction(dampers.bench_recorded(full, t, x))
        coarse = open_fraction(dampers.bench_recorded(massless, t, x))
        assert fine > 0.1
        assert coarse == pytest.approx(fine, abs=0.01)
