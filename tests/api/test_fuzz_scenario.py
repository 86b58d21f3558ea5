"""Fuzz of every scenario field: NaN, ±inf, 0, negative, 1e±30, fractional and wrong types.

Each value of each field of :class:`loco.Scenario` must give either a :class:`loco.LocoError`
naming the field, or a run that finishes (finite time, its metrics finite or NaN for a record too
short to judge): never an abort, a panic, a hang, a raw ``TypeError``/``OverflowError`` or a
silent no-op (a run that records nothing). The cases run in one child process under a memory
and CPU-time limit (one case after the other, each under its own alarm); the cases that once
aborted or hung run in a child process each. The runs are short (20 m at 200 km/h, 0.4 s of
simulated time), so the suite costs seconds.
"""

from __future__ import annotations

import json
import math
import os
import resource
import subprocess
import sys
from typing import Any

import pytest

#: Address-space limit of the child processes, bytes: an allocation that once aborted the process
#: (5 GB for one creep grid) fails inside it, and loco must refuse the value before.
MEMORY_LIMIT = 3 * 2**30
#: CPU seconds of the whole child, and wall seconds of one case.
CPU_LIMIT = 300
CASE_SECONDS = 60

NUMBERS: list[Any] = [
    math.nan,
    math.inf,
    -math.inf,
    0.0,
    -1.0,
    1e30,
    1e-30,
    -1e30,
    0.5,
    2.5,
]
WRONG_TYPES: list[Any] = ["200", None, True, 1 + 2j, [1.0], {"a": 1}]
#: Every field of loco.Scenario a fuzz value goes into (a pair field gets it in either place),
#: and the field name its errors must name.
REAL_FIELDS = [
    "speed",
    "distance",
    "step",
    "output_rate",
    "initial_lateral_offset",
    "lead_in",
    "gauge",
    "gauge_height",
    "rail_inclination",
]
WHOLE_FIELDS = ["seed"]
PAIR_FIELDS = {"band": (2.0, 200.0), "fastsim_grid": (10, 10)}
TEXT_FIELDS = ["spectrum", "creep", "name", "wheel", "rail", "fsd_trigger"]
FLAG_FIELDS: list[str] = []
OBJECT_FIELDS = ["track", "yaw_damper", "curve"]
#: A valid curve section; each of its fields gets every fuzz value in turn (`curve[i].field`).
CURVE_SECTION: dict[str, Any] = {
    "kind": "curve",
    "length_m": 50.0,
    "radius_m": 2000.0,
    "cant_mm": 50.0,
    "direction": "left",
}

#: The base run: short, every field else at its default.
BASE: dict[str, Any] = {"name": "S_norm", "speed": 200 / 3.6, "distance": 20.0}


def cases() -> list[tuple[str, str, Any]]:
    """(label, field, value) of every case; pairs as (field, index)."""
    out: list[tuple[str, str, Any]] = []
    for field in [*REAL_FIELDS, *WHOLE_FIELDS]:
        out += [(f"{field}={v!r}", field, v) for v in [*NUMBERS, *WRONG_TYPES]]
    for field, default in PAIR_FIELDS.items():
        for i in range(2):
            for v in [*NUMBERS, *WRONG_TYPES]:
                pair = list(default)
                pair[i] = v
                out.append((f"{field}[{i}]={v!r}", field, tuple(pair)))
        out += [(f"{field}={v!r}", field, v) for v in ["x", 3.0, (1.0, 2.0, 3.0), None]]
    for field in TEXT_FIELDS:
        out += [(f"{field}={v!r}", field, v) for v in ["", "nonsense", 3.0, None, True]]
    for field in FLAG_FIELDS:
        out += [(f"{field}={v!r}", field, v) for v in [1, 0.0, "yes", None]]
    for field in OBJECT_FIELDS:
        out += [(f"{field}={v!r}", field, v) for v in [3.0, "nonsense-object", [1, 2]]]
    for key in [*CURVE_SECTION, "cant_run_off_m"]:
        for v in [*NUMBERS, *WRONG_TYPES, "", "nonsense"]:
            out.append((f"curve[0].{key}={v!r}", "curve", [{**CURVE_SECTION, key: v}]))
    out += [(f"curve={v!r}", "curve", v) for v in [[], [{}], {"kind": "curve"}, None]]
    return out


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_LIMIT, CPU_LIMIT))


