"""Morris elementary effects from trajectories with missing outputs.

SALib's ``morris.analyze`` needs every point of a trajectory; a trajectory with one output the
model cannot give (a mode rule that finds no mode, a wheel construction with no tread) would be
dropped whole, and with it the effects of every other input along it. Here each step of a
trajectory (one input moved by ±Δ of its range between consecutive points, Morris 1991) gives
one elementary effect where both its points have a finite output, so a missing point loses only
the two steps that touch it. With no missing output the statistics are SALib's: ``mu_star`` the
mean absolute effect, ``mu`` the mean, ``sigma`` the standard deviation (ddof 1), and
``mu_star_conf`` the half-width of the 95 % bootstrap interval of ``mu_star`` (1000 resamples).
Effects are in the output's unit for a step across the input's whole range. :func:`plot_morris`
draws μ* against σ.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import pandas as pd

__all__ = ["elementary_effects", "plot_morris"]

#: Bootstrap resamples of the interval of μ*.
RESAMPLES = 1000


def elementary_effects(
    x: npt.ArrayLike,
    y: npt.ArrayLike,
    low: npt.ArrayLike,
    high: npt.ArrayLike,
    names: list[str],
    seed: int = 0,
) -> pd.DataFrame:
    """Per input (``names``, ranges ``low``–``high``): ``mu_star``, ``mu``, ``sigma``,
    ``mu_star_conf`` and ``effects`` (how many steps gave an effect) from the Morris points
    ``x`` (rows: ``trajectories × (inputs + 1)`` points, trajectory after trajectory) and their
    outputs ``y`` (NaN where the model gives none)."""
    xs = np.asarray(x, dtype=float)
    ys = np.asarray(y, dtype=float)
    lo, hi = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
    k = len(names)
    per = k + 1
    unit = (xs - lo) / (hi - lo)
    effects: list[list[float]] = [[] for _ in range(k)]
    for start in range(0, len(xs), per):
        for step in range(start, start + k):
            moved = unit[step + 1] - unit[step]
            i = int(np.argmax(np.abs(moved)))
            if not (np.isfinite(ys[step]) and np.isfinite(ys[step + 1])):
                continue
            effects[i].append((ys[step + 1] - ys[step]) / moved[i])
    rng = np.random.default_rng(seed)
    rows = []
    for name, e in zip(names, effects, strict=True):
        ee = np.asarray(e)
        if len(ee) == 0:
            rows.append((name, np.nan, np.nan, np.nan, np.nan, 0))
            continue
        boot = np.abs(ee[rng.integers(0, len(ee), size=(RESAMPLES, len(ee)))]).mean(axis=1)
        sigma = float(ee.std(ddof=1)) if len(ee) > 1 else np.nan
        conf = 1.96 * float(boot.std(ddof=1))
        rows.append((name, float(np.abs(ee).mean()), float(ee.mean()), sigma, conf, len(ee)))
    return pd.DataFrame(
        rows, columns=["input", "mu_star", "mu", "sigma", "mu_star_conf", "effects"]
    )


def plot_morris(result: pd.DataFrame, top: int = 5, path: str | Path | None = None) -> Any:
    """μ* against σ per output (one panel each) of a :func:`loco.uncertainty.morris` table, the
    ``top`` inputs of each labelled; saved to ``path`` when given. Returns the matplotlib
    figure."""
    import matplotlib

    if path is not None:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(dict.fromkeys(result["output"]))
    cols = min(len(names), 3)
    rows = math.ceil(len(names) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 4.2 * rows), squeeze=False)
    for ax, name in zip(axes.flat, names, strict=False):
        part = result[result["output"] == name].sort_values("mu_star", ascending=False)
        ax.scatter(part["mu_star"], part["sigma"], s=12, color="0.5")
        for _, r in part.head(top).iterrows():
            ax.scatter([r["mu_star"]], [r["sigma"]], s=18, color="C3")
            ax.annotate(r["input"], (r["mu_star"], r["sigma"]), fontsize=7)
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("μ*")
        ax.set_ylabel("σ")
    for ax in list(axes.flat)[len(names) :]:
        ax.set_visible(False)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=130)
    return fig
