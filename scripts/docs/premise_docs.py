"""``docs/premise.md``, generated from the committed results in ``docs/screening`` (written by
``scripts/docs/premise_map.py`` and ``scripts/docs/morris_screening.py``): where the study's
premise holds on the linearised vehicle, and which uncertain inputs move the modes it is about.

    python scripts/docs/premise_docs.py --write   # rewrite the page
    python scripts/docs/premise_docs.py --check   # exit 1 when the page is out of date (CI test)

The results themselves take minutes; the tests recompute a few of their cells
(``tests/studies/test_premise_map.py``, ``tests/studies/test_uncertainty.py``).
"""

from __future__ import annotations

import json
from pathlib import Path

import pandas as pd

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "premise.md"
RESULTS = ROOT / "docs" / "screening"
#: Inputs per output in the screening table.
TOP = 5


def _conicities(values: pd.Series) -> str:
    """Conicities as a short list (``0.04, 0.05 and 0.06``; ``none`` when empty)."""
    items = [f"{v:g}" for v in sorted(values)]
    if not items:
        return "none"
    if len(items) > 4:
        return f"{items[0]}–{items[-1]} ({len(items)} values)"
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _zeta(v: float) -> str:
    return "no mode" if pd.isna(v) else f"{v:+.3f}"


def premise_section() -> list[str]:
    cells = pd.read_csv(RESULTS / "premise_cells.csv")
    grid = pd.read_csv(RESULTS / "premise_map.csv")
    lines = [
        "## Where the premise holds",
        "",
        "![The premise map](screening/premise_map.png)",
        "",
        "The damping ratio ζ of the carbody-coupled mode (top row) and of the bogie mode",
        "(middle row) at 200 km/h, over conicity and yaw damping (Maxwell dampers in series with",
        "22.5 kN/mm; the dotted and dashed lines are YD1's 200 and YD2's 800 kN·s/m) for a cone",
        "on a knife-edge rail and for a straight-cone JM3 tread on CN60 1:40 (the same conicity",
        "on a real rail head), and over yaw damping for the real wheel/rail pairs. Red is",
        "unstable, the black line is ζ = 0, grey is where no mode passes the mode's rule. The",
        "bottom row is the two modes over speed with YD1 and YD2.",
        "",
        'Read at the presets ("premise": the carbody mode stable with YD1 and unstable with',
        'YD2; "reverse": the bogie mode unstable with YD1 and stable with YD2):',
        "",
    ]
    for family in ("knife-edge cone", "cone on CN60"):
        part = cells[cells["family"] == family]
        both = part[(part["carbody_zeta_low"] < 0) & (part["carbody_zeta_high"] < 0)]
        held = _conicities(part.loc[part["premise"], "conicity"])
        lines.append(
            f"- {family}: the premise holds at conicity {held}; the carbody mode is unstable"
            f" with both dampers at {_conicities(both['conicity'])}."
        )
    carbody = grid[(grid["family"] != "pair") & (grid["mode"] == "carbody")]
    lo, hi = carbody["damping"].min() / 1e3, carbody["damping"].max() / 1e3
    for family, g in carbody.groupby("family", sort=False):
        by_conicity = g.groupby("conicity")["damping_ratio"]
        never = by_conicity.apply(lambda z: bool((z < 0).all()))
        always = by_conicity.apply(lambda z: bool(z.notna().any() and (z.dropna() > 0).all()))
        lines.append(
            f"- {family}, every yaw damping of {lo:g}–{hi:g} kN·s/m: the carbody mode is unstable"
            f" at conicity {_conicities(never[never].index.to_series())} and stable (where the"
            f" rule finds it) at {_conicities(always[always].index.to_series())}."
        )
    lines += [
        "",
        "| pair | λ | carbody ζ, YD1 | carbody ζ, YD2 | bogie ζ, YD1 | bogie ζ, YD2 | |",
        "|---|---|---|---|---|---|---|",
    ]
    for _, r in cells[cells["family"] == "pair"].iterrows():
        verdict = "premise" if r["premise"] else ("reverse" if r["reverse"] else "")
        lines.append(
            f"| {r['pair']} | {r['conicity']:.3f} | {_zeta(r['carbody_zeta_low'])} | "
            f"{_zeta(r['carbody_zeta_high'])} | {_zeta(r['bogie_zeta_low'])} | "
            f"{_zeta(r['bogie_zeta_high'])} | {verdict} |"
        )
    lines += [
        "",
        "λ is the pair's linear conicity ([contact pairs](contact_pairs.md)). The default",
        "vehicle's S_low pair (the thin-flange JM3 on CN60 1:40) is not in the premise's band:",
        "YD2 takes most of the carbody mode's damping but leaves it stable. The same conicity",
        "on a knife-edge cone is inside it: what decides is the contact geometry beyond the",
        "conicity (the rail head's curvature: contact angle, roll and gravitational stiffness).",
        "",
    ]
    return lines


