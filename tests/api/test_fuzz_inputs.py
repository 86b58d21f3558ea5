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
import math
import os
import resource
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

#: Address-space and CPU-time limits of the child, as for the scenario fuzz.
MEMORY_LIMIT = 3 * 2**30
CPU_LIMIT = 300
CASE_SECONDS = 60

#: A case: label, what its error must name (None: a result is the right answer), the call.
Case = tuple[str, str | None, Callable[[Path], Any]]

BAD_NUMBERS: list[Any] = [math.nan, math.inf, -1.0, 0.0, 1e30]
WRONG_TYPES: list[Any] = ["1.0", None, 1 + 2j, {"a": 1}]


def _frequency_cases() -> list[Case]:
    import loco

    vehicle = loco.Locomotive.default()
    straight = loco.Scenario(name="S_norm")
    curved = loco.Scenario(
        name="S_norm",
        curve=[
            {
                "kind": "curve",
                "length_m": 600.0,
                "radius_m": 300.0,
                "cant_mm": 150.0,
                "direction": "left",
            }
        ],
    )
    fr, psd = loco.frequency_response, loco.response_psd
    out: list[Case] = [
        ("frf in a curve", "`curve`", lambda _: fr(vehicle, curved, frequencies=[1.0])),
        ("psd in a curve", "`curve`", lambda _: psd(vehicle, curved, frequencies=[1.0])),
        (
            "frf inputs a string",
            "`inputs`",
            lambda _: fr(vehicle, straight, "vertical", None, [1.0]),
        ),
        ("frf outputs a string", "`outputs`", lambda _: fr(vehicle, straight, None, "A_yb", [1.0])),
        (
            "frf 1e6 frequencies",
            "`frequencies`",
            lambda _: fr(vehicle, straight, frequencies=[1.0] * 1_000_001),
        ),
        ("frf 1e12 Hz", "`frequencies[0]`", lambda _: fr(vehicle, straight, frequencies=[1e12])),
        (
            "frf text frequencies",
            "`frequencies`",
            lambda _: fr(vehicle, straight, frequencies=["a"]),
        ),
        (
            "frf complex frequencies",
            "`frequencies`",
            lambda _: fr(vehicle, straight, frequencies=[1 + 1j]),
        ),
        (
            "psd reversed band",
            "`band`",
            lambda _: psd(vehicle, straight, frequencies=[1.0], band=(50.0, 10.0)),
        ),
        (
            "psd band a string",
            "`band`",
            lambda _: psd(vehicle, straight, frequencies=[1.0], band="ab"),
        ),  # type: ignore[arg-type]
    ]
    for v in [math.nan, math.inf, -1.0, 0.0, *WRONG_TYPES]:
        out.append(
            (
                f"psd amplitude_scale={v!r}",
                "`amplitude_scale`",
                lambda _, v=v: psd(vehicle, straight, frequencies=[1.0], amplitude_scale=v),
            )
        )
    return out


def _curve_cases() -> list[Case]:
    import loco

    def run(curve: Any, distance: float = 20.0) -> Any:
        return loco.simulate(
            loco.Locomotive.default(),
            loco.Scenario(
                name="S_norm", speed=200 / 3.6, distance=distance, track="perfect", curve=curve
            ),
        )

    def section(**kw: Any) -> list[dict[str, Any]]:
        return [{"kind": "curve", "length_m": 100.0, "radius_m": 2000.0, "direction": "left", **kw}]

    return [
        ("curve=[]", "`curve`", lambda _: run([])),
        (
            "fastsim_grid (1, 1)",
            "`fastsim_grid`",
            lambda _: loco.simulate(
                loco.Locomotive.default(),
                loco.Scenario(name="S_norm", distance=1.0, track="perfect", fastsim_grid=(1, 1)),
            ),
        ),
        ("radius inf", "radius_m", lambda _: run(section(radius_m=math.inf))),
        ("radius nan", "radius_m", lambda _: run(section(radius_m=math.nan))),
        (
            "run beyond a design ending in a curve",
            "`distance`",
            lambda _: run(section(), distance=150.0),
        ),
        (
            "run beyond a design ending straight",
            None,
            lambda _: run([{"kind": "straight", "length_m": 5.0}]),
        ),
    ]


