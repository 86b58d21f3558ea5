"""Chunks with the next one already running (:func:`loco.chunk_threads.overlapped`): every result
once, as its chunk ends; never more than the window at once; progress summed over the running
chunks; stopping cancels the running chunks through their progress callback and waits for them.
The native batch is stood in for by functions that poll their callback like it does."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

import pytest

from loco.chunk_threads import CancelledChunkError, overlapped

Progress = Callable[[int, int], object]


class Recorder:
    """A chunk of ``n`` samples taking ``n`` × ``step`` s, polling its progress like the native
    batch; records how many ran at once and which were cancelled."""

    def __init__(self, step: float = 0.01) -> None:
        self.step = step
        self.lock = threading.Lock()
        self.running = 0
        self.most = 0
        self.cancelled: list[int] = []

    def __call__(self, chunk: tuple[int, int], progress: Progress) -> int:
        key, n = chunk
        with self.lock:
            self.running += 1
            self.most = max(self.most, self.running)
        try:
            for done in range(n):
                time.sleep(self.step)
                progress(done + 1, 0)
            return key
        except CancelledChunkError:
            with self.lock:
                self.cancelled.append(key)
            raise
        finally:
            with self.lock:
                self.running -= 1


@pytest.mark.parametrize("window", [1, 2, 3])
def test_every_chunk_once_within_the_window(window: int) -> None:
    run = Recorder()
    chunks = [(k, 1 + (k * 7) % 5) for k in range(12)]
    seen = list(overlapped(run, chunks, window))
    assert sorted(seen) == list(range(12))
    assert run.most == min(window, len(chunks))
    assert not any(t.name.startswith("loco-chunk") for t in threading.enumerate())


def test_progress_is_the_sum_over_the_running_chunks() -> None:
    reports: list[tuple[int, int]] = []
    lock = threading.Lock()

    def progress(done: int, failed: int) -> None:
        with lock:
            reports.append((done, failed))

    handed: list[int] = []
    for key in overlapped(Recorder(), [(0, 5), (1, 5), (2, 3)], 2, progress):
        handed.append(key)
    # Two chunks of 5 at once: the sum reaches past one chunk's count, never past two.
    assert max(d for d, _ in reports) > 5
    assert all(d <= 10 for d, _ in reports)
    assert sorted(handed) == [0, 1, 2]


def test_leaving_early_cancels_the_running_chunks() -> None:
    run = Recorder(step=0.02)
    results = overlapped(run, [(0, 2), *((k, 50) for k in range(1, 6))], 2)
    assert next(results) == 0
    start = time.perf_counter()
    results.close()  # the caller stops: the other running chunk is cancelled at its next poll
    assert time.perf_counter() - start < 0.5
    # Chunk 1 was running; chunk 2, just started, was either cancelled or never ran.
    assert 1 in run.cancelled and run.running == 0
    assert not any(t.name.startswith("loco-chunk") for t in threading.enumerate())


def test_a_failing_chunk_stops_the_others() -> None:
    run = Recorder(step=0.02)

    def failing(chunk: tuple[int, int], progress: Progress) -> int:
        if chunk[0] == 1:
            time.sleep(0.05)
            raise ValueError("row 3: bad")
        return run(chunk, progress)

    with pytest.raises(ValueError, match="row 3"):
        list(overlapped(failing, [(0, 50), (1, 1), (2, 50)], 2))
    assert run.running == 0 and run.cancelled == [0]


def test_window_must_be_positive() -> None:
    with pytest.raises(ValueError, match="window"):
        list(overlapped(Recorder(), [(0, 1)], 0))
