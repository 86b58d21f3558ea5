"""The study report: a Markdown file that shows every figure and table of the studies with the
parameters, seeds, software version and run times that produced them, and the same report as one
self-contained HTML page beside it (:mod:`loco.studies.report_html`).

Each study hands back a :class:`StudyRecord` naming the files it wrote (figures as PNG, numbers
as CSV or JSON) inside the output directory; :func:`write_report` links them relative to the
Markdown report, so the directory can be moved or zipped whole, and embeds them in the page.
"""

from __future__ import annotations

import dataclasses
import json
import os
import platform
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeAlias

import numpy as np
import pandas as pd

__all__ = [
    "StudyRecord",
    "jsonable",
    "save_json",
    "save_table",
    "setting_text",
    "write_report",
]

#: Rows of a CSV table shown inline in the report (the full table is linked).
MAX_INLINE_ROWS = 20
#: CSV tables longer (time histories, spectra, sample designs) or wider than this are linked,
#: not shown.
MAX_SHOWN_TABLE_ROWS = 40
MAX_SHOWN_TABLE_COLUMNS = 12


@dataclass
class StudyRecord:
    """What one study produced.

    Parameters
    ----------
    name : str
        Short identifier (also the stage name), e.g. ``"sensitivity"``.
    title : str
        Section heading.
    figures : list of Path
        PNG files written by the study.
    tables : list of Path
        CSV or JSON files with the numbers behind the figures.
    parameters : dict
        Settings that produced them (sample sizes, seeds, scenarios ...), JSON-serialisable.
    seconds : float
        Wall-clock run time (s).
    notes : str
        Markdown paragraph shown under the heading (findings, caveats such as dropped samples).
    captions : dict
        What to read from each figure (Markdown), by the figure's file name (``"pareto.png"``);
        a figure without one is captioned by its file name.
    """

    name: str
    title: str = ""
    figures: list[Path] = field(default_factory=list)
    tables: list[Path] = field(default_factory=list)
    parameters: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0
    notes: str = ""
    captions: dict[str, str] = field(default_factory=dict)

    def caption(self, figure: Path) -> str:
        """The caption of ``figure``: its entry in :attr:`captions`, else its file name."""
        return self.captions.get(Path(figure).name, Path(figure).name)

    def to_json(self, root: Path) -> dict[str, Any]:
        """A JSON-ready dict with paths relative to ``root``."""
        return {
            "name": self.name,
            "title": self.title,
            "figures": [os.path.relpath(p, root) for p in self.figures],
            "tables": [os.path.relpath(p, root) for p in self.tables],
            "parameters": jsonable(self.parameters),
            "seconds": self.seconds,
            "notes": self.notes,
            "captions": dict(self.captions),
        }

    @classmethod
    def from_json(cls, data: Mapping[str, Any], root: Path) -> StudyRecord:
        """Inverse of :meth:`to_json`, paths resolved against ``root``."""
        return cls(
            name=str(data["name"]),
            title=str(data.get("title", "")),
            figures=[root / p for p in data.get("figures", [])],
            tables=[root / p for p in data.get("tables", [])],
            parameters=dict(data.get("parameters", {})),
            seconds=float(data.get("seconds", 0.0)),
            notes=str(data.get("notes", "")),
            captions={str(k): str(v) for k, v in data.get("captions", {}).items()},
        )


def jsonable(value: Any) -> Any:
    """``value`` with numpy scalars/arrays, paths, tuples and sets made JSON-serialisable."""
    if isinstance(value, Mapping):
        return {str(k): jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, set, frozenset)):
        items = sorted(value, key=str) if isinstance(value, (set, frozenset)) else value
        return [jsonable(v) for v in items]
    if isinstance(value, np.ndarray):
        return jsonable(value.tolist())
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, Path):
        return str(value)
    if isinstance(value, float) and not np.isfinite(value):
        return str(value)
    return value


def save_table(frame: pd.DataFrame, path: str | Path) -> Path:
    """Write ``frame`` as CSV (no index) and return the path."""
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    frame.to_csv(out, index=False)
    return out


def save_json(data: Any, path: str | Path) -> Path:
    """Write ``data`` as indented JSON (via :func:`jsonable`) and return the path."""
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(jsonable(data), indent=2, sort_keys=True) + "\n")
    return out


def setting_text(value: Any) -> str:
    """``value`` as a reader reads it: scalars plainly, lists comma-separated, dicts as
    ``key: value`` pairs separated by semicolons (nested ones in brackets), an empty one as
    "none"."""
    value = jsonable(value)
    if isinstance(value, Mapping):
        if not value:
            return "none"
        return "; ".join(f"{k}: {_nested(v)}" for k, v in value.items())
    if isinstance(value, list):
        return ", ".join(_nested(v) for v in value) if value else "none"
    if value is None:
        return "none"
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


