"""The ``fsd_design`` stage of ``loco reproduce``: the FSD design study
(:mod:`loco.studies.fsd_search`), its picked designs and the reference yaw dampers over the
conicity sweep (:mod:`loco.studies.fsd_conicity`), their linear critical speeds on the three
scenarios, one figure.

Sizes per preset (:data:`SIZES`): ``full`` is population 16 × 6 generations (96 designs, each
two 1 000 m runs and one linear critical speed) and 7 conicities × 3 tracks for up to 6 dampers
(docs/study_results.md, "FSD design study", for its measured time); ``quick`` a small
version, ``tiny`` the test's (300 m, no lead-in). The stage's JSON records the time of each part
and its run counts.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import pandas as pd

import loco
from loco import dampers
from loco.channels import Metric
from loco.studies import captions as figure_captions
from loco.studies import fsd_conicity, fsd_search
from loco.studies.fsd_comparison import LEAD_IN
from loco.studies.plotting import pyplot, save_figure
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.stages import Demand, Runtime, Stage

__all__ = ["SIZES", "DesignSizes", "FsdDesignStage", "design_settings", "run_fsd_design"]


@dataclass(frozen=True)
class DesignSizes:
    """NSGA-II ``pop_size`` × ``n_gen``; each run records ``distance`` m after ``lead_in`` m; the
    sweep's ``conicities`` (–) on ``n_tracks`` tracks; the linear critical speeds of every damper
    on ``critical_scenarios``."""

    pop_size: int
    n_gen: int
    distance: float
    lead_in: float
    conicities: tuple[float, ...]
    n_tracks: int
    critical_scenarios: tuple[str, ...] = ("S_low", "S_norm", "S_high")


SIZES: dict[str, DesignSizes] = {
    "full": DesignSizes(16, 6, 500.0, LEAD_IN, (0.02, 0.05, 0.1, 0.2, 0.3, 0.45, 0.661), 3),
    "quick": DesignSizes(8, 3, 500.0, LEAD_IN, (0.02, 0.1, 0.3, 0.661), 1),
    "tiny": DesignSizes(4, 1, 300.0, 0.0, (0.05, 0.661), 1, ("S_high",)),
}
#: The reference yaw dampers of the sweep: the study's (the paper's FSD is ``FSD``).
REFERENCES: dict[str, dampers.Damper] = dict(dampers.PRESETS)


def design_settings(
    sizes: DesignSizes, *, speed_kmh: float, seed: int, integrator: str = loco.Scenario.integrator
) -> dict[str, Any]:
    """The stage's settings as its JSON file and report show them."""
    setup = fsd_search.DesignSetup(
        speed_kmh=speed_kmh,
        distance=sizes.distance,
        lead_in=sizes.lead_in,
        seed=seed,
        integrator=integrator,
    )
    return {
        **setup.settings(),
        **asdict(sizes),
        "nsga2_seed": seed,
        "references": {n: dampers.describe(d) for n, d in REFERENCES.items()},
    }


@dataclass(frozen=True)
class FsdDesignStage(Stage):
    """The stage ``fsd_design`` of ``loco reproduce``: its ``sizes``, the running speed (km/h),
    the seed of the tracks and of NSGA-II and the runs' integration scheme."""

    name: ClassVar[str] = "fsd_design"
    sizes: DesignSizes
    speed_kmh: float = 200.0
    seed: int = 0
    integrator: str = loco.Scenario.integrator

    def demand(self) -> Demand:
        """At most: two runs (S_low, S_high) per design NSGA-II evaluates (``pop_size`` per
        generation), and every reference and picked design (up to three) on every conicity and
        track (a valve the core refuses, or picks that coincide, run none)."""
        s = self.sizes
        n = 2 * s.pop_size * s.n_gen + (len(REFERENCES) + 3) * len(s.conicities) * s.n_tracks
        return Demand.runs(n, s.lead_in + s.distance, self.speed_kmh / 3.6)

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """:func:`run_fsd_design` into ``out_dir``."""
        return run_fsd_design(
            self.sizes,
            out_dir,
            speed_kmh=self.speed_kmh,
            seed=self.seed,
            threads=runtime.threads,
            integrator=self.integrator,
        )


