"""Campaigns: a batch cut into chunks, run by an executor, every finished chunk kept on disk.

>>> import loco, loco.campaign
>>> from loco.executors import DaskExecutor
>>> with DaskExecutor(n_workers=2) as dask:                      # doctest: +SKIP
...     result = loco.campaign.run_campaign(params, names, scenario=s,
...                                         executor=dask, store="runs/")

:func:`run_campaign` keys the campaign by its inputs (:func:`campaign_inputs`: the vehicle, the
scenario, the design, the seed and the software build), loads what its store
(:class:`loco.store.CampaignStore`) already holds, runs only the missing samples, in chunks, and
appends each finished chunk to the store as it completes. A rerun after ``kill -9`` therefore
recomputes only the chunks that were running. The result is a :class:`loco.BatchResult` in the
design's row order, bit-identical to one ``loco.run_batch`` of the whole design.

``loco.run_batch(..., executor=..., store=...)`` is a campaign; so is every ``loco.run_batch``
inside ``with using(executor=..., store=...)``, which is how ``loco reproduce`` sends every
batch of its stages (Monte Carlo, Saltelli design, NSGA-II re-simulation, speed sweep) to one
executor and one store per stage without each study taking the arguments.
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import time
from collections.abc import Callable, Iterator, Sequence
from contextvars import ContextVar
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd

from loco import _loco, field_types
from loco.batch import STATUS_NAMES, BatchResult, history_results
from loco.channels import channel_kinds_of
from loco.executors import BatchJob, Chunk, Executor, LocalExecutor
from loco.simulation import RUN_STATISTICS, SETTINGS, Scenario
from loco.store import CAMPAIGN_FILE, CampaignStore, campaign_key, describe_damage, file_sha256
from loco.store_lock import check_store_root
from loco.vehicle import Locomotive

__all__ = ["CampaignContext", "campaign_inputs", "current", "run_campaign", "using"]

FloatArray = npt.NDArray[np.float64]
#: Code of a sample that was not run because its batch was cancelled: never stored.
INTERRUPTED = STATUS_NAMES.index("interrupted")
#: Columns of a stored sample besides its parameters and metrics.
META_COLUMNS = (
    "sample", "seed", "status", "status_code", "message",
    "loco_version", "build", "vehicle_hash", "scenario_hash", "campaign",
)  # fmt: skip


@dataclass
class SampleCount:
    """Samples of the campaigns of a :func:`using` block: read back from the store, and run."""

    reused: int = 0
    ran: int = 0


@dataclass(frozen=True)
class CampaignContext:
    """Defaults for every ``loco.run_batch`` inside :func:`using`, and the count of its
    samples (``samples``: from the store and run, over every campaign of the block)."""

    executor: Executor | None = None
    store: Path | None = None
    chunk_size: int | None = None
    samples: SampleCount = field(default_factory=SampleCount)


_CONTEXT: ContextVar[CampaignContext | None] = ContextVar("loco_campaign", default=None)


@contextlib.contextmanager
def using(
    executor: Executor | None = None,
    store: str | Path | None = None,
    *,
    chunk_size: int | None = None,
) -> Iterator[CampaignContext]:
    """Run every ``loco.run_batch`` in the block as a campaign on ``executor`` (default local
    threads) with its samples kept under ``store`` (default: not kept)."""
    executor, chunk_size = _checked(executor, chunk_size)
    context = CampaignContext(executor, None if store is None else Path(store), chunk_size)
    token = _CONTEXT.set(context)
    try:
        yield context
    finally:
        _CONTEXT.reset(token)


def _checked(executor: Any, chunk_size: Any) -> tuple[Executor | None, int | None]:
    """``executor`` (an :class:`Executor` or None; a name such as ``"dask"`` is refused with
    the accepted values) and ``chunk_size`` (None or a whole number >= 1), checked."""
    if executor is not None and not isinstance(executor, Executor):
        raise field_types.wrong_type(
            "executor",
            "a loco.executors.Executor (LocalExecutor(threads), DaskExecutor(address=...) or "
            "DaskExecutor(n_workers=...)); None runs on local threads",
            executor,
        )
    if chunk_size is not None:
        chunk_size = field_types.whole("chunk_size", chunk_size, low=1)
    return executor, chunk_size


def current() -> CampaignContext | None:
    """The innermost :func:`using` block's settings, None outside one."""
    return _CONTEXT.get()


