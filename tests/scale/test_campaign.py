"""Campaigns and their sample store (a killed campaign loses no finished sample): a real
subprocess killed with SIGKILL loses no finished sample, damaged store files are detected and
rerun, finished stages are checked by the content hash of their outputs. Short runs (300 m, the
shortest record the metrics take at 200 km/h) on local threads."""

from __future__ import annotations

import json
import os
import random
import signal
import socket
import subprocess
import sys
import time
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import pandas as pd
import pytest

import loco
from loco.campaign import load_campaign, run_campaign
from loco.cli import main
from loco.store import CampaignStore, CorruptStoreWarning, atomic_write, find_campaigns
from loco.studies.parameters import names
from loco.studies.report import StudyRecord, save_table
from loco.studies.sampling import latin_hypercube
from loco.studies.stages import Runtime, Stage, StageRunner

SCENARIO = loco.Scenario(name="S_high", distance=300.0, seed=3)
N = 10


@pytest.fixture(scope="module")
def design() -> np.ndarray:
    return latin_hypercube(N, seed=5)


@pytest.fixture(scope="module")
def reference(design: np.ndarray) -> loco.BatchResult:
    """The design as one plain batch (no chunks, no store)."""
    return loco.run_batch(design, names(), scenario=SCENARIO, threads=2, progress=False)


def _same(a: loco.BatchResult, b: loco.BatchResult) -> None:
    assert a.metric_names == b.metric_names
    assert a.metrics.tobytes() == b.metrics.tobytes()  # bit-identical, NaN included
    assert np.array_equal(a.status, b.status) and a.messages == b.messages


def _store_dir(root: Path) -> Path:
    (directory,) = [p.parent for p in root.rglob("campaign.json")]
    return directory


def _raw_samples(directory: Path) -> np.ndarray:
    parts = sorted((directory / "samples").glob("part-*.parquet"))
    return np.concatenate([pd.read_parquet(p)["sample"].to_numpy() for p in parts])


def test_rerun_reads_back_every_sample(
    tmp_path: Path, design: np.ndarray, reference: loco.BatchResult
) -> None:
    first = run_campaign(design, names(), scenario=SCENARIO, store=tmp_path, chunk_size=4,
                         threads=2, progress=False)  # fmt: skip
    _same(first, reference)
    assert first.n_reused == 0
    again = loco.run_batch(design, names(), scenario=SCENARIO, store=tmp_path, progress=False)
    _same(again, reference)
    assert again.n_reused == N
    frame = load_campaign(_store_dir(tmp_path))
    assert list(frame["sample"]) == list(range(N))
    assert frame[names()].to_numpy().tobytes() == design.tobytes()
    assert set(frame["loco_version"]) == {loco.__version__}
    assert frame["vehicle_hash"].nunique() == 1 and frame["scenario_hash"].nunique() == 1
    ds = CampaignStore(tmp_path, frame["campaign"][0], N, writable=False).to_xarray()
    assert ds.sizes["sample"] == N and "wy_max" in ds
    # Other inputs are another campaign: nothing reused.
    other = loco.run_batch(design[:2], names(), scenario=SCENARIO, seed=4, store=tmp_path,
                           progress=False)  # fmt: skip
    assert other.n_reused == 0 and len(find_campaigns(tmp_path)) == 2


SCRIPT = """
import sys, numpy as np, loco
from loco.campaign import run_campaign
from loco.studies.parameters import names
design = np.load(sys.argv[1])
scenario = loco.Scenario(name="S_high", distance=300.0, seed=3)
def stored(idx):
    print("stored", *idx.tolist(), flush=True)
run_campaign(design, names(), scenario=scenario, store=sys.argv[2], chunk_size=1, threads=2,
             progress=False, on_chunk=stored)
print("complete", flush=True)
"""


def test_sigkill_loses_no_finished_sample(
    tmp_path: Path, design: np.ndarray, reference: loco.BatchResult
) -> None:
    np.save(tmp_path / "design.npy", design)
    (tmp_path / "campaign.py").write_text(SCRIPT, encoding="utf-8")
    store = tmp_path / "store"
    log = open(tmp_path / "log.txt", "w+", encoding="utf-8")
    proc = subprocess.Popen(
        [sys.executable, str(tmp_path / "campaign.py"), str(tmp_path / "design.npy"), str(store)],
        stdout=log,
    )
    # The kill lands at a random point within the second to fifth chunk, counted in chunks
    # (a chunk's time depends on the machine and on what the process keeps from earlier ones).
    chance = random.Random(os.urandom(8))
    after, delay = chance.randint(1, 4), chance.uniform(0.0, 0.03)
    deadline = time.monotonic() + 120
    while (tmp_path / "log.txt").read_text().count("stored") < after:
        assert proc.poll() is None, "the campaign ended before the chunk to kill it in"
        assert time.monotonic() < deadline, "no chunk stored within 120 s"
        time.sleep(0.002)
    time.sleep(delay)
    proc.send_signal(signal.SIGKILL)
    when = f"after {after} chunks + {delay:.3f} s"
    assert proc.wait(30) == -signal.SIGKILL, f"not killed mid-run ({when})"
    log.close()
    reported = [
        int(i) for line in (tmp_path / "log.txt").read_text().splitlines()
        if line.startswith("stored") for i in line.split()[1:]
    ]  # fmt: skip
    assert reported and "complete" not in (tmp_path / "log.txt").read_text()
    directory = _store_dir(store)
    # Every sample the killed process reported stored is there, whole (no warning).
    with warnings.catch_warnings():
        warnings.simplefilter("error", CorruptStoreWarning)
        held = CampaignStore(store, json.loads((directory / "campaign.json").read_text())["key"],
                             N, writable=False).load().frame  # fmt: skip
    assert set(reported) <= set(held["sample"]), when
    rerun = run_campaign(design, names(), scenario=SCENARIO, store=store, chunk_size=2,
                         threads=2, progress=False)  # fmt: skip
    assert rerun.n_reused == len(held) >= len(reported)
    _same(rerun, reference)
    assert sorted(_raw_samples(directory)) == list(range(N))  # every sample exactly once


