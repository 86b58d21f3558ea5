//! The locomotive on the conical wheel and knife-edge rails of `contact::builtin::conical` (or
//! the S_norm pair), run into a balanced curve: shared by the quasi-static curving tests.
// Each test binary that includes this module uses only some of it.
#![allow(dead_code)]

use super::{run_on_curve, CurveRun};
use loco_core::contact::builtin::conical::conical_pair;
use loco_core::track::{CurveDirection, DesignSection};
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::rail_contact::wheel_rail::WheelRail;
use loco_core::vehicle::scenarios::scenario::{Scenario, TrackSpec};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use std::sync::Arc;

pub const G: f64 = 9.81;

/// Sets a research value outside the parameter's physical range, allowed explicitly.
pub fn research(p: &mut ParameterSet, key: &str, value: f64) {
    p.allow_out_of_range(key).unwrap();
    p.set(key, value).unwrap();
}

/// Runs the locomotive `p` on perfect track with the conical wheel of conicity `lambda` on
/// knife-edge rails (`contact::builtin::conical`; `lambda` 0: the S_norm profiles): 10 m
/// straight, a 60 m clothoid, then a left curve of `radius` (m) with the cant that balances
/// `speed` (m/s), over `distance` m.
pub fn run_cone(p: ParameterSet, lambda: f64, radius: f64, speed: f64, distance: f64) -> CurveRun {
    run_cone_towards(p, lambda, radius, speed, distance, CurveDirection::Left)
}

/// As [`run_cone`], the curve toward `direction`.
pub fn run_cone_towards(
    p: ParameterSet,
    lambda: f64,
    radius: f64,
    speed: f64,
    distance: f64,
    direction: CurveDirection,
) -> CurveRun {
    let mut scenario = Scenario::study("S_norm", speed, distance, 0).unwrap();
    scenario.track = TrackSpec::Perfect;
    if lambda > 0.0 {
        let (wheel, rail) = conical_pair(lambda).unwrap();
        scenario.wheel = wheel;
        scenario.rail = rail;
    }
    let structure = Arc::new(VehicleStructure::new(p).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, &scenario).unwrap());
    let b = wr.contact_half_distance();
    let cant = speed * speed / (G * radius) * 2.0 * b;
    let sections = vec![
        DesignSection::Straight { length: 10.0 },
        DesignSection::Transition {
            length: 60.0,
            cant_run_off: None,
        },
        DesignSection::Curve {
            length: 2000.0,
            radius,
            cant,
            direction,
        },
    ];
    run_on_curve(structure, wr, &scenario, &sections, speed, distance)
}

/// Half the distance between the centred wheelset's contact points, l (m), from the table.
pub fn half_distance(wr: &WheelRail) -> f64 {
    wr.table().lookup(0.0).wheels[0]
        .touching()
        .unwrap()
        .lateral
        .abs()
}
