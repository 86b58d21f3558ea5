"""``docs/study_results.md``, generated from the files of one ``loco reproduce --quick`` run.

The run's files the page reads (every stage's ``stage.json``, the tables the verdict and the
premise section are computed from, and the figures shown) are copied into ``docs/study/``; the
page is written from those copies with the report's own code (:mod:`loco.studies.verdict`,
:mod:`loco.studies.premise_report`), so nothing on it is typed from a run:

    loco reproduce --quick --out results/quick
    python scripts/docs/study_docs.py --from results/quick --write  # copy the files, write the page
    python scripts/docs/study_docs.py --write    # rewrite the page from docs/study
    python scripts/docs/study_docs.py --check    # exit 1 when the page is stale
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "study_results.md"
RESULTS = ROOT / "docs" / "study"

#: Tables copied from each stage's directory (besides its ``stage.json``): what the verdict and
#: the premise section read.
TABLES: dict[str, tuple[str, ...]] = {
    "fsd_comparison": ("fsd_tracks.csv", "fsd_valve_open_fraction.csv"),
    "premise_case": (
        "fsd_tracks.csv",
        "fsd_valve_open_fraction.csv",
        "premise_case_candidates.csv",
    ),
    "premise_map": ("premise_cells.csv",),
    "screening": ("morris.csv",),
    "plausible": (
        "plausible_fraction.csv",
        "plausible_fsd.csv",
        "plausible.json",
        "plausible_importance.csv",
    ),
}
#: Figures shown on the page, by stage (the others stay in the run's report).
FIGURES: dict[str, tuple[str, ...]] = {
    "speed_sweep": ("speed_sweep.png",),
    "fsd_comparison": ("fsd_peaks.png", "fsd_psd.png"),
    "premise_case": ("fsd_peaks.png",),
    "plausible": ("plausible.png",),
    "sensitivity": ("sobol_A_yb.png",),
    "optimisation": ("pareto.png",),
    "fsd_design": ("fsd_design.png",),
}

INTRO = """\
# Current results

What the model says today on the [reference study](STUDY.md). This page is generated from the
files of one `loco reproduce --quick` run, copied into `docs/study/`
(`python scripts/docs/study_docs.py --from DIR --write`; a test fails when the page is not what
those files give). Its verdict and its premise section are computed by the report's own code
from the damper comparisons' per-track tables; every other paragraph is the summary the stage
wrote.
The conclusions are pinned by tests that can fail (`tests/conclusions/`). The run's own report
(`<out>/report.md` and `report.html`) has every table and figure.
"""

METHODS = """\
## How the numbers are summarised

One 500 m record of one synthesised track gives noisy PSD peaks (the same case changes by a factor
2–5 from one track to the next), so the speed sweep and the damper comparison run every case on
several tracks (4 in `--quick`, 8 in `--full`): track `j` is ChaCha stream `j` of the track seed,
the same tracks for every damper, speed and scenario (`loco.studies.seeds`). Positive quantities
(PSD peaks, rms, W_y, A_yb) are given as the geometric mean with the 95 % Student t interval of
their logarithms taken back (never below zero), dominant frequencies as the median with each
track's value ([how the numbers are summarised](guide/reproduce.md#how-the-numbers-are-summarised)).
Because the dampers share their tracks (common random numbers), they are compared by a paired
test: Student's t on the per-track log ratios, with the exact Wilcoxon signed-rank p beside it;
the pairs of a scenario are Holm-adjusted, and a ranking is *significant* when every step of it
is (`loco.studies.statistics`). Only the damper comparisons run a lead-in (500 m, for the FSD's
valve).

