//! Verification of the 90-DOF locomotive against independent results: static equilibrium, rest
//! on perfect track, symmetry, Klingel's kinematic wavelength, determinism, divergence and
//! derailment (stability: `vehicle_stability.rs`).

use crate::record::Record;
use loco_core::track::TrackIrregularity;
use loco_core::vehicle::model::layout::*;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::{build_track, start_distance, Scenario, TrackSpec};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use loco_core::vehicle::system::simulation::{SpeedProfile, VehicleSystem};
use loco_core::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use loco_core::vehicle::time::integrator::OdeSystem;
use loco_core::LocoError;
use std::sync::Arc;

/// Sets a research value outside the parameter's physical range, allowed explicitly.
pub(crate) fn research(p: &mut ParameterSet, key: &str, value: f64) {
    p.allow_out_of_range(key).unwrap();
    p.set(key, value).unwrap();
}

pub(crate) fn perfect(name: &str, speed: f64, distance: f64) -> Scenario {
    let mut s = Scenario::study(name, speed, distance, 0).unwrap();
    s.track = TrackSpec::Perfect;
    s
}

pub(crate) fn system(parameters: ParameterSet, scenario: &Scenario) -> VehicleSystem {
    let structure = Arc::new(VehicleStructure::new(parameters).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, scenario).unwrap());
    let track = Arc::new(build_track(scenario, &structure).unwrap());
    let start = start_distance(&structure);
    VehicleSystem::new(structure, wr, track, scenario.speed, start, None, 5e-4).unwrap()
}

#[test]
fn static_wheel_loads_carry_the_weight_equally() {
    let scenario = perfect("S_norm", 50.0, 100.0);
    let mut sys = system(ParameterSet::default_vehicle(), &scenario);
    let settings = StaticsSettings::default();
    let equilibrium = static_equilibrium(&mut sys, &settings).unwrap();
    let y = equilibrium.state;
    let weight = sys.structure.total_mass() * sys.structure.gravity;
    assert!(equilibrium.iterations >= 1 && equilibrium.residual < settings.tolerance * weight);
    assert_eq!(
        sys.statistics.newton_iterations,
        equilibrium.iterations as u64
    );
    // Evaluate as the static search does (wheels held, nothing rolling).
    sys.contact_mode = settings.contact_mode();
    let mut dy = vec![0.0; sys.dimension()];
    sys.derivatives(0.0, &y, &mut dy);
    let loads: Vec<f64> = sys
        .wheel_forces
        .iter()
        .flatten()
        .map(|f| f.vertical)
        .collect();
    let total: f64 = loads.iter().sum();
    assert!(
        (total - weight).abs() < 1e-6 * weight,
        "{total} vs {weight}"
    );
    let mean = total / 8.0;
    let spread = loads.iter().fold(0.0_f64, |m, q| m.max((q - mean).abs())) / mean;
    for q in &loads {
        assert!(
            (q - mean).abs() < 1e-3 * mean,
            "unequal wheel loads {loads:?}"
        );
    }
    // In equilibrium nothing accelerates.
    let max_acc = dy[N_DOF..2 * N_DOF]
        .iter()
        .fold(0.0_f64, |m, a| m.max(a.abs()));
    assert!(max_acc < 1e-6, "residual acceleration {max_acc}");
    Record::new("statics_wheel_loads", file!())
        .below(
            "load_sum_error",
            (total - weight).abs() / weight,
            "",
            1e-12,
            "<",
            1e-6,
        )
        .within("load_spread", spread, "", 2, "<", 1e-3)
        .below("residual_acceleration", max_acc, "m/s²", 1e-9, "<", 1e-6)
        .check();
}

#[test]
fn vehicle_on_perfect_track_stays_at_rest() {
    let mut largest = 0.0_f64;
    let result = simulate(
        ParameterSet::default_vehicle(),
        &perfect("S_high", 200.0 / 3.6, 300.0),
    )
    .unwrap();
    for name in [
        "carbody_floor_ay_front",
        "frame1_ay_wheelset1",
        "wheelset1_y",
        "wheelset4_yaw",
    ] {
        let peak = result
            .output
            .channel(name)
            .unwrap()
            .iter()
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(peak < 1e-9, "{name} moved: {peak}");
        largest = largest.max(peak);
    }
    Record::new("rest_on_perfect_track", file!())
        .below("largest_motion", largest, "SI", 1e-12, "<", 1e-9)
        .check();
}

