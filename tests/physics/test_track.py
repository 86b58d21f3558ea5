"""Track irregularities: synthesis against its target spectrum, determinism, measured files."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import loco
from loco import _loco, track
from verification_records import record


def test_synthetic_is_reproducible_from_seed_and_stream() -> None:
    a = track.synthetic("cn-hsr", length=500.0, seed=42)
    b = track.synthetic("cn-hsr", length=500.0, seed=42)
    c = track.synthetic("cn-hsr", length=500.0, seed=42, stream=1)
    for name in track.CHANNELS:
        np.testing.assert_array_equal(a.channel(name), b.channel(name))
    assert not np.array_equal(a.vertical, c.vertical)
    assert a.spectrum == "cn-hsr"
    assert a.length >= 500.0


def test_rms_matches_integral_of_spectrum() -> None:
    # Without run-in and over one FFT period (8192 points of 0.1 m) the mean square is the sum
    # of the component variances, i.e. the band integral of the target spectrum.
    t = track.synthetic("german-high", length=819.1, seed=5, run_in=0.0)
    worst = 0.0
    for name in track.CHANNELS:
        x = t.channel(name)
        target = _loco.track_spectrum_variance("german-high", name, 1 / 200, 1 / 2)
        assert np.mean(x**2) == pytest.approx(target, rel=2e-3)
        worst = max(worst, abs(np.mean(x**2) / target - 1))
    record("track_rms", __file__).within("mean_square", worst, "", 2, "<", 2e-3).check()


def test_welch_psd_follows_target_across_the_band() -> None:
    # 20 km, 400 m segments: ~99 averages; octave-band sums within 3 sigma (K/2 effective).
    t = track.synthetic("cn-hsr", length=20_000.0, seed=3)
    worst, bands = 0.0, 0
    for name in track.CHANNELS:
        f, p = t.psd(name, segment_length=409.6)
        k = len(t.vertical) * t.step / 409.6 * 2 - 1
        for lo in (0.01, 0.02, 0.04, 0.08, 0.16):
            band = (f >= lo) & (f < 2 * lo)
            measured = p[band].sum()
            target = track.target_psd("cn-hsr", name, f[band]).sum()
            tol = 3 / np.sqrt(k * band.sum() / 2)
            assert measured / target == pytest.approx(1.0, abs=tol), (name, lo)
            worst, bands = max(worst, abs(measured / target - 1) / tol), bands + 1
    (
        record("track_welch_psd", __file__)
        .count("octave_bands", bands)
        .within("largest_deviation_in_3_sigma", worst, "", 2, "≤", 1.0)
        .check()
    )


def test_run_in_and_rails() -> None:
    t = track.synthetic("cn-hsr", length=300.0, seed=1, run_in=30.0)
    (y_l, z_l, y_r, z_r), slopes = t.at(0.0)
    assert (y_l, z_l, y_r, z_r) == (0.0, 0.0, 0.0, 0.0)
    assert slopes == (0.0, 0.0, 0.0, 0.0)
    # Rails from channels: z_left - z_right is the cross level, y_left - y_right the gauge.
    np.testing.assert_allclose(t.rail("z_left") - t.rail("z_right"), t.cross_level, atol=1e-15)
    np.testing.assert_allclose(t.rail("y_left") - t.rail("y_right"), t.gauge, atol=1e-15)
    # The vehicle sees the interpolated rails; at a node they equal the stored values.
    i = 1234
    (_, z_l, _, _), _ = t.at(t.distance[i])
    assert z_l == pytest.approx(t.rail("z_left")[i], abs=1e-12)


def test_bad_arguments_raise_parameter_errors() -> None:
    with pytest.raises(loco.ParameterError, match="spectrum"):
        track.synthetic("us-class-6", length=100.0)
    with pytest.raises(loco.ParameterError, match="wavelength_max"):
        track.synthetic(length=100.0, band=(50.0, 20.0))
    with pytest.raises(loco.ParameterError, match="length"):
        track.synthetic(length=-1.0)
    with pytest.raises(loco.ParameterError, match="grid points"):
        track.synthetic(length=100.0, band=(2.0, 1e12))
    with pytest.raises(loco.ParameterError, match="seed"):
        track.synthetic(length=100.0, seed=-1)


def test_measured_file_round_trip(tmp_path: Path) -> None:
    s = np.arange(0.0, 200.0, 0.25)
    vertical_mm = 2.0 * np.sin(2 * np.pi * s / 40.0)
    data = np.column_stack([s + 1000.0, vertical_mm, 0 * s, 0 * s, 0.5 + 0 * s])
    path = tmp_path / "track.csv"
    np.savetxt(path, data, delimiter=",", header="distance,vertical,alignment,cross_level,gauge")
    t = track.load(str(path), run_in=0.0)
    assert t.step == pytest.approx(0.25)
    assert t.spectrum is None
    np.testing.assert_allclose(t.vertical, vertical_mm * 1e-3, atol=1e-12)
    np.testing.assert_allclose(t.gauge, 0.5e-3, atol=1e-15)
    with pytest.raises(loco.ParameterError, match="needs 500"):
        track.load(str(path), length=500.0)


def test_malformed_files_name_file_and_line(tmp_path: Path) -> None:
    path = tmp_path / "bad.csv"
    path.write_text("0,1,2,3,4\n1,1,2,3,4\n0.5,1,2,3,4\n")
    with pytest.raises(loco.TrackFormatError, match=r"bad.csv:3:.*does not increase"):
        track.load(str(path))
    path.write_text("0,1,2,3,4\n1,nan,2,3,4\n")
    with pytest.raises(loco.TrackFormatError, match=r"bad.csv:2:.*vertical"):
        track.load(str(path))
    with pytest.raises(loco.LocoIOError):
        track.load(str(tmp_path / "missing.csv"))


def test_a_first_row_is_data_unless_it_has_no_number_and_a_bom_is_skipped(
    tmp_path: Path,
) -> None:
    rows = "".join(f"{0.5 * i},{i % 3},0,0,0\n" for i in range(100))
    plain, bom, typo = (tmp_path / n for n in ("plain.csv", "bom.csv", "typo.csv"))
    plain.write_text(rows)
    bom.write_bytes(b"\xef\xbb\xbf" + rows.encode())
    a, b = (track.load(str(p), run_in=0.0) for p in (plain, bom))
    # The byte-order mark is not read as a header: the first row (vertical 0 mm at 0 m) is kept.
    assert a.length == b.length == pytest.approx(49.5)
    np.testing.assert_array_equal(a.vertical, b.vertical)
    typo.write_text("0,1,2x,0,0\n" + rows)
    with pytest.raises(loco.TrackFormatError, match=r"typo.csv:1: not a number"):
        track.load(str(typo))
    gap = tmp_path / "gap.csv"
    gap.write_text(rows + "10049.5,0,0,0,0\n")
    with pytest.raises(loco.TrackFormatError, match=r"gap.csv:101: a gap of 10000.000 m"):
        track.load(str(gap))
    with pytest.raises(loco.ParameterError, match="`run_in`"):
        track.load(str(plain), run_in=60.0)


def test_plot_draws_psd_against_target() -> None:
    import matplotlib

    matplotlib.use("Agg")
    t = track.synthetic("german-low", length=2000.0, seed=2)
    fig = t.plot()
    assert len(fig.axes) == 8
    assert len(fig.axes[1].lines) == 2
