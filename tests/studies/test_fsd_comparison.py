"""The yaw damper comparison of SPEC §6.6 on a tiny setting: YD1, YD2 and FSD on S_low and
S_high over 300 m at 200 km/h on two tracks, the real simulator."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import loco
from loco.studies.fsd_comparison import (
    CASES,
    DAMPERS,
    LEAD_IN,
    FsdComparison,
    FsdComparisonStage,
    run_fsd_comparison,
    save_fsd_comparison,
    valve_channels,
    valve_closed_fraction,
    valve_open_fractions,
)
from loco.studies.stages import Runtime

TRACKS = 2


@pytest.fixture(scope="module")
def comparison() -> FsdComparison:
    stage = FsdComparisonStage(distance=300.0, seed=2, n_tracks=TRACKS)
    return run_fsd_comparison(stage, Runtime(threads=2, progress=False))


def test_runs_and_table(comparison: FsdComparison) -> None:
    assert comparison.dampers == ("YD1", "YD2", "FSD", "FSD-H")
    assert not comparison.errors
    assert set(comparison.results) == {(s, d) for s, _, _ in CASES for d in DAMPERS}
    table = comparison.table()
    assert len(table) == 8
    assert list(table["quantity"]) == ["A_yc"] * 4 + ["A_yb"] * 4
    assert (table["dominant_hz"] > 0.2).all() and (table["psd_peak"] > 0).all()
    assert (table["rms"] > 0).all() and (table["error"] == "").all()
    assert (table["n_tracks"] == TRACKS).all()
    assert (table["psd_peak_low"] < table["psd_peak"]).all()
    assert (table["psd_peak"] < table["psd_peak_high"]).all()
    # The table summarises the core's run metrics of the case's quantity over the tracks;
    # track 0 is the single run on the seed's track.
    result = comparison.results[("S_high", "YD1")]
    assert result is not None
    single = loco.simulate(
        loco.Locomotive.default(),
        loco.Scenario(name="S_high", distance=300.0, lead_in=LEAD_IN, seed=2,
                      yaw_damper=DAMPERS["YD1"]),
    )  # fmt: skip
    assert single.metrics["ayb_psd_peak"] == result.metrics["ayb_psd_peak"]
    runs = comparison.runs[("S_high", "YD1")]
    row = table[(table["scenario"] == "S_high") & (table["damper"] == "YD1")].iloc[0]
    # The dominant frequency as the median with each track's value; the positive quantities as
    # geometric means.
    assert row["dominant_hz"] == pytest.approx(np.median(runs.values("ayb_f0_hz")))
    assert row["dominant_hz_tracks"] == ", ".join(f"{v:.3g}" for v in runs.values("ayb_f0_hz"))
    for column, metric in (("psd_peak", "ayb_psd_peak"), ("rms", "ayb_rms")):
        geometric = np.exp(np.log(runs.values(metric)).mean())
        assert row[column] == pytest.approx(geometric)
        assert 0 < row[f"{column}_low"] < row[column] < row[f"{column}_high"]
    assert runs.values("ayb_psd_peak")[0] == result.metrics["ayb_psd_peak"]
    # The dampers were applied: the three runs of a scenario differ.
    for scenario, _, channel in CASES:
        signals = [comparison.results[(scenario, d)] for d in DAMPERS]
        a, b, c, *_ = (r.channel(channel) for r in signals if r is not None)
        assert not np.array_equal(a, b) and not np.array_equal(b, c)


def test_valves(comparison: FsdComparison) -> None:
    table = comparison.table()
    fsd = table[table["damper"] == "FSD"]["valve_closed_fraction"]
    assert fsd.between(0.0, 1.0).all()
    others = ~table["damper"].isin(["FSD", "FSD-H"])
    assert table[others]["valve_closed_fraction"].isna().all()
    # Open fractions per damper and per bogie: complements of the table's closed fraction.
    openings = valve_open_fractions(comparison)
    for (scenario, damper), g in openings.groupby(["scenario", "damper"]):
        per_damper = g[g["valve"] != g["bogie"]]
        assert len(per_damper) == 4 and set(g[g["valve"] == g["bogie"]]["valve"]) == {
            "bogie1",
            "bogie2",
        }
        # The open fractions are those of track 0's run (the table's closed fraction is the
        # mean over the tracks).
        run = comparison.results[(scenario, damper)]
        assert run is not None
        assert 1.0 - per_damper["open_fraction"].mean() == pytest.approx(valve_closed_fraction(run))
        bogie1 = per_damper[per_damper["bogie"] == "bogie1"]["open_fraction"].mean()
        assert g[g["valve"] == "bogie1"]["open_fraction"].iloc[0] == pytest.approx(bogie1)
    for scenario, _, _ in CASES:
        result = comparison.results[(scenario, "FSD")]
        assert result is not None
        names = valve_channels(result)
        assert len(names) == 4  # one yaw damper per side per bogie
        values = np.stack([result.channel(n) for n in names])
        assert values.min() >= 0.0 and values.max() <= 1.0


def test_rankings(comparison: FsdComparison) -> None:
    rankings = comparison.rankings()
    assert [(r.label, r.metric) for r in rankings] == [
        ("S_low", "PSD peak of A_yc"),
        ("S_low", "wy_max"),
        ("S_high", "PSD peak of A_yb"),
        ("S_high", "ayb_peak_lp"),
    ]
    pairs = len(DAMPERS) * (len(DAMPERS) - 1) // 2
    for r in rankings:
        assert sorted(r.order) == sorted(DAMPERS) and len(r.tests) == pairs
        means = [r.means[d] for d in r.order]
        assert means == sorted(means)
        for t in r.tests:
            assert t.n == TRACKS and 0.0 <= t.p_t <= t.p_holm <= 1.0
    frame = comparison.rankings_frame()
    assert len(frame) == 4 * pairs and set(frame["ranking_significant"]) <= {True, False}


def test_files(comparison: FsdComparison, tmp_path: Path) -> None:
    out = tmp_path / "fsd_comparison"
    record = save_fsd_comparison(comparison, out)
    for path in [*record.figures, *record.tables]:
        assert path.is_file() and path.stat().st_size > 0, path
    names = {p.name for p in record.figures}
    assert names == {
        "fsd_time_histories.png",
        "fsd_psd.png",
        "fsd_peaks.png",
        "fsd_valve.png",
        "fsd_valve_hydraulic.png",
    }
    tracks = pd.read_csv(out / "fsd_tracks.csv")
    assert len(tracks) == 2 * len(DAMPERS) * TRACKS
    assert set(tracks["track"]) == set(range(TRACKS))
    assert "ranking" in record.notes and record.notes.count("significant at") == 4
    histories = pd.read_csv(out / "fsd_time_histories.csv")
    result = comparison.results[("S_low", "FSD")]
    assert result is not None
    assert len(histories) == len(result.time)
    # 4 valves x 2 scenarios x 2 FSDs (rms-frequency and hydraulic trigger)
    assert sum(c.endswith("_valve") for c in histories.columns) == 16
    assert {"S_low_YD1_A_yc", "S_high_FSD_A_yb"} <= set(histories.columns)
    psd = pd.read_csv(out / "fsd_psd.csv")
    assert set(zip(psd["scenario"], psd["damper"], strict=True)) == set(comparison.results)
    settings = json.loads((out / "fsd_comparison.json").read_text())
    assert settings["loco_version"] == loco.__version__ and settings["speed_kmh"] == 200.0
    assert settings["dampers"]["FSD"]["kind"] == "fsd"
    assert settings["n_tracks"] == TRACKS and settings["lead_in_m"] == LEAD_IN