def morris_section() -> list[str]:
    path = RESULTS / "morris.csv"
    if not path.exists():
        return []
    table = pd.read_csv(path)
    meta = json.loads((RESULTS / "morris.json").read_text(encoding="utf-8"))
    cpu = (
        f" ({meta['worker_cpu_time_s']:.0f} s of their CPU time)"
        if "worker_cpu_time_s" in meta
        else " (on a machine shared with other work: the wall time is an upper bound)"
    )
    lines = [
        "## Which estimates matter",
        "",
        f"Morris screening (`loco.uncertainty.morris`): {meta['trajectories']} trajectories on",
        f"a {meta['levels']}-level grid (seed {meta['seed']}) over the {meta['inputs']} ranged",
        f"inputs that can change the outputs, {meta['samples']} evaluations of the linearised",
        f"vehicle; {meta['wall_time_s']:.0f} s on {meta['workers']} worker processes{cpu}.",
        "μ* is the mean absolute change",
        "of the output for a step across an input's whole range, σ the spread of those changes",
        "(interactions, nonlinearity). A step of a trajectory whose output the model cannot give",
        "at one of its points (no mode passes the rule, no JM3 tread at a corner of the wheel's",
        "ranges) gives no effect: the tables say how many steps of each input did (of",
        f"{meta['trajectories']}). A vehicle stable up to the search limit of 110 m/s counts at",
        "that limit.",
        "",
        "![Morris screening](screening/morris.png)",
        "",
    ]
    for output, g in table.groupby("output", sort=False):
        top = g.sort_values("mu_star", ascending=False).head(TOP)
        share = g["effects"].sum() / (meta["trajectories"] * len(g))
        lines += [
            f"**{output}** ({share:.0%} of the steps gave an effect)",
            "",
            "| input | μ* | ± (95 %) | σ | steps |",
            "|---|---|---|---|---|",
            *(
                f"| `{r['input']}` | {r['mu_star']:.3g} | {r['mu_star_conf']:.2g} | "
                f"{r['sigma']:.3g} | {int(r['effects'])} |"
                for _, r in top.iterrows()
            ),
            "",
        ]
    return lines


def _fsd_reading(fsd: pd.DataFrame) -> list[str]:
    """One sentence per FSD on what its ratios say (no ratio: nothing to say)."""
    out = []
    for name, g in fsd.groupby("damper", sort=False):
        by = {r["scenario"]: r for _, r in g.iterrows()}
        if not all(s in by and pd.notna(by[s]["median_ratio"]) for s in ("S_low", "S_high")):
            continue
        low, high = by["S_low"], by["S_high"]
        both = low["median_ratio"] <= 1 and high["median_ratio"] <= 1
        out.append(
            f"- {name}: where the premise holds, its S_low judging metric is a median "
            f"{low['median_ratio']:.2f} times {low['better_fixed']}'s and its S_high one "
            f"{high['median_ratio']:.2f} times {high['better_fixed']}'s: "
            + ("the best of both." if both else "not the best of both.")
            + (
                f" Its valves were open a median {low['valve_open_median']:.0%} of the S_low "
                "record: where they stay closed it is the high damping."
                if pd.notna(low.get("valve_open_median", float("nan")))
                else ""
            )
        )
    return [*out, ""] if out else []


def plausible_section() -> list[str]:
    path = RESULTS / "plausible.json"
    if not path.exists():
        return []
    meta = json.loads(path.read_text(encoding="utf-8"))
    fraction = pd.read_csv(RESULTS / "plausible_fraction.csv")
    fsd = pd.read_csv(RESULTS / "plausible_fsd.csv")
    importance = pd.read_csv(RESULTS / "plausible_importance.csv")
    lines = [
        "## The verdict's probability over plausible locomotives",
        "",
        f"{meta['n']} plausible locomotives (`loco.studies.premise_probability`): the default",
        "vehicle with every ranged vehicle input drawn by a Latin hypercube (seed",
        f"{meta['seed']}), each on one of the S_low pairs {', '.join(meta['s_low_pairs'])} (equal",
        f"shares, a judgement) and on S_high ({meta['s_high_pair']}); YD1, YD2, FSD and FSD-H,",
        f"{meta['distance_m']:g} m at {meta['speed_kmh']:g} km/h after {meta['lead_in_m']:g} m of",
        f"lead-in, on {meta['n_tracks']} tracks: {meta['failed_runs']} failed runs;",
        f"{meta['wall_time_s']:.0f} s wall, {meta['cpu_time_s']:.0f} s of CPU time. The rule,",
        f"stated before the runs: {meta['premise_rule']}.",
        "",
        "| S_low pair | rule | locomotives | share | 95 % interval (Wilson) |",
        "|---|---|---|---|---|",
        *(
            f"| {r['pair']} | {r['rule']} | {int(r['k'])} of {int(r['n'])} | "
            f"{r['fraction']:.0%} | {r['low']:.0%}–{r['high']:.0%} |"
            for _, r in fraction.iterrows()
        ),
        "",
        "Inside the set where the premise holds, each FSD against the better fixed damper of",
        "each scenario (its judging metric over the fixed damper's, per locomotive):",
        "",
        "| damper | scenario | against | locomotives | median ratio | share at or below 1 "
        "| valves open (median share of the S_low record, track 0) |",
        "|---|---|---|---|---|---|---|",
        *(
            f"| {r['damper']} | {r['scenario']} | {r['better_fixed']} | {int(r['n'])} | "
            + ("–" if pd.isna(r["median_ratio"]) else f"{r['median_ratio']:.2f}")
            + " | "
            + (
                "–"
                if pd.isna(r["share_at_or_below"])
                else f"{r['share_at_or_below']:.0%} ({r['low']:.0%}–{r['high']:.0%})"
            )
            + " | "
            + (
                f"{r['valve_open_median']:.0%}"
                if pd.notna(r.get("valve_open_median", float("nan")))
                else "–"
            )
            + " |"
            for _, r in fsd.iterrows()
        ),
        "",
        *_fsd_reading(fsd),
    ]
    if importance.empty:
        lines += ["No classifier: the premise holds on all or none of them.", ""]
        return lines
    lines += [
        'Which inputs decide it: a random forest classifies "premise holds" from the inputs',
        "and the pair, trained on 75 % of the locomotives; on the other 25 % it is right for",
        f"{meta['classifier_accuracy']:.0%} of them (always answering the majority class would",
        f"be right for {meta['majority_share']:.0%}). The inputs whose shuffling costs it most",
        "accuracy on the held-out locomotives (permutation importance, mean ± sd of 20):",
        "",
        "| input | importance | ± |",
        "|---|---|---|",
        *(
            f"| `{r['input']}` | {r['importance']:.3f} | {r['std']:.3f} |"
            for _, r in importance.head(8).iterrows()
        ),
        "",
    ]
    return lines


