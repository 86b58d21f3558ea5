"""Verification records written by the pytest cases, in the format of the Rust cases'
(``crates/loco-core/tests/verification/record.rs``): what a case measured against its reference,
in ``docs/verification/records/<case>.json``, from which ``scripts/docs/verification_docs.py``
generates the Verification page.

Each value is stored rounded to the significant digits the page shows, so a record changes only
when a result does. In a normal run :meth:`Record.check` compares what the test measured with the
committed record and fails, naming the case and the quantities that differ; with
``LOCO_UPDATE_RECORDS=1`` it rewrites the record instead. The test's own assertion against its
reference stays in the test; the record is in addition.
"""

from __future__ import annotations

import json
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

RECORDS = Path(__file__).resolve().parents[1] / "docs" / "verification" / "records"


def significant(value: float, digits: int) -> str:
    """``value`` rounded to ``digits`` significant digits: plain notation between 1e-4 and 1e6,
    exponent notation outside (as the Rust records write it)."""
    if digits < 1:
        raise ValueError("a record shows at least one digit")
    if not math.isfinite(value):
        return "NaN"
    if value == 0.0:
        return "0"
    scientific = f"{value:.{digits - 1}e}"
    decade = int(scientific.split("e")[1])
    if -4 <= decade < 6:
        return f"{float(scientific):.{max(digits - 1 - decade, 0)}f}"
    mantissa, exponent = scientific.split("e")
    return f"{mantissa}e{int(exponent)}"


def limit_text(limit: float) -> str:
    """A tolerance's limit with the fewest significant digits (up to 6) that give it back (0.01,
    1e-9), or with 3 for a limit computed from other values."""
    for digits in range(1, 7):
        text = significant(limit, digits)
        if float(text) == limit:
            return text
    return significant(limit, 3)


@dataclass
class Record:
    """The record of one verification case, built by the test and checked at its end."""

    case: str
    test: str
    quantities: list[dict[str, str | None]] = field(default_factory=list)

    def __post_init__(self) -> None:
        if not re.fullmatch(r"[a-z0-9_]+", self.case):
            raise ValueError(f"a case id is lower-case letters, digits, underscores: {self.case!r}")

    def _push(self, key: str, value: str, unit: str, tolerance: str | None) -> Record:
        if any(q["key"] == key for q in self.quantities):
            raise ValueError(f"{self.case}: quantity {key} recorded twice")
        self.quantities.append({"key": key, "value": value, "unit": unit, "tolerance": tolerance})
        return self

    def value(self, key: str, value: float, unit: str, digits: int) -> Record:
        """A measured value (in ``unit``, "" for a ratio) shown with ``digits`` significant
        digits."""
        return self._push(key, significant(float(value), digits), unit, None)

    def within(
        self, key: str, value: float, unit: str, digits: int, relation: str, limit: float
    ) -> Record:
        """A measured value with the tolerance the test asserts on it (``relation`` as the page
        reads it, such as "≤", and the limit in the value's unit)."""
        tolerance = f"{relation} {limit_text(float(limit))}"
        return self._push(key, significant(float(value), digits), unit, tolerance)

    def below(
        self, key: str, value: float, unit: str, floor: float, relation: str, limit: float
    ) -> Record:
        """A value expected at round-off level: recorded as "< floor" when smaller than
        ``floor`` (the last bits of a library's arithmetic do not change the record), with one
        significant digit above it."""
        v = float(value)
        shown = f"< {significant(floor, 1)}" if abs(v) < floor else significant(v, 1)
        return self._push(key, shown, unit, f"{relation} {limit_text(float(limit))}")

    def count(self, key: str, n: int) -> Record:
        """A count (of samples, points, bins ...)."""
        return self._push(key, str(int(n)), "", None)

    def render(self) -> str:
        """The record as its file holds it."""
        lines = [
            "{",
            f'  "case": {json.dumps(self.case, ensure_ascii=False)},',
            f'  "test": {json.dumps(self.test, ensure_ascii=False)},',
            '  "quantities": [',
        ]
        for i, q in enumerate(self.quantities):
            comma = "," if i + 1 < len(self.quantities) else ""
            cells = ", ".join(f'"{k}": {json.dumps(q[k], ensure_ascii=False)}' for k in q)
            lines.append(f"    {{{cells}}}{comma}")
        lines += ["  ]", "}", ""]
        return "\n".join(lines)

    def check(self) -> None:
        """Compares the record with the committed one and fails when they differ, or writes it
        when ``LOCO_UPDATE_RECORDS=1``."""
        path = RECORDS / f"{self.case}.json"
        text = self.render()
        committed = path.read_text(encoding="utf-8") if path.exists() else ""
        if os.environ.get("LOCO_UPDATE_RECORDS") == "1":
            if committed != text:
                path.write_text(text, encoding="utf-8")
            return
        if committed != text:
            previous = json.loads(committed)["quantities"] if committed else []
            old = {q["key"]: q["value"] for q in previous}
            changed = [
                f"{q['key']} = {q['value']}"
                for q in self.quantities
                if old.get(str(q["key"])) != q["value"]
            ]
            raise AssertionError(
                f"verification record {self.case} is stale ({path}; now "
                f"{', '.join(changed) or 'its layout changed'}): rerun the test with "
                "LOCO_UPDATE_RECORDS=1 and commit the record, then python "
                "scripts/docs/verification_docs.py --write"
            )


def record(case: str, test_file: str) -> Record:
    """A record of ``case`` measured by the test in ``test_file`` (pass ``__file__``)."""
    path = Path(test_file).resolve()
    root = RECORDS.parents[2]
    return Record(case, str(path.relative_to(root)) if path.is_relative_to(root) else path.name)
