"""Tabulated FASTSIM in the time loop: the same ride and stability figures as direct FASTSIM."""

from __future__ import annotations

import pytest

import loco


@pytest.mark.parametrize("scenario", ["S_low", "S_high"])
def test_tabulated_fastsim_gives_the_direct_metrics_within_its_error(scenario: str) -> None:
    # The table's creep forces are within about 2 % of μN of FASTSIM's (contact.fastsim_table);
    # on a run that error shifts the ride and stability figures by a fraction of that.
    vehicle = loco.Locomotive.default()
    direct = loco.simulate(vehicle, loco.Scenario(scenario=scenario, distance=295.0, seed=2))
    table = loco.simulate(
        vehicle, loco.Scenario(scenario=scenario, distance=295.0, seed=2, creep_table=True)
    )
    for metric in ("wy_max", "ayb_peak_lp", "ayc_dominant_hz"):
        assert table.metrics[metric] == pytest.approx(direct.metrics[metric], rel=0.03), metric
    assert table.metrics["wy_max"] != direct.metrics["wy_max"]
