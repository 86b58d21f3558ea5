"""The curving study's plumbing (``loco.studies.curving``, ``loco curving``) on a small case:
speeds from cant deficiency by hand, the table, files and report note, cases above the speed
cap left out by name, bad options refused."""

from __future__ import annotations

import math
from pathlib import Path

import pandas as pd
import pytest

import loco
from loco import dampers
from loco.cli import main
from loco.studies import curving, en14363
from loco.studies.stages import Runtime

VEHICLE = loco.Locomotive.default()


def test_speed_for_deficiency_by_hand() -> None:
    # R = 1200 m, c = 120 mm, d = 100 mm, 2·b0 = 1.493 m: V = √(9.81·1200·0.22/1.493).
    g = VEHICLE["track.gravity"]
    two_b0 = 2 * VEHICLE["track.contact_point_half_distance"]
    assert two_b0 == pytest.approx(1.493)
    v = curving.speed_for_deficiency(1200.0, 120.0, 100.0, VEHICLE)
    assert v == pytest.approx(math.sqrt(g * 1200.0 * 0.22 / two_b0), rel=1e-12)
    assert v * 3.6 == pytest.approx(149.9, abs=0.1)  # 41.65 m/s


def test_offsets_are_the_wheelset_spacings() -> None:
    # Bogie centres 9 m apart, wheelbase 2.9 m (SPEC §1).
    assert curving.wheelset_offsets(VEHICLE) == pytest.approx([0.0, 2.9, 9.0, 11.9])


@pytest.fixture(scope="module")
def study() -> curving.CurvingStudy:
    sizes = curving.TINY_SIZES
    fast = curving.CurveCase(radius_m=7000.0, cant_mm=30.0, transition_m=60.0, curve_m=40.0)
    stage = curving.CurvingStage(
        curves=(*sizes.curves(), fast),
        deficiencies_mm=(0.0, 100.0, 150.0),
        damper_set={"YD2": dampers.YD2},
        lead_in=sizes.lead_in,
    )
    return curving.run_curving(stage, Runtime(threads=2, progress=False))


def test_table_holds_every_case_below_the_speed_cap(study: curving.CurvingStudy) -> None:
    table = study.table
    # 1200 m: three deficiencies; 7000 m at 150 mm would need 328 km/h (> 300): left out.
    assert len(table) == 5
    assert len(study.skipped) == 1 and "R = 7000 m, d = 150 mm" in study.skipped[0]
    assert (table["speed_kmh"] <= curving.MAX_SPEED_KMH).all()
    r1200 = table[table["radius_m"] == 1200.0].sort_values("deficiency_mm")
    # More cant deficiency, more guiding force on the same curve (Y/Q need not grow: the
    # steering wheelsets' inner wheels carry large Y/Q at balanced cant too).
    assert r1200["sumY_kN"].is_monotonic_increasing
    assert (table["flange_lead_outer"].between(0.0, 1.0)).all()
    assert (table["Tgamma_lead_outer_N"] >= 0.0).all()
    # 2·Q0 is the weight over four wheelsets.
    assert study.axle_load == pytest.approx(VEHICLE.total_mass() * 9.81 / 4, rel=1e-3)


def test_files_and_note(study: curving.CurvingStudy, tmp_path: Path) -> None:
    record = curving.save_curving(study, tmp_path)
    assert [p.name for p in record.figures] == ["curving.png"]
    assert [p.name for p in record.tables] == ["curving.csv"]
    assert (tmp_path / "curving.json").is_file()
    back = pd.read_csv(tmp_path / "curving.csv")
    assert list(back.columns) == list(study.table.columns) and len(back) == len(study.table)
    limit = en14363.sum_y_limit(study.axle_load) / 1e3
    assert f"ΣY {limit:.1f} kN" in record.notes and "Left out" in record.notes


@pytest.mark.parametrize(
    ("option", "value"),
    [("--radius", "500"), ("--deficiency", "250"), ("--deficiency", "a,b"), ("--lead-in", "-1")],
)
def test_bad_options_are_usage_errors(option: str, value: str, tmp_path: Path) -> None:
    with pytest.raises(SystemExit) as e:
        main(["curving", "--out", str(tmp_path), option, value])
    assert e.value.code == 2
