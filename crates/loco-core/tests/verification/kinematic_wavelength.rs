//! Klingel's kinematic wavelength: a free wheelset and a rigid bogie on conical wheels against
//! their closed-form wavelengths.

use crate::record::Record;
use crate::vehicle_model::{perfect, research};
use loco_core::contact::builtin::conical::KNIFE_EDGE;
use loco_core::contact::hertz_table::HertzShapeTable;
use loco_core::contact::kalker::KalkerTable;
use loco_core::contact::profile::ProfileKind;
use loco_core::contact::profile_builder::ProfileBuilder;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::Scenario;
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;

/// A conical wheel (conicity `lambda`, no flange) on a rail with a sharp (10 mm) crown, the
/// textbook set-up of Klingel's analysis: the contact stays at the crown, the contact angle is the
/// cone's, so Δr = 2·λ_eff·y (λ_eff includes the wheelset's roll) and no gravitational stiffness
/// from a changing contact angle enters.
fn conical_scenario(lambda: f64, speed: f64, distance: f64) -> Scenario {
    let wheel = ProfileBuilder::new(-0.065, -0.065 * lambda, lambda.atan())
        .line(0.14)
        .build("cone", ProfileKind::Wheel, 5e-4)
        .unwrap();
    let flank = 80f64.to_radians();
    let rail = ProfileBuilder::new(-0.02, -0.04, flank)
        .line(0.03)
        .arc(0.01, -2.0 * flank)
        .line(0.03)
        // The knife edge of the idealised conical pair, by its name: on it a wheel needs no flange.
        .build(KNIFE_EDGE, ProfileKind::Rail, 2e-4)
        .unwrap();
    let mut s = perfect("S_norm", speed, distance);
    s.wheel = wheel;
    s.rail = rail;
    s.initial_lateral_offset = 2e-3;
    s
}

/// Wavelength (m) of a decaying or steady oscillation from its upward zero crossings.
fn wavelength(signal: &[f64], fs: f64, speed: f64) -> f64 {
    let crossings: Vec<f64> = signal
        .windows(2)
        .enumerate()
        .filter(|(_, w)| w[0] < 0.0 && w[1] >= 0.0)
        .map(|(i, w)| (i as f64 + w[0] / (w[0] - w[1])) / fs)
        .collect();
    assert!(crossings.len() >= 3, "too few cycles: {}", crossings.len());
    let periods = crossings.len() - 1;
    speed * (crossings[periods] - crossings[0]) / periods as f64
}

/// Kinematic quantities of the conical contact from its table: effective conicity λ (Δr/2y),
/// half distance between contact points e (m), centred rolling radius r0 (m), roll per lateral
/// displacement φ' (rad/m) and the ratio C22/C11 of Kalker's coefficients of the static contact.
struct Kinematics {
    lambda: f64,
    e: f64,
    r0: f64,
    roll_slope: f64,
    c22_over_c11: f64,
}

fn kinematics(parameters: &ParameterSet, scenario: &Scenario) -> Kinematics {
    let wr = build_wheel_rail(parameters, scenario).unwrap();
    let y = 1e-3;
    let c = wr.table().lookup(y);
    let centre = wr.table().lookup(0.0);
    let point = centre.wheels[0].touching().unwrap();
    // Static wheel load and its Hertz ellipse give a/b, hence Kalker's C11, C22.
    let structure = VehicleStructure::new(parameters.clone()).unwrap();
    let load = structure.total_mass() * structure.gravity / 8.0;
    let e_star = 2.1e11 / (2.0 * (1.0 - 0.28 * 0.28));
    let hertz = HertzShapeTable::new()
        .coefficients(
            0.5 / point.rolling_radius,
            0.5 * (point.wheel_curvature + point.rail_curvature),
            e_star,
        )
        .unwrap()
        .contact(load);
    let k = KalkerTable::new(0.28)
        .unwrap()
        .coefficients(hertz.semi_axis_long / hertz.semi_axis_lat);
    Kinematics {
        lambda: c.rolling_radius_difference() / (2.0 * y),
        e: point.lateral,
        r0: wr.centred_radius(),
        roll_slope: c.roll / y,
        c22_over_c11: k.c22 / k.c11,
    }
}

