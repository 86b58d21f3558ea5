"""The vehicle's frequency response to track irregularities and its output spectra on a random
track (the classic linear stochastic method), from the model linearised about its static
equilibrium at the scenario's speed with the track as an input.

- :func:`frequency_response` gives complex transfer functions ``H[output][input](f)`` from the
  irregularity channels (``vertical``, ``alignment``, ``cross_level``, ``gauge``; m) to any
  channel a run records (:attr:`loco.SimulationResult.channel_names`; their SI units), per m of
  irregularity at the vehicle origin: the wheelsets see the input delayed by their positions,
  ``e^{ik x_w}`` with ``k = 2πf/V``. ``z(t) = Re(H U e^{iωt})`` for ``u(s) = Re(U e^{iks})``.
- :func:`response_psd` gives one-sided output PSDs (unit²/Hz), their rms over the frequency
  grid and the Sperling index W_y of the carbody floor from the four channels of a track
  spectrum (independent, limited to the wavelength band; spatial PSD ``S(φ)`` seen as
  ``S(f/V)/V``). W_y applies the project's Sperling definition to the expected power of a 5 s
  segment, ``P_k = S(f_k)·Δf`` (Δf = 0.2 Hz), cut into lines at its local minima (a line's
  amplitude ``A = √(2E)`` from its energy E), as the time-domain metric cuts a recorded segment.

The response is that of the linear model: meaningful as a steady state where the vehicle is
linearly stable (:func:`loco.eigen`). The FSD damper is linearised with its valve in its start
state, as in the eigenvalue analysis.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Final

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco.channels import channel_table
from loco.field_types import names, pair, real, real_array, text
from loco.simulation import Scenario
from loco.vehicle import Locomotive

#: The irregularity channels, from the core.
INPUTS: tuple[str, ...] = tuple(_loco.irregularity_channels())
#: Default outputs: the channels the ride and stability metrics use, from the core.
DEFAULT_OUTPUTS: tuple[str, ...] = (
    _loco.metric_channels()["A_yc"],
    _loco.metric_channels()["A_yb"],
    "wheelset1_y",
)


#: A coupling whose largest |H| is below this fraction of the output's largest response is the
#: numerical noise of the left/right symmetric model, not physics: vertical and gauge
#: irregularities drive no lateral motion there, and the central differences of the
#: linearisation leave them at 1e-9 to 1e-12 of the alignment response
#: (``crates/loco-core/tests/verification/frequency_response.rs`` asserts < 1e-8). The figures
#: leave such couplings out and say so; the data keep them.
NOISE_RATIO: Final = 1e-6


def per_metre(unit: str) -> str:
    """The unit of a transfer function from an irregularity (m) to an output of ``unit``."""
    return f"({unit})/m" if "/" in unit else f"{unit}/m"


def squared_per_hertz(unit: str) -> str:
    """The unit of a PSD of an output of ``unit``."""
    return f"({unit})²/Hz" if "/" in unit else f"{unit}²/Hz"


def _output_units(vehicle: Locomotive, outputs: Sequence[str]) -> dict[str, str]:
    units = {c.name: c.unit for c in channel_table(vehicle.native)}
    return {o: units.get(o, "") for o in outputs}


def _frequencies(frequencies: npt.ArrayLike | None) -> npt.NDArray[np.float64]:
    if frequencies is None:
        return np.linspace(0.1, 20.0, 200)
    f = real_array("frequencies", frequencies)
    if f.ndim != 1:
        raise _loco.ParameterError(
            f"invalid parameter `frequencies`: must be one-dimensional, got shape {f.shape}"
        )
    return np.ascontiguousarray(f)


@dataclass(frozen=True)
class FrequencyResponse:
    """Complex transfer functions ``h[output, input, frequency]`` (output unit per m)."""

    frequencies: npt.NDArray[np.float64]
    inputs: list[str]
    outputs: list[str]
    h: npt.NDArray[np.complex128]
    speed: float
    #: Longitudinal position of each wheelset ahead of the vehicle origin, m.
    wheelset_x: tuple[float, ...] = ()
    #: SI unit of each output, by name.
    units: dict[str, str] = field(default_factory=dict)

    def __repr__(self) -> str:
        f = self.frequencies
        band = f"{f[0]:g}–{f[-1]:g} Hz" if len(f) else "no frequencies"
        return (
            f"FrequencyResponse(speed={self.speed:g} m/s, {len(self.outputs)} outputs × "
            f"{len(self.inputs)} inputs, {len(f)} frequencies {band})"
        )

    def transfer(self, output: str, channel: str) -> npt.NDArray[np.complex128]:
        """H from irregularity ``channel`` to ``output`` over the frequencies."""
        if output not in self.outputs:
            raise _loco.ParameterError(
                f"invalid parameter `output`: no output '{output}'; available: {self.outputs}"
            )
        if channel not in self.inputs:
            raise _loco.ParameterError(
                f"invalid parameter `channel`: no input '{channel}'; available: {self.inputs}"
            )
        return self.h[self.outputs.index(output), self.inputs.index(channel)]

    def is_noise(self, output: str, channel: str) -> bool:
        """Whether the coupling from ``channel`` to ``output`` is below :data:`NOISE_RATIO` of
        the output's largest response over every input and frequency (numerical noise)."""
        largest = float(np.max(np.abs(self.h[self.outputs.index(output)]), initial=0.0))
        return bool(
            np.max(np.abs(self.transfer(output, channel)), initial=0.0) < NOISE_RATIO * largest
        )

    def to_xarray(self) -> Any:
        """``xarray.DataArray`` on (output, input, frequency)."""
        import xarray

        return xarray.DataArray(
            self.h,
            dims=("output", "input", "frequency"),
            coords={"output": self.outputs, "input": self.inputs, "frequency": self.frequencies},
            attrs={"speed_mps": self.speed, "loco_version": _loco.__version__},
            name="H",
        )

    def plot(self, path: str | Path | None = None) -> Any:
        """|H| (log) and phase (deg) against frequency, one panel pair per output; saved as PNG
        when ``path`` is given. Returns the figure."""
        from loco.studies.plotting import pyplot, save_figure

        fig, axes = pyplot().subplots(
            2, len(self.outputs), figsize=(4.2 * len(self.outputs), 6.5), squeeze=False
        )
        for o, out in enumerate(self.outputs):
            noise = [name for name in self.inputs if self.is_noise(out, name)]
            for i, name in enumerate(self.inputs):
                if name in noise:
                    continue
                h = self.h[o, i]
                axes[0][o].semilogy(self.frequencies, np.abs(h), label=name)
                axes[1][o].plot(self.frequencies, np.degrees(np.angle(h)), label=name)
            unit = self.units.get(out, "")
            ylabel = f"|H| ({per_metre(unit)})" if unit else "|H| (per m)"
            axes[0][o].set(title=out, ylabel=ylabel)
            axes[1][o].set(xlabel="frequency (Hz)", ylabel="phase (deg)")
            for ax in (axes[0][o], axes[1][o]):
                ax.grid(True, alpha=0.3)
            axes[0][o].legend(fontsize=8)
            if noise:
                axes[0][o].annotate(
                    f"not drawn: {', '.join(noise)}\n(< {NOISE_RATIO:g} of the largest: "
                    "numerical noise\nof the symmetric model)",
                    xy=(0.02, 0.02),
                    xycoords="axes fraction",
                    fontsize=7,
                    color="0.4",
                )
        fig.suptitle(
            f"Frequency response at {self.speed * 3.6:.0f} km/h (loco {_loco.__version__})"
        )
        fig.tight_layout()
        if path is not None:
            save_figure(fig, path)
        return fig


