//! The case the tools share (`run_fingerprint`, `sim_time`, `integrator_compare`,
//! `full_linear_etd`, `creep_replay`): the `vehicle` bench's 500 m run at 200 km/h on a study scenario, with a
//! creep model and a track chosen by name and parameters from `key=value` arguments, built up to
//! what `simulate_prepared` takes, and run.

use loco_core::error::Result;
use loco_core::track::{CurveDirection, DesignSection, TrackIrregularity};
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::output::run::Recorded;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::rail_contact::creep_model::CreepModel;
use loco_core::vehicle::rail_contact::wheel_rail::WheelRail;
use loco_core::vehicle::runs::simulate::{simulate_prepared, SimulationResult};
use loco_core::vehicle::scenarios::scenario::{build_track, Scenario};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use std::sync::Arc;

/// Scenario `name` (`S_high`, `S_low`, ...) at 200 km/h over 500 m, track seed 1, with the creep
/// model `creep` (`fastsim`, `fastrip`, `table`) on the track `track`: `curve` (a 60 m transition
/// into R = 1200 m with 100 mm cant, about 290 mm of cant deficiency), `study_curve` (R = 3000 m
/// with 60 mm cant, about 97 mm, a case of the curving study) or anything else for straight track.
pub fn scenario(creep: &str, name: &str, track: Option<&str>) -> Scenario {
    let mut scenario = Scenario {
        creep: CreepModel::from_name(creep).unwrap(),
        ..Scenario::study(name, 200.0 / 3.6, 500.0, 1).unwrap()
    };
    match track {
        Some("curve") => scenario.curve = DesignSection::reference_curve(0.1, CurveDirection::Left),
        Some("study_curve") => scenario.curve = DesignSection::study_curve(CurveDirection::Left),
        _ => {}
    }
    scenario
}

/// The default vehicle with each `key=value` of `overrides` set (SI values).
pub fn parameters<'a>(overrides: impl IntoIterator<Item = &'a String>) -> ParameterSet {
    let mut parameters = ParameterSet::default_vehicle();
    for kv in overrides {
        let (k, v) = kv.split_once('=').expect("key=value");
        parameters.set(k, v.parse().unwrap()).unwrap();
    }
    parameters
}

/// The vehicle of a parameter set, its contact and a scenario's track, built once: what
/// `simulate_prepared` takes.
pub struct Prepared {
    pub structure: Arc<VehicleStructure>,
    pub wheel_rail: Arc<WheelRail>,
    pub track: Arc<TrackIrregularity>,
}

impl Prepared {
    /// One run of `scenario` on the prepared vehicle, contact and track, recording `recorded`.
    pub fn run(&self, scenario: &Scenario, recorded: Recorded) -> Result<SimulationResult> {
        simulate_prepared(
            self.structure.clone(),
            self.wheel_rail.clone(),
            self.track.clone(),
            scenario,
            recorded,
            None,
        )
    }
}

/// The vehicle of `parameters`, its contact and `scenario`'s track, built once.
pub fn prepared(parameters: ParameterSet, scenario: &Scenario) -> Prepared {
    let structure = Arc::new(VehicleStructure::new(parameters).unwrap());
    let wheel_rail = Arc::new(build_wheel_rail(&structure.parameters, scenario).unwrap());
    let track = Arc::new(build_track(scenario, &structure).unwrap());
    Prepared {
        structure,
        wheel_rail,
        track,
    }
}
