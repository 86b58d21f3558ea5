//! A run scenario as its user states it, in names and numbers, every setting optional: the one
//! mapping from a front end's settings (the batch binary's `[scenario]` TOML section, the Python
//! `RunScenario(...)` keyword arguments) to a core [`Scenario`].
//!
//! Settings left out take the core defaults, all listed by [`ScenarioSettings::defaults`] (which
//! front ends export: Python's `loco.Scenario.defaults()`); presets by name come from
//! [`crate::vehicle::params::presets`]. Settings that
//! contradict each other (a spectrum with a perfect track, a scenario name with a wheel, a speed in
//! both units) are refused with an error naming the field.

use crate::contact::fastsim::FastsimParams;
use crate::contact::profile::Profile;
use crate::contact::setup::TrackSetup;
use crate::dampers::{Damper, FsdTrigger};
use crate::error::{LocoError, Result};
pub use crate::track::design_input::CurveSetting;
use crate::track::{SynthesisParams, TrackIrregularity};
use crate::vehicle::output::run::RunSettings;
use crate::vehicle::params::presets::{yaw_damper_preset, FILE_DAMPER, STUDY_RAIL};
use crate::vehicle::rail_contact::creep_model::CreepModel;
use crate::vehicle::scenarios::scenario::Scenario;
use crate::vehicle::time::integrator::Integrator;
use serde::{Deserialize, Serialize};
use std::path::Path;
use std::sync::Arc;

/// The settings of a run scenario (SI units unless the name says otherwise). See the module
/// documentation; the batch binary reads them from the `[scenario]` section of a study file.
#[derive(Debug, Clone, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ScenarioSettings {
    /// Study scenario `S_low`, `S_norm` or `S_high` (its wheel and rail); or give `wheel`.
    pub name: Option<String>,
    /// Wheel profile: a built-in name or a profile file.
    pub wheel: Option<String>,
    /// Rail profile: a built-in name or a profile file (default: the study's rail, CN60).
    pub rail: Option<String>,
    /// Running speed, m/s (or `speed_kmh`; default [`DEFAULT_SPEED`]).
    pub speed: Option<f64>,
    /// Running speed, km/h (or `speed`).
    pub speed_kmh: Option<f64>,
    /// Distance run and recorded, m (default [`DEFAULT_DISTANCE`]).
    pub distance: Option<f64>,
    /// Distance run before `distance` and not recorded, m (default 0).
    pub lead_in: Option<f64>,
    /// `synthetic` (default), `perfect`, or the path of a measured track CSV.
    pub track: Option<String>,
    /// Spectrum of a synthesised track: `cn-hsr`, `german-low` or `german-high`.
    pub spectrum: Option<String>,
    /// Seed of a synthesised track.
    pub seed: Option<u64>,
    /// Wavelength band of a synthesised track, m.
    pub band: Option<[f64; 2]>,
    /// Yaw damper preset: `file` (the parameter file's Maxwell damper, default), `YD1`, `YD2`
    /// or `FSD`.
    pub yaw_damper: Option<String>,
    /// Trigger of the `FSD` preset: a name of [`FsdTrigger::NAMES`] (`rms-frequency`, the
    /// default, or `hydraulic`); only with `yaw_damper = "FSD"`.
    pub fsd_trigger: Option<String>,
    /// Integration step, s; without it the scheme's own ([`Integrator::default_step`]).
    pub step: Option<f64>,
    /// Integration scheme: `etdrk4` (default: the gearbox bearings and the linear dampers'
    /// series springs solved exactly, at 2 ms) or `rk4` (the classical RK4, the reference at
    /// 1 ms); see [`Integrator`].
    pub integrator: Option<String>,
    /// Output sampling rate, Hz.
    pub output_rate: Option<f64>,
    /// Grid (nx, ny) of the creep model (FASTSIM's, FaStrip's, the table's solver).
    pub fastsim_grid: Option<[usize; 2]>,
    /// Creep model: `fastsim` (default, the study's method), `fastrip` or `table` (FASTSIM
    /// tabulated once, default resolution); see [`CreepModel`].
    pub creep: Option<String>,
    /// Removed (replaced by `creep = "table"`): refused with an error naming `creep`.
    pub creep_table: Option<toml::Value>,
    /// Lateral disturbance of every wheelset at t = 0, m.
    pub initial_lateral_offset: Option<f64>,
    /// Track gauge, m.
    pub gauge: Option<f64>,
    /// Height below the rail top at which the gauge is measured, m.
    pub gauge_height: Option<f64>,
    /// Rail inclination, rad.
    pub rail_inclination: Option<f64>,
    /// Designed curves: a list of sections (`track::design_input`) or the path of a CSV file of
    /// them (relative to the settings' directory); none: straight track.
    pub curve: Option<CurveSetting>,
    /// Batches only, not part of a [`Scenario`]: a track per sample (seed + sample index)
    /// instead of one shared track. [`ScenarioSettings::resolve`] ignores it.
    pub per_sample_track: Option<bool>,
}

