"""One case of a study run on several synthesised tracks, as one batch with the tracks as samples.

Track ``j`` of a study is ChaCha stream ``j`` of the track seed (``loco.run_batch(...,
per_sample_track=True)``: sample ``j`` gets stream ``j``; stream 0 is the track a single run of that
seed gets). Every case of every stage runs on tracks ``0 … n-1``, so the cases compared (dampers,
speeds, scenarios) share their tracks: common random numbers, which the paired tests of
:mod:`loco.studies.statistics` rely on.

The spectra of a case are the mean over its tracks of the per-track Welch PSDs
(:func:`loco.metrics.psd`, same record length so the same frequencies); their dominant frequency
and peak are the means of the core's per-track run metrics, whose intervals the study tables give.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

import loco
from loco import metrics as _metrics
from loco.batch import SPEED, run_batch
from loco.studies.plotting import Spectrum
from loco.studies.statistics import Interval, geometric_interval, mean_interval, median_values

__all__ = ["TrackRuns", "run_over_tracks"]

FloatArray = npt.NDArray[np.float64]

#: (label, channel, (dominant frequency metric, PSD peak metric)) of a spectrum to average.
SpectrumSpec = tuple[str, str, tuple[str, str]]


@dataclass(frozen=True)
class TrackRuns:
    """One case run on tracks ``0 … n-1``.

    ``metrics`` (n, m) has columns ``metric_names`` (the core's run metrics) plus the names of the
    ``derived`` values, NaN where the run on that track failed (``status`` != 0, reason in
    ``messages``). ``first`` is the time history on track 0 (None when not kept or failed);
    ``spectra`` the track-mean spectra by label (absent when no track finished).
    """

    metric_names: list[str]
    metrics: FloatArray
    status: npt.NDArray[np.int64]
    messages: list[str]
    first: loco.SimulationResult | None = None
    spectra: dict[str, Spectrum] = field(default_factory=dict)

    @property
    def n_tracks(self) -> int:
        """Number of tracks run."""
        return len(self.status)

    def values(self, name: str) -> FloatArray:
        """Per-track values of metric ``name``, shape (n,)."""
        return np.asarray(self.metrics[:, self.metric_names.index(name)], dtype=np.float64)

    def interval(self, name: str) -> Interval:
        """Mean and 95 % interval of metric ``name`` over the tracks that finished."""
        return mean_interval(self.values(name))


def run_over_tracks(
    scenario: loco.Scenario,
    n_tracks: int,
    *,
    vehicle: loco.Locomotive | None = None,
    threads: int | None = None,
    progress: bool = True,
    spectra: tuple[SpectrumSpec, ...] = (),
    keep_first: bool = False,
    derived: Mapping[str, Callable[[loco.SimulationResult], float]] | None = None,
) -> TrackRuns:
    """Run ``scenario`` on tracks ``0 … n_tracks-1`` (one ``loco.run_batch``, the tracks as
    samples).

    ``spectra`` are the channels whose track-mean PSD is kept; ``keep_first`` keeps the time
    history of track 0; ``derived`` computes more per-track values from each history (e.g. the
    fraction of time a valve was closed). Histories are only kept while they are needed.
    """
    if n_tracks < 1:
        raise loco.ParameterError(f"invalid parameter `n_tracks`: must be >= 1, got {n_tracks}")
    derived = dict(derived or {})
    need_all = bool(spectra or derived)
    keep = tuple(range(n_tracks)) if need_all else ((0,) if keep_first else ())
    batch = run_batch(
        np.full((n_tracks, 1), scenario.speed),
        [SPEED],
        vehicle=vehicle,
        scenario=scenario,
        threads=threads,
        progress=progress,
        histories=keep,
        per_sample_track=True,
    )
    values = np.asarray(batch.metrics, dtype=np.float64)
    extra = np.full((n_tracks, len(derived)), np.nan)
    densities: dict[str, list[FloatArray]] = {label: [] for label, _, _ in spectra}
    frequency: dict[str, FloatArray] = {}
    for i, history in batch.histories.items():
        for k, fn in enumerate(derived.values()):
            extra[i, k] = fn(history)
        for label, channel, _ in spectra:
            f, p = _metrics.psd(history.channel(channel), history.sampling_rate)
            frequency[label] = f
            densities[label].append(p)
    names = [*batch.metric_names, *derived]
    table = np.hstack([values, extra])
    mean_spectra = {}
    for label, _, (dominant, peak) in spectra:
        if densities[label]:
            column = table[:, names.index(dominant)], table[:, names.index(peak)]
            mean_spectra[label] = Spectrum(
                frequency[label],
                np.mean(densities[label], axis=0),
                median_values(column[0])[0],
                geometric_interval(column[1]).mean,
            )
    return TrackRuns(
        metric_names=names,
        metrics=table,
        status=np.asarray(batch.status, dtype=np.int64),
        messages=[str(m) for m in batch.messages],
        first=batch.histories.get(0) if keep_first else None,
        spectra=mean_spectra,
    )
