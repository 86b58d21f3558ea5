//! The vehicle parameter file: every number of the locomotive with its unit and source.
//!
//! The file is TOML with one table per component and one inline table per parameter:
//! `mass = { value = 42000.0, unit = "kg", source = "SPEC §1" }`. Values are SI. A parameter is
//! addressed by `section.name` (e.g. `secondary.yaw_damper_damping`), which is also the name used
//! for overrides (`ParameterSet::set`) and by the batch engine.

use crate::error::{LocoError, Result};
use serde::Deserialize;
use std::collections::BTreeMap;

/// The embedded default vehicle (an SS8-like B0-B0 locomotive), shipped inside the crate.
pub const DEFAULT_VEHICLE_TOML: &str = include_str!("default_vehicle.toml");

/// The six parameters of the study (SPEC §6) by their names there, and the parameters of the
/// file they stand for (per axle box / per damper, SI units).
pub const STUDY_PARAMETERS: [(&str, &str); 6] = [
    ("K_px", "rotary_arm.node_stiffness_longitudinal"),
    ("K_py", "rotary_arm.node_stiffness_lateral"),
    ("C_sx", "secondary.yaw_damper_damping"),
    ("C_sy", "secondary.lateral_damper_damping"),
    ("K_ncsx", "secondary.yaw_damper_series_stiffness"),
    ("K_ncsy", "secondary.lateral_damper_series_stiffness"),
];

/// The file key for `name`: a study alias (`K_px`, ...) or the key itself.
pub fn resolve_name(name: &str) -> &str {
    STUDY_PARAMETERS
        .iter()
        .find(|(alias, _)| *alias == name)
        .map_or(name, |(_, key)| key)
}

/// One parameter: its value (SI), unit and where the value comes from.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct Parameter {
    /// Value in SI units.
    pub value: f64,
    /// Unit of `value`, for people (the code always works in SI).
    pub unit: String,
    /// Where the value comes from: the spec, a published locomotive, a standard or an estimate.
    pub source: String,
}

/// All parameters of a vehicle, keyed by `section.name`, in a stable (sorted) order.
#[derive(Debug, Clone, PartialEq)]
pub struct ParameterSet {
    entries: BTreeMap<String, Parameter>,
}

impl ParameterSet {
    /// The embedded default vehicle.
    pub fn default_vehicle() -> Self {
        // The embedded file is checked by a unit test, so parsing it cannot fail at run time.
        Self::from_toml_str(DEFAULT_VEHICLE_TOML, "<embedded default_vehicle.toml>")
            .unwrap_or_else(|e| panic!("embedded vehicle file is invalid: {e}"))
    }

    /// Parses a vehicle file; `origin` names it in error messages.
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self> {
        let parse_err = |reason: String| LocoError::Parse {
            path: origin.to_string(),
            line: 0,
            reason,
        };
        let tables: BTreeMap<String, BTreeMap<String, Parameter>> =
            toml::from_str(text).map_err(|e| {
                let line = e
                    .span()
                    .map(|s| text[..s.start.min(text.len())].matches('\n').count() + 1)
                    .unwrap_or(0);
                LocoError::Parse {
                    path: origin.to_string(),
                    line,
                    reason: e.message().to_string(),
                }
            })?;
        let mut entries = BTreeMap::new();
        for (section, params) in tables {
            for (name, param) in params {
                let key = format!("{section}.{name}");
                if !param.value.is_finite() {
                    return Err(parse_err(format!("`{key}` is not finite")));
                }
                entries.insert(key, param);
            }
        }
        Ok(Self { entries })
    }

    /// The value of `key` (`section.name`), or an error naming the missing key.
    pub fn get(&self, key: &str) -> Result<f64> {
        self.entries
            .get(key)
            .map(|p| p.value)
            .ok_or_else(|| LocoError::param(key, "missing from the vehicle parameter file"))
    }

    /// The full record of `key`.
    pub fn parameter(&self, key: &str) -> Option<&Parameter> {
        self.entries.get(key)
    }

    /// Overrides the value of an existing parameter, by file key or study alias (`K_px`, ...);
    /// unknown names and non-finite values are refused (a typo must not silently leave the
    /// default in place).
    pub fn set(&mut self, name: &str, value: f64) -> Result<()> {
        let key = resolve_name(name);
        if !value.is_finite() {
            let label = if key == name {
                key.to_string()
            } else {
                format!("{name} ({key})")
            };
            return Err(LocoError::param(
                label,
                format!("must be finite, got {value}"),
            ));
        }
        match self.entries.get_mut(key) {
            Some(p) => {
                p.value = value;
                p.source = "override".to_string();
                Ok(())
            }
            None => Err(LocoError::param(name, "unknown vehicle parameter")),
        }
    }

    /// All keys in sorted order.
    pub fn keys(&self) -> impl Iterator<Item = &str> {
        self.entries.keys().map(String::as_str)
    }

    /// All entries in sorted order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &Parameter)> {
        self.entries.iter().map(|(k, v)| (k.as_str(), v))
    }

    /// Number of parameters.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// True when the set holds no parameter.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_file_parses_with_sources() {
        let set = ParameterSet::from_toml_str(DEFAULT_VEHICLE_TOML, "embedded").unwrap();
        assert!(set.len() > 60);
        for (key, p) in set.iter() {
            assert!(!p.source.trim().is_empty(), "{key} has no source");
            assert!(!p.unit.trim().is_empty(), "{key} has no unit");
        }
        assert_eq!(set.get("carbody.mass").unwrap(), 42e3);
    }

    #[test]
    fn override_and_errors_name_the_key() {
        let mut set = ParameterSet::default_vehicle();
        set.set("secondary.yaw_damper_damping", 2e5).unwrap();
        assert_eq!(set.get("secondary.yaw_damper_damping").unwrap(), 2e5);
        set.set("K_py", 5e6).unwrap();
        assert_eq!(set.get("rotary_arm.node_stiffness_lateral").unwrap(), 5e6);
        for (_, key) in STUDY_PARAMETERS {
            assert!(set.parameter(key).is_some(), "{key}");
        }
        let e = set.set("secondary.yaw_dampr", 1.0).unwrap_err();
        assert!(e.to_string().contains("secondary.yaw_dampr"));
        assert!(set.set("carbody.mass", f64::NAN).is_err());
        let e = ParameterSet::from_toml_str("[a]\nb = 3", "f.toml").unwrap_err();
        assert!(matches!(e, LocoError::Parse { .. }));
    }
}
