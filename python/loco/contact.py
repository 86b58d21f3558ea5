"""Wheel-rail contact: the rigid contact geometry of a wheelset on a track.

:func:`geometry` solves, for each lateral displacement ``y`` of the wheelset (m, positive to the
left), the roll and rise at which both wheels touch their rails, and returns per wheel up to two
contact points (tread side and flange side, the second with its vertical gap).
:func:`rolling_radius_difference` returns Δr = r_left − r_right for equivalent conicity as
EN 15302 defines it: the wheelset translated without roll, each wheel touching its rail at its own
lowest point (the standard's benchmark Δr functions are those; :func:`geometry` rolls the rigid
wheelset, as the vehicle model does, which moves flange contact about r·φ ≈ 0.3 mm earlier).

Track set-up keywords (SI units): ``gauge`` (m, measured ``gauge_height`` below the rail top),
``rail_inclination`` (rad, rail cant toward the track centre; 0 for already canted rail profiles;
the scenario's name for it too; ``inclination``, its former name, still works and warns),
``back_to_back`` (m, between the wheels' inner faces; EN 15302's flange back spacing),
``flange_back_offset`` (m, from a wheel's inner face to its taping line) and ``nominal_radius``
(m, one value or a (left, right) pair). Defaults are the study's: 1435 mm gauge at 16 mm, 1:40,
back-to-back 1353 mm, 70 mm, 625 mm (:data:`SETUP_DEFAULTS`, from the core).
"""

from __future__ import annotations

import importlib
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from loco import _loco
from loco._loco import Profile

__all__ = [
    "LINEAR_PARAMETERS_AMPLITUDE",
    "SETUP_DEFAULTS",
    "ContactGeometry",
    "LinearContactParameters",
    "axle_load",
    "geometry",
    "linear_parameters",
    "rolling_radius_difference",
]

_FloatArray = npt.NDArray[np.float64]

#: The study's track and wheelset set-up (SI), the defaults of the keywords above, from the core
#: (``TrackSetup::default``, ``WheelsetSetup::default``): ``gauge``, ``gauge_height``,
#: ``rail_inclination``, ``back_to_back``, ``flange_back_offset``, ``nominal_radius_left`` and
#: ``nominal_radius_right``.
SETUP_DEFAULTS: dict[str, float] = dict(_loco.contact_setup_defaults())

#: The default ``nominal_radius``: one value when both wheels have it, else the (left, right) pair.
_NOMINAL_RADIUS: float | tuple[float, float] = (
    SETUP_DEFAULTS["nominal_radius_left"]
    if SETUP_DEFAULTS["nominal_radius_left"] == SETUP_DEFAULTS["nominal_radius_right"]
    else (SETUP_DEFAULTS["nominal_radius_left"], SETUP_DEFAULTS["nominal_radius_right"])
)


@dataclass(frozen=True)
class ContactGeometry:
    """Rigid contact geometry at lateral displacements ``y``.

    ``roll`` (rad, positive lifting the left wheel) and ``rise`` (m, of the wheelset centre from
    its centred pose) have shape (n,). Every other field has shape (n, 2, 2), indexed
    ``[i, wheel, slot]`` with wheel 0 left and 1 right, slot 0 the field-side (tread) point and
    slot 1 the gauge-side (flange) point when the gap has two minima; NaN where a slot is empty.
    Signs and frames follow ``loco_core::contact::ContactPoint``: ``gap`` vertical (m, 0 where
    touching), ``lateral`` and ``vertical`` relative to the wheelset centre in track axes (m),
    ``contact_angle`` positive when the rail pushes the wheel toward the track centre (rad),
    curvatures positive for convex surfaces (1/m), ``wheel_y`` and ``rail_y`` positions on the
    profiles (m).
    """

    y: _FloatArray
    roll: _FloatArray
    rise: _FloatArray
    gap: _FloatArray
    lateral: _FloatArray
    vertical: _FloatArray
    rolling_radius: _FloatArray
    contact_angle: _FloatArray
    wheel_curvature: _FloatArray
    rail_curvature: _FloatArray
    wheel_y: _FloatArray
    rail_y: _FloatArray

    def touching(self, field: str) -> _FloatArray:
        """``field`` at the touching point (smallest gap) of each wheel, shape (n, 2)."""
        values: _FloatArray = getattr(self, field)
        gap = np.where(np.isnan(self.gap), np.inf, self.gap)
        slot = np.argmin(gap, axis=2)
        return np.take_along_axis(values, slot[:, :, None], axis=2)[:, :, 0]


