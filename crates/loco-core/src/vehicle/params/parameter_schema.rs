//! The parameter schema: for every key of a vehicle file its SI unit, kind (real or count),
//! physical range, what it affects (structure, contact, metrics) and a description.
//!
//! The schema is the one list of the vehicle's parameters (`parameter_schema.toml`, embedded): a
//! vehicle file must give exactly its keys, each value is checked against its entry, the batch
//! engine decides from `affects` what it can share between samples, and the docs table and
//! `loco.parameter_schema()` are this list. Keys the model used to carry but does not read are
//! [`RETIRED`], with the reason, so that an old file fails with an explanation.

use crate::error::{LocoError, Result};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::sync::OnceLock;

/// The embedded schema file.
pub const SCHEMA_TOML: &str = include_str!("parameter_schema.toml");

/// Largest count any element may have, even with `allow_out_of_range`: the model builds one
/// element per count for some of them, so a count is a small number, never an allocation size.
pub const MAX_COUNT: f64 = 16.0;

/// Keys that are not vehicle parameters (any more), and why: a file or override naming one is
/// refused with this reason.
pub const RETIRED: [(&str, &str); 10] = [
    ("track.gauge", "the track gauge is a setting of the scenario (`gauge`, m), not of the vehicle"),
    ("track.rail_inclination", "the rail inclination is a setting of the scenario (`rail_inclination`, rad), not of the vehicle"),
    ("track.shear_modulus", "derived: G = E / (2 (1 + ν)) from `track.young_modulus` and `track.poisson_ratio`"),
    ("carbody.length_over_buffers", "not read by the model: the carbody is a rigid body given by its mass, inertias and centre of gravity (the lengths that sized the inertias are in their sources)"),
    ("carbody.body_length", "not read by the model: the carbody is a rigid body given by its mass, inertias and centre of gravity (the lengths that sized the inertias are in their sources)"),
    ("carbody.width", "not read by the model: the carbody is a rigid body given by its mass, inertias and centre of gravity (the width that sized the roll inertia is in its source)"),
    ("traction_motor.gear_centre_distance", "not read by the model: the gear mesh is not modelled; the motor sits at `traction_motor.cog_longitudinal_offset` from its axle"),
    ("hollow_shaft.coupling_torsional_stiffness", "not read by the model: the hollow shaft turns with its wheelset (SPEC §1 gives it no spin coordinate of its own), so the coupling has no torsion to resist"),
    ("traction_rod.length", "derived: the rod's length is the distance between its two ends (`traction_rod.carbody_end_*` and `traction_rod.frame_end_*`)"),
    ("traction_rod.rods_per_bogie", "not read by the model: the model has one traction-rod body per bogie (SPEC §1, 25 bodies); another arrangement is another model"),
];

/// Whether a parameter is any real number in its range or a whole count of identical elements.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    Real,
    Count,
}

/// What changing a parameter changes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Affects {
    /// Bodies, mass matrix, suspension elements (`VehicleStructure`).
    Structure,
    /// The wheel-rail contact of a run (contact table, Hertz, FASTSIM, friction, damping).
    Contact,
    /// Where the channels the metrics are computed from are measured.
    Metrics,
}

impl Affects {
    /// Lower-case name, as in the schema file.
    pub fn name(self) -> &'static str {
        match self {
            Affects::Structure => "structure",
            Affects::Contact => "contact",
            Affects::Metrics => "metrics",
        }
    }
}

impl Kind {
    /// Lower-case name, as in the schema file.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Real => "real",
            Kind::Count => "count",
        }
    }
}

/// One entry of the schema.
#[derive(Debug, Clone, PartialEq)]
pub struct ParameterSpec {
    /// `section.name`.
    pub key: String,
    /// The SI unit the model reads the value in.
    pub unit: String,
    pub kind: Kind,
    /// Physical range, inclusive, in `unit`.
    pub min: f64,
    pub max: f64,
    pub affects: Vec<Affects>,
    pub description: String,
    /// Why the range is what it is.
    pub why: String,
    /// A file may leave it out: the model then computes it (the description says how).
    pub optional: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSpec {
    unit: String,
    kind: Kind,
    range: [f64; 2],
    affects: Vec<Affects>,
    description: String,
    why: String,
    #[serde(default)]
    optional: bool,
}

impl ParameterSpec {
    /// True when a change of this parameter changes `what`.
    pub fn affects(&self, what: Affects) -> bool {
        self.affects.contains(&what)
    }

