"""Where the study's premise lives: the carbody mode and the bogie mode of the linearised vehicle
over conicity, contact family and yaw damping, and over speed.

The study's premise is that high yaw damping destabilises the carbody-coupled lateral mode on
low conicity (carbody hunting) while low yaw damping lets the bogies hunt on high conicity, so a
damper that is soft at the carbody's low frequency and stiff at the bogie's higher one gives the
best of both. :func:`premise_map` computes, at one speed, the damping ratio and frequency of the
two modes (:meth:`loco.stability.Eigen.carbody_mode`, :meth:`~loco.stability.Eigen.bogie_mode`)
with a Maxwell yaw damper of each damping in ``dampings`` (in series with the presets' 22.5 kN/mm)
for three contact families:

- ``knife-edge cone``: a conical wheel of each conicity on a knife-edge rail (Δr = 2·λ·y, no
  gravitational stiffness, no contact-angle or roll effects), the textbook model;
- ``cone on CN60``: a JM3 wheel whose tread is a straight cone of slope λ (``loco.profiles.jm3``
  with ``band_radius=inf``) on CN60 inclined 1:40: the same conicity with a real rail head,
  so the contact angle, roll and gravitational stiffness of a rounded rail;
- ``pair``: the study's and the field problem's real wheel/rail pairs
  (:data:`loco.contact_pairs.PAIRS`), each at its own linear conicity λ.

:func:`speed_sweep` gives the same two modes over speed for YD1 and YD2. :func:`premise_cells`
classifies each (family, conicity) of a map by the signs at the presets' dampings (200 and
800 kN·s/m): ``premise`` where the carbody mode is stable with 200 and unstable with 800,
``reverse`` where the bogie mode is unstable with 200 and stable with 800. :func:`plot_premise_map`
draws it all in one figure.
"""

from __future__ import annotations

import concurrent.futures
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from loco import _loco
from loco.contact_pairs import PAIRS, ContactPair
from loco.dampers import PRESETS, maxwell
from loco.profiles import builtin, jm3
from loco.simulation import Scenario
from loco.stability import eigen
from loco.studies.plotting import pyplot, save_figure
from loco.vehicle import Locomotive

__all__ = [
    "CONICITIES",
    "DAMPINGS",
    "FAMILIES",
    "MAP_COLUMNS",
    "SPEED",
    "plot_premise_map",
    "premise_cells",
    "premise_map",
    "speed_sweep",
]

#: The study speed, m/s (200 km/h).
SPEED = 200 / 3.6
#: Conicities of the cone families (–).
CONICITIES: tuple[float, ...] = tuple(np.round(np.linspace(0.01, 0.15, 15), 3))
#: Yaw dampings of the map, N·s/m (100–1000 kN·s/m).
DAMPINGS: tuple[float, ...] = tuple(np.arange(1, 11) * 100e3)
#: The contact families, in the order of the figure.
FAMILIES = ("knife-edge cone", "cone on CN60", "pair")
#: Columns of :func:`premise_map` and :func:`speed_sweep`.
MAP_COLUMNS = (
    "family",
    "pair",
    "conicity",
    "damping",
    "speed",
    "mode",
    "frequency",
    "damping_ratio",
)
#: The rail of the ``cone on CN60`` family and its inclination (1:40, the study's).
_CONE_RAIL = "cn60"
_CONE_CANT = 40
#: The presets' series stiffness, N/m (YD1 and YD2 share it).
_SERIES_STIFFNESS = float(PRESETS["YD1"].parameters()["series_stiffness"] or 0.0)


