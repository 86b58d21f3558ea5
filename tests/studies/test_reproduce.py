"""``loco reproduce`` end to end on the hidden tiny preset (a few 300 m runs per stage, the real
simulator): every stage's files, the report, and a rerun that skips finished stages."""

from __future__ import annotations

import contextlib
import dataclasses
import functools
import io
import json
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest

import loco
from loco import dampers
from loco.cli import build_parser, main
from loco.commands import reproduce as reproduce_command
from loco.store import find_campaigns
from loco.studies import fsd_comparison, fsd_design
from loco.studies.parameters import names
from loco.studies.reproduce import reproduce, stages
from loco.studies.sizes import FULL, QUICK, TINY
from loco.studies.stages import MARKER, DataFile, encode
from loco.studies.surrogate_selection import CANDIDATES
from loco.studies.verdict import verdict_from_csv

STAGES = {
    "speed_sweep": ["speed_sweep.png", "speed_sweep_psd.png", "speed_sweep_peaks.png",
                    "speed_sweep.csv", "speed_sweep_summary.csv", "speed_sweep_peaks.csv"],
    "monte_carlo": ["monte_carlo.png", "monte_carlo.csv", "monte_carlo_summary.csv"],
    "surrogate_samples": ["surrogate_samples.csv", "surrogate_samples.json"],
    "surrogate_holdout": ["holdout_samples.csv", "holdout_samples.json"],
    "surrogate": ["parity_W_y.png", "parity_A_yb.png", "parity_W_y_used.png",
                  "parity_A_yb_used.png", "surrogate_r2.csv", "surrogate_selection.csv",
                  "surrogate_spec.csv"],
    "sensitivity": ["sobol_W_y.png", "sobol_A_yb.png", "sobol_convergence.png",
                    "sobol_indices.csv", "sobol_summary.csv", "saltelli_samples.csv"],
    "optimisation": ["pareto.png", "pareto_verification.png", "pareto_front.csv",
                     "pareto_verification.csv"],
    "damper_bench": ["damper_bench.png", "damper_bench_summary.csv"],
    "fsd_comparison": ["fsd_time_histories.png", "fsd_psd.png", "fsd_peaks.png",
                       "fsd_valve.png", "fsd_summary.csv", "fsd_rankings.csv", "fsd_tracks.csv"],
    "fsd_design": ["fsd_design.png", "fsd_design_population.csv", "fsd_design_front.csv",
                   "fsd_design_conicity.csv", "fsd_design_conicity_summary.csv",
                   "fsd_design_critical_speeds.csv", "fsd_design.json"],
    "premise_map": ["premise_map.png", "premise_map.csv", "premise_speed.csv",
                    "premise_cells.csv"],
    "screening": ["morris.png", "morris.csv", "morris_outputs.csv"],
    "plausible": ["plausible.png", "plausible.csv", "plausible_fraction.csv",
                  "plausible_fsd.csv", "plausible.json"],
    "premise_case": ["premise_case_candidates.csv", "fsd_summary.csv", "fsd_tracks.csv",
                     "fsd_psd.png"],
    "curving": ["curving.png", "curving.csv", "curving.json"],
}  # fmt: skip
ARGS = ["reproduce", "--tiny", "--threads", "2", "--no-progress"]


@pytest.fixture(scope="module")
def run(tiny_study: tuple[Path, str]) -> tuple[Path, str]:
    """The tiny study (``tiny_study`` of conftest.py, run once per session)."""
    return tiny_study


def test_every_stage_written(run: tuple[Path, str]) -> None:
    out, log = run
    for stage, files in STAGES.items():
        assert (out / stage / MARKER).is_file(), stage
        for name in files:
            path = out / stage / name
            assert path.is_file() and path.stat().st_size > 0, path
        assert f"[{stage}] done" in log
    assert f"report: {(out / 'report.md').resolve()}" in log


