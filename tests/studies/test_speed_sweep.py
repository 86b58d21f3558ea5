"""The speed sweep of SPEC §6.1 on a tiny setting: two speeds, two tracks, 300 m (5.4 s at
200 km/h, the metrics need 5 s), the real simulator."""

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
    PEAK_METRICS,
    SCENARIOS,
    SpeedSweep,
    SpeedSweepStage,
    run_speed_sweep,
    save_speed_sweep,
)
from loco.studies.stages import Runtime

DISTANCE = 300.0
SEED = 3
TRACKS = 2


@pytest.fixture(scope="module")
def sweep() -> SpeedSweep:
    stage = SpeedSweepStage([180.0], distance=DISTANCE, seed=SEED, n_tracks=TRACKS)
    return run_speed_sweep(stage, Runtime(threads=2, progress=False))


def test_shapes_and_ranges(sweep: SpeedSweep) -> None:
    # The PSD speed (200 km/h) is added to the sweep, speeds sorted.
    np.testing.assert_array_equal(sweep.speeds_kmh, [180.0, 200.0])
    assert sweep.scenarios == SCENARIOS
    assert sweep.metrics.shape == (3, 2, TRACKS, len(sweep.metric_names))
    assert sweep.status.shape == (3, 2, TRACKS) and not sweep.status.any()
    for metric in ("wy_max", "ayb_peak_lp"):
        values = sweep.metric(metric)
        assert values.shape == (3, 2, TRACKS)
        assert np.isfinite(values).all() and (values > 0).all()
        # The tracks differ, so the values do.
        assert (values[..., 0] != values[..., 1]).all()
    assert set(sweep.spectra) == {(s, q) for s in SCENARIOS for q in (A_YC[0], A_YB[0])}
    for sp in sweep.spectra.values():
        assert sp.frequency.shape == sp.density.shape
        assert (sp.density >= 0).all() and sp.peak > 0
        assert 0.2 <= sp.dominant_hz <= sp.frequency[-1]
    # SPEC §1: on new-wheel/low-conicity contact the carbody sways at about 1-1.5 Hz.
    assert 0.5 < sweep.spectra[("S_low", "A_yc")].dominant_hz < 2.5


def test_matches_a_single_run(sweep: SpeedSweep) -> None:
    """Track 0 at 200 km/h is the run loco.simulate makes with YD2 on the track of the seed; the
    sweep's values are the tracks' geometric means, its spectra the track-mean PSDs."""
    scenario = loco.Scenario(name="S_high", speed=200 / 3.6, distance=DISTANCE, seed=SEED,
                             yaw_damper=dampers.YD2)  # fmt: skip
    single = loco.simulate(loco.Locomotive.default(), scenario)
    j = 1  # 200 km/h
    for metric in ("wy_max", "ayb_peak_lp"):
        values = sweep.metric(metric)[2, j]
        assert values[0] == pytest.approx(single.metrics[metric], rel=1e-9)
        # The geometric mean, and the t interval of the logs taken back.
        logs = np.log(values)
        assert sweep.at("S_high", metric, 200.0) == pytest.approx(np.exp(logs.mean()), rel=1e-12)
        ci = sweep.interval("S_high", metric, 200.0)
        half = 12.706 * logs.std(ddof=1) / np.sqrt(2)  # t(0.975, 1 dof)
        assert np.log(ci.high / ci.mean) == pytest.approx(half, rel=1e-4)
        assert np.log(ci.mean / ci.low) == pytest.approx(half, rel=1e-4) and ci.low > 0
    f, p = loco.metrics.psd(single.channel(A_YB[1]), single.sampling_rate)
    mean = sweep.spectra[("S_high", "A_yb")]
    np.testing.assert_allclose(mean.frequency, f)
    assert not np.allclose(mean.density, p)  # the mean of two different tracks
    # The legend's peak is the geometric mean of the core's run metrics over the tracks and its
    # dominant frequency their median, not recomputed in Python.
    peaks = sweep.metric("ayb_psd_peak")[2, j]
    assert peaks[0] == single.metrics["ayb_psd_peak"]
    assert mean.peak == pytest.approx(np.exp(np.log(peaks).mean()), rel=1e-12)
    assert mean.dominant_hz == np.median(sweep.metric(PEAK_METRICS["A_yb"][0])[2, j])


def test_files(sweep: SpeedSweep, tmp_path: Path) -> None:
    record = save_speed_sweep(sweep, tmp_path / "speed_sweep")
    for path in [*record.figures, *record.tables]:
        assert path.is_file() and path.stat().st_size > 0, path
    assert {p.suffix for p in record.figures} == {".png"}
    assert "speed_sweep_peaks.png" in {p.name for p in record.figures}
    table = pd.read_csv(tmp_path / "speed_sweep" / "speed_sweep.csv")
    assert len(table) == 6 * TRACKS and set(table["scenario"]) == set(SCENARIOS)
    assert set(table["track"]) == set(range(TRACKS))
    summary = pd.read_csv(tmp_path / "speed_sweep" / "speed_sweep_summary.csv")
    assert len(summary) == 6 and (summary["n_tracks"] == TRACKS).all()
    row = summary[(summary["scenario"] == "S_low") & (summary["speed_kmh"] == 200.0)].iloc[0]
    ci = sweep.interval("S_low", "wy_max", 200.0)
    assert row["W_y geomean"] == pytest.approx(ci.mean)
    assert row["W_y low"] == pytest.approx(ci.low) and row["W_y high"] == pytest.approx(ci.high)
    assert 0 < row["W_y low"] < row["W_y geomean"] < row["W_y high"]
    peaks = pd.read_csv(tmp_path / "speed_sweep" / "speed_sweep_peaks.csv")
    assert len(peaks) == 6 and (peaks["speed_kmh"] == 200.0).all()
    assert (0 < peaks["psd_peak_low"]).all()
    assert (peaks["psd_peak_low"] < peaks["psd_peak_high"]).all()
    # The dominant frequency is the median of the tracks' values, each of them given (to 3
    # significant digits, hence the tolerance).
    for row in peaks.itertuples():
        each = [float(v) for v in row.dominant_hz_tracks.split(", ")]
        assert len(each) == TRACKS and row.dominant_hz == pytest.approx(np.median(each), rel=1e-2)
    settings = json.loads((tmp_path / "speed_sweep" / "speed_sweep.json").read_text())
    assert settings["loco_version"] == loco.__version__
    assert settings["distance_m"] == DISTANCE and settings["track_seed"] == SEED
    assert settings["n_tracks"] == TRACKS
    assert settings["yaw_damper"]["damping"] == dampers.YD2.parameters()["damping"]
    assert "S_low: W_y" in record.notes
