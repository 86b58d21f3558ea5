//! Failures of the model name what caused them: the RK4 step against the vehicle's stiffest mode
//! (the predicted limit separates steps that run, divided into a few substeps where needed, from
//! steps that are refused), and parameters
//! allowed outside their physical range as suspects of an equilibrium or a divergence.

use loco_core::vehicle::analysis::stiffest_mode::{
    stiffest_mode, MAX_SUBSTEPS, RK4_IMAGINARY_LIMIT,
};
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::{build_track, start_distance, Scenario, TrackSpec};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use loco_core::vehicle::system::simulation::VehicleSystem;
use loco_core::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use loco_core::vehicle::time::integrator::Integrator;
use loco_core::LocoError;
use std::sync::Arc;

/// A short run with RK4 at `step` (s): these limits are RK4's (the exponential scheme solves the
/// bearings, the stiffest springs, exactly).
fn scenario(step: f64) -> Scenario {
    let mut s = Scenario::study("S_norm", 200.0 / 3.6, 3.0, 0).unwrap();
    s.track = TrackSpec::Perfect;
    s.run.step = step;
    s.run.integrator = Integrator::Rk4;
    s
}

fn research(key: &str, value: f64) -> ParameterSet {
    let mut set = ParameterSet::default_vehicle();
    set.allow_out_of_range(key).unwrap();
    set.set(key, value).unwrap();
    set
}

fn stiffest(set: ParameterSet) -> (f64, String) {
    let s = scenario(1e-3);
    let structure = Arc::new(VehicleStructure::new(set).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, &s).unwrap());
    let track = Arc::new(build_track(&s, &structure).unwrap());
    let start = start_distance(&structure);
    let mut sys = VehicleSystem::new(structure, wr, track, s.speed, start, None, 1e-3).unwrap();
    sys.integrator = Integrator::Rk4;
    let eq = static_equilibrium(&mut sys, &StaticsSettings::default()).unwrap();
    let mode = stiffest_mode(&sys, &eq);
    (mode.omega, mode.coordinate)
}

#[test]
fn the_default_vehicle_is_stable_at_the_default_step() {
    let (omega, _) = stiffest(ParameterSet::default_vehicle());
    // Its stiffest mode is well above the study's band and inside RK4's limit at 1 ms.
    assert!(omega > 2.0 * std::f64::consts::PI * 50.0, "{omega}");
    assert!(omega * 1e-3 < RK4_IMAGINARY_LIMIT, "{omega}");
    assert!(simulate(ParameterSet::default_vehicle(), &scenario(1e-3)).is_ok());
}

#[test]
fn a_step_beyond_the_stiffest_modes_limit_is_divided_and_far_beyond_refused_naming_step() {
    // Quill bearings twice the stiffest of the range: the hollow shafts' bearing mode needs a
    // few substeps of the 1 ms step. The run takes the longest stable whole fraction of it and
    // is then the run of that explicit step, sample for sample.
    let key = "hollow_shaft.bearing_radial_stiffness";
    let set = research(key, 2e10);
    let (omega, coordinate) = stiffest(set.clone());
    assert!(omega * 1e-3 > RK4_IMAGINARY_LIMIT, "{omega}");
    assert!(
        coordinate.starts_with("hollow_shaft") || coordinate.starts_with("motor"),
        "{coordinate}"
    );
    let k = (omega * 1e-3 / RK4_IMAGINARY_LIMIT).ceil();
    assert!((2.0..=MAX_SUBSTEPS).contains(&k), "{k}");
    let divided = simulate(set.clone(), &scenario(1e-3)).unwrap();
    let explicit = simulate(set, &scenario(1e-3 / k)).unwrap();
    assert_eq!(divided.output, explicit.output);
    assert_eq!(divided.statistics.steps, explicit.statistics.steps);
    assert!(divided
        .output
        .channels
        .iter()
        .flatten()
        .all(|v| v.is_finite()));
    // A hundred times stiffer: more than MAX_SUBSTEPS, refused naming the step, the mode's
    // coordinate and the out-of-range stiffness as the suspect.
    let set = research(key, 2e12);
    let (omega, coordinate) = stiffest(set.clone());
    assert!(omega * 1e-3 > MAX_SUBSTEPS * RK4_IMAGINARY_LIMIT, "{omega}");
    let e = simulate(set.clone(), &scenario(1e-3))
        .unwrap_err()
        .to_string();
    assert!(e.contains("`step`") && e.contains(&coordinate), "{e}");
    assert!(
        e.contains(key),
        "the out-of-range stiffness is the suspect: {e}"
    );
    // Half the predicted limit (a whole number of steps per 500 Hz output sample) runs.
    let limit = RK4_IMAGINARY_LIMIT / omega;
    let step = 2e-3 / (2e-3 / (0.5 * limit)).ceil();
    let run = simulate(set, &scenario(step)).unwrap();
    assert!(run.output.channels.iter().flatten().all(|v| v.is_finite()));
}

#[test]
fn an_unrestrained_coordinate_is_an_equilibrium_error_naming_it_and_the_suspect() {
    let key = "traction_rod.carbody_bushing_stiffness_y";
    let e = simulate(research(key, 1e-30), &scenario(1e-3)).unwrap_err();
    assert!(matches!(e, LocoError::Equilibrium { .. }), "{e:?}");
    let e = e.to_string();
    assert!(
        e.contains("singular at coordinate `") && e.contains(key),
        "{e}"
    );
}

#[test]
fn a_failure_of_the_run_names_the_out_of_range_parameter() {
    // A motor of no mass: its mode is far beyond any step (or the run diverges).
    let key = "traction_motor.mass";
    let e = simulate(research(key, 1e-30), &scenario(1e-3))
        .unwrap_err()
        .to_string();
    assert!(e.contains(&format!("`{key}` = 1e-30 kg")), "{e}");
}
