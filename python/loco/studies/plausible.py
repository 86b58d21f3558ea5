"""The stage ``plausible`` of ``loco reproduce``: plausible locomotives (a Latin hypercube over the
ranged inputs and the low-conicity pairs, :mod:`loco.studies.premise_probability`) with every
damper on S_low and S_high: the share that has the study's premise, with its interval, and what
the FSDs do there. The simulations are ``loco.run_batch`` campaigns with the run's executor and
sample store.

Which inputs decide the premise, and the FSDs' advantage, over plausible locomotives.

:func:`premise_sensitivity`: a random-forest classifier of "premise holds" (scikit-learn) on the
inputs and the S_low pair, fitted on some locomotives and scored on the others, and its
permutation importances on the held-out ones. :func:`advantage_sensitivity`: the same with a
random-forest regressor of each FSD's advantage, the log of its judging metric over the better
fixed damper's (YD1 on S_low, YD2 on S_high), scored by its held-out R². Random forests rather
than Sobol' indices on a surrogate: the inputs number about a hundred and the locomotives a few
hundred, too few for a surrogate of that dimension to be validated, while a forest's held-out
score says directly whether the inputs explain the outcome at all (a score no better than the
majority class, or an R² about zero, means they do not, and the importances are then noise).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import pandas as pd

import loco
from loco.studies import captions as figure_captions
from loco.studies import premise_probability
from loco.studies.fsd_comparison import LEAD_IN
from loco.studies.plotting import pyplot, save_figure
from loco.studies.premise_probability import VALVED, Plausible, premise_holds
from loco.studies.report import StudyRecord, save_json
from loco.studies.stages import DataFile, Demand, Runtime, Stage

__all__ = [
    "PlausibleStage",
    "advantage_sensitivity",
    "plot_plausible",
    "pooled",
    "premise_sensitivity",
    "probability_note",
]


@dataclass(frozen=True)
class PlausibleStage(Stage):
    """``n`` plausible locomotives of ``vehicle`` (from ``seed``) with every damper of
    :data:`loco.studies.premise_probability.DAMPERS` on their S_low pair and on S_high,
    ``distance`` m at ``speed_kmh`` km/h after the lead-in, on ``n_tracks`` tracks. Writes
    ``plausible.csv`` (inputs, pair, metrics, premise and valve shares per locomotive),
    ``plausible_fraction.csv``, ``plausible_fsd.csv``, ``plausible_importance.csv`` (which
    inputs decide the premise), ``plausible_advantage.csv`` (which decide the FSDs' advantage,
    :func:`advantage_sensitivity`), ``plausible.json`` and ``plausible.png``."""

    name: ClassVar[str] = "plausible"
    n: int = 200
    seed: int = 0
    n_tracks: int = 2
    speed_kmh: float = 200.0
    distance: float = 500.0
    vehicle: loco.Locomotive | None = None
    integrator: str = loco.Scenario.integrator
    ranges: DataFile | None = None

    def demand(self) -> Demand:
        runs = self.n * len(premise_probability.DAMPERS) * 2 * self.n_tracks
        return Demand.runs(runs, self.distance + LEAD_IN, self.speed_kmh / 3.6)

    def run(self, out_dir: Path, runtime: Runtime) -> StudyRecord:
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        pp = premise_probability
        result = pp.run_plausible(
            self.n,
            self.seed,
            n_tracks=self.n_tracks,
            speed=self.speed_kmh / 3.6,
            distance=self.distance,
            vehicle=self.vehicle,
            threads=runtime.threads,
            progress=runtime.progress,
            integrator=self.integrator,
            ranges_file=None if self.ranges is None else self.ranges.path,
        )
        summary = pp.summarise(result)
        sens = premise_sensitivity(result, seed=self.seed)
        advantage = advantage_sensitivity(result, seed=self.seed)
        paths = {
            "plausible": out / "plausible.csv",
            "fraction": out / "plausible_fraction.csv",
            "fsd": out / "plausible_fsd.csv",
            "importance": out / "plausible_importance.csv",
            "advantage": out / "plausible_advantage.csv",
        }
        pp.to_frame(result).to_csv(paths["plausible"], index=False, float_format="%.6g")
        summary["fraction"].to_csv(paths["fraction"], index=False, float_format="%.4g")
        summary["fsd"].to_csv(paths["fsd"], index=False, float_format="%.4g")
        sens["importance"].to_csv(paths["importance"], index=False, float_format="%.4g")
        advantage.to_csv(paths["advantage"], index=False, float_format="%.4g")
        meta = {
            **result.settings,
            "failed_runs": result.failed,
            "classifier_accuracy": sens["accuracy"],
            "majority_share": sens["majority"],
        }
        meta_path = save_json(meta, out / "plausible.json")
        figure = plot_plausible(summary, result, out / "plausible.png")
        return StudyRecord(
            name=self.name,
            title="The verdict's probability: plausible locomotives",
            figures=[figure],
            tables=[*paths.values(), meta_path],
            captions=figure_captions.PLAUSIBLE,
            notes=probability_note(summary["fraction"], result.failed),
        )


def pooled(fraction: pd.DataFrame, rule: str = "premise") -> pd.Series:
    """The pooled row of a ``plausible_fraction`` table for ``rule``."""
    return fraction[(fraction["pair"] == "all pairs") & (fraction["rule"] == rule)].iloc[0]


def probability_note(fraction: pd.DataFrame, failed: int = 0) -> str:
    """The share with the premise, pooled, with its interval (and the failed runs)."""
    row = pooled(fraction)
    note = (
        f"The premise holds on {int(row['k'])} of {int(row['n'])} plausible locomotives "
        f"({row['fraction']:.0%}, 95 % Wilson interval {row['low']:.0%}–{row['high']:.0%})."
    )
    if failed:
        note += f" {failed} runs failed (their locomotives' metrics are means of the rest)."
    return note


def plot_plausible(
    summary: dict[str, pd.DataFrame], result: premise_probability.Plausible, path: Path
) -> Path:
    """Left: the share with the premise per S_low pair and pooled, with 95 % intervals. Right:
    inside the premise set, each FSD's judging metric over the better fixed damper's, per
    locomotive (below 1: the FSD is better)."""
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    rows = summary["fraction"][summary["fraction"]["rule"] == "premise"]
    y = np.arange(len(rows))
    left.errorbar(
        rows["fraction"],
        y,
        xerr=[rows["fraction"] - rows["low"], rows["high"] - rows["fraction"]],
        fmt="o",
        capsize=4,
    )
    left.set_yticks(y, [f"{p} (n={n})" for p, n in zip(rows["pair"], rows["n"], strict=True)])
    left.invert_yaxis()
    left.set_xlim(0, 1)
    left.set_xlabel("share of plausible locomotives with the premise (95 % interval)")
    m = result.metrics[premise_probability.premise_holds(result.metrics)]
    data, labels = [], []
    for name in premise_probability.VALVED:
        for scenario, better in (("S_low", "YD1"), ("S_high", "YD2")):
            ratio = (m[f"{scenario} {name}"] / m[f"{scenario} {better}"]).dropna()
            if len(ratio):
                data.append(ratio.to_numpy())
                labels.append(f"{name}/{better}\n{scenario}")
    if data:
        right.boxplot(data)
        right.set_xticks(range(1, len(data) + 1), labels)
        right.set_yscale("log")
    right.axhline(1.0, color="0.5", lw=0.8)
    right.set_ylabel("FSD metric / better fixed damper's (–)")
    right.set_title(f"inside the premise set ({len(m)} locomotives)", fontsize=10)
    fig.tight_layout()
    return save_figure(fig, path)


def _features(result: Plausible) -> pd.DataFrame:
    """The inputs and the S_low pair (one-hot) of every locomotive."""
    pairs = pd.get_dummies(pd.Series(result.pairs, name="pair"), dtype=float)
    return pd.concat([result.inputs, pairs], axis=1)


def _importance(model: Any, x: pd.DataFrame, y: Any, seed: int) -> pd.DataFrame:
    """Permutation importances of ``model`` on held-out ``x``, ``y`` (mean and sd of 20)."""
    from sklearn.inspection import permutation_importance

    imp = permutation_importance(model, x, y, n_repeats=20, random_state=seed, n_jobs=1)
    return (
        pd.DataFrame(
            {
                "input": list(x.columns),
                "importance": imp.importances_mean,
                "std": imp.importances_std,
            }
        )
        .sort_values("importance", ascending=False)
        .reset_index(drop=True)
    )


def premise_sensitivity(
    result: Plausible, seed: int = 0, test_share: float = 0.25
) -> dict[str, Any]:
    """Which inputs decide the premise: a random-forest classifier (scikit-learn, 300 trees)
    of "premise holds" on the inputs and the S_low pair (one-hot), fitted on
    ``1 − test_share`` of the locomotives and scored on the rest (accuracy, and the share of
    the majority class it must beat); then the permutation importance of each input on the
    held-out set (the drop of accuracy when the input is shuffled, mean of 20 repeats). A
    classifier that does no better than the majority class explains nothing, and its
    importances say so by being about zero."""
    from sklearn.ensemble import RandomForestClassifier
    from sklearn.model_selection import train_test_split

    y = premise_holds(result.metrics).to_numpy()
    x = _features(result)
    minority = int(min(y.sum(), (~y).sum()))
    if minority < 2 or round(len(y) * test_share) < 2:
        # Too few locomotives of one class to fit on some and score on others: no classifier.
        majority = float(max(y.mean(), 1 - y.mean())) if len(y) else math.nan
        empty = pd.DataFrame(columns=["input", "importance", "std"])
        return {"accuracy": math.nan, "majority": majority, "importance": empty}
    x_fit, x_test, y_fit, y_test = train_test_split(
        x, y, test_size=test_share, random_state=seed, stratify=y
    )
    model = RandomForestClassifier(n_estimators=300, random_state=seed, n_jobs=1).fit(x_fit, y_fit)
    accuracy = float(model.score(x_test, y_test))
    majority = float(max(y_test.mean(), 1 - y_test.mean()))
    return {
        "accuracy": accuracy,
        "majority": majority,
        "importance": _importance(model, x_test, y_test, seed),
    }


def advantage_sensitivity(
    result: Plausible, seed: int = 0, test_share: float = 0.25
) -> pd.DataFrame:
    """Which inputs decide each FSD's advantage: per FSD and scenario, a random-forest regressor
    (300 trees) of log(FSD metric / better fixed damper's metric) on the inputs and the pair,
    fitted on ``1 − test_share`` of the locomotives with a finite ratio and scored on the rest
    (R², ``r2``); the rows are its inputs' permutation importances on the held-out set (the drop
    of R²), with ``damper``, ``scenario``, ``r2`` and ``n`` (locomotives) on every row. Fewer
    than 8 locomotives: no row."""
    from sklearn.ensemble import RandomForestRegressor
    from sklearn.model_selection import train_test_split

    x = _features(result)
    frames = []
    for name in VALVED:
        for scenario, better in (("S_low", "YD1"), ("S_high", "YD2")):
            ratio = result.metrics[f"{scenario} {name}"] / result.metrics[f"{scenario} {better}"]
            keep = np.isfinite(ratio) & (ratio > 0)
            if int(keep.sum()) < 8:
                continue
            y = np.log(ratio[keep].to_numpy())
            x_fit, x_test, y_fit, y_test = train_test_split(
                x[keep], y, test_size=test_share, random_state=seed
            )
            model = RandomForestRegressor(n_estimators=300, random_state=seed, n_jobs=1)
            model.fit(x_fit, y_fit)
            frame = _importance(model, x_test, y_test, seed)
            frame.insert(0, "n", int(keep.sum()))
            frame.insert(0, "r2", float(model.score(x_test, y_test)))
            frame.insert(0, "scenario", scenario)
            frame.insert(0, "damper", name)
            frames.append(frame)
    if not frames:
        return pd.DataFrame(columns=["damper", "scenario", "r2", "n", "input", "importance", "std"])
    return pd.concat(frames, ignore_index=True)
