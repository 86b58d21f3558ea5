"""Resumable stages: how ``loco reproduce`` restarts without redoing finished work.

A stage is a frozen dataclass (a subclass of :class:`Stage`) whose fields are exactly its inputs:
sizes, seeds, speeds, yaw dampers, the vehicle, the tables of earlier stages it reads
(:class:`DataFile`). Its hash (:meth:`Stage.stage_hash`) is computed from every field, encoded
by :func:`encode` (a damper by its law and parameters, a vehicle by its parameter file's content
and overrides, a table by its content), so no input can be left out of it; a field of a type
:func:`encode` does not know is a ``TypeError``, not a silent ``repr``. How a stage runs (thread
count, progress bars: :class:`Runtime`) is not a field, since it does not change the numbers.
``Stage.run(out_dir, runtime)`` writes the stage's files into ``<out>/<name>/`` and returns a
:class:`~loco.studies.report.StudyRecord`; ``Stage.demand()`` says how many simulations it asks
for (:class:`Demand`, what ``loco reproduce`` sizes its presets by).

When a stage returns, :class:`StageRunner` writes the marker ``<out>/<name>/stage.json``
(atomically: a temporary file, then a rename) holding the stage hash, the encoded inputs, the
record and the SHA-256 of every file the record lists (its figures and tables). On the next run a
stage whose marker exists with the same hash and whose files all still have their recorded
content hashes is skipped and its record read back; a changed input, or an output file that is
missing, truncated or edited, makes the stage run again (the log names the file). A stage
interrupted before it returned has no marker and runs again; the samples it had finished are in
its sample store (:mod:`loco.store`), so only the rest are simulated.
"""

from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import json
import shutil
import time
from collections.abc import Callable, Iterator, Mapping
from contextlib import AbstractContextManager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

import loco
from loco import _loco
from loco.store import atomic_write, file_sha256
from loco.studies.report import StudyRecord, jsonable

__all__ = [
    "MARKER",
    "DataFile",
    "Demand",
    "Runtime",
    "Stage",
    "StageRunner",
    "campaign_executor",
    "campaign_stores",
    "encode",
]

#: File name of a finished stage's marker.
MARKER = "stage.json"


@dataclass(frozen=True)
class Runtime:
    """How a stage runs, not what it computes: simulation ``threads`` (None: all cores) and
    whether batches show ``progress`` bars. Results do not depend on either."""

    threads: int | None = None
    progress: bool = True


@dataclass(frozen=True)
class DataFile:
    """A table an earlier stage wrote that a stage reads: as a stage input it is its content
    (SHA-256 when the stage hash is taken), not its path."""

    path: Path


@dataclass(frozen=True)
class Demand:
    """The simulations a stage asks for: their number and their simulated time in all (s, each
    run's lead-in and recorded distance over its speed)."""

    simulations: int = 0
    simulated_s: float = 0.0

    @classmethod
    def runs(cls, n: int, length_m: float, speed_mps: float) -> Demand:
        """``n`` runs of ``length_m`` (m, lead-in included) at ``speed_mps`` (m/s)."""
        return cls(n, n * length_m / speed_mps)

    def __add__(self, other: Demand) -> Demand:
        return Demand(self.simulations + other.simulations, self.simulated_s + other.simulated_s)


def encode(value: Any) -> Any:
    """A stage input as canonical, JSON-ready content (what the stage hash is taken of).

    Numbers, strings, booleans and None stand for themselves (a non-finite float as its name);
    sequences and mappings element by element, a mapping as ``[key, value]`` pairs in its order
    (the order of e.g. a damper set changes the tables); a yaw damper as its kind and parameters;
    a vehicle as the SHA-256 of its resolved parameters (:meth:`loco.Locomotive.parameters_sha256`:
    a comment or a source edited in its file changes nothing, a value does);
    a :class:`DataFile` as the SHA-256 of its content; a dataclass as its class name and fields.
    Anything else is a ``TypeError``: a new kind of input needs its encoding here.
    """
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, (float, np.floating)):
        return jsonable(float(value))
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, (list, tuple, np.ndarray)):
        return [encode(v) for v in value]
    if isinstance(value, Mapping):
        return [[str(k), encode(v)] for k, v in value.items()]
    if isinstance(value, _loco.Damper):
        return {"damper": value.kind, **jsonable(value.parameters())}
    if isinstance(value, loco.Locomotive):
        return {"vehicle_parameters_sha256": value.parameters_sha256()}
    if isinstance(value, DataFile):
        return {"file_sha256": file_sha256(value.path) if value.path.is_file() else None}
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        fields = {f.name: encode(getattr(value, f.name)) for f in dataclasses.fields(value)}
        return {"type": type(value).__name__, **fields}
    raise TypeError(f"a stage input of type {type(value).__name__} has no encoding for its hash")


@dataclass(frozen=True)
class Stage:
    """A stage of ``loco reproduce``: subclasses are frozen dataclasses whose fields are the
    stage's inputs, with the class attribute ``name`` (its directory)."""

    name: ClassVar[str]

    def inputs(self) -> dict[str, Any]:
        """Every field, encoded (:func:`encode`): what the stage's numbers depend on."""
        return {f.name: encode(getattr(self, f.name)) for f in dataclasses.fields(self)}

    def stage_hash(self) -> str:
        """SHA-256 (hex) of the stage name, the loco version and :meth:`inputs` as canonical
        JSON (sorted keys)."""
        content = {"name": self.name, "loco_version": loco.__version__, "inputs": self.inputs()}
        text = json.dumps(content, sort_keys=True)
        return hashlib.sha256(text.encode("utf-8")).hexdigest()

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """Write the stage's files into ``out_dir`` and return its record."""
        raise NotImplementedError

    def demand(self) -> Demand:
        """The simulations the stage asks for (none by default)."""
        return Demand()


