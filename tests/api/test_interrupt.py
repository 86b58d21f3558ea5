"""Ctrl-C during a long ``loco.simulate``: the run is on a worker thread, the caller
checks for signals every 100 ms, so SIGINT stops it within a step as a ``KeyboardInterrupt``
(never a panic), in a real subprocess."""

from __future__ import annotations

import signal
import subprocess
import sys
import time

import pytest

SCRIPT = """
import loco
print("started", flush=True)
try:
    loco.simulate(loco.Locomotive.default(),
                  loco.Scenario(name="S_high", distance=50_000.0, track="perfect"))
except KeyboardInterrupt:
    print("interrupted", flush=True)
"""


def test_sigint_stops_a_long_simulation() -> None:
    for delay in (0.2, 1.5):  # during the set-up (table, statics) and during the time loop
        process = subprocess.Popen(
            [sys.executable, "-c", SCRIPT],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        assert process.stdout is not None
        assert process.stdout.readline().strip() == "started"
        time.sleep(delay)
        sent = time.perf_counter()
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=60)
        waited = time.perf_counter() - sent
        assert "interrupted" in out, (out, err)
        assert "Panic" not in err, err
        # 50 km would take about half a minute; an honoured Ctrl-C ends it within a few
        # seconds even on a loaded machine (the set-up before the loop is not interruptible).
        assert waited < 10.0, waited


#: Repeated Ctrl-C at random moments of every long call of the bindings, in one subprocess: each
#: call must end as KeyboardInterrupt within a few seconds of its SIGINT (never a panic, never a
#: silent finish), and an interrupted campaign keeps every chunk it reported finished.
MANY = r"""
import json, os, random, signal, sys, tempfile, threading, time
import numpy as np
import loco
from loco.campaign import run_campaign

random.seed(int(sys.argv[1]))
vehicle = loco.Locomotive.default()
long_run = loco.Scenario(name="S_high", distance=50_000.0, track="perfect")
short = loco.Scenario(name="S_high", distance=300.0, seed=3)
# Hunting at 396 km/h, a ramp down to where it dies out near 360 km/h: ~2 s of wall time on an
# idle machine at 0.12 m/s² (the ramp's distance limit, 100 km, allows no slower ramp), so its
# Ctrl-C comes within the first 1.2 s; so does the campaign's (24 short runs, ~2 s idle).
hunting = loco.Scenario(name="S_high", speed=110.0, distance=100.0, track="perfect")
latest = {"critical_speed_nonlinear": 1.2, "campaign": 1.2}
finished = []
calls = {
    "simulate": lambda: loco.simulate(vehicle, long_run),
    "run_batch": lambda: loco.run_batch(np.full((16, 1), 8e5), ["C_sx"], scenario=long_run,
                                        threads=2, progress=False),
    "critical_speed_nonlinear": lambda: loco.critical_speed(vehicle, hunting, method="nonlinear",
                                                            deceleration=0.12),
    "campaign": lambda: run_campaign(np.linspace(2e5, 9e5, 24)[:, None], ["C_sx"], scenario=short,
                                     store=store, chunk_size=2, threads=2, progress=False,
                                     on_chunk=lambda idx: finished.extend(int(i) for i in idx)),
}
for name in sys.argv[2:]:
    if name == "campaign":  # a fresh store: the campaign runs from nothing
        store = tempfile.mkdtemp()
        finished.clear()
    delay = random.uniform(0.05, latest.get(name, 2.5))
    timer = threading.Timer(delay, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.perf_counter()
    timer.start()
    try:
        calls[name]()
        outcome = "finished"
    except KeyboardInterrupt:
        outcome = "interrupted"
    except BaseException as e:
        outcome = f"{type(e).__name__}: {e}"
    timer.cancel()
    late = time.perf_counter() - start - delay
    answer = {"call": name, "delay": delay, "late": late, "outcome": outcome}
    if name == "campaign" and outcome == "interrupted":
        again = run_campaign(np.linspace(2e5, 9e5, 24)[:, None], ["C_sx"], scenario=short,
                             store=store, chunk_size=2, threads=2, progress=False)
        answer |= {"finished_before": len(set(finished)), "reused": int(again.n_reused),
                   "complete": bool((again.status == 0).all())}
    print(json.dumps(answer), flush=True)
"""


