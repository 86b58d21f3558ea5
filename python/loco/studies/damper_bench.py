"""The damper bench stage: force-velocity curves and hysteresis loops of YD1, YD2, FSD (SPEC §6.5).

Each damper is driven with a sine elongation at 1 Hz and 4 Hz. The default amplitude, 3 mm, is of
the order of the yaw damper stroke of a bogie hunting or of carbody sway on straight track (a
bogie yaw of 1 mrad moves a damper mounted 1.3 m off the centre line by 1.3 mm, hunting cycles
reach a few mrad); at 4 Hz it gives a peak velocity of 0.075 m/s. The loops are taken over the
last cycles, after the FSD has settled. Writes ``damper_bench.png`` (both figures),
``damper_bench_loops.csv`` (time histories), ``damper_bench_summary.csv`` (equivalent damping,
stiffness and energy per cycle, with the closed form of the linear models) and
``damper_bench_parameters.json`` (loco version and every parameter). :func:`bench_study` does it
all and returns the report record (``loco damper-bench`` and ``loco reproduce`` run it).

The FSD is benched with both valve models (``FSD``: the rms-frequency estimate, ``FSD-H``: the
hydraulic valve), and :mod:`loco.studies.valve_bench` adds the valve state against time, the
hydraulic valve's cut-off against stroke amplitude and the two-tone (sway + dither) bench.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import pandas as pd

import loco
from loco import dampers
from loco.studies import captions as figure_captions
from loco.studies.plotting import pyplot, save_figure
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.stages import Runtime, Stage
from loco.studies.valve_bench import largest_opening_dither, run_valve_bench, save_valve_bench

FREQUENCIES_HZ = (1.0, 4.0)
#: Default sine amplitude of the elongation, m.
AMPLITUDE = 3e-3
CYCLES = 10
LOOP_CYCLES = 2
#: The dampers benched: the spec's presets and the FSD with the hydraulic valve.
BENCHED: dict[str, dampers.Damper] = dampers.COMPARED
LOOP_COLUMNS = (
    "damper",
    "frequency_hz",
    "time_s",
    "displacement_m",
    "velocity_mps",
    "force_n",
    "scale_factor",
)


def _closed_form(damper: dampers.Damper, frequency: float) -> tuple[float, float]:
    """Equivalent (c, k) of the linear model in the state the damper settles to."""
    p = damper.parameters()
    if damper.kind == "maxwell":
        return dampers.maxwell_closed_form(
            float(p["damping"] or 0.0), float(p["series_stiffness"] or 0.0), frequency
        )
    if p.get("trigger") == "hydraulic":
        # The hydraulic valve opens for part of each stroke: no linear state to settle to.
        return float("nan"), float("nan")
    cutoff = float(p["cutoff_frequency"] or 0.0)
    damping = p["high_damping"] if frequency > cutoff else p["low_damping"]
    return dampers.maxwell_closed_form(
        float(damping or 0.0),
        float(p["equivalent_stiffness"] or 0.0),
        frequency,
        float(p["equivalent_mass"] or 0.0),
    )


@dataclass(frozen=True)
class DamperBenchStage(Stage):
    """The stage ``damper_bench`` of ``loco reproduce``: :func:`bench_study` at the sine
    ``amplitude`` (m); the frequencies, cycles and dampers are this module's."""

    name: ClassVar[str] = "damper_bench"
    amplitude: float = AMPLITUDE

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """:func:`bench_study` into ``out_dir`` (a bench, no vehicle simulation)."""
        return bench_study(out_dir, self.amplitude, threads=runtime.threads)


def bench_study(
    out_dir: str | Path, amplitude: float = AMPLITUDE, *, threads: int | None = None
) -> StudyRecord:
    """Bench YD1, YD2 and FSD at :data:`FREQUENCIES_HZ` with a sine of ``amplitude`` (m); write
    the figure, tables and parameters into ``out_dir`` and return the report record. The valve
    bench's runs share ``threads`` threads (None: one per core); the results do not depend on
    it."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    fig, axes = pyplot().subplots(2, len(FREQUENCIES_HZ), figsize=(11, 8), squeeze=False)
    summary: list[dict[str, object]] = []
    loops: list[pd.DataFrame] = []
    for column, frequency in enumerate(FREQUENCIES_HZ):
        for name, damper in BENCHED.items():
            result = dampers.bench(
                damper, frequency, amplitude, CYCLES, equivalent_cycles=LOOP_CYCLES
            )
            last = result.time >= result.time[-1] - LOOP_CYCLES / frequency - 1e-12
            loops.append(
                pd.DataFrame(
                    {
                        "damper": name,
                        "frequency_hz": frequency,
                        "time_s": result.time[last],
                        "displacement_m": result.displacement[last],
                        "velocity_mps": result.velocity[last],
                        "force_n": result.force[last],
                        "scale_factor": result.scale_factor[last],
                    },
                    columns=list(LOOP_COLUMNS),
                )
            )
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
    parameters = {
        "loco_version": loco.__version__,
        "amplitude_m": amplitude,
        "frequencies_hz": list(FREQUENCIES_HZ),
        "cycles": CYCLES,
        "loop_cycles": LOOP_CYCLES,
        "dampers": {name: dampers.describe(d) for name, d in BENCHED.items()},
        "valve_reference_stroke_m": dampers.REFERENCE_STROKE_AMPLITUDE,
    }
    valve = run_valve_bench(dampers.REFERENCE_STROKE_AMPLITUDE, threads=threads)
    valve_figures, valve_tables = save_valve_bench(valve, out)
    limits = largest_opening_dither(valve)
    limit_text = "; ".join(
        f"{r.trigger} {r.dither_hz:g} Hz: opens up to a dither of {r.largest_opening_ratio:g}"
        for r in limits.itertuples()
    )
    no_dither = {
        r.trigger: r.open_fraction_without_dither
        for r in limits.drop_duplicates("trigger").itertuples()
    }
    return StudyRecord(
        name=out.name,
        title="Yaw damper bench: YD1, YD2 and FSD at 1 and 4 Hz (SPEC §6.5)",
        figures=[save_figure(fig, out / "damper_bench.png"), *valve_figures],
        tables=[
            save_table(pd.DataFrame(summary), out / "damper_bench_summary.csv"),
            save_table(pd.concat(loops, ignore_index=True), out / "damper_bench_loops.csv"),
            save_json(parameters, out / "damper_bench_parameters.json"),
            *valve_tables,
        ],
        parameters={k: v for k, v in parameters.items() if k != "dampers"},
        captions=figure_captions.DAMPER_BENCH,
        notes="Force-velocity curves (top) and hysteresis loops (bottom) over the last "
        f"{LOOP_CYCLES} of {CYCLES} cycles of sine excitation; FSD-H is the FSD with the "
        "hydraulic frequency valve. Valve bench at the reference stroke "
        f"{dampers.REFERENCE_STROKE_AMPLITUDE * 1e3:.2f} mm: open fraction of a pure 1.2 Hz "
        + ", ".join(f"{k} {v:.2f}" for k, v in no_dither.items())
        + f"; with a dither (amplitude over the stroke's, open >= 5 % of the time): {limit_text}.",
    )
