"""The premise study of a vehicle file (``loco.studies.premise_study``): its stages on a vehicle
that is not the default one, its report, a rerun that skips finished stages, and bad input
refused before any run."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest

import loco
from loco import _loco
from loco.studies import premise_study as ps


def _vehicle_file(tmp_path: Path) -> Path:
    """The default vehicle's file with a 10 % lighter carbody: a vehicle of the user's."""
    text = _loco.default_vehicle_toml()
    vehicle = loco.Locomotive.default()
    mass = vehicle["carbody.mass"]
    lines = text.splitlines()
    section = None
    for i, line in enumerate(lines):
        stripped = line.strip()
        if stripped.startswith("["):
            section = stripped.strip("[]")
        elif section == "carbody" and stripped.split("=")[0].strip() == "mass":
            lines[i] = f'mass = {{ value = {0.9 * mass!r}, unit = "kg", source = "a test" }}'
    path = tmp_path / "lighter.toml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    assert loco.Locomotive.from_toml(path)["carbody.mass"] == pytest.approx(0.9 * mass)
    return path


#: A ranges file of two inputs (a lighter carbody's mass and the yaw damping): the screening's
#: trajectories and the plausible locomotives' hypercube are over these alone.
RANGES = """
[parameters.carbody]
mass = { low = 36000.0, high = 40000.0, kind = "estimate", why = "a test", source = "a test" }
[parameters.secondary]
yaw_damper_damping = { low = 7e5, high = 9e5, kind = "tolerance", why = "test", source = "test" }
"""


@pytest.mark.slow
def test_the_premise_study_runs_on_a_vehicle_file(tmp_path: Path) -> None:
    path = _vehicle_file(tmp_path)
    ranges = tmp_path / "ranges.toml"
    ranges.write_text(RANGES, encoding="utf-8")
    out = tmp_path / "premise"
    lines: list[str] = []
    report = ps.premise_study(
        path, out, preset="tiny", ranges_file=ranges, progress=False, log=lines.append
    )
    text = report.read_text(encoding="utf-8")
    assert text.startswith("# The premise study")
    assert f"**On `{path}`: " in text
    plausible = pd.read_csv(out / "plausible" / "plausible.csv")
    # The plausible locomotives draw this file's ranges (the yaw damping is the presets').
    assert list(plausible.columns[:1]) == ["carbody.mass"]
    assert plausible["carbody.mass"].between(36000.0, 40000.0).all()
    screened = pd.read_csv(out / "screening" / "morris.csv")
    assert set(screened["input"]) == {"carbody.mass", "secondary.yaw_damper_damping"}
    fraction = pd.read_csv(out / "plausible" / "plausible_fraction.csv")
    row = fraction[(fraction["pair"] == "all pairs") & (fraction["rule"] == "premise")].iloc[0]
    assert f"The premise holds on {int(row['k'])} of 4 plausible locomotives" in text
    stages = ["fsd_comparison", "premise_map", "screening", "plausible", "premise_case"]
    assert [line.split("]")[0][1:] for line in lines if line.endswith("running")] == stages
    # A rerun finds every stage finished.
    again: list[str] = []
    ps.premise_study(path, out, preset="tiny", ranges_file=ranges, progress=False, log=again.append)
    assert sum("skipped" in line for line in again) == len(stages)
    assert report.read_text(encoding="utf-8") == text


def test_bad_input_is_refused_before_any_run(tmp_path: Path) -> None:
    with pytest.raises(loco.ParameterError, match="`preset`"):
        ps.premise_study(None, tmp_path / "a", preset="huge")
    ranges = tmp_path / "ranges.toml"
    ranges.write_text(
        '[parameters.carbody]\nmass = { low = 1.0, high = 2.0, kind = "estimate", why = "w", '
        'source = "s" }\n',
        encoding="utf-8",
    )
    with pytest.raises(loco.ParameterError, match=r"carbody\.mass"):
        ps.premise_study(None, tmp_path / "b", preset="tiny", ranges_file=ranges)
    assert not (tmp_path / "b").exists()


@pytest.mark.slow
def test_the_advantage_sensitivity_finds_the_input_that_sets_it() -> None:
    # A known answer: the FSD's S_low advantage is exp(a) for an input `a`, noise `b` beside it;
    # the forest must score well on held-out locomotives and rank `a` first.
    import numpy as np

    from loco.studies.plausible import advantage_sensitivity
    from loco.studies.premise_probability import DAMPERS, JUDGE, Plausible

    rng = np.random.default_rng(3)
    n = 60
    inputs = pd.DataFrame({"a": rng.uniform(-1, 1, n), "b": rng.uniform(-1, 1, n)})
    metrics = pd.DataFrame({f"{s} {d}": np.ones(n) for s in JUDGE for d in DAMPERS})
    metrics["S_low FSD"] = np.exp(inputs["a"])
    result = Plausible(inputs, ["pair"] * n, metrics, 0, {})
    table = advantage_sensitivity(result, seed=0)
    low = table[(table["damper"] == "FSD") & (table["scenario"] == "S_low")]
    assert low["r2"].iloc[0] > 0.8 and low["input"].iloc[0] == "a"
