"""Frequency response and linear output PSDs of the linearised vehicle: the measured-
track CSV input path against the transfer function, the PSD bookkeeping, typed errors, the CLI.
The full time-domain verification matrix is in
crates/loco-core/tests/verification/frequency_response.rs."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import loco
import loco.track_response
from loco.cli import main

SPEED = 200.0 / 3.6
AMPLITUDE_MM = 0.2


@pytest.fixture(scope="module")
def vehicle() -> loco.Locomotive:
    return loco.Locomotive.default()


def _sine_csv(path: Path, wavelength: float, length: float) -> Path:
    s = np.arange(0.0, length, 0.1)
    zero = np.zeros_like(s)
    alignment = AMPLITUDE_MM * np.sin(2 * np.pi * s / wavelength)
    np.savetxt(
        path,
        np.column_stack([s, zero, alignment, zero, zero]),
        delimiter=",",
        header="distance,vertical,alignment,cross_level,gauge",
        comments="",
    )
    return path


def test_measured_csv_sine_matches_the_transfer_function(
    vehicle: loco.Locomotive, tmp_path: Path
) -> None:
    # 0.2 mm alignment at 70 m, S_low with YD2, 200 km/h: after 16 s the transient has gone;
    # fit a sinusoid over 4 whole periods and compare with H times the input at the origin.
    wavelength, settle = 70.0, 16.0
    f = SPEED / wavelength
    fit = 4.0 / f
    csv = _sine_csv(tmp_path / "sine.csv", wavelength, SPEED * (settle + fit) + 80.0)
    track = loco.track.load(str(csv), step=0.1, run_in=60.0)
    scenario = loco.Scenario(
        name="S_low",
        yaw_damper=loco.dampers.YD2,
        track=track,
        lead_in=settle * SPEED,
        distance=fit * SPEED,
    )
    run = loco.simulate(vehicle, scenario)
    outputs = ["wheelset1_y", "frame1_ay_wheelset1", "carbody_floor_ay_front"]
    h = loco.frequency_response(vehicle, scenario, ["alignment"], outputs, [f])
    omega, k = 2 * np.pi * f, 2 * np.pi / wavelength
    t = run.time + round(settle / scenario.step) * scenario.step
    # The leading wheelset starts at s = 0: the origin is at s = V t − x_1.
    u0 = -1j * AMPLITUDE_MM * 1e-3 * np.exp(-1j * k * h.wheelset_x[0])
    basis = np.column_stack([np.cos(omega * t), np.sin(omega * t), np.ones_like(t)])
    for o, name in enumerate(outputs):
        a, b, _ = np.linalg.lstsq(basis, run.channel(name), rcond=None)[0]
        measured = complex(a, -b)
        ratio = measured / (h.h[o, 0, 0] * u0)
        assert abs(abs(ratio) - 1.0) < 0.05, (name, abs(ratio))
        assert abs(np.degrees(np.angle(ratio))) < 5.0, (name, np.degrees(np.angle(ratio)))


def test_frequency_response_views_and_plot(vehicle: loco.Locomotive, tmp_path: Path) -> None:
    scenario = loco.Scenario(name="S_norm")
    f = np.linspace(0.2, 10.0, 25)
    h = loco.frequency_response(vehicle, scenario, frequencies=f)
    assert h.h.shape == (len(loco.track_response.DEFAULT_OUTPUTS), 4, 25)
    assert h.h.dtype == np.complex128
    assert h.inputs == ["vertical", "alignment", "cross_level", "gauge"]
    assert repr(h).startswith("FrequencyResponse(speed=55.5556 m/s, ")
    assert repr(h).endswith("4 inputs, 25 frequencies 0.2–10 Hz)")
    da = h.to_xarray()
    assert da.dims == ("output", "input", "frequency")
    np.testing.assert_array_equal(h.transfer("wheelset1_y", "alignment"), h.h[2, 1])
    # Symmetric inputs leave the lateral motion alone (to the finite-difference noise).
    assert np.max(np.abs(h.transfer("wheelset1_y", "vertical"))) < 1e-6
    h.plot(tmp_path / "frf.png")
    assert (tmp_path / "frf.png").stat().st_size > 0
    with pytest.raises(loco.ParameterError, match="output"):
        h.transfer("nope", "alignment")


def test_response_psd_bookkeeping(vehicle: loco.Locomotive) -> None:
    scenario = loco.Scenario(name="S_norm")
    f = np.linspace(0.2, 20.0, 100)
    full = loco.response_psd(vehicle, scenario, ["carbody_floor_ay_front"], f)
    half = loco.response_psd(vehicle, scenario, ["carbody_floor_ay_front"], f, amplitude_scale=0.5)
    np.testing.assert_allclose(half.psd, 0.25 * full.psd, rtol=1e-12)
    assert repr(full).startswith(f"ResponsePsd(spectrum={full.spectrum!r}, 1 outputs, W_y=")
    rms = np.sqrt(np.trapezoid(full.psd[0], f))
    assert full.rms["carbody_floor_ay_front"] == pytest.approx(rms, rel=1e-12)
    # The PSD is the sum over the independent channels of |H|² times the temporal input PSD.
    h = loco.frequency_response(vehicle, scenario, None, ["carbody_floor_ay_front"], f)
    phi = f / scenario.speed
    in_band = (phi >= 1 / scenario.band[1]) & (phi <= 1 / scenario.band[0])
    expected = in_band * sum(
        np.abs(h.h[0, i]) ** 2 * loco.track.target_psd("cn-hsr", c, phi) / scenario.speed
        for i, c in enumerate(h.inputs)
    )
    assert not in_band[0] and full.psd[0, 0] == 0.0
    np.testing.assert_allclose(full.psd[0], expected, rtol=1e-9)
    # W_y scales as A^0.3 with the amplitude: (0.5)^0.3.
    assert half.sperling_lateral / full.sperling_lateral == pytest.approx(0.5**0.3, rel=1e-9)
    assert "rms_carbody_floor_ay_front" in full.to_xarray().attrs
    assert full.stable and full.least_damping_ratio > 0.0
    # Worn wheels with the soft yaw damper hunt at 200 km/h (see test_stability.py).
    hunting = loco.response_psd(
        vehicle, loco.Scenario(name="S_high", yaw_damper=loco.dampers.YD1), frequencies=f
    )
    assert not hunting.stable


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"outputs": ["no_such_channel"]}, "no_such_channel"),
        ({"inputs": ["twist"]}, "twist"),
        ({"frequencies": [1.0, -2.0]}, r"frequencies\[1\]"),
        ({"frequencies": [0.0]}, r"frequencies\[0\]"),
        ({"frequencies": [1.0, float("nan")]}, r"frequencies\[1\]"),
        ({"frequencies": [[1.0, 2.0]]}, "one-dimensional"),
        ({"inputs": []}, "inputs"),
    ],
)
def test_bad_inputs_raise_typed_errors(
    vehicle: loco.Locomotive, kwargs: dict[str, object], match: str
) -> None:
    args: dict[str, object] = {"frequencies": [1.0, 2.0]} | kwargs
    with pytest.raises(loco.ParameterError, match=match):
        loco.frequency_response(vehicle, loco.Scenario(name="S_norm"), **args)  # type: ignore[arg-type]


def test_response_psd_rejects_a_bad_spectrum_and_band(vehicle: loco.Locomotive) -> None:
    scenario = loco.Scenario(name="S_norm")
    with pytest.raises(loco.ParameterError, match="spectrum"):
        loco.response_psd(vehicle, scenario, frequencies=[1.0], spectrum="nope")
    with pytest.raises(loco.ParameterError, match=r"`band`: \(50, 10\) m"):
        loco.response_psd(vehicle, scenario, frequencies=[1.0], band=(50.0, 10.0))


def test_cli_writes_plots_and_data(tmp_path: Path) -> None:
    out = tmp_path / "frf"
    assert main(["frf", "--out", str(out), "--scenario", "S_norm", "--n", "20"]) == 0
    for name in ("frf.png", "frf_psd.png", "frf.csv", "frf_psd.csv", "frf_summary.csv"):
        assert (out / name).stat().st_size > 0, name
    import pandas as pd

    table = pd.read_csv(out / "frf.csv")
    assert len(table) == 20 * 4 * 3
    summary = pd.read_csv(out / "frf_summary.csv")
    assert np.isfinite(summary["value"]).all()


def test_figures_carry_each_outputs_unit_and_leave_the_symmetric_noise_out(
    vehicle: loco.Locomotive,
) -> None:
    scenario = loco.Scenario(name="S_low", speed=SPEED, yaw_damper="YD2")
    f = np.linspace(0.5, 15.0, 30)
    h = loco.frequency_response(vehicle, scenario, frequencies=f)
    assert h.units == {
        "carbody_floor_ay_front": "m/s²",
        "frame1_ay_wheelset1": "m/s²",
        "wheelset1_y": "m",
    }
    for out in h.outputs:
        # Left/right symmetry: vertical and gauge irregularities drive no lateral motion.
        assert h.is_noise(out, "vertical") and h.is_noise(out, "gauge")
        assert not h.is_noise(out, "alignment") and not h.is_noise(out, "cross_level")
    fig = h.plot()
    top = fig.axes[: len(h.outputs)]  # the |H| row (the phases below)
    labels = [ax.get_ylabel() for ax in top]
    assert labels == ["|H| ((m/s²)/m)", "|H| ((m/s²)/m)", "|H| (m/m)"]
    for ax in top:
        assert sorted(line.get_label() for line in ax.get_lines()) == ["alignment", "cross_level"]
        assert "not drawn: vertical, gauge" in " ".join(t.get_text() for t in ax.texts)
    psd = loco.response_psd(vehicle, scenario, frequencies=f)
    fig = psd.plot()
    assert [ax.get_ylabel() for ax in fig.axes] == [
        "PSD ((m/s²)²/Hz)",
        "PSD ((m/s²)²/Hz)",
        "PSD (m²/Hz)",
    ]
