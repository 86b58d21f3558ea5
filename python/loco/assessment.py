"""One run assessed as EN 14363 and EN 12299 do it: :func:`assess`.

The quantities the model gives, per zone of track (each straight and each circular curve of the
run's designed alignment; the whole record on straight track), with the processing of
:mod:`loco.studies.en14363` (2 m sliding means every 0.5 m, 0.15 / 99.85 % percentiles, 50 %
quasi-static values):

- running safety: (Y/Q)_2m of every wheel against 0.8 (Nadal), the bogie frame's stability by
  the simplified method (sliding rms of the f0 ± 2 Hz band-passed frame acceleration against
  ``(12 − m⁺/5)/2``, m⁺ the EN 14363 bogie mass, ``Locomotive.en14363_bogie_mass``) and whether
  the frame settles into a limit cycle (hunting, named at its frequency and amplitude; no limit);
- track loading: (ΣY)_2m of every wheelset against ``α(10 + 2Q0/3)`` kN (Prud'homme), Q_max
  (99.85 %) against ``90 kN + Q0`` capped by speed, and in curves Y_qst and Q_qst (50 %)
  against 60 kN and 145 kN, assessed in the small-radius zone 250 m ≤ R < 400 m (elsewhere a
  reference);
- ride: in curves the carbody's quasi-static lateral acceleration ÿ*_qst (50 % of what the floor
  accelerometers read, channels of kind ``accelerometer``) against 1.5 m/s², and in every zone
  the EN 12299 mean comfort index N_MV from the floor accelerometers (classed on EN 12299's
  scale, no pass or fail).

Every limit carries where it was read; the standards' own texts were not reached, so every
limit value is from a secondary source (the literature quoting them), and the table says so.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from loco import _loco, metrics
from loco.assessment_zones import Zone, wheelset_offsets, zones
from loco.channels import ChannelKind, Metric
from loco.simulation import SimulationResult
from loco.studies import en14363
from loco.vehicle import Locomotive

__all__ = [
    "COMFORT_CLASSES",
    "LIMIT_CYCLES",
    "SOURCES",
    "VEHICLE_CLASSES",
    "Assessment",
    "Quantity",
    "Zone",
    "assess",
    "hunts",
    "stability_quantities",
    "wheelset_offsets",
    "zones",
]

#: α of the ΣY limit by vehicle class (:mod:`loco.studies.en14363`).
VEHICLE_CLASSES: dict[str, float] = {
    "locomotive": en14363.ALPHA_LOCOMOTIVE,
    "passenger": en14363.ALPHA_LOCOMOTIVE,
    "freight": en14363.ALPHA_FREIGHT,
}
#: EN 12299's comfort scale of N_MV: (upper bound, class), the last open.
COMFORT_CLASSES: tuple[tuple[float, str], ...] = (
    (1.5, "very comfortable"),
    (2.5, "comfortable"),
    (3.5, "medium"),
    (4.5, "uncomfortable"),
    (math.inf, "very uncomfortable"),
)

_SECONDARY = "secondary: as commonly quoted from EN 14363 / UIC 518 in the literature"
#: Where each limit was read, by quantity key.
SOURCES: dict[str, str] = {
    "YQ": "UIC 518:2009 as summarised at railwaynews.net (" + _SECONDARY + ")",
    "sumY": "Prud'homme's form (Civil Engineering 27(5); UIC 716 at railwaynews.net); α "
    + _SECONDARY,
    "Qmax": _SECONDARY + ", not confirmed by a searched text",
    "Yqst": _SECONDARY + ", not confirmed by a searched text (the TSI LOC&PAS sets a Y_qst limit)",
    "Qqst": _SECONDARY + ", not confirmed by a searched text",
    "yqst": _SECONDARY + ", not confirmed by a searched text",
    **{
        k: "normal method, 0.4–10 Hz, as recalled from the literature quoting EN 14363 / UIC 518; "
        "not confirmed by a searched text"
        for k in ("ydd_max", "ydd_rms", "zdd_max", "zdd_rms")
    },
    "stability": "EN 14363:2016 simplified method, (12 − m⁺/5)/2 (" + _SECONDARY + ")",
    "limit_cycle": "loco's limit-cycle rule (the core's metrics::limit_cycle); no standard limit",
    "nmv": "EN 12299 N_MV (the core's metrics::comfort); its comfort scale " + _SECONDARY,
}


@dataclass(frozen=True)
class Quantity:
    """One assessed quantity: ``key`` (a key of :data:`SOURCES`), its name, its value and limit
    in SI ``unit`` (``limit`` NaN: none), whether it passes (``None``: no limit, or not assessed
    in this zone, ``note`` says which), the limit's ``source`` and whether that is a
    ``secondary`` one."""

    key: str
    quantity: str
    zone: str
    value: float
    limit: float
    unit: str
    passed: bool | None
    source: str
    secondary: bool
    note: str = ""


@dataclass(frozen=True)
class Assessment:
    """Every quantity of one run (:func:`assess`)."""

    quantities: tuple[Quantity, ...]

    def frame(self) -> pd.DataFrame:
        """One row per quantity (the fields of :class:`Quantity`)."""
        return pd.DataFrame([asdict(q) for q in self.quantities])

    def passed(self) -> bool:
        """Whether every quantity with a verdict passes."""
        return all(q.passed is not False for q in self.quantities)

    def get(self, key: str, zone: str) -> Quantity:
        """The quantity ``key`` (a key of :data:`SOURCES`) in the zone called ``zone``."""
        for q in self.quantities:
            if q.key == key and q.zone == zone:
                return q
        raise KeyError(f"no quantity {key!r} in zone {zone!r}")

    def figure(self, path: str | Path) -> Path:
        """A bar per quantity with a limit: its value over its limit (1 is the limit)."""
        import matplotlib.pyplot as plt

        limited = [q for q in self.quantities if math.isfinite(q.limit) and q.limit > 0]
        fig, ax = plt.subplots(figsize=(9, 0.35 * len(limited) + 1.5), layout="constrained")
        ratios = [abs(q.value) / q.limit for q in limited]
        colours = ["tab:red" if q.passed is False else "tab:blue" for q in limited]
        labels = [f"{q.quantity} ({q.zone})" for q in limited]
        ax.barh(range(len(limited)), ratios, color=colours)
        ax.axvline(1.0, color="k", lw=1)
        ax.set_yticks(range(len(limited)), labels, fontsize="small")
        ax.invert_yaxis()
        ax.set_xlabel("value / limit (–)")
        ax.set_title("EN 14363 assessment: value over limit (limits from secondary sources)")
        out = Path(path)
        fig.savefig(out, dpi=110)
        plt.close(fig)
        return out


def _row(
    key: str,
    quantity: str,
    zone: str,
    value: float,
    limit: float,
    unit: str,
    assessed: bool = True,
    note: str = "",
) -> Quantity:
    passed = None if not assessed or not math.isfinite(value) else bool(abs(value) <= limit)
    return Quantity(key, quantity, zone, value, limit, unit, passed, SOURCES[key], True, note)


#: The limit-cycle metrics of each body: (flag, frequency, amplitude).
LIMIT_CYCLES: dict[str, tuple[str, str, str]] = {
    "bogie frame": (Metric.AYB_LIMIT_CYCLE, Metric.AYB_CYCLE_HZ, Metric.AYB_CYCLE_AMPLITUDE),
    "carbody": (Metric.AYC_LIMIT_CYCLE, Metric.AYC_CYCLE_HZ, Metric.AYC_CYCLE_AMPLITUDE),
}


def hunts(run_metrics: Mapping[str, float], body: str = "bogie frame") -> bool | None:
    """Whether the run's ``body`` (a key of :data:`LIMIT_CYCLES`) settled into a sustained limit
    cycle (the core's limit-cycle flag; ``None``: undefined, a record too short for it)."""
    cycle = float(run_metrics[LIMIT_CYCLES[body][0]])
    return None if math.isnan(cycle) else cycle == 1.0


def _cycle_quantity(run_metrics: Mapping[str, float], body: str, zone: str) -> Quantity:
    _, hz_key, amplitude_key = LIMIT_CYCLES[body]
    hz, amplitude = run_metrics[hz_key], run_metrics[amplitude_key]
    hunting = hunts(run_metrics, body)
    note = {
        True: f"hunts: limit cycle {hz:.1f} Hz, ±{amplitude:.1f} m/s²",
        False: "no sustained limit cycle",
        None: "undefined (record too short)",
    }[hunting]
    value = amplitude if hunting else 0.0
    source = SOURCES["limit_cycle"]
    return Quantity(
        "limit_cycle",
        f"{body} limit cycle amplitude",
        zone,
        value,
        math.nan,
        "m/s²",
        None,
        source,
        False,
        note,
    )


def stability_quantities(
    run_metrics: Mapping[str, float], zone: str = "whole run"
) -> list[Quantity]:
    """The bogie frame's stability by the simplified method and the limit cycles of the frame
    and the carbody, from a run's core metrics (the verdict reads these per track)."""
    rms, limit = run_metrics[Metric.AYB_EN_RMS], run_metrics[Metric.AYB_EN_LIMIT]
    return [
        _row("stability", "bogie frame sliding rms (f0 ± 2 Hz)", zone, rms, limit, "m/s²"),
        *(_cycle_quantity(run_metrics, body, zone) for body in LIMIT_CYCLES),
    ]


def _comfort(result: SimulationResult, inside: np.ndarray, y: str, z: str) -> tuple[float, str]:
    fs = result.sampling_rate
    if inside.sum() < 5.0 * fs:
        return math.nan, "zone shorter than one 5 s block"
    ay = result.channel(y)[inside]
    az = result.channel(z)[inside]
    nmv = metrics.comfort_nmv(fs, ay=ay, az=az - az.mean())
    label = next(c for bound, c in COMFORT_CLASSES if nmv < bound)
    return nmv, f"{label} (EN 12299 scale)"


def _ride(filtered: dict[str, list[np.ndarray]], inside: np.ndarray, zone: str) -> list[Quantity]:
    """The normal method's ride characteristics of one zone: ÿ* and z̈* (band-passed floor
    accelerometers), their maximum (the larger percentile magnitude) and rms, the worst point."""
    out = []
    for axis, symbol in (("y", "ÿ*"), ("z", "z̈*")):
        values = [en14363.ride_values(f[inside]) for f in filtered[axis]]
        if not values:
            continue
        peak, rms = (max((v[k] for v in values), default=math.nan) for k in range(2))
        for kind, value, what in (("max", peak, "max (0.15/99.85 %)"), ("rms", rms, "rms")):
            key = f"{axis}dd_{kind}"
            name = f"{symbol} {what}, carbody floor, 0.4–10 Hz"
            out.append(_row(key, name, zone, value, en14363.RIDE_LIMITS[key], "m/s²"))
    return out


def assess(
    result: SimulationResult,
    vehicle: Locomotive | None = None,
    *,
    curve: Sequence[Mapping[str, Any]] | str | Path | None = None,
    lead_in: float = 0.0,
    speed: float | None = None,
    vehicle_class: str = "locomotive",
) -> Assessment:
    """The EN 14363 / EN 12299 quantities of ``result`` (module docstring).

    ``vehicle`` is the run's (default: the embedded locomotive; its axle load and geometry set
    the limits and where each wheelset is), ``curve`` the run's designed alignment (``None``:
    straight track), ``lead_in`` the distance run before the record (m), ``speed`` the running
    speed (m/s; default the result's), ``vehicle_class`` a key of :data:`VEHICLE_CLASSES`.
    """
    if vehicle_class not in VEHICLE_CLASSES:
        raise _loco.ParameterError(
            f"invalid parameter `vehicle_class`: {vehicle_class!r}, expected one of "
            f"{sorted(VEHICLE_CLASSES)}"
        )
    vehicle = vehicle or Locomotive.default()
    v = float(speed if speed is not None else result.parameters["speed"])
    lead = lead_in + v * result.time
    offsets = wheelset_offsets(vehicle)
    axle_load = vehicle.native.mean_axle_load()
    sum_y_limit = en14363.sum_y_limit(axle_load, VEHICLE_CLASSES[vehicle_class])
    q_max_limit = en14363.q_max_limit(v, axle_load / 2.0)
    wheel, wheelset = _loco.wheel_channels(), _loco.wheelset_channels()
    floor = [n for n in result.channels_of_kind(ChannelKind.ACCELEROMETER) if "carbody" in n]
    floor_y = [n for n in floor if "_y_" in n]
    floor_z = [n for n in floor if "_z_" in n]
    # The carbody's centre runs midway between the bogies' pivots.
    body_lead = lead - 0.5 * (offsets[1] + offsets[3])
    # The ride characteristics' band pass over the whole record (no edge effects at the zones).
    filtered = {
        axis: [en14363.ride_filtered(result.channel(n), result.sampling_rate) for n in names]
        for axis, names in (("y", floor_y), ("z", floor_z))
    }
    out: list[Quantity] = []
    for zone in zones(curve, float(lead[-1])):
        z = zone.name
        sum_y, yq, q_max, yqst, qqst = [], [], [], [], []
        for w, offset in enumerate(offsets):
            s = lead - offset
            inside = (s >= zone.start) & (s <= zone.end)
            sum_y.append(
                en14363.section_values(
                    s, result.channel(wheelset["sumY"][w]), zone.start, zone.end
                ).extreme
            )
            for side in range(2):
                i = 2 * w + side
                yq.append(
                    en14363.section_values(
                        s, result.channel(wheel["YQ"][i]), zone.start, zone.end
                    ).extreme
                )
                q = result.channel(wheel["Q"][i])[inside]
                y = result.channel(wheel["Y"][i])[inside]
                q_max.append(float(np.percentile(q, en14363.Q_PERCENTILE)) if q.size else np.nan)
                yqst.append(abs(float(np.median(y))) if y.size else np.nan)
                qqst.append(float(np.median(q)) if q.size else np.nan)
        if all(math.isnan(x) for x in sum_y):
            continue  # no full 2 m window of this zone in the record
        yq_limit = en14363.YQ_LIMIT
        assessed = not zone.curved or abs(zone.radius) >= en14363.MIN_ASSESSED_RADIUS
        note = "" if assessed else "R < 250 m: outside EN 14363's running tests"
        out += [
            _row("YQ", "(Y/Q)_2m, largest wheel", z, np.nanmax(yq), yq_limit, "–", assessed, note),
            _row("sumY", "(ΣY)_2m, largest wheelset", z, np.nanmax(sum_y), sum_y_limit, "N"),
            _row("Qmax", "Q_max (99.85 %), largest wheel", z, np.nanmax(q_max), q_max_limit, "N"),
        ]
        inside_body = (body_lead >= zone.start) & (body_lead <= zone.end)
        if zone.curved:
            small = en14363.quasi_static_assessed(zone.radius)
            ref = "" if small else "a reference: assessed for 250 m ≤ R < 400 m"
            lateral = [abs(float(np.median(result.channel(n)[inside_body]))) for n in floor_y]
            out += [
                _row(
                    "Yqst",
                    "Y_qst (50 %), largest wheel",
                    z,
                    np.nanmax(yqst),
                    en14363.YQST_LIMIT,
                    "N",
                    small,
                    ref,
                ),
                _row(
                    "Qqst",
                    "Q_qst (50 %), largest wheel",
                    z,
                    np.nanmax(qqst),
                    en14363.QQST_LIMIT,
                    "N",
                    small,
                    ref,
                ),
                _row(
                    "yqst",
                    "ÿ*_qst (50 %), carbody floor accelerometer",
                    z,
                    max(lateral, default=math.nan),
                    en14363.YDD_QST_LIMIT,
                    "m/s²",
                ),
            ]
        out += _ride(filtered, inside_body, z)
        if floor_y and floor_z:
            nmv, label = _comfort(result, inside_body, floor_y[0], floor_z[0])
            out.append(
                Quantity(
                    "nmv",
                    "N_MV (EN 12299, lateral and vertical)",
                    z,
                    nmv,
                    math.nan,
                    "–",
                    None,
                    SOURCES["nmv"],
                    True,
                    label,
                )
            )
    out += stability_quantities(result.metrics)
    return Assessment(tuple(out))
