//! A run scenario as its user states it, in names and numbers, every setting optional: the one
//! mapping from a front end's settings (the batch binary's `[scenario]` TOML section, the Python
//! `RunScenario(...)` keyword arguments) to a core [`Scenario`].
//!
//! Settings left out take the core defaults ([`SynthesisParams::default`],
//! [`RunSettings::default`], [`TrackSetup::default`], [`FastsimParams::default`]); settings that
//! contradict each other (a spectrum with a perfect track, a scenario name with a wheel, a speed in
//! both units) are refused with an error naming the field.

use super::creep_model::CreepModel;
use super::run::RunSettings;
use super::scenario::{scenario_profiles, Scenario, TrackSpec};
use crate::contact::builtin::{builtin_names, builtin_profile};
use crate::contact::fastsim::FastsimParams;
use crate::contact::profile::{Profile, ProfileKind};
use crate::contact::profile_io::load_profile;
use crate::contact::setup::TrackSetup;
use crate::dampers::{Damper, FsdTrigger};
use crate::error::{LocoError, Result};
use crate::track::design::DesignSection;
use crate::track::design_input::{load_sections_csv, resolve_sections, SectionSetting};
use crate::track::{load_csv, MeasuredParams, SynthesisParams, TrackIrregularity, TrackSpectrum};
use serde::Deserialize;
use std::path::Path;
use std::sync::Arc;

/// The settings of a run scenario (SI units unless the name says otherwise). See the module
/// documentation; the batch binary reads them from the `[scenario]` section of a study file.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenarioSettings {
    /// Study scenario `S_low`, `S_norm` or `S_high` (its wheel and rail); or give `wheel`.
    pub name: Option<String>,
    /// Wheel profile: a built-in name or a profile file.
    pub wheel: Option<String>,
    /// Rail profile: a built-in name or a profile file (default: the study's rail, CN60).
    pub rail: Option<String>,
    /// Running speed, m/s (or `speed_kmh`).
    pub speed: Option<f64>,
    /// Running speed, km/h (or `speed`).
    pub speed_kmh: Option<f64>,
    /// Distance run and recorded, m (required).
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
    /// Integration step, s.
    pub step: Option<f64>,
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

/// The `curve` setting: sections in place, or a CSV file of them.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(untagged)]
pub enum CurveSetting {
    File(String),
    Sections(Vec<SectionSetting>),
}

impl CurveSetting {
    /// The sections, a file relative to `dir`.
    pub fn sections(&self, dir: &Path) -> Result<Vec<DesignSection>> {
        match self {
            Self::File(path) => resolve_sections(&load_sections_csv(&dir.join(path))?),
            Self::Sections(list) => resolve_sections(list),
        }
    }
}

/// Profiles, track and yaw damper a front end already holds as objects. Each takes the place of
/// the setting of the same name; giving both is refused.
#[derive(Debug, Clone, Default)]
pub struct GivenObjects {
    pub wheel: Option<Profile>,
    pub rail: Option<Profile>,
    pub track: Option<Arc<TrackIrregularity>>,
    pub yaw_damper: Option<Damper>,
}

/// The yaw damper of a preset name: `file` (`None`: the parameter file's Maxwell yaw damper),
/// `YD1`, `YD2` or `FSD`.
pub fn yaw_damper_preset(name: &str) -> Result<Option<Damper>> {
    match name {
        "file" => Ok(None),
        "YD1" => Ok(Some(Damper::yd1())),
        "YD2" => Ok(Some(Damper::yd2())),
        "FSD" => Ok(Some(Damper::fsd())),
        other => Err(LocoError::param(
            "yaw_damper",
            format!("expected file, YD1, YD2 or FSD, got '{other}'"),
        )),
    }
}

/// A profile by name: built-in, else a file relative to `dir`.
fn lookup_profile(name: &str, kind: ProfileKind, dir: &Path) -> Result<Profile> {
    if builtin_names().contains(&name) {
        builtin_profile(name)
    } else {
        load_profile(&dir.join(name), Some(kind), false)
    }
}

fn conflict(field: &str, reason: impl Into<String>) -> LocoError {
    LocoError::param(field, reason)
}

