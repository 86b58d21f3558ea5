"""A chunk of a campaign and how it runs: a :class:`BatchJob` (what every chunk shares: vehicle,
scenario, track seed, column names), a :class:`Chunk` (its samples' rows) and
:func:`run_chunk`, one native batch on rayon threads giving a :class:`ChunkResult`. Every
executor (:mod:`loco.executors`) runs chunks through :func:`run_chunk`, so a sample's metrics are
the same bits whichever executor ran it.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco.simulation import Scenario
from loco.vehicle import Locomotive

__all__ = ["BatchJob", "Chunk", "ChunkProgress", "ChunkResult", "Histories", "run_chunk"]

FloatArray = npt.NDArray[np.float64]
#: Kept time histories of a chunk: sample index -> (time (s), channel names, channels).
Histories = dict[int, tuple[FloatArray, list[str], FloatArray]]
#: ``progress(done, failed)`` within the running chunk (local executor only).
ChunkProgress = Callable[[int, int], object]


@dataclass(frozen=True)
class BatchJob:
    """What every chunk of a campaign shares: the vehicle, the scenario (and so its track), the
    track seed and the column names. Sent once per worker."""

    vehicle: Locomotive
    scenario: Scenario
    names: tuple[str, ...]
    seed: int | None = None
    #: A track per sample: stream = the sample's index in the campaign's design.
    per_sample_track: bool = False


@dataclass(frozen=True)
class Chunk:
    """Samples ``indices`` (positions in the campaign's design) with their ``rows`` (SI);
    ``histories``: the indices whose time histories come back."""

    indices: npt.NDArray[np.int64]
    rows: FloatArray
    histories: tuple[int, ...] = ()


@dataclass(frozen=True)
class ChunkResult:
    """The outcome of a chunk, rows in the order of ``indices``."""

    indices: npt.NDArray[np.int64]
    metric_names: list[str]
    metrics: FloatArray
    status: npt.NDArray[np.int32]
    messages: list[str]
    histories: Histories
    #: (rows, 4) run statistics, columns :data:`loco.simulation.RUN_STATISTICS`.
    statistics: FloatArray


def run_chunk(
    job: BatchJob, chunk: Chunk, threads: int = 0, progress: ChunkProgress | None = None
) -> ChunkResult:
    """Run one chunk as one native batch on ``threads`` rayon threads (0: one per core)."""
    local = {int(i): k for k, i in enumerate(chunk.indices)}
    keep = sorted(local[i] for i in chunk.histories if i in local)
    try:
        metric_names, metrics, status, messages, kept, statistics = _loco.run_batch(
            job.vehicle.native,
            job.scenario.native(seed=job.seed),
            np.ascontiguousarray(chunk.rows, dtype=np.float64),
            list(job.names),
            threads=threads,
            per_sample_track=job.per_sample_track,
            track_streams=[int(i) for i in chunk.indices] if job.per_sample_track else None,
            histories=keep,
            progress=progress,
        )
    except _loco.ParameterError as e:
        # The native message numbers rows within the chunk; name the campaign's row instead,
        # keeping the class (a `ParameterRangeError` stays one on the driver).
        text = re.sub(r"\brow (\d+)", lambda m: f"row {chunk.indices[int(m[1])]}", str(e))
        raise type(e)(text) from None
    return ChunkResult(
        indices=chunk.indices,
        metric_names=list(metric_names),
        metrics=metrics,
        status=status,
        messages=list(messages),
        histories={int(chunk.indices[k]): (t, list(c), ch) for k, t, c, ch in kept},
        statistics=statistics,
    )