def advantage_section() -> list[str]:
    path = RESULTS / "plausible_advantage.csv"
    if not path.exists():
        return []
    table = pd.read_csv(path)
    if table.empty:
        return []
    lines = [
        "Which inputs decide the FSDs' advantage: per FSD and scenario, a random forest of",
        "log(FSD metric / better fixed damper's) on the inputs and the pair, scored on the 25 %",
        "of the locomotives it was not fitted on (R²; about zero or below: the inputs do not",
        "explain it, and its importances are noise), and its three largest permutation",
        "importances (the drop of R²):",
        "",
        "| damper | scenario | locomotives | held-out R² | largest importances |",
        "|---|---|---|---|---|",
    ]
    for (damper, scenario), g in table.groupby(["damper", "scenario"], sort=False):
        top = ", ".join(f"`{r['input']}` ({r['importance']:.3f})" for _, r in g.head(3).iterrows())
        first = g.iloc[0]
        lines.append(f"| {damper} | {scenario} | {int(first['n'])} | {first['r2']:.2f} | {top} |")
    return [*lines, ""]


def render() -> str:
    lines = [
        "# The premise: where it holds, and which estimates decide it",
        "",
        "<!-- generated by scripts/docs/premise_docs.py from docs/screening: do not edit -->",
        "",
        "The study's premise: with high yaw damping the carbody sways (carbody hunting) on low",
        "conicity, with low yaw damping the bogies hunt on high conicity, and a",
        "frequency-selective damper gives the best of both. This page shows where the",
        "linearised model of the default vehicle has that premise, and which of its uncertain",
        "inputs ([input uncertainty](uncertainty.md)) move the modes the premise is about.",
        "",
        *premise_section(),
        *plausible_section(),
        *advantage_section(),
        *morris_section(),
        "## Run it",
        "",
        "`loco reproduce` runs the map, the screening and the plausible locomotives as stages",
        "(`premise_map`, `screening`, `plausible`) and its report opens with their answer:",
        "`--quick` with 10 trajectories on the damping ratios and 64 locomotives, `--full` at",
        "the sizes of this page. The same study on a vehicle of your own, resumable in its",
        "output directory, on local threads or a Dask cluster (`executor=`):",
        "",
        "```python no-run",
        "from loco.studies.premise_study import premise_study",
        "",
        'report = premise_study("my_locomotive.toml", "results/premise", preset="quick")',
        "print(report.read_text())  # results/premise/premise.md: does the premise hold?",
        "```",
        "",
        "This page's results come from the scripts (each writes into `docs/screening`):",
        "",
        "```",
        "python scripts/docs/premise_map.py       # the map, about a minute",
        "python scripts/docs/morris_screening.py  # the screening, about 5 minutes on 2 cores",
        "python scripts/docs/premise_probability.py  # the plausible locomotives, about 15 minutes",
        "python scripts/docs/premise_docs.py --write",
        "```",
        "",
    ]
    return "\n".join(lines)


def main() -> None:
    from docs_page import run  # scripts/ is on the path when this file runs as a script

    title = (__doc__ or "").splitlines()[0]
    run(PAGE, lambda _page: render(), "scripts/docs/premise_docs.py", title)


if __name__ == "__main__":
    main()
