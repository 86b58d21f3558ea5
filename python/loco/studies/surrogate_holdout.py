"""The surrogates scored on fresh samples: simulated like the training samples, used neither to
fit a model nor to choose one.

The cross-validated R² that chooses the surrogate (:mod:`loco.studies.surrogate_selection`) is
the best of six scores on the same folds, so it is optimistic by the selection itself; and with
the training design extended until the score looks good, the design could be tuned to the target
as well. An independent Latin hypercube (:func:`loco.studies.surrogate_samples.holdout_design`,
its own seed) scored once, after the choice, is free of both: its R² is the honest accuracy of
the model NSGA-II optimises on, within the sampling error of the held-out set
(:func:`r2_interval`, reported by the surrogate stage).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import numpy.typing as npt

import loco
from loco.studies.parameter_study import StudySetup, samples_frame
from loco.studies.rbf_network import r2_score
from loco.studies.report import StudyRecord, save_json, save_table
from loco.studies.stages import Demand, Runtime, Stage
from loco.studies.surrogate_samples import HOLDOUT_SEED_OFFSET, holdout_design, simulate_design
from loco.studies.surrogate_selection import Selection

__all__ = [
    "HoldoutSamplesStage",
    "assert_disjoint",
    "holdout_scores",
    "r2_interval",
    "run_holdout",
]

FloatArray = npt.NDArray[np.float64]


def assert_disjoint(train: npt.ArrayLike, holdout: npt.ArrayLike) -> None:
    """Raise :class:`ValueError` if a held-out sample (row of ``holdout``) is also a training
    sample (row of ``train``, exactly equal): the held-out score would no longer be held out."""
    a = np.ascontiguousarray(np.asarray(train, dtype=np.float64))
    b = np.ascontiguousarray(np.asarray(holdout, dtype=np.float64))
    if a.size == 0 or b.size == 0:
        return
    seen = {row.tobytes() for row in a}
    shared = [i for i, row in enumerate(b) if row.tobytes() in seen]
    if shared:
        raise ValueError(
            f"held-out samples {shared[:5]} (of {len(shared)}) are also training samples"
        )


def holdout_scores(
    selection: Selection, x: FloatArray, y: FloatArray, *, log_target: bool = True
) -> dict[str, float]:
    """R² on the objective ``y`` (n,) at the fresh samples ``x`` (n, 6) of every candidate of
    ``selection`` as fitted on all its training samples (``selection.models``), the ones NSGA-II
    would use. Samples whose objective failed (NaN) are left out."""
    ok = np.isfinite(y)
    out = {}
    for kind, model in selection.models.items():
        p = np.asarray(model.predict(x[ok]), dtype=np.float64)
        out[kind] = float(r2_score(y[ok], np.exp(p) if log_target else p)[0])
    return out


def r2_interval(
    y: FloatArray, predicted: FloatArray, *, level: float = 0.95, n_boot: int = 2000, seed: int = 0
) -> tuple[float, float]:
    """Bootstrap percentile interval of the held-out R² (resampling the held-out points): how
    much the score would move with another held-out set of the same size."""
    rng = np.random.default_rng(seed)
    n = len(y)
    draws = np.empty(n_boot)
    for i in range(n_boot):
        pick = rng.integers(0, n, n)
        draws[i] = float(r2_score(y[pick], predicted[pick])[0])
    tail = (1 - level) / 2
    return float(np.quantile(draws, tail)), float(np.quantile(draws, 1 - tail))


@dataclass(frozen=True)
class HoldoutSamplesStage(Stage):
    """The stage ``surrogate_holdout`` of ``loco reproduce``: :func:`run_holdout` of ``n``
    fresh samples (``seed``, ``setup``)."""

    name: ClassVar[str] = "surrogate_holdout"
    setup: StudySetup
    n: int
    seed: int = 0

    def demand(self) -> Demand:
        """Both objectives on every held-out sample."""
        return self.setup.demand(self.n)

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """:func:`run_holdout` into ``out_dir``."""
        return run_holdout(self.setup, self.n, self.seed, out_dir, runtime)


def run_holdout(
    setup: StudySetup, n: int, seed: int, out_dir: Path, runtime: Runtime | None = None
) -> StudyRecord:
    """Simulate both objectives (``setup``, on ``runtime``) at the :func:`holdout_design` of
    ``n`` samples. Writes ``holdout_samples.csv`` (the columns of ``monte_carlo.csv``) and
    ``holdout_samples.json``."""
    x = holdout_design(n, seed)
    y, failed = simulate_design(setup, runtime, x)
    settings = {
        "loco_version": loco.__version__,
        "holdout_samples": n,
        "holdout_seed": seed + HOLDOUT_SEED_OFFSET,
        **setup.settings(),
    }
    return StudyRecord(
        name=out_dir.name,
        title="Fresh samples the surrogates are scored on (neither trained nor selected on)",
        tables=[
            save_table(samples_frame(x, y), out_dir / "holdout_samples.csv"),
            save_json(settings, out_dir / "holdout_samples.json"),
        ],
        parameters=settings,
        notes=f"{n} Latin hypercube samples (seed {seed + HOLDOUT_SEED_OFFSET}), simulated like "
        f"the training samples; failed runs: {failed}.",
    )
