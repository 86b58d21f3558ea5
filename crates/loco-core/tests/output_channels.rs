//! The output channels of a run: one list of names ([`channel_names`]) shared by `run` and the
//! batch binary's check of a study's channels, with a force channel for every damper.

use loco_core::vehicle::model::suspension::DamperRole;
use loco_core::vehicle::output::run::channel_names;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::perfect_track::PerfectTrackVehicle;
use loco_core::vehicle::scenarios::scenario::Scenario;
use std::collections::HashSet;

/// S_norm at 200 km/h over `distance` (m) of synthesised track (seed 3).
fn scenario(distance: f64) -> Scenario {
    Scenario::study("S_norm", 200.0 / 3.6, distance, 3).unwrap()
}

#[test]
fn names_are_unique_and_cover_every_damper() {
    let s = scenario(20.0);
    let system = PerfectTrackVehicle::new(ParameterSet::default_vehicle(), &s)
        .unwrap()
        .system(s.speed)
        .unwrap();
    let names = channel_names(&system.structure).unwrap();
    let unique: HashSet<&String> = names.iter().collect();
    assert_eq!(unique.len(), names.len(), "duplicate channel names");
    // Names other code and tests rely on.
    for old in [
        "carbody_floor_ay_front",
        "frame1_ay_wheelset1",
        "wheelset1_y",
        "wheel1_left_YQ",
        "yaw_damper_bogie1_left_force",
        "yaw_damper_bogie1_left_valve",
        "secondary_lateral_damper_bogie1_1_force",
    ] {
        assert!(names.iter().any(|n| n == old), "no channel {old}");
    }
    for damper in &system.dampers {
        let force = format!("{}_force", damper.placement.name);
        assert!(names.contains(&force), "no force channel for {force}");
    }
    let count = |role| {
        system
            .dampers
            .iter()
            .filter(|d| d.placement.role == role)
            .count()
    };
    // Two per wheelset, two per bogie (SPEC §1: primary and secondary vertical dampers).
    assert_eq!(count(DamperRole::PrimaryVertical), 8);
    assert_eq!(count(DamperRole::SecondaryVertical), 4);
    assert!(names.contains(&"primary_vertical_damper_wheelset1_left_force".to_string()));
    assert!(names.contains(&"secondary_vertical_damper_bogie2_right_force".to_string()));
}

#[test]
fn run_records_the_listed_channels_and_vertical_damper_forces() {
    let s = scenario(20.0);
    let system = PerfectTrackVehicle::new(ParameterSet::default_vehicle(), &s)
        .unwrap()
        .system(s.speed)
        .unwrap();
    let listed = channel_names(&system.structure).unwrap();
    let result = simulate(ParameterSet::default_vehicle(), &s).unwrap();
    assert_eq!(result.output.names, listed);
    // On an irregular track the vertical dampers work: their force histories are not all zero.
    for name in [
        "primary_vertical_damper_wheelset1_left_force",
        "secondary_vertical_damper_bogie1_left_force",
    ] {
        let force = result.output.channel(name).unwrap();
        assert!(force.iter().all(|f| f.is_finite()), "{name} not finite");
        let peak = force.iter().fold(0.0f64, |m, f| m.max(f.abs()));
        assert!(peak > 1.0, "{name}: peak {peak} N");
    }
}

/// On straight track an accelerometer reads the acceleration channel plus the gravity its
/// body's roll tilts into it, g φ, to first order (with the products φ a_z − ψ a_x of the
/// point's other components): checked at the end of 1.5 s on synthesised track.
#[test]
fn on_straight_track_the_accelerometers_add_the_gravity_of_the_bodys_roll() {
    use loco_core::vehicle::model::layout::*;
    use loco_core::vehicle::model::structure::VehicleStructure;
    use loco_core::vehicle::output::channel_set::ChannelSet;
    use loco_core::vehicle::output::run::{run, Recorded, RunSettings};
    use loco_core::vehicle::scenarios::scenario::{build_track, start_distance};
    use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
    use loco_core::vehicle::system::simulation::VehicleSystem;
    use loco_core::vehicle::system::statics::{static_equilibrium, StaticsSettings};
    use loco_core::vehicle::time::integrator::OdeSystem;
    use std::sync::Arc;
    let s = scenario(100.0);
    let structure = Arc::new(VehicleStructure::new(ParameterSet::default_vehicle()).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, &s).unwrap());
    let track = Arc::new(build_track(&s, &structure).unwrap());
    let start = start_distance(&structure);
    let mut system =
        VehicleSystem::new(structure, wr, track, s.speed, start, None, s.run.step).unwrap();
    let mut y = static_equilibrium(&mut system, &StaticsSettings::default())
        .unwrap()
        .state;
    let settings = RunSettings {
        duration: 1.5,
        ..s.run
    };
    run(&mut system, &mut y, &settings, Recorded::Every, None).unwrap();
    let mut dy = vec![0.0; y.len()];
    system.derivatives(settings.duration, &y, &mut dy);
    let set = ChannelSet::new(&system.structure).unwrap();
    let mut values = Vec::new();
    set.sample(&system, &y, &dy, |v| values.push(v));
    let value = |name: &str| values[set.names().iter().position(|n| n == name).unwrap()];
    let g = system.structure.gravity;
    let cases = [
        ("carbody_floor", "front", CARBODY),
        ("carbody_floor", "rear", CARBODY),
        ("frame1", "centre", frame(0)),
        ("frame1", "wheelset2", frame(0)),
        ("frame2", "wheelset3", frame(1)),
    ];
    for (at, tag, body) in cases {
        let relative = value(&format!("{at}_ay_{tag}"));
        let sensed = value(&format!("{at}_accelerometer_y_{tag}"));
        let (roll, yaw) = (y[body + ROLL], y[body + YAW]);
        let gravity = g * roll;
        // The first-order products with the point's vertical and longitudinal accelerations
        // (below 1 m/s² on this track).
        let products = 1.0 * (roll.abs() + yaw.abs());
        println!(
            "{at} {tag}: relative {relative:.5}, sensed {sensed:.5}, g·φ {gravity:.2e}, \
             bound of the products {products:.1e}"
        );
        assert!(gravity != 0.0 && sensed != relative);
        assert!(
            (sensed - relative - gravity).abs() <= products,
            "{at} {tag}: {sensed} − {relative} against g·φ = {gravity}"
        );
    }
    // The vertical reads g plus the relative acceleration (to first order).
    let vertical = value("carbody_floor_accelerometer_z_front");
    assert!((vertical - g - value("carbody_floor_az_front")).abs() < 1e-3 * g);
}
