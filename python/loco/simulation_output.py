"""The files one run writes (``loco simulate --out DIR``) and how to read them back.

The layout, every name defined here once:

- ``histories.nc``: NetCDF-4 (xarray, netcdf4 engine): every channel on a ``time`` coordinate
  (s), each variable with its SI ``units`` and its ``kind``; the metrics as attributes.
- ``histories.parquet``: the same table, a ``time`` column (s) and one column per channel.
- ``metrics.json``: ``{"metrics": {name: value}, "units": {name: unit}}``; an undefined metric
  (a run too short for it) is ``null``.
- ``run.json``: ``loco_version``, the ``vehicle`` file (``null``: the embedded vehicle), every
  ``scenario`` setting as run (given or default; speed in m/s), the run ``statistics``
  (``rhs_evaluations``, ``steps``, ``newton_iterations``, ``wall_time`` in s), the ``channels``
  (name, unit, kind) and the ``files`` written.
- figures: ``accelerations.png`` (carbody floor and bogie frame accelerations),
  ``wheelsets.png`` (wheelset lateral displacements and yaw angles) and, on a run with a curve,
  ``curving.png`` (Y/Q and ΔQ/Q of every wheel).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Final

import numpy as np
import numpy.typing as npt
import pandas as pd
import xarray

from loco import _loco
from loco.channels import ChannelInfo, ChannelKind, metric_table
from loco.simulation import SimulationResult

__all__ = [
    "ACCELERATION_FIGURE",
    "CURVING_FIGURE",
    "HISTORIES_NETCDF",
    "HISTORIES_PARQUET",
    "METRICS_JSON",
    "NETCDF_ENGINE",
    "RUN_JSON",
    "WHEELSET_FIGURE",
    "SimulationOutput",
    "load_histories",
    "load_result",
    "write_simulation",
]

HISTORIES_NETCDF = "histories.nc"
HISTORIES_PARQUET = "histories.parquet"
METRICS_JSON = "metrics.json"
RUN_JSON = "run.json"
ACCELERATION_FIGURE = "accelerations.png"
WHEELSET_FIGURE = "wheelsets.png"
CURVING_FIGURE = "curving.png"
#: The xarray engine the NetCDF file is written and read with (the ``netCDF4`` package).
NETCDF_ENGINE: Final = "netcdf4"

#: Wheel channels of the curving figure: name suffix, axis label.
_CURVING_QUANTITIES = (("_YQ", "Y/Q (–)"), ("_dQQ", "ΔQ/Q (–)"))


@dataclass(frozen=True)
class SimulationOutput:
    """What :func:`write_simulation` wrote: every file, in the order written."""

    directory: Path
    files: tuple[Path, ...]


def _finite_or_none(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def _dataset(result: SimulationResult, channels: tuple[ChannelInfo, ...]) -> xarray.Dataset:
    ds = result.to_xarray()
    ds["time"].attrs["units"] = "s"
    for info in channels:
        ds[info.name].attrs.update(units=info.unit, kind=info.kind)
    return ds


def _figure_accelerations(
    result: SimulationResult, kinds: dict[str, ChannelInfo], path: Path
) -> None:
    import matplotlib.pyplot as plt

    names = [n for n in result.channel_names if kinds[n].kind == ChannelKind.ACCELERATION]
    carbody = [n for n in names if n.startswith("carbody")]
    groups = [
        ("carbody floor, lateral", [n for n in carbody if "_ay_" in n]),
        ("carbody floor, vertical", [n for n in carbody if "_az_" in n]),
        ("bogie frames, lateral", [n for n in names if n not in carbody]),
    ]
    fig, axes = plt.subplots(len(groups), 1, figsize=(10, 8), sharex=True, layout="constrained")
    for ax, (title, group) in zip(axes, groups, strict=True):
        for n in group:
            ax.plot(result.time, result.channel(n), lw=0.6, label=n)
        unit = kinds[group[0]].unit if group else "m/s²"
        ax.set_ylabel(f"acceleration ({unit})")
        ax.set_title(title)
        ax.legend(fontsize="x-small", ncol=2, loc="upper right")
    axes[-1].set_xlabel("time (s)")
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _plot_panels(
    result: SimulationResult,
    panels: list[tuple[str, list[tuple[str, npt.NDArray[np.float64]]]]],
    title: str,
    path: Path,
) -> None:
    """Time histories in panels one above the other: per panel its axis label and its
    ``(legend, values)`` series."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(panels), 1, figsize=(10, 6.5), sharex=True, layout="constrained")
    for ax, (label, series) in zip(axes, panels, strict=True):
        for legend, values in series:
            ax.plot(result.time, values, lw=0.7, label=legend)
        ax.set_ylabel(label)
        ax.legend(fontsize="x-small", ncol=4, loc="upper right")
    axes[0].set_title(title)
    axes[-1].set_xlabel("time (s)")
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _figure_wheelsets(result: SimulationResult, kinds: dict[str, ChannelInfo], path: Path) -> None:
    names = [n for n in result.channel_names if kinds[n].kind == ChannelKind.WHEELSET_MOTION]
    panels = [
        (label, [(n, result.channel(n) * 1e3) for n in names if n.endswith(suffix)])
        for suffix, label in (("_y", "lateral displacement (mm)"), ("_yaw", "yaw angle (mrad)"))
    ]
    _plot_panels(result, panels, "wheelsets (relative to the track)", path)


