"""``loco batch``: a study file and a samples CSV run through the core's study reader, the same
numbers as the ``loco-batch`` binary and :func:`loco.run_batch`, and the same errors."""

from __future__ import annotations

import csv
from pathlib import Path

import pandas as pd
import pytest

import loco
from loco.cli import main

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE_STUDY = ROOT / "examples" / "study.toml"
EXAMPLE_SAMPLES = ROOT / "examples" / "samples.csv"


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


def test_the_shipped_example_runs_with_the_numbers_of_run_batch(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "metrics.csv"
    code = main(["batch", str(EXAMPLE_STUDY), str(EXAMPLE_SAMPLES), "-o", str(out), "-t", "2"])
    assert code == 0
    err = capsys.readouterr().err
    assert "2 samples in" in err and "2 ok" in err and "1 time histories" in err
    rows = _rows(out)
    table = pd.read_csv(EXAMPLE_SAMPLES, comment="#")
    expected = loco.run_batch(
        table.to_numpy(dtype=float),
        list(table.columns),
        vehicle=loco.Locomotive.default().replace(C_sy=2.5e4),
        scenario=loco.Scenario(
            name="S_high", speed=200 / 3.6, distance=300.0, seed=1, yaw_damper="YD2"
        ),
        threads=1,
        progress=False,
    )
    assert [r["status"] for r in rows] == ["ok", "ok"]
    for i, row in enumerate(rows):
        got = [float(row[m]) for m in expected.metric_names]
        assert got == expected.metrics[i].tolist(), i
    history = pd.read_csv(tmp_path / "metrics_history_0.csv")
    assert list(history.columns) == ["time", "frame1_ay_wheelset1", "carbody_floor_ay_front"]


def test_errors_name_the_file_and_line_or_the_option(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    study = tmp_path / "study.toml"
    study.write_text("[scenario]\nname = 'S_high'\nspeed = 50.0\ndistanse = 10.0\n")
    assert main(["batch", str(study), str(EXAMPLE_SAMPLES), "-o", str(tmp_path / "m.csv")]) != 0
    err = capsys.readouterr().err
    assert f"{study}:4:" in err and "distanse" in err

    samples = tmp_path / "samples.csv"
    samples.write_text("K_px,K_py\n1.5e7,3.5e6\n1.5e7,abc\n", encoding="utf-8")
    assert main(["batch", str(EXAMPLE_STUDY), str(samples), "-o", str(tmp_path / "m.csv")]) != 0
    err = capsys.readouterr().err
    assert f"{samples}:3" in err and "K_py" in err

    # An output that cannot be written is refused before anything is read or run.
    missing = tmp_path / "missing" / "metrics.csv"
    assert main(["batch", str(EXAMPLE_STUDY), str(EXAMPLE_SAMPLES), "-o", str(missing)]) != 0
    err = capsys.readouterr().err
    assert "--output" in err and "does not exist" in err
    assert not missing.parent.exists()