def _batch_cases() -> list[Case]:
    import numpy as np

    import loco

    ok = np.array([[1.0e5]])
    short = loco.Scenario(name="S_norm", distance=1.0, track="perfect")

    def batch(params: Any = ok, names: Any = ("C_sx",), **kw: Any) -> Any:
        return loco.run_batch(params, names, scenario=short, progress=False, **kw)

    out: list[Case] = [
        ("params strings", "`params`", lambda _: batch(np.array([["1e5"]]))),
        ("params complex", "`params`", lambda _: batch(np.array([[1e5 + 1j]]))),
        ("params objects", "`params`", lambda _: batch(np.array([[None]], dtype=object))),
        ("params ragged", "`params`", lambda _: batch([[1e5], [1e5, 2.0]])),
        ("names a string", "`names`", lambda _: batch(names="C_sx")),
        ("executor a string", "`executor`", lambda _: batch(executor="dask")),
        ("threads -1", "`threads`", lambda _: batch(threads=-1)),
        ("threads 0 with a store", None, lambda d: batch(threads=0, store=d / "ok-store")),
    ]
    for v in [0, 2.5, -1, "2", math.nan]:
        out.append(
            (f"chunk_size={v!r}", "`chunk_size`", lambda d, v=v: batch(chunk_size=v, store=d / "s"))
        )
    out.append(("store a file", "`store`", lambda d: batch(store=_file(d / "file", b"x"))))
    out.append(
        ("store under a file", "`store`", lambda d: batch(store=_file(d / "file2", b"x") / "sub"))
    )
    return out


def _status_cases() -> list[Case]:
    from loco.commands import campaign as status_command

    def status(d: Path, content: bytes) -> Any:
        # A store directory named like a campaign's (a 16-digit hexadecimal key).
        store = d / "damaged" / ("0" * 16)
        _file(store / "campaign.json", content)
        import argparse
        import contextlib
        import io

        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            status_command.run(argparse.Namespace(dir=d / "damaged"))
        # The damage is reported, with the file, and the command goes on.
        if f"{store}: damaged campaign.json: it " not in printed.getvalue():
            raise AssertionError(f"damage not reported: {printed.getvalue()}")

    contents = [
        b"{",
        b"[]",
        b'{"key": 3}',
        b'{"key": "' + b"a" * 64 + b'", "n_samples": "x"}',
        b"\xff\xfe",
        b'{"key": "' + b"a" * 64 + b'", "n_samples": 4, "inputs": 3}',
    ]
    return [(f"campaign.json {c!r}", None, lambda d, c=c: status(d, c)) for c in contents]


def _track_cases() -> list[Case]:
    from loco import track

    rows = "".join(f"{0.5 * i},0,0,0,0\n" for i in range(200))
    header = "distance,vertical,alignment,cross_level,gauge\n"
    files = {
        "typo in the first row": "0,1,2x,0,0\n" + rows,
        "a 10 km gap": rows + "10100,0,0,0,0\n",
        "Latin-1": "# d\xe9but\n" + rows,
        "UTF-16": header + rows,
        "binary": "\x00\x01\x02" + rows,
    }
    out: list[Case] = []
    for label, text in files.items():
        data = text.encode("utf-16" if label == "UTF-16" else "latin-1")
        out.append(
            (f"track {label}", "t.csv", lambda d, b=data: track.load(str(_file(d / "t.csv", b))))
        )
    out.append(
        (
            "track run_in longer than the file",
            "`run_in`",
            lambda d: track.load(str(_file(d / "t.csv", rows.encode())), run_in=500.0),
        )
    )
    out.append(
        (
            "track with a BOM",
            None,
            lambda d: track.load(
                str(_file(d / "t.csv", b"\xef\xbb\xbf" + rows.encode())), run_in=0.0
            ),
        )
    )
    return out


