"""FSD design study: NSGA-II on the simulator over the FSD's own design.

Design variables (:data:`VARIABLES`, SI units): low damping c1 and high damping c2 (N·s/m),
cut-off frequency f_p (Hz), switching delay (s) and the valve's amplitude threshold, the
reference stroke amplitude (m) at which the hydraulic valve (trigger ``"hydraulic"``,
``loco_core::dampers::frequency_valve``) is derived to cut off at f_p. The hydraulic valve is
the mechanism SPEC §4 describes; its threshold is a real design quantity (the orifice and spring
follow from it), where the rms-frequency estimator of the spec's FSD stays closed on both
scenarios whatever c1 (docs/guide/dampers.md, "The FSD's frequency valve"), so only its c2
would matter.

Objectives (minimised): W_y on S_low (metric ``wy_max``) and A_yb on S_high (``ayb_peak_lp``),
at the study's speed, after :data:`loco.studies.fsd_comparison.LEAD_IN` of lead-in (the valve
leaves its start state), on track 0 of the seed. Constraint: the linear critical speed on S_high
above :data:`SPEED_MARGIN` × the running speed. The linearised model holds the valve in its start
state (closed: c2 with the equivalent stiffness), so the constraint bounds c2's stability. A
design whose valve cannot be derived (the core refuses it with a typed error naming the field)
or whose run fails is infeasible, not dropped.

The picked designs (:func:`pick_designs`: the front's two ends and its knee) are re-simulated over
the conicity sweep of :mod:`loco.studies.fsd_conicity`.
"""

from __future__ import annotations

import contextvars
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from typing import Any, TypeVar

import numpy as np
import numpy.typing as npt
import pandas as pd

import loco
from loco import dampers
from loco.studies.fsd_comparison import JUDGED_BY, LEAD_IN
from loco.studies.seeds import run_over_tracks

__all__ = [
    "SPEED_MARGIN",
    "TRIGGER",
    "VARIABLES",
    "DesignSetup",
    "FsdDesignResult",
    "design_damper",
    "evaluate_designs",
    "pick_designs",
    "run_design_study",
]

FloatArray = npt.NDArray[np.float64]
T = TypeVar("T")

#: Design variables: name → (lower, upper) bound, SI units. c1 and c2 span the ranges of the
#: study's Maxwell yaw dampers (SPEC §6: 200–1200 kN·s/m) and lighter ones; f_p and the delay
#: bracket the spec's 2 Hz and 0.05 s; the reference stroke brackets the 0.26 mm S_low sway
#: stroke of the preset (the lower end) up to the millimetre strokes of hunting on S_high.
VARIABLES: dict[str, tuple[float, float]] = {
    "low_damping": (100e3, 400e3),
    "high_damping": (500e3, 1200e3),
    "cutoff_frequency": (1.0, 4.0),
    "switching_delay": (0.02, 0.2),
    "reference_stroke_amplitude": (0.2e-3, 3.0e-3),
}
#: The valve the study designs (``dampers.TRIGGERS``).
TRIGGER = "hydraulic"
#: The constraint: linear critical speed on S_high ≥ this × the running speed.
SPEED_MARGIN = 1.1
#: Top of the linear critical speed search, m/s (540 km/h): ``inf`` above.
SEARCH_HIGH = 150.0
#: Objective value of a design whose run failed: worse than any design that ran.
FAILED = 1e3
#: Population table columns after the design variables.
RESULT_COLUMNS = ("W_y", "A_yb", "v_crit_kmh", "error", "feasible")


@dataclass(frozen=True)
class DesignSetup:
    """How each design is judged: ``speed_kmh`` (km/h), recorded ``distance`` and ``lead_in`` (m),
    track ``seed`` (track 0 of it), the runs' ``integrator`` (at its own step), simulation
    ``threads`` (None: all cores)."""

    speed_kmh: float = 200.0
    distance: float = 500.0
    lead_in: float = LEAD_IN
    seed: int = 0
    threads: int | None = None
    integrator: str = loco.Scenario.integrator

    def settings(self) -> dict[str, Any]:
        """What the numbers depend on (not the thread count), JSON-ready."""
        return {
            "speed_kmh": self.speed_kmh,
            "distance_m": self.distance,
            "lead_in_m": self.lead_in,
            "track_seed": self.seed,
            "integrator": self.integrator,
            "trigger": TRIGGER,
            "variables": {k: list(v) for k, v in VARIABLES.items()},
            "objectives": dict(JUDGED_BY),
            "constraint": f"linear critical speed S_high (valve closed) >= {SPEED_MARGIN} x speed",
        }