    /// Checks `value` (SI) for this parameter: finite, a whole number for a count, inside the
    /// range unless `allow_out_of_range` (a count never beyond `0..=MAX_COUNT`).
    pub fn check(&self, value: f64, allow_out_of_range: bool) -> Result<f64> {
        if !value.is_finite() {
            return Err(LocoError::param(
                &self.key,
                format!("must be finite, got {value}"),
            ));
        }
        if self.kind == Kind::Count && value.fract() != 0.0 {
            return Err(LocoError::param(
                &self.key,
                format!("is a count of elements and must be a whole number, got {value}"),
            ));
        }
        let (min, max) = match (allow_out_of_range, self.kind) {
            (false, _) => (self.min, self.max),
            (true, Kind::Count) => (0.0, MAX_COUNT),
            (true, Kind::Real) => return Ok(value),
        };
        if value < min || value > max {
            return Err(LocoError::OutOfRange {
                name: self.key.clone(),
                value,
                min,
                max,
                unit: self.unit.clone(),
            });
        }
        Ok(value)
    }
}

/// The schema, in key order (sections and names sorted).
pub fn schema() -> &'static [ParameterSpec] {
    static SCHEMA: OnceLock<Vec<ParameterSpec>> = OnceLock::new();
    SCHEMA.get_or_init(|| {
        // The embedded file is checked by unit tests, so this cannot fail at run time.
        parse(SCHEMA_TOML).unwrap_or_else(|e| panic!("embedded parameter schema is invalid: {e}"))
    })
}

/// The entry of `key` (`section.name`), if it is a vehicle parameter.
pub fn spec(key: &str) -> Option<&'static ParameterSpec> {
    let all = schema();
    all.binary_search_by(|s| s.key.as_str().cmp(key))
        .ok()
        .map(|i| &all[i])
}

/// Why `key` is not a parameter any more, if it is a retired one.
pub fn retired(key: &str) -> Option<&'static str> {
    RETIRED.iter().find(|(k, _)| *k == key).map(|(_, why)| *why)
}

/// The reason to give for a key that is not in the schema: retired (with why) or unknown (with
/// the closest schema key, for typos).
pub fn unknown_key_reason(key: &str) -> String {
    if let Some(why) = retired(key) {
        return format!("not a vehicle parameter: {why}");
    }
    let closest = schema()
        .iter()
        .map(|s| (edit_distance(&s.key, key), &s.key))
        .min()
        .filter(|(d, _)| *d <= 3);
    match closest {
        Some((_, k)) => format!("unknown vehicle parameter (did you mean `{k}`?)"),
        None => "unknown vehicle parameter (see docs/vehicle_parameters.md)".to_string(),
    }
}

/// Levenshtein distance, for suggestions.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = (diagonal + usize::from(ca != *cb))
                .min(row[j] + 1)
                .min(above + 1);
            diagonal = above;
        }
    }
    row[b.len()]
}

fn parse(text: &str) -> std::result::Result<Vec<ParameterSpec>, String> {
    let sections: BTreeMap<String, BTreeMap<String, RawSpec>> =
        toml::from_str(text).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    for (section, entries) in sections {
        for (name, raw) in entries {
            let key = format!("{section}.{name}");
            let [min, max] = raw.range;
            if !(min.is_finite() && max.is_finite() && min < max) {
                return Err(format!("{key}: range must be finite with min < max"));
            }
            if raw.kind == Kind::Count
                && (min.fract() != 0.0 || max.fract() != 0.0 || max > MAX_COUNT)
            {
                return Err(format!(
                    "{key}: a count's range must be whole numbers ≤ {MAX_COUNT}"
                ));
            }
            if !crate::vehicle::params::units::is_known_si(&raw.unit) {
                return Err(format!("{key}: unit `{}` is not in units.rs", raw.unit));
            }
            if raw.affects.is_empty()
                || raw.description.trim().is_empty()
                || raw.why.trim().is_empty()
            {
                return Err(format!(
                    "{key}: affects, description and why must not be empty"
                ));
            }
            out.push(ParameterSpec {
                key,
                unit: raw.unit,
                kind: raw.kind,
                min,
                max,
                affects: raw.affects,
                description: raw.description,
                why: raw.why,
                optional: raw.optional,
            });
        }
    }
    // `BTreeMap` iteration sorts sections and names; keep the keys sorted as strings for lookups.
    out.sort_by(|a, b| a.key.cmp(&b.key));
    Ok(out)
}

#[cfg(test)]
mod tests;
