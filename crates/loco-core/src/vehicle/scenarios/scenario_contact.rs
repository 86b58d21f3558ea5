//! The wheel-rail contact of a scenario for a vehicle: its profiles checked, the contact table
//! and FASTSIM built, or shared from the contacts kept in this process
//! ([`crate::vehicle::scenarios::wheel_rail_cache`]).

use crate::contact::fastsim::FastsimParams;
use crate::contact::geometry::ContactGeometry;
use crate::contact::profile::{Profile, ProfileKind};
use crate::contact::setup::{ContactSearchParams, WheelsetSetup};
use crate::contact::table::{ContactTable, ContactTableParams};
use crate::error::{LocoError, Result};
use crate::vehicle::params::parameters::ParameterSet;
use crate::vehicle::params::suspects::with_suspects;
use crate::vehicle::rail_contact::wheel_rail::{WheelRail, WheelRailSettings};
use crate::vehicle::scenarios::scenario::{Scenario, TABLE_HALF_RANGE};
use crate::vehicle::scenarios::wheel_rail_cache::{self, WheelRailInputs};
use std::sync::Arc;

/// Builds the wheel-rail contact (contact table and FASTSIM) of a scenario for a vehicle.
pub fn build_wheel_rail(parameters: &ParameterSet, scenario: &Scenario) -> Result<WheelRail> {
    WheelRailInputs::of(parameters, scenario)
        .and_then(|inputs| wheel_rail_of(&inputs))
        .map_err(|e| with_suspects(e, parameters))
}

/// As [`build_wheel_rail`], shared: the contact built before in this process for the same
/// inputs, if it is still kept ([`crate::vehicle::scenarios::wheel_rail_cache`]).
pub fn shared_wheel_rail(parameters: &ParameterSet, scenario: &Scenario) -> Result<Arc<WheelRail>> {
    WheelRailInputs::of(parameters, scenario)
        .and_then(|inputs| wheel_rail_cache::shared(&inputs, wheel_rail_of))
        .map_err(|e| with_suspects(e, parameters))
}

/// The wheel and the rail checked for their kind and their plausibility
/// ([`crate::contact::profile_plausibility::pair_implausibility`]: 1000 times off, no flange, a
/// stray point), before the contact is built: an error names `wheel` or `rail` and why, not the
/// quantity a failure would later be found in (the gauge range of the track, a contact search).
fn check_profiles(wheel: &Profile, rail: &Profile) -> Result<()> {
    for (field, profile, kind) in [
        ("wheel", wheel, ProfileKind::Wheel),
        ("rail", rail, ProfileKind::Rail),
    ] {
        if profile.kind() != kind {
            return Err(LocoError::param(
                field,
                format!(
                    "profile '{}' is a {} profile; the {field} must be a {field} profile",
                    profile.name(),
                    profile.kind().as_str()
                ),
            ));
        }
    }
    match crate::contact::profile_plausibility::pair_implausibility(wheel, rail) {
        Some((field, reason)) => Err(LocoError::param(field, reason)),
        None => Ok(()),
    }
}

fn wheel_rail_of(inputs: &WheelRailInputs) -> Result<WheelRail> {
    check_profiles(inputs.wheel, inputs.rail)?;
    let c = inputs.contact;
    let r0 = c.nominal_radius;
    let half = c.contact_half_distance;
    let wheelset = WheelsetSetup {
        // Nominal contact points 2·half apart on the taping lines (SPEC §1: 1493 mm).
        back_to_back: 2.0 * (half - WheelsetSetup::default().flange_back_offset),
        nominal_radius: [r0, r0],
        ..WheelsetSetup::default()
    };
    let geometry = ContactGeometry::new(
        [inputs.wheel, inputs.wheel],
        [inputs.rail, inputs.rail],
        inputs.track_setup,
        &wheelset,
        &ContactSearchParams::default(),
    )?;
    // ±25 mm covers flange contact of every study wheel (the thin flange leaves ±15 mm of
    // flangeway clearance) and the flange climbing beyond it.
    let table = ContactTable::build(
        &geometry,
        &ContactTableParams {
            y_min: -TABLE_HALF_RANGE,
            y_max: TABLE_HALF_RANGE,
            ..ContactTableParams::default()
        },
    )?;
    let fastsim_params = FastsimParams {
        poisson_ratio: c.poisson_ratio,
        shear_modulus: c.shear_modulus,
        ..*inputs.fastsim
    };
    Ok(WheelRail::new(
        table,
        inputs.creep.solver(fastsim_params)?,
        WheelRailSettings {
            friction: c.friction,
            contact_modulus: c.young_modulus / (2.0 * (1.0 - c.poisson_ratio * c.poisson_ratio)),
            normal_damping: c.normal_damping,
            nominal_radius: r0,
            contact_half_distance: half,
        },
    ))
}
