"""The rows of ``docs/verification.md`` on curves: what each curving case checks, against which
reference, and how its result reads from the records the tests write. Read by
``scripts/docs/verification_docs.py``.
"""

from __future__ import annotations

from verification_cases import KN, MM, MRAD, PCT, Row

CURVES_INTRO = [
    "Verified by the curving cases of `crates/loco-core/tests/verification/` (`curving.rs`,",
    "`curving_quasi_static.rs`, `curving_wheel_loads.rs`, `track_design.rs`) and by the unit",
    "tests of `vehicle/curving/track_frame`; S_norm on perfect track, R = 1200 m unless said:",
]
CURVES = [
    Row(
        "clothoid heading L/2R, offset L²/6R; mirror of left/right design (`track_design.rs`)",
        "hand calculation",
        lambda r: (
            f"heading {r.get('clothoid', 'heading')} rad, offset integral "
            f"{r.get('clothoid', 'offset_integral')} m; "
            f"{r.get('clothoid_mirror', 'values_not_mirrored')} values not mirrored bit for bit"
        ),
    ),
    Row(
        "bogie frames sit on the versine x²/2R, yawed x/R, no rate in a steady curve",
        "hand calculation",
        # The unit test reads the track frame's internal work space, which the verification
        # binary cannot reach: it asserts the bound and records nothing.
        lambda _r: (
            "within 1e-12 (the bound the unit test of `vehicle/curving/track_frame` asserts; "
            "not recorded)"
        ),
    ),
    Row(
        "balanced cant (100 mm, V = 28.08 m/s): lateral acceleration in the track plane",
        "0 within 0.01 m/s²",
        lambda r: (
            f"{r.get('curve_balanced_cant', 'track_plane_lateral')} m/s² (accelerometers "
            f"{r.get('curve_balanced_cant', 'accelerometers_lateral')} m/s²)"
        ),
    ),
    Row(
        "same, 200 m after the transition: every body at rest, traction rods and rotary arms "
        "included, at each of 16 instants over 1.6 m",
        "all accelerations < 1e-3 (along the track: the common curving-resistance drift, wheel "
        "spin = drift/r0)",
        lambda r: (
            f"{r.get('curve_balanced_cant', 'largest_acceleration')} "
            f"(`{r.quantity('curve_balanced_cant', 'largest_acceleration_at').value}`); frames "
            f"≤ {r.get('curve_balanced_cant', 'largest_acceleration_frames')}, traction rods ≤ "
            f"{r.get('curve_balanced_cant', 'largest_acceleration_traction_rods')} "
            "([Curves and the track frame](model/curves.md))"
        ),
    ),
    Row(
        "same: guiding forces cancel over the vehicle",
        "ΣY ≈ 0",
        lambda r: (
            f"{r.get('curve_balanced_cant', 'sum_y')} N against up to "
            f"{r.get('curve_balanced_cant', 'largest_wheelset_y', KN)} kN per wheelset"
        ),
    ),
    Row(
        "100 mm deficiency (50 mm cant, V = 34.39 m/s): lateral acceleration in the track plane",
        "g·d/2b within 2 %",
        lambda r: (
            f"{r.get('curve_cant_deficiency', 'track_plane_lateral')} m/s² against "
            f"{r.get('curve_cant_deficiency', 'expected_lateral')} m/s²"
        ),
    ),
    Row(
        "roll coefficient (carbody roll on its suspension / (d/2b))",
        "reported",
        lambda r: (
            f"{r.get('curve_cant_deficiency', 'roll_coefficient')} (roll "
            f"{r.get('curve_cant_deficiency', 'carbody_roll', MRAD)} mrad, outward)"
        ),
    ),
    Row(
        "left vs right curve",
        "mirror image",
        lambda r: (
            f"wheelset y within {r.get('curve_mirror', 'wheelset_y_difference')} m of "
            f"{r.get('curve_mirror', 'wheelset_offset', MM)} mm; loads mirrored (rms "
            f"{r.get('curve_mirror', 'wheel_load_difference_rms')} N, peak "
            f"{r.get('curve_mirror', 'wheel_load_difference_peak')} N: "
            "[Curves and the track frame](model/curves.md))"
        ),
    ),
    Row(
        "conical wheel on knife-edge rails: a free wheelset and a two-axle bogie in a steady "
        "curve (`curving_quasi_static.rs`)",
        "the pure-rolling offset r0·l/(λR); the classical linear theory of the bogie with "
        "primary yaw stiffness",
        lambda r: (
            "offset within "
            f"{r.get('curve_free_wheelset_offset', 'offset_deviation', PCT, ' %')}; bogie pose "
            f"within {r.get('curve_two_axle_bogie', 'pose_deviation', PCT, ' %')}, the recorded "
            "angle of attack within "
            f"{r.get('curve_two_axle_bogie', 'angle_of_attack_channel_deviation', PCT, ' %')}"
        ),
    ),
    Row(
        "wheel loads at balanced cant (`curving_wheel_loads.rs`)",
        "the roll-moment balance of the whole vehicle from the bodies' positions",
        lambda r: (
            "cone on knife edges: within "
            f"{r.get('curve_wheel_loads', 'cone_balance_deviation', PCT, ' %')}, equal within "
            f"{r.get('curve_wheel_loads', 'cone_unbalance_near_centre_line', PCT, ' %')} near "
            "the centre line (R = 15 km); S_norm: outer wheels "
            f"{r.get('curve_wheel_loads', 's_norm_unbalance', PCT, ' %')} heavier, the rails' "
            "whole wrench closing the bodies' balance within "
            f"{r.get('curve_wheel_loads', 's_norm_rails_against_bodies', PCT, ' %')}"
        ),
    ),
]
