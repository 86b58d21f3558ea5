"""The study's verdict: which yaw damper holds which scenario, and how sure that is.

Computed from the per-track table of the damper comparison (``fsd_tracks.csv``, written by
:func:`loco.studies.fsd_comparison.save_fsd_comparison`), never typed in, so the first section of
the report (docs/STUDY.md, "How loco answers it") always says what the numbers below it say.

Per scenario (:data:`loco.studies.fsd_comparison.JUDGED_BY`: W_y on S_low, A_yb on S_high):

- the ranking of the dampers by the judging metric, lower is better, with the paired t test on
  the per-track log ratios and Holm's correction (:func:`loco.studies.statistics.rank`, the same
  test as the comparison stage's ``fsd_rankings.csv``);
- which dampers *hold* it, on every track that finished: on S_low an excellent ride
  (W_y below 2.75, the locomotive band of GB/T 5599-2019, ``loco.metrics``) and no sustained
  limit cycle of the carbody (carbody hunting, the premise's failure); on S_high no
  instability flag of the bogie frame (EN 14363 sliding rms over its limit, or the GB/T 8 m/s²
  peaks in 6 cycles; metrics ``ayb_en_unstable``, ``ayb_gbt_unstable``) and no sustained limit
  cycle of the frame (:func:`loco.assessment.hunts`, the rule of the core's
  ``metrics::limit_cycle``).
  A damper whose bogie settles into a limit cycle *hunts*, whether or not the EN 14363 sliding
  rms exceeds its limit: the verdict names its frequency and amplitude and which side of the
  limit it is on (:class:`Hunting`); a carbody limit cycle is named the same way (no standard
  sets a limit on it: its ride is what W_y judges). A table without those columns (written by an
  older loco) leaves the criterion unjudged, and says so.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from loco import _loco, assessment
from loco.channels import Metric
from loco.studies.fsd_comparison import (
    CARBODY_CYCLE_COLUMNS,
    JUDGED_BY,
    LIMIT_CYCLE_COLUMNS,
    STABILITY_FLAGS,
)
from loco.studies.statistics import ALPHA, Ranking, rank

__all__ = [
    "HOLD_CRITERIA",
    "Hunting",
    "ScenarioVerdict",
    "Verdict",
    "hunting",
    "verdict",
    "verdict_from_csv",
]

#: The criterion each scenario is held by, in words.
HOLD_CRITERIA: dict[str, str] = {
    "S_low": "an excellent ride, W_y < 2.75 (GB/T 5599-2019, locomotive), and no sustained "
    "limit cycle of the carbody on any track",
    "S_high": "no bogie instability flag (EN 14363 sliding rms, GB/T peaks) and no sustained "
    "limit cycle of the bogie frame on any track",
}


@dataclass(frozen=True)
class Hunting:
    """The tracks on which one damper's bogie frame (or carbody, ``body``) settled into a limit
    cycle.

    ``frequency`` (Hz) and ``amplitude`` (m/s², a cycle of ± this; the band-passed acceleration's
    mean cycle peak) are the means over those tracks; for the bogie frame ``beyond_en`` says
    whether the EN 14363 sliding rms exceeded its limit on any of them, ``en_rms`` the largest
    sliding rms there and ``en_limit`` the limit (m/s²; NaN for the carbody)."""

    tracks: int
    of: int
    frequency: float
    amplitude: float
    en_rms: float
    en_limit: float
    beyond_en: bool
    body: str = "bogie frame"

    def statement(self) -> str:
        """``hunts (limit cycle 3.9 Hz, ±7.5 m/s² …), within the EN 14363 limit`` and so on;
        for the carbody ``carbody hunts (limit cycle 1.1 Hz, ±0.16 m/s² …)``."""
        what = "hunts" if self.body == "bogie frame" else f"{self.body} hunts"
        size = f"{self.amplitude:.1f}" if self.amplitude >= 1 else f"{self.amplitude:.2f}"
        cycle = (
            f"{what} (limit cycle {self.frequency:.1f} Hz, ±{size} m/s², on "
            f"{self.tracks} of {self.of} tracks)"
        )
        if self.body != "bogie frame":
            return cycle
        side = "beyond" if self.beyond_en else "within"
        return (
            f"{cycle}, {side} the EN 14363 limit (sliding rms up to "
            f"{self.en_rms:.2f} against {self.en_limit:.2f} m/s²)"
        )


def hunting(frame: pd.DataFrame, body: str = "bogie frame") -> Hunting | None:
    """The limit cycles of ``body`` (``"bogie frame"``, ``"carbody"``) in the finished rows of one
    damper's per-track table (``None``: on no track; columns
    :data:`loco.studies.fsd_comparison.LIMIT_CYCLE_COLUMNS` or ``CARBODY_CYCLE_COLUMNS``)."""
    done = frame[frame["status"] == 0]
    cycling = done[[assessment.hunts(row, body) is True for _, row in done.iterrows()]]
    if cycling.empty:
        return None
    _, hz, amplitude = assessment.LIMIT_CYCLES[body]
    bogie = body == "bogie frame"
    return Hunting(
        tracks=len(cycling),
        of=len(done),
        frequency=float(cycling[hz].mean()),
        amplitude=float(cycling[amplitude].mean()),
        en_rms=float(cycling[Metric.AYB_EN_RMS].max()) if bogie else float("nan"),
        en_limit=float(cycling[Metric.AYB_EN_LIMIT].max()) if bogie else float("nan"),
        beyond_en=bool((cycling[Metric.AYB_EN_UNSTABLE] == 1.0).any()) if bogie else False,
        body=body,
    )


@dataclass(frozen=True)
class ScenarioVerdict:
    """One scenario: the ranking by its judging metric and which dampers hold it (``None``: the
    table cannot tell)."""

    scenario: str
    metric: str
    ranking: Ranking
    holds: dict[str, bool | None]
    failed: dict[str, int]
    hunts: dict[str, Hunting | None] = field(default_factory=dict)

    @property
    def best(self) -> str:
        """The damper with the lowest mean (best), whether or not significantly."""
        return self.ranking.order[0]

    def significant_best(self) -> bool:
        """Whether the best damper is significantly better than the second (Holm, ALPHA)."""
        order = self.ranking.order
        return len(order) > 1 and self.ranking.test(order[0], order[1]).significant

    def lines(self) -> list[str]:
        """Markdown bullet of this scenario."""
        held = [d for d, h in self.holds.items() if h]
        not_held = [d for d, h in self.holds.items() if h is False]
        if any(h is None for h in self.holds.values()):
            holding = (
                f"Holding ({HOLD_CRITERIA.get(self.scenario, '')}) is not judged: the table has "
                "no instability flags or limit-cycle columns (rerun the damper comparison stage "
                "with --force)."
            )
        else:
            hunting_text = "".join(
                f" {d} {h.statement()}." for d, h in self.hunts.items() if h is not None
            )
            holding = (
                f"Held ({HOLD_CRITERIA.get(self.scenario, '')}) by "
                f"{', '.join(held) or 'no damper'}"
                + (f"; not by {', '.join(not_held)}" if not_held else "")
                + "."
                + hunting_text
            )
        strength = (
            f"significantly better than {self.ranking.order[1]}"
            if self.significant_best()
            else "not significantly better than the next"
        )
        failed = {d: n for d, n in self.failed.items() if n}
        failures = (
            " Failed runs, left out: " + ", ".join(f"{d} {n}" for d, n in failed.items()) + "."
            if failed
            else ""
        )
        return [
            f"- **{self.scenario}**, judged by `{self.metric}` (lower is better): best "
            f"**{self.best}**, {strength} (paired t on log ratios over the tracks, Holm, "
            f"α = {ALPHA:g}). {holding}{failures}",
            f"  - {self.ranking.statement()}.",
        ]


@dataclass(frozen=True)
class Verdict:
    """The verdict of every judged scenario."""

    scenarios: tuple[ScenarioVerdict, ...]
    #: The EN 14363 stability limit of the runs, m/s² (None: not in the table).
    en_limit: float | None = None

    def judged_by(self) -> list[str]:
        """How the bogie frames are judged: the limit and the bogie mass m⁺ it comes from."""
        if self.en_limit is None or not np.isfinite(self.en_limit):
            return []
        bogie_mass = 5.0 * (12.0 - 2.0 * self.en_limit)
        return [
            "",
            "The bogie frames are judged by EN 14363's simplified method, the sliding rms of the "
            f"frame's lateral acceleration against (12 − m⁺/5)/2 = {self.en_limit:.2f} m/s² with "
            f"the bogie mass m⁺ = {bogie_mass:.1f} t (frame, wheelsets and the drive the bogie "
            "carries; docs/assessment.md), and by the limit-cycle rule: a bogie (or carbody) "
            "that settles into a sustained limit cycle hunts, within or beyond that limit, and "
            "does not hold its scenario.",
        ]

    def holding_all(self) -> list[str]:
        """Dampers that hold every scenario (empty when one is not judged)."""
        if not self.scenarios:
            return []
        dampers = list(self.scenarios[0].holds)
        return [d for d in dampers if all(s.holds.get(d) is True for s in self.scenarios)]

    def markdown(self) -> list[str]:
        """The report's first section."""
        lines = [
            "## Verdict: which yaw damper holds which scenario",
            "",
            "Computed from the damper comparison below (its per-track table `fsd_tracks.csv`): "
            "every damper on the same synthesised tracks, the rankings by paired tests "
            "(docs/STUDY.md of loco says what the study asks).",
            "",
        ]
        for s in self.scenarios:
            lines += s.lines()
        if self.scenarios and all(h is not None for s in self.scenarios for h in s.holds.values()):
            both = self.holding_all()
            lines += [
                "",
                "Every scenario is held by: " + (", ".join(both) if both else "no damper") + ".",
            ]
        return [*lines, *self.judged_by(), ""]