def _wheelset(
    wheel: Profile,
    rail: Profile,
    right_wheel: Profile | None,
    right_rail: Profile | None,
    gauge: float,
    gauge_height: float,
    rail_inclination: float,
    back_to_back: float,
    flange_back_offset: float,
    nominal_radius: float | tuple[float, float],
) -> _loco.WheelsetContact:
    """The native wheelset on its rails, its contact search prepared once."""
    if isinstance(nominal_radius, tuple):
        r_left, r_right = nominal_radius
    else:
        r_left = r_right = nominal_radius
    return _loco.WheelsetContact(
        wheel,
        right_wheel if right_wheel is not None else wheel,
        rail,
        right_rail if right_rail is not None else rail,
        gauge=float(gauge),
        gauge_height=float(gauge_height),
        rail_inclination=float(rail_inclination),
        back_to_back=float(back_to_back),
        flange_back_offset=float(flange_back_offset),
        nominal_radius_left=float(r_left),
        nominal_radius_right=float(r_right),
    )


def _rail_inclination(rail_inclination: float, inclination: float | None) -> float:
    """``rail_inclination``, or the value given by its former name ``inclination`` (with a
    :class:`DeprecationWarning`); ``inclination`` with a ``rail_inclination`` other than the
    default is an error naming it."""
    if inclination is None:
        return rail_inclination
    if rail_inclination != SETUP_DEFAULTS["rail_inclination"]:
        raise _loco.ParameterError(
            "invalid parameter `inclination`: give `rail_inclination` only (`inclination` is "
            "its former name)"
        )
    warnings.warn(
        "`inclination` is now `rail_inclination`, as the scenario calls it",
        DeprecationWarning,
        stacklevel=3,
    )
    return inclination


def geometry(
    wheel: Profile,
    rail: Profile,
    y: npt.ArrayLike,
    *,
    right_wheel: Profile | None = None,
    right_rail: Profile | None = None,
    gauge: float = SETUP_DEFAULTS["gauge"],
    gauge_height: float = SETUP_DEFAULTS["gauge_height"],
    rail_inclination: float = SETUP_DEFAULTS["rail_inclination"],
    back_to_back: float = SETUP_DEFAULTS["back_to_back"],
    flange_back_offset: float = SETUP_DEFAULTS["flange_back_offset"],
    nominal_radius: float | tuple[float, float] = _NOMINAL_RADIUS,
    inclination: float | None = None,
) -> ContactGeometry:
    """Rigid contact geometry for the lateral displacements ``y`` (m, array-like).

    ``wheel`` and ``rail`` are the left profiles; the right ones are the same mirrored unless
    ``right_wheel`` / ``right_rail`` are given (also as left-side profiles).
    """
    ys = np.atleast_1d(np.asarray(y, dtype=np.float64))
    wheelset = _wheelset(
        wheel,
        rail,
        right_wheel,
        right_rail,
        gauge,
        gauge_height,
        _rail_inclination(rail_inclination, inclination),
        back_to_back,
        flange_back_offset,
        nominal_radius,
    )
    return ContactGeometry(y=ys, **wheelset.solve(ys))


def rolling_radius_difference(
    wheel: Profile,
    rail: Profile,
    y: npt.ArrayLike,
    *,
    right_wheel: Profile | None = None,
    right_rail: Profile | None = None,
    gauge: float = SETUP_DEFAULTS["gauge"],
    gauge_height: float = SETUP_DEFAULTS["gauge_height"],
    rail_inclination: float = SETUP_DEFAULTS["rail_inclination"],
    back_to_back: float = SETUP_DEFAULTS["back_to_back"],
    flange_back_offset: float = SETUP_DEFAULTS["flange_back_offset"],
    nominal_radius: float | tuple[float, float] = _NOMINAL_RADIUS,
    inclination: float | None = None,
) -> _FloatArray:
    """Δr = r_left − r_right (m) at each lateral displacement ``y`` (m) of the wheelset translated
    without roll (EN 15302's definition, see the module documentation)."""
    ys = np.atleast_1d(np.asarray(y, dtype=np.float64))
    wheelset = _wheelset(
        wheel,
        rail,
        right_wheel,
        right_rail,
        gauge,
        gauge_height,
        _rail_inclination(rail_inclination, inclination),
        back_to_back,
        flange_back_offset,
        nominal_radius,
    )
    return wheelset.rolling_radius_difference(ys)


