"""The report's opening section, "Does the premise hold?": the default vehicle's answer and why,
and the damper comparison of the premise case (:mod:`loco.studies.premise_case`).

It reads what the stages wrote: the damper comparison's per-track table (``fsd_tracks.csv``) of
the study's pairs and of the premise case, and the premise case's candidates table (the
linearised carbody mode on each low-conicity pair). The premise's time-domain rule is the one of
:data:`loco.studies.premise_probability.PREMISE_RULE`.
"""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from loco.studies.premise_probability import FACTOR, PREMISE_RULE, rule_halves
from loco.studies.verdict import verdict

__all__ = ["premise_section", "psd_ratios"]

#: Where the probability over plausible locomotives and the screening are documented.
PREMISE_PAGE = "docs/premise.md"


def psd_ratios(tracks: pd.DataFrame) -> dict[str, float]:
    """The premise rule's two ratios from a per-track table: S_low A_yc PSD peak YD2/YD1 and
    S_high A_yb peak (``ayb_peak_lp``) YD1/YD2, track means of the finished runs."""

    def mean(scenario: str, damper: str, column: str) -> float:
        rows = tracks[
            (tracks["scenario"] == scenario)
            & (tracks["damper"] == damper)
            & (tracks["status"] == 0)
        ]
        return float(rows[column].mean())

    return {
        "S_low": mean("S_low", "YD2", "psd_peak") / mean("S_low", "YD1", "psd_peak"),
        "S_high": mean("S_high", "YD1", "ayb_peak_lp") / mean("S_high", "YD2", "ayb_peak_lp"),
    }


def _valves(path: Path) -> list[str]:
    """A line on the FSDs' valve states on S_low (track 0), when the table is there."""
    if not path.is_file():
        return []
    valves = pd.read_csv(path)
    # One row per valve (the table's per-bogie rows name the bogie as the valve).
    low = valves[(valves["scenario"] == "S_low") & (valves["valve"] != valves["bogie"])]
    parts = [
        f"{damper} {g['open_fraction'].mean():.0%} (per valve "
        + ", ".join(f"{v:.0%}" for v in g["open_fraction"])
        + ")"
        for damper, g in low.groupby("damper", sort=False)
    ]
    if not parts:
        return []
    return [
        "  - The FSDs' valves on S_low were open (low damping) for "
        + "; ".join(parts)
        + " of the record on track 0: where they stay closed the FSD is YD2."
    ]


def _holds(ratios: dict[str, float]) -> bool:
    return all(rule_halves(ratios["S_low"], ratios["S_high"]))


def premise_section(study_tracks: Path | None, case_dir: Path | None) -> list[str]:
    """The section's Markdown lines from the study's ``fsd_tracks.csv`` and the premise case's
    stage directory (either may be missing: the section says what it cannot tell)."""
    lines = [
        "## Does the premise hold?",
        "",
        "The study's premise: with high yaw damping the carbody sways on low conicity, with low "
        "yaw damping the bogies hunt on high conicity, and the FSD gives the best of both. "
        f"The rule, fixed before the runs: {PREMISE_RULE}.",
        "",
    ]
    candidates = None
    if case_dir is not None and (case_dir / "premise_case_candidates.csv").is_file():
        candidates = pd.read_csv(case_dir / "premise_case_candidates.csv")
    if study_tracks is not None and study_tracks.is_file():
        ratios = psd_ratios(pd.read_csv(study_tracks))
        answer = "yes" if _holds(ratios) else "no"
        why = ""
        if candidates is not None and len(candidates):
            first = candidates.iloc[0]
            stable = first["carbody_zeta_high"] > 0
            why = (
                f" On its S_low pair ({first['pair']}) the linearised carbody mode at the study "
                f"speed has ζ = {first['carbody_zeta_low']:.3f} with YD1 and "
                f"{first['carbody_zeta_high']:.3f} with YD2: high damping takes damping from it "
                + ("but leaves it stable." if stable else "and makes it unstable.")
            )
        lines.append(
            f"- **On the default vehicle: {answer}.** S_low A_yc PSD peak YD2/YD1 = "
            f"{ratios['S_low']:.2f}, S_high A_yb YD1/YD2 = {ratios['S_high']:.2f} "
            f"(the rule asks for at least {FACTOR:g} in both).{why}"
        )
    case_tracks = None if case_dir is None else case_dir / "fsd_tracks.csv"
    if case_tracks is not None and case_tracks.is_file() and candidates is not None:
        chosen = candidates[candidates["premise"]].sort_values("margin", ascending=False).iloc[0]
        tracks = pd.read_csv(case_tracks)
        ratios = psd_ratios(tracks)
        by_psd = verdict(tracks, judged_by={"S_low": "psd_peak"})
        lines += [
            f"- **The premise case: S_low on {chosen['pair']}**, the low-conicity pair on which "
            f"the default vehicle's linearised carbody mode is stable with YD1 (ζ = "
            f"{chosen['carbody_zeta_low']:.3f}) and unstable with YD2 "
            f"({chosen['carbody_zeta_high']:.3f}), chosen by that rule before its runs. In the "
            f"time domain: S_low A_yc PSD peak YD2/YD1 = {ratios['S_low']:.2f} (premise "
            f"{'holds' if _holds(ratios) else 'does not hold'} by the rule). Its damper "
            "comparison:",
            *("  " + line for s in by_psd.scenarios for line in s.lines()),
            *("  " + line for s in verdict(tracks).scenarios[:1] for line in s.lines()),
            *_valves(case_tracks.parent / "fsd_valve_open_fraction.csv"),
        ]
    elif candidates is not None:
        lines.append("- **No premise case:** no low-conicity pair has the premise on the "
                     "default vehicle.")  # fmt: skip
    lines += [
        f"- The probability over plausible locomotives and the inputs that decide it are in "
        f"`{PREMISE_PAGE}` (from the scripts it names; not part of this run).",
        "",
    ]
    return lines