impl ScenarioSettings {
    /// The scenario these settings describe, checked. `given` holds the objects a front end
    /// passes instead of names; profile and track files are relative to `dir`.
    pub fn resolve(&self, given: GivenObjects, dir: &Path) -> Result<Scenario> {
        let speed = match (self.speed, self.speed_kmh) {
            (Some(v), None) => v,
            (None, Some(kmh)) => kmh / 3.6,
            (Some(_), Some(_)) => {
                return Err(conflict(
                    "speed",
                    "give `speed` (m/s) or `speed_kmh`, not both",
                ))
            }
            (None, None) => {
                return Err(conflict(
                    "speed",
                    "missing: give `speed` (m/s) or `speed_kmh`",
                ))
            }
        };
        let distance = self
            .distance
            .ok_or_else(|| conflict("distance", "missing: give the distance run, m"))?;
        let (wheel, rail) = self.profiles(given.wheel, given.rail, dir)?;
        let track = self.track(given.track, dir)?;
        let yaw_damper = match (&self.yaw_damper, given.yaw_damper) {
            (Some(_), Some(_)) => {
                return Err(conflict(
                    "yaw_damper",
                    "given both as a preset name and as a damper",
                ))
            }
            (Some(name), None) => yaw_damper_preset(name)?,
            (None, damper) => damper,
        };
        if self.creep_table.is_some() {
            return Err(conflict(
                "creep_table",
                "replaced by `creep`: write creep = \"table\" (or \"fastsim\", \"fastrip\")",
            ));
        }
        let creep = match &self.creep {
            Some(name) => CreepModel::from_name(name)?,
            None => CreepModel::default(),
        };
        let yaw_damper = match (&self.fsd_trigger, yaw_damper) {
            (None, law) => law,
            (Some(name), Some(Damper::Fsd(_))) if self.yaw_damper.as_deref() == Some("FSD") => {
                match FsdTrigger::check_name(name).map_err(|_| {
                    conflict(
                        "fsd_trigger",
                        format!(
                            "expected one of {}, got '{name}'",
                            FsdTrigger::NAMES.join(", ")
                        ),
                    )
                })? {
                    FsdTrigger::HYDRAULIC => Some(Damper::fsd_hydraulic()),
                    _ => Some(Damper::fsd()),
                }
            }
            (Some(_), _) => {
                return Err(conflict(
                    "fsd_trigger",
                    "only with the preset yaw_damper = \"FSD\"",
                ))
            }
        };
        let track_defaults = TrackSetup::default();
        let run_defaults = RunSettings::default();
        let fastsim_defaults = FastsimParams::default();
        let scenario = Scenario {
            wheel,
            rail,
            track_setup: TrackSetup {
                gauge: self.gauge.unwrap_or(track_defaults.gauge),
                gauge_height: self.gauge_height.unwrap_or(track_defaults.gauge_height),
                rail_inclination: self
                    .rail_inclination
                    .unwrap_or(track_defaults.rail_inclination),
            },
            speed,
            distance,
            lead_in: self.lead_in.unwrap_or(0.0),
            track,
            yaw_damper,
            run: RunSettings {
                step: self.step.unwrap_or(run_defaults.step),
                output_rate: self.output_rate.unwrap_or(run_defaults.output_rate),
                ..run_defaults
            },
            fastsim: match self.fastsim_grid {
                Some([nx, ny]) => FastsimParams {
                    nx,
                    ny,
                    ..fastsim_defaults
                },
                None => fastsim_defaults,
            },
            creep,
            initial_lateral_offset: self.initial_lateral_offset.unwrap_or(0.0),
            curve: match &self.curve {
                Some(c) => c.sections(dir)?,
                None => Vec::new(),
            },
        };
        scenario.track_setup.validate()?;
        scenario.validate()?;
        Ok(scenario)
    }