@dataclass(frozen=True)
class _Case:
    """One contact case of a map: a family, the pair's label, its conicity and its scenario
    settings (wheel, rail, inclination; or the knife-edge conicity)."""

    family: str
    pair: str
    conicity: float
    settings: tuple[tuple[str, Any], ...]
    knife_edge: float | None = None
    cone_tread: float | None = None

    def scenario(self, speed: float, damper: float | str) -> Scenario:
        """The case's scenario at ``speed`` (m/s) with a preset damper (its name) or a Maxwell
        yaw damper of ``damper`` N·s/m (built here: dampers and profiles stay in the process
        that uses them)."""
        settings = dict(self.settings)
        if self.cone_tread is not None:
            settings["wheel"] = jm3(tread_slope=self.cone_tread, band_radius=math.inf)
        yaw = damper if isinstance(damper, str) else maxwell(damper, _SERIES_STIFFNESS)
        return Scenario(speed=speed, yaw_damper=yaw, **settings)


def _cone_case(family: str, c: float) -> _Case:
    if family == "knife-edge cone":
        return _Case(family, f"cone {c:g}", c, (), knife_edge=c)
    inclination = math.atan(1.0 / _CONE_CANT)
    settings = (("rail", _CONE_RAIL), ("rail_inclination", inclination))
    return _Case(family, f"cone {c:g} on CN60 1:{_CONE_CANT}", c, settings, cone_tread=c)


def _pair_case(pair: ContactPair) -> _Case:
    from loco import contact

    wheel, rail = builtin(pair.wheel), builtin(pair.rail)
    lam = contact.linear_parameters(wheel, rail, rail_inclination=pair.inclination).conicity
    settings = (("wheel", pair.wheel), ("rail", pair.rail), ("rail_inclination", pair.inclination))
    return _Case("pair", pair.label, lam, settings)


def _cases(families: Sequence[str], conicities: Sequence[float]) -> list[_Case]:
    for f in families:
        if f not in FAMILIES:
            raise _loco.ParameterError(
                f"invalid parameter `families`: unknown family `{f}` (known: {', '.join(FAMILIES)})"
            )
    out: list[_Case] = []
    for f in families:
        if f == "pair":
            out.extend(_pair_case(p) for p in PAIRS)
        else:
            out.extend(_cone_case(f, float(c)) for c in conicities)
    return out


def _modes(
    args: tuple[Locomotive, _Case, Any, float],
) -> list[tuple[str, float, float]]:
    """(mode, frequency, damping ratio) of the carbody and bogie modes of one case; NaN where
    no mode passes the rule."""
    vehicle, case, damper, speed = args
    scenario = case.scenario(speed, damper)
    modes = eigen(vehicle, scenario, conicity=case.knife_edge)
    out = []
    for name, pick in (("carbody", modes.carbody_mode), ("bogie", modes.bogie_mode)):
        try:
            m = pick()
            out.append((name, m.frequency, m.damping_ratio))
        except _loco.ParameterError:
            out.append((name, math.nan, math.nan))
    return out


def _run(
    vehicle: Locomotive,
    tasks: list[tuple[_Case, Any, float, float]],
    executor: concurrent.futures.Executor | None,
    progress: bool,
    desc: str,
) -> pd.DataFrame:
    args = [(vehicle, case, damper, speed) for case, damper, speed, _ in tasks]
    results: Iterable[list[tuple[str, float, float]]]
    results = executor.map(_modes, args) if executor else map(_modes, args)
    if progress:
        from tqdm import tqdm

        results = tqdm(results, total=len(args), desc=desc, unit="eigen")
    rows = []
    for (case, _damper, speed, damping), modes in zip(tasks, results, strict=True):
        for mode, frequency, zeta in modes:
            rows.append(
                (case.family, case.pair, case.conicity, damping, speed, mode, frequency, zeta)
            )
    return pd.DataFrame(rows, columns=list(MAP_COLUMNS))


