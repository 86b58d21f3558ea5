"""The Performance page's text and rows: what each benchmark measures and its target. Every
figure is read from a benchmark record by ``performance_docs.Records``; nothing here is a
measurement."""

from __future__ import annotations

from performance_figures import Records, Row, duration, number, table

INTRO = [
    "Criterion benches in `crates/loco-core/benches/` (`cargo bench -p loco-core --bench <name>`),",
    "the timing tools of `crates/loco-dev` and the benchmark scripts of `scripts/bench/`, release",
    "profile. Every figure below is read from the record its benchmark wrote",
    "(`docs/performance/records/`, with the command, the day, the machine and the version of the",
    "code); earlier figures, and how each speed step was measured, are in the [Performance",
    "history](performance_history.md). A machine's speed varies by 10–20 % between days, so a",
    "speed claim is a paired measurement (two builds alternated in one session), never a",
    "comparison with a figure of another day.",
]


#: The damper laws of the ``dampers`` bench.
_DAMPERS = ("maxwell_yd2", "fsd", "fsd_hydraulic", "hydraulic")


def _dampers(r: Records) -> str:
    return " / ".join(r.crit(f"damper_evaluate_{n}") for n in _DAMPERS)


def _run(r: Records) -> str:
    return (
        f"**{r.time('dev_tools', 'sim_time.S_high.min')}** S_high, "
        f"{r.time('dev_tools', 'sim_time.S_low.min')} S_low (thread CPU time, "
        f"`loco-dev` `sim_time`, minima); criterion "
        f"{r.crit('vehicle/run_500m_200kmh_etdrk4')}"
    )


def _curve(r: Records) -> str:
    study = r.ratio("dev_tools", "sim_time.S_high_study_curve.min", "sim_time.S_high.min")
    reference = r.ratio("dev_tools", "sim_time.S_high_curve.min", "sim_time.S_high.min")
    return (
        f"{number(study)}× the straight run in CPU time; the reference curve (290 mm deficiency, "
        f"flange contact) {number(reference)}×"
    )


def _creep_replay(r: Records) -> str:
    return (
        f"{r.value('dev_tools', 'creep_replay.S_high.ratio')} on S_high "
        f"({r.time('dev_tools', 'creep_replay.S_high.fastrip')} against "
        f"{r.time('dev_tools', 'creep_replay.S_high.fastsim')}), "
        f"{r.value('dev_tools', 'creep_replay.S_low.ratio')} on S_low"
    )


def _batch(r: Records) -> str:
    return (
        f"{r.value('bench_batch', 'speedup')} on 2 threads; Python's overhead "
        f"{r.value('bench_batch', 'python_overhead', 2)}"
    )


def _study(r: Records) -> str:
    quick = r.time("study_quick", "wall")
    if "study_full" not in r.records:
        return (
            f"{quick} (`--full`: not recorded on this machine; the last figure is in the history)"
        )
    return f"{quick} / {r.time('study_full', 'wall')}"


