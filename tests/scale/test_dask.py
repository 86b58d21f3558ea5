"""The Dask executor on a real ``LocalCluster`` of 2 worker processes: metrics
bit-identical to local threads, NSGA-II generations through the cluster, a worker killed
mid-chunk, and the error naming the extra when ``distributed`` is missing. Short runs (300 m)."""

from __future__ import annotations

import os
import pickle
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

import loco
from loco import dampers, profiles
from loco.campaign import run_campaign
from loco.executors import DaskExecutor, executor_from_options, require_distributed
from loco.store import find_campaigns
from loco.studies.evaluators import simulator_evaluator
from loco.studies.parameters import names
from loco.studies.pareto import nsga2
from loco.studies.sampling import latin_hypercube

pytest.importorskip("distributed", reason="needs pip install 'loco[distributed]'")

# The FSD yaw damper makes the scenario carry a native object to the workers.
SCENARIO = loco.Scenario(name="S_low", distance=300.0, seed=2, yaw_damper=dampers.FSD)
# K_px far beyond any vehicle is a research value the vehicle file must allow explicitly.
VEHICLE = loco.Locomotive(
    toml_text='allow_out_of_range = ["rotary_arm.node_stiffness_longitudinal"]\n'
    + loco.Locomotive.default().default_toml(),
    origin="research.toml",
)


@pytest.fixture(scope="module")
def cluster() -> Iterator[DaskExecutor]:
    with DaskExecutor(n_workers=2) as executor:
        yield executor


@pytest.fixture(scope="module")
def design() -> np.ndarray:
    x = latin_hypercube(8, seed=9)
    x[3, 0] = 1e12  # K_px far beyond any vehicle: a sample that fails, with its message
    return x


@pytest.fixture(scope="module")
def local(design: np.ndarray) -> loco.BatchResult:
    return loco.run_batch(design, names(), VEHICLE, scenario=SCENARIO, threads=2, progress=False)


def _same(a: loco.BatchResult, b: loco.BatchResult) -> None:
    assert a.metric_names == b.metric_names
    assert a.metrics.tobytes() == b.metrics.tobytes()
    assert np.array_equal(a.status, b.status) and a.messages == b.messages


def test_native_objects_travel_exactly() -> None:
    for damper in (dampers.YD1, dampers.FSD, dampers.hydraulic(open_area_ratio=3.0)):
        assert dampers.describe(pickle.loads(pickle.dumps(damper))) == dampers.describe(damper)
    wheel = profiles.builtin("jm3-worn")
    copy = pickle.loads(pickle.dumps(wheel))
    y = np.linspace(wheel.y.min(), wheel.y.max(), 500)
    assert np.array_equal(copy.height(y), wheel.height(y))
    assert np.array_equal(copy.curvature(y), wheel.curvature(y))


def test_local_cluster_bit_identical_to_threads(
    cluster: DaskExecutor, design: np.ndarray, local: loco.BatchResult
) -> None:
    assert len(cluster.client.nthreads()) == 2
    assert local.status[3] != 0 and local.messages[3]
    for chunk_size in (None, 3):
        result = loco.run_batch(design, names(), VEHICLE, scenario=SCENARIO, executor=cluster,
                                chunk_size=chunk_size, progress=False)  # fmt: skip
        _same(result, local)
    # An input error on a worker comes back as the loco error, naming the design's row.
    bad = design.copy()
    bad[6, 1] = np.nan
    with pytest.raises(loco.ParameterError, match=r"row 6, column 1 'K_py'"):
        loco.run_batch(bad, names(), VEHICLE, scenario=SCENARIO, executor=cluster,
                       chunk_size=4, progress=False)  # fmt: skip
    # Its class too: a value outside the range is a `ParameterRangeError` on the driver, from
    # local threads and from the cluster alike (K_py is not allowed out of range in VEHICLE).
    bad[6, 1] = 1e30
    for executor in (None, cluster):
        with pytest.raises(loco.ParameterRangeError, match=r"row 6\b.*K_py|K_py.*row 6\b"):
            loco.run_batch(bad, names(), VEHICLE, scenario=SCENARIO, executor=executor,
                           chunk_size=4, progress=False)  # fmt: skip
    # Histories come back from the workers too.
    kept = loco.run_batch(design[:2], names(), scenario=SCENARIO, executor=cluster,
                          histories=[1], progress=False)  # fmt: skip
    alone = loco.run_batch(design[:2], names(), scenario=SCENARIO, histories=[1], progress=False)
    assert kept.histories[1].channels.tobytes() == alone.histories[1].channels.tobytes()


