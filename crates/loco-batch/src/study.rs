//! The study file: vehicle, scenario and outputs of a batch, in TOML.
//!
//! ```toml
//! [vehicle]
//! file = "my_loco.toml"            # optional: a parameter file (default: the embedded vehicle)
//! [vehicle.overrides]              # optional: values (SI) by key or study name
//! C_sy = 2.5e4
//!
//! [scenario]
//! name = "S_high"                  # S_low | S_norm | S_high, or give wheel and rail:
//! # wheel = "jm3-worn"             # built-in name or a profile file (.prw, .txt …)
//! # rail = "cn60"
//! speed = 55.5556                  # m/s (or speed_kmh = 200)
//! distance = 500.0                 # m, recorded
//! lead_in = 0.0                    # m run before it, not recorded
//! track = "synthetic"              # synthetic | perfect | path of a measured CSV
//! spectrum = "cn-hsr"              # cn-hsr | german-low | german-high
//! seed = 0
//! band = [2.0, 200.0]              # m
//! yaw_damper = "file"              # file (the parameter file's Maxwell) | YD1 | YD2 | FSD
//! step = 1e-3                      # s
//! output_rate = 500.0              # Hz
//! per_sample_track = false
//! creep_table = false              # tabulated FASTSIM instead of FASTSIM at every evaluation
//!
//! [output]
//! histories = [0]                  # samples whose time histories are written
//! channels = ["frame1_ay_wheelset1"]   # channels of those histories (default: all)
//! ```
//!
//! Relative paths are relative to the study file.

