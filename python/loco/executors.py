"""Where the chunks of a campaign run: local rayon threads, or a Dask ``distributed`` cluster.

A campaign (:func:`loco.campaign.run_campaign`) cuts its samples into chunks; each chunk is one
native batch (``loco.run_batch`` without the Python layers: rayon threads inside) and comes back
as a :class:`ChunkResult`. An executor runs chunks and yields their results as they complete:

- :class:`LocalExecutor` (the default): the chunks one after the other on this machine's cores.
- :class:`DaskExecutor`: a ``distributed.Client`` — a ``LocalCluster`` of worker processes
  started on request, or a running scheduler by address (``tcp://host:8786``, or the
  ``DASK_SCHEDULER_ADDRESS`` convention). The :class:`BatchJob` (vehicle, scenario, track seed,
  column names) is scattered to every worker once (``broadcast``), then each chunk is a task
  holding only its rows. A worker that dies mid-chunk has its chunk resubmitted by the scheduler
  (and a task that raises is retried ``retries`` times); Ctrl-C cancels the futures.

Every sample is a function of (vehicle, scenario, seed, its row) alone, so the metrics are
bit-identical whatever the executor, the chunking, the number of workers and their threads.
Dask is optional: ``pip install 'loco[distributed]'``.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import multiprocessing
import os
from abc import ABC, abstractmethod
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from loco import _loco
from loco.chunks import BatchJob, Chunk, ChunkProgress, ChunkResult, run_chunk
from loco.field_types import whole
from loco.scheduler import (
    CONNECT_TIMEOUT,
    SCHEDULER_ENV,
    check_scheduler_address,
    connect,
    require_distributed,
)
from loco.track import Track

__all__ = [
    "CONNECT_TIMEOUT",
    "SCHEDULER_ENV",
    "BatchJob",
    "Chunk",
    "ChunkResult",
    "DaskExecutor",
    "Executor",
    "LocalExecutor",
    "check_scheduler_address",
    "executor_from_options",
    "require_distributed",
    "run_chunk",
    "task_pool",
]


class Executor(ABC):
    """Runs chunks of a campaign and yields their results as they complete (any order)."""

    #: Chunks that run at once; a campaign cuts its samples into several chunks per slot.
    slots: int = 1

    @abstractmethod
    def map_chunks(
        self, job: BatchJob, chunks: Sequence[Chunk], progress: ChunkProgress | None = None
    ) -> Iterator[ChunkResult]:
        """Results of ``chunks``; stopping the iteration (or Ctrl-C) cancels what is left."""

    def default_chunk_size(self, n_samples: int) -> int:
        """Samples per chunk: about four chunks per slot, between 1 and 32 samples; each
        finished chunk is stored at once, so a kill loses at most the chunks running."""
        return int(np.clip(-(-n_samples // (4 * self.slots)), 1, 32))

    def describe(self) -> str:
        """One line for logs."""
        return type(self).__name__

    def close(self) -> None:  # noqa: B027 (nothing to release by default)
        """Release the cluster this executor started (nothing for local threads)."""

    def __enter__(self) -> Executor:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class LocalExecutor(Executor):
    """The chunks one after another on this machine, ``threads`` rayon threads each (default:
    one per core), as ``loco.run_batch`` runs a batch."""

    def __init__(self, threads: int | None = None) -> None:
        # 0 is one thread per core, as in `loco.run_batch` and `loco-batch --threads 0`.
        threads = None if threads is None else whole("threads", threads, high=1024)
        self.threads = threads or None
        self.slots = threads or os.cpu_count() or 1

    def default_chunk_size(self, n_samples: int) -> int:
        # Chunks run one at a time here: a few samples per thread keeps the idle tail of each
        # chunk's last samples small while a kill still loses only one chunk.
        return int(np.clip(-(-n_samples // 8), 4 * self.slots, 16 * self.slots))

    def map_chunks(
        self, job: BatchJob, chunks: Sequence[Chunk], progress: ChunkProgress | None = None
    ) -> Iterator[ChunkResult]:
        for chunk in chunks:
            yield run_chunk(job, chunk, self.threads or 0, progress)

    def describe(self) -> str:
        return f"local threads ({self.slots})"


@dataclass(frozen=True)
class _ChunkError:
    """A loco error raised on a worker, by class name: the native exception classes do not
    pickle (their module is ``_loco``), and an input error is not worth Dask's retries."""

    kind: str
    message: str


def _run_chunk_on_worker(job: BatchJob, chunk: Chunk, threads: int) -> ChunkResult | _ChunkError:
    try:
        return run_chunk(job, chunk, threads)
    except _loco.LocoError as e:
        return _ChunkError(type(e).__name__, str(e))


def _worker_build() -> tuple[str, str]:
    from loco.campaign import build_hash

    return _loco.__version__, build_hash()


