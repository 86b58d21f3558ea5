"""One writer per campaign store: two real processes on one real store directory do no work twice,
the second is told who holds the store, and temporary files are removed only by their writer."""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import loco
from loco.store import CampaignStore, find_campaigns
from loco.store_lock import LOCK_FILE, StoreBusyError, StoreLock, remove_stale_temporaries

#: The campaign every writer runs: six 20 m samples, one per chunk (a part file each). Given a
#: second argument (a file), the writer holds on after its first chunk until that file exists, so
#: that a second writer certainly starts while the first holds the store.
WRITER = """
import json, sys, time
from pathlib import Path
import numpy as np
import loco
from loco.executors import LocalExecutor

class Gated(LocalExecutor):
    def map_chunks(self, job, chunks, progress=None):
        for i, result in enumerate(super().map_chunks(job, chunks, progress)):
            yield result
            deadline = time.monotonic() + 120
            while i == 0 and len(sys.argv) > 2 and not Path(sys.argv[2]).exists():
                if time.monotonic() > deadline:
                    raise SystemExit("never released")
                time.sleep(0.02)

params = np.linspace(1.0e5, 3.0e5, 6)[:, None]
scenario = loco.Scenario(name="S_norm", distance=20.0, track="perfect")
try:
    r = loco.run_batch(params, ["C_sx"], scenario=scenario, store=sys.argv[1], chunk_size=1,
                       progress=False, executor=Gated(1))
except loco.LocoError as e:
    print(json.dumps({"error": type(e).__name__, "message": str(e)}))
else:
    print(json.dumps({"reused": r.n_reused, "status": r.status.tolist()}))
"""


def _writer(store: Path, *gate: Path) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-c", WRITER, str(store), *map(str, gate)],
        stdout=subprocess.PIPE,
        text=True,
    )


def _answer(process: subprocess.Popen[str]) -> dict[str, object]:
    out, _ = process.communicate(timeout=300)
    assert process.returncode == 0
    return json.loads(out.strip().splitlines()[-1])


@pytest.mark.slow
def test_a_second_writer_fails_at_once_naming_the_first_and_no_sample_runs_twice(
    tmp_path: Path,
) -> None:
    store, gate = tmp_path / "store", tmp_path / "go"
    first = _writer(store, gate)
    # Wait until the first holds the lock and has stored its first chunk.
    deadline = time.monotonic() + 120
    parts: list[Path] = []
    while time.monotonic() < deadline and first.poll() is None and not parts:
        parts = list(store.glob("*/samples/part-*.parquet"))
        time.sleep(0.05)
    assert parts, "the first writer never stored a chunk"
    lock = parts[0].parent.parent / LOCK_FILE
    assert str(first.pid) in lock.read_text(encoding="utf-8")
    started = time.monotonic()
    second = _answer(_writer(store))
    # It failed before doing anything: within the time of starting Python and loco.
    assert time.monotonic() - started < 60
    gate.touch()
    first_answer = _answer(first)
    assert second.get("error") == "StoreBusyError", second
    message = str(second["message"])
    assert f"pid {first.pid} on {socket.gethostname()}" in message, message
    assert first_answer == {"reused": 0, "status": [0] * 6}
    # Every sample was stored once, by the first writer: one part per chunk.
    assert len(sorted(lock.parent.glob("samples/part-*.parquet"))) == 6
    # A writer after the first has finished reads everything back and runs nothing.
    assert _answer(_writer(store)) == {"reused": 6, "status": [0] * 6}
    assert len(sorted(lock.parent.glob("samples/part-*.parquet"))) == 6
    (status,) = find_campaigns(store)
    assert (status.n_done, status.n_samples, status.damage) == (6, 6, None)


def test_the_lock_is_released_and_taken_again(tmp_path: Path) -> None:
    key = "ab" * 32
    with CampaignStore(tmp_path, key, 3):
        with pytest.raises(StoreBusyError, match=f"pid {os.getpid()}"):
            StoreLock(tmp_path / key[:16])
    with CampaignStore(tmp_path, key, 3):
        pass
    # A read-only store takes no lock.
    with CampaignStore(tmp_path, key, 3):
        CampaignStore(tmp_path, key, 3, writable=False).load()


def test_temporary_files_are_removed_only_when_their_writer_is_gone(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    host = socket.gethostname()
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True)  # fmt: skip
    dead_pid = int(dead.stdout)
    mine = tmp_path / f".part.parquet.{host}.{os.getpid()}.tmp"
    gone = tmp_path / f".part.parquet.{host}.{dead_pid}.tmp"
    other_host = tmp_path / f".part.parquet.elsewhere.{dead_pid}.tmp"
    for path in (mine, gone, other_host):
        path.write_bytes(b"partial")
    assert remove_stale_temporaries(tmp_path) == [gone]
    assert mine.exists() and other_host.exists() and not gone.exists()
    # A host name with dots (a domain) is read whole.
    monkeypatch.setattr(socket, "gethostname", lambda: "node1.cluster.example")
    dotted = tmp_path / f".part.parquet.node1.cluster.example.{dead_pid}.tmp"
    dotted.write_bytes(b"partial")
    assert remove_stale_temporaries(tmp_path) == [dotted]
    assert mine.exists() and other_host.exists()


def test_a_store_that_is_a_file_or_read_only_is_refused_before_any_work(tmp_path: Path) -> None:
    params = np.array([[1.0e5]])
    scenario = loco.Scenario(name="S_norm", distance=1.0, track="perfect")
    a_file = tmp_path / "file"
    a_file.write_text("x")
    for store, match in ((a_file, "is a file"), (a_file / "sub", "is under the file")):
        with pytest.raises(loco.ParameterError, match=f"`store`.*{match}"):
            loco.run_batch(params, ["C_sx"], scenario=scenario, store=store, progress=False)
    read_only = tmp_path / "ro"
    read_only.mkdir()
    read_only.chmod(0o500)
    try:
        # A user who can write anywhere (root) cannot create files in /proc either.
        place = read_only if not os.access(read_only, os.W_OK) else Path("/proc")
        with pytest.raises(loco.LocoIOError, match="the `store`"):
            loco.run_batch(params, ["C_sx"], scenario=scenario, store=place, progress=False)
    finally:
        read_only.chmod(0o700)


def test_threads_zero_means_every_core_with_a_store_too(tmp_path: Path) -> None:
    params = np.array([[1.0e5], [2.0e5]])
    scenario = loco.Scenario(name="S_norm", distance=20.0, track="perfect")
    plain = loco.run_batch(params, ["C_sx"], scenario=scenario, threads=0, progress=False)
    stored = loco.run_batch(
        params, ["C_sx"], scenario=scenario, threads=0, store=tmp_path, progress=False
    )
    np.testing.assert_array_equal(plain.metrics, stored.metrics)
