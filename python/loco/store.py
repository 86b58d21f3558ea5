"""The durable sample store of a campaign: every finished chunk of samples on disk at once.

A campaign (:func:`loco.campaign.run_campaign`) is keyed by its inputs (:func:`campaign_key`:
vehicle, scenario, design, seed, software build); its store is the directory
``<root>/<key[:16]>/`` holding

- ``campaign.json``: the key, the inputs' description and hashes, the number of samples;
- ``samples/part-<first>-<count>-<sha256>.parquet``: one file per finished chunk, one row per
  sample: ``sample`` (its row in the design), the parameters, ``seed``, the metrics, ``status``
  (name), ``status_code``, ``message``, ``loco_version``, ``build``, ``vehicle_hash``,
  ``scenario_hash``.

Why Parquet files and not Zarr: ``scripts/bench/bench_store.py`` (docs/performance.md, "Campaigns on
Dask") measured appending chunks of 8 samples and reading the campaign back. Appending a Parquet
part is one new file, written to a temporary name, fsynced and renamed, so a reader sees a whole
file or none; a Zarr append rewrites array chunks and metadata in place, which a kill can leave
half done, and was slower to append and to read back at these sizes.

Every write is atomic (temporary file, ``fsync``, ``os.replace``, ``fsync`` of the directory),
and a reader trusts a part only if the SHA-256 of its bytes matches the one in its name and its
rows are those the name says: a truncated or corrupted part is renamed ``*.corrupt``, named in a
:class:`CorruptStoreWarning`, and its samples count as missing (the campaign reruns them).
One process writes a campaign at a time: a writer holds the store's advisory lock
(:mod:`loco.store_lock`), and a second one fails at once naming the holder.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import re
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import pandas as pd

from loco.store_lock import StoreLock, remove_stale_temporaries, temporary_name

if TYPE_CHECKING:
    import xarray

__all__ = [
    "CAMPAIGN_FILE",
    "CampaignStore",
    "CorruptStoreWarning",
    "atomic_write",
    "campaign_key",
    "file_sha256",
    "find_campaigns",
]

#: The campaign's description file in its store directory.
CAMPAIGN_FILE = "campaign.json"
_PART = re.compile(r"^part-(\d{8})-(\d{6})-([0-9a-f]{64})\.parquet$")


class CorruptStoreWarning(RuntimeWarning):
    """A store file failed its checks; it was set aside and its samples are rerun."""


def file_sha256(path: str | Path) -> str:
    """SHA-256 (hex) of a file's bytes."""
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def atomic_write(path: str | Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` so that a reader sees the old file, or the whole new one.

    The bytes go to a temporary file in the same directory, are flushed to disk (``fsync``), the
    file is renamed over ``path`` and the directory entry is flushed too.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = temporary_name(path)
    with open(tmp, "wb") as f:
        f.write(data)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)
    fd = os.open(path.parent, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)
    return path


def campaign_key(inputs: Mapping[str, Any]) -> str:
    """SHA-256 (hex) of the campaign's inputs as canonical JSON (sorted keys)."""
    text = json.dumps(inputs, sort_keys=True, separators=(",", ":"), default=str)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


@dataclass(frozen=True)
class StoreState:
    """What a store holds: ``frame`` (one row per stored sample, sorted by ``sample``), the
    valid part files and the corrupt ones set aside (now and earlier)."""

    frame: pd.DataFrame
    parts: list[Path]
    corrupt: list[Path]


class CampaignStore:
    """The store of one campaign in ``<root>/<key[:16]>/`` (created, or checked to be the same
    campaign). ``meta`` is the description written to ``campaign.json`` with ``key`` and
    ``n_samples``. A writable store holds the store's lock until :meth:`close` (a second
    writer gets :class:`loco.store_lock.StoreBusyError`); use it in a ``with`` block."""

    def __init__(
        self,
        root: str | Path,
        key: str,
        n_samples: int,
        meta: Mapping[str, Any] | None = None,
        *,
        writable: bool = True,
    ) -> None:
        self.directory = Path(root) / key[:16]
        self.samples_dir = self.directory / "samples"
        self.key = key
        self.n_samples = int(n_samples)
        self.writable = writable
        self._lock: StoreLock | None = None
        if writable:
            self.directory.mkdir(parents=True, exist_ok=True)
            self._lock = StoreLock(self.directory)
        try:
            self._open(meta)
        except BaseException:
            self.close()
            raise

    def _open(self, meta: Mapping[str, Any] | None) -> None:
        key = self.key
        description = self.directory / CAMPAIGN_FILE
        known = _read_json(description) if description.is_file() else None
        if known is not None and known.get("key") != key:
            raise FileExistsError(
                f"{description} belongs to another campaign (key {known.get('key')})"
            )
        if not self.writable:
            return
        if known is None:
            data = {"key": key, "n_samples": self.n_samples, **dict(meta or {})}
            text = json.dumps(data, indent=2, sort_keys=True, default=str) + "\n"
            atomic_write(description, text.encode("utf-8"))
        self.samples_dir.mkdir(parents=True, exist_ok=True)
        # Left by a killed writer: never renamed, never trusted.
        remove_stale_temporaries(self.directory)
        remove_stale_temporaries(self.samples_dir)

    def close(self) -> None:
        """Releases the store's lock (a read-only store holds none)."""
        if self._lock is not None:
            self._lock.release()
            self._lock = None

    def __enter__(self) -> CampaignStore:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def append(self, frame: pd.DataFrame) -> Path:
        """Store the rows of one finished chunk (a ``sample`` column and the rest) atomically;
        returns the part file."""
        if not self.writable:
            raise PermissionError(f"{self.directory} was opened read-only")
        frame = frame.sort_values("sample").reset_index(drop=True)
        buffer = io.BytesIO()
        frame.to_parquet(buffer, engine="pyarrow", index=False)
        data = buffer.getvalue()
        name = (
            f"part-{int(frame['sample'].iloc[0]):08d}-{len(frame):06d}-"
            f"{hashlib.sha256(data).hexdigest()}.parquet"
        )
        return atomic_write(self.samples_dir / name, data)

    def load(self) -> StoreState:
        """Every valid stored sample; each part is checked (name, hash, rows, campaign key), a
        failing one set aside with a :class:`CorruptStoreWarning` naming it."""
        import pyarrow as pa

        tables, parts, corrupt = [], [], sorted(self.samples_dir.glob("*.corrupt"))
        for path in sorted(self.samples_dir.glob("part-*.parquet")):
            try:
                tables.append(self._read_part(path))
            except ValueError as e:
                target = path.with_name(path.name + ".corrupt")
                if self.writable:
                    os.replace(path, target)
                warnings.warn(
                    f"sample store: {path} is corrupt ({e}); "
                    + (
                        f"set aside as {target.name}, its samples will be run again"
                        if self.writable
                        else "its samples count as missing"
                    ),
                    CorruptStoreWarning,
                    stacklevel=2,
                )
                corrupt.append(target if self.writable else path)
                continue
            parts.append(path)
        if not tables:
            empty = pd.DataFrame({"sample": np.zeros(0, dtype=np.int64)})
            return StoreState(frame=empty, parts=parts, corrupt=corrupt)
        frame = pa.concat_tables(tables, promote_options="default").to_pandas()
        # One writer never stores a sample twice; should two have, keep the first copy.
        frame = frame.drop_duplicates("sample").sort_values("sample", ignore_index=True)
        return StoreState(frame=frame, parts=parts, corrupt=corrupt)

    def _read_part(self, path: Path) -> Any:
        import pyarrow as pa
        import pyarrow.parquet as pq

        match = _PART.match(path.name)
        if match is None:
            raise ValueError("not a part file name")
        data = path.read_bytes()
        if hashlib.sha256(data).hexdigest() != match.group(3):
            raise ValueError("its SHA-256 does not match its name: truncated or modified")
        try:
            table = pq.read_table(pa.BufferReader(data))
            samples = table.column("sample").to_numpy()
            keys = set(table.column("campaign").to_pylist())
        except Exception as e:  # pyarrow raises several types for a damaged file
            raise ValueError(f"unreadable: {e}") from e
        if (
            len(samples) != int(match.group(2))
            or len(samples) == 0
            or int(samples[0]) != int(match.group(1))
            or samples.min() < 0
            or samples.max() >= self.n_samples
        ):
            raise ValueError("its rows are not those its name says")
        if keys != {self.key}:
            raise ValueError("its rows belong to another campaign")
        return table

    def to_xarray(self) -> xarray.Dataset:
        """The stored samples as an ``xarray.Dataset`` on a ``sample`` dimension."""
        return self.load().frame.set_index("sample").to_xarray()


def _read_json(path: Path) -> dict[str, Any] | None:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError):
        return None
    return data if isinstance(data, dict) else None


@dataclass(frozen=True)
class CampaignStatus:
    """Progress of one stored campaign (``loco campaign status``)."""

    directory: Path
    meta: dict[str, Any]
    n_samples: int
    n_done: int
    n_failed: int
    n_parts: int
    corrupt: list[Path]
    #: Why ``campaign.json`` cannot be used (then nothing else is counted), None when it can.
    damage: str | None = None


def describe_damage(description: Path) -> tuple[dict[str, Any] | None, str | None]:
    """The content of the ``campaign.json`` at ``description``, or None and why it is unusable
    (unreadable, not JSON, no key of 64 hex digits, a key that is not the directory's, no whole
    number of samples)."""
    try:
        meta = json.loads(description.read_text(encoding="utf-8"))
    except OSError as e:
        return None, f"cannot be read: {e.strerror or e}"
    except UnicodeDecodeError as e:
        return None, f"is not UTF-8 text (byte offset {e.start})"
    except json.JSONDecodeError as e:
        return None, f"is not valid JSON (line {e.lineno}, column {e.colno}: {e.msg})"
    if not isinstance(meta, dict):
        return None, f"holds a JSON {type(meta).__name__}, not an object"
    key = meta.get("key")
    if not isinstance(key, str) or re.fullmatch(r"[0-9a-f]{64}", key) is None:
        return None, f"has no campaign key of 64 hex digits (key: {key!r})"
    if key[:16] != description.parent.name:
        return None, (
            f"names the campaign {key[:16]}…, not this directory's ({description.parent.name}): "
            "it was copied from another store"
        )
    n = meta.get("n_samples")
    if isinstance(n, bool) or not isinstance(n, int) or n < 0:
        return None, f"has no whole number of samples (n_samples: {n!r})"
    return meta, None


def find_campaigns(root: str | Path) -> list[CampaignStatus]:
    """Every campaign store under ``root`` (at any depth), with its progress; a store whose
    ``campaign.json`` is damaged is listed with :attr:`CampaignStatus.damage` saying why."""
    out = []
    for description in sorted(Path(root).rglob(CAMPAIGN_FILE)):
        meta, damage = describe_damage(description)
        if meta is None:
            out.append(CampaignStatus(description.parent, {}, 0, 0, 0, 0, [], damage=damage))
            continue
        store = CampaignStore(
            description.parent.parent, meta["key"], meta["n_samples"], writable=False
        )
        with warnings.catch_warnings(record=True):
            warnings.simplefilter("always")
            state = store.load()
        status = state.frame.get("status", pd.Series(dtype=str))
        out.append(
            CampaignStatus(
                directory=store.directory,
                meta=meta,
                n_samples=int(meta["n_samples"]),
                n_done=len(state.frame),
                n_failed=int((status != "ok").sum()),
                n_parts=len(state.parts),
                corrupt=state.corrupt,
            )
        )
    return out