Further studies run by scripts (the stability map over conicity, the nonlinear critical speeds,
the FSD design study at full size, a direct Sobol' design of N = 1024) are described in the
[lab notes](development/lab_notes.md#studies-run-by-scripts).
"""


def _stage_names() -> list[str]:
    """The stages in the order `loco reproduce --quick` runs them."""
    from loco.studies.reproduce import stages
    from loco.studies.sizes import QUICK

    return [s.name for s in stages(QUICK, ".", choose_premise_pair=False)]


def copy_run(run: Path, results: Path = RESULTS) -> None:
    """Copies what the page reads from the ``loco reproduce`` output directory ``run``."""
    if not (run / "reproduce.json").is_file():
        raise SystemExit(f"{run}: no reproduce.json; give the output directory of loco reproduce")
    if results.exists():
        shutil.rmtree(results)
    results.mkdir(parents=True)
    shutil.copy2(run / "reproduce.json", results / "reproduce.json")
    for name in _stage_names():
        source = run / name
        if not (source / "stage.json").is_file():
            raise SystemExit(f"{run}: stage {name} has not finished (no stage.json)")
        target = results / name
        target.mkdir()
        shutil.copy2(source / "stage.json", target / "stage.json")
        for file in (*TABLES.get(name, ()), *FIGURES.get(name, ())):
            if (source / file).is_file():
                shutil.copy2(source / file, target / file)


def _record(name: str, results: Path) -> dict:
    data = json.loads((results / name / "stage.json").read_text(encoding="utf-8"))
    return dict(data["record"])


def _run_line(results: Path) -> str:
    run = json.loads((results / "reproduce.json").read_text(encoding="utf-8"))
    command = str(run.get("command", "loco reproduce --quick")).split(" --out ")[0]
    seed = run.get("seed (track, designs, K-means, NSGA-II)", 0)
    return (
        f"The run: `{command}` (seed {seed}), loco {run.get('loco_version', '?')}, "
        f"{run.get('integrator', '')}, on {run.get('executor', '')}."
    )


def render(results: Path = RESULTS) -> str:
    """The page from the copied run files in ``results``."""
    from loco.studies.premise_report import premise_section
    from loco.studies.verdict import verdict_from_csv

    def directory(stage: str) -> Path | None:
        return results / stage if (results / stage).is_dir() else None

    lines = [INTRO, _run_line(results), ""]
    lines += premise_section(
        results / "fsd_comparison" / "fsd_tracks.csv",
        directory("premise_case"),
        map_dir=directory("premise_map"),
        screening_dir=directory("screening"),
        plausible_dir=directory("plausible"),
    )
    lines += verdict_from_csv(results / "fsd_comparison" / "fsd_tracks.csv").markdown()
    lines += ["## The study's stages", ""]
    for name in _stage_names():
        record = _record(name, results)
        lines += [f"### {record['title']}", "", str(record["notes"]).strip(), ""]
        captions = record.get("captions", {})
        for figure in FIGURES.get(name, ()):
            caption = captions.get(figure, figure)
            lines += [f"![{figure}](study/{name}/{figure})", "", f"*{caption}*", ""]
    lines.append(METHODS)
    text = "\n".join(lines)
    # The report cites the study text by its path in the repository; this page sits beside it.
    text = text.replace("`docs/premise.md`", "[the premise page](premise.md)")
    text = text.replace("docs/STUDY.md of loco", "[the reference study](STUDY.md)")
    text = text.replace("docs/assessment.md", "[assessment](assessment.md)")
    return text.rstrip("\n") + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--from", dest="run", type=Path, help="a loco reproduce --quick output")
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--write", action="store_true")
    group.add_argument("--check", action="store_true")
    args = parser.parse_args()
    if args.run is not None:
        if args.check:
            parser.error("--from copies a run's files: use it with --write")
        copy_run(args.run)
    text = render()
    current = PAGE.read_text(encoding="utf-8") if PAGE.exists() else ""
    if args.write:
        PAGE.write_text(text, encoding="utf-8")
    elif text != current:
        print(f"{PAGE} is out of date: run python scripts/docs/study_docs.py --write")
        sys.exit(1)


if __name__ == "__main__":
    main()
