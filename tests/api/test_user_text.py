"""What a user reads names no development labels.

The README, the documentation pages outside the Development section, the CLI help, and every
line of the Python package and the crates' sources (docstrings, comments, report strings) are
searched, with the crates' tests, benches and examples, the Python tests (all but this file,
whose own examples are labels), the scripts, the experiments and the examples, for the
development log's labels ("stop 31", "issue 14", "(issue"), for run fingerprints
(16 hexadecimal digits) and, in the CLI help, for "SPEC §" (the help names what a stage does,
not a section number of the study text). A failure lists every place as file:line.
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Iterable, Iterator
from pathlib import Path

import yaml

from loco.cli import build_parser

ROOT = Path(__file__).resolve().parents[2]

#: Development labels and run fingerprints.
#: Between a label's words: a space, or a line break with the next line's comment marker.
_GAP = r"(?:[ \t]+|[ \t]*\n[ \t]*(?://[/!]?|#:?)?[ \t]*)"
#: A number after "stop" that is a length ("rubber stops 10-100 mm") is not a label.
LABELS = re.compile(
    rf"\b[Ss]tops?(?:-|{_GAP})\d+(?![\d.\-–])(?!\s*(?:mm|cm|m|kN|N)\b)"
    rf"|\b[Ii]ssues?{_GAP}\d+\b|\(issue\b"
    r"|\b(?=[0-9a-f]*[a-f])(?=[0-9a-f]*\d)[0-9a-f]{16}\b"
)
#: What the CLI help must not cite either.
HELP_ONLY = re.compile(r"SPEC §")
#: The README's length limit, lines.
README_LINES = 200


def development_pages(root: Path = ROOT) -> set[Path]:
    """The pages of the documentation's Development section (where history may stand)."""
    config = yaml.load((root / "mkdocs.yml").read_text(encoding="utf-8"), Loader=yaml.BaseLoader)

    def pages(entry: object) -> Iterator[str]:
        if isinstance(entry, str):
            yield entry
        elif isinstance(entry, dict):
            for value in entry.values():
                yield from pages(value)
        elif isinstance(entry, list):
            for item in entry:
                yield from pages(item)

    section = next(
        e["Development"] for e in config["nav"] if isinstance(e, dict) and "Development" in e
    )
    return {(root / "docs" / p).resolve() for p in pages(section)}


def user_files(root: Path = ROOT) -> list[Path]:
    """README, documentation outside Development, the package, the crates (sources, tests,
    benches, examples), the Python tests but this file, the scripts and the examples."""
    dev = development_pages(root)
    docs = [p for p in sorted((root / "docs").rglob("*.md")) if p.resolve() not in dev]
    sources = sorted((root / "python").rglob("*.py")) + sorted((root / "python").rglob("*.pyi"))
    crates = sorted((root / "crates").glob("*/**/*.rs"))
    crates += sorted((root / "crates").glob("*/src/**/*.toml"))
    tests = [p for p in sorted((root / "tests").rglob("*.py")) if p.name != Path(__file__).name]
    scripts = [
        *sorted((root / "scripts").rglob("*.py")),
        *sorted((root / "scripts").rglob("*.sh")),
        *sorted((root / "experiments").rglob("*.py")),
    ]
    examples = sorted((root / "examples").glob("*"))
    return [root / "README.md", *docs, *sources, *crates, *tests, *scripts, *examples]


def findings(texts: Iterable[tuple[str, str]], pattern: re.Pattern[str]) -> list[str]:
    """``where:line: text`` for every match of ``pattern`` in the texts (a match may run over a
    line break, as a wrapped comment does), at the line where it starts."""
    found = []
    for where, text in texts:
        lines = text.splitlines()
        for m in pattern.finditer(text):
            n = text.count("\n", 0, m.start()) + 1
            found.append(f"{where}:{n}: {lines[n - 1].strip()}")
    return found


def file_texts(paths: Iterable[Path]) -> Iterator[tuple[str, str]]:
    for path in paths:
        yield str(path.relative_to(ROOT)), path.read_text(encoding="utf-8")


def help_texts() -> Iterator[tuple[str, str]]:
    parser = build_parser()
    texts = {"loco --help": parser.format_help()}
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                texts[f"loco {name} --help"] = sub.format_help()
    yield from texts.items()


def test_no_development_labels_where_a_user_reads() -> None:
    found = findings(file_texts(user_files()), LABELS)
    assert not found, "development labels or fingerprints:\n" + "\n".join(found)


def test_the_cli_help_cites_no_labels_or_spec_sections() -> None:
    found = findings(help_texts(), LABELS) + findings(help_texts(), HELP_ONLY)
    assert not found, "in the CLI help:\n" + "\n".join(found)


def test_the_scan_finds_each_kind_of_label() -> None:
    text = "\n".join(
        [
            "measured at stop 31",
            "Stop 23: the cut step",
            "before the stop-23 fix",
            "# the valve of issue 14",
            "heading (issue",
            "// fingerprint `d05587156c0f1168`",
            "nothing to see: stops the batch, 1234567890123456",
            "rubber stops 10-100 mm thick, dampers and stops 0.9–0.95 m",
            "/// wrapped over two lines: until stop",
            "/// 27 the range was",
        ]
    )
    assert [f.split(": ")[0] for f in findings([("a.rs", text)], LABELS)] == [
        "a.rs:1",
        "a.rs:2",
        "a.rs:3",
        "a.rs:4",
        "a.rs:5",
        "a.rs:6",
        "a.rs:9",
    ]


def test_the_development_section_is_where_history_stands() -> None:
    dev = development_pages()
    assert (ROOT / "docs" / "performance_history.md").resolve() in dev
    assert (ROOT / "docs" / "development" / "lab_notes.md").resolve() in dev
    assert (ROOT / "docs" / "guide" / "simulate.md").resolve() not in dev


def test_readme_is_one_or_two_screens_and_its_links_resolve() -> None:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert len(text.splitlines()) <= README_LINES
    for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", text):
        if "://" not in target:
            assert (ROOT / target).exists(), f"README.md links to a missing {target}"
    # The two set-up commands are what CI and the main job run.
    assert "bash scripts/ci/test.sh" in text
    assert "bash scripts/ci/test.sh" in (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert "loco reproduce --quick --out results/reproduce" in text