#: Default half step of the linear parameters' central differences, m (from the core).
LINEAR_PARAMETERS_AMPLITUDE: float = _loco.LINEAR_PARAMETERS_AMPLITUDE


@dataclass(frozen=True)
class LinearContactParameters:
    """The linear contact parameters of a wheelset on its rails, in Wickens' notation
    (``loco_core::contact::linear_parameters``, where the definitions and the gravitational
    stiffness's formula are documented): for a small lateral displacement ``y`` (m),
    ``r_L − r_R = 2 λ y``, contact angles relative to the axle ``θ_L − θ_R = 2 ε y / l0``, roll
    ``φ = σ y / l0``, and the gravitational stiffness ``K_g = W·d²h/dy²`` (h the wheelset's
    rise, W its axle load), read from the model's rigid contact by central differences at
    ±``amplitude``.

    ``half_contact_spacing`` l0 (m), ``rolling_radius`` r0 (m) and ``contact_angle`` δ0 (rad)
    are those of the centred pose; ``conicity`` λ, ``contact_angle_parameter`` ε and
    ``roll_parameter`` σ are dimensionless; ``gravitational_stiffness_per_load`` is K_g/W (1/m)
    and ``gravitational_stiffness`` K_g (N/m) under ``axle_load`` (N), NaN when no load was
    given.
    """

    amplitude: float
    half_contact_spacing: float
    rolling_radius: float
    contact_angle: float
    conicity: float
    contact_angle_parameter: float
    roll_parameter: float
    gravitational_stiffness_per_load: float
    axle_load: float
    gravitational_stiffness: float


def axle_load(vehicle: Any = None) -> float:
    """The mean axle load W (N) of ``vehicle`` (a :class:`loco.Locomotive`, default the study's):
    its weight, its own wheelsets included, over its wheelsets (computed by the core)."""
    from loco.vehicle import Locomotive

    loco_ = vehicle if vehicle is not None else Locomotive.default()
    return float(loco_.native.mean_axle_load())


def linear_parameters(
    wheel: Profile,
    rail: Profile,
    *,
    amplitude: float = LINEAR_PARAMETERS_AMPLITUDE,
    axle_load: float | None = None,
    right_wheel: Profile | None = None,
    right_rail: Profile | None = None,
    gauge: float = SETUP_DEFAULTS["gauge"],
    gauge_height: float = SETUP_DEFAULTS["gauge_height"],
    rail_inclination: float = SETUP_DEFAULTS["rail_inclination"],
    back_to_back: float = SETUP_DEFAULTS["back_to_back"],
    flange_back_offset: float = SETUP_DEFAULTS["flange_back_offset"],
    nominal_radius: float | tuple[float, float] = _NOMINAL_RADIUS,
    inclination: float | None = None,
) -> LinearContactParameters:
    """The linear contact parameters λ, ε, σ and the gravitational stiffness of ``wheel`` on
    ``rail`` (see :class:`LinearContactParameters`); ``axle_load`` (N, e.g. :func:`axle_load`)
    gives the stiffness in N/m. A bad ``amplitude`` (m, in (0, 0.01]) or a non-positive
    ``axle_load`` raises :class:`loco.ParameterError` naming it."""
    wheelset = _wheelset(
        wheel,
        rail,
        right_wheel,
        right_rail,
        gauge,
        gauge_height,
        _rail_inclination(rail_inclination, inclination),
        back_to_back,
        flange_back_offset,
        nominal_radius,
    )
    load = None if axle_load is None else float(axle_load)
    return LinearContactParameters(**dict(wheelset.linear_parameters(float(amplitude), load)))


# The contact API of the issue in one place: conicity (EN 15302) and Hertz/creep live in their own
# modules; `loco.conicity` builds on this module, so they are resolved on first access.
_REEXPORTS = {
    "ConicityCurve": "loco.conicity",
    "conicity_curve": "loco.conicity",
    "equivalent_conicity": "loco.conicity",
    "fastsim": "loco.creep",
    "hertz": "loco.creep",
    "kalker_coefficients": "loco.creep",
    "linear_creep_forces": "loco.creep",
}
__all__ += sorted(_REEXPORTS)


def __getattr__(name: str) -> Any:
    if name in _REEXPORTS:
        return getattr(importlib.import_module(_REEXPORTS[name]), name)
    raise AttributeError(f"module 'loco.contact' has no attribute '{name}'")
