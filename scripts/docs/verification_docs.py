"""``docs/verification.md``, generated from the verification records the tests write
(``docs/verification/records/<case>.json``: what each case measured, rounded as the page shows
it, with the tolerance the test asserts) and the rows of ``scripts/docs/verification_cases.py``
and ``scripts/docs/verification_curves.py`` (what is checked and against which reference: text
that is not a measurement). No number on the page is typed: each comes from a record, and a
record the rows do not use, or a row naming a record that does not exist, stops the generator.

    python scripts/docs/verification_docs.py --write   # rewrite the page
    python scripts/docs/verification_docs.py --check   # exit 1 when the page is stale (CI test)

The records themselves are checked by the tests that write them; ``LOCO_UPDATE_RECORDS=1``
rewrites them (``cargo test -p loco-core --release --test verification`` and the pytest cases).
"""

from __future__ import annotations

import fnmatch
import json
import sys
from pathlib import Path
from typing import NamedTuple

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "verification.md"
RECORDS = ROOT / "docs" / "verification" / "records"


class Quantity(NamedTuple):
    """One recorded quantity: its value as the page shows it, unit and asserted tolerance."""

    key: str
    value: str
    unit: str
    tolerance: str | None


class CaseRecord(NamedTuple):
    """The record of one case: the test that wrote it and its quantities, in order."""

    case: str
    test: str
    quantities: tuple[Quantity, ...]


def load_records(directory: Path = RECORDS) -> dict[str, CaseRecord]:
    """Every record in ``directory``, by case id."""
    records = {}
    for path in sorted(directory.glob("*.json")):
        data = json.loads(path.read_text(encoding="utf-8"))
        if data["case"] != path.stem:
            raise ValueError(f"{path}: case {data['case']!r} in a file named {path.stem!r}")
        quantities = tuple(Quantity(**q) for q in data["quantities"])
        records[path.stem] = CaseRecord(data["case"], data["test"], quantities)
    return records


def _digits(text: str) -> int:
    """The significant digits of a recorded value (``"0.0062"`` has 2, ``"6100"`` 2)."""
    mantissa = text.lower().split("e")[0].lstrip("+-")
    if "." not in mantissa:
        mantissa = mantissa.rstrip("0")  # a whole number's trailing zeros place it (6100)
    return max(len(mantissa.replace(".", "").lstrip("0")), 1)


def scaled(text: str, factor: float = 1.0, suffix: str = "") -> str:
    """A recorded value times ``factor`` (1e3 for m to mm, 100 for a ratio in %) with the
    record's significant digits; a minus sign as the page prints it. A bound (``"< 1e-12"``,
    a value at round-off level) stays a bound."""
    if text.startswith("< "):
        return "< " + scaled(text[2:], factor, suffix)
    if factor == 1.0:
        shown = text
    else:
        shown = f"{float(text) * factor:#.{_digits(text)}g}"
        mantissa, _, exponent = shown.partition("e")
        shown = mantissa.rstrip(".") + (f"e{int(exponent)}" if exponent else "")
    return _minus(shown) + suffix


def _minus(text: str) -> str:
    """A leading minus sign as the page prints it (exponents keep theirs)."""
    return "−" + text[1:] if text.startswith("-") else text


def _number(text: str) -> float:
    return float(text.removeprefix("< "))


