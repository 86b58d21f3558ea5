"""Fuzz of every vehicle parameter of the schema: NaN, ±inf, 0, negative, 1e±30, just outside its
range, fractional counts and wrong types, through the Python overrides and through the file.

Three paths, each in one child process under a memory and CPU-time limit (as
``test_fuzz_scenario.py``):

- ``overrides``: ``Locomotive.default().replace({key: value})`` and
  ``Locomotive(overrides={key: value})``: a value outside the range, non-finite, fractional for a
  count or of the wrong type is a :class:`loco.ParameterError` (a
  :class:`loco.ParameterRangeError` for the range) naming the key; an in-range value builds.
- ``file``: the value written into the vehicle file (TOML ``nan``, ``inf``, a string, a bool, an
  array): the same errors naming the key (a wrong TOML type is a :class:`loco.ParameterError`
  naming the file's line and the key, never the file's format error); an in-range value builds.
- ``runs``: the values a build accepts (in range, or outside it with the key in the file's
  ``allow_out_of_range``: 0, −1, 1e±30, −1e30, just outside, and both ends of the range) run,
  each as one sample of a batch (the batch shares what a sample does not change: the contact
  table for every key that does not affect the contact): a finite run, or a typed failure naming
  the key (a research value outside the range is the suspect the core names), never an abort, a
  panic or a hang.

Cost (the CI budget is ≈40 s): builds cost ≈4 ms, so the first two paths take seconds; the runs
are 1 m at 200 km/h on perfect track (statics, the step check against the stiffest mode and 18
RK4 steps), batched on the machine's two cores. The ends of each range run too, the stiffest of
them (hollow-shaft bearings, the lightest shaft and motor inertias) on a whole fraction of the
default step that their stiffest mode allows (`stiffest_mode::stable_step`).
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

MEMORY_LIMIT = 3 * 2**30
CPU_LIMIT = 400

#: Values of the overrides path (Python objects) besides just outside the range and, for counts,
#: a fraction.
NUMBERS: list[Any] = [math.nan, math.inf, -math.inf, 0.0, -1.0, 1e30, 1e-30, -1e30]
WRONG_TYPES: list[Any] = ["1.0", None, True, 1 + 2j, [1.0]]
#: Values of the file path, as TOML.
FILE_NUMBERS = ["nan", "inf", "-inf", "0.0", "-1.0", "1e30", "1e-30", "-1e30"]
FILE_WRONG_TYPES = ['"1.0"', "true", "[1.0]", "{ a = 1 }"]
#: Values run with the key allowed outside its range.
RUN_NUMBERS = [0.0, -1.0, 1e30, 1e-30]


def outside(spec: Any) -> list[float]:
    """Just below and just above the range (0.1 % of its span, at least 1 for a count)."""
    margin = 1.0 if spec.kind == "count" else 1e-3 * (spec.max - spec.min)
    return [spec.min - margin, spec.max + margin]


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_LIMIT, CPU_LIMIT))


def _answer(call: Any) -> dict[str, Any]:
    import loco

    try:
        call()
    except loco.LocoError as e:
        return {"outcome": "error", "type": type(e).__name__, "message": str(e)}
    except BaseException as e:
        return {"outcome": "raw", "type": type(e).__name__, "message": str(e)}
    return {"outcome": "built"}


def overrides_cases() -> list[dict[str, Any]]:
    import loco

    base = loco.Locomotive.default()
    out = []
    for key, spec in loco.parameter_schema().items():
        values = [*NUMBERS, *outside(spec), *WRONG_TYPES]
        if spec.kind == "count":
            values.append(spec.min + 0.5)
        for value in values:
            inside = (
                isinstance(value, float)
                and spec.min <= value <= spec.max
                and (spec.kind == "real" or value == int(value))
            )
            for path, call in [
                ("replace", lambda key=key, value=value: base.replace({key: value})),
                ("constructor", lambda k=key, v=value: loco.Locomotive(overrides={k: v})),
            ]:
                if path == "constructor" and value not in WRONG_TYPES:
                    continue  # the same native check as replace; its own code is the types
                out.append(
                    {"key": key, "value": repr(value), "path": path, "inside": inside}
                    | _answer(call)
                )
    return out


def file_cases() -> list[dict[str, Any]]:
    import loco

    text = loco.Locomotive.default().default_toml()
    lines = text.splitlines()
    out = []
    for key, spec in loco.parameter_schema().items():
        section, name = key.split(".")
        if f"[{section}]" not in lines:
            # An optional key the default file leaves out: fuzzed in a section of its own, which
            # the other keys' cases keep at a value inside its range.
            middle = 0.5 * (spec.min + spec.max)
            lines = [
                *lines,
                "",
                f"[{section}]",
                f'{name} = {{ value = {middle!r}, unit = "{spec.unit}", source = "fuzz" }}',
            ]
        header = lines.index(f"[{section}]")
        row = next(
            i for i in range(header + 1, len(lines)) if lines[i].startswith(f"{name} = {{ value = ")
        )
        values = [*FILE_NUMBERS, *(repr(v) for v in outside(spec)), *FILE_WRONG_TYPES]
        if spec.kind == "count":
            values.append(repr(spec.min + 0.5))
        for value in values:
            rest = lines[row].split(",", 1)[1]
            changed = [*lines[:row], f"{name} = {{ value = {value},{rest}", *lines[row + 1 :]]
            answer = _answer(
                lambda changed=changed: loco.Locomotive(
                    toml_text="\n".join(changed) + "\n", origin="fuzz.toml"
                )
            )
            try:
                number = float(value)
            except ValueError:
                number = math.nan
            inside = spec.min <= number <= spec.max and (
                spec.kind == "real" or number == int(number)
            )
            out.append({"key": key, "value": value, "path": "file", "inside": inside} | answer)
    return out


def run_cases() -> list[dict[str, Any]]:
    import numpy as np

    import loco

    schema = loco.parameter_schema()
    allowed = ", ".join(f'"{k}"' for k in schema)
    # The optional keys the default file leaves out, stated at the middle of their ranges so
    # that every row of the batch has a value for them.
    optional = "".join(
        f"\n[{k.split('.')[0]}]\n{k.split('.')[1]} = {{ value = {0.5 * (s.min + s.max)!r}, "
        f'unit = "{s.unit}", source = "fuzz" }}\n'
        for k, s in schema.items()
        if s.optional
    )
    research = loco.Locomotive(
        toml_text=f"allow_out_of_range = [{allowed}]\n"
        + loco.Locomotive.default().default_toml()
        + optional,
        origin="research.toml",
    )
    scenario = loco.Scenario(name="S_norm", speed=200 / 3.6, distance=1.0, track="perfect")
    out: list[dict[str, Any]] = []
    for contact in (False, True):
        keys = [k for k, s in schema.items() if ("contact" in s.affects) == contact]
        rows, cases = [], []
        for key in keys:
            spec = schema[key]
            for value in [spec.min, spec.max, *outside(spec), *RUN_NUMBERS]:
                end = "min" if value == spec.min else "max" if value == spec.max else ""
                inside = spec.min <= value <= spec.max
                case = {"key": key, "value": repr(value), "path": "run", "inside": inside,
                        "end": end}  # fmt: skip
                built = _answer(lambda key=key, value=value: research.replace({key: value}))
                if built["outcome"] != "built":
                    out.append(case | built)
                    continue
                row = [research[k] for k in keys]
                row[keys.index(key)] = value
                rows.append(row)
                cases.append(case)
        result = loco.run_batch(
            np.array(rows), keys, research, scenario=scenario, threads=2, progress=False
        )
        status = result.to_frame()["status"]
        for case, st, message, metrics in zip(
            cases, status, result.messages, result.metrics, strict=True
        ):
            if st == "ok":
                out.append(case | {"outcome": "run", "inf": bool(np.isinf(metrics).any())})
            else:
                out.append(case | {"outcome": "error", "type": st, "message": message})
    return out


def _judge(case: dict[str, Any]) -> str | None:
    """What is wrong with a case's answer (None: fine)."""
    label = f"{case['path']}: {case['key']} = {case['value']}"
    outcome = case["outcome"]
    if outcome == "built":
        return None if case["inside"] else f"{label}: accepted silently"
    if outcome == "run":
        return f"{label}: infinite metrics" if case["inf"] else None
    if outcome != "error":
        return f"{label}: {outcome} {case.get('type')}: {case.get('message')}"
    message = case["message"]
    # In the file, a value's fault is the parameter's, at its line (a range error names the range).
    if case["path"] == "file" and not (
        case["type"] == "ParameterRangeError"
        or (case["type"] == "ParameterError" and message.startswith("fuzz.toml:"))
    ):
        return f"{label}: not a parameter error at its line: {case['type']}: {message}"
    if case["path"] == "run" and case["inside"]:
        # A physical vehicle: it runs, every end of every range included.
        return f"{label}: a physical value fails: {message}"
    return None if f"`{case['key']}`" in message else f"{label}: not named: {message}"


