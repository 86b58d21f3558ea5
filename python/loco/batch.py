"""Batches: many simulations of the locomotive in parallel (Rust threads, GIL released).

>>> import numpy as np, loco
>>> params = np.array([[2e5, 3.5e6], [8e5, 3.5e6]])          # C_sx (N·s/m), K_py (N/m)
>>> result = loco.run_batch(params, ["C_sx", "K_py"],
...                         scenario=loco.Scenario(name="S_high"))  # doctest: +SKIP
>>> result.to_frame()[["C_sx", "wy_max", "ayb_peak_lp", "status"]]  # doctest: +SKIP

Every sample runs on the same synthesised track (common random numbers: differences between
samples come from the parameters, not from the track) unless ``per_sample_track`` is set, in
which case sample ``i`` gets the track of ChaCha stream ``i`` of the seed. Either way the numbers
are bit-identical for any thread count.

With ``executor`` (local threads or a Dask cluster, :mod:`loco.executors`) or ``store`` (a
directory keeping every finished sample, :mod:`loco.store`), or inside
``loco.campaign.using(...)``, the batch runs as a campaign (:func:`loco.campaign.run_campaign`):
in chunks, only the samples not stored yet, with the same numbers.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from loco import _loco, field_types
from loco.channels import channel_kinds_of
from loco.simulation import RUN_STATISTICS, Scenario, SimulationResult
from loco.vehicle import Locomotive

if TYPE_CHECKING:
    import pandas as pd

    from loco.executors import Executor

__all__ = ["SPEED", "STATUS_NAMES", "BatchResult", "history_results", "run_batch"]

FloatArray = npt.NDArray[np.float64]

#: Status names by code: 0 ``ok``, 1 ``invalid_parameter``, 2 ``diverged``, 3 ``derailed``,
#: 4 ``contact``, 5 ``internal_error``, 6 ``interrupted``.
STATUS_NAMES: list[str] = _loco.batch_status_names()

#: Column name that sets each sample's running speed (m/s).
SPEED = "speed"


@dataclass(frozen=True)
class BatchResult:
    """Metrics and status of every sample of a batch, in row order.

    ``metrics`` is (n, m) with columns ``metric_names`` (the names of
    :attr:`loco.SimulationResult.metrics`), NaN where the sample failed; ``status`` is (n,) with
    codes of :data:`STATUS_NAMES` (0 ok); ``messages`` says why a sample failed ('' if it did
    not); ``histories`` holds the time histories of the samples asked for.
    """

    params: FloatArray
    names: list[str]
    metric_names: list[str]
    metrics: FloatArray
    status: npt.NDArray[np.int32]
    messages: list[str]
    histories: dict[int, SimulationResult] = field(default_factory=dict)
    seconds: float = 0.0
    threads: int = 0
    #: Samples read back from a campaign's store instead of run.
    n_reused: int = 0
    #: (n, 4) run statistics, columns :data:`loco.simulation.RUN_STATISTICS`; None if not given.
    statistics: FloatArray | None = None

    def __repr__(self) -> str:
        failed = self.failures()
        how = f" {failed}" if failed else ""
        return (
            f"BatchResult({len(self.params)} samples of {self.names}, "
            f"{self.n_failed} failed{how}, {self.seconds:.1f} s)"
        )

    @property
    def n_failed(self) -> int:
        """Number of samples that did not finish."""
        return int(np.count_nonzero(self.status))

    def failures(self) -> dict[str, int]:
        """How many samples failed in each way, by status name."""
        codes, counts = np.unique(self.status[self.status != 0], return_counts=True)
        return {STATUS_NAMES[int(c)]: int(n) for c, n in zip(codes, counts, strict=True)}

    def metric(self, name: str) -> FloatArray:
        """The column of metric ``name`` (n,)."""
        try:
            return self.metrics[:, self.metric_names.index(name)]
        except ValueError:
            raise _loco.ParameterError(
                f"invalid parameter `name`: no metric '{name}'; available: {self.metric_names}"
            ) from None

    def to_frame(self) -> pd.DataFrame:
        """One row per sample: parameters, metrics, run statistics, ``status`` (name) and
        ``message``."""
        import pandas as pd

        frame = pd.DataFrame(self.params, columns=self.names)
        for j, name in enumerate(self.metric_names):
            frame[name] = self.metrics[:, j]
        if self.statistics is not None:
            for j, name in enumerate(RUN_STATISTICS):
                frame[name] = self.statistics[:, j]
        frame["status"] = [STATUS_NAMES[int(c)] for c in self.status]
        frame["message"] = self.messages
        return frame


def run_batch(
    params: npt.ArrayLike,
    names: Sequence[str],
    vehicle: Locomotive | None = None,
    scenario: Scenario | None = None,
    threads: int | None = None,
    seed: int | None = None,
    progress: bool = True,
    *,
    histories: Sequence[int] = (),
    per_sample_track: bool = False,
    executor: Executor | None = None,
    store: str | Path | None = None,
    chunk_size: int | None = None,
) -> BatchResult:
    """Simulate one run per row of ``params`` in parallel.

    Parameters
    ----------
    params : (n, k) array
        Values in SI units; column ``j`` sets ``names[j]``.
    names : sequence of str
        Vehicle parameter keys (``section.name``), the study names ``K_px``, ``K_py``,
        ``C_sx``, ``C_sy``, ``K_ncsx``, ``K_ncsy``, or ``"speed"`` (m/s, overrides the
        scenario's speed per sample).
    vehicle : Locomotive, optional
        The base vehicle (default: the embedded one).
    scenario : Scenario, optional
        Wheel and rail, speed, distance, track, yaw damper
        (default: ``Scenario(name="S_high")``).
    threads : int, optional
        Worker threads (default or 0: one per core, as ``loco-batch --threads 0``, with or
        without ``store``). Results do not depend on it.
    seed : int, optional
        Track seed (default: the scenario's).
    progress : bool
        Show a progress bar (samples done, failures, rate).
    histories : sequence of int
        Samples whose time histories are kept (``result.histories[i]``).
    per_sample_track : bool
        Give every sample its own synthesised track (stream ``i`` of the seed). Not with an
        executor or a store (a chunk would number its streams from 0).
    executor : loco.executors.Executor, optional
        Where the chunks run (local threads, a Dask cluster); see :mod:`loco.campaign`. An
        executor object (``LocalExecutor(threads)``, ``DaskExecutor(address=...)``,
        ``DaskExecutor(n_workers=...)`` for a local cluster), not a name: ``"dask"`` is refused.
    store : path, optional
        Directory of campaign stores: finished samples are kept there and not run again. A
        path that is a file or cannot be written is refused before any work; a second process
        writing the same campaign fails at once naming the first
        (:class:`loco.store_lock.StoreBusyError`).
    chunk_size : int, optional
        Samples per chunk of a campaign, a whole number >= 1 (default: the executor's choice).

    Raises
    ------
    loco.ParameterError
        Wrong shape, unknown name, NaN or a non-physical value; the message names the row and
        column. ``params`` must hold real numbers (strings, complex numbers, bools and objects
        are refused, not converted); ``names`` must be a sequence of names, not one string.
        Failures while running do not raise: they are flagged in ``status``.
    KeyboardInterrupt
        Ctrl-C: the batch stops within a few integration steps.
    """
    from loco import campaign

    names = field_types.names("names", names)
    threads = None if threads is None else field_types.whole("threads", threads, high=1024)
    if chunk_size is not None:
        chunk_size = field_types.whole("chunk_size", chunk_size, low=1)
    params = field_types.real_array("params", params)
    if executor is not None or store is not None or campaign.current() is not None:
        return campaign.run_campaign(
            params,
            names,
            vehicle,
            scenario,
            seed=seed,
            executor=executor,
            store=store,
            chunk_size=chunk_size,
            threads=threads,
            progress=progress,
            histories=histories,
            per_sample_track=per_sample_track,
        )
    vehicle = vehicle or Locomotive.default()
    scenario = scenario or Scenario(name="S_high")
    x = params
    if x.ndim != 2:
        raise _loco.ParameterError(
            f"invalid input `params`: must be a 2-D (samples x parameters) array, got shape "
            f"{x.shape}"
        )
    keep = [int(i) for i in histories]
    if any(i < 0 for i in keep):
        raise _loco.ParameterError(f"invalid input `histories`: negative index in {keep}")
    bar = _ProgressBar(len(x)) if progress else None
    start = time.perf_counter()
    try:
        metric_names, metrics, status, messages, kept, statistics = _loco.run_batch(
            vehicle.native,
            scenario.native(seed=seed),
            np.ascontiguousarray(x),
            [str(n) for n in names],
            threads=threads or 0,
            per_sample_track=per_sample_track,
            histories=keep,
            progress=bar.update if bar else None,
        )
    finally:
        if bar:
            bar.close()
    seconds = time.perf_counter() - start
    kept_results = history_results(
        kept, metric_names, metrics, names, x, scenario, channel_kinds_of(vehicle.native)
    )
    return BatchResult(
        params=x,
        names=list(names),
        metric_names=list(metric_names),
        metrics=metrics,
        status=status,
        messages=list(messages),
        histories=kept_results,
        seconds=seconds,
        threads=threads or 0,
        statistics=statistics,
    )


def history_results(
    kept: Sequence[tuple[int, FloatArray, Sequence[str], FloatArray]],
    metric_names: Sequence[str],
    metrics: FloatArray,
    names: Sequence[str],
    x: FloatArray,
    scenario: Scenario,
    channel_kinds: dict[str, str] | None = None,
) -> dict[int, SimulationResult]:
    """The kept time histories ``(sample, time, channel names, channels)`` as results;
    ``channel_kinds`` gives each channel's kind (the samples share the vehicle's structure)."""
    named: dict[str, Any] = dict(zip(metric_names, range(len(metric_names)), strict=True))
    return {
        i: SimulationResult(
            time=t,
            channel_names=list(channel_names),
            channels=channels,
            metrics={k: float(metrics[i, j]) for k, j in named.items()},
            sampling_rate=float(scenario.output_rate),
            parameters={n: float(v) for n, v in zip(names, x[i], strict=True)},
            channel_kinds=dict(channel_kinds or {}),
        )
        for i, t, channel_names, channels in kept
    }


class _ProgressBar:
    """A tqdm bar fed with (done, failed) counts by the native batch."""

    def __init__(self, total: int) -> None:
        from tqdm.auto import tqdm

        self._bar = tqdm(total=total, desc="simulations", unit="run", smoothing=0.1)
        self._done = 0

    def update(self, done: int, failed: int) -> None:
        if done > self._done:
            self._bar.update(done - self._done)
            self._done = done
        if failed:
            self._bar.set_postfix(failed=failed, refresh=False)

    def close(self) -> None:
        self._bar.close()
