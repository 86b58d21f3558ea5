"""The curving study: guiding forces of YD1, YD2 and the FSD in curves.

Each case is a designed curve (a straight, a clothoid transition with a linear cant run-off, a
circular curve with cant) run at the speeds that give the cant deficiencies asked for; the
circular curve is the EN 14363 section, assessed by :mod:`loco.studies.en14363`: ΣY per wheelset
(99.85 % / 0.15 % percentiles of the 2 m sliding mean, the larger magnitude), Y/Q per wheel (the
same), the quasi-static guiding force Y_qst (50 % percentile), and as descriptions the angle of
attack of the leading wheelset, the share of the section the outer leading wheel runs in flange
contact and the wear number T·γ of the outer leading wheel (medians in the section).

Speed for cant deficiency d on a curve of radius R and cant c (rail-top heights over the
distance 2·b0 between the nominal contact points, `track.contact_point_half_distance`; the core
rolls the rails by atan(c / 2·b0)): the lateral acceleration in the track plane is
g·d/(2·b0), so V = √(g·R·(c + d)/(2·b0)) (small cant angles). A case whose speed is above
:data:`MAX_SPEED_KMH` is left out and listed.

Curves (:data:`CURVES`): R = 600, 1200, 3000, 7000 m with cants a line designer could choose
(EN 13803:2017 allows up to 160–180 mm; these give balanced speeds of 87–133 km/h) and
transitions as long as the cant run-off needs at 1 mm/m (EN 13803's recommended run-off
gradient for conventional lines is of that order), at least 60 m.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import pandas as pd

import loco
from loco import _loco, assessment, dampers
from loco.studies import captions as figure_captions
from loco.studies import en14363
from loco.studies.curving_cases import (
    CANT_DEFICIENCIES_MM,
    CURVES,
    FULL_SIZES,
    LEAD_IN,
    MAX_SPEED_KMH,
    RUN_IN,
    TINY_SIZES,
    CurveCase,
    CurvingSizes,
    speed_for_deficiency,
)
from loco.studies.report import StudyRecord, save_json
from loco.studies.stages import Demand, Runtime, Stage

__all__ = [
    "CANT_DEFICIENCIES_MM",
    "CURVES",
    "FULL_SIZES",
    "LEAD_IN",
    "MAX_SPEED_KMH",
    "RUN_IN",
    "TINY_SIZES",
    "CurveCase",
    "CurvingSizes",
    "CurvingStage",
    "CurvingStudy",
    "run_curving",
    "save_curving",
    "speed_for_deficiency",
    "wheelset_offsets",
]

#: How far each wheelset runs behind the leading one (:func:`loco.assessment.wheelset_offsets`).
wheelset_offsets = assessment.wheelset_offsets

#: The per-wheel and per-wheelset channel names, by quantity, from the core.
WHEEL = _loco.wheel_channels()
WHEELSET = _loco.wheelset_channels()


@dataclass
class CurvingStudy:
    """Result of :func:`run_curving`: ``table`` one row per (curve, deficiency, damper) with the
    EN 14363 values (forces in kN, angle of attack in mrad), ``skipped`` the cases above
    :data:`MAX_SPEED_KMH` or failed (with why), ``settings`` and ``seconds``."""

    table: pd.DataFrame
    skipped: list[str]
    settings: dict[str, Any]
    seconds: float
    axle_load: float


@dataclass
class CurveRuns:
    """The runs of one curve: the ``speeds`` (m/s) of the cant ``deficiencies_mm`` at most the
    stage's speed cap, the recorded ``distance`` (m, until the last wheelset has run the whole
    circular curve) and the deficiencies ``skipped`` above the cap, with why."""

    case: CurveCase
    speeds: list[float] = field(default_factory=list)
    deficiencies_mm: list[float] = field(default_factory=list)
    distance: float = 0.0
    skipped: list[str] = field(default_factory=list)


def _presets() -> dict[str, dampers.Damper]:
    return dict(dampers.PRESETS)


@dataclass(frozen=True)
class CurvingStage(Stage):
    """The study's inputs (stage ``curving`` of ``loco reproduce --full``): every curve at every
    cant deficiency (mm) with every yaw damper of ``damper_set``.

    ``lead_in`` (m) of straight is run and not recorded before the design's run-in (the FSD
    leaves its start state there, :data:`loco.studies.fsd_comparison.LEAD_IN`); ``irregular``
    puts the S_norm irregularities (seed ``seed``) on the design, otherwise the track is perfect;
    a case faster than ``max_speed_kmh`` (km/h) is left out. ``vehicle`` None is the embedded
    locomotive. ``integrator`` is the integration scheme of every run, at its own step. Each
    (curve, damper) is one batch over its speeds.
    """

    name: ClassVar[str] = "curving"
    curves: Sequence[CurveCase] = CURVES
    deficiencies_mm: Sequence[float] = CANT_DEFICIENCIES_MM
    damper_set: Mapping[str, dampers.Damper] = field(default_factory=_presets)
    lead_in: float = LEAD_IN
    irregular: bool = False
    seed: int = 0
    vehicle: loco.Locomotive | None = None
    max_speed_kmh: float = MAX_SPEED_KMH
    integrator: str = loco.Scenario.integrator

    def locomotive(self) -> loco.Locomotive:
        """The vehicle run (the embedded one when ``vehicle`` is None)."""
        return self.vehicle or loco.Locomotive.default()

    def settings(self) -> dict[str, Any]:
        """The study's settings as its JSON file and report show them."""
        return {
            "curves": [dataclasses.asdict(c) for c in self.curves],
            "deficiencies_mm": list(self.deficiencies_mm),
            "dampers": {n: repr(d) for n, d in self.damper_set.items()},
            "lead_in": self.lead_in,
            "irregular": self.irregular,
            "seed": self.seed,
            "max_speed_kmh": self.max_speed_kmh,
            "integrator": self.integrator,
            "vehicle": repr(self.locomotive()),
        }

    def plan(self) -> list[CurveRuns]:
        """The runs of each curve (:class:`CurveRuns`)."""
        vehicle = self.locomotive()
        last = wheelset_offsets(vehicle)[-1]
        plan = []
        for case in self.curves:
            runs = CurveRuns(case, distance=RUN_IN + case.transition_m + case.curve_m + last + 1.0)
            for d in self.deficiencies_mm:
                v = speed_for_deficiency(case.radius_m, case.cant_mm, d, vehicle)
                if v * 3.6 > self.max_speed_kmh:
                    runs.skipped.append(
                        f"R = {case.radius_m:g} m, d = {d:g} mm: {v * 3.6:.0f} km/h is above "
                        f"{self.max_speed_kmh:g} km/h"
                    )
                    continue
                runs.speeds.append(v)
                runs.deficiencies_mm.append(d)
            plan.append(runs)
        return plan

    def demand(self) -> Demand:
        """One run per (curve, deficiency below the speed cap, damper)."""
        n = len(self.damper_set)
        runs = [Demand.runs(n, self.lead_in + c.distance, v) for c in self.plan() for v in c.speeds]
        return sum(runs, Demand())

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """Run the study and save it into ``out_dir`` (:func:`save_curving`)."""
        return save_curving(run_curving(self, runtime), out_dir)