def _figure_curving(result: SimulationResult, kinds: dict[str, ChannelInfo], path: Path) -> None:
    wheel = [n for n in result.channel_names if kinds[n].kind == ChannelKind.WHEEL]
    panels = [
        (label, [(n.removesuffix(suffix), result.channel(n)) for n in wheel if n.endswith(suffix)])
        for suffix, label in _CURVING_QUANTITIES
    ]
    _plot_panels(result, panels, "wheel forces on the curve", path)


def write_simulation(
    result: SimulationResult,
    channels: tuple[ChannelInfo, ...],
    out: Path,
    *,
    run_record: dict[str, Any],
    curved: bool,
    figures: bool = True,
) -> SimulationOutput:
    """Writes ``result`` into ``out`` in the layout of this module.

    ``channels`` are the vehicle's channels (:func:`loco.channels.channel_table`), ``run_record``
    the settings that go into ``run.json`` beside the statistics, channels and files; ``curved``
    adds the curving figure."""
    kinds = {c.name: c for c in channels}
    written: list[Path] = []

    ds = _dataset(result, channels)
    ds.to_netcdf(out / HISTORIES_NETCDF, engine=NETCDF_ENGINE)
    written.append(out / HISTORIES_NETCDF)

    frame = pd.DataFrame(result.channels.T, columns=result.channel_names)
    frame.insert(0, "time", result.time)
    frame.to_parquet(out / HISTORIES_PARQUET, index=False)
    written.append(out / HISTORIES_PARQUET)

    units = {m.name: m.unit for m in metric_table()}
    metrics = {
        "metrics": {k: _finite_or_none(v) for k, v in result.metrics.items()},
        "units": {k: units.get(k, "") for k in result.metrics},
    }
    (out / METRICS_JSON).write_text(json.dumps(metrics, indent=2, ensure_ascii=False) + "\n")
    written.append(out / METRICS_JSON)

    if figures:
        _figure_accelerations(result, kinds, out / ACCELERATION_FIGURE)
        _figure_wheelsets(result, kinds, out / WHEELSET_FIGURE)
        written += [out / ACCELERATION_FIGURE, out / WHEELSET_FIGURE]
        if curved:
            _figure_curving(result, kinds, out / CURVING_FIGURE)
            written.append(out / CURVING_FIGURE)

    written.append(out / RUN_JSON)
    record = {
        "loco_version": _loco.__version__,
        **run_record,
        "statistics": dict(result.statistics),
        "channels": [{"name": c.name, "unit": c.unit, "kind": c.kind} for c in channels],
        "files": [p.name for p in written],
    }
    (out / RUN_JSON).write_text(
        json.dumps(record, indent=2, ensure_ascii=False, default=_json_value) + "\n"
    )
    return SimulationOutput(out, tuple(written))


def _json_value(value: object) -> object:
    """Settings that are not JSON types: tuples (lists), paths and profiles (their text)."""
    if isinstance(value, np.generic):
        return value.item()
    return str(value)


def load_histories(directory: str | Path) -> xarray.Dataset:
    """The time histories a run wrote into ``directory``, from its NetCDF file."""
    with xarray.open_dataset(Path(directory) / HISTORIES_NETCDF, engine=NETCDF_ENGINE) as ds:
        return ds.load()


def load_result(directory: str | Path) -> tuple[SimulationResult, dict[str, Any]]:
    """The run a ``loco simulate`` wrote into ``directory`` as a :class:`SimulationResult`
    (channels from the NetCDF file, metrics from ``metrics.json``, NaN where undefined, kinds
    from ``run.json``), with the ``run.json`` record (its ``scenario`` settings as run)."""
    path = Path(directory)
    for name in (HISTORIES_NETCDF, METRICS_JSON, RUN_JSON):
        if not (path / name).is_file():
            raise _loco.LocoIOError(
                f"{path / name}: missing: not the output directory of `loco simulate`"
            )
    record = json.loads((path / RUN_JSON).read_text())
    values = json.loads((path / METRICS_JSON).read_text())["metrics"]
    ds = load_histories(path)
    names = [c["name"] for c in record["channels"]]
    result = SimulationResult(
        time=ds["time"].to_numpy(),
        channel_names=names,
        channels=np.stack([ds[n].to_numpy() for n in names]),
        metrics={k: math.nan if v is None else float(v) for k, v in values.items()},
        sampling_rate=float(ds.attrs["sampling_rate_hz"]),
        parameters={
            "speed": record["scenario"]["speed"],
            "distance": record["scenario"]["distance"],
        },
        statistics=dict(record.get("statistics", {})),
        channel_kinds={c["name"]: c["kind"] for c in record["channels"]},
    )
    return result, record