#[test]
fn free_wheelset_reproduces_klingels_wavelength() {
    // Primary positioning and the drive's coupling made negligible: each wheelset runs free, and
    // at 5 m/s creep dominates inertia, so the motion is kinematic. Klingel: L = 2π√(r0·e/λ).
    // The contact point also moves sideways with the wheelset's roll (r·φ̇, φ = φ'·y), so
    // creep-free rolling has (1 + r0·φ')·ẏ = V·ψ and L = 2π√(r0·e·(1 + r0·φ')/λ).
    let mut p = ParameterSet::default_vehicle();
    for key in ["K_px", "K_py"] {
        research(&mut p, key, 1e3);
    }
    for key in [
        "hollow_shaft.coupling_lateral_stiffness",
        "hollow_shaft.coupling_angular_stiffness",
    ] {
        research(&mut p, key, 1.0);
    }
    let speed = 5.0;
    let scenario = conical_scenario(0.05, speed, 150.0);
    let k = kinematics(&p, &scenario);
    let klingel =
        2.0 * std::f64::consts::PI * (k.r0 * k.e * (1.0 + k.r0 * k.roll_slope) / k.lambda).sqrt();
    let result = simulate(p, &scenario).unwrap();
    let measured = wavelength(result.output.channel("wheelset1_y").unwrap(), 500.0, speed);
    Record::new("klingel_wavelength", file!())
        .value("klingel", klingel, "m", 4)
        .value("measured", measured, "m", 4)
        .within(
            "deviation",
            (measured / klingel - 1.0).abs(),
            "",
            2,
            "<",
            0.01,
        )
        .check();
    assert!(
        (measured / klingel - 1.0).abs() < 0.01,
        "measured {measured:.2} m, Klingel {klingel:.2} m (λ = {:.4}, r0·φ' = {:.4})",
        k.lambda,
        k.r0 * k.roll_slope
    );
}

#[test]
fn rigid_bogie_reproduces_its_wavelength_formula() {
    // Stiff primary positioning, soft secondary suspension: each bogie is a rigid truck whose
    // kinematic wavelength (creep equilibrium of lateral force and yaw moment, Wickens) is
    // L = 2π√(r0·(1 + r0·φ')·(e/λ)·(1 + (C22/C11)·(b/e)²·(1 + r0·φ'))), b the half wheelbase;
    // with C22 = C11 and no roll term this is the textbook L_wheelset·√(1 + (b/e)²).
    let mut p = ParameterSet::default_vehicle();
    research(&mut p, "K_px", 1e9);
    research(&mut p, "K_py", 1e9);
    research(&mut p, "C_sx", 1e4);
    research(&mut p, "C_sy", 1e4);
    for key in [
        "secondary.flexicoil_longitudinal_stiffness",
        "secondary.flexicoil_lateral_stiffness",
        "secondary.flexicoil_bending_stiffness",
    ] {
        research(&mut p, key, 1.0);
    }
    for key in [
        "hollow_shaft.coupling_lateral_stiffness",
        "hollow_shaft.coupling_angular_stiffness",
    ] {
        research(&mut p, key, 1.0);
    }
    let speed = 5.0;
    let mut scenario = conical_scenario(0.05, speed, 250.0);
    // 1e9 N/m between frame and axle boxes is far stiffer than any real primary suspension; the
    // default 1 ms step is not accurate for it (ω·dt ≈ 1), half of it is.
    scenario.run.step = 5e-4;
    let k = kinematics(&p, &scenario);
    let b = p.get("layout.half_wheelbase").unwrap();
    let roll = 1.0 + k.r0 * k.roll_slope;
    let expected = 2.0
        * std::f64::consts::PI
        * (k.r0 * roll * k.e / k.lambda * (1.0 + k.c22_over_c11 * (b / k.e).powi(2) * roll)).sqrt();
    let result = simulate(p, &scenario).unwrap();
    let measured = wavelength(result.output.channel("wheelset1_y").unwrap(), 500.0, speed);
    Record::new("rigid_bogie_wavelength", file!())
        .value("wickens", expected, "m", 4)
        .value("measured", measured, "m", 4)
        .within(
            "deviation",
            (measured / expected - 1.0).abs(),
            "",
            2,
            "<",
            0.02,
        )
        .check();
    assert!(
        (measured / expected - 1.0).abs() < 0.02,
        "measured {measured:.2} m, formula {expected:.2} m (C22/C11 = {:.3})",
        k.c22_over_c11
    );
}
