"""What to read from each figure of the study: the captions the stages put on their records
(:attr:`loco.studies.report.StudyRecord.captions`, by figure file name), shown under each figure
of ``report.md`` and ``report.html``.

A caption says what the figure plots and how to read it, not the run's numbers (those are in
the section's notes and tables), so it holds for any run of the stage.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

__all__ = [
    "CURVING",
    "DAMPER_BENCH",
    "FSD_COMPARISON",
    "FSD_DESIGN",
    "MONTE_CARLO",
    "OPTIMISATION",
    "PLAUSIBLE",
    "PREMISE_MAP",
    "SCREENING",
    "SPEED_SWEEP",
    "parity_captions",
    "sobol_captions",
]

SPEED_SWEEP = {
    "speed_sweep.png": "W_y (left) and A_yb (right) against speed for each scenario, with the "
    "yaw damper of the sweep: where a curve rises steeply the ride or the bogie degrades; the "
    "bars are 95 % intervals over the tracks (of the logs, so never below zero), the dashed line "
    "the study speed.",
    "speed_sweep_psd.png": "Power spectral densities of A_yc and A_yb at the study speed, "
    "averaged over the tracks: a narrow peak is a lightly damped mode (carbody sway at low "
    "frequency, bogie hunting at a few hertz).",
    "speed_sweep_peaks.png": "The PSD peak of each track (dots), their geometric mean (bar) and "
    "its 95 % interval per scenario: how far apart the scenarios are against the spread from "
    "track to track.",
}

MONTE_CARLO = {
    "monte_carlo.png": "Each objective against each of the six parameters over the Latin "
    "hypercube: a clear trend in a panel is a parameter that drives that objective; a shapeless "
    "cloud one that matters little alone."
}

OPTIMISATION = {
    "pareto.png": "The Pareto front of the two objectives found by NSGA-II on the surrogate, and "
    "the parameters along it: each point is a design that no other beats on both objectives; the "
    "trade-off is the front's slope.",
    "pareto_verification.png": "Points of the front re-simulated (markers) against the "
    "surrogate's front (grey): the gap is how far the surrogate's optimum is from the "
    "simulator's.",
}

FSD_COMPARISON = {
    "fsd_time_histories.png": "A_yc and A_yb with each damper on track 0: steady oscillations of "
    "large amplitude are a limit cycle (hunting), a decaying ripple a stable vehicle.",
    "fsd_psd.png": "PSDs of A_yc and A_yb with each damper, averaged over the tracks: the damper "
    "with the lower, broader peak damps that mode better.",
    "fsd_peaks.png": "Per scenario, the PSD peak and the judging metric of each damper: every "
    "track (dots), the geometric mean (bar) and its 95 % interval; compare the dampers within a "
    "scenario (lower is better; the rankings' paired tests say which gaps are significant).",
    "fsd_valve.png": "The FSD's valve scale factor over time on track 0 (1 closed, high "
    "damping; lower open, low damping): where it stays at 1 the FSD acts as the stiff damper "
    "YD2.",
    "fsd_valve_hydraulic.png": "The same for FSD-H, the FSD with the hydraulic frequency valve.",
}

DAMPER_BENCH = {
    "damper_bench.png": "Force against velocity (top) and hysteresis loops (bottom) of each yaw "
    "damper under sine strokes at 1 and 4 Hz: a steeper force-velocity curve is more damping; a "
    "tilted, narrow loop is stiffness (the series stiffness), a wide one dissipation.",
    "valve_states.png": "Force, valve scale factor (0 open, 1 closed) and auxiliary piston "
    "travel of the FSD frequency valve under sine strokes of the reference amplitude, the "
    "rms-frequency estimate against the hydraulic valve: at which frequencies the valve opens "
    "(low damping) and how quickly it follows.",
    "valve_cutoff_vs_amplitude.png": "The valve's switching frequency against stroke amplitude "
    "(log scales): which strokes, by amplitude and frequency, open it.",
    "valve_two_tone.png": "The valve's open fraction under a 1.2 Hz stroke with a dither added, "
    "against the dither's amplitude over the stroke's: how large a dither keeps the valve from "
    "opening at the sway frequency.",
}

FSD_DESIGN = {
    "fsd_design.png": "The FSD designs found by NSGA-II on the simulator (their objectives and "
    "the front) and the chosen design over conicity against the fixed dampers: a design that "
    "stays below both fixed dampers across conicity holds every scenario."
}

PREMISE_MAP = {
    "premise_map.png": "Damping ratio ζ of the linearised carbody (top) and bogie (middle) modes "
    "over conicity and yaw damping, on ideal cones and on real wheel-rail pairs, and over speed "
    "(bottom): red cells (ζ < 0) are unstable; the premise needs the carbody mode stable at low "
    "yaw damping and unstable at high, on low conicity (left of the black line)."
}

SCREENING = {
    "morris.png": "Morris screening per output: μ* (mean absolute elementary effect) against σ "
    "(its spread) for each ranged input: inputs far to the right matter most; a high σ means a "
    "non-linear effect or interactions."
}

PLAUSIBLE = {
    "plausible.png": "The share of plausible locomotives on which the premise holds, per "
    "wheel-rail pair and pooled, with 95 % Wilson intervals, and how the FSD compares with the "
    "fixed dampers on them: a share near 0 or 1 with a narrow interval is a firm answer."
}

CURVING = {
    "curving.png": "Guiding forces (ΣY, Y/Q, Y_qst) against cant deficiency for each yaw damper, "
    "with the EN 14363 limits as lines: a point above its line fails the limit."
}


def sobol_captions(metrics: Iterable[str]) -> dict[str, str]:
    """Captions of ``sobol_<metric>.png`` for each of ``metrics`` and of the convergence plot."""
    captions = {
        f"sobol_{metric}.png": f"First-order (S1, left) and total (ST, right) Sobol' indices of "
        f"{metric} per parameter, direct and on the surrogate, with 95 % bootstrap intervals: a "
        "tall ST is a parameter that matters; ST well above S1 one that acts through "
        "interactions. A negative S1 is estimator noise around zero (the true index is at least "
        "0); with a small base sample N the direct intervals are wide."
        for metric in metrics
    }
    captions["sobol_convergence.png"] = (
        "The direct indices against the Saltelli base sample N: where they still move between "
        "the last sizes, N is too small to trust them."
    )
    return captions


def parity_captions(figures: Iterable[Path]) -> dict[str, str]:
    """Captions of the parity plots ``parity_<objective>[_used].png``."""
    captions = {}
    for figure in figures:
        objective = figure.stem.removeprefix("parity_").removesuffix("_used")
        model = "the surrogate used" if figure.stem.endswith("_used") else "the SPEC network"
        captions[figure.name] = (
            f"{objective} predicted by {model} (held out by k-fold cross-validation) against the "
            "simulated value: points on the diagonal are predicted well; a spread or a bend away "
            "from it is the surrogate's error."
        )
    return captions