@functools.cache
def build_hash() -> str:
    """SHA-256 of the native module's file: results of another build are never reused."""
    return file_sha256(_loco.__file__)


def _array_sha(*arrays: Any) -> str:
    digest = hashlib.sha256()
    for a in arrays:
        a = np.ascontiguousarray(a)
        digest.update(f"{a.dtype.str}{a.shape}".encode())
        digest.update(a.tobytes())
    return digest.hexdigest()


def _describe(value: Any) -> Any:
    """A JSON-ready, exact description of a scenario field (native objects by content)."""
    if isinstance(value, _loco.Profile):
        return {"profile": value.name, "kind": value.kind, "points": _array_sha(value.y, value.z)}
    if isinstance(value, _loco.Damper):
        return {"damper": value.kind, **value.parameters()}
    if hasattr(value, "native") and isinstance(value.native, _loco.Track):
        t = value.native
        return {"track": _array_sha(t.distance(), *(t.rail(n) for n in _RAILS)), "step": t.step}
    if isinstance(value, (tuple, list)):
        return [_describe(v) for v in value]
    if isinstance(value, float):
        return repr(value)  # exact
    return value


_RAILS = ("y_left", "z_left", "y_right", "z_right")


def campaign_inputs(
    x: FloatArray,
    names: Sequence[str],
    vehicle: Locomotive,
    scenario: Scenario,
    seed: int,
    per_sample_track: bool = False,
) -> dict[str, Any]:
    """Everything a campaign's numbers depend on, as JSON: its key is the hash of this."""
    # The resolved parameters (after overrides): a vehicle file's comments, sources and units
    # do not change the key, a value does.
    vehicle_desc = {"parameters_sha256": vehicle.parameters_sha256()}
    # Every setting, given or default: a default the core changes changes the key.
    scenario_desc = {name: _describe(getattr(scenario, name)) for name in SETTINGS}
    return {
        "kind": "loco.run_batch",
        "names": list(names),
        "n_samples": len(x),
        "design_sha256": _array_sha(x),
        "seed": int(seed),
        # Absent when false, so stores written before the option existed keep their keys.
        **({"per_sample_track": True} if per_sample_track else {}),
        "vehicle": vehicle_desc,
        "vehicle_hash": campaign_key(vehicle_desc),
        "scenario": scenario_desc,
        "scenario_hash": campaign_key(scenario_desc),
        "loco_version": _loco.__version__,
        "build": build_hash(),
    }


def _chunks(todo: npt.NDArray[np.int64], x: FloatArray, size: int, keep: set[int]) -> list[Chunk]:
    return [
        Chunk(
            indices=part,
            rows=x[part],
            histories=tuple(int(i) for i in part if int(i) in keep),
        )
        for part in (todo[i : i + size] for i in range(0, len(todo), size))
    ]


