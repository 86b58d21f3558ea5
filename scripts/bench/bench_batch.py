"""Batch throughput: simulations per second on 1 and 2 threads, and Python against the binary.

Runs the same batch (default 8 samples of the six study parameters, S_high, 200 km/h, 500 m)
through ``loco.run_batch`` on 1 and 2 threads and through the ``loco-batch`` binary on 2 threads,
``--repeat`` times each, and prints the best wall-clock time of each with the derived figures
(speed-up from 1 to 2 threads, Python overhead against the binary). Run it on a quiet machine;
``--record`` writes the benchmark record the Performance page is generated from:

    python scripts/bench/bench_batch.py --samples 16 --repeat 3 --record
"""

from __future__ import annotations

import argparse
import subprocess
import tempfile
import time
from pathlib import Path

import bench_record

import loco
from loco.studies.parameters import names
from loco.studies.sampling import latin_hypercube

ROOT = Path(__file__).resolve().parents[2]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=8)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--distance", type=float, default=500.0, help="m")
    parser.add_argument("--binary", type=Path, default=ROOT / "target/release/loco-batch")
    parser.add_argument(
        "--integrator",
        choices=loco.simulation.INTEGRATORS,
        default=loco.Scenario.integrator,
        help="time scheme (default: the study's)",
    )
    parser.add_argument("--record", action="store_true", help="write the benchmark record")
    args = parser.parse_args()
    step = loco.simulation.INTEGRATOR_STEPS[args.integrator]

    columns = names()
    params = latin_hypercube(args.samples, seed=1)
    scenario = loco.Scenario(
        name="S_high",
        speed=200 / 3.6,
        distance=args.distance,
        seed=1,
        integrator=args.integrator,
        step=step,
    )

    def python_run(threads: int) -> float:
        start = time.perf_counter()
        result = loco.run_batch(params, columns, scenario=scenario, threads=threads, progress=False)
        elapsed = time.perf_counter() - start
        assert result.n_failed == 0, result.failures()
        return elapsed

    with tempfile.TemporaryDirectory() as tmp:
        study = Path(tmp) / "study.toml"
        study.write_text(
            f'[scenario]\nname = "S_high"\nspeed = {200 / 3.6!r}\ndistance = {args.distance!r}\n'
            f'seed = 1\nintegrator = "{args.integrator}"\nstep = {step!r}\n',
            encoding="utf-8",
        )
        samples = Path(tmp) / "samples.csv"
        rows = [",".join(columns)] + [",".join(repr(float(v)) for v in r) for r in params]
        samples.write_text("\n".join(rows) + "\n", encoding="utf-8")

        def binary_run() -> float:
            start = time.perf_counter()
            out = str(Path(tmp) / "m.csv")
            command = [str(args.binary), str(study), str(samples), "-o", out]
            subprocess.run([*command, "--threads", "2", "--quiet"], check=True)
            return time.perf_counter() - start

        best = {
            "python, 1 thread": min(python_run(1) for _ in range(args.repeat)),
            "python, 2 threads": min(python_run(2) for _ in range(args.repeat)),
            "binary, 2 threads": min(binary_run() for _ in range(args.repeat)),
        }
    n = args.samples
    for label, seconds in best.items():
        print(f"{label:20s} {seconds:7.2f} s  {n / seconds:6.2f} runs/s  {seconds / n:.3f} s/run")
    speedup = best["python, 1 thread"] / best["python, 2 threads"]
    overhead = best["python, 2 threads"] / best["binary, 2 threads"] - 1.0
    print(f"speed-up 1 -> 2 threads: {speedup:.2f}x (target >= 1.8x)")
    print(f"Python overhead against the binary: {100 * overhead:+.1f} % (target < 3 %)")
    if args.record:
        bench_record.write(
            "bench_batch",
            {
                "samples": {"value": n, "unit": ""},
                "python_1_thread": bench_record.figure(best["python, 1 thread"], "s"),
                "python_2_threads": bench_record.figure(best["python, 2 threads"], "s"),
                "binary_2_threads": bench_record.figure(best["binary, 2 threads"], "s"),
                "speedup": bench_record.figure(speedup, "×"),
                "python_overhead": bench_record.figure(100 * overhead, "%", 2),
            },
        )


if __name__ == "__main__":
    main()
