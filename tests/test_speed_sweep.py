"""The speed sweep of SPEC §6.1 on a tiny setting: two speeds, 300 m (5.4 s at 200 km/h, the
metrics need 5 s), the real simulator."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import loco
from loco import dampers
from loco.studies.speed_sweep import (
    A_YB,
    A_YC,
    SCENARIOS,
    SpeedSweep,
    run_speed_sweep,
    save_speed_sweep,
)

DISTANCE = 300.0
SEED = 3


@pytest.fixture(scope="module")
def sweep() -> SpeedSweep:
    return run_speed_sweep([180.0], distance=DISTANCE, seed=SEED, threads=2, progress=False)


def test_shapes_and_ranges(sweep: SpeedSweep) -> None:
    # The PSD speed (200 km/h) is added to the sweep, speeds sorted.
    np.testing.assert_array_equal(sweep.speeds_kmh, [180.0, 200.0])
    assert sweep.scenarios == SCENARIOS
    assert sweep.metrics.shape == (3, 2, len(sweep.metric_names))
    assert sweep.status.shape == (3, 2) and not sweep.status.any()
    for metric in ("wy_max", "ayb_peak_lp"):
        values = sweep.metric(metric)
        assert values.shape == (3, 2)
        assert np.isfinite(values).all() and (values > 0).all()
    assert set(sweep.spectra) == {(s, q) for s in SCENARIOS for q in (A_YC[0], A_YB[0])}
    for sp in sweep.spectra.values():
        assert sp.frequency.shape == sp.density.shape
        assert (sp.density >= 0).all() and sp.peak > 0
        assert 0.2 <= sp.dominant_hz <= sp.frequency[-1]
    # SPEC §1: on new-wheel/low-conicity contact the carbody sways at about 1-1.5 Hz.
    assert 0.5 < sweep.spectra[("S_low", "A_yc")].dominant_hz < 2.5


def test_matches_a_single_run(sweep: SpeedSweep) -> None:
    """The batch row at 200 km/h is the run loco.simulate makes with YD2 on the same track."""
    scenario = loco.Scenario(scenario="S_high", speed=200 / 3.6, distance=DISTANCE, seed=SEED,
                             yaw_damper=dampers.YD2)  # fmt: skip
    single = loco.simulate(loco.Locomotive.default(), scenario)
    for metric in ("wy_max", "ayb_peak_lp"):
        assert sweep.at("S_high", metric, 200.0) == pytest.approx(single.metrics[metric], rel=1e-9)
    f, p = loco.metrics.psd(single.channel(A_YB[1]), single.sampling_rate)
    np.testing.assert_allclose(sweep.spectra[("S_high", "A_yb")].density, p, rtol=1e-9)
    np.testing.assert_allclose(sweep.spectra[("S_high", "A_yb")].frequency, f)
    # The peaks are the core's run metrics, not recomputed in Python.
    assert sweep.spectra[("S_high", "A_yb")].dominant_hz == single.metrics["ayb_f0_hz"]
    assert sweep.spectra[("S_high", "A_yb")].peak == single.metrics["ayb_psd_peak"]


def test_files(sweep: SpeedSweep, tmp_path: Path) -> None:
    record = save_speed_sweep(sweep, tmp_path / "speed_sweep")
    for path in [*record.figures, *record.tables]:
        assert path.is_file() and path.stat().st_size > 0, path
    assert {p.suffix for p in record.figures} == {".png"}
    table = pd.read_csv(tmp_path / "speed_sweep" / "speed_sweep.csv")
    assert len(table) == 6 and set(table["scenario"]) == set(SCENARIOS)
    summary = pd.read_csv(tmp_path / "speed_sweep" / "speed_sweep_summary.csv")
    assert summary.shape == (2, 7)
    assert summary["W_y S_low"].iloc[1] == pytest.approx(sweep.at("S_low", "wy_max", 200.0))
    peaks = pd.read_csv(tmp_path / "speed_sweep" / "speed_sweep_peaks.csv")
    assert len(peaks) == 6 and (peaks["speed_kmh"] == 200.0).all()
    settings = json.loads((tmp_path / "speed_sweep" / "speed_sweep.json").read_text())
    assert settings["loco_version"] == loco.__version__
    assert settings["distance_m"] == DISTANCE and settings["track_seed"] == SEED
    assert settings["yaw_damper"]["damping"] == dampers.YD2.parameters()["damping"]
    assert "S_low: W_y" in record.notes
