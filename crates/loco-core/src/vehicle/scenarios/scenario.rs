//! A run of the locomotive as an engineer states it: which wheel and rail, how fast, how far, on
//! which track, with which yaw damper; and what a run is built from (its contact and track).
//! The functions that simulate it are in [`crate::vehicle::runs::simulate`] (re-exported here); the study's
//! scenarios (SPEC §2) by name are in [`crate::vehicle::params::presets`].

use crate::contact::builtin::builtin_profile;
use crate::contact::fastsim::FastsimParams;
use crate::contact::profile::Profile;
use crate::contact::setup::TrackSetup;
use crate::dampers::Damper;
use crate::error::{check_positive, LocoError, Result};
use crate::track::{synthesize, DesignSection, SynthesisParams, TrackDesign, TrackIrregularity};
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::output::run::RunSettings;
use crate::vehicle::params::parameters::ParameterSet;
use crate::vehicle::params::sections::{ContactSection, TrackSection};
use crate::vehicle::rail_contact::creep_model::CreepModel;
use crate::vehicle::rail_contact::wheel_rail::WheelRail;
use std::sync::Arc;

pub mod cost;

/// Highest running speed the model accepts, m/s (400 km/h: well above the SS8's 240 km/h test
/// speed; the contact tables and creep model are not meant for more).
pub const MAX_SPEED: f64 = 400.0 / 3.6;

/// Longest run the model accepts, m (100 km: the output of one run stays within memory).
pub const MAX_DISTANCE: f64 = 100_000.0;

/// Half range of the contact tables, m.
pub const TABLE_HALF_RANGE: f64 = 0.025;

pub use crate::vehicle::params::presets::scenario_profiles;

/// The track a run uses.
#[derive(Debug, Clone)]
pub enum TrackSpec {
    /// Perfect straight track (no irregularity).
    Perfect,
    /// Irregularities synthesised from a spectrum (length is set from the run).
    Synthetic(SynthesisParams),
    /// A given (e.g. measured) irregularity.
    Given(Arc<TrackIrregularity>),
}

/// Everything about a run except the vehicle's parameters.
#[derive(Debug, Clone)]
pub struct Scenario {
    /// Wheel profile (used on both wheels of every wheelset).
    pub wheel: Profile,
    /// Rail profile (both rails).
    pub rail: Profile,
    /// Track set-up (gauge, gauge height, inclination).
    pub track_setup: TrackSetup,
    /// Running speed, m/s.
    pub speed: f64,
    /// Distance run and recorded, m (the recorded time is distance / speed).
    pub distance: f64,
    /// Distance run before the recorded `distance`, m (not recorded; 0 by default, as in the
    /// study): lets start transients settle, e.g. an FSD valve leaving its defined start state.
    pub lead_in: f64,
    pub track: TrackSpec,
    /// Yaw damper law; `None` keeps the parameter file's Maxwell yaw damper.
    pub yaw_damper: Option<Damper>,
    pub run: RunSettings,
    /// Grid, Kalker factor and material of the creep model (the material is replaced by the
    /// parameter file's track material when the wheel-rail contact is built).
    pub fastsim: FastsimParams,
    /// Creep model (default FASTSIM, the study's method).
    pub creep: CreepModel,
    /// Lateral disturbance of every wheelset at t = 0, m (0: start from equilibrium).
    pub initial_lateral_offset: f64,
    /// Designed alignment and cant the track frames follow (`track::design`), s = 0 where the
    /// leading wheelset starts; empty: straight track.
    pub curve: Vec<DesignSection>,
}

