//! Test support shared by the curving integration tests: the locomotive run on a designed
//! alignment from its static equilibrium, with the system and final state kept for inspection
//! (`vehicle::runs::simulate` keeps neither).

use loco_core::track::DesignSection;
use loco_core::vehicle::analysis::stiffest_mode::stable_step;
use loco_core::vehicle::curving::track_frame::CurvedTrack;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::output::run::{run, Recorded, RunOutput, RunSettings};
use loco_core::vehicle::rail_contact::wheel_rail::WheelRail;
use loco_core::vehicle::scenarios::scenario::{
    build_track, curve_design, start_distance, Scenario,
};
use loco_core::vehicle::system::simulation::VehicleSystem;
use loco_core::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use loco_core::vehicle::time::integrator::OdeSystem;
use std::sync::Arc;

pub mod cone;

/// A run on a curve: its recorded output, the system after it (contact, last wheel forces), its
/// final state (coordinates, velocities, damper states) and that state's derivatives.
// Each test binary that includes this module reads only some of the fields.
#[allow(dead_code)]
pub struct CurveRun {
    pub output: RunOutput,
    pub system: VehicleSystem,
    pub y: Vec<f64>,
    pub dy: Vec<f64>,
}

/// Runs `structure` on `wr` and `scenario`'s track along `sections` at `speed` (m/s) over
/// `distance` (m), from the static equilibrium at the start.
pub fn run_on_curve(
    structure: Arc<VehicleStructure>,
    wr: Arc<WheelRail>,
    scenario: &Scenario,
    sections: &[DesignSection],
    speed: f64,
    distance: f64,
) -> CurveRun {
    let track = Arc::new(build_track(scenario, &structure).unwrap());
    let design = Arc::new(curve_design(&wr, sections).unwrap());
    let start = start_distance(&structure);
    let mut system = VehicleSystem::new(
        structure.clone(),
        wr,
        track,
        speed,
        start,
        None,
        scenario.run.step,
    )
    .unwrap();
    system.curve = Some(Arc::new(CurvedTrack::new(design, &structure)));
    let equilibrium = static_equilibrium(&mut system, &StaticsSettings::default()).unwrap();
    // The step a run takes (the stable-step rule of `simulate`).
    let step = stable_step(&system, &equilibrium, scenario.run.step).unwrap();
    let mut y = equilibrium.state;
    let settings = RunSettings {
        duration: distance / speed,
        step,
        ..scenario.run
    };
    let output = run(&mut system, &mut y, &settings, Recorded::Every, None).unwrap();
    let mut dy = vec![0.0; y.len()];
    system.derivatives(settings.duration, &y, &mut dy);
    CurveRun {
        output,
        system,
        y,
        dy,
    }
}