class DaskExecutor(Executor):
    """Chunks as tasks of a Dask cluster.

    Parameters
    ----------
    client : distributed.Client, optional
        A client to use (not closed by :meth:`close`).
    address : str, optional
        A running scheduler, e.g. ``tcp://host:8786``.
    n_workers : int, optional
        Start a ``LocalCluster`` of this many worker processes (one task at a time each).
    threads : int, optional
        Rayon threads per chunk. Default: this machine's cores shared among the local workers;
        on a remote cluster 1, the worker's Dask threads being its parallelism (start workers
        with ``--nthreads`` = cores).
    retries : int
        Times a chunk whose task raised is resubmitted (a dead worker's chunks are resubmitted
        by the scheduler anyway, up to its ``allowed-failures``).
    """

    def __init__(
        self,
        client: Any = None,
        *,
        address: str | None = None,
        n_workers: int | None = None,
        threads: int | None = None,
        retries: int = 3,
    ) -> None:
        distributed = require_distributed()
        if sum(x is not None for x in (client, address, n_workers)) != 1:
            raise _loco.ParameterError(
                "invalid parameter `executor`: give exactly one of a client, a scheduler "
                "address or a number of local workers"
            )
        if n_workers is not None and n_workers < 1:
            raise _loco.ParameterError(
                f"invalid parameter `workers`: must be >= 1, got {n_workers}"
            )
        if threads is not None and threads < 1:
            raise _loco.ParameterError(f"invalid parameter `threads`: must be >= 1, got {threads}")
        self._owned: list[Any] = []
        if client is None and address is not None:
            client = connect(distributed, address)
            self._owned.append(client)
        elif client is None:
            cluster = distributed.LocalCluster(
                n_workers=n_workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=":0",  # any free port: several clusters may run
            )
            client = distributed.Client(cluster)
            self._owned += [client, cluster]
            threads = threads or max(1, (os.cpu_count() or 1) // int(n_workers or 1))
        self.client = client
        self.threads = threads or 1
        self.retries = retries
        self.slots = max(1, sum(self.client.nthreads().values()))
        self._distributed = distributed

    def map_chunks(
        self, job: BatchJob, chunks: Sequence[Chunk], progress: ChunkProgress | None = None
    ) -> Iterator[ChunkResult]:
        if not chunks:
            return
        if isinstance(job.scenario.track, Track):
            raise _loco.ParameterError(
                "invalid parameter `scenario.track`: a loaded track cannot be sent to Dask "
                "workers; run it with local threads"
            )
        self._check_builds()
        # One copy of the job per worker, not per task.
        shared = self.client.scatter(job, broadcast=True, hash=False)
        futures = [
            self.client.submit(
                _run_chunk_on_worker, shared, chunk, self.threads, retries=self.retries, pure=False
            )
            for chunk in chunks
        ]
        try:
            for future in self._distributed.as_completed(futures):
                result = future.result()
                if isinstance(result, _ChunkError):
                    raise getattr(_loco, result.kind, _loco.LocoError)(result.message)
                yield result
        finally:
            # Reached on completion, on an error, on Ctrl-C and when the caller stops early.
            self.client.cancel([f for f in futures if not f.done()])
            self.client.cancel(shared)

    def _check_builds(self) -> None:
        """Refuse workers running another loco build: their numbers would be stored under this
        build's campaign key."""
        from loco.campaign import build_hash

        mine = (_loco.__version__, build_hash())
        for worker, theirs in self.client.run(_worker_build).items():
            if tuple(theirs) != mine:
                raise _loco.LocoError(
                    f"Dask worker {worker} runs loco {theirs[0]} (build {theirs[1][:12]}), this "
                    f"process loco {mine[0]} (build {mine[1][:12]}): install the same build"
                )

    def describe(self) -> str:
        workers = self.client.nthreads()
        return (
            f"Dask at {self.client.scheduler.address}: {len(workers)} workers, "
            f"{self.slots} slots, {self.threads} rayon thread(s) per chunk"
        )

    def close(self) -> None:
        for owned in self._owned:
            owned.close()
        self._owned.clear()


@contextlib.contextmanager
def task_pool(executor: Executor | None = None) -> Iterator[concurrent.futures.Executor]:
    """A :class:`concurrent.futures.Executor` for independent tasks that are not simulations
    (eigen analyses, screening trajectories) on the resources of ``executor``: the Dask cluster's
    workers for a :class:`DaskExecutor` (``client.get_executor()``), else a pool of worker
    processes, one per slot of ``executor`` (default: per core). The pool's processes are spawned,
    not forked: a fork of a process whose native thread pool is running can hang. Tasks and their
    arguments must pickle (vehicles, scenarios, dampers and profiles do); ``map`` keeps their
    order, so a result does not depend on where each task ran."""
    if isinstance(executor, DaskExecutor):
        yield executor.client.get_executor(pure=False)
        return
    slots = executor.slots if isinstance(executor, LocalExecutor) else os.cpu_count() or 1
    context = multiprocessing.get_context("spawn")
    pool = concurrent.futures.ProcessPoolExecutor(max_workers=slots, mp_context=context)
    try:
        yield pool
    except BaseException:
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    pool.shutdown()


def executor_from_options(
    *, workers: int | None = None, scheduler: str | None = None, threads: int | None = None
) -> Executor:
    """The executor the command-line options ask for: a ``LocalCluster`` of ``workers``
    processes, the scheduler at ``scheduler`` (or ``$DASK_SCHEDULER_ADDRESS`` when neither is
    given), else local threads."""
    if workers is not None and scheduler is not None:
        raise _loco.ParameterError(
            "invalid parameter `workers`: give --workers or --scheduler, not both"
        )
    if scheduler is not None:
        check_scheduler_address(scheduler, "--scheduler")
    elif workers is None and os.environ.get(SCHEDULER_ENV):
        scheduler = check_scheduler_address(os.environ[SCHEDULER_ENV], SCHEDULER_ENV)
    if scheduler:
        return DaskExecutor(address=scheduler, threads=threads)
    if workers is not None:
        return DaskExecutor(n_workers=workers, threads=threads)
    return LocalExecutor(threads)