impl Scenario {
    /// A study scenario (`S_low`, `S_norm`, `S_high`) at `speed` (m/s) over `distance` (m) on a
    /// track synthesised from the Chinese high-speed spectrum with `seed`.
    pub fn study(name: &str, speed: f64, distance: f64, seed: u64) -> Result<Self> {
        let (wheel, rail) = scenario_profiles(name)?;
        Ok(Self {
            wheel: builtin_profile(wheel)?,
            rail: builtin_profile(rail)?,
            track_setup: TrackSetup::default(),
            speed,
            distance,
            lead_in: 0.0,
            track: TrackSpec::Synthetic(SynthesisParams {
                seed,
                ..SynthesisParams::default()
            }),
            yaw_damper: None,
            run: RunSettings::default(),
            fastsim: FastsimParams::default(),
            creep: CreepModel::Fastsim,
            initial_lateral_offset: 0.0,
            curve: Vec::new(),
        })
    }

    /// Checks speed, distance and settings, and the cost bounds of
    /// [`crate::vehicle::scenarios::run_limits`]; errors name the field.
    pub fn validate(&self) -> Result<()> {
        check_positive("speed", self.speed)?;
        if self.speed > MAX_SPEED {
            return Err(LocoError::param(
                "speed",
                format!(
                    "{:.1} km/h is beyond the model's range (max {:.0} km/h)",
                    self.speed * 3.6,
                    MAX_SPEED * 3.6
                ),
            ));
        }
        check_positive("distance", self.distance)?;
        check_positive("step", self.run.step)?;
        check_positive("output_rate", self.run.output_rate)?;
        if !(self.lead_in.is_finite() && (0.0..=MAX_DISTANCE).contains(&self.lead_in)) {
            return Err(LocoError::param(
                "lead_in",
                format!(
                    "must be finite and in [0, {MAX_DISTANCE}] m, got {}",
                    self.lead_in
                ),
            ));
        }
        if self.distance > MAX_DISTANCE {
            return Err(LocoError::param(
                "distance",
                format!(
                    "{} m is beyond {MAX_DISTANCE} m: run long tracks as several runs",
                    self.distance
                ),
            ));
        }
        // One output sample per step at most: a faster rate would silently shorten the step.
        // Blame the setting moved from its default (a long step, else a fast rate).
        if self.run.output_rate * self.run.step > 1.0 + 1e-9 {
            let reason = format!(
                "{} Hz is faster than one sample per integration step ({} s)",
                self.run.output_rate, self.run.step
            );
            let field = if self.run.step > RunSettings::default().step {
                "step"
            } else {
                "output_rate"
            };
            return Err(LocoError::param(field, reason));
        }
        if !self.initial_lateral_offset.is_finite() || self.initial_lateral_offset.abs() > 0.01 {
            return Err(LocoError::param(
                "initial_lateral_offset",
                format!(
                    "must be finite and within ±0.01 m, got {}",
                    self.initial_lateral_offset
                ),
            ));
        }
        self.check_curve_covers_run()?;
        cost::check_cost(self)
    }

    /// A run longer than its curve design continues on straight, level track after the last
    /// section when the design ends there (a straight, or a transition, which runs out to
    /// straight track); a design ending in a circular curve would end in a step of curvature and
    /// cant no track has, so a run beyond it is refused naming `distance`.
    fn check_curve_covers_run(&self) -> Result<()> {
        let Some(last) = self.curve.last() else {
            return Ok(());
        };
        // The sections' own faults first (the smallest radius needs the contact: checked when
        // the run builds the design).
        crate::track::design::check_sections(&self.curve, 0.0)?;
        let length: f64 = self.curve.iter().map(DesignSection::length).sum();
        let run = self.lead_in + self.distance;
        if matches!(last, DesignSection::Curve { .. }) && run > length {
            return Err(LocoError::param(
                "distance",
                format!(
                    "the leading wheelset runs to {run} m (lead_in + distance) but the `curve` \
                     design ends at {length} m in a circular curve; lengthen the curve, or end \
                     the design with a transition and a straight (after a design that ends \
                     straight the run continues on straight track)"
                ),
            ));
        }
        Ok(())
    }