#[test]
fn symmetric_vertical_input_gives_no_lateral_response() {
    // Vertical profile only (both rails up and down together): the vehicle is symmetric about
    // its centre plane, so no lateral motion may appear.
    let n = 2700;
    let step = 0.1;
    let profile: Vec<f64> = (0..n)
        .map(|i| 2e-3 * (i as f64 * step * 2.0 * std::f64::consts::PI / 13.0).sin())
        .collect();
    let slope: Vec<f64> = (0..n)
        .map(|i| {
            2e-3 * 2.0 * std::f64::consts::PI / 13.0
                * (i as f64 * step * 2.0 * std::f64::consts::PI / 13.0).cos()
        })
        .collect();
    let zeros = vec![0.0; n];
    let values = [profile, zeros.clone(), zeros.clone(), zeros.clone()];
    let slopes = [slope, zeros.clone(), zeros.clone(), zeros];
    let track = TrackIrregularity::from_channels(step, &values, &slopes, 10.0, None).unwrap();
    let mut scenario = perfect("S_norm", 160.0 / 3.6, 240.0);
    scenario.track = TrackSpec::Given(Arc::new(track));
    let result = simulate(ParameterSet::default_vehicle(), &scenario).unwrap();
    let vertical = result
        .output
        .channel("carbody_floor_az_front")
        .unwrap()
        .iter()
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    assert!(
        vertical > 1e-3,
        "the input must excite the vehicle vertically ({vertical})"
    );
    let mut largest = 0.0_f64;
    for name in ["carbody_floor_ay_front", "frame1_ay_centre", "wheelset2_y"] {
        let peak = result
            .output
            .channel(name)
            .unwrap()
            .iter()
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(peak < 1e-9, "{name}: {peak}");
        largest = largest.max(peak);
    }
    Record::new("symmetric_vertical_input", file!())
        .value("vertical_floor_acceleration", vertical, "m/s²", 2)
        .below("largest_lateral_response", largest, "SI", 1e-12, "<", 1e-9)
        .check();
}

#[test]
fn same_inputs_give_bit_identical_results() {
    let scenario = Scenario::study("S_high", 200.0 / 3.6, 300.0, 7).unwrap();
    let a = simulate(ParameterSet::default_vehicle(), &scenario).unwrap();
    let b = simulate(ParameterSet::default_vehicle(), &scenario).unwrap();
    assert_eq!(a.output, b.output);
    assert_eq!(a.metrics.values(), b.metrics.values());
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let differing = (a.output.channels.iter().zip(&b.output.channels))
        .filter(|(x, y)| bits(x) != bits(y))
        .count();
    Record::new("determinism", file!())
        .count("channels_compared", a.output.channels.len())
        .within("channels_differing", differing as f64, "", 1, "=", 0.0)
        .check();
}

#[test]
fn an_absurdly_stiff_primary_spring_is_refused_for_the_step() {
    // 1.5e13 N/m per axle box (a million times the real spring) puts the wheelset's vertical mode
    // near 25 kHz, far outside RK4's stability region at 1 ms: the run would blow up within
    // steps, so it is refused at the equilibrium, naming the step and the suspect.
    let key = "primary.axle_box_spring_vertical_stiffness";
    let mut p = ParameterSet::default_vehicle();
    research(&mut p, key, 1.5e13);
    let e = simulate(p, &perfect("S_norm", 200.0 / 3.6, 100.0)).unwrap_err();
    assert!(
        matches!(&e, LocoError::InvalidParameter { name, .. } if name == "step"),
        "{e}"
    );
    assert!(e.to_string().contains(key), "{e}");
    // A mode of the bodies the springs join (frame on its wheelsets), tens of kHz.
    let e = e.to_string();
    assert!(
        e.contains("mostly `frame") || e.contains("mostly `wheelset"),
        "{e}"
    );
}