/// The `track` setting of a synthesised track (the default).
pub const SYNTHETIC: &str = "synthetic";

/// The `track` setting of a perfect (irregularity-free) track.
pub const PERFECT: &str = "perfect";

/// Profiles, track and yaw damper a front end already holds as objects. Each takes the place of
/// the setting of the same name; giving both is refused.
#[derive(Debug, Clone, Default)]
pub struct GivenObjects {
    pub wheel: Option<Profile>,
    pub rail: Option<Profile>,
    pub track: Option<Arc<TrackIrregularity>>,
    pub yaw_damper: Option<Damper>,
}

/// Track gauge of a run, m: standard-gauge track as laid and as worn (EN 13848-5's limits for
/// every speed lie within 1.426–1.470 m); the study's wheelsets (back-to-back 1.353 m) are made
/// for it, so another gauge needs another wheelset, not this setting.
pub const GAUGE_RANGE: [f64; 2] = [1.400, 1.470];

/// Height of the gauge measuring point below the rail top, m: 14 mm in EN 13848-1, 16 mm in the
/// Chinese rules; the range leaves room for other conventions while staying on the rail head.
pub const GAUGE_HEIGHT_RANGE: [f64; 2] = [0.005, 0.025];

/// The user's track set-up inside the ranges the run's wheelsets and rails are made for (the
/// contact code takes any geometry it can build; a scenario is the physical case).
fn check_track_setup_range(track: &TrackSetup) -> Result<()> {
    for (field, value, [low, high]) in [
        ("gauge", track.gauge, GAUGE_RANGE),
        ("gauge_height", track.gauge_height, GAUGE_HEIGHT_RANGE),
    ] {
        if !(low..=high).contains(&value) {
            return Err(LocoError::param(
                field,
                format!("{value} m is outside [{low}, {high}] m"),
            ));
        }
    }
    Ok(())
}

fn conflict(field: &str, reason: impl Into<String>) -> LocoError {
    LocoError::param(field, reason)
}

/// Running speed of a scenario that gives none, m/s: the study's 200 km/h (SPEC §6).
pub const DEFAULT_SPEED: f64 = 200.0 / 3.6;

/// Distance of a scenario that gives none, m: the study's 500 m of track (SPEC §6).
pub const DEFAULT_DISTANCE: f64 = 500.0;

impl ScenarioSettings {
    /// Every setting that has a default, at its default (`name`, `wheel`, `speed_kmh` and
    /// `creep_table` have none): the one place the front ends' defaults come from. Collected from
    /// the core's parameter structs ([`SynthesisParams`], [`RunSettings`], [`TrackSetup`],
    /// [`FastsimParams`], [`CreepModel`]) so that each is still defined once.
    pub fn defaults() -> Self {
        let synthesis = SynthesisParams::default();
        let run = RunSettings::default();
        let track = TrackSetup::default();
        let fastsim = FastsimParams::default();
        Self {
            name: None,
            wheel: None,
            rail: Some(STUDY_RAIL.to_string()),
            speed: Some(DEFAULT_SPEED),
            speed_kmh: None,
            distance: Some(DEFAULT_DISTANCE),
            lead_in: Some(0.0),
            track: Some(SYNTHETIC.to_string()),
            spectrum: Some(synthesis.spectrum.name().to_string()),
            seed: Some(synthesis.seed),
            band: Some([synthesis.wavelength_min, synthesis.wavelength_max]),
            yaw_damper: Some(FILE_DAMPER.to_string()),
            fsd_trigger: Some(FsdTrigger::DEFAULT.to_string()),
            step: Some(run.step),
            integrator: Some(run.integrator.name().to_string()),
            output_rate: Some(run.output_rate),
            fastsim_grid: Some([fastsim.nx, fastsim.ny]),
            creep: Some(CreepModel::default().name().to_string()),
            creep_table: None,
            initial_lateral_offset: Some(0.0),
            gauge: Some(track.gauge),
            gauge_height: Some(track.gauge_height),
            rail_inclination: Some(track.rail_inclination),
            per_sample_track: Some(false),
            curve: None,
        }
    }

