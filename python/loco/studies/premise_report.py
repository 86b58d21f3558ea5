"""The report's opening section, "Does the premise hold?": the default vehicle's answer and why,
and the damper comparison of the premise case (:mod:`loco.studies.premise_case`).

It reads what the stages wrote: the damper comparison's per-track table (``fsd_tracks.csv``) of
the study's pairs and of the premise case, and the premise case's candidates table (the
linearised carbody mode on each low-conicity pair). The premise's time-domain rule is the one of
:data:`loco.studies.premise_probability.PREMISE_RULE`.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pandas as pd

from loco.studies.plausible import probability_note
from loco.studies.premise_map import premise_cells_note
from loco.studies.premise_probability import FACTOR, PREMISE_RULE, rule_halves
from loco.studies.screening import top_inputs
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


def _plausible_lines(plausible_dir: Path) -> list[str]:
    """The share of plausible locomotives with the premise, what the FSDs do inside that set,
    and which inputs the classifier finds deciding, from the ``plausible`` stage's tables."""
    fraction = pd.read_csv(plausible_dir / "plausible_fraction.csv")
    fsd = pd.read_csv(plausible_dir / "plausible_fsd.csv")
    meta = json.loads((plausible_dir / "plausible.json").read_text(encoding="utf-8"))
    rows = fraction[fraction["rule"] == "premise"]
    per_pair = "; ".join(
        f"{r['pair']} {r['fraction']:.0%} [{r['low']:.0%}, {r['high']:.0%}]"
        for _, r in rows[rows["pair"] != "all pairs"].iterrows()
    )
    lines = [
        f"- **Over plausible locomotives:** {probability_note(fraction)} Each is the "
        "vehicle with every ranged input drawn from its range (a Latin hypercube) and one of the "
        f"low-conicity S_low pairs, on {meta['n_tracks']} tracks. Per pair: {per_pair}."
    ]
    parts = []
    for damper, g in fsd.groupby("damper", sort=False):
        words = []
        for _, r in g.iterrows():
            metric = "A_yc PSD peak" if r["scenario"] == "S_low" else "A_yb peak"
            words.append(
                f"{r['scenario']} {metric} a median {r['median_ratio']:.2f}× "
                f"{r['better_fixed']}'s (at or below it on {r['share_at_or_below']:.0%})"
            )
            if pd.notna(r.get("valve_open_median")):
                words.append(
                    f"valves open a median {r['valve_open_median']:.0%} of the S_low record"
                )
        parts.append(f"{damper}: " + ", ".join(words))
    if parts and int(fsd["n"].max()) > 0:
        lines.append(
            f"  - Inside that set ({int(fsd['n'].max())} locomotives), against the better fixed "
            "damper of each scenario: " + "; ".join(parts) + "."
        )
    accuracy, majority = meta.get("classifier_accuracy"), meta.get("majority_share")
    importance_file = plausible_dir / "plausible_importance.csv"
    importance = pd.read_csv(importance_file) if importance_file.is_file() else pd.DataFrame()
    if accuracy is None or not isinstance(accuracy, float) or math.isnan(accuracy):
        lines.append("  - Too few locomotives of one kind to tell which inputs decide it.")
    elif accuracy <= majority or importance.empty:
        lines.append(
            f"  - A random-forest classifier of the premise scores {accuracy:.2f} on held-out "
            f"locomotives, no better than always answering the majority ({majority:.2f}): no "
            "input decides it alone."
        )
    else:
        top = ", ".join(
            f"`{r['input']}` ({r['importance']:.3f})" for _, r in importance.head(3).iterrows()
        )
        lines.append(
            f"  - What decides it: a random-forest classifier of the premise scores "
            f"{accuracy:.2f} on held-out locomotives (the majority share is {majority:.2f}); its "
            f"largest permutation importances: {top}."
        )
    return lines


def _screening_lines(screening_dir: Path) -> list[str]:
    """The inputs each screened output hangs on most, from the ``screening`` stage's table."""
    result = pd.read_csv(screening_dir / "morris.csv")
    parts = []
    for output in ("S_low_carbody_zeta_YD2", "S_high_bogie_zeta_YD1"):
        if output in set(result["output"]):
            names = ", ".join(f"`{k}`" for k, _ in top_inputs(result, output))
            parts.append(f"{output} on {names}")
    if not parts:
        return []
    return [
        "  - Which estimates the modes hang on (Morris screening, largest μ*): "
        + "; ".join(parts)
        + "."
    ]


def premise_section(
    study_tracks: Path | None,
    case_dir: Path | None,
    *,
    map_dir: Path | None = None,
    screening_dir: Path | None = None,
    plausible_dir: Path | None = None,
    vehicle: str = "the default vehicle",
) -> list[str]:
    """The section's Markdown lines from the study's ``fsd_tracks.csv``, the premise case's
    stage directory and the premise map's, the screening's and the plausible locomotives'
    (any may be missing: the section says what it cannot tell); ``vehicle`` names the vehicle
    they ran on."""
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
            f"- **On {vehicle}: {answer}.** S_low A_yc PSD peak YD2/YD1 = "
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
            f"{vehicle}'s linearised carbody mode is stable with YD1 (ζ = "
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
        lines.append(f"- **No premise case:** no low-conicity pair has the premise on {vehicle}.")
    if map_dir is not None and (map_dir / "premise_cells.csv").is_file():
        note = premise_cells_note(pd.read_csv(map_dir / "premise_cells.csv"))
        lines.append(f"- **The premise map** (linearised, 200 km/h): {note}")
    if plausible_dir is not None and (plausible_dir / "plausible_fraction.csv").is_file():
        lines += _plausible_lines(plausible_dir)
        if screening_dir is not None and (screening_dir / "morris.csv").is_file():
            lines += _screening_lines(screening_dir)
        lines.append(
            f"- The same study at full size (`loco reproduce --full`: 200 locomotives, the "
            f"screening on the critical speeds too) is in `{PREMISE_PAGE}`."
        )
    else:
        lines.append(
            f"- The probability over plausible locomotives and the inputs that decide it are in "
            f"`{PREMISE_PAGE}` (not part of this run)."
        )
    lines.append("")
    return lines