class Records:
    """The records as the rows read them; remembers which cases were read, so that the page
    can refuse a record no row shows."""

    def __init__(self, records: dict[str, CaseRecord]) -> None:
        self.records = records
        self.used: set[str] = set()

    def cases(self, pattern: str) -> list[CaseRecord]:
        """The records whose case id matches the shell pattern (``conicity_given_dr_e*``)."""
        found = [r for c, r in self.records.items() if fnmatch.fnmatchcase(c, pattern)]
        if not found:
            raise KeyError(f"no verification record matches {pattern!r}")
        self.used.update(r.case for r in found)
        return found

    def quantity(self, case: str, key: str) -> Quantity:
        (record,) = self.cases(case)
        for q in record.quantities:
            if q.key == key:
                return q
        raise KeyError(f"verification record {case} has no quantity {key!r}")

    def get(self, case: str, key: str, factor: float = 1.0, suffix: str = "") -> str:
        """One recorded value, scaled and with its suffix (a unit or %)."""
        return scaled(self.quantity(case, key).value, factor, suffix)

    def values(self, pattern: str, key: str) -> list[str]:
        """The values of the quantities matching ``key`` (a shell pattern too) in the cases
        matching ``pattern``."""
        found = [
            q.value
            for r in self.cases(pattern)
            for q in r.quantities
            if fnmatch.fnmatchcase(q.key, key)
        ]
        if not found:
            raise KeyError(f"no quantity {key!r} in the verification records {pattern!r}")
        return found

    def largest(self, pattern: str, key: str, factor: float = 1.0, suffix: str = "") -> str:
        """The largest value of ``key`` over the matching cases (a bound counts as its value)."""
        return scaled(max(self.values(pattern, key), key=_number), factor, suffix)

    def smallest(self, pattern: str, key: str, factor: float = 1.0, suffix: str = "") -> str:
        """The smallest value of ``key`` over the matching cases."""
        return scaled(min(self.values(pattern, key), key=_number), factor, suffix)

    def total(self, pattern: str, key: str) -> str:
        """The sum of a count over the matching cases."""
        return str(sum(int(v) for v in self.values(pattern, key)))


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _table(header: tuple[str, ...], rows: list[tuple[str, ...]]) -> list[str]:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(_cell(c) for c in row) + " |" for row in rows]
    return lines


def _case_table(records: dict[str, CaseRecord]) -> list[str]:
    """Every record's quantities, one row each: the case and its test on its first row."""
    rows = []
    for record in records.values():
        for i, q in enumerate(record.quantities):
            first = i == 0
            rows.append(
                (
                    f"`{record.case}`" if first else "",
                    f"`{record.test}`" if first else "",
                    q.key.replace("_", " "),
                    _minus(q.value),
                    q.unit,
                    q.tolerance or "",
                )
            )
    return _table(("case", "test", "quantity", "value", "unit", "tolerance"), rows)


def render(records: dict[str, CaseRecord] | None = None) -> str:
    """The whole page."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from verification_cases import INTRO, MODEL_PARTS
    from verification_curves import CURVES, CURVES_INTRO

    data = Records(load_records() if records is None else records)
    model = [(row.what, row.against, row.result(data)) for row in MODEL_PARTS]
    curves = [(row.what, row.against, row.result(data)) for row in CURVES]
    unused = sorted(set(data.records) - data.used)
    if unused:
        raise ValueError(f"verification records no row of the page shows: {', '.join(unused)}")
    lines = [
        "# Verification",
        "",
        "<!-- generated by scripts/docs/verification_docs.py from docs/verification/records: "
        "do not edit -->",
        "",
        *INTRO,
        "",
        "## The model's parts",
        "",
        *_table(("what", "against", "result"), model),
        "",
        "## Curves",
        "",
        *CURVES_INTRO,
        "",
        *_table(("check", "against", "result"), curves),
        "",
        "## Every recorded case",
        "",
        "What each case's test measured, as its record holds it (`docs/verification/records/`),",
        "with the tolerance the test asserts where it asserts one on that quantity (SI units; a",
        'unit "SI" is the largest of several channels, each in its own unit).',
        "",
        *_case_table(data.records),
        "",
    ]
    return "\n".join(lines)


def main() -> None:
    from docs_page import run  # scripts/ is on the path when this file runs as a script

    run(PAGE, lambda _page: render(), "scripts/docs/verification_docs.py", __doc__.splitlines()[0])


if __name__ == "__main__":
    main()