def _holds(scenario: str, frame: pd.DataFrame) -> bool | None:
    """Whether the finished tracks of one (scenario, damper) meet the scenario's criterion."""
    done = frame[frame["status"] == 0]
    if done.empty:
        return False
    if scenario == "S_low":
        if not all(c in done.columns for c in CARBODY_CYCLE_COLUMNS):
            return None
        ratings = [_loco.locomotive_ride_rating(float(w)) for w in done[JUDGED_BY["S_low"]]]
        cycling = [assessment.hunts(row, "carbody") for _, row in done.iterrows()]
        if None in cycling:
            return None
        return all(r == "excellent" for r in ratings) and not any(cycling)
    if scenario == "S_high":
        columns = [*STABILITY_FLAGS, *LIMIT_CYCLE_COLUMNS]
        if not all(f in done.columns for f in columns):
            return None
        flags = done[list(STABILITY_FLAGS)].to_numpy(dtype=np.float64)
        hunting = [assessment.hunts(row) for _, row in done.iterrows()]
        if not np.isfinite(flags).all() or None in hunting:
            return None
        return bool((flags == 0.0).all()) and not any(hunting)
    return None


def _hunts(scenario: str, frame: pd.DataFrame) -> Hunting | None:
    """The limit cycles of one (scenario, damper): of the bogie frame on S_high, of the carbody
    on S_low."""
    body, columns = {
        "S_high": ("bogie frame", LIMIT_CYCLE_COLUMNS),
        "S_low": ("carbody", CARBODY_CYCLE_COLUMNS),
    }.get(scenario, ("", ()))
    if not columns or not all(c in frame.columns for c in columns):
        return None
    return hunting(frame, body)


