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
                    .map(|s| text[..s.start.min(text.len())].lines().count().max(1))
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

    /// Overrides the value of an existing parameter; unknown names and non-finite values are
    /// refused (a typo must not silently leave the default in place).
    pub fn set(&mut self, key: &str, value: f64) -> Result<()> {
        if !value.is_finite() {
            return Err(LocoError::param(
                key,
                format!("must be finite, got {value}"),
            ));
        }
        match self.entries.get_mut(key) {
            Some(p) => {
                p.value = value;
                p.source = "override".to_string();
                Ok(())
            }
            None => Err(LocoError::param(key, "unknown vehicle parameter")),
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
        let e = set.set("secondary.yaw_dampr", 1.0).unwrap_err();
        assert!(e.to_string().contains("secondary.yaw_dampr"));
        assert!(set.set("carbody.mass", f64::NAN).is_err());
        let e = ParameterSet::from_toml_str("[a]\nb = 3", "f.toml").unwrap_err();
        assert!(matches!(e, LocoError::Parse { .. }));
    }
}
