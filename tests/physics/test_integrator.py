"""The integration schemes from Python: the exponential scheme at 2 ms (the default), which
solves the gearbox bearings' stiff springs and the linear dampers' series springs exactly, and
RK4 at 1 ms (the reference it is checked against: the Rust test ``exponential_step.rs`` over the
SPEC §6 box; here the Python path)."""

from __future__ import annotations

import pytest

import loco
from loco.simulation import INTEGRATOR_STEPS, INTEGRATORS

SHORT = {"speed": 200 / 3.6, "distance": 310.0}


def test_the_schemes_come_from_the_core_and_etdrk4_at_2_ms_is_the_default() -> None:
    assert INTEGRATORS == ("rk4", "etdrk4")
    defaults = loco.Scenario.defaults()
    assert defaults["integrator"] == "etdrk4"
    assert defaults["step"] == pytest.approx(2e-3)


def test_a_scheme_named_without_a_step_runs_at_its_own() -> None:
    assert INTEGRATOR_STEPS == {"rk4": pytest.approx(1e-3), "etdrk4": pytest.approx(2e-3)}
    assert loco.Scenario("S_high", integrator="etdrk4").step == pytest.approx(2e-3)
    assert loco.Scenario("S_high", integrator="etdrk4", step=1e-3).step == pytest.approx(1e-3)
    assert loco.Scenario("S_high").step == pytest.approx(2e-3)
    assert loco.Scenario("S_high", integrator="rk4").step == pytest.approx(1e-3)
    # The core resolves the same step: the run takes 2 ms steps (S_high's nominal vehicle stays
    # within 3 mm of the centre, so none is cut), half as many as at 1 ms.
    short = {"speed": 200 / 3.6, "distance": 60.0}
    vehicle = loco.Locomotive()
    named = loco.simulate(vehicle, loco.Scenario("S_high", integrator="etdrk4", **short))  # type: ignore[arg-type]
    at_1_ms = loco.simulate(vehicle, loco.Scenario("S_high", integrator="rk4", **short))  # type: ignore[arg-type]
    assert 2 * named.statistics["steps"] == at_1_ms.statistics["steps"]
    given = loco.simulate(
        vehicle,
        loco.Scenario("S_high", integrator="etdrk4", step=2e-3, **short),  # type: ignore[arg-type]
    )
    assert named.statistics["steps"] == given.statistics["steps"]
    channel = "frame1_ay_wheelset1"  # 60 m is too short for the metrics: the record itself
    assert (named.channel(channel) == given.channel(channel)).all()


@pytest.mark.parametrize("name", ["S_low", "S_high"])
def test_the_exponential_scheme_at_2_ms_keeps_the_reference_metrics(name: str) -> None:
    vehicle = loco.Locomotive()
    reference = loco.simulate(vehicle, loco.Scenario(name, integrator="rk4", **SHORT))  # type: ignore[arg-type]
    fast = loco.simulate(vehicle, loco.Scenario(name, **SHORT))  # type: ignore[arg-type]
    # About half the steps: the nominal vehicle runs mostly within 3 mm of the track centre, and
    # its steps beyond it are cut to 1 ms (none on S_high, a tenth on S_low's wider motion).
    steps, reference_steps = fast.statistics["steps"], reference.statistics["steps"]
    assert reference_steps // 2 <= steps < 0.6 * reference_steps
    for metric in ("wy_max", "ayb_peak_lp", "ayc_psd_peak"):
        r, f = reference.metrics[metric], fast.metrics[metric]
        assert abs(f - r) < 5e-3 * abs(r), (metric, r, f)


def test_rk4_at_2_ms_is_cut_to_its_stable_step() -> None:
    # The gearbox bearings (230–330 Hz) hold RK4 below 1.4 ms: 2 ms runs as two 1 ms steps,
    # the reference itself.
    vehicle = loco.Locomotive()
    cut = loco.simulate(vehicle, loco.Scenario("S_high", integrator="rk4", step=2e-3, **SHORT))  # type: ignore[arg-type]
    reference = loco.simulate(vehicle, loco.Scenario("S_high", integrator="rk4", **SHORT))  # type: ignore[arg-type]
    assert cut.metrics["ayb_peak_lp"] == reference.metrics["ayb_peak_lp"]


def test_an_unknown_scheme_is_refused_by_name() -> None:
    with pytest.raises(loco.ParameterError, match=r"`integrator`.*unknown scheme `euler`"):
        loco.Scenario("S_high", integrator="euler").native()
    with pytest.raises(loco.ParameterError, match="`integrator`"):
        loco.Scenario("S_high", integrator=4).native()  # type: ignore[arg-type]
