//! A vehicle with its scenario's contact on perfect track, built once for the analyses that need
//! the system at several speeds (linearisation, linear and nonlinear critical speeds).

use crate::dampers::Damper;
use crate::error::Result;
use crate::track::TrackIrregularity;
use crate::vehicle::model::structure::{IntoVehicle, VehicleStructure};
use crate::vehicle::rail_contact::wheel_rail::WheelRail;
use crate::vehicle::scenarios::scenario::{build_track, start_distance, Scenario, TrackSpec};
use crate::vehicle::scenarios::scenario_contact::shared_wheel_rail;
use crate::vehicle::system::simulation::VehicleSystem;
use std::sync::Arc;

/// A vehicle with its scenario's contact on perfect track, built once for analyses that need
/// the system at several speeds (linearisation, critical speeds).
pub struct PerfectTrackVehicle {
    structure: Arc<VehicleStructure>,
    wheel_rail: Arc<WheelRail>,
    track: Arc<TrackIrregularity>,
    yaw_damper: Option<Damper>,
    step: f64,
}

impl PerfectTrackVehicle {
    /// Builds the vehicle (unless given built), the scenario's contact and a perfect track of
    /// the scenario's length.
    pub fn new(vehicle: impl IntoVehicle, scenario: &Scenario) -> Result<Self> {
        scenario.validate()?;
        Self::of_valid(vehicle, scenario)
    }

    /// [`Self::new`] for a scenario its caller has validated.
    pub(crate) fn of_valid(vehicle: impl IntoVehicle, scenario: &Scenario) -> Result<Self> {
        let structure = vehicle.into_vehicle()?;
        let wheel_rail = shared_wheel_rail(&structure.parameters, scenario)?;
        let perfect = Scenario {
            track: TrackSpec::Perfect,
            ..scenario.clone()
        };
        let track = Arc::new(build_track(&perfect, &structure)?);
        Ok(Self {
            structure,
            wheel_rail,
            track,
            yaw_damper: scenario.yaw_damper,
            step: scenario.run.step,
        })
    }

    /// The system running at `speed` (m/s), not yet in equilibrium.
    pub fn system(&self, speed: f64) -> Result<VehicleSystem> {
        self.system_with_step(speed, self.step)
    }

    /// As [`Self::system`], its dampers built for the RK4 step `step` (s) instead of the
    /// scenario's.
    pub fn system_with_step(&self, speed: f64, step: f64) -> Result<VehicleSystem> {
        VehicleSystem::new(
            self.structure.clone(),
            self.wheel_rail.clone(),
            self.track.clone(),
            speed,
            start_distance(&self.structure),
            self.yaw_damper.as_ref(),
            step,
        )
    }
}
