"""The standalone ``loco-batch`` binary gives the same numbers as ``loco.run_batch``."""

from __future__ import annotations

import csv
import os
import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import loco

ROOT = Path(__file__).resolve().parents[2]
BINARY = Path(os.environ.get("LOCO_BATCH_BIN", ROOT / "target" / "release" / "loco-batch"))

pytestmark = pytest.mark.skipif(
    not BINARY.is_file(),
    reason=f"loco-batch binary not built ({BINARY}); `cargo build --release -p loco-batch`",
)

STUDY = """
[vehicle]
allow_out_of_range = ["K_py"]  # the third sample's 3.5e13 N/m, which diverges

[vehicle.overrides]
C_sy = 3.0e4

[scenario]
name = "S_high"
speed_kmh = 200.0
distance = 295.0
seed = 5
yaw_damper = "FSD"

[output]
histories = [1]
channels = ["frame1_ay_wheelset1", "yaw_damper_bogie1_left_valve"]
"""

PARAMS = np.array([[1.5e7, 3.5e6], [3.0e7, 6.0e6], [1.5e7, 3.5e13]])
NAMES = ["K_px", "K_py"]


def _write_inputs(tmp: Path) -> tuple[Path, Path]:
    study = tmp / "study.toml"
    study.write_text(STUDY, encoding="utf-8")
    samples = tmp / "samples.csv"
    rows = [",".join(NAMES)] + [",".join(repr(float(v)) for v in row) for row in PARAMS]
    samples.write_text("# two study parameters, SI\n" + "\n".join(rows) + "\n", encoding="utf-8")
    return study, samples


def _batch(*args: str | Path) -> subprocess.CompletedProcess[str]:
    """``loco-batch`` with ``args``, its output captured."""
    command = [str(BINARY), *map(str, args)]
    return subprocess.run(command, capture_output=True, text=True, check=False)


def _rows(path: Path) -> list[dict[str, str]]:
    """The rows of a metrics file the binary wrote."""
    with path.open(encoding="utf-8") as f:
        return list(csv.DictReader(f))


def test_binary_matches_python_bit_for_bit(tmp_path: Path) -> None:
    study, samples = _write_inputs(tmp_path)
    out = tmp_path / "metrics.csv"
    done = _batch(study, samples, "-o", out, "--threads", "2", "--quiet")
    assert done.returncode == 0, done.stderr
    rows = _rows(out)

    allowed = 'allow_out_of_range = ["rotary_arm.node_stiffness_lateral"]\n'
    vehicle = loco.Locomotive(toml_text=allowed + loco.Locomotive.default().default_toml())
    vehicle = vehicle.replace(C_sy=3.0e4)
    scenario = loco.Scenario(
        name="S_high", speed=200 / 3.6, distance=295.0, seed=5, yaw_damper=loco.dampers.FSD
    )
    expected = loco.run_batch(
        PARAMS, NAMES, vehicle=vehicle, scenario=scenario, threads=1, progress=False, histories=[1]
    )
    assert [r["status"] for r in rows] == ["ok", "ok", expected.to_frame()["status"][2]]
    for i, row in enumerate(rows):
        got = np.array([float(row[m]) for m in expected.metric_names])
        assert np.array_equal(got, expected.metrics[i], equal_nan=True), (i, row["message"])
    # Run statistics columns: the same counts as the Python batch (wall time differs).
    assert expected.statistics is not None
    for i, row in enumerate(rows):
        for j, name in enumerate(loco.simulation.RUN_STATISTICS[:3]):
            assert float(row[name]) == expected.statistics[i, j], (i, name)
        assert float(row["wall_time"]) > 0.0

    history = np.genfromtxt(tmp_path / "metrics_history_1.csv", delimiter=",", names=True)
    kept = expected.histories[1]
    assert np.array_equal(history["time"], kept.time)
    assert np.array_equal(history["frame1_ay_wheelset1"], kept.channel("frame1_ay_wheelset1"))


