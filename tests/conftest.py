"""Shared pytest fixtures: the reference data of ``shared/data`` (never copied into the repo),
and the tiny ``loco reproduce`` run that the reproduce and report-page tests read."""

from __future__ import annotations

import contextlib
import io
import os
from pathlib import Path

import pytest


def find_shared_data() -> Path | None:
    """``$LOCO_SHARED_DATA`` if set, else the first ``shared/data`` directory next to this
    repository or one of its ancestors (``<root>/main`` or ``<root>/wt/<name>`` with the data at
    ``<root>/shared/data``); None when absent."""
    env = os.environ.get("LOCO_SHARED_DATA")
    if env:
        path = Path(env)
        return path if path.is_dir() else None
    for parent in Path(__file__).resolve().parents:
        candidate = parent / "shared" / "data"
        if candidate.is_dir():
            return candidate
    return None


@pytest.fixture(scope="session")
def shared_data() -> Path:
    """The reference-data directory; skips the test with the reason when it is absent."""
    path = find_shared_data()
    if path is None:
        pytest.skip("reference data not found: set LOCO_SHARED_DATA or provide ../shared/data")
    return path


#: The command line of the tiny study (the hidden preset: a few 300 m runs per stage).
TINY_ARGS = ["reproduce", "--tiny", "--threads", "2", "--no-progress"]


@pytest.fixture(scope="session")
def tiny_study(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, str]:
    """The tiny study, run once through the CLI; its output directory and printed log."""
    from loco.cli import main

    out = tmp_path_factory.mktemp("reproduce")
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        assert main([*TINY_ARGS, "--out", str(out)]) == 0
    return out, buffer.getvalue()


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Every test on the tiny study is slow: the study itself takes minutes (once per session)."""
    for item in items:
        if "tiny_study" in getattr(item, "fixturenames", ()):
            item.add_marker(pytest.mark.slow)
