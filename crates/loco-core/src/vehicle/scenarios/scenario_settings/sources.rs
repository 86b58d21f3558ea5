//! Where a scenario's profiles and track come from: a study scenario's name, built-in or file
//! profiles by name, given profile objects; a synthesised, perfect, measured or given track;
//! each conflict between two ways of giving the same thing refused naming the field.

use super::{conflict, ScenarioSettings, PERFECT, SYNTHETIC};
use crate::contact::builtin::{builtin_names, builtin_profile};
use crate::contact::profile::{Profile, ProfileKind};
use crate::contact::profile_io::load_profile;
use crate::error::{LocoError, Result};
use crate::track::{load_csv, MeasuredParams, SynthesisParams, TrackIrregularity, TrackSpectrum};
use crate::vehicle::params::presets::{scenario_profiles, STUDY_RAIL};
use crate::vehicle::scenarios::scenario::TrackSpec;
use std::path::Path;
use std::sync::Arc;

/// A profile by name: built-in, else a file relative to `dir`.
fn lookup_profile(name: &str, kind: ProfileKind, dir: &Path) -> Result<Profile> {
    if builtin_names().contains(&name) {
        builtin_profile(name)
    } else {
        let path = dir.join(name);
        if !path.is_file() {
            let field = if kind == ProfileKind::Wheel {
                "wheel"
            } else {
                "rail"
            };
            return Err(LocoError::param(
                field,
                format!(
                    "'{name}' is neither a built-in profile ({}) nor a profile file",
                    builtin_names().join(", ")
                ),
            ));
        }
        load_profile(&path, Some(kind), false)
    }
}

impl ScenarioSettings {
    pub(super) fn profiles(
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
            (None, None) => builtin_profile(STUDY_RAIL)?,
        };
        Ok((wheel, rail))
    }

    /// Refuses the synthesis settings for a track that is not synthesised.
    pub(super) fn no_synthesis_settings(&self, what: &str) -> Result<()> {
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

    pub(super) fn track(
        &self,
        given: Option<Arc<TrackIrregularity>>,
        dir: &Path,
    ) -> Result<TrackSpec> {
        if let Some(track) = given {
            if self.track.is_some() {
                return Err(conflict("track", "given both as a setting and as a track"));
            }
            self.no_synthesis_settings("a given one")?;
            return Ok(TrackSpec::Given(track));
        }
        match self.track.as_deref().unwrap_or(SYNTHETIC) {
            SYNTHETIC => {
                let defaults = SynthesisParams::default();
                let spectrum = match &self.spectrum {
                    Some(name) => TrackSpectrum::from_name(name)?,
                    None => defaults.spectrum,
                };
                let band = self
                    .band
                    .unwrap_or([defaults.wavelength_min, defaults.wavelength_max]);
                let params = SynthesisParams {
                    spectrum,
                    seed: self.seed.unwrap_or(defaults.seed),
                    wavelength_min: band[0],
                    wavelength_max: band[1],
                    ..defaults
                };
                // The band is checked now and under its own name, not at the run as the
                // synthesis' internal fields.
                params.validate().map_err(|e| match e {
                    LocoError::InvalidParameter { name, reason }
                        if ["wavelength_min", "wavelength_max", "step", "length"]
                            .contains(&name.as_str()) =>
                    {
                        conflict(
                            "band",
                            format!("[{}, {}] m: {name} {reason}", band[0], band[1]),
                        )
                    }
                    other => other,
                })?;
                Ok(TrackSpec::Synthetic(params))
            }
            PERFECT => {
                self.no_synthesis_settings("perfect")?;
                Ok(TrackSpec::Perfect)
            }
            file => {
                self.no_synthesis_settings("a measured one")?;
                let path = dir.join(file);
                if !path.is_file() {
                    return Err(LocoError::param(
                        "track",
                        format!(
                            "'{file}' is neither '{SYNTHETIC}', '{PERFECT}' nor a measured track file"
                        ),
                    ));
                }
                Ok(TrackSpec::Given(Arc::new(load_csv(
                    &path.display().to_string(),
                    &MeasuredParams::default(),
                )?)))
            }
        }
    }
}