def linear_critical_speeds(
    laws: dict[str, dampers.Damper],
    scenarios: tuple[str, ...],
    speed_kmh: float,
    threads: int | None,
) -> pd.DataFrame:
    """Linear critical speed (km/h; ``inf`` above 540 km/h) of every law on ``scenarios``, with
    the valve as the linearisation holds it (its start state, closed)."""
    jobs = [(s, n) for s in scenarios for n in laws]
    vehicle = loco.Locomotive.default()

    def one(job: tuple[str, str]) -> float:
        s = loco.Scenario(name=job[0], speed=speed_kmh / 3.6, distance=100.0)
        v = loco.critical_speed(
            vehicle, s.replace(yaw_damper=laws[job[1]]), high=fsd_search.SEARCH_HIGH
        )
        return float(v) * 3.6

    values = fsd_search.parallel_map(one, jobs, threads)
    return pd.DataFrame(
        [
            {"scenario": s, "damper": n, "linear_kmh": v}
            for (s, n), v in zip(jobs, values, strict=True)
        ]
    )


def run_fsd_design(
    sizes: DesignSizes,
    out_dir: str | Path,
    *,
    speed_kmh: float = 200.0,
    seed: int = 0,
    threads: int | None = None,
    integrator: str = loco.Scenario.integrator,
) -> StudyRecord:
    """Run the study into ``out_dir``; files: ``fsd_design_population.csv`` (every design and
    generation), ``fsd_design_front.csv``, ``fsd_design_conicity.csv`` (every run of the sweep)
    and ``..._summary.csv``, ``fsd_design_critical_speeds.csv``, ``fsd_design.png``,
    ``fsd_design.json``."""
    marks = [_clock()]
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    setup = fsd_search.DesignSetup(
        speed_kmh=speed_kmh,
        distance=sizes.distance,
        lead_in=sizes.lead_in,
        seed=seed,
        threads=threads,
        integrator=integrator,
    )
    study = fsd_search.run_design_study(
        setup, pop_size=sizes.pop_size, n_gen=sizes.n_gen, seed=seed
    )
    marks.append(_clock())
    laws = {**REFERENCES, **study.picked_dampers()}
    sweep = fsd_conicity.run_conicity_sweep(
        laws,
        sizes.conicities,
        speed_kmh=speed_kmh,
        distance=sizes.distance,
        lead_in=sizes.lead_in,
        seed=seed,
        n_tracks=sizes.n_tracks,
        threads=threads,
        integrator=integrator,
    )
    summary = fsd_conicity.sweep_summary(sweep)
    marks.append(_clock())
    critical = linear_critical_speeds(laws, sizes.critical_scenarios, speed_kmh, threads)
    marks.append(_clock())
    picks = {
        label: {k: float(study.front[k].iloc[i]) for k in [*fsd_search.VARIABLES, "W_y", "A_yb"]}
        for label, i in study.picks.items()
    }
    parts = ("optimisation", "sweep", "critical_speeds")
    wall, cpu = (
        {part: marks[i + 1][k] - marks[i][k] for i, part in enumerate(parts)} for k in (0, 1)
    )
    seconds = marks[-1][0] - marks[0][0]
    settings = {
        **design_settings(sizes, speed_kmh=speed_kmh, seed=seed, integrator=integrator),
        "loco_version": loco.__version__,
        "picked_designs": picks,
        "designs_evaluated": len(study.population),
        "feasible_designs": int(study.population["feasible"].sum()),
        "optimisation_seconds": wall["optimisation"],
        "seconds": seconds,
        "part_seconds": wall,
        "generation_seconds": list(study.generation_seconds),
        # CPU time of all the process's threads, s: what the parts cost whatever the machine's
        # load (the wall time on a shared machine is not).
        "part_cpu_seconds": cpu,
        "runs": run_counts(study, sweep, critical),
    }
    figure = plot_design(study, summary, out / "fsd_design.png", sizes, speed_kmh)
    tables = [
        save_table(study.population, out / "fsd_design_population.csv"),
        save_table(study.front, out / "fsd_design_front.csv"),
        save_table(sweep, out / "fsd_design_conicity.csv"),
        save_table(summary, out / "fsd_design_conicity_summary.csv"),
        save_table(critical, out / "fsd_design_critical_speeds.csv"),
        save_json(settings, out / "fsd_design.json"),
    ]
    return StudyRecord(
        name=out.name,
        title="FSD design study: NSGA-II on the simulator, conicity sweep",
        figures=[figure],
        tables=tables,
        parameters={k: v for k, v in settings.items() if k != "references"},
        seconds=seconds,
        notes=_notes(study, summary, critical, wall["optimisation"], speed_kmh),
        captions=figure_captions.FSD_DESIGN,
    )


def _clock() -> tuple[float, float]:
    """(wall, CPU of every thread of the process) time, s."""
    return time.perf_counter(), time.process_time()


