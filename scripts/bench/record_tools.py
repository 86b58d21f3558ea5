"""The timing tools' record: one run's CPU time and FaStrip's cost against FASTSIM's.

Builds and runs two developer tools of ``crates/loco-dev`` in release and records what they print:

- ``sim_time``: the thread CPU time of one 500 m run at 200 km/h of the 90-DOF model without
  its set-up (the contact table and track built once), minimum and median of ``--repeats`` runs,
  for the default scheme on S_high and S_low, the tabulated creep model, the curving study's
  curve and the reference curve; with the number of evaluations of the equations of motion,
  the cost of one evaluation is the run's time over it;
- ``creep_replay``: FaStrip's and FASTSIM's time per call on a run's own contacts.

    python scripts/bench/record_tools.py --record
"""

from __future__ import annotations

import argparse
import re
import subprocess
from typing import Any

import bench_record

#: The ``sim_time`` cases: record key → the tool's arguments (creep, scenario, track).
SIM_TIME_CASES = {
    "S_high": ("fastsim", "S_high", "straight"),
    "S_low": ("fastsim", "S_low", "straight"),
    "S_high_table": ("table", "S_high", "straight"),
    "S_high_study_curve": ("fastsim", "S_high", "study_curve"),
    "S_high_curve": ("fastsim", "S_high", "curve"),
}

SIM_TIME = re.compile(
    r"min (?P<min>[\d.]+) ms, median (?P<median>[\d.]+) ms; (?P<evals>\d+) right-hand side"
)
CREEP_REPLAY = re.compile(
    r"(?P<calls>\d+) contact calls; FASTSIM (?P<sim>[\d.]+) ns, FaStrip (?P<rip>[\d.]+) ns "
    r"per call, ratio (?P<ratio>[\d.]+)"
)


def run_tool(name: str, arguments: list[str], features: list[str] | None = None) -> str:
    """The standard output of ``cargo run --release -p loco-dev --bin name -- arguments``."""
    command = ["cargo", "run", "--quiet", "--release", "-p", "loco-dev", "--bin", name]
    if features:
        command += ["--features", ",".join(features)]
    output = subprocess.run(
        [*command, "--", *arguments], cwd=bench_record.ROOT, capture_output=True, text=True,
        check=True,
    ).stdout  # fmt: skip
    print(output.strip())
    return output


def sim_time(repeats: int) -> dict[str, dict[str, Any]]:
    """Every :data:`SIM_TIME_CASES` case's minimum and median CPU time, ms, and evaluations."""
    figures: dict[str, dict[str, Any]] = {}
    for key, (creep, scenario, track) in SIM_TIME_CASES.items():
        match = SIM_TIME.search(run_tool("sim_time", [creep, scenario, track, str(repeats)]))
        if match is None:
            raise RuntimeError(f"sim_time {key}: output not understood")
        minimum = float(match["min"])
        figures[f"sim_time.{key}.min"] = bench_record.figure(minimum, "ms")
        figures[f"sim_time.{key}.median"] = bench_record.figure(float(match["median"]), "ms")
        figures[f"sim_time.{key}.evaluations"] = {"value": int(match["evals"]), "unit": ""}
        per_evaluation = minimum * 1e3 / int(match["evals"])
        figures[f"sim_time.{key}.per_evaluation"] = bench_record.figure(per_evaluation, "µs", 2)
    return figures


def creep_replay(rounds: int) -> dict[str, dict[str, Any]]:
    """FaStrip's and FASTSIM's time per call on S_high's and S_low's contacts, and the ratio."""
    figures: dict[str, dict[str, Any]] = {}
    for scenario in ("S_high", "S_low"):
        output = run_tool("creep_replay", [scenario, str(rounds)], ["record-contacts"])
        match = CREEP_REPLAY.search(output)
        if match is None:
            raise RuntimeError(f"creep_replay {scenario}: output not understood")
        figures[f"creep_replay.{scenario}.calls"] = {"value": int(match["calls"]), "unit": ""}
        figures[f"creep_replay.{scenario}.fastsim"] = bench_record.figure(float(match["sim"]), "ns")
        figures[f"creep_replay.{scenario}.fastrip"] = bench_record.figure(float(match["rip"]), "ns")
        figures[f"creep_replay.{scenario}.ratio"] = bench_record.figure(float(match["ratio"]), "×")
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="sim_time runs per case")
    parser.add_argument("--rounds", type=int, default=15, help="creep_replay rounds")
    parser.add_argument("--record", action="store_true", help="write the benchmark record")
    args = parser.parse_args()
    figures = {**sim_time(args.repeats), **creep_replay(args.rounds)}
    if args.record:
        bench_record.write("dev_tools", figures)


if __name__ == "__main__":
    main()