ROWS = [
    Row(
        "`dampers` `damper_evaluate_maxwell_yd2` / `_fsd` / `_fsd_hydraulic` / `_hydraulic`",
        "one damper force and state derivatives",
        _dampers,
        "< 50 ns",
        lambda r: max(r.seconds("criterion", f"damper_evaluate_{n}") for n in _DAMPERS) < 50e-9,
    ),
    Row(
        "`dampers` `damper_advance_fsd` / `_fsd_hydraulic`",
        "the FSD's valve update, once per accepted step (rms-frequency / hydraulic valve)",
        lambda r: f"{r.crit('damper_advance_fsd')} / {r.crit('damper_advance_fsd_hydraulic')}",
        "< 50 ns (hydraulic)",
        lambda r: r.seconds("criterion", "damper_advance_fsd_hydraulic") < 50e-9,
    ),
    Row(
        "`metrics` `run_metrics_9s_500Hz`",
        "every metric of one run on 9 s records at 500 Hz",
        lambda r: r.crit("run_metrics_9s_500Hz"),
        "< 1 ms",
        lambda r: r.seconds("criterion", "run_metrics_9s_500Hz") < 1e-3,
    ),
    Row(
        "`metrics` `track_at` / `track_synthesize_1km`",
        "one irregularity look-up / 1 km of the four irregularities",
        lambda r: f"{r.crit('track_at')} / {r.crit('track_synthesize_1km')}",
    ),
    Row(
        "`fastsim` `fastsim 10x10`",
        "one FASTSIM call (CONTACT's spin case); on a run's own contacts (`creep_replay`)",
        lambda r: (
            f"{r.crit('fastsim 10x10 Parabolic')}; on a run's own contacts "
            f"{r.time('dev_tools', 'creep_replay.S_high.fastsim')} (S_high) and "
            f"{r.time('dev_tools', 'creep_replay.S_low.fastsim')} (S_low)"
        ),
        "< 2 µs",
        lambda r: r.seconds("criterion", "fastsim 10x10 Parabolic") < 2e-6,
    ),
    Row(
        "`loco-dev` `creep_replay`",
        "FaStrip against FASTSIM on a run's own contacts, default grid",
        _creep_replay,
        "≤ 1.5×",
        lambda r: r.raw("dev_tools", "creep_replay.S_high.ratio") <= 1.5,
    ),
    Row(
        "`contact_table` build / lookup",
        "one wheel/rail pair (S1002/UIC60, ±15 mm by 0.1 mm, with the roll layers) / one look-up",
        lambda r: f"{r.crit('contact_table_build')} / {r.crit('contact_table_lookup')}",
        "< 100 ms / < 100 ns",
        lambda r: (
            r.seconds("criterion", "contact_table_build") < 0.1
            and r.seconds("criterion", "contact_table_lookup") < 100e-9
        ),
    ),
    Row(
        "`conicity`",
        "EN 15302 nonlinear method, one amplitude / 66 amplitudes",
        lambda r: (
            f"{r.crit('conicity nonlinear, 3 mm')} / {r.crit('conicity nonlinear, 66 amplitudes')}"
        ),
    ),
    Row(
        "`eigen` `S_high_linear_critical_speed`",
        "the linear critical speed: statics, linearisation and eigenvalues over speed",
        lambda r: r.crit("eigen/S_high_linear_critical_speed"),
    ),
    Row(
        "`vehicle` `run_500m_200kmh_etdrk4`",
        "one 500 m run at 200 km/h of the 90-DOF model with the default scheme (ETDRK4 at 2 ms, "
        "FASTSIM 10×10, metrics), one core",
        _run,
        "≤ 150 ms",
        lambda r: r.seconds("dev_tools", "sim_time.S_high.min") <= 0.15,
    ),
    Row(
        "`vehicle` `run_500m_200kmh_table_etdrk4`",
        'the same with `creep = "table"`',
        lambda r: (
            f"{r.crit('vehicle/run_500m_200kmh_table_etdrk4')}; "
            f"{r.time('dev_tools', 'sim_time.S_high_table.min')} CPU time (`sim_time`)"
        ),
        "≤ 100 ms",
        lambda r: r.seconds("criterion", "vehicle/run_500m_200kmh_table_etdrk4") <= 0.1,
    ),
    Row(
        "`vehicle` `run_500m_200kmh`",
        "the reference settings: RK4 at 1 ms",
        lambda r: r.crit("vehicle/run_500m_200kmh"),
        "< 0.5 s",
        lambda r: r.seconds("criterion", "vehicle/run_500m_200kmh") < 0.5,
    ),
    Row(
        "`vehicle` `run_500m_200kmh_study_curve_etdrk4`",
        "the default run on the curving study's curve (R = 3000 m, 60 mm cant)",
        _curve,
        "≤ 1.10× on the study curve",
        lambda r: (
            r.ratio("dev_tools", "sim_time.S_high_study_curve.min", "sim_time.S_high.min") <= 1.10
        ),
    ),
    Row(
        "right-hand side",
        "one evaluation of the equations of motion (a run's CPU time over its evaluations)",
        lambda r: (
            f"{r.value('dev_tools', 'sim_time.S_high.per_evaluation', 2)} "
            f"({number(r.raw('dev_tools', 'sim_time.S_high.evaluations'), 5)} evaluations); "
            f"criterion `vehicle_right_hand_side` {r.crit('vehicle_right_hand_side')}"
        ),
    ),
    Row(
        "`frequency_response` `one_case_100f_4in_10out`",
        "vehicle, contact table, equilibrium, linearisation with the track as input, "
        "100 frequencies × 4 inputs × 10 outputs",
        lambda r: r.crit("frequency_response/one_case_100f_4in_10out"),
        "< 200 ms",
        lambda r: r.seconds("criterion", "frequency_response/one_case_100f_4in_10out") < 0.2,
    ),
    Row(
        "`scripts/bench/bench_batch.py`",
        "`loco.run_batch` on 1 and 2 threads; the `loco-batch` binary against it",
        _batch,
        "≥ 1.8×; < 3 %",
        lambda r: (
            r.raw("bench_batch", "speedup") >= 1.8 and r.raw("bench_batch", "python_overhead") < 3.0
        ),
    ),
    Row(
        "`scripts/bench/bench_campaign.py`",
        "one batch against a local campaign in chunks with its store",
        lambda r: (
            f"campaign / batch {r.value('bench_campaign', 'ratio')} "
            f"({number(r.raw('bench_campaign', 'samples'))} samples)"
        ),
    ),
    Row(
        "`scripts/bench/bench_surrogate.py`",
        "the surrogate stage's selection (6 candidates, 5 folds, nested) on `--quick`'s samples, "
        "2 processes",
        lambda r: (
            f"{r.time('bench_surrogate', 'wall')} wall "
            f"({number(r.raw('bench_surrogate', 'samples'))} samples)"
        ),
    ),
    Row(
        "`scripts/verify/saltelli_direct.py`",
        "a direct Saltelli design with second-order rows on both objectives, runs of 500 m",
        lambda r: (
            f"**{r.time('saltelli_direct', 'wall')}** for "
            f"{number(r.raw('saltelli_direct', 'runs'), 5)} runs (N = "
            f"{number(r.raw('saltelli_direct', 'base'), 5)}, "
            f"{number(r.raw('saltelli_direct', 'threads'))} threads)"
        ),
        "< 1 h for N = 1024",
        lambda r: r.seconds("saltelli_direct", "wall") < 3600.0,
        optional="saltelli_direct",
    ),
    Row(
        "`loco damper-bench`",
        "the damper bench stage: sine benches, the valve's two-tone runs and opening band",
        lambda r: r.time("study_quick", "damper_bench"),
    ),
    Row(
        "`scripts/bench/bench_study.py`: `loco reproduce --quick` / `--full`",
        "the whole study, 2 threads",
        _study,
    ),
]