def design_damper(x: Sequence[float] | FloatArray) -> dampers.Damper:
    """The hydraulic FSD of design vector ``x`` (:data:`VARIABLES` order); the core refuses a
    valve it cannot derive with :class:`loco.ParameterError` naming the field."""
    c1, c2, f_p, delay, stroke = (float(v) for v in x)
    return dampers.fsd(
        low_damping=c1,
        high_damping=c2,
        cutoff_frequency=f_p,
        switching_delay=delay,
        reference_stroke_amplitude=stroke,
        trigger=TRIGGER,
    )


def parallel_map(fn: Callable[[Any], T], items: Sequence[Any], threads: int | None) -> list[T]:
    """``fn`` over ``items`` on ``threads`` threads (the core releases the GIL), each call in a
    copy of the caller's context (so a ``loco.campaign.using`` block applies inside)."""
    context = contextvars.copy_context()
    with ThreadPoolExecutor(max(1, threads or 2)) as pool:
        return list(pool.map(lambda item: context.copy().run(fn, item), items))


def _run(setup: DesignSetup, law: dampers.Damper, scenario: str, metric: str) -> float:
    s = loco.Scenario(
        name=scenario,
        speed=setup.speed_kmh / 3.6,
        distance=setup.distance,
        lead_in=setup.lead_in,
        seed=setup.seed,
        yaw_damper=law,
        integrator=setup.integrator,
    )
    runs = run_over_tracks(s, 1, threads=1, progress=False)
    return float(runs.values(metric)[0])


def _critical_kmh(setup: DesignSetup, law: dampers.Damper) -> float:
    s = loco.Scenario(name="S_high", speed=setup.speed_kmh / 3.6, distance=100.0)
    vehicle = loco.Locomotive.default()
    return float(loco.critical_speed(vehicle, s.replace(yaw_damper=law), high=SEARCH_HIGH)) * 3.6


def evaluate_designs(x: npt.ArrayLike, setup: DesignSetup) -> pd.DataFrame:
    """Every design of ``x`` (n, 5): its variables and :data:`RESULT_COLUMNS` (W_y on S_low, A_yb
    on S_high, the linear critical speed on S_high with the valve closed, km/h, whether
    the constraint holds, and why a design is infeasible)."""
    designs = np.atleast_2d(np.asarray(x, dtype=np.float64))
    laws: list[dampers.Damper | None] = []
    errors: list[str] = []
    for row in designs:
        try:
            laws.append(design_damper(row))
            errors.append("")
        except loco.ParameterError as e:
            laws.append(None)
            errors.append(str(e))
    ok = [i for i, law in enumerate(laws) if law is not None]
    jobs: list[tuple[str, int, str]] = [(kind, i, "") for i in ok for kind in ("low", "high")]
    jobs += [("vcrit", i, "") for i in ok]

    def job(j: tuple[str, int, str]) -> float:
        kind, i, _ = j
        law = laws[i]
        assert law is not None
        try:
            if kind == "vcrit":
                return _critical_kmh(setup, law)
            scenario = "S_low" if kind == "low" else "S_high"
            return _run(setup, law, scenario, JUDGED_BY[scenario])
        except loco.SimulationError:
            return np.nan

    values = parallel_map(job, jobs, setup.threads)
    out = {k: np.full(len(designs), np.nan) for k in ("W_y", "A_yb", "v_crit_kmh")}
    column = {"low": "W_y", "high": "A_yb", "vcrit": "v_crit_kmh"}
    for (kind, i, _), value in zip(jobs, values, strict=True):
        out[column[kind]][i] = value
    frame = pd.DataFrame(designs, columns=list(VARIABLES))
    for name, col in out.items():
        frame[name] = col
    frame["error"] = errors
    frame["feasible"] = constraint(frame, setup) <= 0.0
    return frame


