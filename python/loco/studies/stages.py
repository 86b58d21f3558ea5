"""Resumable stages: how ``loco reproduce`` restarts without redoing finished work.

A stage is a named function that writes its files into ``<out>/<name>/`` and returns a
:class:`~loco.studies.report.StudyRecord`. When it returns, the runner writes the marker
``<out>/<name>/stage.json`` (atomically: a temporary file, then a rename) holding a SHA-256 hash of
the stage's name and settings, the record and the SHA-256 of every file the record lists (its
figures and tables). On the next run a stage whose marker exists with the same settings hash and
whose files all still have their recorded content hashes is skipped and its record read back; a
changed setting, or an output file that is missing, truncated or edited, makes the stage run
again (the log names the file). A stage interrupted before it returned has no marker and runs
again; the samples it had finished are in its sample store (:mod:`loco.store`), so only the rest
are simulated.
"""

from __future__ import annotations

import hashlib
import json
import time
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from loco.store import atomic_write, file_sha256
from loco.studies.report import StudyRecord, jsonable

__all__ = ["MARKER", "StageRunner", "settings_hash"]

#: File name of a finished stage's marker.
MARKER = "stage.json"


def settings_hash(name: str, settings: Mapping[str, Any]) -> str:
    """SHA-256 (hex) of the stage name and its settings as canonical JSON (sorted keys)."""
    text = json.dumps({"name": name, "settings": jsonable(settings)}, sort_keys=True)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


class StageRunner:
    """Runs stages into ``out_dir``, skipping those already finished with the same settings.

    Parameters
    ----------
    out_dir : path
        Output directory of the whole run (created if missing).
    log : callable
        Receives one line per stage started, skipped or finished (default: ``print``).
    force : bool
        Run every stage even when its marker matches.
    """

    def __init__(
        self,
        out_dir: str | Path,
        *,
        log: Callable[[str], None] = print,
        force: bool = False,
    ) -> None:
        self.out_dir = Path(out_dir)
        self.out_dir.mkdir(parents=True, exist_ok=True)
        self.log = log
        self.force = force
        self.skipped: list[str] = []
        self.ran: list[str] = []

    def marker(self, name: str) -> Path:
        """Path of the marker of stage ``name``."""
        return self.out_dir / name / MARKER

    def finished(self, name: str, settings: Mapping[str, Any]) -> StudyRecord | None:
        """The record of stage ``name`` if its marker matches ``settings``, else None."""
        path = self.marker(name)
        if not path.is_file():
            return None
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, json.JSONDecodeError):
            return None
        if data.get("hash") != settings_hash(name, settings):
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

    def output_hash(self, path: str | Path) -> str:
        """SHA-256 of an output file of a finished stage (for the settings of the stages that
        read it, so that they run again when it changes)."""
        return file_sha256(path)

    def run(
        self,
        name: str,
        settings: Mapping[str, Any],
        stage: Callable[[Path], StudyRecord],
    ) -> StudyRecord:
        """Run ``stage(<out>/<name>)`` unless it already finished with these ``settings``.

        The record's ``parameters`` default to ``settings`` and its ``seconds`` to the measured
        run time when the stage leaves them empty. Returns the record (read back when skipped).
        """
        if not self.force:
            done = self.finished(name, settings)
            if done is not None:
                self.log(f"[{name}] finished earlier ({done.seconds:.1f} s), skipped")
                self.skipped.append(name)
                return done
        stage_dir = self.out_dir / name
        stage_dir.mkdir(parents=True, exist_ok=True)
        self.log(f"[{name}] running")
        start = time.perf_counter()
        record = stage(stage_dir)
        elapsed = time.perf_counter() - start
        if not record.parameters:
            record.parameters = dict(settings)
        if record.seconds <= 0:
            record.seconds = elapsed
        payload = {
            "hash": settings_hash(name, settings),
            "settings": jsonable(settings),
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