def frequency_response(
    vehicle: Locomotive,
    scenario: Scenario,
    inputs: Sequence[str] | None = None,
    outputs: Sequence[str] | None = None,
    frequencies: npt.ArrayLike | None = None,
) -> FrequencyResponse:
    """Transfer functions of the vehicle linearised at ``scenario.speed`` (m/s) with the
    scenario's wheel, rail and yaw damper (its track is not used) from ``inputs`` (default all
    four channels) to ``outputs`` (recorded channel names, default :data:`DEFAULT_OUTPUTS`) at
    ``frequencies`` (Hz, positive; default 0.1–20 Hz).

    Raises :class:`loco.ParameterError` for an unknown channel or input name, a string where a
    list of names is expected, frequencies that are not real numbers, non-positive, non-finite,
    above 1 kHz or more than 100 000 of them, and for a scenario with a ``curve`` (the response
    about a steady curve is not implemented; it is refused, not taken on straight track)."""
    ins = names("inputs", INPUTS if inputs is None else inputs)
    outs = names("outputs", DEFAULT_OUTPUTS if outputs is None else outputs)
    f = _frequencies(frequencies)
    h, speed, wheelset_x = _loco.frequency_response(
        vehicle.native,
        scenario.native(),
        ins,
        outs,
        f,
    )
    return FrequencyResponse(
        frequencies=f,
        inputs=ins,
        outputs=outs,
        h=h,
        speed=float(speed),
        wheelset_x=tuple(wheelset_x),
        units=_output_units(vehicle, outs),
    )


