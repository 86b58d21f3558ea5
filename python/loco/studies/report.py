"""The study report: a Markdown file that shows every figure and table of the studies with the
parameters, seeds, software version and run times that produced them.

Each study hands back a :class:`StudyRecord` naming the files it wrote (figures as PNG, numbers
as CSV or JSON) inside the output directory; :func:`write_report` links them relative to the
report, so the directory can be moved or zipped whole.
"""

from __future__ import annotations

import json
import os
import platform
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

__all__ = [
    "StudyRecord",
    "jsonable",
    "save_json",
    "save_table",
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
    """

    name: str
    title: str = ""
    figures: list[Path] = field(default_factory=list)
    tables: list[Path] = field(default_factory=list)
    parameters: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0
    notes: str = ""

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


def _cell(value: Any) -> str:
    if isinstance(value, (float, np.floating)):
        return f"{value:.4g}"
    return str(value).replace("|", "\\|")


def _markdown_table(frame: pd.DataFrame) -> str:
    header = "| " + " | ".join(map(str, frame.columns)) + " |"
    rule = "|" + "---|" * len(frame.columns)
    rows = ["| " + " | ".join(_cell(v) for v in row) + " |" for row in frame.itertuples(False)]
    return "\n".join([header, rule, *rows])


def _section(record: StudyRecord, root: Path) -> list[str]:
    lines = [f"## {record.title or record.name}", ""]
    lines.append(f"Run time: {record.seconds:.1f} s.")
    lines.append("")
    if record.notes:
        lines += [record.notes, ""]
    if record.parameters:
        lines += ["| setting | value |", "|---|---|"]
        for key, value in record.parameters.items():
            lines.append(f"| {key} | `{json.dumps(jsonable(value))}` |")
        lines.append("")
    for fig in record.figures:
        rel = Path(os.path.relpath(fig, root)).as_posix()
        lines += [f"![{fig.stem}]({rel})", ""]
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
    return lines


def write_report(
    records: Sequence[StudyRecord],
    path: str | Path,
    *,
    title: str = "loco study report",
    preamble: str = "",
    settings: Mapping[str, Any] | None = None,
    first_section: Sequence[str] = (),
) -> Path:
    """Write the Markdown report of ``records`` to ``path`` and return it.

    The header gives the loco version, Python and platform, the date, the total run time and
    ``settings`` (e.g. the command line, thread count, master seed); ``first_section`` (Markdown
    lines, e.g. the study's verdict, :mod:`loco.studies.verdict`) comes next; each record becomes a
    section with its settings, figures (embedded with links relative to the report) and tables
    (linked; a CSV of at most :data:`MAX_SHOWN_TABLE_ROWS` rows and
    :data:`MAX_SHOWN_TABLE_COLUMNS` columns is also shown inline, up to
    :data:`MAX_INLINE_ROWS` of them).
    """
    from loco import __version__

    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    root = out.parent.resolve()
    total = sum(r.seconds for r in records)
    lines = [f"# {title}", ""]
    if preamble:
        lines += [preamble, ""]
    lines += [
        f"- loco {__version__}, Python {platform.python_version()}, {platform.platform()}",
        f"- written {time.strftime('%Y-%m-%d %H:%M:%S %Z')}",
        f"- total run time {total:.1f} s",
    ]
    for key, value in (settings or {}).items():
        lines.append(f"- {key}: `{json.dumps(jsonable(value))}`")
    lines.append("")
    lines += first_section
    for record in records:
        resolved = StudyRecord(
            name=record.name,
            title=record.title,
            figures=[Path(p).resolve() for p in record.figures],
            tables=[Path(p).resolve() for p in record.tables],
            parameters=record.parameters,
            seconds=record.seconds,
            notes=record.notes,
        )
        lines += _section(resolved, root)
    out.write_text("\n".join(lines).rstrip() + "\n", encoding="utf-8")
    return out
