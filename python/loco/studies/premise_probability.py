"""The verdict's probability: how many plausible locomotives have the study's premise, and what
the FSD does on them.

A plausible locomotive is the default vehicle with every ranged vehicle input
(:func:`loco.uncertainty.ranges`, the inputs that can change a run) drawn from its range by a
Latin hypercube, and an S_low wheel/rail pair drawn from :data:`S_LOW_PAIRS`, the low-conicity
pairs of the study and of its field problem (each pair for an equal share of the locomotives,
assigned by a seeded permutation: which of them a fleet runs on is not known, so each is given
the same weight, a judgement). S_high is the worn JM3 on CN60 1:40 for every locomotive. Each
runs with YD1, YD2, FSD and FSD-H on its S_low pair and on S_high, ``distance`` metres at
``speed`` after the study's lead-in, on ``n_tracks`` synthesised tracks (track ``j``: the track
of seed ``j``, the same for every locomotive and damper). The yaw dampers are the presets at
their nominal laws: what is compared is the damper designs, on uncertain locomotives.

The premise rule, fixed before any run (:data:`PREMISE_RULE`): a locomotive has the premise when
its track-mean S_low A_yc PSD peak with YD2 is at least twice that with YD1 (high damping makes
the carbody sway) and its track-mean S_high A_yb peak (10 Hz low-passed) with YD1 is at least
twice that with YD2 (low damping lets the bogies hunt).

:func:`run_plausible` runs them (one ``loco.run_batch`` per pair, damper, scenario and track, so
an executor and a store make it a resumable Dask campaign); :func:`summarise` gives the fraction
with the premise and its 95 % interval, per pair and pooled; the FSD's and FSD-H's A_yc and A_yb
against the better fixed damper inside that set, and how much of the S_low record their valves
were open (track 0). Which inputs decide the premise and the FSDs' advantage is
:mod:`loco.studies.plausible`'s (random forests validated on held-out locomotives).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

import loco
from loco import dampers, uncertainty
from loco.channels import Metric
from loco.contact_pairs import ContactPair
from loco.studies.fsd_comparison import LEAD_IN, valve_closed_fraction

__all__ = [
    "DAMPERS",
    "PREMISE_RULE",
    "S_HIGH_PAIR",
    "S_LOW_PAIRS",
    "Plausible",
    "from_frame",
    "premise_holds",
    "run_plausible",
    "sample_locomotives",
    "summarise",
    "to_frame",
]

#: The low-conicity S_low pairs: the study's thin-flange JM3 on CN60 1:40, the same on rail
#: ground at the gauge corner, and the newly turned JM3 on rails inclined 1:20 and on ground
#: rails inclined 1:20 (the field problem: reprofiled wheels, gauge-corner grinding, a larger
#: rail cant). The thin flange on 1:20 is left out: its conicity is about zero (EN 15302 finds
#: no centred running position), not the low conicity of the problem.
S_LOW_PAIRS: tuple[ContactPair, ...] = (
    ContactPair("jm3-thin-flange", "cn60", 40),
    ContactPair("jm3-thin-flange", "cn60-gauge-ground", 40),
    ContactPair("jm3-new", "cn60", 20),
    ContactPair("jm3-new", "cn60-gauge-ground", 20),
)
#: The high-conicity pair: the study's S_high.
S_HIGH_PAIR = ContactPair("jm3-worn", "cn60", 40)
#: The yaw dampers, by name.
DAMPERS: dict[str, dampers.Damper] = dampers.COMPARED
#: The metric that judges each scenario in the premise rule.
JUDGE = {"S_low": Metric.AYC_PSD_PEAK, "S_high": Metric.AYB_PEAK_LP}
#: Factor of the premise rule.
FACTOR = 2.0
#: The FSDs whose valve states are recorded, and the columns of :attr:`Plausible.valves`.
VALVED = ("FSD", "FSD-H")
VALVE_COLUMNS = tuple(f"S_low {d} valve open" for d in VALVED)
PREMISE_RULE = (
    f"S_low A_yc PSD peak with YD2 at least {FACTOR:g} times that with YD1, and S_high A_yb peak "
    f"(10 Hz low-passed) with YD1 at least {FACTOR:g} times that with YD2 (track means)"
)


def sampled_inputs(
    vehicle: loco.Locomotive | None = None, ranges_file: str | Path | None = None
) -> pd.DataFrame:
    """The ranged vehicle inputs a plausible locomotive draws: the rows of
    :func:`loco.uncertainty.ranges` that can change a run, without the scenario's (the pair
    stands for the wheel and the rail inclination) and without the yaw damper's (the presets
    replace it)."""
    table = uncertainty.screened_inputs(
        uncertainty.ranges(vehicle, ranges_file), list(uncertainty.OUTPUTS)
    )
    left_out = set(uncertainty.PRESET_DAMPER_KEYS)
    keep = [not k.startswith(("wheel.", "scenario.")) and k not in left_out for k in table["key"]]
    return table[keep].reset_index(drop=True)


def sample_locomotives(
    n: int,
    seed: int = 0,
    vehicle: loco.Locomotive | None = None,
    ranges_file: str | Path | None = None,
) -> tuple[pd.DataFrame, list[str]]:
    """``n`` plausible locomotives: a frame of their inputs (SI; a Latin hypercube over
    :func:`sampled_inputs`, scipy's, from ``seed``) and each one's S_low pair label (equal
    shares of :data:`S_LOW_PAIRS` by a permutation from ``seed``)."""
    from scipy.stats import qmc

    if not (isinstance(n, int) and n >= len(S_LOW_PAIRS)):
        raise loco.ParameterError(
            f"invalid parameter `n`: must be a whole number ≥ {len(S_LOW_PAIRS)}, got {n!r}"
        )
    table = sampled_inputs(vehicle, ranges_file)
    unit = qmc.LatinHypercube(d=len(table), seed=seed).random(n)
    values = qmc.scale(unit, table["low"].to_numpy(float), table["high"].to_numpy(float))
    rng = np.random.default_rng(seed)
    pairs = [S_LOW_PAIRS[i % len(S_LOW_PAIRS)].label for i in rng.permutation(n)]
    return pd.DataFrame(values, columns=list(table["key"])), pairs


@dataclass(frozen=True)
class Plausible:
    """The runs of :func:`run_plausible`: the inputs, each locomotive's S_low pair, and the
    track-mean judging metric per (scenario, damper) (``metrics``, one column each, named
    ``"<scenario> <damper>"``; NaN where a run failed) with the number of failed runs."""

    inputs: pd.DataFrame
    pairs: list[str]
    metrics: pd.DataFrame
    failed: int
    settings: dict[str, Any]
    #: Per locomotive, the share of the S_low record (track 0) the valves of each FSD were
    #: open, mean over its valves (columns :data:`VALVE_COLUMNS`; NaN where the run failed).
    valves: pd.DataFrame = dataclasses.field(default_factory=pd.DataFrame)


def run_plausible(
    n: int = 200,
    seed: int = 0,
    *,
    n_tracks: int = 2,
    speed: float = 200 / 3.6,
    distance: float = 500.0,
    vehicle: loco.Locomotive | None = None,
    threads: int | None = None,
    progress: bool = True,
    executor: Any = None,
    store: str | Path | None = None,
    integrator: str = loco.Scenario.integrator,
    ranges_file: str | Path | None = None,
) -> Plausible:
    """Run ``n`` plausible locomotives (:func:`sample_locomotives`) with every damper of
    :data:`DAMPERS` on their S_low pair and on S_high, ``distance`` m at ``speed`` (m/s) after
    the study's lead-in, on tracks ``0 … n_tracks-1``. ``executor`` and ``store`` go to each
    ``loco.run_batch`` (a Dask cluster, a resumable store); every run uses ``integrator``; the
    ranges are those of ``ranges_file`` (default: the embedded ranges file)."""
    inputs, pairs = sample_locomotives(n, seed, vehicle, ranges_file)
    names = list(inputs.columns)
    by_pair = {p.label: p for p in S_LOW_PAIRS}
    metrics = pd.DataFrame(index=range(n), dtype=float)
    valves = pd.DataFrame(np.nan, index=range(n), columns=list(VALVE_COLUMNS))
    failed = 0
    groups: list[tuple[str, ContactPair, np.ndarray]] = [
        ("S_low", by_pair[label], np.flatnonzero(np.asarray(pairs) == label)) for label in by_pair
    ]
    groups.append(("S_high", S_HIGH_PAIR, np.arange(n)))
    for scenario_name, pair, rows in groups:
        metric = JUDGE[scenario_name]
        for damper_name, law in DAMPERS.items():
            per_track = np.full((len(rows), n_tracks), np.nan)
            for track in range(n_tracks):
                # The valve states of the FSDs on S_low, track 0: their histories are kept.
                valved = scenario_name == "S_low" and damper_name in VALVED and track == 0
                scenario = loco.Scenario(
                    wheel=pair.wheel,
                    rail=pair.rail,
                    rail_inclination=pair.inclination,
                    speed=speed,
                    distance=distance,
                    lead_in=LEAD_IN,
                    seed=track,
                    yaw_damper=law,
                    integrator=integrator,
                )
                batch = loco.run_batch(
                    inputs.to_numpy(float)[rows],
                    names,
                    vehicle=vehicle,
                    scenario=scenario,
                    threads=threads,
                    progress=progress,
                    executor=executor,
                    store=None if store is None else Path(store),
                    histories=range(len(rows)) if valved else (),
                )
                ok = np.asarray(batch.status) == 0
                if valved:
                    column = f"S_low {damper_name} valve open"
                    for k, history in batch.histories.items():
                        if ok[k]:
                            valves.loc[rows[k], column] = 1.0 - valve_closed_fraction(history)
                failed += int((~ok).sum())
                values = np.asarray(batch.metric(metric), dtype=float)
                per_track[:, track] = np.where(ok, values, np.nan)
            column = f"{scenario_name} {damper_name}"
            if column not in metrics:
                metrics[column] = np.nan
            metrics.loc[rows, column] = per_track.mean(axis=1)
    settings = {
        "loco_version": loco.__version__,
        "n": n,
        "seed": seed,
        "n_tracks": n_tracks,
        "speed_kmh": speed * 3.6,
        "distance_m": distance,
        "lead_in_m": LEAD_IN,
        "premise_rule": PREMISE_RULE,
        "s_low_pairs": [p.label for p in S_LOW_PAIRS],
        "s_high_pair": S_HIGH_PAIR.label,
        "integrator": integrator,
    }
    return Plausible(inputs, pairs, metrics, failed, settings, valves)


def rule_halves(s_low_ratio: Any, s_high_ratio: Any) -> tuple[Any, Any]:
    """The two halves of :data:`PREMISE_RULE` from its ratios (S_low A_yc PSD peak YD2/YD1,
    S_high A_yb peak YD1/YD2; numbers or arrays): each at least :data:`FACTOR` (a NaN ratio,
    from a failed run, is False)."""
    return s_low_ratio >= FACTOR, s_high_ratio >= FACTOR


def _halves(metrics: pd.DataFrame) -> tuple[pd.Series, pd.Series]:
    return rule_halves(
        metrics["S_low YD2"] / metrics["S_low YD1"], metrics["S_high YD1"] / metrics["S_high YD2"]
    )


def premise_holds(metrics: pd.DataFrame) -> pd.Series:
    """Per locomotive, whether :data:`PREMISE_RULE` holds (False where a run it needs failed)."""
    carbody, bogie = _halves(metrics)
    return (carbody & bogie).astype(bool)


def _wilson(k: int, n: int) -> tuple[float, float]:
    from scipy.stats import binomtest

    if n == 0:
        return (math.nan, math.nan)
    ci = binomtest(k, n).proportion_ci(confidence_level=0.95, method="wilson")
    return (float(ci.low), float(ci.high))


def summarise(result: Plausible) -> dict[str, pd.DataFrame]:
    """``fraction``: the share of locomotives with the premise (and with each half of it), with
    95 % Wilson intervals, per S_low pair and pooled; ``fsd``: inside the premise set, the
    FSD's and FSD-H's judging metric over the better fixed damper's (YD1 on S_low, YD2 on
    S_high, per locomotive: median and the share at or below 1) and, on S_low, the median share
    of the record (track 0) the FSD's valves were open (``valve_open_median``)."""
    m = result.metrics
    holds = premise_holds(m)
    carbody, bogie = _halves(m)
    pairs = pd.Series(result.pairs)
    rows = []
    for label in [*dict.fromkeys(result.pairs), "all pairs"]:
        mask = pairs == label if label != "all pairs" else pd.Series(True, index=pairs.index)
        n = int(mask.sum())
        for what, flag in (("premise", holds), ("S_low half", carbody), ("S_high half", bogie)):
            k = int(flag[mask].sum())
            low, high = _wilson(k, n)
            rows.append((label, what, k, n, k / n if n else math.nan, low, high))
    fraction = pd.DataFrame(rows, columns=["pair", "rule", "k", "n", "fraction", "low", "high"])
    fsd_rows = []
    inside = m[holds]
    for name in ("FSD", "FSD-H"):
        for scenario, better in (("S_low", "YD1"), ("S_high", "YD2")):
            ratio = inside[f"{scenario} {name}"] / inside[f"{scenario} {better}"]
            ratio = ratio.dropna()
            k = int((ratio <= 1.0).sum())
            low, high = _wilson(k, len(ratio))
            valve = f"{scenario} {name} valve open"
            opened = result.valves[holds][valve].dropna() if valve in result.valves else None
            fsd_rows.append(
                (
                    name,
                    scenario,
                    better,
                    len(ratio),
                    ratio.median() if len(ratio) else math.nan,
                    k / len(ratio) if len(ratio) else math.nan,
                    low,
                    high,
                    opened.median() if opened is not None and len(opened) else math.nan,
                )
            )
    fsd = pd.DataFrame(
        fsd_rows,
        columns=[
            "damper",
            "scenario",
            "better_fixed",
            "n",
            "median_ratio",
            "share_at_or_below",
            "low",
            "high",
            "valve_open_median",
        ],
    )
    return {"fraction": fraction, "fsd": fsd}


def to_frame(result: Plausible) -> pd.DataFrame:
    """One row per locomotive: its inputs, ``s_low_pair``, the metric of every case and
    ``premise`` (what ``scripts/docs/premise_probability.py`` writes as ``plausible.csv``)."""
    frame = pd.concat(
        [result.inputs, pd.Series(result.pairs, name="s_low_pair"), result.metrics], axis=1
    )
    frame["premise"] = premise_holds(result.metrics)
    return pd.concat([frame, result.valves], axis=1)


def from_frame(frame: pd.DataFrame, settings: dict[str, Any] | None = None) -> Plausible:
    """The :class:`Plausible` of a :func:`to_frame` table (the failed-run count is not kept
    there: -1)."""
    cases = [f"{s} {d}" for s in JUDGE for d in DAMPERS]
    valves = [c for c in VALVE_COLUMNS if c in frame]
    inputs = frame.drop(columns=[*cases, *valves, "s_low_pair", "premise"])
    return Plausible(
        inputs,
        list(frame["s_low_pair"]),
        frame[cases],
        -1,
        dict(settings or {}),
        frame[valves].reset_index(drop=True),
    )
