"""How big each stage of ``loco reproduce`` is: :class:`Sizes` and the presets ``--quick``
(:data:`QUICK`, the default), ``--full`` (:data:`FULL`, the reference study's sizes) and the
hidden ``--tiny`` (:data:`TINY`, the tests' run)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from loco.studies import curving, surrogate_samples
from loco.studies.stages import Demand

__all__ = ["FULL", "PRESETS", "QUICK", "TINY", "Sizes"]


@dataclass(frozen=True)
class Sizes:
    """How big each stage is.

    ``distance`` (m) and ``speed_kmh`` (km/h) are the study's run; ``sweep_speeds_kmh`` the
    speed sweep (km/h); ``lhs_samples`` the Monte Carlo; ``surrogate_samples`` the samples the
    surrogate of the Sobol' and NSGA-II stages learns from (the Monte Carlo's and more:
    :mod:`loco.studies.surrogate_samples`); ``holdout_samples`` the fresh samples the surrogates
    are scored on (:mod:`loco.studies.surrogate_holdout`); ``convergence_bases`` the Saltelli base
    sample counts N of the direct Sobol' indices (the largest is simulated: N·8 runs per
    scenario); ``surrogate_base`` the Saltelli N on the surrogate; ``kfold`` the folds of the R²;
    ``pop_size`` and ``n_gen`` NSGA-II; ``n_verify`` the Pareto points re-simulated;
    ``n_tracks`` the synthesised tracks every case of the speed sweep and the damper comparison
    runs on (their tables give the mean and 95 % interval over them); ``curving_sizes`` the
    curving stage's sizes (None: no curving stage).
    """

    name: str
    distance: float
    speed_kmh: float
    sweep_speeds_kmh: tuple[float, ...]
    lhs_samples: int
    surrogate_samples: int
    holdout_samples: int
    convergence_bases: tuple[int, ...]
    surrogate_base: int
    kfold: int
    pop_size: int
    n_gen: int
    n_verify: int
    n_tracks: int
    curving_sizes: curving.CurvingSizes | None

    def runs(self) -> int:
        """Simulations of ``distance`` at ``speed_kmh`` the stages of these sizes cost, about:
        the simulated time they ask for (:meth:`loco.studies.stages.Stage.demand`, lead-ins and
        slower speeds included) over that of one such run."""
        return round(self.demand().simulated_s * self.speed_kmh / 3.6 / self.distance)

    def demand(self) -> Demand:
        """The simulations every stage of these sizes asks for, together."""
        # The premise case asks for the same runs whichever pair it is on: not chosen here, so
        # that counting (the --help text) needs no eigen analysis.
        from loco.studies.reproduce import stages  # the stages read these sizes

        planned = stages(self, ".", choose_premise_pair=False)
        return sum((s.demand() for s in planned), Demand())


#: SPEC §6 sizes (the direct Sobol' indices, which SPEC does not size, on 256 base samples; the
#: surrogate of Sobol' and NSGA-II on the Monte Carlo's 200 samples and 300 more, the count the
#: learning curve of :data:`loco.studies.surrogate_samples.SURROGATE_SAMPLES` asks for).
FULL = Sizes(
    name="full",
    distance=500.0,
    speed_kmh=200.0,
    sweep_speeds_kmh=tuple(float(v) for v in range(80, 301, 10)),
    lhs_samples=200,
    surrogate_samples=surrogate_samples.SURROGATE_SAMPLES,
    holdout_samples=500,
    convergence_bases=(16, 32, 64, 128, 256),
    surrogate_base=8192,
    kfold=5,
    pop_size=500,
    n_gen=100,
    n_verify=20,
    n_tracks=8,
    curving_sizes=curving.FULL_SIZES,
)
#: The README's main job: about 4.5 min on an idle 2-core machine for the study's own stages and
#: 7 more for the premise stages (~4 370 runs of 500 m that ``QUICK.runs()`` counts). It
#: keeps SPEC's distance, speed, Latin hypercube and NSGA-II sizes (NSGA-II on the surrogate
#: costs seconds); the direct Sobol' indices use 32 Saltelli base samples (256 runs per
#: scenario) and the speed sweep steps 25 km/h. The sweep and the damper comparison run on 4
#: tracks (3 is the least the study's statistics allow; on 2 cores a batch of 3 tracks takes as
#: long as one of 4): 12-18 % more CPU time than on one track (two before/after pairs on the
#: shared machine: 307 -> 345 s and 330 -> 389 s).
QUICK = dataclasses.replace(
    FULL,
    name="quick",
    sweep_speeds_kmh=tuple(float(v) for v in range(100, 301, 25)),
    holdout_samples=200,
    convergence_bases=(8, 16, 32),
    surrogate_base=4096,
    n_verify=8,
    n_tracks=4,
    curving_sizes=None,
)
#: For tests: every stage on a few short runs (300 m is the shortest record the metrics take at
#: 200 km/h, and 10 RBF centres need 10 training samples in each of 3 folds).
TINY = dataclasses.replace(
    FULL,
    name="tiny",
    distance=300.0,
    sweep_speeds_kmh=(180.0,),
    lhs_samples=16,
    surrogate_samples=24,
    holdout_samples=6,
    convergence_bases=(2, 4),
    surrogate_base=256,
    kfold=3,
    pop_size=24,
    n_gen=4,
    n_verify=3,
    n_tracks=2,
    curving_sizes=curving.TINY_SIZES,
)
PRESETS: dict[str, Sizes] = {s.name: s for s in (QUICK, FULL, TINY)}
