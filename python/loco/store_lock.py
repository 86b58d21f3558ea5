"""One writer per campaign store: an advisory lock, and the checks of a store's place.

A process that writes a campaign store (:class:`loco.store.CampaignStore`) holds an exclusive
``fcntl.flock`` on ``<store>/.lock`` from the moment it opens the store until it closes it (or
exits: the operating system releases the lock of a process that dies, so a killed writer never
leaves a store locked). The holder writes its process id, host and start time into the file, and
a second writer fails at once with :class:`StoreBusyError` naming them, before it reads what is
stored or runs anything: two processes never do the same samples twice. Readers
(``loco campaign status``, :func:`loco.campaign.load_campaign`) take no lock; every file they read
was renamed into place whole.

Temporary files are named with their writer's host and process id (``.<name>.<host>.<pid>.tmp``)
and removed only when that writer is gone (a process id on this host that no longer runs); a
temporary file of a live process, or of another host, is left alone.
"""

from __future__ import annotations

import fcntl
import json
import os
import socket
import time
from pathlib import Path
from typing import IO, Any

from loco import _loco
from loco.directories import directory_problem

__all__ = [
    "LOCK_FILE",
    "StoreBusyError",
    "StoreLock",
    "check_store_root",
    "remove_stale_temporaries",
    "temporary_name",
]

#: The lock file in a campaign store directory.
LOCK_FILE = ".lock"


class StoreBusyError(_loco.LocoError):
    """Another process is writing the campaign store; the message names it (pid, host, start)."""


class StoreLock:
    """The exclusive advisory lock of the store ``directory``, taken when created; a held lock
    is a :class:`StoreBusyError` naming its holder. :meth:`release` (or the process's end)
    frees it."""

    def __init__(self, directory: Path) -> None:
        self.path = directory / LOCK_FILE
        self._file: IO[str] | None = open(self.path, "a+", encoding="utf-8")
        try:
            fcntl.flock(self._file.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = _holder(self.path)
            self._file.close()
            self._file = None
            raise StoreBusyError(
                f"the campaign store {directory} is being written by another process "
                f"({holder}); wait for it to finish (its samples will then be read back, not "
                f"run again) or stop it"
            ) from None
        self._file.seek(0)
        self._file.truncate()
        json.dump(
            {"pid": os.getpid(), "host": socket.gethostname(), "started": time.ctime()},
            self._file,
        )
        self._file.write("\n")
        self._file.flush()

    def release(self) -> None:
        """Frees the lock (the file stays: its content only names the last holder)."""
        if self._file is not None:
            fcntl.flock(self._file.fileno(), fcntl.LOCK_UN)
            self._file.close()
            self._file = None


def _holder(path: Path) -> str:
    """Who holds the lock at ``path``, from what the holder wrote."""
    try:
        info: Any = json.loads(path.read_text(encoding="utf-8"))
        return f"pid {info['pid']} on {info['host']}, since {info['started']}"
    except (OSError, ValueError, KeyError, TypeError):
        return "a process that has not yet written its name"


def temporary_name(path: Path) -> Path:
    """The temporary file a write of ``path`` goes through, named with this host and process."""
    return path.with_name(f".{path.name}.{socket.gethostname()}.{os.getpid()}.tmp")


def remove_stale_temporaries(directory: Path) -> list[Path]:
    """Removes the temporary files in ``directory`` whose writer is gone (a process of this
    host that no longer runs); returns them. Files of live processes or other hosts stay."""
    host = socket.gethostname()
    removed = []
    for tmp in directory.glob(".*.tmp"):
        # `.<name>.<host>.<pid>.tmp`; a host name may hold dots itself.
        rest, _, pid = tmp.name[1:-4].rpartition(".")
        if not rest.endswith(f".{host}") or not pid.isdigit():
            continue
        if not _running(int(pid)):
            tmp.unlink(missing_ok=True)
            removed.append(tmp)
    return removed


def _running(pid: int) -> bool:
    """Whether process ``pid`` of this host exists."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True  # it exists, as another user's
    return True


def check_store_root(root: str | Path) -> Path:
    """``root`` as the directory of campaign stores, checked before any work: not a file, not
    under a file, and writable (a probe file is written and removed). Errors name ``store``."""
    out = Path(root)
    problem = directory_problem(out)
    if problem is not None:
        kind, reason = problem
        if kind == "file":
            raise _loco.ParameterError(f"invalid parameter `store`: {reason}")
        raise _loco.LocoIOError(
            f"cannot access `{out}` (the `store`): cannot write into it: {reason}"
        )
    return out