def _nested(value: Any) -> str:
    if isinstance(value, Mapping):
        return "{" + setting_text(value) + "}"
    if isinstance(value, list):
        return "[" + setting_text(value) + "]"
    return setting_text(value)


def _cell(value: Any) -> str:
    if isinstance(value, (float, np.floating)):
        return f"{value:.4g}"
    return str(value).replace("|", "\\|")


def _markdown_table(frame: pd.DataFrame) -> str:
    header = "| " + " | ".join(_cell(c) for c in frame.columns) + " |"
    rule = "|" + "---|" * len(frame.columns)
    rows = ["| " + " | ".join(_cell(v) for v in row) + " |" for row in frame.itertuples(False)]
    return "\n".join([header, rule, *rows])


@dataclass(frozen=True)
class Figure:
    """A figure of the report: the PNG, its path relative to the report and its caption."""

    path: Path
    link: str
    caption: str

    def markdown(self) -> list[str]:
        """The figure as Markdown lines: the image, then its caption in italics."""
        return [f"![{self.path.stem}]({self.link})", "", f"*{self.caption}*", ""]


#: A part of a section: Markdown lines, or a figure.
Block: TypeAlias = list[str] | Figure


def _section(record: StudyRecord, root: Path) -> list[Block]:
    lines = [f"## {record.title or record.name}", ""]
    lines.append(f"Run time: {record.seconds:.1f} s.")
    lines.append("")
    if record.notes:
        lines += [record.notes, ""]
    if record.parameters:
        lines += ["| setting | value |", "|---|---|"]
        for key, value in record.parameters.items():
            lines.append(f"| {key} | {_cell(setting_text(value))} |")
        lines.append("")
    blocks: list[Block] = [lines]
    for fig in record.figures:
        rel = Path(os.path.relpath(fig, root)).as_posix()
        blocks.append(Figure(fig, rel, record.caption(fig)))
    lines = []
    for table in record.tables:
        rel = Path(os.path.relpath(table, root)).as_posix()
        lines.append(f"Data: [{table.name}]({rel})")
        lines.append("")
        if table.suffix == ".csv" and table.exists():
            frame = pd.read_csv(table)
            if len(frame) > MAX_SHOWN_TABLE_ROWS or len(frame.columns) > MAX_SHOWN_TABLE_COLUMNS:
                lines += [f"({len(frame)} rows × {len(frame.columns)} columns, not shown.)", ""]
                continue
            lines.append(_markdown_table(frame.head(MAX_INLINE_ROWS)))
            if len(frame) > MAX_INLINE_ROWS:
                lines.append(f"\n({MAX_INLINE_ROWS} of {len(frame)} rows shown.)")
            lines.append("")
    blocks.append(lines)
    return blocks


def write_report(
    records: Sequence[StudyRecord],
    path: str | Path,
    *,
    title: str = "loco study report",
    preamble: str = "",
    settings: Mapping[str, Any] | None = None,
    first_section: Sequence[str] = (),
) -> Path:
    """Write the Markdown report of ``records`` to ``path`` and the same report as an HTML page
    beside it (``path`` with the suffix ``.html``, :func:`loco.studies.report_html.write_html`);
    return the Markdown report's path.

    The header gives the loco version, Python and platform, the date, the total run time and
    ``settings`` (e.g. the command line, thread count, master seed); ``first_section`` (Markdown
    lines, e.g. the study's verdict, :mod:`loco.studies.verdict`) comes next; each record becomes a
    section with its settings, figures (embedded with links relative to the report, each with its
    caption) and tables (linked; a CSV of at most :data:`MAX_SHOWN_TABLE_ROWS` rows and
    :data:`MAX_SHOWN_TABLE_COLUMNS` columns is also shown inline, up to
    :data:`MAX_INLINE_ROWS` of them).
    """
    from loco import __version__
    from loco.studies.report_html import write_html

    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    root = out.parent.resolve()
    total = sum(r.seconds for r in records)
    about = [
        f"- loco {__version__}, Python {platform.python_version()}, {platform.platform()}",
        f"- written {time.strftime('%Y-%m-%d %H:%M:%S %Z')}",
        f"- total run time {total:.1f} s",
    ]
    for key, value in (settings or {}).items():
        about.append(f"- {key}: {setting_text(value)}")
    about.append("")
    sections: list[Block] = []
    for record in records:
        resolved = dataclasses.replace(
            record,
            figures=[Path(p).resolve() for p in record.figures],
            tables=[Path(p).resolve() for p in record.tables],
        )
        sections += _section(resolved, root)
    intro = [preamble, ""] if preamble else []
    lines = [f"# {title}", "", *intro, *about, *first_section]
    for block in sections:
        lines += block.markdown() if isinstance(block, Figure) else block
    out.write_text("\n".join(lines).rstrip() + "\n", encoding="utf-8")
    write_html(
        out.with_suffix(".html"),
        title=title,
        intro=intro,
        about=about,
        first_section=list(first_section),
        sections=sections,
    )
    return out