@pytest.mark.slow
def test_many_sigints_across_the_bindings() -> None:
    import json

    calls = ["simulate", "run_batch", "critical_speed_nonlinear", "campaign"] * 2
    done = subprocess.run(
        [sys.executable, "-c", MANY, "13", *calls],
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    assert "Panic" not in done.stderr and "panicked" not in done.stderr, done.stderr
    answers = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    assert [a["call"] for a in answers] == calls
    for a in answers:
        # Every call takes far longer than its delay: a Ctrl-C that is not honoured shows.
        assert a["outcome"] == "interrupted", a
        # Within a step or a sample of the signal (the set-up before a run is not
        # interruptible: a contact table, ~1 s on a loaded machine).
        assert a["late"] < 8.0, a
        if a["call"] == "campaign":
            # Every chunk reported finished was stored: the rerun reads them back.
            assert a["reused"] >= a["finished_before"] and a["complete"], a


#: The linear calls (critical speed by bisection, FRF, response PSD), each made long: a 50 × 50
#: FASTSIM grid and a tolerance below the floats' spacing (≈60 linearisations, ~5 s idle), 2e5
#: frequencies (~1 min). A Python thread ticks while the call runs: ticks show the GIL released.
LINEAR = r"""
import json, os, signal, sys, threading, time
import numpy as np
import loco

vehicle = loco.Locomotive.default()
fine = loco.Scenario(name="S_high", fastsim_grid=(50, 50))
plain = loco.Scenario(name="S_high")
many = np.linspace(0.1, 20.0, 100_000)  # the most frequencies a call takes, about 50 s of work
calls = {
    "critical_speed_linear": lambda: loco.critical_speed(vehicle, fine, method="linear",
                                                         tolerance=1e-300, low=1.0, high=1000.0),
    "frequency_response": lambda: loco.frequency_response(vehicle, plain, frequencies=many),
    "response_psd": lambda: loco.response_psd(vehicle, plain, frequencies=many),
}
for name, delay in zip(sys.argv[1::2], map(float, sys.argv[2::2])):
    ticks = []
    stop = threading.Event()
    def tick():
        while not stop.wait(0.01):
            ticks.append(1)
    ticker = threading.Thread(target=tick)
    timer = threading.Timer(delay, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.perf_counter()
    ticker.start()
    timer.start()
    try:
        calls[name]()
        outcome = "finished"
    except KeyboardInterrupt:
        outcome = "interrupted"
    except BaseException as e:
        outcome = f"{type(e).__name__}: {e}"
    late = time.perf_counter() - start - delay
    timer.cancel()
    stop.set()
    ticker.join()
    print(json.dumps({"call": name, "delay": delay, "late": late, "outcome": outcome,
                      "ticks": len(ticks)}), flush=True)
"""


def test_sigint_stops_the_linear_calls() -> None:
    import json

    # Early (in the linearisation or the first solves) and later (inside the loop).
    plan = [
        (call, delay)
        for call in ("critical_speed_linear", "frequency_response", "response_psd")
        for delay in (0.3, 1.2)
    ]
    done = subprocess.run(
        [sys.executable, "-c", LINEAR, *(str(x) for pair in plan for x in pair)],
        capture_output=True,
        text=True,
        check=False,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    assert "Panic" not in done.stderr and "panicked" not in done.stderr, done.stderr
    answers = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    assert [(a["call"], a["delay"]) for a in answers] == plan
    for a in answers:
        assert a["outcome"] == "interrupted", a
        # Within one linearisation or a few frequencies of the signal (a linearisation and the
        # Hessenberg reduction before the first frequency are not interruptible: < 1 s idle).
        assert a["late"] < 5.0, a
        # The GIL was free during the call: the ticker ran (~100 per second).
        assert a["ticks"] > 10 * a["delay"], a