def test_binary_reports_malformed_samples_with_file_and_line(tmp_path: Path) -> None:
    study, samples = _write_inputs(tmp_path)
    samples.write_text("K_px,K_py\n1.5e7,3.5e6\n1.5e7,abc\n", encoding="utf-8")
    done = _batch(study, samples, "-o", tmp_path / "m.csv", "--quiet")
    assert done.returncode != 0
    assert f"{samples}:3" in done.stderr and "K_py" in done.stderr

    study.write_text("[scenario]\nname = 'S_high'\nspeed = 50.0\ndistanse = 10.0\n")
    done = _batch(study, samples, "--quiet")
    assert done.returncode != 0 and "study.toml" in done.stderr
    # The unknown key is reported on its own line (the 4th), not the one before.
    assert f"{study}:4:" in done.stderr and "distanse" in done.stderr

    study.write_text(
        "[scenario]\nname = 'S_high'\nspeed = 50.0\ndistance = 10.0\ntrack = 'perfect'\nseed = 3\n"
    )
    done = _batch(study, samples, "--quiet")
    assert done.returncode != 0 and "scenario.seed" in done.stderr


def test_binary_rejects_an_unknown_channel_before_running(tmp_path: Path) -> None:
    study, samples = _write_inputs(tmp_path)
    study.write_text(STUDY.replace("yaw_damper_bogie1_left_valve", "yaw_damper_bogie1_left_valv"))
    # Many samples: were the channels checked only when the histories are written, the batch
    # would run them all and write the metrics file first.
    rows = ["K_px,K_py"] + ["1.5e7,3.5e6"] * 400
    samples.write_text("\n".join(rows) + "\n", encoding="utf-8")
    out = tmp_path / "metrics.csv"
    done = _batch(study, samples, "-o", out, "--quiet")
    assert done.returncode != 0
    assert "output.channels" in done.stderr and "yaw_damper_bogie1_left_valv'" in done.stderr
    # The message lists what is available, including the new vertical damper forces.
    assert "primary_vertical_damper_wheelset1_left_force" in done.stderr
    assert not out.exists()


def test_study_file_selects_the_hydraulic_valve(tmp_path: Path) -> None:
    """``fsd_trigger = "hydraulic"`` in the study file is the Python ``FSD_HYDRAULIC``."""
    study, samples = _write_inputs(tmp_path)
    text = STUDY.replace('yaw_damper = "FSD"', 'yaw_damper = "FSD"\nfsd_trigger = "hydraulic"')
    study.write_text(text.replace("distance = 295.0", "distance = 60.0"), encoding="utf-8")
    out = tmp_path / "metrics.csv"
    done = _batch(study, samples, "-o", out, "--threads", "1", "--quiet")
    assert done.returncode == 0, done.stderr
    rows = _rows(out)
    vehicle = loco.Locomotive.default().replace(C_sy=3.0e4)
    scenario = loco.Scenario(
        name="S_high",
        speed=200 / 3.6,
        distance=60.0,
        seed=5,
        yaw_damper=loco.dampers.FSD_HYDRAULIC,
    )
    expected = loco.run_batch(
        PARAMS[:1], NAMES, vehicle=vehicle, scenario=scenario, threads=1, progress=False
    )
    got = np.array([float(rows[0][m]) for m in expected.metric_names])
    assert np.array_equal(got, expected.metrics[0], equal_nan=True)
    study.write_text(text.replace('fsd_trigger = "hydraulic"', 'fsd_trigger = "zero"'))
    done = _batch(study, samples, "-o", out, "--quiet")
    assert done.returncode != 0 and "fsd_trigger" in done.stderr


