"""The Performance page (``docs/performance.md``) is generated from the benchmark records the
benchmarks write; these tests fail when the page is stale or a record is not shown, and run a
real benchmark script to check that what it records is what the page reads."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from script_modules import load_script

ROOT = Path(__file__).resolve().parents[2]


def test_committed_performance_page_is_the_generated_one() -> None:
    docs = load_script("performance_docs")
    assert docs.PAGE.read_text(encoding="utf-8") == docs.render(), (
        "run python scripts/docs/performance_docs.py --write"
    )


def test_a_record_no_row_shows_or_a_missing_one_stops_the_generator() -> None:
    docs = load_script("performance_docs")
    records = docs.load_records()
    extra = dict(records)
    extra["unused_bench"] = {**records["bench_batch"], "bench": "unused_bench"}
    with pytest.raises(ValueError, match="unused_bench"):
        docs.render(extra)
    missing = {b: r for b, r in records.items() if b != "bench_surrogate"}
    with pytest.raises(KeyError, match="bench_surrogate"):
        docs.render(missing)


def test_every_record_says_how_where_and_on_which_code_it_was_measured() -> None:
    docs = load_script("performance_docs")
    records = docs.load_records()
    assert {"criterion", "dev_tools", "bench_batch", "study_quick"} <= set(records)
    for bench, record in records.items():
        assert record["command"], bench
        assert record["machine"]["cores"] >= 1, bench
        assert record["code"] != "unknown", bench
        for key, figure in record["figures"].items():
            assert isinstance(figure["value"], int | float), (bench, key)
            assert "unit" in figure, (bench, key)


def test_durations_are_shown_in_the_unit_that_fits() -> None:
    figures = load_script("performance_figures")
    assert figures.duration(3.21e-9) == "3.21 ns"
    assert figures.duration(2.34e-7) == "234 ns"
    assert figures.duration(4.5e-3) == "4.5 ms"
    assert figures.duration(0.1304) == "130 ms"
    assert figures.duration(264.0) == "264 s"
    assert figures.duration(1926.0) == "32.1 min"


@pytest.mark.slow
def test_a_benchmark_script_writes_the_record_the_page_reads(tmp_path: Path) -> None:
    """``bench_campaign.py --record`` on a tiny design: its record, read back by the page's
    reader, gives the row the page would show."""
    env = {**os.environ, "LOCO_BENCH_RECORDS": str(tmp_path)}
    command = [sys.executable, str(ROOT / "scripts/bench/bench_campaign.py"), "--samples", "2",
               "--chunk-size", "1", "--repeat", "1", "--threads", "1", "--record"]  # fmt: skip
    subprocess.run(command, check=True, env=env, cwd=ROOT, capture_output=True)
    record = json.loads((tmp_path / "bench_campaign.json").read_text(encoding="utf-8"))
    assert record["bench"] == "bench_campaign"
    assert record["command"].startswith("python scripts/bench/bench_campaign.py --samples 2")
    assert record["figures"]["samples"]["value"] == 2
    assert record["figures"]["chunks"]["value"] == 2
    assert record["figures"]["batch_wall"]["unit"] == "s"
    assert 0.2 < record["figures"]["ratio"]["value"] < 5.0
    docs = load_script("performance_docs")
    records = {**docs.load_records(), "bench_campaign": record}
    page = docs.render(records)
    assert f"campaign / batch {record['figures']['ratio']['value']:.3g}× (2 samples)" in page
