"""How many samples the parameter study's surrogate needs: held-out R² against the number of
training samples, and how much of each objective no function of the six parameters can predict.

1. Learning curve. The study's design (:func:`loco.studies.surrogate_samples.training_design`:
   the Monte Carlo's 200-point Latin hypercube, then an independent one up to ``--n-total``) is
   simulated once on the study's track (seed 0, 500 m at 200 km/h, W_y on S_low and A_yb on
   S_high). For each training size n, ``--repeats`` random subsets of n samples are scored as the
   surrogate stage scores them (:func:`loco.studies.surrogate_selection.select_surrogate`: 5-fold
   held-out R² of the SPEC network, the larger RBF network and the GP).
2. Noise of the target. The objective is one track's value, a peak (A_yb) or a maximum over
   sections (W_y) of a random response. At ``--noise-points`` of the samples it is simulated again
   on other track seeds (``--noise-seeds``): the spread across tracks at a fixed parameter point
   is the part of the seed-0 value that belongs to that track's realisation. Whether a surrogate
   sees it as noise depends on how fast it changes with the parameters, so the same points are
   also simulated at small steps ``--steps`` (fractions of the box, random directions) on seed 0:
   the semivariogram gamma(d) = E[(f(x + d) - f(x))^2] / 2 against the across-track variance.
   The R² a perfect smooth model of the parameters could reach, if the track part is rough at the
   sample spacing, is 1 - sigma_track^2 / var(f).

Writes into ``--out``: ``samples.csv`` (the design and both objectives), ``learning_curve.csv``,
``noise.csv`` (every repeated evaluation), ``noise_summary.csv``, ``surrogate_learning_curve.png``
and ``surrogate_learning_curve.json``. The simulations are kept in ``<out>/store`` (an interrupted
run resumes); ``--analyse`` only redoes the fits and the figure from ``samples.csv``/``noise.csv``.

Usage: ``python experiments/surrogate_learning_curve.py [--n-total 800] [--threads 2]``.
"""

from __future__ import annotations

import argparse
import itertools
import json
import time
from pathlib import Path

import numpy as np
import pandas as pd

import loco
from loco import campaign
from loco.executors import LocalExecutor
from loco.studies.parameter_study import OBJECTIVES, StudySetup, labels
from loco.studies.parameters import bounds_si, names
from loco.studies.plotting import pyplot, save_figure
from loco.studies.stages import Runtime
from loco.studies.surrogate_samples import training_design
from loco.studies.surrogate_selection import CANDIDATES, R2_REQUIRED, select_surrogate


def _noise(args: argparse.Namespace, x: np.ndarray) -> pd.DataFrame:
    """The first ``--noise-points`` samples again on other track seeds and at small steps."""
    rng = np.random.default_rng(args.seed)
    points = np.arange(args.noise_points)
    rows = []
    for s in args.noise_seeds:
        setup = StudySetup(track_seed=s)
        ys = setup.evaluator(Runtime(args.threads, progress=False))(x[points], names())
        rows += [{"point": int(i), "kind": "track_seed", "value": s,
                  **dict(zip(labels(), v, strict=True))}
                 for i, v in zip(points, ys, strict=True)]  # fmt: skip
    bounds = bounds_si()
    lo, hi = bounds[:, 0], bounds[:, 1]
    for step in args.steps:
        u = rng.normal(size=(len(points), x.shape[1]))
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        xp = x[points] + step * u * (hi - lo)
        # Reflect at the box's faces so that every perturbed point stays inside it.
        xp = np.where(xp < lo, 2 * lo - xp, xp)
        xp = np.where(xp > hi, 2 * hi - xp, xp)
        yp = StudySetup().evaluator(Runtime(args.threads, progress=False))(xp, names())
        rows += [{"point": int(i), "kind": "step", "value": step,
                  **dict(zip(labels(), v, strict=True))}
                 for i, v in zip(points, yp, strict=True)]  # fmt: skip
    return pd.DataFrame(rows)


