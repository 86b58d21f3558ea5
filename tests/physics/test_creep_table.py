"""The creep model in the time loop (Scenario(creep=...)): tabulated FASTSIM gives the same ride
and stability figures as direct FASTSIM; FaStrip reaches the run; bad names are refused."""

from __future__ import annotations

import math
import re

import pytest

import loco
from loco import ParameterError
from loco.simulation import CREEP_MODELS


@pytest.mark.parametrize("scenario", ["S_low", "S_high"])
def test_tabulated_fastsim_gives_the_direct_metrics_within_its_error(scenario: str) -> None:
    # The table's creep forces are within about 2 % of μN of FASTSIM's (contact.fastsim_table);
    # on a run that error shifts the ride and stability figures by a fraction of that.
    vehicle = loco.Locomotive.default()
    direct = loco.simulate(vehicle, loco.Scenario(name=scenario, distance=295.0, seed=2))
    table = loco.simulate(
        vehicle, loco.Scenario(name=scenario, distance=295.0, seed=2, creep="table")
    )
    for metric in ("wy_max", "ayb_peak_lp", "ayc_dominant_hz"):
        assert table.metrics[metric] == pytest.approx(direct.metrics[metric], rel=0.03), metric
    assert table.metrics["wy_max"] != direct.metrics["wy_max"]


def test_scenario_creep_model_reaches_the_run() -> None:
    assert CREEP_MODELS == ("fastsim", "fastrip", "table")
    vehicle = loco.Locomotive.default()
    runs = {
        creep: loco.simulate(
            vehicle, loco.Scenario(name="S_high", distance=295.0, seed=2, creep=creep)
        )
        for creep in ("fastsim", "fastrip")
    }
    assert all(math.isfinite(r.metrics["ayb_peak_lp"]) for r in runs.values())
    assert runs["fastrip"].metrics["ayb_peak_lp"] != runs["fastsim"].metrics["ayb_peak_lp"]


def test_scenario_creep_model_errors_name_the_field() -> None:
    with pytest.raises(ParameterError, match="`creep`"):
        loco.Scenario(name="S_low", creep="kalker").native()
    with pytest.raises(ParameterError, match=re.escape('creep="table"')):
        loco.Scenario(name="S_low", creep_table=True)