def premise_map(
    vehicle: Locomotive | None = None,
    *,
    conicities: Sequence[float] = CONICITIES,
    dampings: Sequence[float] = DAMPINGS,
    families: Sequence[str] = FAMILIES,
    speed: float = SPEED,
    executor: concurrent.futures.Executor | None = None,
    progress: bool = True,
) -> pd.DataFrame:
    """The carbody and bogie modes (frequency, Hz; damping ratio, –; NaN where no mode passes
    the rule) of ``vehicle`` at ``speed`` (m/s) for every contact case of ``families`` (the
    cone families at each of ``conicities``, the pairs at their own) and Maxwell yaw dampers of
    each of ``dampings`` (N·s/m) in series with 22.5 kN/mm: one row per case, damping and mode
    (columns :data:`MAP_COLUMNS`). ``executor``: any :class:`concurrent.futures.Executor`
    (default: one case after the other); the result does not depend on it."""
    vehicle = vehicle or Locomotive.default()
    cases = _cases(families, conicities)
    tasks = [(case, float(c), speed, float(c)) for case in cases for c in dampings]
    return _run(vehicle, tasks, executor, progress, "premise map")


def speed_sweep(
    vehicle: Locomotive | None = None,
    *,
    speeds: Sequence[float] = tuple(np.arange(100, 361, 20) / 3.6),
    cases: Sequence[tuple[str, float | str]] = (
        ("knife-edge cone", 0.04),
        ("pair", "jm3-thin-flange on cn60 1:40"),
        ("pair", "jm3-worn on cn60 1:40"),
    ),
    executor: concurrent.futures.Executor | None = None,
    progress: bool = True,
) -> pd.DataFrame:
    """The carbody and bogie modes over ``speeds`` (m/s) with YD1 and YD2 for each of ``cases``
    (a cone family and its conicity, or ``("pair", label)`` of :data:`loco.contact_pairs.PAIRS`
    as ``"<wheel> on <rail> 1:<cant>"``): columns :data:`MAP_COLUMNS`, ``damping`` the preset's."""
    vehicle = vehicle or Locomotive.default()
    chosen: list[_Case] = []
    pairs = {c.pair: c for c in _cases(("pair",), ())}
    for family, which in cases:
        if family == "pair":
            if which not in pairs:
                raise _loco.ParameterError(
                    f"invalid parameter `cases`: unknown pair `{which!s}` "
                    f"(known: {', '.join(pairs)})"
                )
            chosen.append(pairs[str(which)])
        else:
            chosen.append(_cases((family,), (float(which),))[0])
    tasks: list[tuple[_Case, Any, float, float]] = []
    for case in chosen:
        for name in ("YD1", "YD2"):
            damping = float(PRESETS[name].parameters()["damping"] or 0.0)
            tasks.extend((case, name, float(v), damping) for v in speeds)
    return _run(vehicle, tasks, executor, progress, "speed sweep")


def premise_cells(result: pd.DataFrame, low: float = 200e3, high: float = 800e3) -> pd.DataFrame:
    """Per (family, pair, conicity) of a :func:`premise_map`: the carbody and bogie damping
    ratios at the dampings ``low`` and ``high`` (N·s/m, default the presets YD1 and YD2) and
    ``premise`` (the carbody mode stable with ``low``, unstable with ``high``) and ``reverse``
    (the bogie mode unstable with ``low``, stable with ``high``)."""
    keys = ["family", "pair", "conicity"]
    rows = []
    for key, g in result.groupby(keys, sort=False):
        row = dict(zip(keys, key, strict=True))
        for mode in ("carbody", "bogie"):
            for tag, d in (("low", low), ("high", high)):
                hit = g[(g["mode"] == mode) & (g["damping"] == d)]["damping_ratio"]
                row[f"{mode}_zeta_{tag}"] = float(hit.iloc[0]) if len(hit) else math.nan
        rows.append(row)
    out = pd.DataFrame(rows)
    out["premise"] = (out["carbody_zeta_low"] > 0) & (out["carbody_zeta_high"] < 0)
    out["reverse"] = (out["bogie_zeta_low"] < 0) & (out["bogie_zeta_high"] > 0)
    return out


