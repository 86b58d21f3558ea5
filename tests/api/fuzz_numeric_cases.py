"""The input-fuzz cases of the numeric inputs: the frequency response, curves, batches, campaign
status and measured tracks (run by ``tests/api/test_fuzz_inputs.py``)."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

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
    out.append(("store a file", "`store`", lambda d: batch(store=write_file(d / "file", b"x"))))
    out.append(
        (
            "store under a file",
            "`store`",
            lambda d: batch(store=write_file(d / "file2", b"x") / "sub"),
        )
    )
    return out


def _status_cases() -> list[Case]:
    from loco.commands import campaign as status_command

    def status(d: Path, content: bytes) -> Any:
        # A store directory named like a campaign's (a 16-digit hexadecimal key).
        store = d / "damaged" / ("0" * 16)
        write_file(store / "campaign.json", content)
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
            (
                f"track {label}",
                "t.csv",
                lambda d, b=data: track.load(str(write_file(d / "t.csv", b))),
            )
        )
    out.append(
        (
            "track run_in longer than the file",
            "`run_in`",
            lambda d: track.load(str(write_file(d / "t.csv", rows.encode())), run_in=500.0),
        )
    )
    out.append(
        (
            "track with a BOM",
            None,
            lambda d: track.load(
                str(write_file(d / "t.csv", b"\xef\xbb\xbf" + rows.encode())), run_in=0.0
            ),
        )
    )
    return out


def write_file(path: Path, data: bytes) -> Path:
    """Writes ``data`` to ``path`` (its folder made) and returns the path."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)
    return path


def numeric_cases() -> list[Case]:
    """The numeric inputs' cases, in a fixed order."""
    return [
        *_frequency_cases(),
        *_curve_cases(),
        *_batch_cases(),
        *_status_cases(),
        *_track_cases(),
    ]
