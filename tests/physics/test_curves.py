"""Curves from Python: the ``curve`` keyword (sections or a CSV file) reaches the core."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import loco

G = 9.81
#: Half distance between the nominal contact points, m, read from the parameter file.
B = loco.Locomotive.default()["track.contact_point_half_distance"]


def _sections(direction: str) -> list[dict[str, float | str]]:
    return [
        {"kind": "straight", "length_m": 10.0},
        {"kind": "transition", "length_m": 40.0},
        {
            "kind": "curve",
            "length_m": 500.0,
            "radius_m": 1200.0,
            "cant_mm": 50.0,
            "direction": direction,
        },
    ]


def _run(curve: object, distance: float = 120.0) -> loco.SimulationResult:
    speed = float(np.sqrt(G * 0.15 / (2 * B) * 1200.0))  # 100 mm cant deficiency
    scenario = loco.Scenario(
        name="S_norm", speed=speed, distance=distance, track="perfect", curve=curve
    )
    return loco.simulate(loco.Locomotive(), scenario)


def test_sections_and_csv_give_the_same_run_and_a_mirror_image(tmp_path: Path) -> None:
    left = _run(_sections("left"))
    csv = tmp_path / "curve.csv"
    csv.write_text(
        "kind,length_m,radius_m,cant_mm,direction\n"
        "straight,10,,,\ntransition,40,,,\ncurve,500,1200,50,right\n"
    )
    right = _run(str(csv))
    y_left = left.channel("wheelset1_y")
    y_right = right.channel("wheelset1_y")
    # The leading wheelset moves toward the outer rail: −y in a left curve.
    assert y_left[-1] < -1e-3
    np.testing.assert_allclose(y_right, -y_left, atol=1e-3 * np.abs(y_left).max())
    # The outer wheel carries more under cant deficiency.
    assert left.channel("wheel1_right_Q")[-1] > left.channel("wheel1_left_Q")[-1]


def test_bad_sections_are_named() -> None:
    bad = [
        {
            "kind": "curve",
            "length_m": 100.0,
            "radius_m": 600.0,
            "cant_mm": 250.0,
            "direction": "left",
        }
    ]
    with pytest.raises(loco.ParameterError, match=r"curve section 1 \(cant_mm\)"):
        _run(bad)
    with pytest.raises(loco.ParameterError, match=r"curve section 1 \(speed\)"):
        _run([{"kind": "straight", "length_m": 10.0, "speed": 3.0}])
    with pytest.raises(loco.ParameterError, match=r"curve section 2 \(cant_run_off_m\)"):
        _run(
            [
                {"kind": "straight", "length_m": 10.0},
                {"kind": "transition", "length_m": 10.0, "cant_run_off_m": 20.0},
            ]
        )


def test_a_run_beyond_a_design_ending_straight_continues_on_straight_track() -> None:
    """The design ends in a transition (which runs out to straight track); the run goes on 150 m
    beyond it: the wheelsets come back to the centre of straight track. A design that ends in
    the circular curve is refused for the same run, naming `distance`."""
    curve = [
        {"kind": "straight", "length_m": 10.0},
        {"kind": "transition", "length_m": 40.0},
        {"kind": "curve", "length_m": 60.0, "radius_m": 1200.0, "cant_mm": 50.0,
         "direction": "left"},
        {"kind": "transition", "length_m": 40.0},
    ]  # fmt: skip
    result = _run(curve, distance=300.0)
    y = result.channel("wheelset1_y")
    assert np.abs(y).max() > 1e-3  # in the curve
    assert abs(y[-1]) < 2e-4  # on straight track after the design
    with pytest.raises(loco.ParameterError, match=r"`distance`.*`curve` design ends at 110 m"):
        _run(curve[:3], distance=300.0)