def test_report(run: tuple[Path, str]) -> None:
    out, _ = run
    text = (out / "report.md").read_text()
    assert f"loco {loco.__version__}" in text
    assert f"loco reproduce --tiny --out {out} --seed 0" in text
    # The settings read plainly: scalars as they are, a dict as its key: value pairs.
    assert "lhs_samples: 16;" in text and "- seed (track, designs, K-means, NSGA-II): 0\n" in text
    assert text.count("Run time: ") == len(STAGES)
    links = re.findall(r"\]\(([^)]+)\)", text)
    figures = [link for link in links if link.endswith(".png")]
    assert len(figures) >= sum(n.endswith(".png") for f in STAGES.values() for n in f)
    for link in links:
        assert (out / link).is_file(), link
    # The first section asks whether the premise holds (the default vehicle, the premise case),
    # the second is the verdict, computed from the damper comparison's tracks.
    sections = [line for line in text.splitlines() if line.startswith("## ")]
    assert sections[0] == "## Does the premise hold?"
    assert "**The premise case: S_low on jm3-new on cn60 1:20**" in text
    # ... and gives the map, the probability over plausible locomotives and the screening, from
    # this run's stages.
    fraction = pd.read_csv(out / "plausible" / "plausible_fraction.csv")
    pooled = fraction[(fraction["pair"] == "all pairs") & (fraction["rule"] == "premise")]
    k, n = int(pooled["k"].iloc[0]), int(pooled["n"].iloc[0])
    assert n == 4 and f"The premise holds on {k} of {n} plausible locomotives" in text
    assert "**The premise map** (linearised, 200 km/h): Premise" in text
    assert "Which estimates the modes hang on (Morris screening, largest μ*): " in text
    assert "not part of this run" not in text
    assert sections[1].startswith("## Verdict: which yaw damper holds which scenario")
    computed = verdict_from_csv(out / "fsd_comparison" / "fsd_tracks.csv").markdown()
    assert "\n".join(computed).strip() in text
    assert "**S_low**, judged by `wy_max`" in text and "**S_high**, judged by `ayb_peak_lp`" in text
    # The damper comparison says whether each ranking is significant; the surrogate section
    # which surrogate the optimisation used, and still the SPEC network's R².
    rankings = re.findall(r"ranking (not |partly )?significant at 0.05 over 2 tracks", text)
    # 4 in the comparison's section (2 scenarios x PSD peak and judging metric) and the 2 of the
    # judging metrics again in the verdict; as many in the premise case's section, and its
    # S_low rankings (PSD peak, W_y) in the premise section.
    assert len(rankings) == 4 + 2 + 4 + 2
    assert "Surrogate used by the surrogate Sobol' indices and NSGA-II: W_y: **" in text
    assert "SPEC network (10 Gaussian units) mean held-out R²: W_y " in text
    meta = json.loads((out / "reproduce.json").read_text())
    assert meta["loco_version"] == loco.__version__ and meta["sizes"]["name"] == "tiny"


