//! Simulating a [`Scenario`]: the static equilibrium at a step the vehicle is stable with, the
//! time integration, the metrics; and the state matrix on perfect track.

use crate::error::Result;
use crate::track::TrackIrregularity;
use crate::vehicle::analysis::stiffest_mode::in_equilibrium_at_stable_step;
use crate::vehicle::curving::track_frame::CurvedTrack;
use crate::vehicle::model::structure::{IntoVehicle, VehicleStructure};
use crate::vehicle::output::run::{run, Recorded, RunOutput, RunSettings};
use crate::vehicle::rail_contact::track_limits::TrackLimits;
use crate::vehicle::rail_contact::wheel_rail::WheelRail;
use crate::vehicle::scenarios::perfect_track::PerfectTrackVehicle;
use crate::vehicle::scenarios::scenario::{build_track, curve_design, start_distance, Scenario};
use crate::vehicle::scenarios::scenario_contact::shared_wheel_rail;
use crate::vehicle::system::simulation::VehicleSystem;
use crate::vehicle::system::statics::StaticsSettings;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// A run's channels, metrics and cost.
#[derive(Debug, Clone)]
pub struct SimulationResult {
    pub output: RunOutput,
    pub metrics: crate::metrics::RunMetrics,
    pub statistics: crate::vehicle::system::run_statistics::RunStatistics,
}

/// Simulates a scenario with prepared contact and track (batches share them across samples),
/// recording the `recorded` channels.
pub fn simulate_prepared(
    structure: Arc<VehicleStructure>,
    wheel_rail: Arc<WheelRail>,
    track: Arc<TrackIrregularity>,
    scenario: &Scenario,
    recorded: Recorded,
    cancel: Option<&AtomicBool>,
) -> Result<SimulationResult> {
    scenario.validate()?;
    run_prepared(structure, wheel_rail, track, scenario, recorded, cancel)
}

/// [`simulate_prepared`] of a scenario its caller has validated (a batch checks its scenario
/// once, not once per sample).
pub(crate) fn run_prepared(
    structure: Arc<VehicleStructure>,
    wheel_rail: Arc<WheelRail>,
    track: Arc<TrackIrregularity>,
    scenario: &Scenario,
    recorded: Recorded,
    cancel: Option<&AtomicBool>,
) -> Result<SimulationResult> {
    let started = std::time::Instant::now();
    TrackLimits::of(&wheel_rail).check(&track)?;
    let start = start_distance(&structure);
    let bogie_mass = crate::vehicle::model::bogie_mass::en14363_bogie_mass(&structure)?;
    let design = if scenario.curve.is_empty() {
        None
    } else {
        Some(Arc::new(curve_design(&wheel_rail, &scenario.curve)?))
    };
    let build = |step: f64| -> Result<VehicleSystem> {
        let mut system = VehicleSystem::new(
            Arc::clone(&structure),
            Arc::clone(&wheel_rail),
            Arc::clone(&track),
            scenario.speed,
            start,
            scenario.yaw_damper.as_ref(),
            step,
        )?;
        system.integrator = scenario.run.integrator;
        if let Some(design) = &design {
            system.curve = Some(Arc::new(CurvedTrack::new(
                Arc::clone(design),
                &system.structure,
            )));
        }
        Ok(system)
    };
    // The scenario's step is the longest: a vehicle stiffer than it suits runs at a whole
    // fraction of it.
    let (mut system, equilibrium, step) =
        in_equilibrium_at_stable_step(scenario.run.step, &StaticsSettings::default(), build)?;
    if step != scenario.run.step {
        crate::vehicle::scenarios::scenario::cost::check_cost(&Scenario {
            run: RunSettings {
                step,
                ..scenario.run
            },
            ..scenario.clone()
        })?;
    }
    let mut y = equilibrium.state;
    if scenario.initial_lateral_offset != 0.0 {
        // On the rails: rise and roll follow the contact table, as in the critical-speed ramp.
        crate::vehicle::runs::critical_speed::disturb(
            &system,
            &mut y,
            scenario.initial_lateral_offset,
        );
    }
    let settings = RunSettings {
        step,
        duration: scenario.distance / scenario.speed,
        settle: scenario.lead_in / scenario.speed,
        ..scenario.run
    };
    let output = run(&mut system, &mut y, &settings, recorded, cancel)?;
    let metrics = crate::vehicle::output::run_metrics::run_metrics_or_undefined(
        &output,
        scenario.speed,
        bogie_mass,
    )?;
    let mut statistics = system.statistics;
    statistics.wall_time = started.elapsed().as_secs_f64();
    Ok(SimulationResult {
        output,
        metrics,
        statistics,
    })
}

/// The state matrix of the vehicle linearised about its static equilibrium at the scenario's
/// speed on perfect track (row-major n×n), with n (coordinates, velocities, damper states).
pub fn linearised(vehicle: impl IntoVehicle, scenario: &Scenario) -> Result<(Vec<f64>, usize)> {
    let mut system = PerfectTrackVehicle::new(vehicle, scenario)?.system(scenario.speed)?;
    let (a, _) = crate::vehicle::analysis::linearise::linearise(&mut system)?;
    let n = system.len_states();
    Ok((a, n))
}

/// Simulates a scenario for a vehicle (a parameter set or a built structure): builds the
/// vehicle when needed, the contact and the track.
pub fn simulate(vehicle: impl IntoVehicle, scenario: &Scenario) -> Result<SimulationResult> {
    simulate_cancellable(vehicle, scenario, None)
}

/// As [`simulate`]; `cancel`, when set from another thread, stops the run with `Interrupted`
/// within a step (Ctrl-C in the Python front end).
pub fn simulate_cancellable(
    vehicle: impl IntoVehicle,
    scenario: &Scenario,
    cancel: Option<&AtomicBool>,
) -> Result<SimulationResult> {
    scenario.validate()?;
    let structure = vehicle.into_vehicle()?;
    let wheel_rail = shared_wheel_rail(&structure.parameters, scenario)?;
    let track = Arc::new(build_track(scenario, &structure)?);
    run_prepared(
        structure,
        wheel_rail,
        track,
        scenario,
        Recorded::Every,
        cancel,
    )
}
