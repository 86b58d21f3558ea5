"""The input-fuzz cases of files and services: profiles, vehicle, track and curve files and their
encodings, damper benches, executors and the command line (run by
``tests/api/test_fuzz_inputs.py``)."""

from __future__ import annotations

import math
import os
from typing import Any

from fuzz_numeric_cases import Case, numeric_cases, write_file


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
        (
            f"profile {label}",
            "p.txt",
            lambda d, b=b, k=k: profiles.load(write_file(d / "p.txt", b), k),
        )
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
                lambda d, v=v: profiles.load(
                    write_file(d / "p.txt", good), "wheel", smoothing_length=v
                ),
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
                write_file(d / "v.toml", "# \xe9\n".encode("latin-1") + text.encode())
            ),
        ),
        (
            "vehicle UTF-16",
            "v.toml",
            lambda d: loco.Locomotive.from_toml(write_file(d / "v.toml", text.encode("utf-16"))),
        ),
        (
            "vehicle binary",
            "v.toml",
            lambda d: loco.Locomotive.from_toml(write_file(d / "v.toml", b"\x00\xff" * 20)),
        ),
        ("vehicle text malformed", "<toml_text>", lambda _: loco.Locomotive(toml_text="[x")),
        (
            "vehicle file malformed",
            "v.toml:1",
            lambda d: loco.Locomotive.from_toml(write_file(d / "v.toml", b"[x")),
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
                    curve=str(write_file(d / "c.csv", b"kind,length_m\nstraight,30,1\n")),
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
                    curve=str(write_file(d / "c.csv", ("# \xe9\n" + sections).encode("latin-1"))),
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
                    curve=str(write_file(d / "c.csv", b"kind,length_m\n")),
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
                    curve=str(write_file(d / "c.csv", b"\xef\xbb\xbf" + sections.encode())),
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
            lambda d: _cli(
                ["frf", "--vehicle", str(write_file(d / "v.toml", latin1)), "--out", str(d)]
            ),
        ),
        (
            "loco simulate --curve Latin-1",
            "c.csv",
            lambda d: _cli(
                ["simulate", "--curve", str(write_file(d / "c.csv", sections)), "--out", str(d)]
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


def cases() -> list[Case]:
    """Every case, in a fixed order."""
    return [
        *numeric_cases(),
        *_profile_cases(),
        *_file_cases(),
        *_bench_cases(),
        *_executor_cases(),
        *_cli_cases(),
    ]
