"""The conicity sweep of the FSD design study: yaw dampers re-simulated on wheels of given
equivalent conicity.

How the conicity is changed, from the model's own wheel geometry (``loco.profiles.jm3``, the
JM3-type family of the built-in wheels, on the CN60 rail inclined 1:40, the study's track):

- up to :data:`MAX_CONE` (0.25): the new JM3 wheel with its tread band replaced by a straight cone
  of slope λ. The contact point on the rail is where the rail's slope equals the cone's, so it
  does not move and EN 15302's Δr is exactly 2λy: the equivalent conicity is λ at every
  amplitude. Steeper cones meet the flange face above the depth the flange thickness is measured
  at, so the flange no longer fits;
- above it: the hollow-worn tread of ``jm3-worn`` (slope 1:10 at the taping line) whose band
  radius is found by bisection (:func:`worn_band_radius`) so that the EN 15302 equivalent
  conicity at 3 mm (``loco.conicity.equivalent_conicity``, the core's kinematic method) is the
  requested one: a band conforming more to the rail's R80 shoulder gives a higher conicity
  (0.25 at about 200 mm, 0.664 at 125 mm; the built-in ``jm3-worn`` is R124, 0.661, and is the
  sweep's wheel at that value). Between 125.2 and 125.3 mm the conicity jumps from 0.6645 to
  0.6571 (the contact point jumps), and below 125 mm it is no longer monotonic in the radius
  (peak near 0.669), so the sweep stops at :data:`MAX_CONICITY`, the S_high wheel's 0.661,
  not 0.7.

Every case runs on the study's synthesised track (the scenarios differ only by their wheel), at
the study's speed after the FSD comparison's lead-in, on tracks ``0 … n-1`` of the seed; both
W_y and A_yb come from each run.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

import loco
from loco import dampers, profiles
from loco.conicity import equivalent_conicity
from loco.studies.fsd_comparison import JUDGED_BY, LEAD_IN
from loco.studies.fsd_search import parallel_map
from loco.studies.seeds import TrackRuns, run_over_tracks

__all__ = [
    "MAX_CONE",
    "MAX_CONICITY",
    "MIN_CONICITY",
    "conicity_wheel",
    "run_conicity_sweep",
    "worn_band_radius",
]

#: Steepest straight cone of the JM3 family (–): ``loco_core`` ``jm3::MAX_CONE_SLOPE``.
MAX_CONE = 0.25
#: Flattest cone of the sweep (–): the issue's lower end.
MIN_CONICITY = 0.02
#: Highest conicity the hollow-worn family reaches (–): the built-in ``jm3-worn``'s.
MAX_CONICITY = 0.661
#: The worn tread's slope at the taping line (–), that of ``jm3-worn``.
WORN_SLOPE = 0.1
#: Band radii over which the worn family's conicity falls monotonically, m (0.664 to 0.137;
#: between 124 and 125 mm it wobbles by 0.003, the built-in R124's 0.6614 inside the wobble).
WORN_BRACKET = (0.125, 0.5)
#: Largest difference between the requested and the reached conicity of a worn wheel (–).
CONICITY_TOLERANCE = 1e-3
#: The rail of the sweep (the study's) and the amplitude its conicity is judged at (m).
RAIL = "cn60"
AMPLITUDE = 0.003
#: Metrics re-simulated (W_y judges S_low, A_yb S_high; here both from every run).
METRICS: tuple[str, ...] = tuple(JUDGED_BY.values())


def worn_band_radius(conicity: float, *, tolerance: float = 1e-6) -> float:
    """Band radius (m) of the hollow-worn JM3 tread whose EN 15302 equivalent conicity at 3 mm on
    the study's rail is ``conicity`` (–, in about [0.14, 0.664]), by bisection over
    :data:`WORN_BRACKET` (where the conicity falls as the radius grows)."""
    lo, hi = WORN_BRACKET

    def tan(r: float) -> float:
        return equivalent_conicity(profiles.jm3(WORN_SLOPE, r), RAIL, AMPLITUDE)

    if not (tan(hi) <= conicity <= tan(lo) + 1e-9):
        raise loco.ParameterError(
            f"invalid parameter `conicity`: the worn family spans [{tan(hi):.3f}, {tan(lo):.3f}],"
            f" got {conicity}"
        )
    while hi - lo > tolerance:
        mid = 0.5 * (lo + hi)
        if tan(mid) > conicity:
            lo = mid
        else:
            hi = mid
    radius = 0.5 * (lo + hi)
    reached = tan(radius)
    if abs(reached - conicity) > CONICITY_TOLERANCE:
        raise loco.ParameterError(
            f"invalid parameter `conicity`: {conicity} lies in a jump of the worn family "
            f"(the contact point jumps at a band radius of {radius:.5f} m: {reached:.4f})"
        )
    return radius


def conicity_wheel(conicity: float) -> profiles.Profile:
    """The sweep's wheel of equivalent conicity ``conicity`` (–, in [:data:`MIN_CONICITY`,
    :data:`MAX_CONICITY`]) on the study's rail: a straight cone up to :data:`MAX_CONE`, the
    hollow-worn tread above (module documentation)."""
    c = float(conicity)
    if not (MIN_CONICITY - 1e-12 <= c <= MAX_CONICITY + 1e-12):
        raise loco.ParameterError(
            f"invalid parameter `conicity`: must be in [{MIN_CONICITY}, {MAX_CONICITY}], got {c}"
        )
    if c <= MAX_CONE:
        return profiles.jm3(c, math.inf)
    if abs(c - MAX_CONICITY) < CONICITY_TOLERANCE:
        # The family's conicity jumps from 0.6645 to 0.6571 at R125.25 (the contact point
        # jumps); the S_high wheel, R124, is the member that has 0.661.
        return profiles.builtin("jm3-worn")
    return profiles.jm3(WORN_SLOPE, worn_band_radius(c))


def sweep_settings(
    laws: Mapping[str, dampers.Damper],
    conicities: Sequence[float],
    *,
    speed_kmh: float,
    distance: float,
    lead_in: float = LEAD_IN,
    seed: int,
    n_tracks: int,
) -> dict[str, Any]:
    """What the sweep's numbers depend on, JSON-ready."""
    return {
        "conicities": [float(c) for c in conicities],
        "wheels": "JM3 straight cone up to 0.25, hollow-worn band radius above (fsd_conicity)",
        "rail": RAIL,
        "speed_kmh": speed_kmh,
        "distance_m": distance,
        "lead_in_m": lead_in,
        "track_seed": seed,
        "n_tracks": n_tracks,
        "dampers": {n: dampers.describe(d) for n, d in laws.items()},
    }


