//! Built wheel/rail contacts kept for reuse within the process ([`crate::util::kept`]).
//!
//! Why: building a contact (the contact table on ±25 mm at 0.1 mm with its relative-roll layers,
//! the creep solver) costs two thirds of a 500 m run (1.04·10⁹ instructions against 1.54·10⁹,
//! callgrind), and a campaign built one for every chunk it sent to a native batch (a few hundred
//! in `loco reproduce --full`), a single run one per call.
//!
//! The key is every input the build reads ([`WheelRailInputs`], the only thing the builder is
//! given, so no input can be missed).

use crate::contact::fastsim::FastsimParams;
use crate::contact::profile::Profile;
use crate::contact::setup::TrackSetup;
use crate::error::Result;
use crate::util::kept::Kept;
use crate::vehicle::params::parameters::ParameterSet;
use crate::vehicle::rail_contact::creep_model::CreepModel;
use crate::vehicle::rail_contact::wheel_rail::WheelRail;
use crate::vehicle::scenarios::scenario::{ContactParameters, Scenario};
use std::sync::Arc;

/// Contacts kept (the study's three wheel/rail pairs and a few variants): a contact is about
/// 1 MB (its table: ±25 mm at 0.1 mm, three roll layers), 10 MB with the tabulated FASTSIM.
pub const CAPACITY: usize = 8;

/// Everything the contact of a vehicle on a scenario's wheel and rail is built from.
#[derive(Debug)]
pub struct WheelRailInputs<'a> {
    /// The vehicle's contact parameters, checked.
    pub contact: ContactParameters,
    pub wheel: &'a Profile,
    pub rail: &'a Profile,
    pub track_setup: &'a TrackSetup,
    pub fastsim: &'a FastsimParams,
    pub creep: CreepModel,
}

impl<'a> WheelRailInputs<'a> {
    /// The inputs of the contact of the vehicle `parameters` on `scenario` (an error names the
    /// contact parameter that is out of range).
    pub fn of(parameters: &ParameterSet, scenario: &'a Scenario) -> Result<Self> {
        Ok(Self {
            contact: ContactParameters::from_parameters(parameters)?,
            wheel: &scenario.wheel,
            rail: &scenario.rail,
            track_setup: &scenario.track_setup,
            fastsim: &scenario.fastsim,
            creep: scenario.creep,
        })
    }
}

static BUILT: Kept<WheelRail> = Kept::new(CAPACITY);

/// The contact for `inputs`: one built before for the same inputs, or `build(inputs)`, then kept.
pub fn shared(
    inputs: &WheelRailInputs,
    build: impl FnOnce(&WheelRailInputs) -> Result<WheelRail>,
) -> Result<Arc<WheelRail>> {
    BUILT.get_or_try_build(format!("{inputs:?}"), || build(inputs))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::scenarios::scenario_contact::shared_wheel_rail;

    fn scenario(name: &str) -> Scenario {
        Scenario::study(name, 55.0, 300.0, 1).unwrap()
    }

    #[test]
    fn the_same_inputs_get_the_same_contact_and_others_their_own() {
        // Each comparison fetches the study contact again just before: other tests in this
        // process share the store and could push it out in between.
        let p = ParameterSet::default_vehicle();
        let (low, high) = (scenario("S_low"), scenario("S_high"));
        let study = || shared_wheel_rail(&p, &high).unwrap();
        assert!(Arc::ptr_eq(&study(), &study()));
        let other = shared_wheel_rail(&p, &low).unwrap();
        assert!(!Arc::ptr_eq(&study(), &other));
        // A speed or a track seed is not an input of the contact.
        let faster = Scenario::study("S_high", 80.0, 500.0, 7).unwrap();
        assert!(Arc::ptr_eq(
            &study(),
            &shared_wheel_rail(&p, &faster).unwrap()
        ));
        // A contact parameter is, down to its last bit.
        let mut nudged = p.clone();
        let mu = p.get("track.wheel_rail_friction").unwrap();
        nudged
            .set(
                "track.wheel_rail_friction",
                f64::from_bits(mu.to_bits() + 1),
            )
            .unwrap();
        let c = shared_wheel_rail(&nudged, &high).unwrap();
        assert!(!Arc::ptr_eq(&study(), &c));
        let mut grid = high.clone();
        grid.fastsim.nx += 2;
        let g = shared_wheel_rail(&p, &grid).unwrap();
        assert!(!Arc::ptr_eq(&study(), &g));
    }

    #[test]
    fn a_kept_contact_is_the_one_a_fresh_build_gives() {
        let p = ParameterSet::default_vehicle();
        let s = scenario("S_norm");
        let kept = shared_wheel_rail(&p, &s).unwrap();
        let fresh = crate::vehicle::scenarios::scenario_contact::build_wheel_rail(&p, &s).unwrap();
        assert_eq!(format!("{:?}", *kept), format!("{fresh:?}"));
    }
}