def test_stage_contents(run: tuple[Path, str]) -> None:
    out, _ = run
    mc = pd.read_csv(out / "monte_carlo" / "monte_carlo.csv")
    assert len(mc) == TINY.lhs_samples and set(names()) <= set(mc.columns)
    assert mc[["W_y", "A_yb"]].notna().all().all()
    extra = pd.read_csv(out / "surrogate_samples" / "surrogate_samples.csv")
    assert len(extra) == TINY.surrogate_samples - TINY.lhs_samples
    assert list(extra.columns) == list(mc.columns)
    assert extra[["W_y", "A_yb"]].notna().all().all()
    # The extension is a second design, not a copy of the Monte Carlo's points.
    assert not np.isin(extra[names()[0]], mc[names()[0]]).any()
    r2 = pd.read_csv(out / "surrogate" / "surrogate_r2.csv")
    assert len(r2) == 2 * len(CANDIDATES) * TINY.kfold and (r2["r2"] <= 1.0).all()
    # The SPEC network is also scored on the Monte Carlo's samples alone (SPEC §6.3's R²).
    spec = pd.read_csv(out / "surrogate" / "surrogate_spec.csv")
    assert len(spec) == 2 * TINY.kfold and (spec["samples"] == TINY.lhs_samples).all()
    meta = json.loads((out / "surrogate" / "surrogate.json").read_text())
    assert meta["training_samples"] == TINY.surrogate_samples
    assert meta["spec_samples"] == TINY.lhs_samples
    chosen = pd.read_csv(out / "surrogate" / "surrogate_selection.csv")
    assert (
        len(chosen) == 2 * len(CANDIDATES) and chosen.groupby("objective")["used"].sum().eq(1).all()
    )
    for _, group in chosen.groupby("objective"):
        assert group.loc[group["used"], "r2_mean"].iloc[0] == group["r2_mean"].max()
    # Fresh samples, disjoint from the training ones, score every candidate.
    fresh = pd.read_csv(out / "surrogate_holdout" / "holdout_samples.csv")
    assert len(fresh) == TINY.holdout_samples and list(fresh.columns) == list(mc.columns)
    train = pd.concat([mc, extra])[names()].to_numpy()
    assert not (fresh[names()].to_numpy()[:, None, :] == train[None, :, :]).all(axis=2).any()
    assert chosen["holdout_r2"].notna().all() and (chosen["holdout_r2"] <= 1.0).all()
    assert meta["holdout_samples"] == TINY.holdout_samples
    for label in ("W_y", "A_yb"):
        r2 = meta["r2"][label]
        assert r2["meets_r2_required"] == (r2["holdout_r2_used"] >= 0.9)
        assert len(r2["nested_choices"]) == TINY.kfold
    sweep = pd.read_csv(out / "speed_sweep" / "speed_sweep_summary.csv")
    assert (sweep["n_tracks"] == TINY.n_tracks).all()
    assert (sweep["W_y low"] <= sweep["W_y geomean"]).all() and (
        sweep["W_y geomean"] <= sweep["W_y high"]
    ).all()
    indices = pd.read_csv(out / "sensitivity" / "sobol_indices.csv")
    assert set(indices["method"]) == {"direct", "surrogate"}
    assert len(indices) == 2 * 2 * 2 * len(names())  # method x metric x order x parameter
    surrogate_st = indices[(indices["method"] == "surrogate") & (indices["index"] == "ST")]
    assert surrogate_st["value"].between(0.0, 1.5).all()  # Jansen's ST estimator is >= 0
    saltelli = pd.read_csv(out / "sensitivity" / "saltelli_samples.csv")
    assert len(saltelli) == max(TINY.convergence_bases) * (len(names()) + 2)
    front = pd.read_csv(out / "optimisation" / "pareto_front.csv")
    assert 1 <= len(front) <= TINY.pop_size
    assert np.all(np.diff(front["W_y"]) >= 0) and np.all(np.diff(front["A_yb"]) <= 0)
    check = pd.read_csv(out / "optimisation" / "pareto_verification.csv")
    assert 1 <= len(check) <= TINY.n_verify
    assert np.isfinite(check[["W_y_simulated", "A_yb_simulated"]].to_numpy()).all()
    summary = pd.read_csv(out / "fsd_comparison" / "fsd_summary.csv")
    assert len(summary) == 8 and (summary["n_tracks"] == TINY.n_tracks).all()  # 4 dampers x 2
    openings = pd.read_csv(out / "fsd_comparison" / "fsd_valve_open_fraction.csv")
    assert set(openings["damper"]) == {"FSD", "FSD-H"}
    assert openings["open_fraction"].between(0.0, 1.0).all()
    tests = pd.read_csv(out / "fsd_comparison" / "fsd_rankings.csv")
    pairs = len(fsd_comparison.DAMPERS) * (len(fsd_comparison.DAMPERS) - 1) // 2
    assert len(tests) == 4 * pairs  # (scenario, metric) x damper pairs
    design = fsd_design.SIZES["tiny"]
    population = pd.read_csv(out / "fsd_design" / "fsd_design_population.csv")
    assert len(population) == design.pop_size * design.n_gen
    front = pd.read_csv(out / "fsd_design" / "fsd_design_front.csv")
    assert front["feasible"].all() and (front["v_crit_kmh"] >= 1.1 * TINY.speed_kmh).all()
    sweep = pd.read_csv(out / "fsd_design" / "fsd_design_conicity.csv")
    assert set(sweep["conicity"]) == set(design.conicities)
    assert np.allclose(sweep["measured_conicity"], sweep["conicity"], atol=1e-3)
    assert {"YD1", "YD2", "FSD"} <= set(sweep["damper"]) and (sweep["status"] == 0).all()
    critical = pd.read_csv(out / "fsd_design" / "fsd_design_critical_speeds.csv")
    assert set(critical["damper"]) == set(sweep["damper"])


