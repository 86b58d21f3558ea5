"""Held-out R² of the parameter study's surrogates on fresh samples, against the number of
training samples.

Training designs are nested: n = 300 is exactly the ``loco reproduce`` surrogate's training set
(the Monte Carlo's Latin hypercube of 200, seed ``--seed``, and the extension's 100, seed
``seed + 7919``, :func:`loco.studies.surrogate_samples.training_design`); every further block is
an independent Latin hypercube (``--blocks`` sizes, seeds ``seed + (i + 2)·7919``), so each
training set is a uniform random design that contains the smaller ones. The held-out set is a
Latin hypercube of ``--holdout`` points seeded ``seed + HOLDOUT_SEED_OFFSET``
(:func:`loco.studies.surrogate_samples.holdout_design`), disjoint from every training block
(checked), used neither to fit nor to choose a model.

For each training size n: every candidate of :mod:`loco.studies.surrogate_selection` scored by
5-fold cross-validation on the n (hyperparameters tuned inside the folds), the best chosen, and
every candidate refitted on the n and scored on the held-out set
(:func:`loco.studies.surrogate_holdout.holdout_scores`). ``--nested`` adds the nested
cross-validation of the choice (:func:`loco.studies.surrogate_selection.nested_selection_r2`,
five times the fits). ``--block-objectives A_yb`` simulates the blocks beyond the first for A_yb
only, which halves their cost.

All runs are the study's: ``loco.run_batch`` on the seed-0 synthetic track, 500 m at 200 km/h,
W_y on S_low and A_yb on S_high (:class:`loco.studies.parameter_study.StudySetup`). They are kept
in ``<out>/store`` (an interrupted run resumes); ``--analyse`` only redoes the fits.

Usage:
``python scripts/verify/surrogate_holdout.py --threads 2 [--holdout 400] [--blocks 200 300]``.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np
import pandas as pd

import loco
from loco import campaign
from loco.executors import LocalExecutor
from loco.studies.evaluators import simulator_evaluator
from loco.studies.parameter_study import OBJECTIVES, StudySetup, labels
from loco.studies.parameters import names
from loco.studies.sampling import latin_hypercube
from loco.studies.surrogate import select_surrogates
from loco.studies.surrogate_holdout import assert_disjoint, holdout_scores
from loco.studies.surrogate_samples import (
    EXTENSION_SEED_OFFSET,
    holdout_design,
    training_design,
)


def designs(args: argparse.Namespace) -> list[tuple[str, np.ndarray, list[str]]]:
    """(name, design, objectives simulated) of every block, in the order simulated."""
    out = [("train_0", training_design(300, 200, args.seed), labels()),
           ("holdout", holdout_design(args.holdout, args.seed), labels())]  # fmt: skip
    for i, n in enumerate(args.blocks):
        x = latin_hypercube(n, seed=args.seed + (i + 2) * EXTENSION_SEED_OFFSET)
        out.append((f"train_{i + 1}", x, args.block_objectives))
    return out


def simulate(args: argparse.Namespace, out: Path) -> pd.DataFrame:
    setup = StudySetup(track_seed=args.seed)
    frames = []
    t0 = time.perf_counter()
    blocks = designs(args)
    assert_disjoint(np.vstack([b[1] for b in blocks if b[0] != "holdout"]),
                    blocks[1][1])  # fmt: skip
    with campaign.using(LocalExecutor(args.threads), out / "store"):
        for name, x, wanted in blocks:
            frame = pd.DataFrame(x, columns=names()).assign(block=name)
            for o in OBJECTIVES:
                if o.label in wanted:
                    ev = simulator_evaluator(setup.scenario(o.scenario), o.metric,
                                             threads=args.threads, seed=args.seed,
                                             progress=False)  # fmt: skip
                    frame[o.label] = ev(x, names())[:, 0]
                else:
                    frame[o.label] = np.nan
                print(f"{name} {o.label}: {len(x)} samples at {time.perf_counter() - t0:.0f} s",
                      flush=True)  # fmt: skip
            frames.append(frame)
            pd.concat(frames, ignore_index=True).to_csv(out / "samples.csv", index=False)
    return pd.concat(frames, ignore_index=True)


def analyse(samples: pd.DataFrame, sizes: list[int], seed: int, nested: bool) -> pd.DataFrame:
    hold = samples[samples.block == "holdout"]
    train = samples[samples.block != "holdout"]
    x_hold, y_hold = hold[names()].to_numpy(), hold[labels()].to_numpy()
    rows = []
    for n in sizes:
        part = train.iloc[:n]
        x, y = part[names()].to_numpy(), part[labels()].to_numpy()
        assert_disjoint(x, x_hold)
        t0 = time.perf_counter()
        sels = select_surrogates(x, y, seed=seed, nested=nested)
        for j, (o, sel) in enumerate(zip(OBJECTIVES, sels, strict=True)):
            if np.isfinite(y[:, j]).sum() < n:
                continue  # this objective was not simulated on every block up to n
            held = holdout_scores(sel, x_hold, y_hold[:, j])
            for k, s in sel.scores.items():
                rows.append({"n": n, "objective": o.label, "model": k, "cv_r2": s.r2_mean,
                             "cv_r2_min": s.r2_min, "holdout_r2": held[k],
                             "chosen": k == sel.chosen,
                             "nested_selection_r2": sel.nested.r2_mean if sel.nested else np.nan,
                             "holdout_samples": int(np.isfinite(y_hold[:, j]).sum())})  # fmt: skip
            print(f"n={n} {o.label}: chosen {sel.chosen}, "
                  + ", ".join(f"{k} cv {s.r2_mean:.3f} held-out {held[k]:.3f}"
                              for k, s in sel.scores.items())
                  + (f"; nested selection {sel.nested.r2_mean:.3f}" if sel.nested else "")
                  + f" ({time.perf_counter() - t0:.0f} s)", flush=True)  # fmt: skip
    return pd.DataFrame(rows)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--holdout", type=int, default=500)
    p.add_argument("--blocks", type=int, nargs="*", default=[200, 300])
    p.add_argument("--block-objectives", nargs="+", default=["W_y", "A_yb"])
    p.add_argument("--sizes", type=int, nargs="+", default=[300, 500, 800])
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--threads", type=int, default=None)
    p.add_argument("--nested", action="store_true", help="also the nested CV of the selection")
    p.add_argument("--out", type=Path, default=Path("results/surrogate_holdout"))
    p.add_argument("--analyse", action="store_true", help="fits only, from samples.csv")
    args = p.parse_args()
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    samples = pd.read_csv(out / "samples.csv") if args.analyse else simulate(args, out)
    n_train = int((samples.block != "holdout").sum())
    table = analyse(samples, [n for n in args.sizes if n <= n_train], args.seed, args.nested)
    table.to_csv(out / "holdout_r2.csv", index=False)
    (out / "surrogate_holdout.json").write_text(json.dumps({
        "loco_version": loco.__version__, "args": {k: str(v) for k, v in vars(args).items()},
        "rows": table.to_dict(orient="records")}, indent=2, default=float) + "\n")  # fmt: skip


if __name__ == "__main__":
    main()