    fn profiles(
        &self,
        wheel: Option<Profile>,
        rail: Option<Profile>,
        dir: &Path,
    ) -> Result<(Profile, Profile)> {
        if let Some(name) = &self.name {
            if self.wheel.is_some() || self.rail.is_some() || wheel.is_some() || rail.is_some() {
                return Err(conflict(
                    "name",
                    "give either `name` (S_low, S_norm, S_high) or `wheel` (and optionally \
                     `rail`), not both",
                ));
            }
            let (w, r) = scenario_profiles(name).map_err(|_| {
                conflict(
                    "name",
                    format!("unknown scenario '{name}'; expected S_low, S_norm or S_high"),
                )
            })?;
            return Ok((builtin_profile(w)?, builtin_profile(r)?));
        }
        let wheel = match (&self.wheel, wheel) {
            (Some(_), Some(_)) => {
                return Err(conflict("wheel", "given both as a name and as a profile"))
            }
            (Some(name), None) => lookup_profile(name, ProfileKind::Wheel, dir)?,
            (None, Some(profile)) => profile,
            (None, None) => {
                return Err(conflict(
                    "name",
                    "missing: give either `name` (S_low, S_norm, S_high) or `wheel` (and \
                     optionally `rail`)",
                ))
            }
        };
        let rail = match (&self.rail, rail) {
            (Some(_), Some(_)) => {
                return Err(conflict("rail", "given both as a name and as a profile"))
            }
            (Some(name), None) => lookup_profile(name, ProfileKind::Rail, dir)?,
            (None, Some(profile)) => profile,
            // The study's rail (the same for every study scenario).
            (None, None) => builtin_profile(scenario_profiles("S_norm")?.1)?,
        };
        Ok((wheel, rail))
    }

    /// Refuses the synthesis settings for a track that is not synthesised.
    fn no_synthesis_settings(&self, what: &str) -> Result<()> {
        let given = [
            ("spectrum", self.spectrum.is_some()),
            ("seed", self.seed.is_some()),
            ("band", self.band.is_some()),
        ];
        match given.iter().find(|(_, set)| *set) {
            Some((field, _)) => Err(conflict(
                field,
                format!("only a synthesised track uses it, but the track is {what}"),
            )),
            None => Ok(()),
        }
    }

