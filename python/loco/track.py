"""Track irregularities: synthesis from a target spectrum, measured files, plots.

Units are SI: distances in m, irregularities in m, spectra in m²/(1/m) over spatial frequency
in 1/m. Measured files are CSV with distance (m) and the four irregularities in mm (vertical,
alignment, cross_level, gauge); the loader converts them to m.

Spectra: ``"cn-hsr"`` (TB/T 3352-2014, Chinese high-speed ballastless track), ``"german-low"``
and ``"german-high"`` (German low/high-interference spectra). See ``loco_core::track`` for the
formulas, conventions and sources.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from loco import _loco

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["CHANNELS", "RAILS", "SPECTRA", "Track", "load", "synthetic", "target_psd"]

CHANNELS = ("vertical", "alignment", "cross_level", "gauge")
RAILS = ("y_left", "z_left", "y_right", "z_right")
SPECTRA = ("cn-hsr", "german-low", "german-high")

FloatArray = npt.NDArray[np.float64]


class Track:
    """A track irregularity on a uniform grid, as the vehicle model sees it."""

    def __init__(self, native: _loco.Track) -> None:
        self._native = native

    @property
    def native(self) -> _loco.Track:
        """The native object (for passing to simulations)."""
        return self._native

    @property
    def length(self) -> float:
        """Length covered by the data, m."""
        return self._native.length

    @property
    def step(self) -> float:
        """Grid step, m."""
        return self._native.step

    @property
    def run_in(self) -> float:
        """Length of the cosine run-in at the start, m."""
        return self._native.run_in

    @property
    def spectrum(self) -> str | None:
        """Target spectrum of a synthesised track, None for a measured one."""
        return self._native.spectrum

    @property
    def distance(self) -> FloatArray:
        """Distances of the grid nodes, m."""
        return self._native.distance()

    @property
    def vertical(self) -> FloatArray:
        """Vertical profile (mean of both rails, + up), m."""
        return self._native.channel("vertical")

    @property
    def alignment(self) -> FloatArray:
        """Alignment (mean of both rails, + left), m."""
        return self._native.channel("alignment")

    @property
    def cross_level(self) -> FloatArray:
        """Cross level (left rail height minus right), m."""
        return self._native.channel("cross_level")

    @property
    def gauge(self) -> FloatArray:
        """Gauge deviation (+ wider), m."""
        return self._native.channel("gauge")

    def channel(self, name: str) -> FloatArray:
        """One of ``CHANNELS`` at the grid nodes, m."""
        return self._native.channel(name)

    def rail(self, name: str) -> FloatArray:
        """One of ``RAILS`` (rail lateral y / vertical z positions) at the grid nodes, m."""
        return self._native.rail(name)

    def at(
        self, s: float
    ) -> tuple[tuple[float, float, float, float], tuple[float, float, float, float]]:
        """Rail irregularities at distance ``s`` (m): ``(y_left, z_left, y_right, z_right)``
        in m and their derivatives d/ds (m/m) in the same order."""
        return self._native.at(s)

    def psd(self, name: str, segment_length: float = 400.0) -> tuple[FloatArray, FloatArray]:
        """Welch PSD of a channel: (spatial frequency 1/m, PSD m²/(1/m)).

        Hann segments of ``segment_length`` m (clipped to the track), 50 % overlap; the run-in
        is excluded so that the taper does not bias the estimate.
        """
        x = self.channel(name)
        start = min(int(np.ceil(self.run_in / self.step)), len(x) - 16)
        x = x[start:]
        n = max(16, min(len(x), round(segment_length / self.step)))
        return _loco.welch_psd(x, 1.0 / self.step, segment_len=n)

    def plot(self, segment_length: float = 400.0) -> Figure:
        """Figure of the four irregularities and their PSDs against the target spectrum."""
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(4, 2, figsize=(11, 10), constrained_layout=True)
        for row, name in enumerate(CHANNELS):
            ax_t, ax_f = axes[row]
            ax_t.plot(self.distance, self.channel(name) * 1e3, lw=0.6)
            ax_t.set_ylabel(f"{name} (mm)")
            f, p = self.psd(name, segment_length)
            keep = f > 0
            ax_f.loglog(f[keep], p[keep], lw=0.8, label="Welch PSD")
            if self.spectrum is not None:
                ax_f.loglog(
                    f[keep], target_psd(self.spectrum, name, f[keep]), "k--", label=self.spectrum
                )
            ax_f.set_ylabel("PSD (m²/(1/m))")
            ax_f.legend(fontsize="small")
        axes[-1][0].set_xlabel("distance (m)")
        axes[-1][1].set_xlabel("spatial frequency (1/m)")
        return fig

    def __repr__(self) -> str:
        return repr(self._native)


def synthetic(
    spectrum: str = "cn-hsr",
    length: float = 1000.0,
    seed: int = 0,
    band: tuple[float, float] = (2.0, 200.0),
    *,
    step: float = 0.1,
    run_in: float = 30.0,
    stream: int = 0,
) -> Track:
    """Synthesises ``length`` m of track from ``spectrum`` over the wavelength ``band`` (m).

    Reproducible bit for bit from (``seed``, ``stream``) and the other arguments; a batch can
    give run i the stream i.
    """
    if seed < 0 or stream < 0:
        raise _loco.ParameterError(
            f"invalid parameter `seed`/`stream`: must be >= 0, got {seed}/{stream}"
        )
    lo, hi = band
    native = _loco.synthesize_track(spectrum, length, seed, stream, lo, hi, step, run_in)
    return Track(native)


def load(
    path: str, *, step: float | None = None, run_in: float = 30.0, length: float | None = None
) -> Track:
    """Reads a measured irregularity CSV (distance m, vertical, alignment, cross_level,
    gauge in mm; UTF-8, a byte-order mark skipped), resampled to ``step`` m (default: the file's
    median spacing). ``length`` (m): raise if the file is shorter than the run needs.

    Raises :class:`loco.TrackFormatError` naming the file and line for a file that is not UTF-8,
    a first row with a number and a field that is not one (a header has no numbers), a gap
    between rows longer than 10 times the median spacing, distances that do not increase; and
    :class:`loco.ParameterError` for a ``run_in`` longer than the file."""
    return Track(_loco.load_track(str(path), step, run_in, length))


def target_psd(spectrum: str, channel: str, f: npt.ArrayLike) -> FloatArray:
    """Target one-sided PSD (m²/(1/m)) of ``channel`` at spatial frequencies ``f`` (1/m)."""
    return _loco.track_spectrum_psd(spectrum, channel, np.ascontiguousarray(f, dtype=np.float64))
