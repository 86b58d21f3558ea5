"""Why the curving study's YD2 case at R = 3000 m and 150 mm cant deficiency (232 km/h) unloads
a wheel to ΔQ/Q0 = 0.95: the wheelset motion in the curve, its frequency against the
kinematic (Klingel) frequency at the curve's operating point, how it develops along a longer
curve, and the linear critical speed at the conicity the wheelsets see there.

    python experiments/curving_unloading.py [--curve 200] [--dampers YD1,YD2,FSD] [--csv out.csv]

Prints, per yaw damper: where and on which wheel ΔQ/Q0 is largest, the leading wheelset's mean
offset and oscillation (peak-to-peak, dominant frequency by FFT, in the first and the last 100 m
of the circular curve), the share of the curve with flange contact on each leading wheel and the
number of flange contacts (separate episodes) of the outer one. Then the local conicity
(dΔr/dy / 2, Δr from :func:`loco.contact.rolling_radius_difference`, S_norm) at the leading
wheelset's mean offset and the linear critical speed with a cone of that conicity
(:func:`loco.critical_speed`), and the kinematic frequency V/2π·√(λ/(r0·b0)).
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import loco
import loco.contact
import loco.profiles
import loco.simulation
from loco import _loco, dampers
from loco.studies import curving

WHEEL = _loco.wheel_channels()
WHEELSET = _loco.wheelset_channels()


def run_case(
    vehicle: loco.Locomotive, case: curving.CurveCase, speed: float, damper: str
) -> tuple[loco.SimulationResult, float]:
    """The study's run of ``case`` at ``speed`` (m/s) with ``damper``: its lead-in, run-in and
    record (the recorded distance as in :func:`loco.studies.curving.run_curving`)."""
    straight = curving.LEAD_IN + curving.RUN_IN
    offsets = curving.wheelset_offsets(vehicle)
    distance = curving.RUN_IN + case.transition_m + case.curve_m + offsets[-1] + 1.0
    scenario = loco.Scenario(
        name="S_norm",
        speed=speed,
        distance=distance,
        lead_in=curving.LEAD_IN,
        yaw_damper=dampers.PRESETS[damper],
        curve=case.sections(straight, run_m=curving.LEAD_IN + distance),
        track="perfect",
    )
    return loco.simulate(vehicle, scenario), straight + case.transition_m


def episodes(flag: np.ndarray) -> int:
    """Number of separate runs of 1 in a 0/1 signal."""
    f = flag.astype(int)
    return int(np.sum(np.diff(np.concatenate([[0], f])) == 1))


def dominant_frequency(t: np.ndarray, x: np.ndarray) -> float:
    """Frequency (Hz) of the largest FFT peak of ``x`` less its mean (Hann window)."""
    x = (x - x.mean()) * np.hanning(x.size)
    spectrum = np.abs(np.fft.rfft(x))
    freqs = np.fft.rfftfreq(x.size, t[1] - t[0])
    spectrum[0] = 0.0
    return float(freqs[np.argmax(spectrum)])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--curve", type=float, default=200.0, help="circular curve length, m")
    parser.add_argument("--dampers", default="YD1,YD2,FSD")
    parser.add_argument("--radius", type=float, default=3000.0)
    parser.add_argument("--deficiency", type=float, default=150.0, help="mm")
    parser.add_argument(
        "--offset-mm", type=float, default=None, help="leading wheelset's mean offset (no runs)"
    )
    args = parser.parse_args()
    vehicle = loco.Locomotive.default()
    base = {c.radius_m: c for c in curving.CURVES}[args.radius]
    case = curving.CurveCase(
        radius_m=base.radius_m,
        cant_mm=base.cant_mm,
        transition_m=base.transition_m,
        curve_m=args.curve,
    )
    speed = curving.speed_for_deficiency(case.radius_m, case.cant_mm, args.deficiency, vehicle)
    print(
        f"R = {case.radius_m:g} m, cant {case.cant_mm:g} mm, deficiency {args.deficiency:g} mm: "
        f"V = {speed:.3f} m/s ({speed * 3.6:.1f} km/h), circular curve {case.curve_m:g} m"
    )
    offsets = curving.wheelset_offsets(vehicle)
    mean_offset = 0.0
    if args.offset_mm is not None:
        mean_offset = 1e-3 * args.offset_mm
    for damper in [d for d in args.dampers.split(",") if d]:
        started = time.perf_counter()
        result, start = run_case(vehicle, case, speed, damper)
        lead = curving.LEAD_IN + speed * result.time
        end = start + case.curve_m
        print(f"\n{damper} ({time.perf_counter() - started:.1f} s)")
        worst = (0.0, "", 0.0)
        for w, offset in enumerate(offsets):
            s = lead - offset
            inside = (s >= start) & (s <= end)
            for side in range(2):
                i = 2 * w + side
                dqq = result.channel(WHEEL["dQQ"][i])[inside]
                k = int(np.argmax(dqq))
                if dqq[k] > worst[0]:
                    worst = (float(dqq[k]), WHEEL["dQQ"][i], float(s[inside][k] - start))
        print(f"  largest ΔQ/Q0 {worst[0]:.3f} at {worst[1]}, {worst[2]:.1f} m into the curve")
        inside = (lead >= start) & (lead <= end)
        t = result.time[inside]
        y = result.channel(WHEELSET["y"][0])[inside]
        yaw = result.channel(WHEELSET["yaw"][0])[inside]
        if damper == "YD2" or mean_offset == 0.0:
            mean_offset = float(np.mean(y))
        s_in = lead[inside] - start
        for label, part in (
            ("first 100 m", s_in <= 100.0),
            ("last 100 m", s_in >= case.curve_m - 100.0),
        ):
            print(
                f"  wheelset 1, {label}: y mean {1e3 * y[part].mean():+.2f} mm, "
                f"peak-to-peak {1e3 * np.ptp(y[part]):.2f} mm, yaw p-p "
                f"{1e3 * np.ptp(yaw[part]):.3f} mrad, "
                f"dominant {dominant_frequency(t[part], y[part]):.2f} Hz"
            )
        half = s_in >= 0.5 * case.curve_m
        body = result.channel("carbody_floor_ay_front")[inside]
        print(
            f"  second half of the curve: wheelset 1 y dominant "
            f"{dominant_frequency(t[half], y[half]):.2f} Hz, carbody floor a_y (front) dominant "
            f"{dominant_frequency(t[half], body[half]):.2f} Hz, rms {np.std(body[half]):.3f} m/s²"
        )
        for side, name in enumerate(("left (inner)", "right (outer)")):
            flag = result.channel(WHEEL["flange"][side])[inside]
            q = result.channel(WHEEL["Q"][side])[inside]
            print(
                f"  wheel 1 {name}: flange contact {100 * flag.mean():.1f} % of the curve "
                f"({episodes(flag)} contacts), Q {q.min() / 1e3:.1f}–{q.max() / 1e3:.1f} kN"
            )
    # The local conicity at the mean offset and what the linear model says there.
    wheel_name, rail_name = loco.simulation.SCENARIOS["S_norm"]
    wheel, rail = loco.profiles.builtin(wheel_name), loco.profiles.builtin(rail_name)
    h = 0.5e-3
    ys = mean_offset + np.array([-h, h])
    dr = loco.contact.rolling_radius_difference(wheel, rail, ys)
    local = float(abs(dr[1] - dr[0]) / (2 * h) / 2.0)
    centred = loco.contact.rolling_radius_difference(wheel, rail, np.array([-h, h]))
    print(
        f"\nleading wheelset's mean offset in the curve {1e3 * mean_offset:+.2f} mm: local "
        f"conicity dΔr/dy/2 {local:.3f} (centred {abs(centred[1] - centred[0]) / (4 * h):.3f})"
    )
    r0 = vehicle["track.wheel_rolling_radius"]
    b0 = vehicle["track.contact_point_half_distance"]
    scenario = loco.Scenario(name="S_norm", speed=speed, distance=100.0, yaw_damper="YD2")
    straight = loco.critical_speed(vehicle, scenario)
    print(f"  S_norm, YD2, straight: linear critical speed {straight * 3.6:.0f} km/h")
    for lam in sorted({0.11, round(local, 3), 0.3, 0.45}):
        f = speed / (2 * np.pi) * np.sqrt(lam / (r0 * b0))
        crit = loco.critical_speed(vehicle, scenario, conicity=lam)
        print(
            f"  cone λ {lam:.3f}: kinematic frequency at V {f:.2f} Hz, YD2 linear critical "
            f"speed {crit * 3.6:.0f} km/h ({crit.outcome})"
        )


if __name__ == "__main__":
    main()
