"""report.html beside report.md (the same sections, figures embedded with their captions, tables as
tables, settings read plainly), and the report's statistics of positive quantities, dominant
frequencies and Sobol' indices."""

from __future__ import annotations

import base64
import re
from pathlib import Path

import numpy as np
import pytest
from scipy import stats

from loco.studies.report import StudyRecord, save_table, setting_text, write_report
from loco.studies.sobol import SobolIndices, indices_note
from loco.studies.statistics import (
    geometric_interval,
    mean_interval,
    median_values,
    track_values_text,
)

#: A 1x1 PNG (the smallest valid image), so the page's figure is a real one.
PNG = base64.b64decode(
    "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAQAAAC1HAwCAAAAC0lEQVR42mNkYAAAAAYAAjCB0C8AAAAASUVORK5CYII="
)


def _record(out: Path) -> StudyRecord:
    (out / "stage").mkdir(parents=True)
    (out / "stage" / "plot.png").write_bytes(PNG)
    (out / "stage" / "bare.png").write_bytes(PNG)
    import pandas as pd

    table = save_table(pd.DataFrame({"a": [1, 2], "b | c": [0.5, 0.25]}), out / "stage" / "t.csv")
    return StudyRecord(
        name="stage",
        title="A stage",
        figures=[out / "stage" / "plot.png", out / "stage" / "bare.png"],
        tables=[table],
        parameters={"n": 3, "speeds_kmh": [100.0, 200.0], "channels": {"A": "x", "B": "y"}},
        notes="Some *notes*.",
        captions={"plot.png": "What to read: the *line*."},
    )


def test_the_page_says_what_the_markdown_says(tmp_path: Path) -> None:
    record = _record(tmp_path)
    first = ["## Does the premise hold?", "", "- **Yes.**", "  - nested", "", "## Verdict", ""]
    md = write_report([record], tmp_path / "report.md", settings={"sizes": {"n": 2}},
                      first_section=first)  # fmt: skip
    text = md.read_text(encoding="utf-8")
    page = (tmp_path / "report.html").read_text(encoding="utf-8")
    # The caption under its figure in both; a figure without one is captioned by its file name.
    assert "![plot](stage/plot.png)\n\n*What to read: the *line*.*" in text
    assert "<figcaption>What to read: the <em>line</em>." in page
    assert "<figcaption>bare.png</figcaption>" in page
    # Figures embedded, nothing linked but the data files.
    images = re.findall(r'<img src="([^"]+)"', page)
    assert images == ["data:image/png;base64," + base64.b64encode(PNG).decode()] * 2
    assert not re.search(r'(src|href)="(?!data:|#|stage/t\.csv)', page)
    assert "<link" not in page and "<script" not in page
    # Settings read plainly in both (no JSON); tables are HTML tables, the escaped pipe kept.
    assert "| speeds_kmh | 100, 200 |" in text and "| channels | A: x; B: y |" in text
    assert "- sizes: n: 2" in text and '"' not in text.split("## A stage")[1]
    assert page.count("<table>") == 2 and "<td>100, 200</td>" in page and "b | c" in page
    # The first sections first and side by side, each heading in the contents; nesting kept.
    assert page.index("Does the premise hold?</h2>") < page.index("About this report")
    assert page.index("About this report") < page.index("A stage</h2>")
    assert page.count('<section class="part">') == 2
    for slug in ("does-the-premise-hold", "verdict", "a-stage"):
        assert f'href="#{slug}"' in page and f'<h2 id="{slug}">' in page
    assert re.search(r"<li><strong>Yes.</strong>\s*<ul>\s*<li>nested</li>", page)


def test_captions_survive_the_stage_marker(tmp_path: Path) -> None:
    record = _record(tmp_path)
    again = StudyRecord.from_json(record.to_json(tmp_path), tmp_path)
    assert again.captions == record.captions
    assert again.caption(tmp_path / "stage" / "bare.png") == "bare.png"


@pytest.mark.parametrize(
    ("value", "shown"),
    [
        (3, "3"),
        (0.5, "0.5"),
        ("etdrk4", "etdrk4"),
        ([1.0, 2.5], "1, 2.5"),
        ({}, "none"),
        (None, "none"),
        ({"a": [1, 2], "b": {"c": True}}, "a: [1, 2]; b: {c: True}"),
        (np.array([1, 2]), "1, 2"),
    ],
)
def test_settings_read_plainly(value: object, shown: str) -> None:
    assert setting_text(value) == shown


def test_geometric_interval_of_a_positive_quantity() -> None:
    # PSD peaks that vary by a factor 6 over four tracks: the t interval of the mean goes below
    # zero, the geometric one (the t interval of the logs taken back) does not.
    x = np.array([0.0072, 0.0035, 0.0022, 0.0130])
    assert mean_interval(x).low < 0
    ci = geometric_interval(x)
    logs = np.log(x)
    half = stats.t.ppf(0.975, 3) * logs.std(ddof=1) / 2
    assert ci.mean == pytest.approx(np.exp(logs.mean()))
    assert (ci.low, ci.high) == pytest.approx(np.exp([logs.mean() - half, logs.mean() + half]))
    assert 0 < ci.low < ci.mean < ci.high and ci.n == 4
    # Failed runs (NaN) are left out; a value at zero falls back to the mean, cut at zero.
    assert geometric_interval([*x, np.nan]) == ci
    zero = geometric_interval([0.0, 0.001, 0.02])
    assert zero.mean == pytest.approx(0.007) and zero.low == 0.0


def test_dominant_frequency_as_the_median_with_each_track() -> None:
    median, each = median_values([1.14, 10.37, np.nan, 1.2])
    assert median == pytest.approx(1.2) and len(each) == 4
    assert track_values_text(each) == "1.14, 10.4, -, 1.2"


def _indices(s1: list[float], conf: float, n_base: int = 32) -> SobolIndices:
    k = len(s1)
    return SobolIndices(
        metric="W_y",
        parameters=tuple(f"p{i}" for i in range(k)),
        S1=np.array(s1),
        S1_conf=np.full(k, conf),
        ST=np.array(s1) + 0.1,
        ST_conf=np.full(k, conf),
        n_base=n_base,
        n_dropped=0,
        n_evaluations=n_base * (k + 2),
    )


def test_sobol_note_says_where_the_estimates_are_noise() -> None:
    noisy = indices_note([_indices([0.4, -0.13], conf=0.3)], "Direct")
    assert noisy.startswith("Direct: W_y (N = 32): p0 ST 0.50 ± 0.30 (S1 0.40 ± 0.30)")
    assert "Negative S1 (p1 on W_y -0.13 ± 0.30) are estimator noise" in noisy
    assert "each of these intervals reaches 0" in noisy
    assert "The base sample is small for these indices" in noisy and "±0.30 on W_y" in noisy
    precise = indices_note([_indices([0.4, 0.2], conf=0.02, n_base=4096)], "On the surrogate")
    assert "Negative" not in precise and "small" not in precise
