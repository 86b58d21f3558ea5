"""The Verification page (``docs/verification.md``) is generated from the verification records
the tests write; these tests fail when the page is stale, when a record is not shown or a row
names a record that does not exist, and check the Python writer of the records."""

from __future__ import annotations

import json
from pathlib import Path
from types import ModuleType

import pytest

import verification_records
from script_modules import load_script
from verification_records import Record, limit_text, significant

ROOT = Path(__file__).resolve().parents[2]


def _docs_script() -> ModuleType:
    return load_script("verification_docs")


def test_committed_verification_page_is_the_generated_one() -> None:
    docs = _docs_script()
    assert docs.PAGE.read_text(encoding="utf-8") == docs.render(), (
        "run python scripts/docs/verification_docs.py --write"
    )


def test_every_record_names_an_existing_test_and_is_on_the_page() -> None:
    docs = _docs_script()
    records = docs.load_records()
    assert len(records) > 50
    page = docs.render(records)
    for case, record in records.items():
        assert (ROOT / record.test).is_file(), f"{case}: {record.test}"
        assert f"`{case}`" in page
        assert record.quantities, case


def test_a_record_no_row_shows_or_a_missing_one_stops_the_generator() -> None:
    docs = _docs_script()
    records = docs.load_records()
    extra = dict(records)
    extra["unused_case"] = docs.CaseRecord("unused_case", "tests/x.py", ())
    with pytest.raises(ValueError, match="unused_case"):
        docs.render(extra)
    missing = {c: r for c, r in records.items() if c != "klingel_wavelength"}
    with pytest.raises(KeyError, match="klingel_wavelength"):
        docs.render(missing)


def test_scaled_values_keep_the_records_digits() -> None:
    docs = _docs_script()
    assert docs.scaled("0.0062", 100.0, " %") == "0.62 %"
    assert docs.scaled("0.050", 100.0) == "5.0"
    assert docs.scaled("6100", 1e-3) == "6.1"
    assert docs.scaled("-0.000837", 1e3) == "−0.837"
    assert docs.scaled("< 1e-12") == "< 1e-12"


@pytest.mark.parametrize(
    ("value", "digits", "text"),
    [
        (0.0062, 2, "0.0062"),
        (9.96, 2, "10"),
        (34.2, 3, "34.2"),
        (6123.0, 2, "6100"),
        (1234567.0, 3, "1.23e6"),
        (-0.000123, 2, "-0.00012"),
        (1.234e-5, 3, "1.23e-5"),
        (0.0, 3, "0"),
    ],
)
def test_values_are_rounded_as_the_rust_records_round_them(
    value: float, digits: int, text: str
) -> None:
    # The same cases as the Rust writer's test (crates/loco-core/tests/verification/record.rs).
    assert significant(value, digits) == text


def test_limits_are_written_with_the_fewest_digits() -> None:
    assert limit_text(0.01) == "0.01"
    assert limit_text(1e-9) == "1e-9"
    assert limit_text(1.1 * 0.0093503) == "0.0103"


def test_a_stale_record_fails_naming_the_case_and_an_update_rewrites_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(verification_records, "RECORDS", tmp_path)
    monkeypatch.delenv("LOCO_UPDATE_RECORDS", raising=False)

    def measured(value: float) -> Record:
        return Record("example", "tests/x.py").within("error", value, "", 2, "<", 0.01)

    with pytest.raises(AssertionError, match="verification record example is stale"):
        measured(0.0042).check()
    monkeypatch.setenv("LOCO_UPDATE_RECORDS", "1")
    measured(0.0042).check()
    written = json.loads((tmp_path / "example.json").read_text(encoding="utf-8"))
    assert written["quantities"] == [
        {"key": "error", "value": "0.0042", "unit": "", "tolerance": "< 0.01"}
    ]
    monkeypatch.delenv("LOCO_UPDATE_RECORDS")
    measured(0.0042).check()  # the same measurement matches its record
    measured(0.00421).check()  # and so does one that rounds the same
    with pytest.raises(AssertionError, match=r"error = 0\.0043"):
        measured(0.0043).check()