class StageRunner:
    """Runs stages into ``out_dir``, skipping those already finished with the same inputs.

    Parameters
    ----------
    out_dir : path
        Output directory of the whole run (created if missing).
    log : callable
        Receives one line per stage started, skipped or finished (default: ``print``).
    force : bool
        Run every stage even when its marker matches.
    runtime : Runtime
        Threads and progress bars of every stage.
    around : callable, optional
        ``around(stage_dir)`` is a context manager each stage runs inside (``loco reproduce``:
        the stage's campaign store).
    """

    def __init__(
        self,
        out_dir: str | Path,
        *,
        log: Callable[[str], None] = print,
        force: bool = False,
        runtime: Runtime | None = None,
        around: Callable[[Path], AbstractContextManager[Any]] | None = None,
    ) -> None:
        self.out_dir = Path(out_dir)
        self.out_dir.mkdir(parents=True, exist_ok=True)
        self.log = log
        self.force = force
        self.runtime = runtime or Runtime()
        self.around = around or (lambda _: contextlib.nullcontext())
        self.skipped: list[str] = []
        self.ran: list[str] = []

    def marker(self, name: str) -> Path:
        """Path of the marker of stage ``name``."""
        return self.out_dir / name / MARKER

    def finished(self, stage: Stage) -> StudyRecord | None:
        """The record of ``stage`` if its marker matches its hash and outputs, else None."""
        name = stage.name
        path = self.marker(name)
        if not path.is_file():
            return None
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, json.JSONDecodeError):
            return None
        if data.get("hash") != stage.stage_hash():
            return None
        record = StudyRecord.from_json(data["record"], self.out_dir)
        hashes = data.get("outputs")
        if not isinstance(hashes, dict):
            self.log(f"[{name}] marker without output hashes (older loco): running it again")
            return None
        for path in [*record.figures, *record.tables]:
            rel = self._relative(path)
            if not path.is_file() or hashes.get(rel) != file_sha256(path):
                what = "missing" if not path.is_file() else "changed or truncated"
                self.log(f"[{name}] output {rel} is {what} since the stage finished: running again")
                return None
        return record

    def _relative(self, path: Path) -> str:
        try:
            return str(Path(path).relative_to(self.out_dir))
        except ValueError:
            return str(path)

    def run(self, stage: Stage) -> StudyRecord:
        """Run ``stage`` into ``<out>/<stage.name>`` unless it already finished with these
        inputs.

        The record's ``parameters`` default to the encoded inputs and its ``seconds`` to the
        measured run time when the stage leaves them empty. Returns the record (read back when
        skipped).
        """
        name = stage.name
        if not self.force:
            done = self.finished(stage)
            if done is not None:
                self.log(f"[{name}] finished earlier ({done.seconds:.1f} s), skipped")
                self.skipped.append(name)
                return done
        stage_dir = self.out_dir / name
        stage_dir.mkdir(parents=True, exist_ok=True)
        self.log(f"[{name}] running")
        # The hash of the inputs as they were when the stage started (a table it reads may be
        # rewritten by a later stage of the same run, never by this one).
        stage_hash, inputs = stage.stage_hash(), stage.inputs()
        start = time.perf_counter()
        with self.around(stage_dir):
            record = stage.run(stage_dir, self.runtime)
        elapsed = time.perf_counter() - start
        if not record.parameters:
            record.parameters = dict(inputs)
        if record.seconds <= 0:
            record.seconds = elapsed
        payload = {
            "hash": stage_hash,
            "inputs": inputs,
            "finished": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
            "record": record.to_json(self.out_dir),
            "outputs": {
                self._relative(p): file_sha256(p) for p in [*record.figures, *record.tables]
            },
        }
        text = json.dumps(payload, indent=2, sort_keys=True) + "\n"
        atomic_write(self.marker(name), text.encode("utf-8"))
        self.log(f"[{name}] done in {elapsed:.1f} s")
        self.ran.append(name)
        return record


def campaign_executor() -> Any:
    """The executor of the enclosing campaign block (:func:`loco.campaign.using`), None outside
    one: what a stage's own tasks (eigen analyses) run on, beside its batches."""
    from loco import campaign

    context = campaign.current()
    return None if context is None else context.executor


def campaign_stores(
    executor: Any = None,
    *,
    chunk_size: int | None = None,
    force: bool = False,
    log: Callable[[str], None] = print,
) -> Callable[[Path], AbstractContextManager[None]]:
    """The ``around`` of a :class:`StageRunner` that runs every batch of a stage as a campaign
    on ``executor`` (:mod:`loco.campaign`; default local threads) with its samples kept in
    ``<stage>/store`` (cleared first when ``force``), and logs how many came from the store."""
    from loco import campaign

    @contextlib.contextmanager
    def around(stage_dir: Path) -> Iterator[None]:
        if force:
            shutil.rmtree(stage_dir / "store", ignore_errors=True)
        with campaign.using(executor, stage_dir / "store", chunk_size=chunk_size) as context:
            yield
        # Printed with or without progress bars: where the stage's samples came from.
        count = context.samples
        log(f"[{stage_dir.name}] samples: {count.reused} from the store, {count.ran} run")

    return around