#[test]
fn runaway_states_diverge_and_a_bounded_wheelset_off_the_rail_derails() {
    let sys = system(
        ParameterSet::default_vehicle(),
        &perfect("S_norm", 50.0, 100.0),
    );
    let rest = vec![0.0; sys.dimension()];
    assert!(sys.check_state(1.0, &rest).is_ok());
    let with = |i: usize, v: f64| {
        let mut y = rest.clone();
        y[i] = v;
        sys.check_state(1.0, &y)
    };
    let diverged_at = |r: Result<(), LocoError>| match r {
        Err(LocoError::Diverged { location, .. }) => location,
        other => panic!("expected divergence, got {other:?}"),
    };
    assert_eq!(diverged_at(with(CARBODY + Z, 1.5)), "carbody.z");
    assert_eq!(diverged_at(with(frame(0) + YAW, -0.6)), "frame1.yaw");
    assert_eq!(
        diverged_at(with(hollow_shaft(2), 2.0)),
        "hollow_shaft3.y_rel"
    );
    assert_eq!(diverged_at(with(wheelset(1) + Y, 1.2)), "wheelset2.y");
    assert_eq!(
        diverged_at(with(N_DOF + motor(3) + X, f64::NAN)),
        "motor4.x (velocity)"
    );
    assert_eq!(diverged_at(with(motor(2) + X, 1.5)), "motor3.x");
    // Wheelset spin accumulates creep over a run: not bounded.
    assert!(with(wheelset(0) + PITCH, 3.0).is_ok());
    // The coasting vehicle falls behind the reference frame as a whole: not bounded either.
    let mut behind = rest.clone();
    let bodies = [CARBODY, frame(0), frame(1)]
        .into_iter()
        .chain((0..N_WHEELSETS).flat_map(|w| [wheelset(w), motor(w)]));
    for body in bodies {
        behind[body + X] = -3.0;
    }
    assert!(sys.check_state(1.0, &behind).is_ok());
    // Off the rail by 6 cm with everything else in place: a derailment, not divergence.
    match with(wheelset(1) + Y, 0.06) {
        Err(LocoError::Derailed { location, .. }) => assert_eq!(location, "wheelset2"),
        other => panic!("expected derailment, got {other:?}"),
    }
}

#[test]
fn a_speed_ramp_moves_every_wheelset_at_the_ramp_speed() {
    let mut sys = system(
        ParameterSet::default_vehicle(),
        &perfect("S_norm", 60.0, 100.0),
    );
    let at_rest = sys.wheelset_distance(0, 3.0);
    sys.speed = SpeedProfile::ramp(60.0, 0.5);
    // A ramp that has not been started holds its speed.
    assert_eq!(sys.speed_at(5.0), 60.0);
    assert_eq!(sys.wheelset_distance(0, 3.0), at_rest);
    sys.speed.start_ramp(2.0);
    // Before the ramp nothing changes; after it the speed falls by 0.5 m/s per second.
    assert_eq!(sys.speed_at(1.5), 60.0);
    assert!((sys.speed_at(12.0) - 55.0).abs() < 1e-12);
    assert!((at_rest - sys.wheelset_distance(0, 3.0) - 0.25).abs() < 1e-9);
    for w in 0..N_WHEELSETS {
        for t in [1.0, 2.5, 7.5, 30.0] {
            let h = 1e-4;
            let rate =
                (sys.wheelset_distance(w, t + h) - sys.wheelset_distance(w, t - h)) / (2.0 * h);
            assert!(
                (rate - sys.speed_at(t)).abs() < 1e-6,
                "wheelset {w} at {t} s: {rate}"
            );
        }
    }
}

/// The recorded yaw-damper stroke is the elongation the damper law sees: for a Maxwell damper
/// (c in series with k) the recorded force obeys F = c·(ẋ − Ḟ/k), checked with finite
/// differences of the recorded stroke x and force F; the two dampers of a hunting bogie
/// stroke in opposition.
#[test]
fn yaw_damper_strokes_obey_the_damper_law() {
    let mut scenario = Scenario::study("S_high", 200.0 / 3.6, 200.0, 0).unwrap();
    scenario.yaw_damper = Some(loco_core::dampers::Damper::yd1());
    let out = simulate(ParameterSet::default_vehicle(), &scenario)
        .unwrap()
        .output;
    let x = out.channel("yaw_damper_bogie1_left_stroke").unwrap();
    let f = out.channel("yaw_damper_bogie1_left_force").unwrap();
    let right = out.channel("yaw_damper_bogie1_right_stroke").unwrap();
    let (c, k) = (2.0e5, 22.5e6);
    let dt = 1.0 / out.sampling_rate;
    let (mut err, mut norm) = (0.0, 0.0);
    for i in 1..x.len() - 1 {
        let xd = (x[i + 1] - x[i - 1]) / (2.0 * dt);
        let fd = (f[i + 1] - f[i - 1]) / (2.0 * dt);
        err += (f[i] - c * (xd - fd / k)).powi(2);
        norm += f[i] * f[i];
    }
    assert!(
        (err / norm).sqrt() < 0.02,
        "damper law residual {}",
        (err / norm).sqrt()
    );
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (ml, mr) = (mean(x), mean(right));
    let cov: f64 = x.iter().zip(right).map(|(a, b)| (a - ml) * (b - mr)).sum();
    let var = |v: &[f64], m: f64| v.iter().map(|a| (a - m).powi(2)).sum::<f64>();
    let corr = cov / (var(x, ml) * var(right, mr)).sqrt();
    assert!(corr < -0.9, "left/right stroke correlation {corr}");
}
