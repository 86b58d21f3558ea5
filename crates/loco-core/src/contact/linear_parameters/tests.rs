//! The linear contact parameters against the closed forms of two circles in contact.
//!
//! # The closed forms (derived here; Wickens 2003 ch. 2 gives λ and σ in the same form)
//!
//! Near the contact the wheel is a circle of radius `R_w` (concave, its centre below the contact
//! on the normal; a cone is `R_w → ∞`) and the rail head a circle of radius `R_r`. The contact
//! normal passes through both centres, so their distance stays `Δ = R_w − R_r` as the wheelset
//! moves. At the centred pose the left contact is at `(l0, −r0)` from the wheelset centre with
//! normal `n0 = (−sin δ0, cos δ0)` (track axes y left, z up); the wheel's centre sits at
//! `(a, b) = (l0 + R_w sin δ0, −r0 − R_w cos δ0)` in the wheelset. Move the wheelset by `y`,
//! raise it by `z` and roll it by `φ`: the wheel centre moves by `d = (y − bφ, z + aφ)`.
//!
//! 1. Distance kept: `n0·d = 0`, so `z + aφ = tan δ0 (y − bφ)`; on the right wheel (mirror)
//!    `z − aφ = −tan δ0 (y − bφ)`. Their difference: `φ (a + b tan δ0) = y tan δ0` with
//!    `a + b tan δ0 = l0 − r0 tan δ0`, so `φ' = tan δ0/(l0 − r0 tan δ0)` and σ = l0 φ'.
//! 2. The normal turns by `t0·d/Δ` (t0 the tangent): `δ_L' = (1 − bφ')/(Δ cos δ0)` in track
//!    axes; relative to the axle `θ' = δ_L' − φ' = (1 + (r0 + R_r cos δ0) φ')/(Δ cos δ0)` and
//!    ε = l0 θ' (0 for a cone).
//! 3. The contact slides along the wheel circle by `R_w θ'`, so `r_L' = R_w sin δ0 θ' = λ`.
//! 4. Moments about the wheelset centre (each normal force passes through its wheel's centre):
//!    the load transfer `N_L − N_R = −2N g'(e − φ)/g` with `g = l0 cos δ0 − r0 sin δ0`,
//!    `g' = −(l0 sin δ0 + r0 cos δ0 + R_w)`, `e = δ_L − δ0`, `N = W/(2 cos δ0)`; the lateral
//!    resultant `−N_L sin δ_L + N_R sin δ_R` then gives `K_g/W` of the module documentation.
//!
//! The model computes none of these: it solves the rigid contact of the sampled profiles and
//! differentiates it. These tests fail when the search, the frames or the differences are wrong.

use super::*;
use crate::contact::builtin::conical::conical_pair;
use crate::contact::profile::{Profile, ProfileKind};
use crate::contact::profile_builder::ProfileBuilder;
use crate::contact::{ContactSearchParams, TrackSetup, WheelsetSetup};

/// Closed forms of the two-circle contact (module doc): (λ, ε, σ, K_g/W). `wheel_radius`
/// infinite is a cone.
fn closed_form(delta0: f64, l0: f64, r0: f64, wheel_radius: f64, rail_radius: f64) -> [f64; 4] {
    let (s, c) = delta0.sin_cos();
    let t = delta0.tan();
    let roll = t / (l0 - r0 * t);
    let numerator = 1.0 + (r0 + rail_radius * c) * roll;
    // θ' and R_w θ' (finite for the cone).
    let (theta, rw_theta) = if wheel_radius.is_finite() {
        let theta = numerator / ((wheel_radius - rail_radius) * c);
        (theta, wheel_radius * theta)
    } else {
        (0.0, numerator / c)
    };
    let g = l0 * c - r0 * s;
    let stiffness = theta + roll + t * ((l0 * s + r0 * c) * theta + rw_theta) / g;
    [s * rw_theta, l0 * theta, l0 * roll, stiffness]
}

/// An upright rail head: a crown arc of `radius` (m) over ±`half_angle` (rad), R5 corners and
/// 80° flanks.
fn round_rail(radius: f64, half_angle: f64) -> Profile {
    let flank = 80f64.to_radians();
    ProfileBuilder::new(-0.05, -0.05, flank)
        .line(0.03)
        .arc(0.005, -(flank - half_angle))
        .arc(radius, -2.0 * half_angle)
        .arc(0.005, -(flank - half_angle))
        .line(0.03)
        .build(&format!("R{radius}"), ProfileKind::Rail, 1e-4)
        .unwrap()
}

/// A wheel tread of slope `slope` at the taping line: a cone, or a concave arc of `radius` (m).
fn tread(slope: f64, radius: f64) -> Profile {
    let alpha = slope.atan();
    if radius.is_infinite() {
        return ProfileBuilder::new(-0.1, -0.1 * slope, alpha)
            .line(0.2 * (1.0 + slope * slope).sqrt())
            .build("cone", ProfileKind::Wheel, 1e-4)
            .unwrap();
    }
    // Clockwise arc through the origin with direction α there, starting β before it.
    let beta = 0.12 / radius;
    let (cy, cz) = (radius * alpha.sin(), -radius * alpha.cos());
    let start = alpha + beta;
    ProfileBuilder::new(cy - radius * start.sin(), cz + radius * start.cos(), start)
        .arc(radius, -2.0 * beta)
        .build("arc", ProfileKind::Wheel, 1e-4)
        .unwrap()
}

