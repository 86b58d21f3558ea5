"""Wheel and rail profiles: loading files, built-in profiles, evaluation.

Profiles are in the profile frame documented in ``loco_core::contact::profile``: points in m,
``y`` lateral toward the field side (the flange / gauge corner on the low-``y`` side, as for a
left wheel and rail), ``z`` up; a wheel's origin is its taping line. Every method of
:class:`Profile` takes and returns SI units.

Files: SIMPACK ``.prw`` (wheel) and ``.prr`` (rail) profiles, or two-column text files with y and z
in mm (``#`` and ``%`` start comments), such as the EN 15302 reference profiles.
"""

from __future__ import annotations

import copyreg
import os
from typing import Any

from loco._loco import (
    Profile,
    builtin_profile_named,
    builtin_profile_names,
    jm3_tread_profile,
    load_profile_file,
)
from loco.field_types import real

__all__ = ["Profile", "builtin", "builtin_names", "jm3", "load"]


def load(
    path: str | os.PathLike[str],
    kind: str | None = None,
    *,
    drop_backtracking: bool = False,
    smoothing_length: float = 0.0,
) -> Profile:
    """Loads a profile file.

    ``kind`` ('wheel' or 'rail') is required for text files and, when given for a SIMPACK file,
    must match the file's type. ``drop_backtracking`` drops points of a text file that do not
    advance in y instead of raising :class:`loco.ProfileFormatError`. ``smoothing_length`` (m)
    > 0 smooths the profile (cubic smoothing spline, see :meth:`Profile.smoothed`; at most
    0.01 m); use about 2e-3 for measured or rounded profiles so that curvatures are meaningful.
    A loaded profile is checked for plausibility (width, height, a wheel's flange and monotonic
    tread, a rail head falling from its top): a file in the wrong unit, a wheel file given as the
    rail or a stray point is a :class:`loco.ProfileFormatError` saying so.
    """
    length = real("smoothing_length", smoothing_length)
    profile = load_profile_file(os.fspath(path), kind, drop_backtracking)
    # Any value but 0 goes to the core, which refuses a negative, NaN or over-long one.
    return profile if length == 0.0 else profile.smoothed(length)


def builtin(name: str) -> Profile:
    """The built-in profile ``name`` (see :func:`builtin_names`); raises
    :class:`loco.ParameterError` listing the available names for an unknown one."""
    return builtin_profile_named(name)


def builtin_names() -> list[str]:
    """Names accepted by :func:`builtin`."""
    return builtin_profile_names()


def jm3(
    tread_slope: float = 1.0 / 20.0,
    band_radius: float = 0.5,
    flange_thickness: float = 0.033,
) -> Profile:
    """A JM3-type wheel (``loco_core::contact::builtin::jm3``: the family of the built-in
    ``jm3-*`` wheels, whose flange height is 28 mm) with tread slope ``tread_slope`` (–) at the
    taping line, tread band radius ``band_radius`` (m; ``math.inf`` for a straight cone, whose
    equivalent conicity on any rail is its slope) and ``flange_thickness`` (m). The defaults are
    ``jm3-new``. A bad field raises :class:`loco.ParameterError` naming it."""
    return jm3_tread_profile(float(tread_slope), float(band_radius), float(flange_thickness))


def _reduce(profile: Profile) -> tuple[Any, tuple[str, str, Any, Any]]:
    return Profile, (profile.name, profile.kind, profile.y, profile.z)


# A profile pickles by its name, kind and points (validated again where it is unpickled), so
# scenarios travel to process pools and Dask workers.
copyreg.pickle(Profile, _reduce)
