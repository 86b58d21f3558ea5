"""Which inputs decide the premise, and the FSDs' advantage, over plausible locomotives.

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
from typing import Any

import numpy as np
import pandas as pd

from loco.studies.premise_probability import VALVED, Plausible, premise_holds

__all__ = ["advantage_sensitivity", "premise_sensitivity"]


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
