"""loco.run_batch: same numbers as single runs, any thread count, failures flagged, typed errors."""

from __future__ import annotations

import os
import signal
import threading
import time

import numpy as np
import pytest

import loco
from loco.batch import STATUS_NAMES

# 5.3 s at 200 km/h: one full Sperling segment, so every metric is defined.
SCENARIO = loco.Scenario(name="S_high", speed=200 / 3.6, distance=295.0, seed=3)


def test_bit_identical_for_any_thread_count_and_equal_to_simulate() -> None:
    params = np.array([[2e5, 3.5e6], [8e5, 8e6], [1.2e6, 2e6]])
    one = loco.run_batch(params, ["C_sx", "K_py"], scenario=SCENARIO, threads=1, progress=False)
    two = loco.run_batch(
        params, ["C_sx", "K_py"], scenario=SCENARIO, threads=2, progress=False, histories=[2]
    )
    assert one.n_failed == 0, one.messages
    assert one.metrics.shape == (3, len(one.metric_names))
    assert np.array_equal(one.metrics.view(np.uint64), two.metrics.view(np.uint64))
    single = loco.simulate(loco.Locomotive.default().replace(C_sx=1.2e6, K_py=2e6), SCENARIO)
    expected = np.array([single.metrics[m] for m in one.metric_names])
    assert np.array_equal(one.metrics[2].view(np.uint64), expected.view(np.uint64))
    kept = two.histories[2]
    assert np.array_equal(kept.time, single.time)
    assert np.array_equal(
        kept.channel("frame1_ay_wheelset1"), single.channel("frame1_ay_wheelset1")
    )
    # A softer yaw damper lets the worn-wheel bogie hunt harder (SPEC §6: A_yb falls with C_sx).
    ayb = one.metric("ayb_peak_lp")
    assert ayb[0] > ayb[1]


def test_speed_column_and_frame() -> None:
    params = np.array([[160 / 3.6], [200 / 3.6]])
    result = loco.run_batch(params, ["speed"], scenario=SCENARIO, threads=2, progress=False)
    frame = result.to_frame()
    assert list(frame["status"]) == ["ok", "ok"]
    assert {"speed", "wy_max", "ayb_peak_lp", "message"} <= set(frame.columns)
    # Run statistics per row, the same counts as a single run's.
    assert result.statistics is not None
    assert {"rhs_evaluations", "steps", "newton_iterations", "wall_time"} <= set(frame.columns)
    assert (frame["steps"] > 0).all() and (frame["wall_time"] > 0).all()
    assert repr(result).startswith("BatchResult(2 samples of ['speed'], 0 failed")
    single = loco.simulate(
        loco.Locomotive.default(), loco.Scenario(**{**SCENARIO.__dict__, "speed": 160 / 3.6})
    )
    assert result.metric("wy_max")[0] == single.metrics["wy_max"]
    assert frame["rhs_evaluations"][0] == single.statistics["rhs_evaluations"]


def test_a_diverging_sample_is_flagged_and_the_rest_completes() -> None:
    # A primary spring a million times too stiff puts a mode far beyond RK4's limit at 1 ms.
    # Far outside the physical range: the vehicle file allows it explicitly.
    key = "primary.axle_box_spring_vertical_stiffness"
    text = f'allow_out_of_range = ["{key}"]\n' + loco.Locomotive.default().default_toml()
    vehicle = loco.Locomotive(toml_text=text, origin="research.toml")
    params = np.array([[1.5e7], [1.5e13], [1.5e7]])
    result = loco.run_batch(params, [key], vehicle, scenario=SCENARIO, progress=False)
    # The mode is found at the equilibrium, before the run: refused naming the step, the mode's
    # coordinate and the out-of-range stiffness as the suspect (it would blow up within steps).
    assert [STATUS_NAMES[s] for s in result.status] == ["ok", "invalid_parameter", "ok"]
    assert np.isnan(result.metrics[1]).all()
    assert np.isfinite(result.metrics[[0, 2]]).all()
    assert "`step`" in result.messages[1] and f"`{key}` = 1.5e13" in result.messages[1]
    assert result.messages[0] == ""
    assert result.failures() == {"invalid_parameter": 1}


@pytest.mark.parametrize(
    ("params", "names", "fragment"),
    [
        (np.array([[8e5, 1.5e7], [8e5, np.nan]]), ["C_sx", "K_px"], "row 1, column 1 'K_px'"),
        (np.array([[8e5, 1.5e7], [8e5, -1.0]]), ["C_sx", "K_px"], "row 1, column 1 'K_px'"),
        (np.array([[8e5]]), ["C_sz"], "C_sz"),
        (np.array([[8e5, 1.0]]), ["C_sx"], "2 columns but 1 names"),
        (np.array([8e5, 1.0]), ["C_sx"], "2-D"),
        (np.array([[500.0]]), ["speed"], "speed"),
    ],
)
def test_bad_input_raises_parameter_error_naming_it(
    params: np.ndarray, names: list[str], fragment: str
) -> None:
    with pytest.raises(loco.ParameterError) as info:
        loco.run_batch(params, names, scenario=SCENARIO, progress=False)
    assert fragment in str(info.value)


def test_bad_options_raise() -> None:
    with pytest.raises(loco.ParameterError, match="threads"):
        loco.run_batch(np.ones((1, 1)) * 8e5, ["C_sx"], threads=-1, progress=False)
    with pytest.raises(loco.ParameterError, match="seed"):
        loco.run_batch(np.ones((1, 1)) * 8e5, ["C_sx"], seed=-1, progress=False)
    with pytest.raises(loco.ParameterError, match="histories"):
        loco.run_batch(np.ones((1, 1)) * 8e5, ["C_sx"], histories=[4], progress=False)


def test_threads_zero_is_one_per_core_as_in_the_binary() -> None:
    # `loco-batch --threads 0` and `run_batch(threads=0)`: one thread per core, same numbers.
    scenario = loco.Scenario(name="S_high", distance=20.0)
    x = np.array([[8e5], [2e5]])
    per_core = loco.run_batch(x, ["C_sx"], scenario=scenario, threads=0, progress=False)
    one = loco.run_batch(x, ["C_sx"], scenario=scenario, threads=1, progress=False)
    assert per_core.n_failed == 0
    assert np.array_equal(per_core.metrics, one.metrics, equal_nan=True)


def test_ctrl_c_stops_the_batch_promptly() -> None:
    params = np.full((16, 1), 8e5)
    scenario = loco.Scenario(name="S_high", distance=2000.0)  # ~36 s of simulated time each

    def interrupt() -> None:
        time.sleep(1.0)
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=interrupt, daemon=True).start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        loco.run_batch(params, ["C_sx"], scenario=scenario, threads=2, progress=False)
    # 16 runs of ~2 s each on 2 threads would take ~16 s; a prompt stop takes ~1 s.
    assert time.perf_counter() - start < 6.0


def test_progress_callback_sees_every_sample() -> None:
    seen: list[tuple[int, int]] = []
    loco._loco.run_batch(
        loco.Locomotive.default().native,
        SCENARIO.native(),
        np.array([[8e5], [2e5]]),
        ["C_sx"],
        progress=lambda done, failed: seen.append((done, failed)),
    )
    assert seen[-1] == (2, 0)
