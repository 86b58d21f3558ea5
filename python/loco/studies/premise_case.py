"""The premise case: the study's damper comparison where its premise holds.

On the default vehicle the study's S_low pair does not have the premise (high yaw damping keeps
the carbody mode stable there, :mod:`loco.studies.premise_modes`), so the comparison of YD1, YD2
and the FSD on it cannot show what the FSD is for. The premise case reruns the same comparison
(:class:`loco.studies.fsd_comparison.FsdComparisonStage`: the same dampers, tracks, lead-in,
intervals and paired tests) with S_low replaced by a pair on which the premise holds.

The rule that chooses it, fixed before the FSD runs on it (:func:`choose_pair`): the most
plausible locomotive is the default vehicle itself (every input at its nominal value). Among the
low-conicity pairs of :data:`loco.studies.premise_probability.S_LOW_PAIRS`, take those on which
its linearised carbody mode at the study speed is stable with YD1 and unstable with YD2 (the
premise's S_low half; its S_high half, the bogies hunting with YD1 on worn wheels, holds on the
default vehicle already), and of them the one with the largest margin min(ζ_YD1, −ζ_YD2). When
no pair qualifies there is no premise case, and the report says so.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import pandas as pd

import loco
from loco.contact_pairs import ContactPair
from loco.studies import premise_modes
from loco.studies.fsd_comparison import FsdComparisonStage, run_fsd_comparison, save_fsd_comparison
from loco.studies.premise_probability import S_LOW_PAIRS
from loco.studies.report import StudyRecord, save_table
from loco.studies.stages import Runtime

__all__ = ["PremiseCaseStage", "candidates", "choose_pair"]

#: The presets' yaw dampings, N·s/m (YD1, YD2).
_PRESET_DAMPINGS = (200e3, 800e3)


def candidates(
    vehicle: loco.Locomotive | None = None, speed: float = premise_modes.SPEED
) -> pd.DataFrame:
    """Per pair of :data:`S_LOW_PAIRS`: the carbody mode's damping ratio with YD1 and YD2 on
    ``vehicle`` (default: the default vehicle) at ``speed`` (m/s), whether the premise's S_low
    half holds, and the margin min(ζ_YD1, −ζ_YD2)."""
    labels = {p.label for p in S_LOW_PAIRS}
    result = premise_modes.premise_map(
        vehicle, dampings=_PRESET_DAMPINGS, families=("pair",), speed=speed, progress=False
    )
    cells = premise_modes.premise_cells(result, *_PRESET_DAMPINGS)
    cells = cells[cells["pair"].isin(labels)].reset_index(drop=True)
    cells["margin"] = np.minimum(cells["carbody_zeta_low"], -cells["carbody_zeta_high"])
    return cells[["pair", "conicity", "carbody_zeta_low", "carbody_zeta_high", "premise", "margin"]]


def choose_pair(table: pd.DataFrame) -> ContactPair | None:
    """The pair of a :func:`candidates` table the rule chooses (module documentation), or None."""
    held = table[table["premise"]]
    if held.empty:
        return None
    label = str(held.sort_values("margin", ascending=False)["pair"].iloc[0])
    return next(p for p in S_LOW_PAIRS if p.label == label)


@dataclass(frozen=True)
class PremiseCaseStage(FsdComparisonStage):
    """Stage ``premise_case`` of ``loco reproduce``: the damper comparison with S_low on the
    pair :func:`choose_pair` picks (``s_low_pair``; chosen by :meth:`chosen` when None)."""

    name: ClassVar[str] = "premise_case"

    @classmethod
    def chosen(cls, **fields: object) -> PremiseCaseStage:
        """The stage on the pair the rule chooses for the default vehicle (``fields`` as
        :class:`FsdComparisonStage`'s); ``s_low_pair`` stays None when none qualifies."""
        return cls(s_low_pair=choose_pair(candidates()), **fields)  # type: ignore[arg-type]

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """The candidates' table (``premise_case_candidates.csv``), then the comparison on the
        chosen pair (:func:`loco.studies.fsd_comparison.save_fsd_comparison`)."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        table = candidates(self.vehicle, self.speed_kmh / 3.6)
        path = save_table(table, out / "premise_case_candidates.csv")
        if self.s_low_pair is None:
            return StudyRecord(
                name=self.name,
                title="The premise case",
                tables=[path],
                parameters=self.settings(),
                notes="No low-conicity pair has the premise on the default vehicle.",
            )
        record = save_fsd_comparison(run_fsd_comparison(self, runtime), out)
        return dataclasses.replace(
            record,
            name=self.name,
            title=f"The premise case: the damper comparison with S_low on {self.s_low_pair.label}",
            tables=[path, *record.tables],
        )
