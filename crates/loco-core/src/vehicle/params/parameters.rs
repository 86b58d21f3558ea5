//! The vehicle parameter file: every number of the locomotive with its unit and source.
//!
//! The file is TOML with one table per component and one inline table per parameter:
//! `mass = { value = 42000.0, unit = "kg", source = "SPEC §1" }`. A parameter is addressed by
//! `section.name` (e.g. `secondary.yaw_damper_damping`), which is also the name used for overrides
//! (`ParameterSet::set`) and by the batch engine.
//!
//! The file must give exactly the keys of the [parameter schema](crate::vehicle::params::parameter_schema): an
//! unknown, misspelt or retired key, a missing key, an unknown field, a unit that is not a unit of
//! the parameter's quantity, a non-finite value, a fractional count or a value outside the
//! physical range is an error naming the key. Values may be stated in any unit the schema's SI
//! unit accepts (`vehicle/params/units.rs`) and are converted to SI on reading. A research value outside
//! the range is allowed only explicitly: `allow_out_of_range = ["carbody.mass", ...]` at the top of
//! the file lifts the range (not finiteness, not whole counts) for those keys, in the file and in
//! every override applied to the set. Derived values (the steel's shear modulus) are computed
//! (`TrackSection::shear_modulus` in [`crate::vehicle::params::sections`]).

use crate::error::{FileKind, LocoError, Result};
use crate::vehicle::params::parameter_schema::{schema, spec, unknown_key_reason};
use crate::vehicle::params::units;
use serde::Deserialize;
use std::collections::{BTreeMap, BTreeSet};

/// The embedded default vehicle (an SS8-like B0-B0 locomotive), shipped inside the crate.
pub const DEFAULT_VEHICLE_TOML: &str = include_str!("default_vehicle.toml");

/// The top-level key of a vehicle file that lists the parameters allowed outside their range.
pub const ALLOW_OUT_OF_RANGE: &str = "allow_out_of_range";

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
#[derive(Debug, Clone, PartialEq)]
pub struct Parameter {
    /// Value in SI units.
    pub value: f64,
    /// The SI unit of `value` (the schema's).
    pub unit: String,
    /// Where the value comes from: the spec, a published locomotive, a standard or an estimate
    /// (with the value as the file stated it when it was converted from another unit).
    pub source: String,
}

/// A parameter as a file states it.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileParameter {
    value: f64,
    unit: String,
    source: String,
}

/// All parameters of a vehicle, keyed by `section.name`, in a stable (sorted) order: exactly the
/// keys of the schema, each checked against it.
#[derive(Debug, Clone, PartialEq)]
pub struct ParameterSet {
    entries: BTreeMap<String, Parameter>,
    allow_out_of_range: BTreeSet<String>,
}

impl ParameterSet {
    /// The embedded default vehicle.
    pub fn default_vehicle() -> Self {
        // The embedded file is checked by a unit test, so parsing it cannot fail at run time.
        Self::from_toml_str(DEFAULT_VEHICLE_TOML, "<embedded default_vehicle.toml>")
            .unwrap_or_else(|e| panic!("embedded vehicle file is invalid: {e}"))
    }

    /// Parses and checks a vehicle file; `origin` names it in error messages. A file that is not
    /// TOML is a [`LocoError::Parse`]; a fault of one parameter (wrong type, unknown key or
    /// field, foreign unit, non-finite value, fractional count) a
    /// [`LocoError::InvalidParameterInFile`] naming the key and its line; a value outside its
    /// range a [`LocoError::OutOfRange`].
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self> {
        let bad = |name: &str, line: usize, reason: String| LocoError::InvalidParameterInFile {
            path: origin.to_string(),
            line,
            name: name.to_string(),
            reason,
        };
        let table: toml::Table = toml::from_str(text)
            .map_err(|e| LocoError::toml(FileKind::Vehicle, origin, text, &e))?;
        let mut allow = BTreeSet::new();
        let mut given: Vec<(String, FileParameter, usize)> = Vec::new();
        for (top, item) in table {
            let line = line_of(text, None, &top);
            if top == ALLOW_OUT_OF_RANGE {
                let names: Vec<String> = item
                    .try_into()
                    .map_err(|_| bad(&top, line, "must be a list of parameter keys".to_string()))?;
                for name in names {
                    if spec(&name).is_none() {
                        let reason = format!("`{name}`: {}", unknown_key_reason(&name));
                        return Err(bad(&top, line, reason));
                    }
                    allow.insert(name);
                }
                continue;
            }
            let toml::Value::Table(params) = item else {
                let reason = format!(
                    "expected a [section] of parameters or `{ALLOW_OUT_OF_RANGE}`, got {}",
                    describe(&item)
                );
                return Err(bad(&top, line, reason));
            };
            for (name, value) in params {
                let key = format!("{top}.{name}");
                let line = line_of(text, Some(&top), &name);
                let p = read_parameter(value).map_err(|reason| bad(&key, line, reason))?;
                given.push((key, p, line));
            }
        }
        let mut entries = BTreeMap::new();
        for (key, p, line) in given {
            let Some(s) = spec(&key) else {
                return Err(bad(&key, line, unknown_key_reason(&key)));
            };
            let Some(factor) = units::factor_to_si(&p.unit, &s.unit) else {
                let reason = format!(
                    "unit `{}` is not a unit of {} (accepted: {})",
                    p.unit,
                    s.unit,
                    units::accepted(&s.unit).join(", ")
                );
                return Err(bad(&key, line, reason));
            };
            let value = s
                .check(p.value * factor, allow.contains(&key))
                .map_err(|e| match e {
                    LocoError::InvalidParameter { reason, .. } => bad(&key, line, reason),
                    other => other,
                })?;
            let source = if p.unit.trim() == s.unit {
                p.source
            } else {
                format!("{} [stated as {} {}]", p.source, p.value, p.unit.trim())
            };
            let unit = s.unit.clone();
            entries.insert(
                key,
                Parameter {
                    value,
                    unit,
                    source,
                },
            );
        }
        let missing: Vec<&str> = schema()
            .iter()
            .filter(|s| !s.optional)
            .map(|s| s.key.as_str())
            .filter(|k| !entries.contains_key(*k))
            .collect();
        if !missing.is_empty() {
            return Err(LocoError::parse(
                FileKind::Vehicle,
                origin,
                0,
                format!("missing vehicle parameters: {}", missing.join(", ")),
            ));
        }
        Ok(Self {
            entries,
            allow_out_of_range: allow,
        })
    }