DASK_INTRO = [
    "Overhead of the Dask path (`scripts/bench/bench_dask.py`), S_high at 200 km/h,",
    "Latin-hypercube samples of the six study parameters. Local threads means one `run_batch` on",
    "2 rayon threads. Dask means a `LocalCluster` of 2 worker processes with 1 rayon thread each,",
    "on the same 2 cores and with the cluster already running. CPU time is summed over the client",
    "and the workers; on a shared machine it is the better guide, the wall time also measuring the",
    "other jobs' load. The metrics of every way are checked bit-identical to the plain batch's.",
]

_WAYS = ("local", "local+store", "dask", "dask+store")


def dask_section(r: Records) -> list[str]:
    """The four ways' times per sample count, and the projection to a cluster."""
    keys = r.records.get("bench_dask", {}).get("figures", {})
    counts = sorted({int(k.split(".")[0]) for k in keys if k.split(".")[0].isdigit()})
    if not counts:
        r.raw("bench_dask", "startup")  # names the missing record
    distance = number(r.raw("bench_dask", "distance"))
    rows = []
    for n in counts:
        cells = [f"{n} × {distance} m"]
        for way in _WAYS:
            wall, cpu = (
                r.time("bench_dask", f"{n}.{way}.wall"),
                r.time("bench_dask", f"{n}.{way}.cpu"),
            )
            if way == "local":
                per_run = number(r.raw("bench_dask", f"{n}.per_run"))
                cells.append(f"{wall} wall, {cpu} CPU ({per_run} core-s per run)")
            else:
                extra = r.raw("bench_dask", f"{n}.{way}.cpu_overhead")
                sign = "+" if extra >= 0 else ""
                cells.append(f"{wall}, {cpu} (CPU {sign}{number(extra, 2)} %)")
        rows.append(tuple(cells))
    largest = counts[-1]
    overhead = r.raw("bench_dask", f"{largest}.dask+store.cpu_overhead")
    per_run = r.raw("bench_dask", f"{largest}.per_run")
    cores = r.raw("bench_dask", "cluster_cores")
    chunk = r.raw("bench_dask", f"{largest}.chunk")
    runs = 2 * 1024 * (2 * 6 + 2)
    simulation = runs * per_run / cores
    tail = chunk * per_run
    startup = r.seconds("bench_dask", "startup")
    total = simulation * (1 + max(overhead, 0.0) / 100) + tail + startup
    return [
        *table(("samples × distance", *_WAYS), rows),
        "",
        f"The cluster's start-up took {duration(startup)}. At {largest} samples the Dask path",
        f"with the store costs {number(abs(overhead), 2)} % {'more' if overhead >= 0 else 'less'}",
        "CPU than local threads (target: under 10 % more).",
        "",
        "Projected from these figures, a Saltelli N = 1024 study (N·(2k + 2) = 14 336 runs per",
        f"scenario, two scenarios, {runs} runs) on a {number(cores)}-core cluster takes about",
        f"**{duration(total)}**: {runs} × {number(per_run)} core-s / {number(cores)} cores =",
        f"{duration(simulation)} of simulation, plus the {number(max(overhead, 0.0), 2)} % Dask",
        f"and store overhead, plus one chunk of tail (at most {number(chunk)} × {number(per_run)}",
        f"s = {duration(tail)}), plus the cluster's start-up. A cluster core of another speed",
        f"scales it; the per-run cost here is for {distance} m runs.",
    ]