def _profile_cases() -> list[Case]:
    import numpy as np

    import loco
    from loco import profiles

    wheel = profiles.builtin("jm3-new")
    rail = profiles.builtin("cn60")

    def text(y: Any, z: Any, k: float = 1e3) -> bytes:
        return "".join(f"{a * k:.6f} {b * k:.6f}\n" for a, b in zip(y, z, strict=True)).encode()

    spike = np.array(wheel.z)
    spike[np.searchsorted(wheel.y, 0.02)] += 0.05
    flat = -0.05 * np.array(wheel.y)
    cases = {
        "wheel in m read as mm": (text(wheel.y, wheel.z, 1.0), "wheel"),
        "wheel 1000x too large": (text(wheel.y, wheel.z, 1e6), "wheel"),
        "wheel given as the rail": (text(wheel.y, wheel.z), "rail"),
        "rail given as the wheel": (text(rail.y, rail.z), "wheel"),
        "flangeless wheel": (text(wheel.y, flat), "wheel"),
        "a point raised 50 mm": (text(wheel.y, spike), "wheel"),
        "Latin-1 comment": (b"# \xe9\n" + text(wheel.y, wheel.z), "wheel"),
    }
    out: list[Case] = [
        (f"profile {label}", "p.txt", lambda d, b=b, k=k: profiles.load(_file(d / "p.txt", b), k))
        for label, (b, k) in cases.items()
    ]

    def scenario(**kw: Any) -> Any:
        run = loco.Scenario(distance=5.0, track="perfect", **{"wheel": wheel, "rail": rail, **kw})
        return loco.simulate(loco.Locomotive.default(), run)

    huge = profiles.Profile("huge", "wheel", np.array(wheel.y) * 1e3, np.array(wheel.z) * 1e3)
    flangeless = profiles.Profile("flat", "wheel", np.array(wheel.y), flat)
    out += [
        ("scenario with a huge wheel", "`wheel`", lambda _: scenario(wheel=huge)),
        ("scenario with a flangeless wheel", "`wheel`", lambda _: scenario(wheel=flangeless)),
        ("scenario with a rail as the wheel", "`wheel`", lambda _: scenario(wheel=rail)),
        ("scenario with a wheel as the rail", "`rail`", lambda _: scenario(rail=wheel)),
    ]
    good = text(wheel.y, wheel.z)
    for v in [-1.0, math.nan, 1000.0, "2e-3"]:
        out.append(
            (
                f"smoothing_length={v!r}",
                "`smoothing_length`",
                lambda d, v=v: profiles.load(_file(d / "p.txt", good), "wheel", smoothing_length=v),
            )
        )
    return out


def _file_cases() -> list[Case]:
    import loco

    text = loco.Locomotive.default().default_toml()
    sections = "kind,length_m\nstraight,30\n"
    out: list[Case] = [
        (
            "vehicle Latin-1",
            "v.toml",
            lambda d: loco.Locomotive.from_toml(
                _file(d / "v.toml", "# \xe9\n".encode("latin-1") + text.encode())
            ),
        ),
        (
            "vehicle UTF-16",
            "v.toml",
            lambda d: loco.Locomotive.from_toml(_file(d / "v.toml", text.encode("utf-16"))),
        ),
        (
            "vehicle binary",
            "v.toml",
            lambda d: loco.Locomotive.from_toml(_file(d / "v.toml", b"\x00\xff" * 20)),
        ),
        ("vehicle text malformed", "<toml_text>", lambda _: loco.Locomotive(toml_text="[x")),
        (
            "vehicle file malformed",
            "v.toml:1",
            lambda d: loco.Locomotive.from_toml(_file(d / "v.toml", b"[x")),
        ),
        (
            "sections malformed",
            "c.csv:2",
            lambda d: loco.simulate(
                loco.Locomotive.default(),
                loco.Scenario(
                    name="S_norm",
                    distance=10.0,
                    track="perfect",
                    curve=str(_file(d / "c.csv", b"kind,length_m\nstraight,30,1\n")),
                ),
            ),
        ),
        (
            "sections Latin-1",
            "c.csv",
            lambda d: loco.simulate(
                loco.Locomotive.default(),
                loco.Scenario(
                    name="S_norm",
                    distance=10.0,
                    track="perfect",
                    curve=str(_file(d / "c.csv", ("# \xe9\n" + sections).encode("latin-1"))),
                ),
            ),
        ),
        (
            "sections file without sections",
            "c.csv:0: no sections",
            lambda d: loco.simulate(
                loco.Locomotive.default(),
                loco.Scenario(
                    name="S_norm",
                    distance=10.0,
                    track="perfect",
                    curve=str(_file(d / "c.csv", b"kind,length_m\n")),
                ),
            ),
        ),
        (
            "sections with a BOM",
            None,
            lambda d: loco.simulate(
                loco.Locomotive.default(),
                loco.Scenario(
                    name="S_norm",
                    distance=10.0,
                    track="perfect",
                    curve=str(_file(d / "c.csv", b"\xef\xbb\xbf" + sections.encode())),
                ),
            ),
        ),
    ]
    return out