def test_the_same_scenario_keys_mean_the_same_run_in_both_front_ends(tmp_path: Path) -> None:
    """One spelling per setting: the study file's ``[scenario]`` keys are ``loco.Scenario``'s
    keywords (a preset damper by name, the track set-up), and ``threads = 0`` is one per core in
    both."""
    settings = {
        "speed": 50.0,
        "distance": 260.0,  # m: the 5 s the metrics need at 50 m/s
        "track": "perfect",
        "initial_lateral_offset": 0.003,
        "yaw_damper": "FSD",
        "gauge": 1.44,
        "gauge_height": 0.014,
        "rail_inclination": 0.03,
    }
    lines = [f"{k} = {v!r}".replace("'", '"') for k, v in settings.items()]
    study = tmp_path / "study.toml"
    study.write_text("[scenario]\nname = 'S_high'\n" + "\n".join(lines) + "\n", encoding="utf-8")
    samples = tmp_path / "samples.csv"
    samples.write_text("C_sx\n800000.0\n200000.0\n", encoding="utf-8")
    out = tmp_path / "metrics.csv"
    done = _batch(study, samples, "-o", out, "--threads", "0", "--quiet")
    assert done.returncode == 0, done.stderr
    rows = _rows(out)
    scenario = loco.Scenario(name="S_high", **settings)  # type: ignore[arg-type]
    x = np.array([[8e5], [2e5]])
    expected = loco.run_batch(x, ["C_sx"], scenario=scenario, threads=0, progress=False)
    assert expected.n_failed == 0 and np.isfinite(expected.metric("wy_max")).all()
    for i, row in enumerate(rows):
        got = np.array([float(row[m]) for m in expected.metric_names])
        assert np.array_equal(got, expected.metrics[i], equal_nan=True), (i, row["message"])
    # The settings are used: the study's gauge and rail give another run.
    default = loco.run_batch(
        x,
        ["C_sx"],
        scenario=scenario.replace(gauge=None, gauge_height=None, rail_inclination=None),
        progress=False,
    )
    assert not np.array_equal(default.metrics, expected.metrics, equal_nan=True)


def test_a_bad_curve_section_in_a_study_file_is_named_with_its_field(tmp_path: Path) -> None:
    """`[[scenario.curve]]` tables are read section by section: the error names the section and
    the field (an untagged enum's "did not match any variant" named neither), at the file's line."""
    _, samples = _write_inputs(tmp_path)
    study = tmp_path / "curve.toml"
    head = "[scenario]\nname = 'S_norm'\nspeed = 50.0\ndistance = 10.0\ntrack = 'perfect'\n"
    straight = "[[scenario.curve]]\nkind = 'straight'\nlength_m = 20.0\n"
    for section, field, expected in [
        ("kind = 'curve'\nlength_m = 50.0\nradius_m = 'x'\ndirection = 'left'\n",
         "curve section 2 (radius_m)", "invalid type"),
        ("kind = 'curve'\nlength_m = 50.0\nradius = 800.0\ndirection = 'left'\n",
         "curve section 2 (radius)", "unknown field"),
        ("length_m = 50.0\n", "curve section 2", "missing field `kind`"),
    ]:  # fmt: skip
        study.write_text(head + straight + "[[scenario.curve]]\n" + section, encoding="utf-8")
        done = _batch(study, samples, "--quiet")
        assert done.returncode != 0
        assert f"`{field}`" in done.stderr and expected in done.stderr, done.stderr
        assert f"{study}:" in done.stderr, done.stderr
    study.write_text(head + "curve = 3\n", encoding="utf-8")
    done = _batch(study, samples, "--quiet")
    assert done.returncode != 0 and "`curve`" in done.stderr and "list of sections" in done.stderr


def test_the_shipped_example_study_runs_as_the_guide_shows(tmp_path: Path) -> None:
    """``examples/study.toml`` with ``examples/samples.csv``: every sample runs, with the numbers
    of ``loco.run_batch`` on the same vehicle, scenario and samples."""
    out = tmp_path / "metrics.csv"
    study, samples = ROOT / "examples" / "study.toml", ROOT / "examples" / "samples.csv"
    done = _batch(study, samples, "-o", out, "--threads", "2")
    assert done.returncode == 0, done.stderr
    with out.open(newline="") as f:
        rows = list(csv.DictReader(f))
    table = pd.read_csv(samples, comment="#")
    names = list(table.columns)
    params = table.to_numpy(dtype=float)
    expected = loco.run_batch(
        params,
        names,
        vehicle=loco.Locomotive.default().replace(C_sy=2.5e4),
        scenario=loco.Scenario(
            name="S_high", speed=200 / 3.6, distance=300.0, seed=1, yaw_damper="YD2"
        ),
        threads=1,
        progress=False,
    )
    assert [r["status"] for r in rows] == ["ok"] * len(params)
    got = [float(r["ayb_peak_lp"]) for r in rows]
    assert got == expected.metric("ayb_peak_lp").tolist()
    assert (tmp_path / "metrics_history_0.csv").is_file()