@dataclass(frozen=True)
class ResponsePsd:
    """Output PSDs ``psd[output, frequency]`` (unit²/Hz), rms (unit) and W_y (–)."""

    frequencies: npt.NDArray[np.float64]
    outputs: list[str]
    psd: npt.NDArray[np.float64]
    rms: dict[str, float]
    sperling_lateral: float
    spectrum: str
    #: Damping ratio of the least damped mode in 0.3–20 Hz (–, NaN when none).
    least_damping_ratio: float = float("nan")
    #: SI unit of each output, by name.
    units: dict[str, str] = field(default_factory=dict)

    def __repr__(self) -> str:
        return (
            f"ResponsePsd(spectrum={self.spectrum!r}, {len(self.outputs)} outputs, "
            f"W_y={self.sperling_lateral:.3f}, least damping ratio {self.least_damping_ratio:.4f})"
        )

    @property
    def stable(self) -> bool:
        """Whether the linear model is stable (no growing mode in 0.3–20 Hz): only then do
        the spectra describe the running vehicle."""
        return bool(np.isnan(self.least_damping_ratio) or self.least_damping_ratio > 0.0)

    def to_xarray(self) -> Any:
        """``xarray.DataArray`` on (output, frequency), rms and W_y as attributes."""
        import xarray

        attrs: dict[str, Any] = {f"rms_{k}": v for k, v in self.rms.items()}
        attrs.update(
            sperling_lateral=self.sperling_lateral,
            least_damping_ratio=self.least_damping_ratio,
            spectrum=self.spectrum,
            loco_version=_loco.__version__,
        )
        return xarray.DataArray(
            self.psd,
            dims=("output", "frequency"),
            coords={"output": self.outputs, "frequency": self.frequencies},
            attrs=attrs,
            name="psd",
        )

    def plot(self, path: str | Path | None = None) -> Any:
        """The output PSDs (log), one panel per output; saved as PNG when ``path`` is given."""
        from loco.studies.plotting import pyplot, save_figure

        fig, axes = pyplot().subplots(
            1, len(self.outputs), figsize=(4.2 * len(self.outputs), 3.8), squeeze=False
        )
        for o, out in enumerate(self.outputs):
            ax = axes[0][o]
            ax.semilogy(self.frequencies, self.psd[o])
            unit = self.units.get(out, "")
            ax.set(
                title=f"{out} (rms {self.rms[out]:.3g} {unit})".replace(" )", ")"),
                xlabel="frequency (Hz)",
                ylabel=f"PSD ({squared_per_hertz(unit)})" if unit else "PSD (per Hz)",
            )
            ax.grid(True, alpha=0.3)
        fig.suptitle(
            f"Linear output PSD, {self.spectrum}, W_y = {self.sperling_lateral:.2f} "
            f"(loco {_loco.__version__})"
        )
        fig.tight_layout()
        if path is not None:
            save_figure(fig, path)
        return fig


def response_psd(
    vehicle: Locomotive,
    scenario: Scenario,
    outputs: Sequence[str] | None = None,
    frequencies: npt.ArrayLike | None = None,
    spectrum: str | None = None,
    band: tuple[float, float] | None = None,
    amplitude_scale: float = 1.0,
) -> ResponsePsd:
    """Output PSDs, rms values and W_y of the linearised vehicle on a random track of
    ``spectrum`` (default the scenario's) in the wavelength ``band`` (m, default the scenario's),
    amplitudes times ``amplitude_scale``; ``outputs``, ``frequencies`` and the refusal of a
    ``curve`` as in :func:`frequency_response`."""
    outs = names("outputs", DEFAULT_OUTPUTS if outputs is None else outputs)
    f = _frequencies(frequencies)
    name = text("spectrum", scenario.spectrum if spectrum is None else spectrum)
    lo, hi = pair("band", scenario.band if band is None else band)
    lo, hi = real("band[0]", lo), real("band[1]", hi)
    amplitude_scale = real("amplitude_scale", amplitude_scale)
    psd, rms, wy, zeta = _loco.response_psd(
        vehicle.native,
        scenario.native(),
        outs,
        f,
        spectrum=name,
        band=(lo, hi),
        amplitude_scale=amplitude_scale,
    )
    return ResponsePsd(
        frequencies=f,
        outputs=outs,
        psd=psd,
        rms=dict(zip(outs, rms.tolist(), strict=True)),
        sperling_lateral=float(wy),
        spectrum=name,
        least_damping_ratio=float(zeta),
        units=_output_units(vehicle, outs),
    )