def simulate(args: argparse.Namespace, out: Path) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The design and the repeated evaluations, simulated (or read back from the store) in
    blocks: the Monte Carlo's samples, the repeated evaluations, then ``--block`` samples at a
    time, each block written to ``samples.csv`` when done (``--analyse`` works on a partial
    run)."""
    x = training_design(args.n_total, args.lhs_samples, args.seed)
    edges = [0, args.lhs_samples, *range(args.lhs_samples + args.block, len(x), args.block)]
    edges.append(len(x))
    frames = []
    noise = pd.DataFrame()
    t0 = time.perf_counter()
    with campaign.using(LocalExecutor(args.threads), out / "store"):
        for a, b in itertools.pairwise(edges):
            y = StudySetup().evaluator(Runtime(args.threads, progress=False))(x[a:b], names())
            frames.append(pd.DataFrame(x[a:b], columns=names()).assign(
                **{k: y[:, j] for j, k in enumerate(labels())}))  # fmt: skip
            pd.concat(frames, ignore_index=True).to_csv(out / "samples.csv", index=False)
            print(f"samples {a}-{b} done at {time.perf_counter() - t0:.0f} s", flush=True)
            if a == 0:
                noise = _noise(args, x)
                noise.to_csv(out / "noise.csv", index=False)
                print(f"noise: {len(noise)} samples at {time.perf_counter() - t0:.0f} s",
                      flush=True)  # fmt: skip
    return pd.concat(frames, ignore_index=True), noise


def learning_curve(
    samples: pd.DataFrame, sizes: list[int], repeats: int, seed: int
) -> pd.DataFrame:
    x = samples[names()].to_numpy()
    rows = []
    for n in sizes:
        for r in range(repeats if n < len(x) else 1):
            pick = np.random.default_rng([seed, n, r]).choice(len(x), n, replace=False)
            for objective in OBJECTIVES:
                y = samples[objective.label].to_numpy()[pick]
                ok = np.isfinite(y)
                t0 = time.perf_counter()
                sel = select_surrogate(x[pick][ok], y[ok], bounds_si(), n_splits=5, seed=r)
                rows += [{"n": n, "repeat": r, "objective": objective.label, "model": k,
                          "r2_mean": s.r2_mean, "r2_min": s.r2_min,
                          "noise_share": s.hyperparameters.get("noise_share", np.nan),
                          "chosen": k == sel.chosen} for k, s in sel.scores.items()]  # fmt: skip
                print(f"n={n} repeat {r} {objective.label}: "
                      + ", ".join(f"{k} {s.r2_mean:.3f}" for k, s in sel.scores.items())
                      + f" ({time.perf_counter() - t0:.0f} s)")  # fmt: skip
    return pd.DataFrame(rows)


def noise_summary(samples: pd.DataFrame, noise: pd.DataFrame) -> pd.DataFrame:
    """Per objective: the variance over the design, the mean across-track variance at a point,
    the R² ceiling it implies, the R² of one other track's value as a prediction of seed 0's, and
    the semivariogram at each step."""
    rows = []
    for label in labels():
        f = samples[label].to_numpy()
        total = float(np.nanvar(f))
        seeds = noise[noise.kind == "track_seed"].pivot(index="point", columns="value",
                                                        values=label)  # fmt: skip
        f0 = f[seeds.index.to_numpy()]
        every = np.column_stack([f0, seeds.to_numpy()])
        var_track = float(np.nanmean(np.nanvar(every, axis=1, ddof=1)))
        # Relative spread (the across-track coefficient of variation) at each point.
        cv = float(np.nanmean(np.nanstd(every, axis=1, ddof=1) / np.nanmean(every, axis=1)))
        repeat_r2 = float(np.nanmean([1 - np.nanmean((seeds[s].to_numpy() - f0) ** 2) / total
                                      for s in seeds.columns]))  # fmt: skip
        row = {"objective": label, "var_design": total, "var_track": var_track,
               "track_cv": cv, "r2_ceiling": 1 - var_track / total,
               "r2_other_track": repeat_r2, "points": len(seeds),
               "tracks": every.shape[1]}  # fmt: skip
        for step, group in noise[noise.kind == "step"].groupby("value"):
            g = group.set_index("point")[label]
            d = g.to_numpy() - f[g.index.to_numpy()]
            row[f"gamma_step_{step:g}"] = float(np.nanmean(d**2) / 2)
        rows.append(row)
    return pd.DataFrame(rows)


def plot(curve: pd.DataFrame, summary: pd.DataFrame, n_spec: int, path: Path) -> Path:
    fig, axes = pyplot().subplots(1, len(OBJECTIVES), figsize=(11, 4.2), layout="constrained")
    for ax, objective in zip(axes, OBJECTIVES, strict=True):
        c = curve[curve.objective == objective.label]
        for i, model in enumerate(CANDIDATES):
            m = c[c.model == model].groupby("n").r2_mean
            mean, lo, hi = m.mean(), m.min(), m.max()
            ax.plot(mean.index, mean.to_numpy(), "o-", color=f"C{i}", label=model)
            ax.fill_between(mean.index, lo.to_numpy(), hi.to_numpy(), color=f"C{i}", alpha=0.15)
        s = summary.set_index("objective").loc[objective.label]
        ax.axhline(R2_REQUIRED, color="k", ls="--", lw=0.8, label=f"required {R2_REQUIRED}")
        ax.axhline(
            s.r2_ceiling,
            color="C3",
            ls=":",
            lw=1.2,
            label=f"1 − σ²_track/var = {s.r2_ceiling:.2f} (if the track part were white)",
        )
        steps = [col for col in summary.columns if col.startswith("gamma_step_")]
        for col in steps:
            bound = 1 - s[col] / s.var_design
            ax.axhline(
                bound,
                color="C4",
                ls="-.",
                lw=1.0,
                label=f"1 − γ({col.removeprefix('gamma_step_')} box)/var = {bound:.3f}",
            )
        ax.axvline(n_spec, color="0.6", lw=0.8)
        ax.set(xlabel="training samples n (5-fold held-out)", ylabel="held-out R²",
               title=f"{objective.label} ({objective.scenario})", ylim=(0.3, 1.0))  # fmt: skip
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="lower right")
    fig.suptitle(f"Surrogate learning curve (loco {loco.__version__}; band: min–max over subsets)")
    return save_figure(fig, path)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--n-total", type=int, default=800)
    p.add_argument("--lhs-samples", type=int, default=200, help="the Monte Carlo's (SPEC 200)")
    p.add_argument("--sizes", type=int, nargs="+", default=[100, 200, 300, 400, 600, 800])
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--block", type=int, default=100, help="samples per block beyond the MC's")
    p.add_argument("--noise-points", type=int, default=24)
    p.add_argument("--noise-seeds", type=int, nargs="+", default=[1, 2, 3])
    p.add_argument("--steps", type=float, nargs="+", default=[0.02, 0.1])
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--threads", type=int, default=None)
    p.add_argument("--out", type=Path, default=Path("results/surrogate_learning_curve"))
    p.add_argument("--analyse", action="store_true", help="fits and figure from the CSV files")
    p.add_argument("--plot", action="store_true", help="figure from learning_curve.csv only")
    args = p.parse_args()
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    if args.plot:
        summary = noise_summary(pd.read_csv(out / "samples.csv"), pd.read_csv(out / "noise.csv"))
        curve = pd.read_csv(out / "learning_curve.csv")
        plot(curve, summary, args.lhs_samples, out / "surrogate_learning_curve.png")
        return
    if args.analyse:
        samples, noise = pd.read_csv(out / "samples.csv"), pd.read_csv(out / "noise.csv")
    else:
        samples, noise = simulate(args, out)
    summary = noise_summary(samples, noise)
    summary.to_csv(out / "noise_summary.csv", index=False)
    print(summary.to_string())
    sizes = [n for n in args.sizes if n <= len(samples)]
    curve = learning_curve(samples, sizes, args.repeats, args.seed)
    curve.to_csv(out / "learning_curve.csv", index=False)
    plot(curve, summary, args.lhs_samples, out / "surrogate_learning_curve.png")
    table = curve.groupby(["objective", "model", "n"]).r2_mean.mean().unstack("n")
    print(table.round(3).to_string())
    (out / "surrogate_learning_curve.json").write_text(json.dumps({
        "loco_version": loco.__version__, "args": {k: str(v) for k, v in vars(args).items()},
        "noise": summary.to_dict(orient="records"),
        "r2_mean": {f"{o} {m}": row.to_dict() for (o, m), row in table.iterrows()},
    }, indent=2, default=float) + "\n")  # fmt: skip


if __name__ == "__main__":
    main()