    /// The scenario these settings describe, checked. `given` holds the objects a front end
    /// passes instead of names; profile and track files are relative to `dir`.
    pub fn resolve(&self, given: GivenObjects, dir: &Path) -> Result<Scenario> {
        let defaults = Self::defaults();
        let speed = match (self.speed, self.speed_kmh) {
            (Some(v), None) => v,
            (None, Some(kmh)) => kmh / 3.6,
            (Some(_), Some(_)) => {
                return Err(conflict(
                    "speed",
                    "give `speed` (m/s) or `speed_kmh`, not both",
                ))
            }
            (None, None) => DEFAULT_SPEED,
        };
        let distance = self.distance.unwrap_or(DEFAULT_DISTANCE);
        let (wheel, rail) = self.profiles(given.wheel, given.rail, dir)?;
        let track = self.track(given.track, dir)?;
        let yaw_damper = match (&self.yaw_damper, given.yaw_damper) {
            (Some(_), Some(_)) => {
                return Err(conflict(
                    "yaw_damper",
                    "given both as a preset name and as a damper",
                ))
            }
            (Some(name), None) => yaw_damper_preset(name, self.fsd_trigger.as_deref())?,
            (None, _) if self.fsd_trigger.is_some() => {
                return Err(conflict(
                    "fsd_trigger",
                    "only with the preset yaw_damper = \"FSD\"",
                ))
            }
            (None, damper) => damper,
        };
        if self.creep_table.is_some() {
            return Err(conflict(
                "creep_table",
                "replaced by `creep`: write creep = \"table\" (or \"fastsim\", \"fastrip\")",
            ));
        }
        let integrator = match &self.integrator {
            Some(name) => Integrator::from_name(name)?,
            None => Integrator::default(),
        };
        let creep = match &self.creep {
            Some(name) => CreepModel::from_name(name)?,
            None => CreepModel::default(),
        };
        let fastsim_defaults = FastsimParams::default();
        let [nx, ny] = self
            .fastsim_grid
            .or(defaults.fastsim_grid)
            .unwrap_or_default();
        let or = |given: Option<f64>, default: Option<f64>| given.or(default).unwrap_or_default();
        let scenario = Scenario {
            wheel,
            rail,
            track_setup: TrackSetup {
                gauge: or(self.gauge, defaults.gauge),
                gauge_height: or(self.gauge_height, defaults.gauge_height),
                rail_inclination: or(self.rail_inclination, defaults.rail_inclination),
            },
            speed,
            distance,
            lead_in: or(self.lead_in, defaults.lead_in),
            track,
            yaw_damper,
            run: RunSettings {
                // A scheme named without a step runs at its own step, not the default scheme's.
                step: self.step.unwrap_or(integrator.default_step()),
                integrator,
                output_rate: or(self.output_rate, defaults.output_rate),
                ..RunSettings::default()
            },
            fastsim: FastsimParams {
                nx,
                ny,
                ..fastsim_defaults
            },
            creep,
            initial_lateral_offset: or(
                self.initial_lateral_offset,
                defaults.initial_lateral_offset,
            ),
            curve: match &self.curve {
                Some(c) => c.sections(dir)?,
                None => Vec::new(),
            },
        };
        scenario.track_setup.validate()?;
        check_track_setup_range(&scenario.track_setup)?;
        scenario.validate()?;
        Ok(scenario)
    }
}

mod sources;

#[cfg(test)]
mod refusal_tests;
#[cfg(test)]
mod tests;
