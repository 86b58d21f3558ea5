"""``loco simulate``: a short run writes its files, numbers equal to ``loco.simulate``'s, and bad
options are refused before any work."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import loco
from loco import simulation_output as layout
from loco.cli import main

SHORT = ["--scenario", "S_norm", "--speed", "160", "--distance", "40", "--seed", "3"]


def _run(argv: list[str]) -> int:
    return main(["simulate", *argv])


def test_short_run_writes_every_file_with_the_numbers_of_simulate(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "run"
    assert _run([*SHORT, "--yaw-damper", "YD1", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "40 m at 160 km/h" in printed and "m/s²" in printed

    expected = loco.simulate(
        loco.Locomotive.default(),
        loco.Scenario(name="S_norm", speed=160 / 3.6, distance=40.0, seed=3, yaw_damper="YD1"),
    )
    ds = layout.load_histories(out)
    assert np.array_equal(ds["time"].values, expected.time)
    name = "frame1_ay_wheelset1"
    assert np.array_equal(ds[name].values, expected.channel(name))
    assert ds[name].attrs["units"] == "m/s²"
    assert ds["time"].attrs["units"] == "s"

    table = pd.read_parquet(out / layout.HISTORIES_PARQUET)
    assert list(table.columns) == ["time", *expected.channel_names]
    assert np.array_equal(table["wheelset1_y"].to_numpy(), expected.channel("wheelset1_y"))

    metrics = json.loads((out / layout.METRICS_JSON).read_text())
    # 40 m at 160 km/h is under one 5 s Sperling segment: every metric undefined, written null.
    assert set(metrics["metrics"]) == set(expected.metrics)
    assert all(math.isnan(v) for v in expected.metrics.values())
    assert all(v is None for v in metrics["metrics"].values())
    assert metrics["units"]["ayb_peak_lp"] == "m/s²"

    record = json.loads((out / layout.RUN_JSON).read_text())
    assert record["scenario"]["speed"] == pytest.approx(160 / 3.6)
    assert record["scenario"]["yaw_damper"] == "YD1"
    assert record["statistics"]["steps"] == expected.statistics["steps"]
    assert len(record["channels"]) == len(expected.channel_names)
    for file in record["files"]:
        assert (out / file).stat().st_size > 0
    assert layout.ACCELERATION_FIGURE in record["files"]
    assert layout.CURVING_FIGURE not in record["files"]


def test_curve_and_measured_track_add_the_curving_figure(tmp_path: Path) -> None:
    sections = tmp_path / "sections.csv"
    sections.write_text(
        "kind,length_m,radius_m,cant_mm,direction,cant_run_off_m\n"
        "straight,10,,,,\ntransition,20,,,,\ncurve,100,1200,100,left,\n"
    )
    track = tmp_path / "track.csv"
    rows = [f"{0.5 * i:.1f},0.0,{0.3 * math.sin(i / 20)},0.0,0.0" for i in range(400)]
    track.write_text("distance,vertical,alignment,cross_level,gauge\n" + "\n".join(rows) + "\n")
    out = tmp_path / "curve"
    argv = ["--scenario", "S_norm", "--speed", "100", "--distance", "60"]
    assert _run([*argv, "--curve", str(sections), "--track", str(track), "--out", str(out)]) == 0
    record = json.loads((out / layout.RUN_JSON).read_text())
    assert layout.CURVING_FIGURE in record["files"]
    assert record["scenario"]["track"] == str(track)
    ds = layout.load_histories(out)
    # Left curve, 100 mm cant at 100 km/h on R = 1200 m: the vehicle carries a guiding force.
    assert abs(float(ds["wheelset1_sumY"].values[-1])) > 100.0


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--speed", "0"], "--speed: must be > 0"),
        (["--speed", "500"], "--speed: must be <= 400 km/h"),
        (["--speed", "fast"], "--speed: expected a number"),
        (["--distance", "-5"], "--distance: must be > 0"),
        (["--distance", "nan"], "--distance: must be finite"),
        (["--seed", "-1"], "--seed: must be >= 0"),
        (["--lead-in", "-1"], "--lead-in: must be >= 0"),
        (["--scenario", "S_mid"], "--scenario: invalid choice"),
        (["--yaw-damper", "YD3"], "--yaw-damper: invalid choice"),
        (["--track", "missing.csv"], "--track: no such file"),
        (["--curve", "missing.csv"], "--curve: no such file"),
        (["--vehicle", "missing.toml"], "--vehicle: no such file"),
        (["--scenario", "S_low", "--wheel", "jm3-new"], "not allowed with argument"),
        (["--rail", "cn60"], "--rail: needs --wheel"),
        (["--track", "perfect", "--seed", "2"], "--seed: only with a synthetic track"),
    ],
)
def test_bad_options_are_usage_errors_before_any_work(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], argv: list[str], message: str
) -> None:
    out = tmp_path / "never"
    with pytest.raises(SystemExit) as exit_:
        _run([*argv, "--out", str(out)])
    assert exit_.value.code == 2
    assert message in capsys.readouterr().err
    assert not out.exists()


def test_output_on_a_file_and_an_unknown_wheel_are_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(SystemExit) as exit_:
        _run([*SHORT, "--out", str(blocker)])
    assert exit_.value.code == 2
    assert "is a file" in capsys.readouterr().err
    out = tmp_path / "never"
    assert _run(["--wheel", "no-such-wheel", "--out", str(out)]) == 2
    assert "no-such-wheel" in capsys.readouterr().err
    assert not out.exists()
