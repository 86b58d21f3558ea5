"""The Markdown report writer and the resumable stage runner."""

from __future__ import annotations

import contextlib
import json
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import pandas as pd
import pytest

from loco import __version__
from loco.studies.report import StudyRecord, save_json, save_table, write_report
from loco.studies.stages import MARKER, Runtime, Stage, StageRunner

#: The stage directories the demo stages ran in, in order.
CALLS: list[str] = []


@dataclass(frozen=True)
class Demo(Stage):
    """A stage writing a figure and two tables; its inputs ``n`` and ``seed`` change nothing
    but its hash."""

    name: ClassVar[str] = "demo"
    n: int
    seed: int = 1

    def run(self, out: Path, runtime: Runtime) -> StudyRecord:
        CALLS.append(out.name)
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


@dataclass(frozen=True)
class Broken(Demo):
    def run(self, out: Path, runtime: Runtime) -> StudyRecord:
        raise KeyboardInterrupt


def test_stage_skipped_when_finished(tmp_path: Path) -> None:
    CALLS.clear()
    lines: list[str] = []
    runner = StageRunner(tmp_path, log=lines.append)
    first = runner.run(Demo(8))
    assert CALLS == ["demo"] and (tmp_path / "demo" / MARKER).is_file()
    assert first.parameters == {"n": 8, "seed": 1} and first.seconds > 0
    again = StageRunner(tmp_path, log=lines.append)
    record = again.run(Demo(8))
    assert CALLS == ["demo"] and again.skipped == ["demo"]
    assert record.figures == [tmp_path / "demo" / "line.png"]
    # A changed input, a missing output or force runs the stage again.
    StageRunner(tmp_path, log=lines.append).run(Demo(16))
    assert CALLS == ["demo", "demo"]
    (tmp_path / "demo" / "line.png").unlink()
    StageRunner(tmp_path, log=lines.append).run(Demo(16))
    assert len(CALLS) == 3
    StageRunner(tmp_path, log=lines.append, force=True).run(Demo(16))
    assert len(CALLS) == 4
    assert any("skipped" in line for line in lines)
    # The marker holds the hash of the inputs it ran with, and the inputs.
    marker = json.loads((tmp_path / "demo" / MARKER).read_text())
    assert marker["hash"] == Demo(16).stage_hash() and marker["inputs"] == {"n": 16, "seed": 1}


def test_interrupted_stage_reruns(tmp_path: Path) -> None:
    CALLS.clear()
    runner = StageRunner(tmp_path, log=lambda _: None)
    with pytest.raises(KeyboardInterrupt):
        runner.run(Broken(1))
    assert not (tmp_path / "demo" / MARKER).exists()
    runner.run(Demo(1))
    assert CALLS == ["demo"]


def test_stage_runs_inside_around(tmp_path: Path) -> None:
    """``around`` wraps the run (``loco reproduce``: the stage's campaign store), not a skip."""
    entered: list[Path] = []

    @contextlib.contextmanager
    def around(stage_dir: Path) -> Iterator[None]:
        entered.append(stage_dir)
        yield

    StageRunner(tmp_path, log=lambda _: None, around=around).run(Demo(2))
    StageRunner(tmp_path, log=lambda _: None, around=around).run(Demo(2))
    assert entered == [tmp_path / "demo"]


def test_report_links_and_contents(tmp_path: Path) -> None:
    runner = StageRunner(tmp_path / "out", log=lambda _: None)
    record = runner.run(Demo(8))
    report = write_report([record], tmp_path / "out" / "report.md", settings={"threads": 2})
    text = report.read_text()
    assert f"loco {__version__}" in text
    assert "![line](demo/line.png)" in text
    assert "[numbers.csv](demo/numbers.csv)" in text and "[meta.json](demo/meta.json)" in text
    assert "(20 of 25 rows shown.)" in text
    assert "| seed | 1 |" in text and "- threads: 2\n" in text
    assert "Some *notes*." in text
    for link in ("demo/line.png", "demo/numbers.csv"):
        assert (report.parent / link).is_file()
    assert json.loads((tmp_path / "out" / "demo" / "meta.json").read_text()) == {
        "seed": 3,
        "x": [1.0, 2.0],
    }
