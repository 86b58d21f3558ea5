"""Chunks of a local campaign with the next one already running: no core idles between chunks.

Run one after the other, each chunk of a campaign (a native batch on every rayon thread) ends
with some cores idle: while its last samples finish, while the next chunk builds what it shares
(contact table, track), and while the campaign appends the finished chunk to its Parquet store.
:func:`overlapped` keeps ``window`` chunks running on Python threads (the native batch releases
the GIL), so the next chunk fills those gaps; each result is handed over as soon as its chunk
ends, so the caller still stores every finished chunk at once.

The results are those of the chunks run one by one: a sample depends on its own row alone,
not on which thread or chunk ran it. Progress is the sum over the running chunks. Stopping
(an error, Ctrl-C, the caller leaving the loop) cancels the running chunks through their
progress callback, which the native batch polls every 100 ms, and waits for them.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ThreadPoolExecutor, wait
from typing import TypeVar

__all__ = ["CancelledChunkError", "overlapped"]

C = TypeVar("C")
R = TypeVar("R")
#: ``progress(done, failed)`` of the samples of the running chunks.
Progress = Callable[[int, int], object]
#: Runs one chunk, reporting through the ``progress(done, failed)`` it is given.
RunChunk = Callable[[C, Progress], R]


class CancelledChunkError(Exception):
    """Raised in a running chunk's progress callback to cancel its native batch."""


class _Meter:
    """The running chunks' progress, summed; raises :class:`CancelledChunkError` once stopped."""

    def __init__(self, progress: Progress | None) -> None:
        self._progress = progress
        self._lock = threading.Lock()
        self._running: dict[int, tuple[int, int]] = {}
        self._stopped = threading.Event()

    def callback(self, k: int) -> Progress:
        def report(done: int, failed: int) -> None:
            if self._stopped.is_set():
                raise CancelledChunkError
            with self._lock:
                self._running[k] = (done, failed)
                if self._progress is not None:
                    self._progress(
                        sum(d for d, _ in self._running.values()),
                        sum(f for _, f in self._running.values()),
                    )

        return report

    def finished(self, k: int) -> None:
        # Before the result is handed over, so the caller's count of finished chunks never
        # includes a chunk that is still counted here.
        with self._lock:
            self._running.pop(k, None)

    def stop(self) -> None:
        self._stopped.set()


def overlapped(
    run: RunChunk[C, R],
    chunks: Sequence[C],
    window: int,
    progress: Progress | None = None,
) -> Iterator[R]:
    """``run(chunk, progress)`` of every chunk, at most ``window`` at once, each result yielded
    as its chunk ends (in the order they end; chunks ending together in chunk order)."""
    if window < 1:
        raise ValueError(f"overlapped: window must be >= 1, got {window}")
    meter = _Meter(progress)

    def one(k: int, chunk: C) -> R:
        try:
            return run(chunk, meter.callback(k))
        finally:
            meter.finished(k)

    pending = iter(enumerate(chunks))
    running: dict[Future[R], int] = {}
    pool = ThreadPoolExecutor(max_workers=window, thread_name_prefix="loco-chunk")

    def refill() -> None:
        while len(running) < window:
            item = next(pending, None)
            if item is None:
                return
            running[pool.submit(one, *item)] = item[0]

    try:
        refill()
        while running:
            finished, _ = wait(running, return_when=FIRST_COMPLETED)
            order = sorted(finished, key=running.__getitem__)
            for future in order:
                del running[future]
            # The next chunks start before the caller stores these results.
            refill()
            for future in order:
                yield future.result()
    finally:
        # Reached on completion, an error, Ctrl-C and when the caller stops early: the running
        # chunks stop at their next progress poll, and none is left running behind the caller.
        meter.stop()
        for future in running:
            future.cancel()
        pool.shutdown(wait=True)
