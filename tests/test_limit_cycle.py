"""A limit cycle is called by its name on the vehicle: worn wheels (S_high) with the low yaw
damping YD1 on perfect track after a 5 mm lateral disturbance, above and below the linear
critical speed (``loco.critical_speed``). Above it the bogie frame settles into hunting, which
the core's limit-cycle metrics report at about the linear hunting mode's frequency; below it the
disturbance decays and nothing is reported, although the EN 14363 dominant frequency is the
same mode's."""

import loco
from loco.assessment import stability_quantities
from loco.channels import Metric

DISTURBANCE = 0.005


def _run(speed: float) -> tuple[dict[str, float], float]:
    vehicle = loco.Locomotive.default()
    scenario = loco.Scenario(
        name="S_high",
        yaw_damper=loco.dampers.YD1,
        speed=speed,
        distance=400.0,
        track="perfect",
        initial_lateral_offset=DISTURBANCE,
    )
    mode = loco.eigen(vehicle, scenario).least_damped()
    return loco.simulate(vehicle, scenario).metrics, mode.frequency


def test_hunting_above_the_linear_critical_speed_is_a_limit_cycle_and_a_decay_below_is_not() -> (
    None
):
    vehicle = loco.Locomotive.default()
    critical = loco.critical_speed(
        vehicle, loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD1), tolerance=1.0
    )
    assert critical.found
    above, linear_hz = _run(1.3 * critical)
    print(
        f"critical {critical * 3.6:.1f} km/h; at 1.3×: cycle {above[Metric.AYB_LIMIT_CYCLE]}, "
        f"{above[Metric.AYB_CYCLE_HZ]:.3f} Hz (linear mode {linear_hz:.3f} Hz), "
        f"±{above[Metric.AYB_CYCLE_AMPLITUDE]:.2f} m/s²"
    )
    assert above[Metric.AYB_LIMIT_CYCLE] == 1.0
    # The nonlinear cycle runs a little slower than the linear mode (4.02 against 4.41 Hz when
    # this was written): the contact's effective conicity at the cycle's amplitude is not the
    # linearisation's.
    assert abs(above[Metric.AYB_CYCLE_HZ] - linear_hz) < 0.12 * linear_hz
    assert above[Metric.AYB_CYCLE_AMPLITUDE] > 1.0
    # The assessment calls it hunting, whichever side of the EN 14363 limit its rms is on.
    sliding_rms, cycle = stability_quantities(above)
    assert cycle.note.startswith(f"hunts: limit cycle {above[Metric.AYB_CYCLE_HZ]:.1f} Hz")
    assert sliding_rms.passed == (above[Metric.AYB_EN_UNSTABLE] == 0.0)
    below, _ = _run(0.9 * critical)
    print(
        f"at 0.9×: cycle {below[Metric.AYB_LIMIT_CYCLE]}, dominant {below[Metric.AYB_F0_HZ]:.3f} "
        f"Hz, ±{below[Metric.AYB_CYCLE_AMPLITUDE]:.3f} m/s²"
    )
    assert below[Metric.AYB_LIMIT_CYCLE] == 0.0
    assert below[Metric.AYB_CYCLE_AMPLITUDE] < 0.05 * above[Metric.AYB_CYCLE_AMPLITUDE]
    assert stability_quantities(below)[1].note == "no sustained limit cycle"