def run_conicity_sweep(
    laws: Mapping[str, dampers.Damper],
    conicities: Sequence[float],
    *,
    speed_kmh: float = 200.0,
    distance: float = 500.0,
    lead_in: float = LEAD_IN,
    seed: int = 0,
    n_tracks: int = 1,
    threads: int | None = None,
    integrator: str = loco.Scenario.integrator,
) -> pd.DataFrame:
    """Every yaw damper of ``laws`` on the wheel of each conicity, on tracks ``0 … n_tracks-1``
    with ``integrator`` at its own step: one row per (damper, requested conicity, track) with the
    measured EN 15302 conicity of the wheel, W_y, A_yb, the run status and its message."""
    wheels = {float(c): conicity_wheel(c) for c in conicities}
    measured = {c: equivalent_conicity(w, RAIL, AMPLITUDE) for c, w in wheels.items()}
    jobs = [(c, name) for c in wheels for name in laws]

    def one(job: tuple[float, str]) -> TrackRuns:
        c, name = job
        scenario = loco.Scenario(
            name="S_norm",
            speed=speed_kmh / 3.6,
            distance=distance,
            lead_in=lead_in,
            seed=seed,
            yaw_damper=laws[name],
            integrator=integrator,
        ).replace(name=None, wheel=wheels[c], rail=RAIL)
        return run_over_tracks(scenario, n_tracks, threads=1, progress=False)

    # One case per worker, its tracks in turn: a case's few tracks would leave cores idle, and
    # each case builds its own contact table. The numbers do not depend on the split.
    rows = []
    for (c, name), runs in zip(jobs, parallel_map(one, jobs, threads), strict=True):
        for i in range(runs.n_tracks):
            row: dict[str, Any] = {"damper": name, "conicity": c, "measured_conicity": measured[c]}
            row["track"] = i
            for metric in METRICS:
                row[metric] = float(runs.values(metric)[i])
            row["status"] = int(runs.status[i])
            row["message"] = runs.messages[i]
            rows.append(row)
    return pd.DataFrame(rows)


def sweep_summary(table: pd.DataFrame) -> pd.DataFrame:
    """Mean, min and max over the tracks of W_y and A_yb per (damper, conicity)."""
    g = table.groupby(["damper", "conicity"], sort=False)[list(METRICS)]
    out = g.agg(["mean", "min", "max"])
    out.columns = [f"{pair[0]}_{pair[1]}" for pair in out.columns]
    return out.reset_index().assign(n_tracks=g.size().to_numpy())


def summary_array(summary: pd.DataFrame, damper: str, metric: str) -> np.ndarray:
    """(conicity, mean, min, max) columns of one damper and metric, sorted by conicity."""
    s = summary[summary["damper"] == damper].sort_values("conicity")
    return s[["conicity", f"{metric}_mean", f"{metric}_min", f"{metric}_max"]].to_numpy()