HOW_TO = [
    "Each benchmark writes its record, then the page is regenerated:",
    "",
    "```bash",
    "cargo bench -p loco-core && python scripts/bench/record_criterion.py",
    "python scripts/bench/record_tools.py --record          # sim_time and creep_replay",
    "cargo build --release -p loco-batch",
    "python scripts/bench/bench_batch.py --samples 16 --record",
    "python scripts/bench/bench_campaign.py --samples 48 --chunk-size 8 --record",
    "python scripts/bench/bench_dask.py --samples 64 512 --distance 500 --record",
    "python scripts/bench/bench_study.py --preset quick --out /tmp/quick --record",
    "python scripts/bench/bench_surrogate.py --out /tmp/quick --record",
    "python scripts/verify/saltelli_direct.py --base 1024 --threads 2 --record",
    "python scripts/docs/performance_docs.py --write",
    "```",
    "",
    "Run them on a quiet machine: another job's load shows in every wall time.",
    "`cargo run --release -p loco-dev --bin sim_time -- fastsim S_high [straight|study_curve|",
    "curve] [repeats]` times one simulation's thread CPU time without the contact table's build;",
    "built from two versions and alternated, it gives a paired comparison. `run_fingerprint`",
    "prints a hash of every output sample, so a speed step can be checked bit for bit. The step",
    "convergence of the schemes is on the [Verification](verification.md) page.",
]