fn geometry(wheel: &Profile, rail: &Profile, inclination: f64) -> ContactGeometry {
    let track = TrackSetup {
        rail_inclination: inclination,
        ..TrackSetup::default()
    };
    ContactGeometry::symmetric(
        wheel,
        rail,
        &track,
        &WheelsetSetup::default(),
        &ContactSearchParams::default(),
    )
    .unwrap()
}

fn check(label: &str, got: &LinearContactParameters, expected: [f64; 4], tolerance: f64) {
    let values = [
        got.conicity,
        got.contact_angle_parameter,
        got.roll_parameter,
        got.gravitational_stiffness_per_load,
    ];
    for ((name, value), want) in ["λ", "ε", "σ", "K_g/W"].iter().zip(values).zip(expected) {
        eprintln!("{label}: {name} = {value:.6e}, closed form {want:.6e}");
        // ε of a cone is 0: compared on the scale 0.05 (an absolute 1e-4 at the tolerance 2e-3).
        let scale = want.abs().max(0.05);
        assert!(
            (value - want).abs() <= tolerance * scale,
            "{label}: {name} = {value}, closed form {want}"
        );
    }
}

#[test]
fn cone_on_a_knife_edge_has_no_contact_angle_parameter() {
    for lambda in [0.02, 0.04, 0.1, 0.3] {
        let (wheel, rail) = conical_pair(lambda).unwrap();
        let p = linear_parameters(
            &geometry(&wheel, &rail, (1.0f64 / 40.0).atan()),
            DEFAULT_AMPLITUDE,
        )
        .unwrap();
        // The contact normal is the cone's: δ0 = atan λ whatever the rail.
        assert!((p.contact_angle - lambda.atan()).abs() < 1e-6, "{p:?}");
        assert!(p.contact_angle_parameter.abs() < 1e-4, "ε = {p:?}");
        // The built-in knife edge is a 10 mm crown.
        let want = closed_form(
            p.contact_angle,
            p.half_contact_spacing,
            p.rolling_radius,
            f64::INFINITY,
            0.01,
        );
        check(&format!("cone {lambda} on knife edge"), &p, want, 2e-3);
        // No stiffness from the contact angles, but the rolled axle and the load transfer give
        // about 2δ0/l0 at small δ0 (module documentation).
        if lambda <= 0.04 {
            let rough = 2.0 * lambda / p.half_contact_spacing;
            assert!((p.gravitational_stiffness_per_load / rough - 1.0).abs() < 0.1);
        }
    }
}

#[test]
fn cone_on_a_round_rail_head_matches_the_closed_form() {
    for (lambda, rail_radius) in [(0.04, 0.3), (0.1, 0.3), (0.04, 0.08), (0.15, 0.08)] {
        let p = linear_parameters(
            &geometry(
                &tread(lambda, f64::INFINITY),
                &round_rail(rail_radius, 0.25),
                0.0,
            ),
            DEFAULT_AMPLITUDE,
        )
        .unwrap();
        assert!((p.contact_angle - lambda.atan()).abs() < 1e-6, "{p:?}");
        assert!(p.contact_angle_parameter.abs() < 1e-4, "{p:?}");
        let want = closed_form(
            p.contact_angle,
            p.half_contact_spacing,
            p.rolling_radius,
            f64::INFINITY,
            rail_radius,
        );
        check(&format!("cone {lambda} on R{rail_radius}"), &p, want, 2e-3);
    }
}

#[test]
fn arc_wheel_on_a_round_rail_head_matches_the_closed_form() {
    for (slope, wheel_radius, rail_radius) in
        [(0.05, 0.5, 0.3), (0.05, 0.3, 0.08), (0.1, 0.5, 0.08)]
    {
        let p = linear_parameters(
            &geometry(
                &tread(slope, wheel_radius),
                &round_rail(rail_radius, 0.25),
                0.0,
            ),
            DEFAULT_AMPLITUDE,
        )
        .unwrap();
        let want = closed_form(
            p.contact_angle,
            p.half_contact_spacing,
            p.rolling_radius,
            wheel_radius,
            rail_radius,
        );
        check(
            &format!("R{wheel_radius} wheel ({slope}) on R{rail_radius}"),
            &p,
            want,
            5e-3,
        );
        // Conformal circles: ε is large, the gravitational stiffness well above the cone's.
        assert!(p.contact_angle_parameter > 1.0, "{p:?}");
    }
}

#[test]
fn bad_amplitude_and_axle_load_are_refused_by_name() {
    let (wheel, rail) = conical_pair(0.1).unwrap();
    let g = geometry(&wheel, &rail, 0.0);
    for bad in [0.0, -1e-3, f64::NAN, 0.02] {
        let err = linear_parameters(&g, bad).unwrap_err().to_string();
        assert!(err.contains("amplitude"), "{err}");
    }
    let p = linear_parameters(&g, DEFAULT_AMPLITUDE).unwrap();
    let err = p.gravitational_stiffness(-1.0).unwrap_err().to_string();
    assert!(err.contains("axle_load"), "{err}");
    assert_eq!(
        p.gravitational_stiffness(2e5).unwrap(),
        2e5 * p.gravitational_stiffness_per_load
    );
}
