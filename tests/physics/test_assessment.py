"""``loco.assess`` on a steady curve with 100 mm cant deficiency: the zones of the alignment, the
limits computed by hand from the vehicle's mass and the speed, what the floor accelerometers read
against g·d/2b0, the quasi-static quantities outside the small-radius zone as references, the
table, the figure and bad input."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import loco
from loco.assessment import assess, stability_quantities, zones

G = 9.81
B0 = 0.7465
RADIUS, CANT, DEFICIENCY = 1200.0, 0.05, 0.10
CURVE = [
    {"kind": "straight", "length_m": 50.0},
    {"kind": "transition", "length_m": 80.0},
    {"kind": "curve", "length_m": 300.0, "radius_m": RADIUS, "cant_mm": CANT * 1e3,
     "direction": "left"},
]  # fmt: skip


@pytest.fixture(scope="module")
def curved() -> loco.SimulationResult:
    speed = math.sqrt(G * RADIUS * (CANT + DEFICIENCY) / (2 * B0))
    scenario = loco.Scenario(
        name="S_norm", speed=speed, distance=420.0, curve=CURVE, track="perfect"
    )
    return loco.simulate(loco.Locomotive.default(), scenario)


def test_the_zones_of_an_alignment_are_its_straights_and_circular_curves(tmp_path: Path) -> None:
    found = zones(CURVE, 400.0)
    assert [(z.name, z.start, z.end) for z in found] == [
        ("straight 1", 0.0, 50.0), ("curve R = 1200 m", 130.0, 430.0)]  # fmt: skip
    pd.DataFrame(CURVE).to_csv(tmp_path / "sections.csv", index=False)
    assert zones(tmp_path / "sections.csv", 400.0) == found
    assert [z.name for z in zones(None, 400.0)] == ["straight track"]


def test_a_curve_is_assessed_against_the_limits_by_hand(
    curved: loco.SimulationResult, tmp_path: Path
) -> None:
    result = curved
    vehicle = loco.Locomotive.default()
    found = assess(result, vehicle, curve=CURVE)
    zone = f"curve R = {RADIUS:g} m"
    # Prud'homme with α = 1 for a locomotive, from the vehicle's weight over four axles; Q_max's
    # limit 90 kN + Q0, below its 200 kN cap at 124 km/h.
    axle_load = vehicle.total_mass() * vehicle["track.gravity"] / 4.0
    assert found.get("sumY", zone).limit == pytest.approx(10e3 + axle_load / 3.0, rel=1e-9)
    assert found.get("Qmax", zone).limit == pytest.approx(90e3 + axle_load / 2.0, rel=1e-9)
    assert found.get("YQ", zone).limit == 0.8
    # The carbody floor accelerometer reads the cant deficiency's g·d/2b0 and more, by the
    # carbody's roll on its suspension (a roll coefficient between 0 and 0.3).
    in_track_plane = G * DEFICIENCY / (2 * B0)
    sensed = found.get("yqst", zone).value
    print(f"ÿ*_qst {sensed:.4f} m/s², g·d/2b0 {in_track_plane:.4f}")
    assert in_track_plane < sensed < 1.3 * in_track_plane
    assert found.get("yqst", zone).passed is True
    # Y_qst and Q_qst are references outside 250 m ≤ R < 400 m.
    for key in ("Yqst", "Qqst"):
        q = found.get(key, zone)
        assert q.passed is None and "reference" in q.note and q.value > 0.0
    # The quasi-static wheel load of the outer wheels is above the static one, below the limit.
    assert axle_load / 2.0 < found.get("Qqst", zone).value < 145e3
    assert found.passed()
    assert all(q.secondary for q in found.quantities if q.key != "limit_cycle")
    frame = found.frame()
    assert {"key", "quantity", "zone", "value", "limit", "unit", "passed", "source"} <= set(frame)
    assert set(frame.zone) == {"straight 1", zone, "whole run"}
    assert found.figure(tmp_path / "assessment.png").stat().st_size > 0
    hunting = stability_quantities(result.metrics)
    assert hunting[1].note == "no sustained limit cycle"


def test_bad_input_is_a_parameter_error_naming_it(
    curved: loco.SimulationResult,
) -> None:
    with pytest.raises(loco.ParameterError, match="vehicle_class"):
        assess(curved, vehicle_class="tram")


def test_the_ride_characteristics_band_pass_and_read_a_sine_by_hand() -> None:
    # A 2 Hz sine of 0.8 m/s² plus a 0.1 Hz drift and g: the 0.4–10 Hz band keeps the sine
    # (its percentile magnitude about the amplitude, its rms amplitude/√2) and drops the rest.
    from loco.studies import en14363

    fs = 500.0
    t = np.arange(0.0, 30.0, 1.0 / fs)
    signal = 0.8 * np.sin(2 * np.pi * 2.0 * t) + 0.5 * np.sin(2 * np.pi * 0.1 * t) + 9.81
    filtered = en14363.ride_filtered(signal, fs)
    peak, rms = en14363.ride_values(filtered[int(5 * fs) : int(25 * fs)])
    assert peak == pytest.approx(0.8, rel=0.01)
    assert rms == pytest.approx(0.8 / math.sqrt(2.0), rel=0.01)
    assert all(math.isnan(v) for v in en14363.ride_values(np.array([])))


def test_the_ride_characteristics_of_a_run_are_assessed_per_zone(
    curved: loco.SimulationResult,
) -> None:
    found = assess(curved, curve=CURVE)
    for zone in ("straight 1", f"curve R = {RADIUS:g} m"):
        for key, limit in (("ydd_max", 3.0), ("ydd_rms", 0.5), ("zdd_max", 3.0), ("zdd_rms", 1.0)):
            q = found.get(key, zone)
            assert q.limit == limit and q.unit == "m/s²" and q.secondary
            # Perfect track: the carbody barely moves in the ride band.
            assert 0.0 <= q.value < 0.2 * limit and q.passed is True, (key, zone, q.value)
        assert found.get("ydd_max", zone).value >= found.get("ydd_rms", zone).value