    /// Track length a run needs, m.
    pub fn track_length(&self, _structure: &VehicleStructure) -> f64 {
        self.lead_in + self.distance + 20.0
    }
}

/// Track distance of the vehicle's origin at t = 0, m: the leading wheelset starts at s = 0, so
/// every wheelset enters the track through its run-in (the track is perfect before s = 0).
pub fn start_distance(structure: &VehicleStructure) -> f64 {
    -structure.layout.wheelset_x[0]
}

/// What the wheel-rail contact reads from the vehicle parameters (the keys whose schema entry
/// `affects` the contact), checked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactParameters {
    /// Nominal rolling radius, m.
    pub nominal_radius: f64,
    /// Half the distance between the nominal contact points, m.
    pub contact_half_distance: f64,
    /// Young's modulus of the steel, Pa.
    pub young_modulus: f64,
    /// Poisson's ratio of the steel.
    pub poisson_ratio: f64,
    /// Shear modulus of the steel, Pa, derived from the two above.
    pub shear_modulus: f64,
    /// Coulomb friction coefficient.
    pub friction: f64,
    /// Normal contact damping, N·s/m.
    pub normal_damping: f64,
}

impl ContactParameters {
    /// Reads and checks the contact parameters of a vehicle (its track and contact sections
    /// only: a contact is built without the rest of the vehicle).
    pub fn from_parameters(parameters: &ParameterSet) -> Result<Self> {
        let track = TrackSection::read(parameters)?;
        let contact = ContactSection::read(parameters)?;
        let nu = track.poisson_ratio;
        if !(0.0..0.5).contains(&nu) {
            return Err(LocoError::param(
                "track.poisson_ratio",
                format!("must be in [0, 0.5), got {nu}"),
            ));
        }
        Ok(Self {
            nominal_radius: track.wheel_rolling_radius,
            contact_half_distance: track.contact_point_half_distance,
            young_modulus: track.young_modulus,
            poisson_ratio: nu,
            shear_modulus: track.shear_modulus(),
            friction: track.wheel_rail_friction,
            normal_damping: contact.normal_contact_damping,
        })
    }
}

/// Checks and resolves curve sections for a wheel-rail contact: the cant's roll uses the
/// contact's nominal half distance b, and the smallest radius is the one the table's largest
/// rolling radius difference follows in pure rolling ([`crate::track::design::min_radius_of`]).
pub fn curve_design(wheel_rail: &WheelRail, sections: &[DesignSection]) -> Result<TrackDesign> {
    let (lo, hi) = wheel_rail.table().y_range();
    let n = ((hi - lo) / 1e-4).round() as usize;
    let ys: Vec<f64> = (0..=n)
        .map(|i| lo + (hi - lo) * i as f64 / n as f64)
        .collect();
    let largest = wheel_rail
        .table()
        .rolling_radius_difference(&ys)
        .into_iter()
        .fold(0.0, |a: f64, d| a.max(d.abs()));
    let b = wheel_rail.contact_half_distance();
    let min_radius = crate::track::design::min_radius_of(largest, wheel_rail.centred_radius(), b);
    TrackDesign::new(sections, b, min_radius)
}

/// Builds the track of a scenario (synthesised ones get the run's length).
pub fn build_track(scenario: &Scenario, structure: &VehicleStructure) -> Result<TrackIrregularity> {
    let length = scenario.track_length(structure);
    match &scenario.track {
        TrackSpec::Perfect => {
            let n = (length / 0.5).ceil() as usize + 2;
            let zeros = vec![0.0; n];
            let values = [zeros.clone(), zeros.clone(), zeros.clone(), zeros];
            TrackIrregularity::from_channels(0.5, &values, &values, 0.0, None)
        }
        TrackSpec::Synthetic(params) => synthesize(&SynthesisParams { length, ..*params }),
        TrackSpec::Given(track) => {
            track.check_covers(length)?;
            Ok((**track).clone())
        }
    }
}
