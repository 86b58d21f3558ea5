"""The figures of the benchmark records as the Performance page shows them: the records, a
reader that notes which records the page uses, the page's rows and number formats."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any, NamedTuple

RECORDS = Path(__file__).resolve().parents[2] / "docs" / "performance" / "records"

#: Seconds per unit of the time units the records use.
SECONDS = {"ns": 1e-9, "µs": 1e-6, "ms": 1e-3, "s": 1.0, "min": 60.0}


def load_records(directory: Path = RECORDS) -> dict[str, dict[str, Any]]:
    """Every record in ``directory``, by bench."""
    records = {}
    for path in sorted(directory.glob("*.json")):
        data = json.loads(path.read_text(encoding="utf-8"))
        if data["bench"] != path.stem:
            raise ValueError(f"{path}: bench {data['bench']!r} in a file named {path.stem!r}")
        records[path.stem] = data
    return records


def number(value: float, digits: int = 3) -> str:
    """``value`` to ``digits`` significant digits, without an exponent for page-sized numbers."""
    if value == 0:
        return "0"
    text = f"{value:.{digits}g}"
    if "e" in text:
        text = f"{value:.0f}" if abs(value) >= 1 else f"{value:.{digits + 2}f}"
    return text.replace("-", "−")


def duration(seconds: float) -> str:
    """A time in the unit that shows it best (ns up to s, minutes from 10 min)."""
    for unit, limit in (("ns", 1e-6), ("µs", 1e-3), ("ms", 1.0), ("s", 600.0)):
        if seconds < limit:
            return f"{number(seconds / SECONDS[unit])} {unit}"
    return f"{number(seconds / 60.0)} min"


class Records:
    """The records with the figures the rows read (to find the unused ones)."""

    def __init__(self, records: dict[str, dict[str, Any]]) -> None:
        self.records = records
        self.used: set[str] = set()

    def raw(self, bench: str, key: str) -> float:
        """The figure ``key`` of ``bench``'s record, in its own unit."""
        if bench not in self.records:
            raise KeyError(f"no benchmark record {bench!r} (docs/performance/records/)")
        figures = self.records[bench]["figures"]
        if key not in figures:
            raise KeyError(f"benchmark record {bench!r} has no figure {key!r}")
        self.used.add(bench)
        return float(figures[key]["value"])

    def seconds(self, bench: str, key: str) -> float:
        """A time figure in seconds."""
        value = self.raw(bench, key)
        return value * SECONDS[self.records[bench]["figures"][key]["unit"]]

    def time(self, bench: str, key: str) -> str:
        """A time figure as the page shows it."""
        return duration(self.seconds(bench, key))

    def value(self, bench: str, key: str, digits: int = 3) -> str:
        """Any figure with its unit."""
        unit = self.records[bench]["figures"][key]["unit"] if bench in self.records else ""
        text = number(self.raw(bench, key), digits)
        if unit in ("", "×"):
            return text + unit
        return f"{text} {unit}"

    def ratio(self, bench: str, key: str, over: str) -> float:
        """Figure ``key`` over figure ``over`` of the same record."""
        return self.raw(bench, key) / self.raw(bench, over)

    def crit(self, bench_id: str) -> str:
        """A criterion bench's median time."""
        return self.time("criterion", bench_id)


class Row(NamedTuple):
    """One benchmark on the page: its name, what it measures, its figure from the records and
    its target, met or not (``met`` gives whether, ``None`` when there is no target).
    ``optional`` names a record the row may lack (a benchmark too long to rerun every time):
    without it the row says so instead of failing."""

    bench: str
    what: str
    figure: Callable[[Records], str]
    target: str = ""
    met: Callable[[Records], bool] | None = None
    optional: str | None = None

    def cells(self, records: Records) -> tuple[str, str, str, str]:
        if self.optional is not None and self.optional not in records.records:
            missing = "not recorded on this machine (the last figure is in the history)"
            return (self.bench, self.what, missing, self.target)
        target = self.target
        if self.met is not None:
            target += " (met)" if self.met(records) else " (not met)"
        return (self.bench, self.what, self.figure(records), target)


def table(header: tuple[str, ...], rows: list[tuple[str, ...]]) -> list[str]:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cells) + " |" for cells in rows]
    return lines
