"""The study's quantities, named once: the scenarios, the channels the core computes each
quantity's metrics on, and the run metrics of each quantity's PSD peak and rms. The speed sweep,
the damper comparison and their figures all read them from here.

- W_y: the Sperling lateral ride index (metric ``wy_max``);
- A_yb: the bogie frame lateral acceleration (m/s²), channel ``METRIC_CHANNELS["A_yb"]``;
- A_yc: the carbody floor lateral acceleration (m/s²), channel ``METRIC_CHANNELS["A_yc"]``.
"""

from __future__ import annotations

import loco
from loco import _loco, metrics
from loco.channels import Metric
from loco.studies.plotting import Spectrum

__all__ = [
    "A_YB",
    "A_YC",
    "CHANNELS",
    "METRIC_CHANNELS",
    "PEAK_METRICS",
    "RMS_METRICS",
    "SCENARIOS",
    "spectrum",
]

#: The three wheel states of SPEC §2.
SCENARIOS: tuple[str, ...] = ("S_low", "S_norm", "S_high")
#: Channel of each quantity whose metrics the core computes (``A_yc``, ``A_zc``, ``A_yb``), as the
#: core names it.
METRIC_CHANNELS: dict[str, str] = dict(_loco.metric_channels())
#: (label, channel) of the carbody floor lateral acceleration A_yc.
A_YC: tuple[str, str] = ("A_yc", METRIC_CHANNELS["A_yc"])
#: (label, channel) of the bogie frame lateral acceleration A_yb.
A_YB: tuple[str, str] = ("A_yb", METRIC_CHANNELS["A_yb"])
#: Channel of each quantity of the sweep's spectra.
CHANNELS: dict[str, str] = dict((A_YC, A_YB))
#: Run metrics (the core's) of the PSD peak of each quantity: (dominant frequency Hz, PSD peak
#: (m/s²)²/Hz). A_yc is searched over 0.2-20 Hz, A_yb over the EN 14363 f0 band.
PEAK_METRICS: dict[str, tuple[str, str]] = {
    "A_yc": (Metric.AYC_DOMINANT_HZ, Metric.AYC_PSD_PEAK),
    "A_yb": (Metric.AYB_F0_HZ, Metric.AYB_PSD_PEAK),
}
#: Run metric of the rms of each quantity, m/s².
RMS_METRICS: dict[str, str] = {"A_yc": Metric.AYC_RMS, "A_yb": Metric.AYB_RMS}


def spectrum(result: loco.SimulationResult, quantity: str) -> Spectrum:
    """The :class:`Spectrum` of ``quantity`` (``"A_yc"`` or ``"A_yb"``) of a run: the Welch PSD of
    its channel by :func:`loco.metrics.psd` (for the curves), its peak from the run's metrics
    (:data:`PEAK_METRICS`)."""
    f, p = metrics.psd(result.channel(CHANNELS[quantity]), result.sampling_rate)
    frequency, peak = PEAK_METRICS[quantity]
    return Spectrum(f, p, result.metrics[frequency], result.metrics[peak])