def test_nsga2_generations_through_the_cluster(cluster: DaskExecutor) -> None:
    def evaluator(executor: DaskExecutor | None) -> object:
        scenario = loco.Scenario(name="S_high", distance=300.0, seed=2)
        return simulator_evaluator(scenario, ["wy_max", "ayb_peak_lp"], threads=2,
                                   executor=executor, progress=False)  # fmt: skip

    runs = [nsga2(evaluator(e), ["W_y", "A_yb"], pop_size=6, n_gen=2, seed=4, progress=False)
            for e in (None, cluster)]  # fmt: skip
    assert runs[0].x.tobytes() == runs[1].x.tobytes()
    assert runs[0].f.tobytes() == runs[1].f.tobytes()


def test_worker_killed_mid_chunk(
    cluster: DaskExecutor, design: np.ndarray, local: loco.BatchResult, tmp_path: Path
) -> None:
    client = cluster.client
    pids = client.run(os.getpid)
    killed: list[int] = []

    def kill_when_busy() -> None:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            busy = [w for w, tasks in client.processing().items() if tasks]
            if busy:
                # At once: a chunk here takes a few tenths of a second (the workers keep the
                # contact they built for the module's earlier tests), and the worker holds it.
                os.kill(pids[busy[0]], signal.SIGKILL)
                killed.append(pids[busy[0]])
                return
            time.sleep(0.01)

    killer = threading.Thread(target=kill_when_busy)
    killer.start()
    result = run_campaign(design, names(), VEHICLE, scenario=SCENARIO, executor=cluster,
                          chunk_size=2, store=tmp_path, progress=False)  # fmt: skip
    killer.join()
    assert killed, "no worker was busy"
    _same(result, local)
    # The process is gone once its nanny has reaped it (until then it is a zombie).
    deadline = time.monotonic() + 60
    with pytest.raises(ProcessLookupError):
        while time.monotonic() < deadline:
            os.kill(killed[0], 0)
            time.sleep(0.05)
    client.wait_for_workers(2, timeout=120)  # the nanny restarted it


def test_missing_extra_is_named(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(ImportError, match=r"pip install 'loco\[distributed\]'"):
        require_distributed()
    with pytest.raises(ImportError, match="loco\\[distributed\\]"):
        executor_from_options(workers=2)
    monkeypatch.setenv("DASK_SCHEDULER_ADDRESS", "tcp://127.0.0.1:1")
    with pytest.raises(ImportError, match="loco\\[distributed\\]"):
        executor_from_options()


INTERRUPTED = """
import sys, numpy as np, loco
from loco.campaign import run_campaign
from loco.executors import DaskExecutor
from loco.studies.parameters import names
from loco.studies.sampling import latin_hypercube

if __name__ == "__main__":
    scenario = loco.Scenario(name="S_high", distance=300.0, seed=2)
    def stored(idx):
        print("stored", *idx.tolist(), flush=True)
    with DaskExecutor(n_workers=1) as dask:
        print("pids", *dask.client.run(__import__("os").getpid).values(), flush=True)
        run_campaign(latin_hypercube(12, seed=1), names(), scenario=scenario, executor=dask,
                     store=sys.argv[1], chunk_size=1, progress=False, on_chunk=stored)
    print("complete", flush=True)
"""


@pytest.mark.slow
def test_ctrl_c_cancels_the_futures(tmp_path: Path) -> None:
    """SIGINT to a campaign on a cluster: the client cancels its futures and closes the
    cluster it started, the process ends with KeyboardInterrupt, the finished chunks are
    stored."""
    script = tmp_path / "campaign.py"
    script.write_text(INTERRUPTED, encoding="utf-8")
    out = tmp_path / "out.txt"
    with open(out, "w", encoding="utf-8") as log:
        proc = subprocess.Popen([sys.executable, str(script), str(tmp_path / "store")],
                                stdout=log, stderr=subprocess.PIPE, text=True)  # fmt: skip
        deadline = time.monotonic() + 180
        while "stored" not in out.read_text() and time.monotonic() < deadline:
            assert proc.poll() is None, proc.stderr.read() if proc.stderr else ""
            time.sleep(0.05)
        proc.send_signal(signal.SIGINT)
        _, stderr = proc.communicate(timeout=120)
    text = out.read_text()
    assert "complete" not in text and "KeyboardInterrupt" in stderr
    assert proc.returncode != 0
    worker = int(next(line for line in text.splitlines() if line.startswith("pids")).split()[1])
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:  # the worker process ends with its cluster
        try:
            os.kill(worker, 0)
        except ProcessLookupError:
            break
        time.sleep(0.1)
    else:
        pytest.fail("the worker process outlived its cluster")
    reported = {int(i) for line in text.splitlines() if line.startswith("stored")
                for i in line.split()[1:]}  # fmt: skip
    (campaign,) = find_campaigns(tmp_path / "store")
    assert campaign.n_done >= len(reported) > 0 and campaign.n_done < 12