@pytest.mark.slow
def test_stages_request_what_they_demand(run: tuple[Path, str]) -> None:
    """The simulations each stage of the tiny run stored (its campaign stores) are those its
    ``demand()`` counts, so ``Sizes.runs()`` and the ``--quick``/``--full`` help count every
    stage, ``fsd_design`` and ``curving`` included. Two demands are upper bounds: NSGA-II's
    Pareto picks re-simulated (the front may have fewer points) and the FSD design stage's
    picked designs (picks that coincide run once)."""
    out, _ = run
    planned = stages(TINY, out, seed=0)
    assert [s.name for s in planned] == list(STAGES)
    stored = {s.name: sum(c.n_samples for c in find_campaigns(out / s.name)) for s in planned}
    demanded = {s.name: s.demand().simulations for s in planned}
    bounds = {"optimisation", "fsd_design"}
    assert {k: v for k, v in stored.items() if k not in bounds} == {
        k: v for k, v in demanded.items() if k not in bounds
    }
    verified = len(pd.read_csv(out / "optimisation" / "pareto_verification.csv"))
    assert stored["optimisation"] == 2 * verified <= demanded["optimisation"]
    population = pd.read_csv(out / "fsd_design" / "fsd_design_population.csv")
    sweep = pd.read_csv(out / "fsd_design" / "fsd_design_conicity.csv")
    ran = 2 * int(population["error"].isna().sum()) + len(sweep)
    assert stored["fsd_design"] == ran <= demanded["fsd_design"]
    assert stored["curving"] > 0 and stored["fsd_design"] > 0
    assert sum(demanded.values()) == TINY.demand().simulations
    # The help text gives the preset's count.
    help_text = io.StringIO()
    with contextlib.redirect_stdout(help_text), pytest.raises(SystemExit):
        main(["reproduce", "--help"])
    text = " ".join(help_text.getvalue().split())
    assert f"~{QUICK.runs()} runs" in text and f"~{FULL.runs()} runs" in text


@pytest.mark.slow
def test_rerun_skips_finished_stages(
    run: tuple[Path, str], capsys: pytest.CaptureFixture[str]
) -> None:
    out, first = run
    # The first run (with --no-progress) printed where each stage's samples came from.
    assert "[monte_carlo] samples: 0 from the store, " in first
    markers = {s: (out / s / MARKER).stat().st_mtime_ns for s in STAGES}
    assert main([*ARGS, "--out", str(out)]) == 0
    log = capsys.readouterr().out
    assert log.count("finished earlier") == len(STAGES) and "running" not in log
    assert {s: (out / s / MARKER).stat().st_mtime_ns for s in STAGES} == markers
    # A changed size reruns the stages that depend on it, and only those.
    lines: list[str] = []
    fewer = dataclasses.replace(TINY, n_verify=2)
    reproduce(fewer, out, threads=2, progress=False, log=lines.append)
    ran = [line for line in lines if line.endswith("running")]
    assert ran == ["[optimisation] running"]
    assert len(pd.read_csv(out / "optimisation" / "pareto_verification.csv")) <= 2


