"""The core's names as constants: the metric table behind ``loco.Metric`` and ``docs/metrics.md``,
and the channel set behind a run's channel names and kinds."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

import numpy as np

import loco
from loco.channels import CHANNEL_KINDS, METRIC_NAMES, ChannelKind, Metric, channel_table
from script_modules import load_script

ROOT = Path(__file__).resolve().parents[2]

#: The metric columns as the SPEC's report reads them (an independent list, not the table).
EXPECTED_METRICS = (
    "wy_mean wy_max wz_mean wz_max ayc_rms ayc_peak ayc_dominant_hz ayc_psd_peak ayc_wd_p95 "
    "azc_wb_p95 nmv ayb_rms ayb_peak_lp ayb_gbt_cycles ayb_gbt_unstable ayb_f0_hz ayb_psd_peak "
    "ayb_en_rms ayb_en_limit ayb_en_unstable ayb_limit_cycle ayb_cycle_hz ayb_cycle_amplitude "
    "ayc_limit_cycle ayc_cycle_hz ayc_cycle_amplitude"
).split()


def _docs_script() -> ModuleType:
    return load_script("metric_docs")


def test_metric_constants_are_the_tables_names_in_column_order() -> None:
    assert list(METRIC_NAMES) == EXPECTED_METRICS
    assert list(METRIC_NAMES) == loco.metrics.run_metric_names()
    for name in METRIC_NAMES:
        assert getattr(Metric, name.upper()) == name
    assert loco.Metric is Metric
    flags = [m.name for m in loco.channels.metric_table() if m.flag]
    assert flags == ["ayb_gbt_unstable", "ayb_en_unstable", "ayb_limit_cycle", "ayc_limit_cycle"]


def test_committed_metrics_page_is_the_generated_one() -> None:
    docs = _docs_script()
    assert docs.PAGE.read_text(encoding="utf-8") == docs.render(), (
        "run python scripts/docs/metric_docs.py --write"
    )
    for name in METRIC_NAMES:
        assert f"`{name}`" in docs.render()


def test_channel_table_names_and_kinds_the_channels_a_run_records() -> None:
    vehicle = loco.Locomotive.default()
    table = channel_table(vehicle.native)
    assert {c.kind for c in table} == set(CHANNEL_KINDS)
    assert ChannelKind.DAMPER_VALVE in CHANNEL_KINDS
    scenario = loco.Scenario(name="S_norm", speed=50.0, distance=40.0, track="perfect")
    result = loco.simulate(vehicle, scenario)
    assert result.channel_names == [c.name for c in table]
    valves = result.channels_of_kind(ChannelKind.DAMPER_VALVE)
    # The valve channels are the yaw dampers' (only they have a frequency valve), each a scale
    # factor in [0, 1].
    assert valves and all(n.startswith("yaw_damper") for n in valves)
    for name in valves:
        v = result.channel(name)
        assert np.all((v >= 0.0) & (v <= 1.0)), name
    units = {c.name: c.unit for c in table}
    assert units["carbody_floor_ay_front"] == "m/s²"
    assert units["wheel1_left_Q"] == "N"
    assert units["wheelset1_yaw"] == "rad"
    accelerations = result.channels_of_kind(ChannelKind.ACCELERATION)
    assert "frame1_ay_wheelset1" in accelerations and "wheel1_left_Q" not in accelerations