use loco_core::contact::builtin::{builtin_names, builtin_profile};
use loco_core::contact::fastsim_table::FastsimTableParams;
use loco_core::contact::profile::{Profile, ProfileKind};
use loco_core::contact::profile_io::load_profile;
use loco_core::dampers::Damper;
use loco_core::track::{load_csv, MeasuredParams, SynthesisParams, TrackSpectrum};
use loco_core::vehicle::parameters::ParameterSet;
use loco_core::vehicle::scenario::{scenario_profiles, Scenario, TrackSpec};
use loco_core::{LocoError, Result};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The study file as written.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StudyFile {
    #[serde(default)]
    pub vehicle: VehicleSection,
    pub scenario: ScenarioSection,
    #[serde(default)]
    pub output: OutputSection,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VehicleSection {
    pub file: Option<PathBuf>,
    #[serde(default)]
    pub overrides: BTreeMap<String, f64>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenarioSection {
    pub name: Option<String>,
    pub wheel: Option<String>,
    pub rail: Option<String>,
    /// m/s.
    pub speed: Option<f64>,
    pub speed_kmh: Option<f64>,
    /// m.
    pub distance: f64,
    /// m, run before `distance` and not recorded.
    #[serde(default)]
    pub lead_in: f64,
    pub track: Option<String>,
    pub spectrum: Option<String>,
    pub seed: Option<u64>,
    pub band: Option<[f64; 2]>,
    pub yaw_damper: Option<String>,
    pub step: Option<f64>,
    pub output_rate: Option<f64>,
    #[serde(default)]
    pub per_sample_track: bool,
    #[serde(default)]
    pub creep_table: bool,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSection {
    #[serde(default)]
    pub histories: Vec<usize>,
    pub channels: Option<Vec<String>>,
}

/// What the batch needs from a study file, resolved and checked.
pub struct Study {
    pub base: ParameterSet,
    pub scenario: Scenario,
    pub per_sample_track: bool,
    pub histories: Vec<usize>,
    pub channels: Option<Vec<String>>,
}

fn read(path: &Path) -> Result<String> {
    std::fs::read_to_string(path).map_err(|e| LocoError::Io {
        path: path.display().to_string(),
        reason: e.to_string(),
    })
}

/// Reads and resolves the study file at `path`.
pub fn load_study(path: &Path) -> Result<Study> {
    let text = read(path)?;
    let origin = path.display().to_string();
    let file: StudyFile = toml::from_str(&text).map_err(|e| LocoError::Parse {
        path: origin.clone(),
        line: e
            .span()
            .map(|s| text[..s.start.min(text.len())].lines().count().max(1))
            .unwrap_or(0),
        reason: e.message().to_string(),
    })?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut base = match &file.vehicle.file {
        Some(f) => {
            let p = dir.join(f);
            ParameterSet::from_toml_str(&read(&p)?, &p.display().to_string())?
        }
        None => ParameterSet::default_vehicle(),
    };
    for (name, value) in &file.vehicle.overrides {
        base.set(name, *value)?;
    }
    let scenario = scenario(&file.scenario, dir)?;
    scenario.validate()?;
    Ok(Study {
        base,
        scenario,
        per_sample_track: file.scenario.per_sample_track,
        histories: file.output.histories,
        channels: file.output.channels,
    })
}

fn profile(name: &str, kind: ProfileKind, dir: &Path) -> Result<Profile> {
    if builtin_names().contains(&name) {
        builtin_profile(name)
    } else {
        load_profile(&dir.join(name), Some(kind), false)
    }
}

fn scenario(s: &ScenarioSection, dir: &Path) -> Result<Scenario> {
    let speed = match (s.speed, s.speed_kmh) {
        (Some(v), None) => v,
        (None, Some(kmh)) => kmh / 3.6,
        _ => {
            return Err(LocoError::param(
                "scenario.speed",
                "give exactly one of `speed` (m/s) and `speed_kmh`",
            ))
        }
    };
    let (wheel, rail) = match (&s.name, &s.wheel, &s.rail) {
        (Some(name), None, None) => {
            let (w, r) = scenario_profiles(name)?;
            (builtin_profile(w)?, builtin_profile(r)?)
        }
        (None, Some(w), r) => (
            profile(w, ProfileKind::Wheel, dir)?,
            profile(r.as_deref().unwrap_or("cn60"), ProfileKind::Rail, dir)?,
        ),
        _ => {
            return Err(LocoError::param(
                "scenario.name",
                "give either `name` (S_low, S_norm, S_high) or `wheel` (and optionally `rail`)",
            ))
        }
    };
    let seed = s.seed.unwrap_or(0);
    let band = s.band.unwrap_or([2.0, 200.0]);
    let track = match s.track.as_deref().unwrap_or("synthetic") {
        "synthetic" => TrackSpec::Synthetic(SynthesisParams {
            spectrum: TrackSpectrum::from_name(s.spectrum.as_deref().unwrap_or("cn-hsr"))?,
            seed,
            wavelength_min: band[0],
            wavelength_max: band[1],
            ..SynthesisParams::default()
        }),
        "perfect" => TrackSpec::Perfect,
        file => {
            let p = dir.join(file);
            TrackSpec::Given(Arc::new(load_csv(
                &p.display().to_string(),
                &MeasuredParams::default(),
            )?))
        }
    };
    let yaw_damper = match s.yaw_damper.as_deref().unwrap_or("file") {
        "file" => None,
        "YD1" => Some(Damper::yd1()),
        "YD2" => Some(Damper::yd2()),
        "FSD" => Some(Damper::fsd()),
        other => {
            return Err(LocoError::param(
                "scenario.yaw_damper",
                format!("expected file, YD1, YD2 or FSD, got '{other}'"),
            ))
        }
    };
    let mut scenario = Scenario::study("S_norm", speed, s.distance, seed)?;
    scenario.wheel = wheel;
    scenario.rail = rail;
    scenario.track = track;
    scenario.yaw_damper = yaw_damper;
    scenario.lead_in = s.lead_in;
    if let Some(step) = s.step {
        scenario.run.step = step;
    }
    if let Some(rate) = s.output_rate {
        scenario.run.output_rate = rate;
    }
    if s.creep_table {
        scenario.creep_table = Some(FastsimTableParams::default());
    }
    Ok(scenario)
}