def run_counts(
    study: fsd_search.FsdDesignResult, sweep: pd.DataFrame, critical: pd.DataFrame
) -> dict[str, int]:
    """How many simulations and linear critical speeds each part of the stage computed: two runs
    and one critical speed per design whose valve could be derived, one run per sweep row, one
    critical speed per damper and scenario."""
    derived = int((study.population["error"] == "").sum())
    return {
        "design_runs": 2 * derived,
        "design_critical_speeds": derived,
        "sweep_runs": len(sweep),
        "critical_speeds": len(critical),
    }


def _notes(
    study: fsd_search.FsdDesignResult,
    summary: pd.DataFrame,
    critical: pd.DataFrame,
    optimisation_seconds: float,
    speed_kmh: float,
) -> str:
    pop = study.population
    lines = [
        f"{len(pop)} designs simulated ({int(pop['feasible'].sum())} feasible: linear critical "
        f"speed on S_high with the valve closed ≥ {fsd_search.SPEED_MARGIN} × {speed_kmh:g} "
        f"km/h and both runs finished) in {optimisation_seconds:.0f} s; front of "
        f"{len(study.front)}: W_y {study.front['W_y'].min():.3f}–{study.front['W_y'].max():.3f},"
        f" A_yb {study.front['A_yb'].min():.3f}–{study.front['A_yb'].max():.3f} m/s²."
        if len(study.front)
        else f"{len(pop)} designs simulated, none feasible."
    ]
    for label, i in study.picks.items():
        row = study.front.loc[i]
        lines.append(
            f"{label}: c1 {row['low_damping'] / 1e3:.0f}, c2 {row['high_damping'] / 1e3:.0f} "
            f"kN·s/m, f_p {row['cutoff_frequency']:.2f} Hz, delay {row['switching_delay']:.3f} s,"
            f" reference stroke {row['reference_stroke_amplitude'] * 1e3:.2f} mm."
        )
    table = critical.pivot(index="damper", columns="scenario", values="linear_kmh")
    scenarios = list(dict.fromkeys(critical["scenario"]))
    lines.append(
        f"Linear critical speed (km/h, valve closed) {' / '.join(scenarios)}: "
        + "; ".join(
            f"{d} " + " / ".join(f"{table.loc[d, s]:.0f}" for s in scenarios) for d in table.index
        )
        + "."
    )
    return " ".join(lines)


def plot_design(
    study: fsd_search.FsdDesignResult,
    summary: pd.DataFrame,
    path: Path,
    sizes: DesignSizes,
    speed_kmh: float,
) -> Path:
    """Designs in the objective plane (grey: infeasible), and W_y and A_yb against conicity for
    every damper (mean and range over the tracks)."""
    plt = pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5), layout="constrained")
    pop = study.population
    ok = pop["feasible"].to_numpy()
    axes[0].scatter(pop["W_y"][~ok], pop["A_yb"][~ok], s=10, color="0.7", label="infeasible")
    axes[0].scatter(pop["W_y"][ok], pop["A_yb"][ok], s=12, color="C0", label="feasible")
    if len(study.front):
        axes[0].plot(study.front["W_y"], study.front["A_yb"], "o-", color="C3", label="front")
    axes[0].set(xlabel="W_y, S_low", ylabel="A_yb peak, S_high (m/s²)", title="designs")
    axes[0].legend(fontsize=7)
    panels = ((axes[1], Metric.WY_MAX, "W_y"), (axes[2], Metric.AYB_PEAK_LP, "A_yb (m/s²)"))
    for ax, metric, label in panels:
        for k, name in enumerate(dict.fromkeys(summary["damper"])):
            c, mean, lo, hi = fsd_conicity.summary_array(summary, name, metric).T
            err = np.vstack([mean - lo, hi - mean])
            ax.errorbar(c, mean, yerr=err, fmt="o-", ms=4, capsize=3, color=f"C{k}", label=name)
        ax.set(xscale="log", xlabel="equivalent conicity at 3 mm (–)", ylabel=label)
        ticks = list(sizes.conicities)
        ax.set_xticks(ticks, [f"{t:g}" for t in ticks])
        ax.minorticks_off()
        ax.grid(True, alpha=0.3)
    axes[1].legend(fontsize=7)
    fig.suptitle(
        f"FSD design (hydraulic valve): NSGA-II pop {sizes.pop_size} × {sizes.n_gen} gen, "
        f"{speed_kmh:g} km/h; conicity sweep on {sizes.n_tracks} track(s); loco {loco.__version__}"
    )
    return save_figure(fig, path)