def constraint(frame: pd.DataFrame, setup: DesignSetup) -> FloatArray:
    """NSGA-II's inequality constraint per design (feasible where ≤ 0), km/h:
    :data:`SPEED_MARGIN` × speed minus the linear critical speed (``inf`` clipped, NaN — a valve
    that cannot be derived — counted as 0 km/h), plus the margin again for a failed run."""
    v = frame["v_crit_kmh"].fillna(0.0).clip(upper=10 * setup.speed_kmh).to_numpy()
    failed = frame[["W_y", "A_yb"]].isna().any(axis=1).to_numpy()
    limit = SPEED_MARGIN * setup.speed_kmh
    return np.asarray(limit - v + np.where(failed, limit, 0.0), dtype=np.float64)


@dataclass(frozen=True)
class FsdDesignResult:
    """The study: every evaluated design (``population``, with its generation), the final
    non-dominated feasible designs (``front``, sorted by W_y), the ``picks`` (label → front row)
    and the run time (s), in total and per generation."""

    population: pd.DataFrame
    front: pd.DataFrame
    picks: dict[str, int]
    seconds: float
    generation_seconds: tuple[float, ...] = ()

    def picked_dampers(self) -> dict[str, dampers.Damper]:
        """The picked designs as yaw damper laws, by label."""
        return {
            label: design_damper(self.front.loc[i, list(VARIABLES)].to_numpy(dtype=np.float64))
            for label, i in self.picks.items()
        }


def pick_designs(front: pd.DataFrame) -> dict[str, int]:
    """Labels of the front rows re-simulated: the lowest-W_y end, the knee (nearest the utopia
    point in objectives normalised over the front) and the lowest-A_yb end; one label per row."""
    if front.empty:
        return {}
    f = front[["W_y", "A_yb"]].to_numpy()
    span = np.ptp(f, axis=0)
    norm = (f - f.min(axis=0)) / np.where(span > 0, span, 1.0)
    rows = {
        "opt. FSD (knee)": int(np.argmin(np.hypot(norm[:, 0], norm[:, 1]))),
        "opt. FSD (low W_y)": int(np.argmin(f[:, 0])),
        "opt. FSD (low A_yb)": int(np.argmin(f[:, 1])),
    }
    picks: dict[str, int] = {}
    for label, i in rows.items():
        if i not in picks.values():
            picks[label] = i
    return picks


def run_design_study(
    setup: DesignSetup, *, pop_size: int, n_gen: int, seed: int = 0
) -> FsdDesignResult:
    """NSGA-II (pymoo, ``seed``) over :data:`VARIABLES` with ``pop_size`` designs for ``n_gen``
    generations, every design simulated (:func:`evaluate_designs`)."""
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.core.problem import Problem
    from pymoo.optimize import minimize

    start = time.perf_counter()
    evaluated: list[pd.DataFrame] = []
    timings: list[float] = []

    class Design(Problem):
        def __init__(self) -> None:
            bounds = np.array(list(VARIABLES.values()))
            super().__init__(
                n_var=len(VARIABLES), n_obj=2, n_ieq_constr=1, xl=bounds[:, 0], xu=bounds[:, 1]
            )

        def _evaluate(self, x: FloatArray, out: dict[str, Any], *a: Any, **k: Any) -> None:
            began = time.perf_counter()
            frame = evaluate_designs(x, setup)
            timings.append(time.perf_counter() - began)
            frame.insert(0, "generation", len(evaluated))
            evaluated.append(frame)
            # A failed run or an underivable valve is a bad design, not a missing one.
            out["F"] = frame[["W_y", "A_yb"]].fillna(FAILED).to_numpy()
            out["G"] = constraint(frame, setup)[:, None]

    minimize(Design(), NSGA2(pop_size=pop_size), ("n_gen", n_gen), seed=seed)
    population = pd.concat(evaluated, ignore_index=True)
    front = non_dominated(population[population["feasible"]])
    return FsdDesignResult(
        population=population,
        front=front,
        picks=pick_designs(front),
        seconds=time.perf_counter() - start,
        generation_seconds=tuple(timings),
    )


def non_dominated(frame: pd.DataFrame) -> pd.DataFrame:
    """Rows of ``frame`` no other row beats in both W_y and A_yb (duplicates kept once), sorted
    by W_y."""
    f = frame[["W_y", "A_yb"]].to_numpy()
    keep = []
    for i in range(len(f)):
        dominated = np.any(np.all(f <= f[i], axis=1) & np.any(f < f[i], axis=1))
        if not dominated:
            keep.append(i)
    out = frame.iloc[keep].drop_duplicates(subset=["W_y", "A_yb"])
    return out.sort_values(["W_y", "A_yb"], kind="stable").reset_index(drop=True)