def _bench_cases() -> list[Case]:
    from loco import dampers

    return [
        ("bench 1 GHz", "frequency", lambda _: dampers.bench(dampers.FSD, 1e9, 0.005)),
        ("bench 10 m", "amplitude", lambda _: dampers.bench(dampers.FSD, 1.0, 10.0)),
        (
            "sweep to 1 GHz",
            "frequency",
            lambda _: dampers.bench_sweep(dampers.FSD, 1.0, 1e9, 0.005, 1.0),
        ),
    ]


def _executor_cases() -> list[Case]:
    from loco import executors

    def from_environment(address: str) -> Any:
        os.environ[executors.SCHEDULER_ENV] = address
        try:
            return executors.executor_from_options()
        finally:
            del os.environ[executors.SCHEDULER_ENV]

    out: list[Case] = [
        (
            f"{executors.SCHEDULER_ENV}={a!r}",
            f"`{executors.SCHEDULER_ENV}`",
            lambda _, a=a: from_environment(a),
        )
        for a in ["bogus", "tcp://", "http://host:8786", "host:99999", "host:port"]
    ]
    out.append(
        (
            "--scheduler malformed",
            "`--scheduler`",
            lambda _: executors.executor_from_options(scheduler="::::"),
        )
    )
    out.append(
        (
            "a scheduler address where a web server answers",
            "not a Dask scheduler",
            lambda _: executors.DaskExecutor(address=f"tcp://127.0.0.1:{_web_server()}"),
        )
    )
    # Nothing listens on port 1: refused at once, or at worst after the 5 s connect timeout.
    out.append(
        (
            "unreachable scheduler",
            "cannot reach the Dask scheduler",
            lambda _: executors.DaskExecutor(address="tcp://127.0.0.1:1"),
        )
    )
    return out


def _cli(argv: list[str], environment: dict[str, str] | None = None) -> None:
    """``loco <argv>`` in this process: nothing for exit 0; for exit 1 or 2 with a one-line
    ``error:`` message and no traceback, a :class:`loco.LocoError` carrying what it printed (so
    the case is judged on the message); anything else raises as it came."""
    import contextlib
    import io

    import loco
    from loco.cli import main

    printed = io.StringIO()
    saved = {k: os.environ.get(k) for k in environment or {}}
    os.environ.update(environment or {})
    try:
        with contextlib.redirect_stderr(printed):
            try:
                code = main(argv)
            except SystemExit as e:
                code = int(e.code or 0)
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    message = printed.getvalue()
    if code == 0:
        return
    if code in (1, 2) and "error:" in message and "Traceback" not in message:
        raise loco.LocoError(message)
    raise RuntimeError(f"exit {code}: {message}")


def _cli_cases() -> list[Case]:
    import loco
    from loco import executors

    text = loco.Locomotive.default().default_toml()
    latin1 = "# \xe9\n".encode("latin-1") + text.encode()
    sections = "# \xe9\nkind,length_m\nstraight,30\n".encode("latin-1")
    return [
        (
            "loco frf --vehicle Latin-1",
            "v.toml",
            lambda d: _cli(["frf", "--vehicle", str(_file(d / "v.toml", latin1)), "--out", str(d)]),
        ),
        (
            "loco simulate --curve Latin-1",
            "c.csv",
            lambda d: _cli(
                ["simulate", "--curve", str(_file(d / "c.csv", sections)), "--out", str(d)]
            ),
        ),
        (
            f"loco reproduce with {executors.SCHEDULER_ENV}=bogus",
            executors.SCHEDULER_ENV,
            lambda d: _cli(
                ["reproduce", "--tiny", "--no-progress", "--out", str(d / "out")],
                {executors.SCHEDULER_ENV: "bogus"},
            ),
        ),
    ]


def _web_server() -> int:
    """The port of a local server that answers every connection as a web server would (an
    HTTP error), in a daemon thread of this process."""
    import socket
    import threading

    server = socket.create_server(("127.0.0.1", 0))

    def answer() -> None:
        while True:
            connection, _ = server.accept()
            with connection:
                connection.sendall(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n")

    threading.Thread(target=answer, daemon=True).start()
    return int(server.getsockname()[1])


def _file(path: Path, data: bytes) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)
    return path


def cases() -> list[Case]:
    """Every case, in a fixed order."""
    return [
        *_frequency_cases(),
        *_curve_cases(),
        *_batch_cases(),
        *_status_cases(),
        *_track_cases(),
        *_profile_cases(),
        *_file_cases(),
        *_bench_cases(),
        *_executor_cases(),
        *_cli_cases(),
    ]


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
