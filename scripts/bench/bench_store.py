"""Sample store formats: appending small chunks of finished samples, and reading them back.

Compares the store of :mod:`loco.store` (one Parquet file per chunk, written atomically: temporary
file, fsync, rename, fsync of the directory; read back with every file's SHA-256 checked) with
a Zarr store written by xarray (``Dataset.to_zarr(append_dim="sample")``, one store appended in
place; read back with ``xarray.open_zarr(...).load()``). The rows are those of a real campaign:
the six study parameters, the run metrics, status, message and the provenance columns. Needs
``zarr`` (not a loco dependency) for the second half.

    python scripts/bench/bench_store.py --chunks 64 --rows 8 --repeat 3
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

import loco
from loco.store import CampaignStore
from loco.studies.parameters import names


def chunk_frame(first: int, rows: int, rng: np.random.Generator) -> pd.DataFrame:
    """One finished chunk with the columns of a real stored sample."""
    frame = pd.DataFrame({"sample": np.arange(first, first + rows, dtype=np.int64)})
    for name in names():
        frame[name] = rng.uniform(1e4, 1e7, rows)
    frame["seed"] = 0
    for metric in loco._loco.run_metric_names():
        frame[metric] = rng.normal(size=rows)
    frame["status"] = "ok"
    frame["status_code"] = np.zeros(rows, dtype=np.int32)
    frame["message"] = ""
    for column in ("loco_version", "build", "vehicle_hash", "scenario_hash", "campaign"):
        frame[column] = "f" * 64
    return frame


def bench_parquet(frames: list[pd.DataFrame], root: Path) -> tuple[float, float]:
    n = sum(len(f) for f in frames)
    store = CampaignStore(root, "f" * 64, n)
    start = time.perf_counter()
    for frame in frames:
        store.append(frame)
    append = time.perf_counter() - start
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        back = store.load().frame
    read = time.perf_counter() - start
    assert len(back) == n
    return append, read


def bench_zarr(frames: list[pd.DataFrame], root: Path) -> tuple[float, float]:
    import xarray

    path = root / "samples.zarr"
    warnings.simplefilter("ignore")  # zarr's notes on string columns
    start = time.perf_counter()
    for i, frame in enumerate(frames):
        ds = frame.set_index("sample").to_xarray()
        if i == 0:
            ds.to_zarr(path, mode="w")
        else:
            ds.to_zarr(path, append_dim="sample")
    append = time.perf_counter() - start
    start = time.perf_counter()
    back = xarray.open_zarr(path).load().to_dataframe()
    read = time.perf_counter() - start
    assert len(back) == sum(len(f) for f in frames)
    return append, read


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--chunks", type=int, default=64)
    parser.add_argument("--rows", type=int, default=8)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    frames = [chunk_frame(i * args.rows, args.rows, rng) for i in range(args.chunks)]
    benches = {"parquet parts (loco.store)": bench_parquet}
    try:
        import zarr  # noqa: F401

        benches["zarr (xarray append)"] = bench_zarr
    except ImportError:
        print("zarr not installed: Parquet only")
    print(f"{args.chunks} chunks of {args.rows} samples, best of {args.repeat}")
    for label, bench in benches.items():
        best = (np.inf, np.inf)
        for _ in range(args.repeat):
            root = Path(tempfile.mkdtemp())
            try:
                a, r = bench(frames, root)
            finally:
                shutil.rmtree(root)
            best = (min(best[0], a), min(best[1], r))
        print(
            f"{label:28s} append {best[0] / args.chunks * 1e3:7.2f} ms/chunk, "
            f"read back {best[1] * 1e3:7.1f} ms"
        )


if __name__ == "__main__":
    main()
