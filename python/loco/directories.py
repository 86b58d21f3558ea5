"""Output directories: whether a path can be one, checked before any work is done."""

from __future__ import annotations

import tempfile
from pathlib import Path

__all__ = ["directory_problem"]


def directory_problem(path: str | Path) -> tuple[str, str] | None:
    """Makes ``path`` a directory that takes files (created if missing) or says why it cannot
    be one: ``("file", "<path> is a file, not a directory")`` when it is a file or lies under
    one, ``("write", reason)`` when it cannot be created or written (read-only place, no
    permission), None when it is fine. The check writes and removes a probe file, so it holds
    for any user (root included) and any file system (read-only mounts)."""
    out = Path(path)
    for parent in (out, *out.parents):
        if parent.exists() and not parent.is_dir():
            where = "is a file" if parent == out else f"is under the file {parent}"
            return ("file", f"{out} {where}, not a directory")
        if parent.exists():
            break
    try:
        out.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=out):
            pass
    except OSError as e:
        return ("write", e.strerror or str(e))
    return None
