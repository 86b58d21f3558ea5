//! The study file: vehicle, scenario and outputs of a batch, in TOML.
//!
//! ```toml
//! [vehicle]
//! file = "my_loco.toml"            # optional: a parameter file (default: the embedded vehicle)
//! allow_out_of_range = ["K_py"]    # optional: keys allowed outside their physical range
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
//! fsd_trigger = "rms-frequency"    # with FSD: rms-frequency (default) | hydraulic
//! step = 1e-3                      # s
//! output_rate = 500.0              # Hz
//! per_sample_track = false         # a track per sample (seed + sample index)
//! creep = "fastsim"                # fastsim (the study's) | fastrip | table (FASTSIM tabulated)
//! fastsim_grid = [10, 10]          # grid (nx, ny) of the creep model
//! initial_lateral_offset = 0.0     # m, every wheelset at t = 0
//! gauge = 1.435                    # m
//! gauge_height = 0.016             # m below the rail top
//! # rail_inclination = 0.025       # rad (default 1:40)
//!
//! [output]
//! histories = [0]                  # samples whose time histories are written
//! channels = ["frame1_ay_wheelset1"]   # channels of those histories (default: all)
//! ```
//!
//! Relative paths are relative to the study file. Every `[scenario]` key but `distance` and the
//! speed is optional; left out, it takes the core default
//! ([`crate::vehicle::scenarios::scenario_settings::ScenarioSettings`]). Settings that contradict each
//! other (`spectrum`, `seed` or `band` with a perfect or measured track; `name` with `wheel`;
//! `speed` with `speed_kmh`) are refused.

use crate::error::FileKind;
use crate::vehicle::params::parameters::ParameterSet;
use crate::vehicle::scenarios::scenario::Scenario;
use crate::vehicle::scenarios::scenario_settings::{GivenObjects, ScenarioSettings};
use crate::{LocoError, Result};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The study file as written.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StudyFile {
    #[serde(default)]
    pub vehicle: VehicleSection,
    pub scenario: ScenarioSettings,
    #[serde(default)]
    pub output: OutputSection,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VehicleSection {
    pub file: Option<PathBuf>,
    /// Keys (or study names) allowed outside their physical range, in the file, the overrides
    /// and the samples, as a vehicle file's own `allow_out_of_range` list.
    #[serde(default)]
    pub allow_out_of_range: Vec<String>,
    #[serde(default)]
    pub overrides: BTreeMap<String, f64>,
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

fn read(path: &Path, kind: FileKind) -> Result<String> {
    crate::util::text_file::read_text(path, kind)
}

/// Reads and resolves the study file at `path`.
pub fn load_study(path: &Path) -> Result<Study> {
    let text = read(path, FileKind::Study)?;
    let origin = path.display().to_string();
    let file: StudyFile =
        toml::from_str(&text).map_err(|e| LocoError::toml(FileKind::Study, &origin, &text, &e))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut base = match &file.vehicle.file {
        Some(f) => {
            let p = dir.join(f);
            ParameterSet::from_toml_str(&read(&p, FileKind::Vehicle)?, &p.display().to_string())?
        }
        None => ParameterSet::default_vehicle(),
    };
    for name in &file.vehicle.allow_out_of_range {
        base.allow_out_of_range(name)?;
    }
    for (name, value) in &file.vehicle.overrides {
        base.set(name, *value)?;
    }
    let scenario = file
        .scenario
        .resolve(GivenObjects::default(), dir)
        .map_err(|e| match e {
            LocoError::InvalidParameter { name, reason } => LocoError::InvalidParameter {
                name: format!("scenario.{name}"),
                reason,
            },
            other => other,
        })?;
    Ok(Study {
        base,
        scenario,
        per_sample_track: file.scenario.per_sample_track.unwrap_or(false),
        histories: file.output.histories,
        channels: file.output.channels,
    })
}