def plot_premise_map(
    result: pd.DataFrame, sweep: pd.DataFrame | None = None, path: str | Path | None = None
) -> Any:
    """One figure: per mode (rows) the damping ratio over conicity × yaw damping for the two
    cone families (colour, red unstable, blue stable, the ζ = 0 contour in black, grey where no
    mode passes the rule) and over yaw damping for the real pairs; with ``sweep``, a last row of
    the damping ratio over speed for YD1 and YD2. Saved to ``path`` when given."""
    from matplotlib.colors import TwoSlopeNorm

    plt = pyplot()
    rows = 3 if sweep is not None else 2
    fig, axes = plt.subplots(rows, 3, figsize=(15, 4.2 * rows), layout="constrained", squeeze=False)
    norm = TwoSlopeNorm(vmin=-0.1, vcenter=0.0, vmax=0.3)
    for r, mode in enumerate(("carbody", "bogie")):
        part = result[result["mode"] == mode]
        image = None
        for c, family in enumerate(("knife-edge cone", "cone on CN60")):
            ax = axes[r, c]
            g = part[part["family"] == family]
            if g.empty:
                ax.set_visible(False)
                continue
            grid = g.pivot_table(
                index="damping", columns="conicity", values="damping_ratio", dropna=False
            )
            x, y = grid.columns.to_numpy(float), grid.index.to_numpy(float) / 1e3
            z = grid.to_numpy(float)
            ax.set_facecolor("0.8")
            image = ax.pcolormesh(
                x, y, np.ma.masked_invalid(z), cmap="RdBu", norm=norm, shading="nearest"
            )
            if np.isfinite(z).sum() > 3 and np.nanmin(z) < 0 < np.nanmax(z):
                ax.contour(
                    x,
                    y,
                    np.where(np.isfinite(z), z, np.nan),
                    levels=[0.0],
                    colors="k",
                    linewidths=1.2,
                )
            for d, style in ((200, ":"), (800, "--")):
                ax.axhline(d, color="k", lw=0.7, ls=style)
            ax.set(
                xlabel="conicity λ (–)",
                ylabel="yaw damping (kN·s/m)",
                title=f"{mode} mode, {family}",
            )
        if image is not None:
            fig.colorbar(image, ax=axes[r, :2], label="damping ratio ζ (–)", shrink=0.9)
        ax = axes[r, 2]
        pairs = part[part["family"] == "pair"]
        for i, (label, g) in enumerate(pairs.groupby("pair", sort=False)):
            lam = g["conicity"].iloc[0]
            ax.plot(
                g["damping"] / 1e3,
                g["damping_ratio"],
                "o-",
                ms=3,
                color=f"C{i}",
                label=f"{label} (λ {lam:.3f})",
            )
        ax.axhline(0.0, color="k", lw=0.8)
        ax.set(
            xlabel="yaw damping (kN·s/m)",
            ylabel="damping ratio ζ (–)",
            title=f"{mode} mode, real pairs",
        )
        if r == 0:
            ax.legend(fontsize=6.5)
    if sweep is not None:
        for c, (label, g) in enumerate(sweep.groupby("pair", sort=False)):
            if c > 2:
                break
            ax = axes[2, c]
            for mode, marker in (("carbody", "o"), ("bogie", "s")):
                for damping, style in ((200e3, ":"), (800e3, "-")):
                    h = g[(g["mode"] == mode) & (g["damping"] == damping)]
                    name = "YD1" if damping == 200e3 else "YD2"
                    ax.plot(
                        h["speed"] * 3.6,
                        h["damping_ratio"],
                        marker + style,
                        ms=3,
                        label=f"{mode}, {name}",
                    )
            ax.axhline(0.0, color="k", lw=0.8)
            ax.axvline(200.0, color="0.5", lw=0.6)
            ax.set(
                xlabel="speed (km/h)", ylabel="damping ratio ζ (–)", title=f"over speed: {label!s}"
            )
            ax.legend(fontsize=7)
    if path is not None:
        save_figure(fig, path)
    return fig