def run_campaign(
    params: npt.ArrayLike,
    names: Sequence[str],
    vehicle: Locomotive | None = None,
    scenario: Scenario | None = None,
    *,
    seed: int | None = None,
    executor: Executor | None = None,
    store: str | Path | None = None,
    chunk_size: int | None = None,
    threads: int | None = None,
    progress: bool = True,
    histories: Sequence[int] = (),
    per_sample_track: bool = False,
    on_chunk: Callable[[npt.NDArray[np.int64]], object] | None = None,
) -> BatchResult:
    """Run the design ``params`` (n, k; columns ``names``) as a campaign.

    Arguments as for ``loco.run_batch``, plus: ``executor`` (default: the :func:`using` block's,
    else local threads on ``threads``), ``store`` (a directory holding campaign stores; default:
    the :func:`using` block's, else none: nothing kept), ``chunk_size`` (samples per chunk;
    default: the executor's choice). Samples already in the store are read back, not run (the
    result's ``n_reused`` counts them); samples whose ``histories`` are asked for always run.
    With ``per_sample_track`` sample ``i`` of the design gets track stream ``i`` whatever chunk
    runs it, as in one ``loco.run_batch``.
    ``on_chunk(indices)`` is called after each chunk is finished and stored.
    Ctrl-C cancels the running chunks; every chunk finished before stays in the store.
    """
    context = current() or CampaignContext()
    vehicle = vehicle or Locomotive.default()
    scenario = scenario or Scenario(name="S_high")
    names = field_types.names("names", names)
    x = field_types.real_array("params", params)
    executor, chunk_size = _checked(executor, chunk_size)
    threads = None if threads is None else field_types.whole("threads", threads, high=1024)
    if x.ndim != 2 or x.shape[1] != len(names):
        raise _loco.ParameterError(
            f"invalid input `params`: must be a 2-D (samples x {len(names)} parameters) array, "
            f"got shape {x.shape}"
        )
    clash = set(names) & {*META_COLUMNS, *_loco.run_metric_names()}
    if clash:
        raise _loco.ParameterError(f"invalid input `names`: {sorted(clash)} are reserved")
    keep = {int(i) for i in histories}
    if any(i < 0 or i >= len(x) for i in keep):
        raise _loco.ParameterError(f"invalid input `histories`: index out of range in {keep}")
    store = store if store is not None else context.store
    if store is not None:
        store = check_store_root(store)  # a file or read-only place fails before any work
    executor = executor or context.executor or LocalExecutor(threads)
    n = len(x)
    track_seed = int(scenario.seed if seed is None else seed)
    scenario.native(seed=seed)  # a bad scenario fails here, before any chunk is sent
    inputs = campaign_inputs(x, names, vehicle, scenario, track_seed, per_sample_track)
    key = campaign_key(inputs)
    metric_names = list(_loco.run_metric_names())
    metrics = np.full((n, len(metric_names)), np.nan)
    status = np.full(n, INTERRUPTED, dtype=np.int32)
    messages = [""] * n
    done = np.zeros(n, dtype=bool)
    sink = None
    if store is not None:
        sink = CampaignStore(store, key, n, meta={"inputs": inputs, "created": time.ctime()})
        try:
            stored = sink.load().frame
        except BaseException:
            sink.close()
            raise
        if len(stored):
            rows = stored["sample"].to_numpy(dtype=np.int64)
            metrics[rows] = stored[metric_names].to_numpy(dtype=np.float64)
            status[rows] = stored["status_code"].to_numpy(dtype=np.int32)
            for i, m in zip(rows, stored["message"], strict=True):
                messages[int(i)] = str(m)
            done[rows] = True
    n_reused = int(done.sum())
    context.samples.reused += n_reused
    todo = np.flatnonzero(~done | np.isin(np.arange(n), sorted(keep))).astype(np.int64)
    size = chunk_size or context.chunk_size or executor.default_chunk_size(len(todo))
    chunks = _chunks(todo, x, int(size), keep)
    job = BatchJob(
        vehicle=vehicle,
        scenario=scenario,
        names=tuple(names),
        seed=seed,
        per_sample_track=per_sample_track,
    )
    kept: dict[int, Any] = {}
    # Samples read back from the store did not run here: their statistics stay NaN.
    statistics = np.full((n, len(RUN_STATISTICS)), np.nan)
    start = time.perf_counter()
    bar = None
    try:
        bar = _Bar(n, n_reused, int((status[done] != 0).sum())) if progress else None
        for result in executor.map_chunks(job, chunks, bar.chunk_progress if bar else None):
            if result.metric_names != metric_names:
                raise _loco.InternalError(f"batch metrics {result.metric_names} != {metric_names}")
            idx = result.indices
            new = ~done[idx] & (result.status != INTERRUPTED)
            metrics[idx] = result.metrics
            statistics[idx] = result.statistics
            status[idx] = result.status
            for i, m in zip(idx, result.messages, strict=True):
                messages[int(i)] = m
            kept.update(result.histories)
            context.samples.ran += int(new.sum())
            if sink is not None and new.any():
                sink.append(_frame(idx[new], x, names, result, new, track_seed, inputs, key))
            done[idx] = True
            if on_chunk is not None:
                on_chunk(idx)
            if bar:
                bar.chunk_done(int(new.sum()), int((result.status[new] != 0).sum()))
    finally:
        if bar:
            bar.close()
        if sink is not None:
            sink.close()
    return BatchResult(
        params=x,
        names=list(names),
        metric_names=metric_names,
        metrics=metrics,
        status=status,
        messages=messages,
        histories=history_results(
            [(i, *kept[i]) for i in sorted(kept)],
            metric_names,
            metrics,
            names,
            x,
            scenario,
            channel_kinds_of(vehicle.native),
        ),
        seconds=time.perf_counter() - start,
        threads=threads or 0,
        n_reused=n_reused,
        statistics=statistics,
    )


