"""Scenario inputs: wrong Python types, the cost bounds of a run, undefined metrics and a
critical speed not found are each said so, with the field or the reason."""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest

import loco
from loco.stability import CriticalSpeed

S = {"name": "S_norm"}


def _refusal(settings: dict[str, object], field: str) -> str:
    """The message of the :class:`loco.ParameterError` refusing ``settings`` (on top of
    :data:`S`), which must name ``field``."""
    with pytest.raises(loco.ParameterError, match=f"`{field}`") as error:
        loco.Scenario(**{**S, **settings}).native()  # type: ignore[arg-type]
    return str(error.value)


@pytest.mark.parametrize(
    ("settings", "field", "words"),
    [
        ({"speed": "200"}, "speed", "expected a real number, got str '200'"),
        ({"speed": True}, "speed", "got bool True"),
        ({"speed": 1 + 2j}, "speed", "got complex"),
        ({"step": [1e-3]}, "step", "expected a real number"),
        ({"seed": 1.5}, "seed", "must be a whole number, got 1.5"),
        ({"seed": -1}, "seed", "must be in [0, "),
        ({"seed": 2**64}, "seed", "must be in [0, "),
        ({"seed": 2**63}, "seed", "must be in [0, "),
        ({"seed": math.inf}, "seed", "must be a whole number"),
        ({"seed": True}, "seed", "got bool True"),
        ({"fastsim_grid": (1e30, 10)}, "fastsim_grid", "must be in [1, "),
        ({"fastsim_grid": (2.5, 10)}, "fastsim_grid", "must be a whole number"),
        ({"fastsim_grid": 10}, "fastsim_grid", "expected a pair"),
        ({"band": "2-200"}, "band", "expected a pair"),
        ({"band": (2.0, "200")}, "band", "expected a real number"),
        ({"spectrum": 3}, "spectrum", "expected a name (str)"),
        ({"creep": 3}, "creep", "expected a name (str)"),
        ({"track": 1}, "track", "expected a name (str)"),
        ({"yaw_damper": 2e5}, "yaw_damper", "expected a name (str)"),
        ({"gauge": "1.435"}, "gauge", "expected a real number"),
        ({"name": 3}, "name", "expected a name (str)"),
    ],
)
def test_a_wrong_type_is_a_parameter_error_naming_the_field(
    settings: dict[str, object], field: str, words: str
) -> None:
    assert words in _refusal(settings, field)


def test_numpy_and_integral_values_are_accepted() -> None:
    native = loco.Scenario(
        name="S_norm", speed=np.float64(50.0), seed=np.int64(3), fastsim_grid=(12.0, 8)
    ).native()
    assert native.speed == 50.0


@pytest.mark.parametrize(
    ("settings", "field", "reason"),
    [
        # SPEC-scale runs are 4 500 steps; 1e-3 m/s would be half a million steps per metre.
        ({"speed": 1e-3}, "speed", "500000 integration steps per metre"),
        ({"speed": 0.5}, "speed", "below the lowest speed 1 m/s"),
        ({"fastsim_grid": (10_000, 10_000)}, "fastsim_grid", "nx·ny <= 2500"),
        ({"fastsim_grid": (0, 10)}, "fastsim_grid", "must be in [1, "),
        # Blames the rate, not a channel of the metrics.
        ({"output_rate": 1e-3}, "output_rate", "must exceed 40 Hz"),
        ({"step": 1e-9}, "step", "beyond the 1e7 of one run"),
        ({"distance": 1e-30}, "distance", "would record nothing"),
        ({"speed": 1.0, "distance": 100_000.0}, "distance", "integration steps"),
    ],
)
def test_cost_bounds_refuse_with_the_field_and_the_reason(
    settings: dict[str, object], field: str, reason: str
) -> None:
    assert reason in _refusal(settings, field)


def test_the_cost_bounds_hold_in_batches_too() -> None:
    # A speed column below the lowest speed is refused before the batch, naming its cell.
    with pytest.raises(loco.ParameterError, match="speed") as error:
        loco.run_batch(np.array([[0.5]]), ["speed"], scenario=loco.Scenario(**S), progress=False)
    assert "1 m/s" in str(error.value) or "[1," in str(error.value)


def test_a_run_too_short_for_the_metrics_has_every_metric_nan_flags_included() -> None:
    # 30 m at 200 km/h: 0.54 s, under one 5 s Sperling segment. A flag of 0.0 would read
    # "stable"; it is NaN like every other metric.
    result = loco.simulate(loco.Locomotive.default(), loco.Scenario(**S, distance=30.0))
    assert len(result.time) > 2
    nan = [k for k, v in result.metrics.items() if math.isnan(v)]
    assert nan == list(result.metrics), result.metrics
    assert math.isnan(result.metrics["ayb_en_unstable"])
    assert math.isnan(result.metrics["ayb_gbt_unstable"])


def test_critical_speed_result_says_what_it_is() -> None:
    found = CriticalSpeed(34.2, "found", 20.0, "linear")
    assert found == 34.2 and found.found and "linear critical speed 34.20 m/s" in found.reason
    above = CriticalSpeed(math.inf, "stable_at_high", 110.0, "linear")
    assert math.isinf(above) and not above.found
    assert "no linear critical speed found up to the search limit 110.00 m/s" in above.reason
    assert "not" not in found.reason and "above it" in above.reason
    below = CriticalSpeed(20.0, "hunts_at_end", 20.0, "nonlinear")
    assert not below.found and "at or below" in below.reason
    assert "stable_at_high" in repr(above)
    again = pickle.loads(pickle.dumps(above))
    assert isinstance(again, CriticalSpeed) and again.outcome == "stable_at_high"
    assert math.isinf(again) and again.limit == 110.0
