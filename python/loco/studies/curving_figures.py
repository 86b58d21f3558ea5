"""The curving study's figure: ΣY and Y/Q against cant deficiency, per yaw damper and radius."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from loco.studies import en14363
from loco.studies.plotting import pyplot, save_figure

__all__ = ["plot_curving"]


def plot_curving(table: pd.DataFrame, axle_load: float, path: str | Path) -> Path:
    """Two panels (ΣY in kN, Y/Q) against cant deficiency (mm): one colour per damper, one
    marker per radius, the EN 14363 limits dashed. Returns ``path``."""
    fig, axes = pyplot().subplots(1, 2, figsize=(10, 4.2), constrained_layout=True)
    markers = "osD^v<>"
    dampers = list(dict.fromkeys(table["damper"])) if not table.empty else []
    radii = sorted(set(table["radius_m"])) if not table.empty else []
    panels = (
        ("sumY_kN", "ΣY (2 m mean, 99.85 %), kN", en14363.sum_y_limit(axle_load) / 1e3),
        ("YQ", "Y/Q (2 m mean, 99.85 %)", en14363.YQ_LIMIT),
    )
    for ax, (column, label, limit) in zip(axes, panels, strict=True):
        for c, damper in enumerate(dampers):
            for m, radius in enumerate(radii):
                rows = table[(table["damper"] == damper) & (table["radius_m"] == radius)]
                rows = rows.sort_values("deficiency_mm")
                ax.plot(
                    rows["deficiency_mm"],
                    rows[column],
                    color=f"C{c}",
                    marker=markers[m % len(markers)],
                    lw=1.0,
                    label=f"{damper}, R = {radius:g} m",
                )
        ax.axhline(limit, color="k", ls="--", lw=0.8)
        ax.annotate(
            "EN 14363 limit",
            (0.01, limit),
            xycoords=("axes fraction", "data"),
            va="bottom",
            fontsize=8,
        )
        ax.set_xlabel("cant deficiency, mm")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    if dampers:
        axes[1].legend(fontsize=7, ncol=2)
    return save_figure(fig, path)