def _frame(
    idx: npt.NDArray[np.int64],
    x: FloatArray,
    names: Sequence[str],
    result: Any,
    new: npt.NDArray[np.bool_],
    seed: int,
    inputs: dict[str, Any],
    key: str,
) -> pd.DataFrame:
    # Built from one dict of columns (a column at a time fragments a frame of many inputs).
    codes = result.status[new]
    columns: dict[str, Any] = {"sample": idx}
    columns.update({name: x[idx, j] for j, name in enumerate(names)})
    columns["seed"] = seed
    columns.update({name: result.metrics[new, j] for j, name in enumerate(result.metric_names)})
    columns["status"] = [STATUS_NAMES[int(c)] for c in codes]
    columns["status_code"] = codes.astype(np.int32)
    columns["message"] = [m for m, k in zip(result.messages, new, strict=True) if k]
    for name in ("loco_version", "build", "vehicle_hash", "scenario_hash"):
        columns[name] = inputs[name]
    columns["campaign"] = key
    return pd.DataFrame(columns)


class _Bar:
    """A tqdm bar over the campaign: samples done (stored ones from the start), failures."""

    def __init__(self, total: int, done: int, failed: int) -> None:
        from tqdm.auto import tqdm

        self._bar = tqdm(total=total, initial=done, desc="simulations", unit="run", smoothing=0.1)
        self._base = done
        self._failed = failed

    def chunk_progress(self, done: int, failed: int) -> None:
        """Within the running chunk (local threads)."""
        if self._base + done != self._bar.n:
            self._bar.n = self._base + done
            if self._failed + failed:
                self._bar.set_postfix(failed=self._failed + failed, refresh=False)
            self._bar.refresh()

    def chunk_done(self, n: int, failed: int) -> None:
        self._base += n
        self._failed += failed
        self._bar.n = self._base
        if self._failed:
            self._bar.set_postfix(failed=self._failed, refresh=False)
        self._bar.refresh()

    def close(self) -> None:
        self._bar.close()


def load_campaign(directory: str | Path) -> pd.DataFrame:
    """The stored samples of the campaign store ``directory`` (``<root>/<key16>``) as a frame,
    one row per sample in design order (``store.to_xarray()`` for an ``xarray.Dataset``)."""
    description = Path(directory) / CAMPAIGN_FILE
    meta, damage = describe_damage(description)
    if meta is None:
        raise _loco.LocoIOError(f"cannot access `{description}`: it {damage}")
    store = CampaignStore(Path(directory).parent, meta["key"], meta["n_samples"], writable=False)
    return store.load().frame