def _assess(
    result: loco.SimulationResult,
    vehicle: loco.Locomotive,
    case: CurveCase,
    straight: float,
    lead_in: float,
    speed: float,
) -> dict[str, float]:
    """The EN 14363 values of one run in the circular curve (:func:`loco.assessment.assess`),
    and the angle of attack, flange contact, wear number and load transfer there."""
    sections = case.sections(straight)
    found = assessment.assess(result, vehicle, curve=sections, lead_in=lead_in, speed=speed)
    curve = next(z for z in assessment.zones(sections, math.inf) if z.curved)
    start, end = curve.start, curve.end
    lead = lead_in + speed * result.time
    inside = (lead >= start) & (lead <= end)
    # The outer wheel of a left curve is the right one.
    outer = 1 if case.direction == "left" else 0
    return {
        "sumY_kN": found.get("sumY", curve.name).value / 1e3,
        "YQ": found.get("YQ", curve.name).value,
        "Yqst_kN": found.get("Yqst", curve.name).value / 1e3,
        "Qqst_kN": found.get("Qqst", curve.name).value / 1e3,
        "yqst_carbody": found.get("yqst", curve.name).value,
        "aoa_lead_mrad": float(np.median(result.channel(WHEELSET["yaw"][0])[inside])) * 1e3,
        "flange_lead_outer": float(np.mean(result.channel(WHEEL["flange"][outer])[inside])),
        "Tgamma_lead_outer_N": float(np.median(result.channel(WHEEL["Tgamma"][outer])[inside])),
        "dQQ_max": float(max(np.max(result.channel(c)[inside]) for c in WHEEL["dQQ"])),
    }


