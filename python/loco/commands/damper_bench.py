"""``loco damper-bench``: force-velocity curves and hysteresis loops of YD1, YD2, FSD (spec §6.5).

Each damper is driven with a sine elongation at 1 Hz and 4 Hz. The default amplitude, 3 mm, is of
the order of the yaw damper stroke of a bogie hunting or of carbody sway on straight track (a
bogie yaw of 1 mrad moves a damper mounted 1.3 m off the centre line by 1.3 mm, hunting cycles
reach a few mrad); at 4 Hz it gives a peak velocity of 0.075 m/s. The loops are taken over the
last cycles, after the FSD has settled. Writes ``damper_bench.png`` (both figures),
``damper_bench_loops.csv`` (time histories), ``damper_bench_summary.csv`` (equivalent damping,
stiffness and energy per cycle, with the closed form of the linear models) and
``damper_bench_parameters.json`` (loco version and every parameter).
"""

from __future__ import annotations

import argparse
import csv
import json
from pathlib import Path

import numpy as np

import loco
from loco import dampers

NAME = "damper-bench"
HELP = "bench YD1, YD2 and FSD at 1 Hz and 4 Hz: force-velocity curves and hysteresis loops"

FREQUENCIES_HZ = (1.0, 4.0)
CYCLES = 10
LOOP_CYCLES = 2
LOOP_COLUMNS = (
    "damper",
    "frequency_hz",
    "time_s",
    "displacement_m",
    "velocity_mps",
    "force_n",
    "scale_factor",
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", type=Path, default=Path("out/damper_bench"), help="output dir")
    parser.add_argument(
        "--amplitude", type=float, default=3e-3, help="sine amplitude of the elongation (m)"
    )


def _closed_form(damper: dampers.Damper, frequency: float) -> tuple[float, float]:
    """Equivalent (c, k) of the linear model in the state the damper settles to."""
    p = damper.parameters()
    if damper.kind == "maxwell":
        return dampers.maxwell_closed_form(
            float(p["damping"] or 0.0), float(p["series_stiffness"] or 0.0), frequency
        )
    cutoff = float(p["cutoff_frequency"] or 0.0)
    damping = p["high_damping"] if frequency > cutoff else p["low_damping"]
    return dampers.maxwell_closed_form(
        float(damping or 0.0),
        float(p["equivalent_stiffness"] or 0.0),
        frequency,
        float(p["equivalent_mass"] or 0.0),
    )


def run(args: argparse.Namespace) -> int:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    amplitude = float(args.amplitude)
    models = {"YD1": dampers.YD1, "YD2": dampers.YD2, "FSD": dampers.FSD}
    fig, axes = plt.subplots(2, len(FREQUENCIES_HZ), figsize=(11, 8), squeeze=False)
    summary: list[dict[str, object]] = []
    with open(out / "damper_bench_loops.csv", "w", newline="") as loops_file:
        loops_file.write(f"# loco {loco.__version__}; amplitude {amplitude} m; last cycles\n")
        loops = csv.writer(loops_file)
        loops.writerow(LOOP_COLUMNS)
        for column, frequency in enumerate(FREQUENCIES_HZ):
            for name, damper in models.items():
                result = dampers.bench(
                    damper, frequency, amplitude, CYCLES, equivalent_cycles=LOOP_CYCLES
                )
                last = result.time >= result.time[-1] - LOOP_CYCLES / frequency - 1e-12
                for row in zip(
                    result.time[last],
                    result.displacement[last],
                    result.velocity[last],
                    result.force[last],
                    result.scale_factor[last],
                    strict=True,
                ):
                    loops.writerow([name, frequency, *(f"{v:.9g}" for v in row)])
                c_closed, k_closed = _closed_form(damper, frequency)
                print(
                    f"{name:>4} {frequency:g} Hz: c_eq = "
                    f"{(result.equivalent_damping or 0) / 1e3:.1f} kN·s/m "
                    f"(linear model {c_closed / 1e3:.1f}), k_eq = "
                    f"{(result.equivalent_stiffness or 0) / 1e6:.3f} kN/mm"
                )
                summary.append(
                    {
                        "damper": name,
                        "frequency_hz": frequency,
                        "amplitude_m": amplitude,
                        "equivalent_damping_nspm": result.equivalent_damping,
                        "equivalent_stiffness_npm": result.equivalent_stiffness,
                        "energy_per_cycle_j": result.energy_per_cycle,
                        "closed_form_damping_nspm": c_closed,
                        "closed_form_stiffness_npm": k_closed,
                        "final_scale_factor": float(result.scale_factor[-1]),
                    }
                )
                axes[0][column].plot(result.velocity[last], result.force[last] / 1e3, label=name)
                axes[1][column].plot(
                    result.displacement[last] * 1e3, result.force[last] / 1e3, label=name
                )
            axes[0][column].set(
                title=f"force-velocity, {frequency:g} Hz, {amplitude * 1e3:g} mm",
                xlabel="velocity (m/s)",
                ylabel="force (kN)",
            )
            axes[1][column].set(
                title=f"hysteresis loop, {frequency:g} Hz, {amplitude * 1e3:g} mm",
                xlabel="displacement (mm)",
                ylabel="force (kN)",
            )
    for ax in np.ravel(axes):
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle(f"Yaw damper bench (loco {loco.__version__})")
    fig.tight_layout()
    fig.savefig(out / "damper_bench.png", dpi=120)
    plt.close(fig)
    with open(out / "damper_bench_summary.csv", "w", newline="") as summary_file:
        summary_file.write(f"# loco {loco.__version__}\n")
        writer = csv.DictWriter(summary_file, fieldnames=list(summary[0]))
        writer.writeheader()
        writer.writerows(summary)
    parameters = {
        "loco_version": loco.__version__,
        "amplitude_m": amplitude,
        "frequencies_hz": list(FREQUENCIES_HZ),
        "cycles": CYCLES,
        "loop_cycles": LOOP_CYCLES,
        "dampers": {name: {"kind": d.kind, **d.parameters()} for name, d in models.items()},
    }
    (out / "damper_bench_parameters.json").write_text(json.dumps(parameters, indent=2) + "\n")
    print(f"written to {out}")
    return 0
