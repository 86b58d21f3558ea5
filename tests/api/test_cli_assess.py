"""``loco assess DIR`` on what ``loco simulate`` wrote: the table equals ``loco.assess`` on the
same run simulated in Python, and a directory that is not a run's output is an error naming the
missing file."""

from __future__ import annotations

import math
from pathlib import Path

import pandas as pd
import pytest

import loco
from loco.cli import main
from loco.commands import assess as command

RADIUS, CANT_MM, DEFICIENCY_MM = 1200.0, 50.0, 100.0
CURVE = [
    {"kind": "straight", "length_m": 50.0},
    {"kind": "transition", "length_m": 80.0},
    {"kind": "curve", "length_m": 200.0, "radius_m": RADIUS, "cant_mm": CANT_MM,
     "direction": "left"},
]  # fmt: skip


def test_assess_reads_a_simulate_output_and_writes_the_table_of_loco_assess(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    speed = math.sqrt(9.81 * RADIUS * (CANT_MM + DEFICIENCY_MM) * 1e-3 / (2 * 0.7465))
    sections = tmp_path / "sections.csv"
    pd.DataFrame(CURVE).to_csv(sections, index=False)
    run = tmp_path / "run"
    argv = ["simulate", "--scenario", "S_norm", "--speed", f"{speed * 3.6!r}", "--distance",
            "320", "--track", "perfect", "--curve", str(sections), "--no-figures", "--out",
            str(run)]  # fmt: skip
    assert main(argv) == 0
    assert main(["assess", str(run)]) == 0
    printed = capsys.readouterr().out
    assert "curve R = 1200 m" in printed and "every assessed quantity passes" in printed
    table = pd.read_csv(run / command.TABLE)
    assert (run / command.FIGURE).stat().st_size > 0

    result = loco.simulate(
        loco.Locomotive.default(),
        loco.Scenario(name="S_norm", speed=speed, distance=320.0, curve=CURVE, track="perfect"),
    )
    expected = loco.assess(result, curve=CURVE).frame()
    assert list(table["quantity"]) == list(expected["quantity"])
    assert list(table["zone"]) == list(expected["zone"])
    pd.testing.assert_series_equal(table["value"], expected["value"], rtol=1e-5)


def test_a_directory_without_a_run_is_an_error_naming_the_missing_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["assess", str(tmp_path)]) == 1
    assert "histories.nc: missing" in capsys.readouterr().err
