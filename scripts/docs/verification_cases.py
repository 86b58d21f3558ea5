"""The rows of ``docs/verification.md`` on the model's parts: what each verification case checks
and against which reference (text, not a measurement), and how its result reads, every number
taken from the records the tests write (``docs/verification/records/``). The curves' rows are
``scripts/docs/verification_curves.py``; both are read by ``scripts/docs/verification_docs.py``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from verification_docs import Records


@dataclass(frozen=True)
class Row:
    """One row of the page: the check, its reference and its result from the records."""

    what: str
    against: str
    result: Callable[[Records], str]


MM, PCT, KN, MRAD = 1e3, 100.0, 1e-3, 1e3

INTRO = [
    "Every model part is checked against something independent of it: closed forms, published",
    "benchmarks and standards' cases. Each row names its reference and the result measured by",
    "the test that pins it. The tests write what they measure into verification records",
    "(`docs/verification/records/<case>.json`, values rounded as shown here) and fail when a",
    "record no longer matches what they measure; this page is generated from those records",
    "(`python scripts/docs/verification_docs.py --write`), and the last section lists every record",
    "with the tolerance its test asserts. The Rust cases are one test binary,",
    "`cargo test -p loco-core --release --test verification`; the Python ones are in `tests/`.",
    "`LOCO_UPDATE_RECORDS=1` before either command rewrites the records.",
]


def _stability(r: Records) -> str:
    linear = r.get("stability_ramp_down", "linear_critical_speed")
    kmh = r.get("stability_ramp_down", "linear_critical_speed", 3.6)
    return (
        f"YD1: linear {linear} m/s ({kmh} km/h); the ramp-down at 0.5 m/s² loses the cycle at "
        f"{r.get('stability_ramp_down', 'nonlinear_critical_speed')} m/s (at 1 m/s²: "
        f"{r.get('stability_ramp_down', 'nonlinear_at_1_m_s2')} m/s); at 0.8× the disturbance "
        f"decays to {r.get('stability_decay_and_limit_cycle', 'decay_below')} of "
        "its size, at 1.3× the limit cycle's amplitude changes by "
        f"{r.get('stability_decay_and_limit_cycle', 'cycle_change_above', PCT, ' %')} over the "
        f"last 2 s; YD2: linear {r.get('stability_yd1_yd2', 'yd2')} m/s (YD1 "
        f"{r.get('stability_yd1_yd2', 'yd1')} m/s, both by bisection to "
        f"{r.get('stability_yd1_yd2', 'bisection_tolerance')} m/s)"
    )


def _rolled(r: Records) -> str:
    case = "rolled_rails"
    return (
        f"wheelsets within {r.largest(case, '*_shift', MM)} mm of −h0 sin θ = "
        f"{r.get(case, 's_norm_rolled_pose', MM)} mm (S_norm), ΣY below "
        f"{r.largest(case, '*_sum_y', KN)} kN, per-wheel Y changed by at most "
        f"{r.largest(case, '*_wheel_y_change', KN)} kN, one contact point per wheel; carbody "
        f"sag {r.largest(case, '*_carbody_sag', MM)} to {r.smallest(case, '*_carbody_sag', MM)}"
        f" mm against {r.get(case, 's_norm_carbody_sag_hand', MM)} mm (S_norm)"
    )


def _relative_roll(r: Records) -> str:
    case = "rolled_rails_relative_roll"
    return (
        f"largest roll beyond the rigid pose {r.get(case, 's_low_yd2_roll')} (S_low), "
        f"{r.get(case, 's_norm_yd2_roll')} (S_norm), {r.get(case, 's_high_yd2_roll')} "
        f"(S_high, YD2), {r.get(case, 's_high_yd1_roll')} (S_high hunting with YD1, "
        f"{r.get(case, 's_high_yd1_two_point_samples')} wheel samples in two-point contact) and "
        f"{r.get(case, 's_low_yd1_roll')} rad (S_low with YD1)"
    )


def _frf(r: Records) -> str:
    psd = "response_psd_band"
    bins = int(r.total(psd, "*_bins"))
    inside = bins - int(r.total(psd, "*_outside"))
    return (
        f"{len(r.cases('frf_s_*'))} scenario and channel cases at 4 wavelengths: amplitude within "
        f"{r.largest('frf_s_*', 'amplitude', PCT, ' %')}, phase within "
        f"{r.largest('frf_s_*', 'phase')}°; vertical and gauge input move the vehicle laterally "
        f"by {r.get('frf_symmetric_channels', 'lateral_of_alignment_response')} of the "
        "alignment's response; on a 2 km wave each wheelset follows its delay e^(ikx) within "
        f"{r.get('frf_wheelset_delays', 'tracking_error')}; PSD inside the 99 % χ² band in "
        f"{inside} of {bins} bins"
    )


def _bearing(r: Records, case: str, name: str) -> str:
    return (
        f"{name}: ζ {r.get(case, 'damping_ratio')} at {r.get(case, 'frequency')} Hz against "
        f"β·ω/2 = {r.get(case, 'expected_damping_ratio')} "
        f"({r.get(case, 'damping_ratio_without')} without their damping)"
    )


MODEL_PARTS = [
    Row(
        "equivalent conicity, EN 15302 cases E1–E9 from the given Δr",
        "EN 15302:2008+A1:2010 Annex E: the reference values and tolerance bands (`ben_E*.dat`)",
        lambda r: (
            f"all {r.total('conicity_given_dr_e*', 'amplitudes')} amplitudes inside both pairs "
            "of limits (largest deviation from the reference "
            f"{r.largest('conicity_given_dr_e*', 'largest_deviation')})"
        ),
    ),
    Row(
        "equivalent conicity, EN 15302 cases E1–E9 from the reference profiles (our contact "
        "geometry)",
        "the standard's Δr functions (`dr_E*.dat`), reference values and tolerance bands",
        lambda r: (
            f"Δr within a median {r.get('conicity_profiles_delta_r', 'lowest_median')}–"
            f"{r.get('conicity_profiles_delta_r', 'highest_median')} mm per case; "
            f"{r.get('conicity_profiles_tan', 'inside_as_set_up')} of "
            f"{r.get('conicity_profiles_tan', 'amplitudes')} amplitudes inside the limits as set "
            "up (largest deviation "
            f"{r.get('conicity_profiles_tan', 'largest_deviation_inside')}), the other "
            f"{r.get('conicity_profiles_tan', 'inside_with_rails_moved')} (contact jumps a few "
            "µm from the standard's 0.1 mm grid points) inside with the rails moved 10 µm"
        ),
    ),
    Row(
        "Manchester benchmark A-2.2 (S1002/UIC60, 21 poses, 10 kN per wheel)",
        "CONTACT's reference output (Shackleton & Iwnicki, Vehicle System Dynamics 46, 2008)",
        lambda r: (
            "positions within "
            f"{r.get('manchester_a22_positions', 'wheel_position')} mm (away from contact "
            f"jumps), contact angle {r.get('manchester_a22_positions', 'contact_angle')} rad, "
            f"rolling radius {r.get('manchester_a22_positions', 'rolling_radius')} mm; Hertz "
            "from our curvatures: peak pressure within "
            f"{r.get('manchester_a22_hertz', 'peak_pressure', PCT, ' %')}, approach "
            f"{r.get('manchester_a22_hertz', 'approach', PCT, ' %')}; normal force within "
            f"{r.get('manchester_a22_normal_force', 'tread', PCT, ' %')} on the tread, "
            f"{r.get('manchester_a22_normal_force', 'flange_lowest', PCT)}–"
            f"{r.get('manchester_a22_normal_force', 'flange', PCT, ' %')} high in flange contact "
            "where the 2-D geometry misses the yaw's contact lead "
            f"({r.get('manchester_a22_normal_force', 'flange_with_lead', PCT, ' %')} with it); "
            "per-pose table in [Manchester benchmark A-2.2](manchester_a22.md)"
        ),
    ),
    Row(
        "Hertz",
        "sphere on plane (closed form); Hertz's m/n table (Timoshenko & Goodier, Theory of "
        "Elasticity, 1951, §140); CONTACT's normal solution of its `fastsim` example",
        lambda r: (
            f"{r.get('hertz_sphere_on_plane', 'semi_axes_approach_load')}, "
            f"{r.get('hertz_m_n_table', 'largest_deviation', PCT, ' %')}, "
            f"{r.get('hertz_contact_case', 'largest_deviation', PCT, ' %')}"
        ),
    ),
    Row(
        "FASTSIM",
        "Kalker's linear theory at small creepage; the strip closed form of the simplified "
        "theory under pure creepage; CONTACT's FASTSIM on its 220 × 220 grid",
        lambda r: (
            f"{r.largest('fastsim_linear_*', 'deviation', PCT, ' %')}; "
            f"{r.get('fastsim_strip_closed_form', 'fine_grid', PCT, ' %')} on 200 × 200; FY "
            f"{r.get('fastsim_contact_fine_grid', 'parabolic_fy', PCT, ' %')}, Mz "
            f"{r.get('fastsim_contact_fine_grid', 'parabolic_mz', PCT, ' %')} (parabolic bound; "
            f"elliptic {r.get('fastsim_contact_fine_grid', 'elliptic_fy', PCT, ' %')}, "
            f"{r.get('fastsim_contact_fine_grid', 'elliptic_mz', PCT, ' %')})"
        ),
    ),
    Row(
        "Maxwell dampers (YD1, YD2 at 0.5, 1 and 4 Hz on the bench)",
        "closed-form c_eff = c/(1 + (ωc/k)²), k_eff = k(ωc/k)²/(1 + (ωc/k)²) and the energy "
        "per cycle",
        lambda r: (
            "c_eff "
            f"{r.largest('maxwell_*', 'c_eff')}, k_eff {r.largest('maxwell_*', 'k_eff')}, "
            f"energy {r.largest('maxwell_*', 'energy')}"
        ),
    ),
    Row(
        "track synthesis",
        "Welch PSD vs TB/T 3352-2014 across the 2–200 m band (octave bands); mean square vs "
        "the German spectrum's integral",
        lambda r: (
            f"{r.get('track_welch_psd', 'octave_bands')} octave bands within "
            f"{r.get('track_welch_psd', 'largest_deviation_in_3_sigma')} × 3 standard errors; "
            f"mean square within {r.get('track_rms', 'mean_square')}"
        ),
    ),
    Row(
        "Sperling",
        "hand-worked single sines on and off FFT bins (GB/T 5599-2019 weighting)",
        lambda r: f"{r.largest('sperling_*', 'deviation')}",
    ),
    Row(
        "locomotive statics",
        "weight",
        lambda r: (
            "wheel loads sum to the weight "
            f"({r.get('statics_wheel_loads', 'load_sum_error')}), equal within "
            f"{r.get('statics_wheel_loads', 'load_spread', PCT, ' %')}"
        ),
    ),
    Row(
        "free wheelset, conical contact",
        "Klingel (with the contact's roll term)",
        lambda r: (
            f"{r.get('klingel_wavelength', 'measured')} m against "
            f"{r.get('klingel_wavelength', 'klingel')} m "
            f"({r.get('klingel_wavelength', 'deviation', PCT, ' %')})"
        ),
    ),
    Row(
        "rigid two-axle bogie",
        "Wickens' creep-equilibrium wavelength (Fundamentals of Rail Vehicle Dynamics, 2003)",
        lambda r: (
            f"{r.get('rigid_bogie_wavelength', 'measured')} m against "
            f"{r.get('rigid_bogie_wavelength', 'wickens')} m "
            f"({r.get('rigid_bogie_wavelength', 'deviation', PCT, ' %')})"
        ),
    ),
    Row(
        "symmetry, rest, determinism",
        "exact",
        lambda r: (
            "lateral response to vertical input "
            f"{r.get('symmetric_vertical_input', 'largest_lateral_response')}, motion on perfect "
            f"track {r.get('rest_on_perfect_track', 'largest_motion')}; "
            f"{r.get('determinism', 'channels_differing')} of "
            f"{r.get('determinism', 'channels_compared')} channels of a rerun differ in any bit"
        ),
    ),
    Row(
        "stability, S_high with YD1",
        "linearised eigenvalues (nalgebra, balanced; numpy's eigenvalues bracket the result); "
        "decay at 0.8× and a steady limit cycle at 1.3× the linear critical speed; nonlinear "
        "critical speed by speed ramp-down at or below the linear one (subcritical hunting)",
        _stability,
    ),
    Row(
        "rolled rails: constant 2 mm cross level on S_low, S_norm, S_high (`rolled_rails.rs`)",
        "hand calculation: wheelsets rolled with the rails about the rail-top line, "
        "y = −h0 sin θ, shifted downhill by at most W sin θ / K_g (K_g from the contact table); "
        "carbody sag M_c g sin θ / K_y on the flexicoils",
        _rolled,
    ),
    Row(
        "relative roll of running wheelsets (same file)",
        "the contact table's roll layers (±1 mrad)",
        _relative_roll,
    ),
    Row(
        "frequency response (linear model with the track as input)",
        "time domain, 0.2 mm sinusoids of each channel at 20–150 m; Welch PSD of a long run "
        "against the linear stochastic PSD (Percival & Walden 1993, §6.17); the full matrix: "
        "[the frequency response's verification](model/frequency_response.md)",
        _frf,
    ),
    Row(
        "measured track beyond the contact",
        "a file with 40 mm of gauge widening or 45 mm of cross level",
        lambda r: (
            "refused before the run naming the file, the line "
            f"({r.get('measured_track_refused', 'gauge_widening_line')} and "
            f"{r.get('measured_track_refused', 'cross_level_line')}) and the value"
        ),
    ),
    Row(
        "step convergence over the SPEC §6 box",
        "the same runs at half the step (nominal and opposite corners in CI, 8 Latin-hypercube "
        "samples by script)",
        lambda r: (
            f"W_y within {r.get('parameter_box_half_step', 'wy_change_s_low', PCT, ' %')}, A_yb "
            f"within {r.get('parameter_box_half_step', 'ayb_change_s_high', PCT, ' %')}; "
            f"{r.get('parameter_box_damper_corners', 'runs')} damper-corner runs, "
            f"{r.get('parameter_box_damper_corners', 'failed')} failed"
        ),
    ),
    Row(
        'exponential integrator (`integrator = "etdrk4"`, 2 ms, the default)',
        "the SPEC §6 box (nominal, opposite corners, damper corners, a 2000 1/s damper pole) "
        "against RK4 at 1 ms (`exponential_step.rs`); its propagator, decaying state and "
        "φ-functions against their closed forms in the unit tests of `vehicle/time`",
        lambda r: (
            f"on the study's 500 m, {r.get('exponential_step_box', 'runs')} runs: W_y within "
            f"{r.get('exponential_step_box', 'wy', PCT, ' %')}, A_yb within "
            f"{r.get('exponential_step_box', 'ayb', PCT, ' %')}, A_yc PSD peak within "
            f"{r.get('exponential_step_box', 'ayc_psd_peak', PCT, ' %')} (the 0.5 % gate)"
        ),
    ),
    Row(
        "light bodies' stiff modes (`bearing_damping.rs`)",
        "stiffness-proportional damping c = β·k: the linearised modes' ζ = β·ω/2",
        lambda r: (
            f"{_bearing(r, 'bearing_damping_bearings', 'gearbox bearings')}; "
            f"{_bearing(r, 'bearing_damping_traction_rods', 'traction rods')}"
        ),
    ),
    Row(
        "batch",
        "single runs; 1 vs 2 threads",
        lambda r: (
            f"{r.get('batch_bit_identity', 'differing_one_vs_two_threads')} of "
            f"{r.get('batch_bit_identity', 'metric_values')} metric values differ in any bit "
            "between 1 and 2 threads, "
            f"{r.get('batch_bit_identity', 'differing_batch_vs_single_run')} between a batch row "
            "and its single run; a failing sample flagged (status "
            f"{r.get('batch_failed_sample', 'failed_status_code')}, "
            f"{r.quantity('batch_failed_sample', 'failed_status').value}, "
            f"{r.get('batch_failed_sample', 'failed_nan_metrics')} NaN metrics), the other "
            f"{r.get('batch_failed_sample', 'completed')} complete"
        ),
    ),
]
