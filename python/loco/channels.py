"""The core's names of run metrics and output channel kinds, as constants.

Every name here comes from the Rust core, where it is defined once: :class:`Metric` has one
constant per run metric (``Metric.WY_MAX == "wy_max"``, generated from the core's metric table),
:class:`ChannelKind` one per family of output channels (``ChannelKind.DAMPER_VALVE``). Code that
selects a metric or a channel family uses these constants, not retyped strings, so a renamed
metric fails at import rather than reading a missing column.

>>> import loco
>>> loco.Metric.WY_MAX
'wy_max'
>>> METRIC_NAMES[:2]
('wy_mean', 'wy_max')
"""

from __future__ import annotations

from dataclasses import dataclass

from loco import _loco
from loco._loco import ChannelKind, Metric

__all__ = [
    "CHANNEL_KINDS",
    "METRIC_NAMES",
    "ChannelInfo",
    "ChannelKind",
    "Metric",
    "MetricInfo",
    "channel_kinds_of",
    "channel_table",
    "metric_table",
]


@dataclass(frozen=True)
class MetricInfo:
    """One row of the core's metric table."""

    name: str
    unit: str
    description: str
    #: A flag: 0/1 in the results, NaN when undefined.
    flag: bool


@dataclass(frozen=True)
class ChannelInfo:
    """One output channel of a vehicle: name, SI unit and kind (a :class:`ChannelKind`)."""

    name: str
    unit: str
    kind: str


def metric_table() -> tuple[MetricInfo, ...]:
    """Every run metric, in the order of the metric columns."""
    return tuple(MetricInfo(*row) for row in _loco.metric_table())


def channel_table(vehicle: _loco.Vehicle) -> tuple[ChannelInfo, ...]:
    """Every output channel a run of ``vehicle`` (a ``Locomotive.native``) records, in order."""
    return tuple(ChannelInfo(*row) for row in _loco.channel_table(vehicle))


def channel_kinds_of(vehicle: _loco.Vehicle) -> dict[str, str]:
    """The kind of each output channel of ``vehicle``, by channel name."""
    return {c.name: c.kind for c in channel_table(vehicle)}


#: Names of the run metrics, in column order.
METRIC_NAMES: tuple[str, ...] = tuple(m.name for m in metric_table())
#: Names of the channel kinds, in the core's order.
CHANNEL_KINDS: tuple[str, ...] = tuple(_loco.channel_kinds())
