"""The Study page (``docs/study_results.md``) is generated from one ``loco reproduce --quick``
run's files copied into ``docs/study/``: it must be what those files give, and the generator
must read what ``loco reproduce`` writes now."""

from __future__ import annotations

import json
from pathlib import Path

from script_modules import load_script


def test_the_study_page_is_what_the_committed_run_files_give() -> None:
    docs = load_script("study_docs")
    assert docs.PAGE.read_text(encoding="utf-8") == docs.render(), (
        "docs/study_results.md is out of date: run python scripts/docs/study_docs.py --write"
    )


def test_the_committed_files_are_one_quick_run_of_every_stage() -> None:
    docs = load_script("study_docs")
    run = json.loads((docs.RESULTS / "reproduce.json").read_text(encoding="utf-8"))
    assert run["sizes"]["name"] == "quick"
    for name in docs._stage_names():
        assert (docs.RESULTS / name / "stage.json").is_file(), name
    for stage, figures in docs.FIGURES.items():
        for figure in figures:
            assert (docs.RESULTS / stage / figure).is_file(), (stage, figure)


def test_the_generator_reads_a_fresh_run(tiny_study: tuple[Path, str], tmp_path: Path) -> None:
    """The tiny study through the generator: every stage copied, the verdict and the premise
    section computed from its tables, and each stage's own summary on the page."""
    out, _log = tiny_study
    docs = load_script("study_docs")
    results = tmp_path / "study"
    docs.copy_run(out, results)
    page = docs.render(results)
    assert "## Does the premise hold?" in page
    assert "## Verdict: which yaw damper holds which scenario" in page
    record = json.loads((out / "speed_sweep" / "stage.json").read_text(encoding="utf-8"))
    assert record["record"]["notes"].strip() in page
    assert (results / "fsd_comparison" / "fsd_tracks.csv").is_file()
