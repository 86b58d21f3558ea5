"""Figures of the studies: the headless Matplotlib setup, saving, and the shared PSD drawing.

Matplotlib loads only when a figure is drawn (:func:`pyplot`), on the non-interactive Agg
backend so that the studies run without a display.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = ["DPI", "Spectrum", "draw_intervals", "draw_spectra", "pyplot", "save_figure"]

FloatArray = npt.NDArray[np.float64]

#: Resolution of every saved figure, dots per inch.
DPI = 120


def pyplot() -> Any:
    """``matplotlib.pyplot`` on the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save_figure(fig: Any, path: str | Path) -> Path:
    """Save ``fig`` as PNG at :data:`DPI` (parent directories created), close it, return the
    path."""
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=DPI)
    pyplot().close(fig)
    return out


@dataclass(frozen=True)
class Spectrum:
    """Welch PSD of one channel of one run (:func:`loco.metrics.psd`, for drawing) and its peak
    as the core's run metrics give it."""

    frequency: FloatArray
    """Frequencies, Hz."""
    density: FloatArray
    """PSD, (m/s²)²/Hz."""
    dominant_hz: float
    """Frequency of the PSD peak (the run metric, e.g. ``ayc_dominant_hz``), Hz."""
    peak: float
    """PSD at the peak (the run metric, e.g. ``ayc_psd_peak``), (m/s²)²/Hz."""


def draw_spectra(
    ax: Any, lines: Mapping[str, Spectrum | None], label: str, title: str, fmax: float
) -> None:
    """Draw PSDs on a log axis up to ``fmax`` (Hz), one line per name with its dominant frequency
    and PSD peak in the legend; ``label`` names the signal (e.g. A_yc). None entries are skipped
    (failed runs)."""
    for name, sp in lines.items():
        if sp is None:
            continue
        shown = (sp.frequency > 0) & (sp.frequency <= fmax)
        ax.semilogy(
            sp.frequency[shown],
            sp.density[shown],
            label=f"{name}: {sp.dominant_hz:.2f} Hz, {sp.peak:.3g}",
        )
    ax.set(
        xlabel="frequency (Hz)",
        ylabel=f"PSD of {label} ((m/s²)²/Hz)",
        xlim=(0, fmax),
        title=title,
    )
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(title="dominant frequency, PSD peak", fontsize=8)


def draw_intervals(ax: Any, groups: Mapping[str, npt.ArrayLike], ylabel: str, title: str) -> None:
    """Draw one column per group of a positive quantity: the value of every track (dots), their
    geometric mean (bar) and its 95 % interval (error bar,
    :func:`loco.studies.statistics.geometric_interval`, never below zero); NaN tracks are left
    out."""
    from loco.studies.statistics import geometric_interval

    for k, values in enumerate(groups.values()):
        v = np.asarray(values, dtype=np.float64)
        v = v[np.isfinite(v)]
        ci = geometric_interval(v)
        ax.bar(k, ci.mean, color=f"C{k}", alpha=0.35, width=0.6)
        if ci.n > 1:
            ax.errorbar(k, ci.mean, yerr=[[ci.mean - ci.low], [ci.high - ci.mean]],
                        color="k", capsize=5, lw=1.2)  # fmt: skip
        ax.plot(np.full(len(v), k) + np.linspace(-0.12, 0.12, len(v)), v, "o", ms=3,
                color=f"C{k}")  # fmt: skip
    ax.set_xticks(range(len(groups)), list(groups))
    ax.set(ylabel=ylabel, title=title)
    ax.set_ylim(bottom=0.0)
    ax.grid(True, axis="y", alpha=0.3)
