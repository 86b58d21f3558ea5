"""``loco contact-report``: the contact geometry of the JM3 wheel states on CN60 rail.

Writes to ``--out`` (default ``contact-report``): ``profiles.png``, ``delta_r.png``,
``contact_angle.png``, ``conicity.png`` and the table ``conicity.csv`` / ``conicity.md`` with the
equivalent conicity at 3 mm (EN 15302 nonlinear method, and harmonic linearisation), the scenario
targets of the study, the loco version and the track parameters used; and ``contact_pairs.csv`` /
``contact_pairs.md``: every pair of :mod:`loco.contact_pairs` (the study's and the low-conicity
pairs of its field problem) with its conicity and linear contact parameters (λ, ε, σ, the
gravitational stiffness).
"""

from __future__ import annotations

import argparse
import csv
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import loco
from loco import conicity, contact, contact_pairs, profiles
from loco.commands.arguments import output_dir

NAME = "contact-report"
HELP = "contact report of the JM3 wheel states on CN60 rail (figures and conicity table)"

RAIL = "cn60"
#: (wheel, scenario, nominal tan γe at 3 mm) of SPEC §2.
WHEELS: list[tuple[str, str, float]] = [
    ("jm3-thin-flange", "S_low", 0.04),
    ("jm3-new", "S_norm", 0.10),
    ("jm3-worn", "S_high", 0.70),
]
#: The study's track and wheelset (SI): the defaults of :mod:`loco.contact` (from the core),
#: spelled out in the table.
TRACK: dict[str, Any] = {
    "gauge": contact.SETUP_DEFAULTS["gauge"],
    "gauge_height": contact.SETUP_DEFAULTS["gauge_height"],
    "rail_inclination": contact.SETUP_DEFAULTS["rail_inclination"],
    "back_to_back": contact.SETUP_DEFAULTS["back_to_back"],
    "flange_back_offset": contact.SETUP_DEFAULTS["flange_back_offset"],
    "nominal_radius": contact._NOMINAL_RADIUS,
}
AMPLITUDE = 0.003


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", default="contact-report", help="output directory")


def _plot_profiles(out: Path) -> None:
    fig, (ax_w, ax_r) = plt.subplots(1, 2, figsize=(11, 4))
    for wheel, _, _ in WHEELS:
        p = profiles.builtin(wheel)
        ax_w.plot(p.y * 1e3, p.z * 1e3, label=wheel)
    rail = profiles.builtin(RAIL)
    ax_r.plot(rail.y * 1e3, rail.z * 1e3, color="k", label=RAIL)
    ax_w.set(title="Wheel profiles (origin: taping line)", xlabel="y [mm]", ylabel="z [mm]")
    ax_r.set(title="Rail profile (upright)", xlabel="y [mm]", ylabel="z [mm]")
    ax_r.set_aspect("equal")
    for ax in (ax_w, ax_r):
        ax.grid(True)
        ax.legend()
    fig.tight_layout()
    fig.savefig(out / "profiles.png", dpi=120)
    plt.close(fig)


def _save(fig: Any, path: Path) -> None:
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def run(args: argparse.Namespace) -> int:
    out = output_dir(args.out)
    _plot_profiles(out)

    fig_dr, ax_dr = plt.subplots(figsize=(7, 4.5))
    fig_ca, ax_ca = plt.subplots(figsize=(7, 4.5))
    fig_c, ax_c = plt.subplots(figsize=(7, 4.5))
    rows: list[dict[str, Any]] = []
    for wheel, scenario, target in WHEELS:
        curve = conicity.conicity_curve(wheel, RAIL, **TRACK)
        geometry = contact.geometry(
            profiles.builtin(wheel), profiles.builtin(RAIL), curve.y, **TRACK
        )
        angle = geometry.touching("contact_angle")[:, 0]
        ax_dr.plot(curve.y * 1e3, curve.delta_r * 1e3, label=wheel)
        ax_ca.plot(curve.y * 1e3, np.degrees(angle), label=wheel)
        (line,) = ax_c.plot(curve.amplitudes * 1e3, curve.nonlinear, label=f"{wheel} (EN 15302)")
        ax_c.plot(
            curve.amplitudes * 1e3,
            curve.harmonic,
            "--",
            color=line.get_color(),
            label=f"{wheel} (harmonic)",
        )
        rows.append(
            {
                "wheel": wheel,
                "rail": RAIL,
                "scenario": scenario,
                "target_tan_gamma_e": target,
                "tan_gamma_e_3mm": conicity.equivalent_conicity(wheel, RAIL, AMPLITUDE, **TRACK),
                "tan_gamma_e_3mm_harmonic": curve.at(AMPLITUDE, "harmonic"),
            }
        )
    ax_dr.set(title="Rolling radius difference", xlabel="y [mm]", ylabel="Δr [mm]")
    ax_ca.set(title="Contact angle, left wheel", xlabel="y [mm]", ylabel="contact angle [°]")
    ax_c.set(title="Equivalent conicity", xlabel="wheelset amplitude ŷ [mm]", ylabel="tan γe [-]")
    for ax in (ax_dr, ax_ca, ax_c):
        ax.grid(True)
        ax.legend(fontsize=8)
    _save(fig_dr, out / "delta_r.png")
    _save(fig_ca, out / "contact_angle.png")
    _save(fig_c, out / "conicity.png")
    _write_tables(out, rows)
    _write_pairs(out)
    print(f"contact report written to {out}")
    return 0


def _parameters() -> dict[str, Any]:
    return {"loco_version": loco.__version__, "amplitude_m": AMPLITUDE, **TRACK}


def _write_tables(out: Path, rows: list[dict[str, Any]]) -> None:
    params = _parameters()
    with (out / "conicity.csv").open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=[*rows[0], *params])
        writer.writeheader()
        for row in rows:
            writer.writerow({**row, **params})
    lines = [
        "# Equivalent conicity of the JM3 wheel states on CN60",
        "",
        f"loco {loco.__version__}; EN 15302 nonlinear method at ŷ = {AMPLITUDE * 1e3:g} mm; "
        + ", ".join(f"{k} = {v:.6g}" for k, v in TRACK.items())
        + " (SI units).",
        "",
        "| wheel | rail | scenario | target tan γe | tan γe (3 mm) | harmonic (3 mm) |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['wheel']} | {r['rail']} | {r['scenario']} | {r['target_tan_gamma_e']:.2f} "
            f"| {r['tan_gamma_e_3mm']:.4f} | {r['tan_gamma_e_3mm_harmonic']:.4f} |"
        )
    (out / "conicity.md").write_text("\n".join(lines) + "\n")


def _write_pairs(out: Path) -> None:
    rows = contact_pairs.pair_rows()
    params = {"loco_version": loco.__version__, "amplitude_m": contact_pairs.AMPLITUDE}
    with (out / "contact_pairs.csv").open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=[*rows[0], *params])
        writer.writeheader()
        for row in rows:
            writer.writerow({**row, **params})
    lines = [
        "# Contact pairs: conicity and linear contact parameters",
        "",
        f"loco {loco.__version__}; EN 15302 at ŷ = {contact_pairs.AMPLITUDE * 1e3:g} mm; Wickens'"
        f" λ, ε, σ; K_g under the mean axle load {rows[0]['axle_load_n'] / 1e3:.1f} kN.",
        "",
        *contact_pairs.markdown_table(rows),
    ]
    (out / "contact_pairs.md").write_text("\n".join(lines) + "\n")
