"""The surrogate stage of the parameter study (SPEC §6.3): the held-out R² of the SPEC RBF network
on the Latin hypercube Monte Carlo (SPEC's 200 samples), that of every candidate of
:mod:`loco.studies.surrogate_selection` on the surrogate's training samples (the Monte Carlo's
and the extension of :mod:`loco.studies.surrogate_samples`), the nested cross-validation of the
choice, which surrogate the Sobol' and NSGA-II stages (:mod:`loco.studies.sensitivity`,
:mod:`loco.studies.optimisation`) use, and every candidate's R² on fresh samples
(:mod:`loco.studies.surrogate_holdout`): the number the requirement of SPEC §6.3 is judged on
when they exist.

The models learn log(objective) (:data:`loco.studies.parameter_study.LOG_TARGET`) and are scored on
the objective itself.
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import pandas as pd

import loco
from loco.studies import captions as figure_captions
from loco.studies.parameter_study import (
    LOG_TARGET,
    OBJECTIVES,
    FloatArray,
    StudySetup,
    load_monte_carlo,
)
from loco.studies.parameters import bounds_si
from loco.studies.rbf_network import parity_plot
from loco.studies.report import StudyRecord, jsonable, save_json, save_table
from loco.studies.stages import DataFile, Runtime, Stage, encode
from loco.studies.surrogate_fits import Objective, select_objectives
from loco.studies.surrogate_holdout import assert_disjoint, holdout_scores, r2_interval
from loco.studies.surrogate_selection import (
    CANDIDATES,
    DESCRIPTIONS,
    R2_REQUIRED,
    SPEC_MODEL,
    CandidateScore,
    Selection,
    selection_settings,
)

__all__ = [
    "OnSurrogates",
    "SurrogateStage",
    "Training",
    "select_surrogates",
    "spec_scores",
    "surrogate_label",
    "validate_surrogate",
]


def select_surrogates(
    x: FloatArray,
    y: FloatArray,
    *,
    n_splits: int = 5,
    seed: int = 0,
    log_target: bool = LOG_TARGET,
    candidates: Sequence[str] = CANDIDATES,
    nested: bool = False,
    n_jobs: int | None = None,
) -> list[Selection]:
    """For each objective (column of ``y``), on the samples where it is finite: every candidate
    of :mod:`loco.studies.surrogate_selection` (or of ``candidates``) scored on the same
    ``n_splits`` folds, the best refitted on all of them (``selection.model``, the surrogate
    Sobol' and NSGA-II use) and the SPEC network (``selection.spec_model``); with ``nested``
    the nested cross-validation of the choice too (``selection.nested``).

    Every fit (objective × candidate × fold) is a task of :mod:`loco.studies.surrogate_fits`,
    run in ``n_jobs`` processes (joblib's loky; default one per core): every fit is seeded and
    single-threaded, so the result is the same for any ``n_jobs``."""
    objectives = []
    for j in range(y.shape[1]):
        ok = np.isfinite(y[:, j])
        objectives.append(Objective(x[ok], y[ok, j]))
    return select_objectives(
        objectives,
        bounds_si(),
        n_splits=n_splits,
        seed=seed,
        log_target=log_target,
        candidates=candidates,
        nested=nested,
        n_jobs=os.cpu_count() or 1 if n_jobs is None else n_jobs,
    )


def spec_scores(
    x: FloatArray,
    y: FloatArray,
    *,
    n_splits: int = 5,
    seed: int = 0,
    log_target: bool = LOG_TARGET,
) -> list[CandidateScore]:
    """The SPEC network's held-out scores for each objective on ``(x, y)`` alone (the Monte
    Carlo's samples), on the folds :func:`select_surrogates` would use there."""
    only_spec = select_surrogates(
        x, y, n_splits=n_splits, seed=seed, log_target=log_target, candidates=(SPEC_MODEL,)
    )
    return [s.scores[SPEC_MODEL] for s in only_spec]


def surrogate_label(selections: Sequence[Selection]) -> str:
    """Which surrogate each objective uses, e.g. ``W_y: gp, A_yb: gp``."""
    return ", ".join(f"{o.label}: {s.chosen}" for o, s in zip(OBJECTIVES, selections, strict=True))


#: The training set of the last :meth:`Training.fitted` (by its hash), shared by the surrogate,
#: Sobol' and NSGA-II stages of one run: the selection fits every candidate on every fold.
_FITTED: dict[str, tuple[FloatArray, FloatArray, list[Selection]]] = {}


@dataclass(frozen=True)
class Training:
    """The surrogates' training: the sample ``tables`` (``monte_carlo.csv`` and the extension's,
    by content), chosen by ``kfold``-fold held-out R² among ``candidates`` (``seed``: the folds
    and the networks' K-means), learning log(objective) when ``log_target``."""

    tables: tuple[DataFile, ...]
    kfold: int
    seed: int = 0
    log_target: bool = LOG_TARGET
    candidates: tuple[str, ...] = CANDIDATES
    nested: bool = True

    def fitted(self) -> tuple[FloatArray, FloatArray, list[Selection]]:
        """The samples (x SI, y objectives) of the tables, stacked, and the surrogates chosen and
        fitted on them (:func:`select_surrogates`); computed once for the same training."""
        key = json.dumps(encode(self), sort_keys=True)
        if key not in _FITTED:
            parts = [load_monte_carlo(t.path) for t in self.tables]
            x = np.vstack([p[0] for p in parts])
            y = np.vstack([p[1] for p in parts])
            chosen = select_surrogates(
                x,
                y,
                n_splits=self.kfold,
                seed=self.seed,
                log_target=self.log_target,
                candidates=self.candidates,
                nested=self.nested,
            )
            _FITTED.clear()
            _FITTED[key] = (x, y, chosen)
        return _FITTED[key]


@dataclass(frozen=True)
class SurrogateStage(Stage):
    """The stage ``surrogate`` of ``loco reproduce``: :func:`validate_surrogate` of the
    ``training``, the SPEC network also scored on the first ``spec_samples`` (the Monte
    Carlo's), every candidate on the fresh samples of the table ``holdout`` if given."""

    name: ClassVar[str] = "surrogate"
    training: Training
    spec_samples: int
    holdout: DataFile | None = None

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        """:func:`validate_surrogate` into ``out_dir`` (no simulation)."""
        t = self.training
        x, y, chosen = t.fitted()
        fresh = None if self.holdout is None else load_monte_carlo(self.holdout.path)
        return validate_surrogate(
            x,
            y,
            out_dir,
            n_splits=t.kfold,
            seed=t.seed,
            log_target=t.log_target,
            selections=chosen,
            spec_samples=self.spec_samples,
            holdout=fresh,
        )


def validate_surrogate(
    x: FloatArray,
    y: FloatArray,
    out_dir: Path,
    *,
    n_splits: int = 5,
    seed: int = 0,
    log_target: bool = LOG_TARGET,
    selections: Sequence[Selection] | None = None,
    spec_samples: int | None = None,
    holdout: tuple[FloatArray, FloatArray] | None = None,
) -> StudyRecord:
    """k-fold held-out R² of the SPEC network (SPEC §6.3) and of the other surrogate candidates
    for each objective, and which one the surrogate Sobol' indices and NSGA-II use
    (:func:`select_surrogates`; pass its result as ``selections`` when already computed with the
    same ``n_splits``, ``seed`` and ``log_target``). Failed samples (NaN) are left out of that
    objective's folds. With ``log_target`` the models learn log(objective) and the R² is that of
    their exponential against the objective itself (scikit-learn ``KFold`` shuffled with
    ``seed``). The first ``spec_samples`` rows (default all) are the Monte Carlo's: the SPEC
    network is also scored on those alone (:func:`spec_scores`), the R² SPEC §6.3 asks about.
    ``holdout`` (x, y) are fresh samples, disjoint from ``x`` (checked): every candidate fitted on
    all of ``x`` is scored on them (:func:`~loco.studies.surrogate_holdout.holdout_scores`, with
    a bootstrap 95 % interval for the one used), and whether the requirement is met is judged on
    that score.

    Writes ``surrogate_r2.csv`` (R² per model and fold on every sample),
    ``surrogate_selection.csv`` (mean and worst-fold R² per model, hyperparameters, which was
    used), ``surrogate_spec.csv`` (the SPEC network's R² per fold on the Monte Carlo's samples),
    ``surrogate_predictions.csv`` (held-out prediction of every sample by every model),
    ``parity_<label>.png`` (the SPEC network on the Monte Carlo's samples),
    ``parity_<label>_used.png`` (the model used) and ``surrogate.json``.
    """
    if selections is None:
        selections = select_surrogates(x, y, n_splits=n_splits, seed=seed, log_target=log_target)
    if holdout is not None:
        assert_disjoint(x, holdout[0])
    n_spec = len(x) if spec_samples is None else spec_samples
    spec = spec_scores(x[:n_spec], y[:n_spec], n_splits=n_splits, seed=seed, log_target=log_target)
    folds, predictions, rows, figures, spec_folds = [], [], [], [], []
    summary: dict[str, dict[str, Any]] = {}
    for j, (objective, sel) in enumerate(zip(OBJECTIVES, selections, strict=True)):
        ok = np.isfinite(y[:, j])
        spec_folds.append(pd.DataFrame({"objective": objective.label, "model": SPEC_MODEL,
                                        "samples": n_spec,
                                        "fold": np.arange(len(spec[j].r2_folds)),
                                        "r2": spec[j].r2_folds}))  # fmt: skip
        frame = pd.DataFrame({"objective": objective.label, "sample": np.flatnonzero(ok),
                              "simulated": y[ok, j]})  # fmt: skip
        for kind, score in sel.scores.items():
            folds.append(pd.DataFrame({"objective": objective.label, "model": kind,
                                       "fold": np.arange(len(score.r2_folds)),
                                       "r2": score.r2_folds}))  # fmt: skip
            frame[f"predicted_{kind}"] = score.predictions
            rows.append({
                "objective": objective.label,
                "model": kind,
                "description": DESCRIPTIONS[kind],
                "r2_mean": score.r2_mean,
                "r2_min": score.r2_min,
                "used": kind == sel.chosen,
                "hyperparameters": json.dumps(jsonable(score.hyperparameters)),
            })  # fmt: skip
        predictions.append(frame)
        fresh: dict[str, Any] = {}
        if holdout is not None:
            held = holdout_scores(sel, holdout[0], holdout[1][:, j], log_target=log_target)
            okh = np.isfinite(holdout[1][:, j])
            p = sel.model.predict(holdout[0][okh])
            lo, hi = r2_interval(holdout[1][okh, j], np.exp(p) if log_target else p, seed=seed)
            for row in rows:
                if row["objective"] == objective.label:
                    row["holdout_r2"] = held[str(row["model"])]
            fresh = {"holdout_r2": held, "holdout_r2_used": held[sel.chosen],
                     "holdout_r2_used_95": [lo, hi], "holdout_samples": int(okh.sum())}  # fmt: skip
        ok_spec = np.isfinite(y[:n_spec, j])
        for kind, suffix, truth, predicted, n in (
            (SPEC_MODEL, "", y[:n_spec][ok_spec, j], spec[j].predictions, int(ok_spec.sum())),
            (sel.chosen, "_used", y[ok, j], sel.scores[sel.chosen].predictions, int(ok.sum())),
        ):
            figures.append(
                parity_plot(
                    truth,
                    predicted,
                    out_dir / f"parity_{objective.label}{suffix}.png",
                    label=objective.label,
                    unit=objective.unit,
                    title=f"{kind} surrogate of {objective.label} ({objective.scenario}), "
                    f"{n} samples, {n_splits}-fold held out" + (" (used)" if suffix else " (SPEC)"),
                )
            )
        summary[objective.label] = {
            "spec_r2_mean": spec[j].r2_mean,
            "spec_r2_min": spec[j].r2_min,
            "spec_samples": int(ok_spec.sum()),
            "used": sel.chosen,
            "used_r2_mean": sel.scores[sel.chosen].r2_mean,
            "nested_selection_r2": None if sel.nested is None else sel.nested.r2_mean,
            "nested_choices": None if sel.nested is None else list(sel.nested.chosen),
            "meets_r2_required": (
                fresh["holdout_r2_used"] >= R2_REQUIRED if fresh else sel.meets_requirement
            ),
            **fresh,
            "why": sel.reason(),
            "r2_mean": {k: v.r2_mean for k, v in sel.scores.items()},
            "n_samples": int(ok.sum()),
        }
    settings = {
        "loco_version": loco.__version__,
        "n_splits": n_splits,
        "seed": seed,
        "log_target": log_target,
        "training_samples": len(x),
        "spec_samples": n_spec,
        "holdout_samples": 0 if holdout is None else len(holdout[0]),
        **selection_settings(n_splits),
        "r2": summary,
    }
    spec_text = ", ".join(
        f"{k} {v['spec_r2_mean']:.3f} (worst fold {v['spec_r2_min']:.3f})"
        for k, v in summary.items()
    )
    used = "; ".join(f"{k}: **{v['used']}**, because {v['why']}" for k, v in summary.items())
    met = all(v["meets_r2_required"] for v in summary.values())
    notes = (
        f"SPEC network (10 Gaussian units) mean held-out R²: {spec_text} on the Monte Carlo's "
        f"{n_spec} samples (SPEC §6.3 asks for > {R2_REQUIRED}). Candidates on the surrogate's "
        f"{len(x)} training samples, same folds (mean held-out R²): "
        + "; ".join(
            f"{k}: " + ", ".join(f"{m} {r:.3f}" for m, r in v["r2_mean"].items())
            for k, v in summary.items()
        )
        + f". Surrogate used by the surrogate Sobol' indices and NSGA-II: {used}. "
        + "".join(
            f"{k}: nested cross-validation of the choice {v['nested_selection_r2']:.3f}. "
            for k, v in summary.items()
            if v["nested_selection_r2"] is not None
        )
        + (
            "On fresh samples used neither to train nor to choose (judged on these): "
            + "; ".join(
                f"{k} {v['holdout_r2_used']:.3f} (95 % [{v['holdout_r2_used_95'][0]:.3f}, "
                f"{v['holdout_r2_used_95'][1]:.3f}], {v['holdout_samples']} samples)"
                for k, v in summary.items()
            )
            + ". "
            if holdout is not None
            else ""
        )
        + (
            f"Both objectives reach R² ≥ {R2_REQUIRED}."
            if met
            else f"**Not every objective reaches R² ≥ {R2_REQUIRED}**: the Pareto front rests on a "
            "surrogate below the required accuracy (see the re-simulated points)."
        )
    )
    return StudyRecord(
        name=out_dir.name,
        title="Surrogates: held-out R² by k-fold cross-validation, and the one used (SPEC §6.3)",
        figures=figures,
        tables=[
            save_table(pd.DataFrame(rows), out_dir / "surrogate_selection.csv"),
            save_table(pd.concat(folds, ignore_index=True), out_dir / "surrogate_r2.csv"),
            save_table(pd.concat(spec_folds, ignore_index=True), out_dir / "surrogate_spec.csv"),
            save_table(
                pd.concat(predictions, ignore_index=True), out_dir / "surrogate_predictions.csv"
            ),
            save_json(settings, out_dir / "surrogate.json"),
        ],
        parameters={k: v for k, v in settings.items() if k != "r2"},
        notes=notes,
        captions=figure_captions.parity_captions(figures),
    )


@dataclass(frozen=True)
class OnSurrogates(Stage):
    """A stage on the surrogates of ``training`` that also simulates on ``setup``; ``seed``
    seeds its designs and the networks."""

    setup: StudySetup
    training: Training
    seed: int

    def _study(
        self, study: Callable[..., StudyRecord], out_dir: Path, runtime: Runtime, **sizes: Any
    ) -> StudyRecord:
        x, y, chosen = self.training.fitted()
        return study(
            self.setup,
            x,
            y,
            out_dir,
            seed=self.seed,
            log_target=self.training.log_target,
            models=[c.model for c in chosen],
            surrogate_name=surrogate_label(chosen),
            runtime=runtime,
            **sizes,
        )