def _child(path: str) -> list[dict[str, Any]]:
    done = subprocess.run(
        [sys.executable, __file__, path],
        capture_output=True,
        text=True,
        check=False,
        timeout=CPU_LIMIT + 60,
        preexec_fn=_limit,
        env={**os.environ, "RAYON_NUM_THREADS": "2"},
    )
    assert done.returncode == 0, f"child died ({done.returncode}): {done.stderr[-3000:]}"
    return [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]


@pytest.mark.slow
@pytest.mark.parametrize("path", ["overrides", "file", "runs"])
def test_every_vehicle_parameter_gives_a_typed_error_naming_it_or_a_finite_run(path: str) -> None:
    import loco

    cases = _child(path)
    keys = {c["key"] for c in cases}
    assert keys == set(loco.parameter_schema()), "every key is fuzzed"
    problems = [p for c in cases if (p := _judge(c)) is not None]
    assert not problems, f"{len(problems)} of {len(cases)}:\n" + "\n".join(problems)
    if path == "runs":
        outcomes = [c["outcome"] for c in cases]
        # Most research values run or are refused by name; the ends of the ranges run.
        assert outcomes.count("run") > len(keys)
        ran = {(c["key"], c["end"]) for c in cases if c["outcome"] == "run"}
        ends = {(k, e) for k in keys for e in ("min", "max")}
        assert ends <= ran, sorted(ends - ran)


def _main(path: str) -> None:
    cases = {"overrides": overrides_cases, "file": file_cases, "runs": run_cases}[path]()
    for case in cases:
        print(json.dumps(case), flush=True)


if __name__ == "__main__":
    _main(sys.argv[1])
