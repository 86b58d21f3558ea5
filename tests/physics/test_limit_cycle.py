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
#: How far a limit cycle's frequency may lie from the linear mode's at the same speed: the contact's
#: effective conicity at the cycle's amplitude is not the linearisation's.
FREQUENCY_TOLERANCE = 0.15


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
    # The nonlinear cycle runs a little slower than the linear mode (4.02 against 4.41 Hz).
    assert abs(above[Metric.AYB_CYCLE_HZ] - linear_hz) < FREQUENCY_TOLERANCE * linear_hz
    assert above[Metric.AYB_CYCLE_AMPLITUDE] > 1.0
    # The assessment calls it hunting, whichever side of the EN 14363 limit its rms is on.
    sliding_rms, cycle, _ = stability_quantities(above)
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


def test_the_carbody_of_thin_flanged_wheels_with_high_yaw_damping_settles_into_a_limit_cycle() -> (
    None
):
    # S_low with YD2 after an 8 mm disturbance on perfect track (2000 m): at 250 km/h, 0.94 of
    # the linear critical speed (266 km/h) where the 1.3 Hz carbody mode is still damped
    # (ζ ≈ 0.5 %), the sway grows and settles (band rms 0.11 → 0.64 m/s² over 28 s): a
    # subcritical limit cycle of the low-conicity carbody mode; at 200 km/h it decays to nothing.
    vehicle = loco.Locomotive.default()
    found = {}
    for kmh in (250.0, 200.0):
        scenario = loco.Scenario(
            name="S_low",
            yaw_damper=loco.dampers.YD2,
            speed=kmh / 3.6,
            distance=2000.0,
            track="perfect",
            initial_lateral_offset=0.008,
        )
        mode = loco.eigen(vehicle, scenario).least_damped()
        found[kmh] = (loco.simulate(vehicle, scenario).metrics, mode.frequency)
    (hunting, linear_hz), (quiet, _) = found[250.0], found[200.0]
    print(
        f"250 km/h: carbody cycle {hunting[Metric.AYC_LIMIT_CYCLE]}, "
        f"{hunting[Metric.AYC_CYCLE_HZ]:.3f} Hz (linear mode {linear_hz:.3f} Hz), "
        f"±{hunting[Metric.AYC_CYCLE_AMPLITUDE]:.3f} m/s²; 200 km/h: "
        f"{quiet[Metric.AYC_LIMIT_CYCLE]}, ±{quiet[Metric.AYC_CYCLE_AMPLITUDE]:.4f} m/s²"
    )
    assert hunting[Metric.AYC_LIMIT_CYCLE] == 1.0 and hunting[Metric.AYB_LIMIT_CYCLE] == 0.0
    assert abs(hunting[Metric.AYC_CYCLE_HZ] - linear_hz) < FREQUENCY_TOLERANCE * linear_hz
    assert quiet[Metric.AYC_LIMIT_CYCLE] == 0.0
    assert quiet[Metric.AYC_CYCLE_AMPLITUDE] < 0.05 * hunting[Metric.AYC_CYCLE_AMPLITUDE]
    carbody = stability_quantities(hunting)[2]
    assert carbody.quantity == "carbody limit cycle amplitude"
    assert carbody.note.startswith("hunts: limit cycle")