    fn track(&self, given: Option<Arc<TrackIrregularity>>, dir: &Path) -> Result<TrackSpec> {
        if let Some(track) = given {
            if self.track.is_some() {
                return Err(conflict("track", "given both as a setting and as a track"));
            }
            self.no_synthesis_settings("a given one")?;
            return Ok(TrackSpec::Given(track));
        }
        match self.track.as_deref().unwrap_or("synthetic") {
            "synthetic" => {
                let defaults = SynthesisParams::default();
                let spectrum = match &self.spectrum {
                    Some(name) => TrackSpectrum::from_name(name)?,
                    None => defaults.spectrum,
                };
                let band = self
                    .band
                    .unwrap_or([defaults.wavelength_min, defaults.wavelength_max]);
                Ok(TrackSpec::Synthetic(SynthesisParams {
                    spectrum,
                    seed: self.seed.unwrap_or(defaults.seed),
                    wavelength_min: band[0],
                    wavelength_max: band[1],
                    ..defaults
                }))
            }
            "perfect" => {
                self.no_synthesis_settings("perfect")?;
                Ok(TrackSpec::Perfect)
            }
            file => {
                self.no_synthesis_settings("a measured one")?;
                let path = dir.join(file);
                Ok(TrackSpec::Given(Arc::new(load_csv(
                    &path.display().to_string(),
                    &MeasuredParams::default(),
                )?)))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings(name: &str) -> ScenarioSettings {
        ScenarioSettings {
            name: Some(name.into()),
            speed: Some(50.0),
            distance: Some(100.0),
            ..ScenarioSettings::default()
        }
    }

    fn field_of(e: LocoError) -> String {
        match e {
            LocoError::InvalidParameter { name, .. } => name,
            other => panic!("expected an invalid parameter, got {other}"),
        }
    }

    #[test]
    fn defaults_are_the_core_defaults() {
        let s = settings("S_norm")
            .resolve(GivenObjects::default(), Path::new("."))
            .unwrap();
        let study = Scenario::study("S_norm", 50.0, 100.0, 0).unwrap();
        assert_eq!(s.wheel.name(), study.wheel.name());
        assert_eq!(s.rail.name(), study.rail.name());
        assert_eq!(s.track_setup, TrackSetup::default());
        assert_eq!(s.track_setup, study.track_setup);
        assert_eq!(s.run.step, RunSettings::default().step);
        assert_eq!(s.run.output_rate, RunSettings::default().output_rate);
        assert_eq!(s.fastsim, FastsimParams::default());
        assert_eq!(s.lead_in, study.lead_in);
        assert_eq!(s.initial_lateral_offset, study.initial_lateral_offset);
        assert!(s.creep == CreepModel::Fastsim && s.yaw_damper.is_none());
        assert_eq!(s.creep, study.creep);
        match (&s.track, &study.track) {
            (TrackSpec::Synthetic(a), TrackSpec::Synthetic(b)) => {
                assert_eq!(a, b);
                assert_eq!(*a, SynthesisParams::default());
            }
            other => panic!("expected synthetic tracks, got {other:?}"),
        }
    }

    #[test]
    fn settings_are_applied() {
        let s = ScenarioSettings {
            speed: None,
            speed_kmh: Some(180.0),
            wheel: Some("jm3-worn".into()),
            name: None,
            seed: Some(7),
            band: Some([3.0, 100.0]),
            spectrum: Some("german-low".into()),
            step: Some(5e-4),
            output_rate: Some(200.0),
            fastsim_grid: Some([8, 12]),
            creep: Some("table".into()),
            initial_lateral_offset: Some(0.002),
            lead_in: Some(20.0),
            gauge: Some(1.44),
            gauge_height: Some(0.014),
            rail_inclination: Some(0.05),
            yaw_damper: Some("YD2".into()),
            ..settings("S_norm")
        }
        .resolve(GivenObjects::default(), Path::new("."))
        .unwrap();
        assert!((s.speed - 50.0).abs() < 1e-12);
        assert_eq!(s.wheel.name(), "jm3-worn");
        assert_eq!(s.rail.name(), "cn60");
        assert_eq!((s.fastsim.nx, s.fastsim.ny), (8, 12));
        assert_eq!(s.run.step, 5e-4);
        assert_eq!(s.run.output_rate, 200.0);
        assert_eq!(s.creep, CreepModel::from_name("table").unwrap());
        assert_eq!(s.initial_lateral_offset, 0.002);
        assert_eq!(s.lead_in, 20.0);
        assert_eq!(
            s.track_setup,
            TrackSetup {
                gauge: 1.44,
                gauge_height: 0.014,
                rail_inclination: 0.05
            }
        );
        assert_eq!(s.yaw_damper, Some(Damper::yd2()));
        match s.track {
            TrackSpec::Synthetic(p) => {
                assert_eq!(p.seed, 7);
                assert_eq!((p.wavelength_min, p.wavelength_max), (3.0, 100.0));
                assert_eq!(p.spectrum, TrackSpectrum::GermanLow);
            }
            other => panic!("expected a synthetic track, got {other:?}"),
        }
    }

    #[test]
    fn presets() {
        assert_eq!(yaw_damper_preset("file").unwrap(), None);
        assert_eq!(yaw_damper_preset("YD1").unwrap(), Some(Damper::yd1()));
        assert_eq!(yaw_damper_preset("YD2").unwrap(), Some(Damper::yd2()));
        assert_eq!(yaw_damper_preset("FSD").unwrap(), Some(Damper::fsd()));
        let base = ScenarioSettings {
            name: Some("S_low".into()),
            speed: Some(50.0),
            distance: Some(10.0),
            track: Some("perfect".into()),
            yaw_damper: Some("FSD".into()),
            fsd_trigger: Some("hydraulic".into()),
            ..ScenarioSettings::default()
        };
        let dir = Path::new(".");
        let hydraulic = base.resolve(GivenObjects::default(), dir).unwrap();
        assert_eq!(hydraulic.yaw_damper, Some(Damper::fsd_hydraulic()));
        let bad = ScenarioSettings {
            fsd_trigger: Some("zero-crossing".into()),
            ..base.clone()
        };
        assert_eq!(
            field_of(bad.resolve(GivenObjects::default(), dir).unwrap_err()),
            "fsd_trigger"
        );
        let not_fsd = ScenarioSettings {
            yaw_damper: Some("YD1".into()),
            ..base
        };
        assert_eq!(
            field_of(not_fsd.resolve(GivenObjects::default(), dir).unwrap_err()),
            "fsd_trigger"
        );
        assert_eq!(
            field_of(yaw_damper_preset("fsd").unwrap_err()),
            "yaw_damper"
        );
    }

    #[test]
    fn conflicts_are_refused_naming_the_field() {
        let dir = Path::new(".");
        let err = |s: ScenarioSettings, g: GivenObjects| field_of(s.resolve(g, dir).unwrap_err());
        let both_speeds = ScenarioSettings {
            speed_kmh: Some(100.0),
            ..settings("S_low")
        };
        assert_eq!(err(both_speeds, GivenObjects::default()), "speed");
        let name_and_wheel = ScenarioSettings {
            wheel: Some("jm3-new".into()),
            ..settings("S_low")
        };
        assert_eq!(err(name_and_wheel, GivenObjects::default()), "name");
        for (field, s) in [
            (
                "spectrum",
                ScenarioSettings {
                    spectrum: Some("cn-hsr".into()),
                    ..settings("S_low")
                },
            ),
            (
                "seed",
                ScenarioSettings {
                    seed: Some(1),
                    ..settings("S_low")
                },
            ),
            (
                "band",
                ScenarioSettings {
                    band: Some([2.0, 100.0]),
                    ..settings("S_low")
                },
            ),
        ] {
            let perfect = ScenarioSettings {
                track: Some("perfect".into()),
                ..s.clone()
            };
            assert_eq!(err(perfect, GivenObjects::default()), field);
            let given = GivenObjects {
                track: Some(Arc::new(
                    TrackIrregularity::from_channels(
                        0.5,
                        &[vec![0.0; 4], vec![0.0; 4], vec![0.0; 4], vec![0.0; 4]],
                        &[vec![0.0; 4], vec![0.0; 4], vec![0.0; 4], vec![0.0; 4]],
                        0.0,
                        None,
                    )
                    .unwrap(),
                )),
                ..GivenObjects::default()
            };
            assert_eq!(err(s, given), field);
        }
        let damper_twice = GivenObjects {
            yaw_damper: Some(Damper::fsd()),
            ..GivenObjects::default()
        };
        let preset = ScenarioSettings {
            yaw_damper: Some("YD1".into()),
            ..settings("S_low")
        };
        assert_eq!(err(preset, damper_twice), "yaw_damper");
        let missing = ScenarioSettings {
            distance: None,
            ..settings("S_low")
        };
        assert_eq!(err(missing, GivenObjects::default()), "distance");
        let nothing = ScenarioSettings {
            name: None,
            ..settings("S_low")
        };
        assert_eq!(err(nothing, GivenObjects::default()), "name");
    }

    #[test]
    fn toml_keys_are_checked() {
        let s: ScenarioSettings = toml::from_str(
            "name = 'S_high'\nspeed_kmh = 200.0\ndistance = 10.0\nfastsim_grid = [6, 6]\n",
        )
        .unwrap();
        assert_eq!(s.fastsim_grid, Some([6, 6]));
        assert!(toml::from_str::<ScenarioSettings>("name = 'S_high'\ndistanse = 10.0\n").is_err());
    }

    #[test]
    fn creep_model_by_name_and_the_removed_key() {
        let resolve = |text: &str| {
            toml::from_str::<ScenarioSettings>(text)
                .unwrap()
                .resolve(GivenObjects::default(), Path::new("."))
        };
        let base = "name = 'S_norm'\nspeed = 50.0\ndistance = 10.0\ntrack = 'perfect'\n";
        let s = resolve(&format!("{base}creep = 'fastrip'\n")).unwrap();
        assert_eq!(s.creep, CreepModel::Fastrip);
        let err = resolve(&format!("{base}creep = 'kalker'\n")).unwrap_err();
        assert_eq!(field_of(err), "creep");
        let err = resolve(&format!("{base}creep_table = true\n")).unwrap_err();
        assert!(err.to_string().contains("creep = \"table\""), "{err}");
        assert_eq!(field_of(err), "creep_table");
    }
}
