"""Fuzz of the inputs beyond a scenario's fields: the frequency response, curves, batches and
their stores, campaign status, measured tracks, profiles, damper benches and file encodings.

Each case must give a :class:`loco.LocoError` whose message names what is wrong (the argument,
or the file), or a result: never an abort, a hang, a raw ``TypeError``/``ValueError``/
``KeyError``/``UnicodeDecodeError`` or a silent acceptance of what the case marks as bad. The
cases run in one child process under a memory and CPU-time limit, as in
``tests/api/test_fuzz_scenario.py``; none runs a simulation longer than 20 m, so the suite costs a
few seconds.
"""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import pytest
from fuzz_file_cases import cases
from fuzz_numeric_cases import Case

#: Address-space and CPU-time limits of the child, as for the scenario fuzz.
MEMORY_LIMIT = 3 * 2**30
CPU_LIMIT = 300
CASE_SECONDS = 60


def run_case(case: Case, directory: Path) -> dict[str, Any]:
    """One case in this process: what happened, as a JSON-ready dict."""
    import signal

    import loco

    def timeout(signum: int, frame: object) -> None:
        raise TimeoutError(f"no answer in {CASE_SECONDS} s")

    signal.signal(signal.SIGALRM, timeout)
    signal.alarm(CASE_SECONDS)
    try:
        case[2](directory)
    except loco.LocoError as e:
        return {"outcome": "error", "type": type(e).__name__, "message": str(e)}
    except TimeoutError as e:
        return {"outcome": "hang", "message": str(e)}
    except BaseException as e:
        return {"outcome": "raw", "type": type(e).__name__, "message": str(e)}
    finally:
        signal.alarm(0)
    return {"outcome": "result"}


#: The class a file's fault must raise, by the start of the case's label: the file's kind, not
#: another kind's (a malformed track file is not a profile error).
FILE_CLASSES = {
    "vehicle": "VehicleFormatError",
    "track ": "TrackFormatError",
    "sections": "TrackFormatError",
    "profile ": "ProfileFormatError",
}


def judge(label: str, named: str | None, answer: dict[str, Any]) -> str | None:
    """What is wrong with an answer (None: fine)."""
    if named is None:
        return None if answer["outcome"] == "result" else f"{label}: {answer}"
    if answer["outcome"] != "error":
        return f"{label}: expected an error naming {named}, got {answer}"
    if named not in answer["message"]:
        return f"{label}: the error does not name {named}: {answer['message']}"
    expected = next((c for start, c in FILE_CLASSES.items() if label.startswith(start)), None)
    if expected and named.startswith(("v.toml", "t.csv", "c.csv", "p.txt", "<toml_text>")):
        if answer["type"] != expected:
            return f"{label}: expected a {expected}, got {answer['type']}: {answer['message']}"
    return None


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_LIMIT, CPU_LIMIT))


@pytest.mark.slow
def test_every_bad_input_gives_a_typed_error_naming_it() -> None:
    done = subprocess.run(
        [sys.executable, __file__],
        capture_output=True,
        text=True,
        check=False,
        timeout=CPU_LIMIT + 60,
        preexec_fn=_limit,
        env={**os.environ, "RAYON_NUM_THREADS": "1"},
    )
    answers = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    assert done.returncode == 0, f"child died after {len(answers)} cases: {done.stderr[-2000:]}"
    labels = [a["case"] for a in answers]
    assert len(labels) == len(set(labels)) and len(labels) > 60, labels
    problems = [p for a in answers if (p := judge(a["case"], a["named"], a["answer"]))]
    assert not problems, "\n".join(problems)


def _main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        for i, case in enumerate(cases()):
            directory = Path(tmp) / f"case{i}"
            directory.mkdir()
            answer = run_case(case, directory)
            print(json.dumps({"case": case[0], "named": case[1], "answer": answer}), flush=True)


if __name__ == "__main__":
    _main()