@pytest.mark.slow
def test_damaged_monte_carlo_table_is_rebuilt_from_the_store(run: tuple[Path, str]) -> None:
    """A truncated ``monte_carlo.csv`` (the file still exists) is not trusted; the stage
    runs again and takes every sample from its store (no simulation), so the stages that read
    the table see the same content hash and stay finished."""
    out, _ = run
    fewer = dataclasses.replace(TINY, n_verify=2)
    # The output at these sizes first (the test before leaves it so; run alone, this brings it
    # there), so that what runs below is the damaged stage's doing only.
    reproduce(fewer, out, threads=2, progress=False, log=lambda _: None)
    table = out / "monte_carlo" / "monte_carlo.csv"
    whole = table.read_bytes()
    parts = sorted((out / "monte_carlo" / "store").rglob("part-*.parquet"))
    assert parts, "the Monte Carlo samples are kept in the stage's store"
    table.write_bytes(whole[: len(whole) // 2])
    lines: list[str] = []
    reproduce(fewer, out, threads=2, progress=False, log=lines.append)
    assert "[monte_carlo] output monte_carlo/monte_carlo.csv is changed or truncated since the " \
        "stage finished: running again" in lines  # fmt: skip
    assert [line for line in lines if line.endswith("running")] == ["[monte_carlo] running"]
    # Without progress bars the stage still says where its samples came from: all the store.
    (count,) = [line for line in lines if line.startswith("[monte_carlo] samples: ")]
    reused = int(count.split()[2])
    assert reused > 0 and count == f"[monte_carlo] samples: {reused} from the store, 0 run"
    assert table.read_bytes() == whole
    assert sorted((out / "monte_carlo" / "store").rglob("part-*.parquet")) == parts


@functools.cache
def _other_vehicles() -> tuple[loco.Locomotive, loco.Locomotive]:
    """A vehicle from another file (the embedded one's text plus a comment) and the embedded
    one with an override."""
    text = loco.Locomotive.default().default_toml() + "\n#\n"
    return loco.Locomotive(toml_text=text), loco.Locomotive.default().replace(C_sx=1.5e5)


def _variants(value: Any, files: list[DataFile]) -> list[Any]:
    """Values of a stage input that differ from ``value`` (a nested dataclass: each of its
    fields changed in turn); an input type this does not know fails the test."""
    if dataclasses.is_dataclass(value) and not isinstance(value, (type, loco.Locomotive)):
        if isinstance(value, DataFile):
            return [f for f in files if f.path.read_bytes() != value.path.read_bytes()][:1]
        return [
            dataclasses.replace(value, **{f.name: v})
            for f in dataclasses.fields(value)
            for v in _variants(getattr(value, f.name), files)
        ]
    if isinstance(value, bool):
        return [not value]
    if isinstance(value, (int, float)):
        return [value + 1, value * 2 + 0.5]
    if isinstance(value, str):
        return [value + "x"]
    if value is None or isinstance(value, loco.Locomotive):
        return [v for v in (*_other_vehicles(), dampers.YD1) if value is None or v != value]
    if isinstance(value, dampers.Damper):
        return [d for d in (dampers.YD1, dampers.YD2) if d.parameters() != value.parameters()]
    if isinstance(value, Mapping):
        items = list(value.items())
        reordered = [dict(items[::-1])] if len(items) > 1 else []
        return [dict(items[:-1]), *reordered, {**value, "YD1x": dampers.YD1}]
    if isinstance(value, (tuple, list)):
        changed = [(*value[:i], v, *value[i + 1 :]) for i in range(len(value))
                   for v in _variants(value[i], files)]  # fmt: skip
        return [*changed, tuple(value[:-1]), (*value, value[-1])]
    raise AssertionError(f"no variants for a stage input of type {type(value).__name__}")


@pytest.mark.slow
def test_every_stage_input_changes_its_hash(tmp_path: Path) -> None:
    """Each stage's hash changes with every one of its fields, nested fields included, and with
    nothing else: the speed sweep's damper was once left out of a hand-made settings list. A
    table is its content, not its path."""
    full = stages(FULL, tmp_path, seed=0)
    assert [s.name for s in full] == list(STAGES)
    files = []
    tables = ("monte_carlo/monte_carlo.csv", "surrogate_samples/surrogate_samples.csv",
              "surrogate_holdout/holdout_samples.csv", "b.csv")  # fmt: skip
    for i, table in enumerate(tables):
        (tmp_path / table).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / table).write_text(f"a\n{i}\n")
        files.append(DataFile(tmp_path / table))
    checked = 0
    for stage in full:
        reference = stage.stage_hash()
        assert dataclasses.replace(stage).stage_hash() == reference
        for field in dataclasses.fields(stage):
            variants = _variants(getattr(stage, field.name), files)
            assert variants, (stage.name, field.name)
            for v in variants:
                changed = dataclasses.replace(stage, **{field.name: v})
                assert changed.stage_hash() != reference, (stage.name, field.name, v)
                checked += 1
    assert checked > 100
    moved = tmp_path / "moved.csv"
    moved.write_bytes(files[0].path.read_bytes())
    assert encode(DataFile(moved)) == encode(files[0])


def _integrators(value: Any) -> list[str]:
    """Every ``integrator`` field in a stage input, nested dataclasses included."""
    if not dataclasses.is_dataclass(value) or isinstance(value, type):
        return []
    found = []
    for field in dataclasses.fields(value):
        v = getattr(value, field.name)
        found += [v] if field.name == "integrator" else _integrators(v)
    return found


@pytest.mark.slow
def test_the_integrator_reaches_every_stage_that_simulates(tmp_path: Path) -> None:
    """``--integrator rk4`` (the reference; the default is etdrk4) sets the scheme of every stage
    that runs the simulator (the surrogate, the damper bench, the premise map and the screening
    run none) and is part of each one's hash."""
    default = stages(FULL, tmp_path, seed=0)
    reference = stages(FULL, tmp_path, seed=0, integrator="rk4")
    simulating = set(STAGES) - {"surrogate", "damper_bench", "premise_map", "screening"}
    for d, r in zip(default, reference, strict=True):
        assert _integrators(d) == (["etdrk4"] if d.name in simulating else []), d.name
        assert _integrators(r) == (["rk4"] if r.name in simulating else []), r.name
        assert (d.stage_hash() != r.stage_hash()) == (d.name in simulating), d.name
    parsed = build_parser().parse_args(["reproduce", "--quick", "--integrator", "rk4"])
    assert parsed.integrator == "rk4"
    assert "--integrator rk4" in reproduce_command._command_line(parsed)
    assert "--integrator" not in reproduce_command._command_line(
        build_parser().parse_args(["reproduce", "--quick"])
    )
    with pytest.raises(SystemExit):
        build_parser().parse_args(["reproduce", "--integrator", "euler"])