def run_curving(stage: CurvingStage, runtime: Runtime | None = None) -> CurvingStudy:
    """Run the study ``stage`` describes (``runtime``: threads and progress bars, default all
    cores and no bars)."""
    runtime = runtime or Runtime(progress=False)
    started = time.perf_counter()
    vehicle = stage.locomotive()
    lead_in = stage.lead_in
    straight = lead_in + RUN_IN
    rows: list[dict[str, Any]] = []
    skipped: list[str] = []
    for planned in stage.plan():
        skipped += planned.skipped
        case, speeds = planned.case, planned.speeds
        if not speeds:
            continue
        for name, law in stage.damper_set.items():
            # Perfect track, or the S_norm irregularities of `seed`.
            irregular = {"seed": stage.seed}
            track: dict[str, Any] = irregular if stage.irregular else {"track": "perfect"}
            scenario = loco.Scenario(
                name="S_norm",
                speed=speeds[0],
                distance=planned.distance,
                lead_in=lead_in,
                yaw_damper=law,
                curve=case.sections(straight, run_m=lead_in + planned.distance),
                integrator=stage.integrator,
                **track,
            )
            batch = loco.run_batch(
                np.array(speeds)[:, None],
                ["speed"],
                vehicle,
                scenario,
                threads=runtime.threads,
                progress=runtime.progress,
                histories=range(len(speeds)),
            )
            for i, (v, d) in enumerate(zip(speeds, planned.deficiencies_mm, strict=True)):
                label = f"R = {case.radius_m:g} m, d = {d:g} mm, {name}"
                if batch.status[i] != 0 or i not in batch.histories:
                    skipped.append(f"{label}: {batch.messages[i] or int(batch.status[i])}")
                    continue
                rows.append(
                    {
                        "radius_m": case.radius_m,
                        "cant_mm": case.cant_mm,
                        "deficiency_mm": d,
                        "speed_kmh": v * 3.6,
                        "damper": name,
                        **_assess(batch.histories[i], vehicle, case, straight, lead_in, v),
                    }
                )
    axle_load = vehicle_axle_load(vehicle)
    return CurvingStudy(
        table=pd.DataFrame(rows),
        skipped=skipped,
        settings=stage.settings(),
        seconds=time.perf_counter() - started,
        axle_load=axle_load,
    )


def vehicle_axle_load(vehicle: loco.Locomotive) -> float:
    """Mean static axle load 2·Q0 of the vehicle, N (its weight over its four wheelsets)."""
    return float(vehicle.total_mass() * vehicle["track.gravity"] / 4.0)


def save_curving(study: CurvingStudy, out_dir: str | Path) -> StudyRecord:
    """Write ``curving.csv`` (every case), ``curving.png`` (ΣY and Y/Q against cant deficiency
    per damper, with the limits) and ``curving.json`` (settings); return the record."""
    from loco.studies.curving_figures import plot_curving

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    table = out / "curving.csv"
    study.table.to_csv(table, index=False, float_format="%.6g")
    figure = plot_curving(study.table, study.axle_load, out / "curving.png")
    save_json(
        {"loco_version": loco.__version__, "settings": study.settings, "skipped": study.skipped},
        out / "curving.json",
    )
    return StudyRecord(
        name="curving",
        title="Curving: guiding forces against cant deficiency (EN 14363 processing)",
        figures=[figure],
        tables=[table],
        parameters=study.settings,
        seconds=study.seconds,
        notes=curving_notes(study),
        captions=figure_captions.CURVING,
    )


def curving_notes(study: CurvingStudy) -> str:
    """The report paragraph: the limits, the largest values per damper, what was left out."""
    limit = en14363.sum_y_limit(study.axle_load) / 1e3
    parts = [
        f"ΣY is the 99.85 % / 0.15 % percentile of the 2 m sliding mean (every 0.5 m) in the "
        f"circular curve, the largest over the wheelsets; Y/Q the same over the wheels; Y_qst the "
        f"50 % value. Limits: ΣY {limit:.1f} kN (Prud'homme, α = {en14363.ALPHA_LOCOMOTIVE:g}, "
        f"axle load {study.axle_load / 1e3:.1f} kN), Y/Q {en14363.YQ_LIMIT:g} (Nadal, R ≥ 250 m), "
        f"Y_qst {en14363.YQST_LIMIT / 1e3:g} kN (a reference: EN 14363 assesses it for "
        f"250 m ≤ R < 400 m)."
    ]
    if not study.table.empty:
        worst = study.table.groupby("damper")[["sumY_kN", "YQ", "Yqst_kN"]].max()
        for name, row in worst.iterrows():
            parts.append(
                f"{name}: largest ΣY {row['sumY_kN']:.1f} kN, Y/Q {row['YQ']:.3f}, "
                f"Y_qst {row['Yqst_kN']:.1f} kN."
            )
    if study.skipped:
        parts.append("Left out: " + "; ".join(study.skipped) + ".")
    return " ".join(parts)