    /// The value of `key` (`section.name`), or an error naming the missing key.
    pub fn get(&self, key: &str) -> Result<f64> {
        self.entries
            .get(key)
            .map(|p| p.value)
            .ok_or_else(|| LocoError::param(key, "missing from the vehicle parameter file"))
    }

    /// The value of an optional `key` when the file or an override gives it (`None`: the model
    /// computes it).
    pub fn get_optional(&self, key: &str) -> Option<f64> {
        self.entries.get(key).map(|p| p.value)
    }

    /// The full record of `key`.
    pub fn parameter(&self, key: &str) -> Option<&Parameter> {
        self.entries.get(key)
    }

    /// Overrides the value of a parameter, by file key or study alias (`K_px`, ...), checked
    /// against the schema: unknown and retired names, non-finite values, fractional counts and
    /// values out of range (unless allowed) are refused.
    pub fn set(&mut self, name: &str, value: f64) -> Result<()> {
        let key = resolve_name(name);
        let label = if key == name {
            key.to_string()
        } else {
            format!("{name} ({key})")
        };
        let Some(s) = spec(key) else {
            return Err(LocoError::param(name, unknown_key_reason(key)));
        };
        let value = s
            .check(value, self.allow_out_of_range.contains(key))
            .map_err(|e| match e {
                LocoError::OutOfRange {
                    value,
                    min,
                    max,
                    unit,
                    ..
                } => LocoError::OutOfRange {
                    name: label.clone(),
                    value,
                    min,
                    max,
                    unit,
                },
                LocoError::InvalidParameter { reason, .. } => LocoError::param(&label, reason),
                other => other,
            })?;
        if s.optional && !self.entries.contains_key(key) {
            self.entries.insert(
                key.to_string(),
                Parameter {
                    value,
                    unit: s.unit.clone(),
                    source: "override".to_string(),
                },
            );
            return Ok(());
        }
        let p = self
            .entries
            .get_mut(key)
            .ok_or_else(|| LocoError::param(key, "missing from the vehicle parameter file"))?;
        p.value = value;
        p.source = "override".to_string();
        Ok(())
    }

    /// Lifts the range of `key` (not finiteness, not whole counts) for this set, as the file's
    /// `allow_out_of_range` list does.
    pub fn allow_out_of_range(&mut self, key: &str) -> Result<()> {
        let key = resolve_name(key);
        if spec(key).is_none() {
            return Err(LocoError::param(key, unknown_key_reason(key)));
        }
        self.allow_out_of_range.insert(key.to_string());
        Ok(())
    }

    /// The keys allowed outside their range, sorted.
    pub fn allowed_out_of_range(&self) -> impl Iterator<Item = &str> {
        self.allow_out_of_range.iter().map(String::as_str)
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

/// One parameter as the file states it, or why it is not one. The types are checked here rather
/// than left to serde, whose message names neither the field nor what was given for it.
fn read_parameter(value: toml::Value) -> std::result::Result<FileParameter, String> {
    const FORM: &str = "{ value = <number>, unit = \"<unit>\", source = \"<text>\" }";
    let toml::Value::Table(fields) = &value else {
        return Err(format!("expected {FORM}, got {}", describe(&value)));
    };
    match fields.get("value") {
        Some(toml::Value::Float(_) | toml::Value::Integer(_)) | None => {}
        Some(other) => return Err(format!("`value` must be a number, got {}", describe(other))),
    }
    for text in ["unit", "source"] {
        match fields.get(text) {
            Some(toml::Value::String(_)) | None => {}
            Some(other) => {
                return Err(format!(
                    "`{text}` must be a string, got {}",
                    describe(other)
                ))
            }
        }
    }
    value
        .try_into()
        .map_err(|e: toml::de::Error| format!("{} (expected {FORM})", e.message().trim()))
}

/// A TOML value for a message: its type, and the value itself when short.
fn describe(value: &toml::Value) -> String {
    let shown = value.to_string();
    let kind = value.type_str();
    if shown.chars().count() <= 40 {
        format!("{kind} {shown}")
    } else {
        kind.to_string()
    }
}

/// The 1-based line of `name` in `[section]` (None: a top-level key) of `text`, or 0.
pub(crate) fn line_of(text: &str, section: Option<&str>, name: &str) -> usize {
    let mut current: Option<&str> = None;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if let Some(header) = t.strip_prefix('[') {
            current = header.split(']').next().map(str::trim);
            continue;
        }
        let starts = t
            .strip_prefix(name)
            .is_some_and(|rest| rest.trim_start().starts_with('='));
        if starts && current == section {
            return i + 1;
        }
    }
    0
}

#[cfg(test)]
mod tests;