def verdict(tracks: pd.DataFrame, judged_by: Mapping[str, str] = JUDGED_BY) -> Verdict:
    """The verdict from a per-track table (columns ``scenario``, ``damper``, ``track``,
    ``status``, and the judging metrics; a failed run has a nonzero status and NaN metrics)."""
    out = []
    for scenario, metric in judged_by.items():
        rows = tracks[tracks["scenario"] == scenario]
        if rows.empty:
            continue
        dampers = list(dict.fromkeys(rows["damper"]))
        per = {d: rows[rows["damper"] == d].sort_values("track") for d in dampers}
        values = {
            d: np.where(f["status"] == 0, f[metric], np.nan).astype(np.float64)
            for d, f in per.items()
        }
        out.append(
            ScenarioVerdict(
                scenario=scenario,
                metric=metric,
                ranking=rank(values, label=scenario, metric=metric),
                holds={d: _holds(scenario, f) for d, f in per.items()},
                failed={d: int((f["status"] != 0).sum()) for d, f in per.items()},
                hunts={d: _hunts(scenario, f) for d, f in per.items()},
            )
        )
    limits = (
        tracks.loc[tracks["status"] == 0, Metric.AYB_EN_LIMIT]
        if Metric.AYB_EN_LIMIT in tracks.columns
        else pd.Series(dtype=float)
    )
    return Verdict(tuple(out), float(limits.max()) if len(limits) else None)


def verdict_from_csv(path: str | Path) -> Verdict:
    """The verdict from a ``fsd_tracks.csv``."""
    return verdict(pd.read_csv(path))
