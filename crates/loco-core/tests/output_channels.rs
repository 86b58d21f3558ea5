//! The output channels of a run: one list of names ([`channel_names`]) shared by `run` and the
//! batch binary's check of a study's channels, with a force channel for every damper.

use loco_core::vehicle::parameters::ParameterSet;
use loco_core::vehicle::run::channel_names;
use loco_core::vehicle::scenario::{simulate, PerfectTrackVehicle, Scenario};
use loco_core::vehicle::suspension::DamperRole;
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
