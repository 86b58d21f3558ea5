"""The Markdown report writer and the resumable stage runner."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd

from loco import __version__
from loco.studies.report import StudyRecord, save_json, save_table, write_report
from loco.studies.stages import MARKER, StageRunner


def _stage(calls: list[str]) -> Callable[[Path], StudyRecord]:
    def run(out: Path) -> StudyRecord:
        calls.append(out.name)
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots()
        ax.plot([0, 1], [0, 1])
        fig.savefig(out / "line.png")
        plt.close(fig)
        table = save_table(pd.DataFrame({"a": np.arange(25), "b": np.arange(25) * 0.5}),
                           out / "numbers.csv")  # fmt: skip
        meta = save_json({"seed": np.int64(3), "x": np.array([1.0, 2.0])}, out / "meta.json")
        return StudyRecord(name=out.name, title="A stage", figures=[out / "line.png"],
                           tables=[table, meta], notes="Some *notes*.")  # fmt: skip

    return run


def test_stage_skipped_when_finished(tmp_path: Path) -> None:
    calls: list[str] = []
    lines: list[str] = []
    settings = {"n": 8, "seed": 1}
    runner = StageRunner(tmp_path, log=lines.append)
    first = runner.run("demo", settings, _stage(calls))
    assert calls == ["demo"] and (tmp_path / "demo" / MARKER).is_file()
    assert first.parameters == settings and first.seconds > 0
    again = StageRunner(tmp_path, log=lines.append)
    record = again.run("demo", settings, _stage(calls))
    assert calls == ["demo"] and again.skipped == ["demo"]
    assert record.figures == [tmp_path / "demo" / "line.png"]
    # A changed setting, a missing output or force runs the stage again.
    StageRunner(tmp_path, log=lines.append).run("demo", {"n": 16, "seed": 1}, _stage(calls))
    assert calls == ["demo", "demo"]
    (tmp_path / "demo" / "line.png").unlink()
    StageRunner(tmp_path, log=lines.append).run("demo", {"n": 16, "seed": 1}, _stage(calls))
    assert len(calls) == 3
    StageRunner(tmp_path, log=lines.append, force=True).run("demo", {"n": 16, "seed": 1},
                                                            _stage(calls))  # fmt: skip
    assert len(calls) == 4
    assert any("skipped" in line for line in lines)


def test_interrupted_stage_reruns(tmp_path: Path) -> None:
    def broken(out: Path) -> StudyRecord:
        raise KeyboardInterrupt

    runner = StageRunner(tmp_path, log=lambda _: None)
    try:
        runner.run("demo", {"n": 1}, broken)
    except KeyboardInterrupt:
        pass
    assert not (tmp_path / "demo" / MARKER).exists()
    calls: list[str] = []
    runner.run("demo", {"n": 1}, _stage(calls))
    assert calls == ["demo"]


def test_report_links_and_contents(tmp_path: Path) -> None:
    runner = StageRunner(tmp_path / "out", log=lambda _: None)
    record = runner.run("demo", {"n": 8, "seed": 1}, _stage([]))
    report = write_report([record], tmp_path / "out" / "report.md", settings={"threads": 2})
    text = report.read_text()
    assert f"loco {__version__}" in text
    assert "![line](demo/line.png)" in text
    assert "[numbers.csv](demo/numbers.csv)" in text and "[meta.json](demo/meta.json)" in text
    assert "(20 of 25 rows shown.)" in text
    assert "| seed | `1` |" in text and "- threads: `2`" in text
    assert "Some *notes*." in text
    for link in ("demo/line.png", "demo/numbers.csv"):
        assert (report.parent / link).is_file()
    assert json.loads((tmp_path / "out" / "demo" / "meta.json").read_text()) == {
        "seed": 3,
        "x": [1.0, 2.0],
    }
