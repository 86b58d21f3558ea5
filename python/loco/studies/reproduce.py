"""The whole study of SPEC §6 as one pipeline, and its report (``loco reproduce`` runs it).

Stages (:func:`stages`, sized by :mod:`loco.studies.sizes`; each a frozen dataclass of its
inputs, :mod:`loco.studies.stages`, run in ``<out>/<stage>/`` by
:class:`loco.studies.stages.StageRunner`: a stage finished with the same inputs is skipped on a
rerun, ``--force`` runs it again):

1. ``speed_sweep``: W_y and A_yb against speed, S_low / S_norm / S_high, YD2; PSDs at 200 km/h;
   each point the mean and 95 % interval over ``n_tracks`` synthesised tracks.
2. ``monte_carlo``: Latin hypercube over the six parameters, W_y (S_low) and A_yb (S_high).
3. ``surrogate_samples``: a second Latin hypercube, so that the surrogate learns from
   ``surrogate_samples`` samples in all (:mod:`loco.studies.surrogate_samples`).
4. ``surrogate_holdout``: a third, independent Latin hypercube of ``holdout_samples`` (200 in
   ``--quick``, 500 in ``--full``), simulated like the others and used neither to train nor to
   choose the surrogate (:mod:`loco.studies.surrogate_holdout`).
5. ``surrogate``: k-fold held-out R² of the SPEC RBF network on the Monte Carlo's samples, and of
   six candidates (:mod:`loco.studies.surrogate_selection`) on all the training samples, with the
   nested cross-validation of the choice; the best is the surrogate of stages 6 and 7; every
   candidate's R² on the fresh samples of stage 4, on which the requirement is judged; parity
   plots.
6. ``sensitivity``: Sobol' indices direct (Saltelli, simulator) and on the surrogate; convergence.
7. ``optimisation``: NSGA-II on the surrogate, Pareto front; Pareto points re-simulated.
8. ``damper_bench``: YD1, YD2, FSD at 1 and 4 Hz (``loco damper-bench``).
9. ``fsd_comparison``: YD1, YD2, FSD on S_low and S_high at 200 km/h, on ``n_tracks`` tracks
   (the same for every damper), with paired tests of whether each ranking is significant.
10. ``fsd_design``: NSGA-II on the simulator over the hydraulic FSD's design, the picked designs
    and YD1, YD2, FSD over a conicity sweep (:mod:`loco.studies.fsd_design`; sizes per
    preset in its ``SIZES``).
11. ``premise_map``: the linearised carbody and bogie modes over conicity, contact family and
    yaw damping at 200 km/h, and over speed (:mod:`loco.studies.premise_map`).
12. ``screening``: Morris screening of every ranged input on the modes' damping (and in
    ``--full`` the linear critical speeds): which estimates the answer hangs on.
13. ``plausible``: plausible locomotives (a Latin hypercube over the ranged inputs and the
    low-conicity pairs) with YD1, YD2, FSD and FSD-H on S_low and S_high: the share with the
    premise, with its interval, and what the FSDs do there.
14. ``premise_case``: the damper comparison of stage 9 with S_low on the low-conicity pair on
    which the default vehicle has the study's premise, chosen by the rule of
    :mod:`loco.studies.premise_case` before any of its runs.
15. ``curving`` (``--full`` only, a stage beyond the SPEC's study): YD1, YD2, FSD in curves of
    600–7000 m at 0–150 mm cant deficiency, ΣY, Y/Q and Y_qst by EN 14363
    (:mod:`loco.studies.curving`).

Then ``<out>/report.md`` shows every figure and table with settings, seeds, version, run times,
and ``<out>/report.html`` the same report as one self-contained page (figures embedded).

Every batch of a stage runs as a campaign (:mod:`loco.campaign`) on one executor — local threads
(default), ``--workers N`` (a Dask ``LocalCluster``) or ``--scheduler tcp://host:8786`` (or
``$DASK_SCHEDULER_ADDRESS``) — and keeps its finished samples in ``<out>/<stage>/store/``: a rerun
after a kill simulates only the samples not stored. ``--force`` clears those stores too. A stage's
marker records the content hash of its outputs, and the stages that learn from the Monte Carlo's
and the extension's tables take them as inputs by content, so a damaged output is never reused.

Sizes: ``--full`` is SPEC §6 (200 Latin hypercube samples, population 500 × 100 generations,
500 m at 200 km/h; 256 Saltelli base samples for the direct indices), plus 300 more samples for
the surrogate (500 in all, :mod:`loco.studies.surrogate_samples`) and 500 fresh ones to score
it on (200 in ``--quick``). ``--quick`` (default, the
README's main job) keeps those sizes but uses 32 Saltelli base samples and a coarser speed
sweep, and 4 tracks for the speed sweep and the damper comparison (8 in ``--full``). The FSD
design stage has sizes of its own per preset. ``Sizes.runs()`` (the ``--quick``/``--full`` help)
counts what every stage asks for (:meth:`loco.studies.stages.Stage.demand`) in runs of 500 m at
200 km/h: about 4 370 for ``--quick`` (the FSD design stage, the surrogate's 300 extra samples
and its 200 fresh ones at two runs each, and the 64 plausible locomotives' 1 024 runs of 1 000 m
included; one run of 500 m costs about 0.3 s of one core) and 14 200 for ``--full`` (the curving
stage, 1 000 runs for the 500 fresh samples and 200 plausible locomotives included). The premise
stages have sizes of their own (:data:`loco.studies.premise_study.SIZES`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from pathlib import Path
from typing import Any

import loco
from loco import dampers
from loco.executors import Executor, LocalExecutor
from loco.studies import (
    curving,
    damper_bench,
    fsd_comparison,
    fsd_design,
    monte_carlo,
    optimisation,
    parameter_study,
    plausible,
    premise_case,
    premise_map,
    premise_study,
    screening,
    sensitivity,
    speed_sweep,
    surrogate,
    surrogate_holdout,
    surrogate_samples,
)
from loco.studies.premise_report import premise_section
from loco.studies.report import StudyRecord, save_json, write_report
from loco.studies.sizes import Sizes
from loco.studies.stages import DataFile, Runtime, Stage, StageRunner, campaign_stores
from loco.studies.verdict import verdict_from_csv

__all__ = ["PREAMBLE", "reproduce", "stages"]


def stages(
    sizes: Sizes,
    out_dir: str | Path,
    *,
    seed: int = 0,
    integrator: str = loco.Scenario.integrator,
    choose_premise_pair: bool = True,
) -> list[Stage]:
    """The stages of a run of ``sizes`` into ``out_dir`` with ``seed``, every run with
    ``integrator`` at its own step, in order: each a frozen dataclass of its inputs
    (:mod:`loco.studies.stages`).

    A stage's inputs are what its numbers depend on, not the preset's name, so a ``--full`` run
    after ``--quick`` reuses the stages whose sizes the two share. ``seed`` seeds the track
    irregularities, the Latin hypercubes, the Saltelli designs, the networks' K-means and the two
    NSGA-II runs. Only the damper comparison has a lead-in (its FSD must leave its start state):
    for the passive Maxwell yaw dampers of the other stages, 8 tracks at 200 km/h with 0, 100,
    200 and 500 m of lead-in gave W_y on S_low 2.72 / 2.82 / 2.82 / 2.62 (track-to-track sd
    0.11-0.19) and A_yb on S_high 1.40 / 1.50 / 1.69 / 1.56 m/s² (sd 0.17-0.46): no systematic
    change, while 500 m would double the cost of the Monte Carlo and Sobol' stages.
    ``choose_premise_pair=False`` leaves the premise case's pair unchosen (no eigen analysis),
    for counting what the stages ask for.
    """
    out = Path(out_dir)
    setup = parameter_study.StudySetup(
        speed_kmh=sizes.speed_kmh, distance=sizes.distance, track_seed=seed, integrator=integrator
    )
    # The surrogates learn from the Monte Carlo's table and the extension's, by content: the
    # stages that use them run again when either changed (each is checked by its own marker).
    tables = (
        DataFile(out / "monte_carlo" / "monte_carlo.csv"),
        DataFile(out / "surrogate_samples" / "surrogate_samples.csv"),
    )
    training = surrogate.Training(tables, kfold=sizes.kfold, seed=seed)
    # A preset of its own name, else (a hand-made Sizes) the quick study.
    design_sizes = fsd_design.SIZES.get(sizes.name, fsd_design.SIZES["quick"])
    premise_sizes = premise_study.SIZES.get(sizes.name, premise_study.SIZES["quick"])
    comparison: dict[str, Any] = {
        "speed_kmh": sizes.speed_kmh,
        "distance": sizes.distance,
        "lead_in": fsd_comparison.LEAD_IN,
        "seed": seed,
        "n_tracks": sizes.n_tracks,
        "integrator": integrator,
    }
    out_stages: list[Stage] = [
        speed_sweep.SpeedSweepStage(
            speeds_kmh=sizes.sweep_speeds_kmh,
            psd_speed_kmh=sizes.speed_kmh,
            distance=sizes.distance,
            seed=seed,
            n_tracks=sizes.n_tracks,
            yaw_damper=dampers.YD2,
            integrator=integrator,
        ),
        monte_carlo.MonteCarloStage(setup, sizes.lhs_samples, seed),
        surrogate_samples.SurrogateSamplesStage(
            setup, sizes.surrogate_samples, sizes.lhs_samples, seed
        ),
        surrogate_holdout.HoldoutSamplesStage(setup, sizes.holdout_samples, seed),
        surrogate.SurrogateStage(
            training,
            spec_samples=sizes.lhs_samples,
            holdout=DataFile(out / "surrogate_holdout" / "holdout_samples.csv"),
        ),
        sensitivity.SensitivityStage(
            setup, training, seed, sizes.convergence_bases, sizes.surrogate_base
        ),
        optimisation.OptimisationStage(
            setup, training, seed, sizes.pop_size, sizes.n_gen, sizes.n_verify
        ),
        damper_bench.DamperBenchStage(),
        fsd_comparison.FsdComparisonStage(**comparison),
        fsd_design.FsdDesignStage(
            design_sizes, speed_kmh=sizes.speed_kmh, seed=seed, integrator=integrator
        ),
        # Where the premise holds, on which estimates it hangs, how probable it is.
        *premise_study.premise_stages(premise_sizes, seed=seed, integrator=integrator),
        # The same comparison where the premise holds.
        (
            premise_case.PremiseCaseStage.chosen(**comparison)
            if choose_premise_pair
            else premise_case.PremiseCaseStage(**comparison)
        ),
    ]
    c = sizes.curving_sizes
    if c is not None:
        out_stages.append(
            curving.CurvingStage(
                curves=tuple(c.curves()),
                deficiencies_mm=c.deficiencies_mm,
                lead_in=c.lead_in,
                seed=seed,
                integrator=integrator,
            )
        )
    return out_stages


def reproduce(
    sizes: Sizes,
    out: str | Path,
    *,
    threads: int | None = None,
    seed: int = 0,
    integrator: str = loco.Scenario.integrator,
    force: bool = False,
    progress: bool = True,
    log: Callable[[str], None] = print,
    command: str = "",
    executor: Executor | None = None,
    chunk_size: int | None = None,
) -> Path:
    """Run every stage (:func:`stages`) into ``out`` and write ``out/report.md`` (and the same
    report as the page ``out/report.html``); return the Markdown report's path.

    ``seed`` seeds the track irregularities, the Latin hypercube, the Saltelli designs, the
    networks' K-means and NSGA-II. ``integrator`` is every run's scheme (at its own step; its
    results differ from the reference's within 0.5 %). ``threads``, ``executor`` (default local
    threads) and ``chunk_size`` only change the speed.
    """
    out_dir = Path(out)
    executor = executor or LocalExecutor(threads)

    runner = StageRunner(
        out_dir,
        log=log,
        force=force,
        runtime=Runtime(threads=threads, progress=progress),
        around=campaign_stores(executor, chunk_size=chunk_size, force=force, log=log),
    )
    planned = stages(sizes, out_dir, seed=seed, integrator=integrator)
    log(
        f"loco {loco.__version__}: reproducing SPEC §6 ({sizes.name}, ~{sizes.runs()} runs of "
        f"{sizes.distance:g} m) into {out_dir}"
    )
    log(f"simulations on {executor.describe()}")
    records = []
    for i, stage in enumerate(planned, start=1):
        log(f"stage {i}/{len(planned)}: {stage.name}")
        record = runner.run(stage)
        records.append(record)
        if record.notes:
            log(f"  {record.notes}")
    run_settings = {
        "command": command or f"loco reproduce --{sizes.name}",
        "sizes": dataclasses.asdict(sizes),
        "seed (track, designs, K-means, NSGA-II)": seed,
        "integrator": f"{integrator} at {loco.simulation.INTEGRATOR_STEPS[integrator] * 1e3:g} ms",
        "tracks of the speed sweep and the damper comparison": (
            f"{sizes.n_tracks} (ChaCha streams 0-{sizes.n_tracks - 1} of the track seed)"
        ),
        "threads": threads or "all cores",
        "executor": executor.describe(),
        "stages run": runner.ran,
        "stages skipped (finished earlier)": runner.skipped,
    }
    save_json({"loco_version": loco.__version__, **run_settings}, out_dir / "reproduce.json")
    return write_report(
        records,
        out_dir / "report.md",
        title="loco: the reference study (docs/STUDY.md)",
        preamble=PREAMBLE,
        settings=run_settings,
        first_section=_verdict(records),
    )


def _tracks_table(records: list[StudyRecord], stage: str) -> Path | None:
    """The per-track table of the damper comparison stage ``stage``, when it wrote one."""
    for record in records:
        if record.name != stage:
            continue
        for table in record.tables:
            if Path(table).name == "fsd_tracks.csv" and Path(table).is_file():
                return Path(table)
    return None


def _verdict(records: list[StudyRecord]) -> list[str]:
    """The report's first sections: "Does the premise hold?" (the study's and the premise
    case's damper comparisons, :mod:`loco.studies.premise_report`), then the verdict, computed
    from the damper comparison's per-track table."""
    study = _tracks_table(records, fsd_comparison.FsdComparisonStage.name)
    case = next(
        (r for r in records if r.name == premise_case.PremiseCaseStage.name and r.tables), None
    )
    stage_dirs = {r.name: Path(r.tables[0]).parent for r in records if r.tables}
    premise = premise_section(
        study,
        None if case is None else Path(case.tables[0]).parent,
        map_dir=stage_dirs.get(premise_map.PremiseMapStage.name),
        screening_dir=stage_dirs.get(screening.ScreeningStage.name),
        plausible_dir=stage_dirs.get(plausible.PlausibleStage.name),
    )
    if study is None:
        return [
            *premise,
            "## Verdict",
            "",
            "Not available: the damper comparison stage wrote no table.",
            "",
        ]
    return [*premise, *verdict_from_csv(study).markdown()]


PREAMBLE = (
    "Every figure and table of the reference study (described in `docs/STUDY.md` of loco; the "
    "sections cite it as SPEC §n), produced by `loco reproduce`. "
    "W_y is the Sperling lateral ride index (metric `wy_max`), A_yb the 10 Hz low-passed peak "
    "bogie frame lateral acceleration (metric `ayb_peak_lp`, m/s²), A_yc the carbody floor "
    "lateral acceleration. Run times are those of the run that produced each stage."
)