def test_damaged_files_are_detected_and_rerun(
    tmp_path: Path, design: np.ndarray, reference: loco.BatchResult
) -> None:
    run_campaign(design, names(), scenario=SCENARIO, store=tmp_path, chunk_size=4, threads=2,
                 progress=False)  # fmt: skip
    directory = _store_dir(tmp_path)
    parts = sorted((directory / "samples").glob("part-*.parquet"))
    assert len(parts) == 3
    truncated, flipped = parts[0], parts[2]
    data = truncated.read_bytes()
    truncated.write_bytes(data[: len(data) // 2])
    data = bytearray(flipped.read_bytes())
    data[len(data) // 2] ^= 0xFF
    flipped.write_bytes(bytes(data))
    # A killed writer's temporary file: this host, a process id that no longer runs.
    dead = int(Path("/proc/sys/kernel/pid_max").read_text()) + 1
    tmp = directory / "samples" / f".part-x.{socket.gethostname()}.{dead}.tmp"
    tmp.write_bytes(b"half a file")
    main(["campaign", "status", str(tmp_path)])
    with pytest.warns(CorruptStoreWarning) as caught:
        rerun = run_campaign(design, names(), scenario=SCENARIO, store=tmp_path, chunk_size=4,
                             threads=2, progress=False)  # fmt: skip
    named = " ".join(str(w.message) for w in caught)
    assert truncated.name in named and flipped.name in named
    assert rerun.n_reused == 4  # only the middle part was whole
    _same(rerun, reference)
    assert sorted(_raw_samples(directory)) == list(range(N))
    assert len(list((directory / "samples").glob("*.corrupt"))) == 2
    assert not list((directory / "samples").glob("*.tmp"))


def test_status_command(tmp_path: Path, design: np.ndarray, capsys: pytest.CaptureFixture) -> None:
    run_campaign(design[:4], names(), scenario=SCENARIO, store=tmp_path / "a", chunk_size=2,
                 threads=2, progress=False)  # fmt: skip
    assert main(["campaign", "status", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "4/4 samples (complete), 0 failed, 2 part files; S_high" in out
    assert "1 campaigns, 4/4 samples stored" in out
    with pytest.raises(SystemExit) as usage:
        main(["campaign", "status", str(tmp_path / "nothing")])
    assert usage.value.code == 2
    assert "is not a directory" in capsys.readouterr().err


def test_atomic_write_replaces_whole_files(tmp_path: Path) -> None:
    path = atomic_write(tmp_path / "a" / "x.json", b"one")
    atomic_write(path, b"two")
    assert path.read_bytes() == b"two" and [p.name for p in path.parent.iterdir()] == ["x.json"]


@dataclass(frozen=True)
class TableStage(Stage):
    name: ClassVar[str] = "demo"
    n: int = 1

    def run(self, out: Path, runtime: Runtime) -> StudyRecord:
        table = save_table(pd.DataFrame({"a": np.arange(50)}), out / "table.csv")
        return StudyRecord(name=out.name, title="t", figures=[], tables=[table])


def test_stage_with_damaged_output_runs_again(tmp_path: Path) -> None:
    lines: list[str] = []
    StageRunner(tmp_path, log=lines.append).run(TableStage())
    runner = StageRunner(tmp_path, log=lines.append)
    runner.run(TableStage())
    assert runner.skipped == ["demo"]
    table = tmp_path / "demo" / "table.csv"
    table.write_text(table.read_text()[:40])  # truncated: the file still exists
    runner = StageRunner(tmp_path, log=lines.append)
    runner.run(TableStage())
    assert runner.ran == ["demo"] and len(pd.read_csv(table)) == 50
    assert any("demo/table.csv is changed or truncated" in line for line in lines)


def test_per_sample_tracks_in_chunks_are_those_of_one_batch(tmp_path: Path) -> None:
    """A track per sample in a campaign: sample i draws stream i whatever chunk runs it, so the
    chunked, stored campaign gives the one-batch numbers (and a rerun reuses the store)."""
    rows = np.tile(latin_hypercube(1, seed=2), (3, 1))  # same parameters: only the tracks differ
    whole = loco.run_batch(
        rows, names(), scenario=SCENARIO, threads=2, progress=False, per_sample_track=True
    )
    assert len({float(v) for v in whole.metric("ayb_peak_lp")}) == 3
    chunked = run_campaign(
        rows,
        names(),
        scenario=SCENARIO,
        store=tmp_path,
        chunk_size=1,
        threads=2,
        progress=False,
        per_sample_track=True,
    )
    _same(whole, chunked)
    again = run_campaign(
        rows, names(), scenario=SCENARIO, store=tmp_path, progress=False, per_sample_track=True
    )
    assert again.n_reused == 3
    _same(whole, again)
