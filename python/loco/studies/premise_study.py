"""The premise study of any vehicle: where its carbody hunts on low conicity, which estimates
decide it, how probable the premise is over plausible versions of it, and the FSD where it holds.

:func:`premise_stages` gives the premise map, the Morris screening and the plausible locomotives
(:mod:`loco.studies.premise_map`, :mod:`loco.studies.screening`,
:mod:`loco.studies.plausible`) of a vehicle at the sizes of a preset (:data:`SIZES`);
``loco reproduce`` runs them on the default vehicle. :func:`premise_study` runs them on any
vehicle file, with the damper comparison on the study's pairs and on the vehicle's premise case
(:mod:`loco.studies.premise_case`), resumable in its output directory like ``loco reproduce``
(a finished stage is skipped, a stage's finished samples are kept in its store), and writes
``premise.md``: the answer to "does the premise hold?" for that vehicle.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import loco
from loco import uncertainty
from loco.executors import Executor
from loco.studies import premise_modes
from loco.studies.fsd_comparison import FsdComparisonStage
from loco.studies.plausible import PlausibleStage
from loco.studies.premise_case import PremiseCaseStage, candidates, choose_pair
from loco.studies.premise_map import SWEEP_SPEEDS_KMH, PremiseMapStage
from loco.studies.premise_report import premise_section
from loco.studies.screening import ScreeningStage
from loco.studies.stages import DataFile, Runtime, Stage, StageRunner, campaign_stores

__all__ = ["SIZES", "PremiseSizes", "premise_stages", "premise_study"]

#: The screening's outputs without the critical speeds (the modes' damping ratios alone, a
#: quarter of the cost of a point).
ZETA_OUTPUTS = tuple(k for k, o in uncertainty.OUTPUTS.items() if o.quantity != "critical_speed")


@dataclass(frozen=True)
class PremiseSizes:
    """The premise map's ``conicities`` (–), ``dampings`` (N·s/m) and ``sweep_speeds_kmh``;
    the screening's ``trajectories`` on ``outputs``; ``plausible`` locomotives on
    ``plausible_tracks`` tracks of ``distance`` m; the damper comparisons on ``n_tracks``."""

    conicities: tuple[float, ...]
    dampings: tuple[float, ...]
    sweep_speeds_kmh: tuple[float, ...]
    trajectories: int
    outputs: tuple[str, ...]
    plausible: int
    plausible_tracks: int
    distance: float
    n_tracks: int


#: Sizes per preset. ``full``: the whole map, 20 trajectories on every output (the modes and the
#: critical speeds) and 200 locomotives on 2 tracks, the results of the premise page;
#: ``quick``: the whole map, 10 trajectories on the damping ratios alone and 64 locomotives
#: (16 per S_low pair), a few minutes on 2 cores; ``tiny``: the tests'.
SIZES: dict[str, PremiseSizes] = {
    "full": PremiseSizes(
        premise_modes.CONICITIES,
        premise_modes.DAMPINGS,
        SWEEP_SPEEDS_KMH,
        20,
        tuple(uncertainty.OUTPUTS),
        200,
        2,
        500.0,
        8,
    ),
    "quick": PremiseSizes(
        premise_modes.CONICITIES,
        premise_modes.DAMPINGS,
        SWEEP_SPEEDS_KMH,
        10,
        ZETA_OUTPUTS,
        64,
        2,
        500.0,
        4,
    ),
    "tiny": PremiseSizes(
        (0.03, 0.05), (200e3, 800e3), (200.0,), 2, ZETA_OUTPUTS[1:2], 4, 1, 300.0, 2
    ),
}


def premise_stages(
    sizes: PremiseSizes,
    *,
    seed: int = 0,
    vehicle: loco.Locomotive | None = None,
    integrator: str = loco.Scenario.integrator,
    ranges: DataFile | None = None,
) -> list[Stage]:
    """The premise map, the screening and the plausible locomotives of ``vehicle`` with
    ``sizes``, seeded by ``seed`` (the screening's trajectories, the Latin hypercube), the
    simulations with ``integrator``, the inputs' ranges from the file ``ranges`` (default: the
    embedded ranges file)."""
    return [
        PremiseMapStage(
            conicities=sizes.conicities,
            dampings=sizes.dampings,
            sweep_speeds_kmh=sizes.sweep_speeds_kmh,
            vehicle=vehicle,
        ),
        ScreeningStage(
            trajectories=sizes.trajectories,
            seed=seed,
            outputs=sizes.outputs,
            vehicle=vehicle,
            ranges=ranges,
        ),
        PlausibleStage(
            n=sizes.plausible,
            seed=seed,
            n_tracks=sizes.plausible_tracks,
            distance=sizes.distance,
            vehicle=vehicle,
            integrator=integrator,
            ranges=ranges,
        ),
    ]


def premise_study(
    vehicle: loco.Locomotive | str | Path | None,
    out: str | Path,
    *,
    preset: str = "quick",
    seed: int = 0,
    ranges_file: str | Path | None = None,
    executor: Executor | None = None,
    threads: int | None = None,
    progress: bool = True,
    force: bool = False,
    log: Callable[[str], None] = print,
) -> Path:
    """Run the premise study of ``vehicle`` (a :class:`loco.Locomotive`, the path of a vehicle
    file, or None for the default vehicle) into ``out`` at the sizes of ``preset``
    (:data:`SIZES`: ``"quick"`` or ``"full"``) and return the path of ``out/premise.md``.

    Stages, each in ``out/<stage>/``: ``fsd_comparison`` (YD1, YD2, FSD and FSD-H on the study's
    S_low and S_high), the premise map, the screening, the plausible locomotives and
    ``premise_case`` (the comparison on the low-conicity pair where this vehicle's carbody mode
    has the premise, if any). The inputs' ranges come from ``ranges_file`` (default: the
    embedded ranges file; a range that does not contain the vehicle's value is refused naming
    the key). ``seed`` seeds the tracks, the screening and the Latin hypercube; ``executor``
    (default local threads, or a :class:`loco.executors.DaskExecutor`) runs the simulations and
    the eigen analyses; a rerun skips the finished stages (``force`` runs them again)."""
    if preset not in SIZES:
        raise loco.ParameterError(
            f"invalid parameter `preset`: `{preset}` (known: {', '.join(SIZES)})"
        )
    sizes = SIZES[preset]
    if isinstance(vehicle, (str, Path)):
        vehicle = loco.Locomotive.from_toml(vehicle)
    vehicle = vehicle or loco.Locomotive.default()
    ranges = None if ranges_file is None else DataFile(Path(ranges_file))
    # A bad range or vehicle is refused before any stage runs.
    uncertainty.ranges(vehicle, ranges_file)
    comparison = {
        "distance": sizes.distance,
        "seed": seed,
        "n_tracks": sizes.n_tracks,
        "vehicle": vehicle,
    }
    planned: list[Stage] = [
        FsdComparisonStage(**comparison),  # type: ignore[arg-type]
        *premise_stages(sizes, seed=seed, vehicle=vehicle, ranges=ranges),
        PremiseCaseStage(
            s_low_pair=choose_pair(candidates(vehicle)),
            **comparison,  # type: ignore[arg-type]
        ),
    ]
    runner = StageRunner(
        out,
        log=log,
        force=force,
        runtime=Runtime(threads=threads, progress=progress),
        around=campaign_stores(executor, force=force, log=log),
    )
    records = {stage.name: runner.run(stage) for stage in planned}
    dirs = {name: Path(out) / name for name in records}
    lines = premise_section(
        dirs["fsd_comparison"] / "fsd_tracks.csv",
        dirs["premise_case"],
        map_dir=dirs["premise_map"],
        screening_dir=dirs["screening"],
        plausible_dir=dirs["plausible"],
        vehicle="the default vehicle" if vehicle.toml_text is None else f"`{vehicle.origin}`",
    )
    path = Path(out) / "premise.md"
    path.write_text("\n".join(["# The premise study", "", *lines]), encoding="utf-8")
    return path