def run_case(field: str, value: Any) -> dict[str, Any]:
    """One case in this process: what happened, as a JSON-ready dict."""
    import signal

    import numpy as np

    import loco

    def timeout(signum: int, frame: object) -> None:
        raise TimeoutError(f"no answer in {CASE_SECONDS} s")

    signal.signal(signal.SIGALRM, timeout)
    signal.alarm(CASE_SECONDS)
    settings = {**BASE, field: value}
    if field in ("wheel", "rail"):
        # A profile by name, without the scenario's pair of them.
        settings = {"wheel": "jm3-new", field: value, "speed": BASE["speed"],
                    "distance": BASE["distance"]}  # fmt: skip
    try:
        result = loco.simulate(loco.Locomotive.default(), loco.Scenario(**settings))
    except loco.LocoError as e:
        return {"outcome": "error", "type": type(e).__name__, "message": str(e)}
    except TimeoutError as e:
        return {"outcome": "hang", "message": str(e)}
    except BaseException as e:
        return {"outcome": "raw", "type": type(e).__name__, "message": str(e)}
    finally:
        signal.alarm(0)
    values = np.array(list(result.metrics.values()), dtype=float)
    return {
        "outcome": "run",
        "samples": len(result.time),
        "finite_channels": bool(np.isfinite(result.channels).all()),
        "metrics_nan": int(np.isnan(values).sum()),
        "metrics_inf": int(np.isinf(values).sum()),
    }


def _judge(label: str, field: str, answer: dict[str, Any]) -> str | None:
    """What is wrong with an answer (None: fine)."""
    if answer["outcome"] == "error":
        # The field by its Python name, never the core's spelling of it (a curve section's
        # field as `curve section 1 (radius_m)`).
        message = answer["message"]
        named = f"`{field}`" in message or f"`{field} section " in message
        return None if named else f"{label}: error does not name `{field}`: {message}"
    if answer["outcome"] == "run":
        if answer["samples"] < 2 or not answer["finite_channels"] or answer["metrics_inf"]:
            return f"{label}: silent nonsense {answer}"
        return None
    return f"{label}: {answer}"


def _child(args: list[str], timeout: float) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, __file__, *args],
        capture_output=True,
        text=True,
        check=False,
        timeout=timeout,
        preexec_fn=_limit,
        env={**os.environ, "RAYON_NUM_THREADS": "1"},
    )


def test_every_scenario_field_gives_a_typed_error_or_a_finite_run() -> None:
    done = _child(["all"], timeout=CPU_LIMIT + 60)
    answers = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    labels = [label for label, _, _ in cases()]
    assert done.returncode == 0, (
        f"child died ({done.returncode}) after {len(answers)} of {len(labels)} cases, in "
        f"{labels[len(answers)] if len(answers) < len(labels) else '?'}: {done.stderr[-2000:]}"
    )
    assert len(answers) == len(labels)
    problems = [
        p
        for (label, field, _), answer in zip(cases(), answers, strict=True)
        if (p := _judge(label, field, answer["answer"])) is not None
    ]
    assert not problems, "\n".join(problems)
    # The fuzz reaches the core: some cases run, most are refused.
    outcomes = [a["answer"]["outcome"] for a in answers]
    assert 0 < outcomes.count("run") < outcomes.count("error")


@pytest.mark.parametrize(
    ("field", "value", "reason"),
    [
        # Once: 45 s per metre; a creep grid that allocated without end and ignored Ctrl-C; a
        # record with no sample; a step that would never finish.
        ("speed", 1e-3, "lowest speed"),
        ("fastsim_grid", (10_000, 10_000), "cost grows with nx·ny"),
        ("output_rate", 1e-3, "too slow for the run's metrics"),
        ("step", 1e-9, "integration steps"),
    ],
)
def test_once_aborting_or_hanging_values_are_refused_in_their_own_process(
    field: str, value: Any, reason: str
) -> None:
    done = _child(["one", field, json.dumps(value)], timeout=CASE_SECONDS + 30)
    assert done.returncode == 0, done.stderr[-2000:]
    answer = json.loads(done.stdout.strip().splitlines()[-1])
    assert answer["outcome"] == "error" and answer["type"] == "ParameterError", answer
    assert f"`{field}`" in answer["message"] and reason in answer["message"], answer


def _main(argv: list[str]) -> None:
    if argv[0] == "all":
        for label, field, value in cases():
            answer = run_case(field, value)
            print(json.dumps({"case": label, "answer": answer}), flush=True)
    else:
        field, value = argv[1], json.loads(argv[2])
        value = tuple(value) if isinstance(value, list) else value
        print(json.dumps(run_case(field, value)), flush=True)


if __name__ == "__main__":
    _main(sys.argv[1:])
