//! Plausible ranges of a vehicle's inputs: what each value could be, given where it comes from
//! (a tolerance on a given value, the range an estimate or a scaling leaves open), read from a
//! ranges file (the embedded `default_uncertainty.toml` or a user's, same format; its header
//! describes it) against a vehicle's parameters.
//!
//! Refused, naming the key and the file's line: a key that is not a vehicle parameter or a
//! scenario input, an unknown class, an empty or reversed range, a range outside the
//! parameter's validity (the schema's range) or one that does not contain the vehicle's value.

use crate::contact::builtin::jm3::{
    self, TreadState, MAX_CONE_SLOPE, MIN_BAND_RADIUS, MIN_CONE_SLOPE,
};
use crate::contact::setup::TrackSetup;
use crate::error::{FileKind, LocoError, Result};
use crate::vehicle::params::parameter_schema::{spec, unknown_key_reason, Kind};
use crate::vehicle::params::parameters::{line_of, ParameterSet};
use serde::Deserialize;
use std::collections::BTreeMap;

/// The embedded ranges of the default vehicle.
pub const DEFAULT_UNCERTAINTY_TOML: &str = include_str!("default_uncertainty.toml");

/// Where a range comes from.
pub const RANGE_KINDS: [&str; 3] = ["tolerance", "scaling", "estimate"];

/// One input's plausible range.
#[derive(Debug, Clone, PartialEq)]
pub struct InputRange {
    /// A vehicle parameter key (`carbody.mass`), `scenario.rail_inclination` or
    /// `wheel.<built-in JM3 profile>.<field>`.
    pub key: String,
    /// The vehicle's (or the built-in's) value, in `unit`.
    pub nominal: f64,
    pub low: f64,
    pub high: f64,
    pub unit: String,
    /// One of [`RANGE_KINDS`].
    pub kind: String,
    pub why: String,
    pub source: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Class {
    factors: [f64; 2],
    kind: String,
    why: String,
    source: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Explicit {
    low: Option<f64>,
    high: Option<f64>,
    factors: Option<[f64; 2]>,
    kind: String,
    why: String,
    source: String,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum Entry {
    Class(String),
    Explicit(Explicit),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RangesFile {
    #[serde(default)]
    classes: BTreeMap<String, Class>,
    #[serde(default)]
    parameters: BTreeMap<String, BTreeMap<String, Entry>>,
    #[serde(default)]
    scenario: BTreeMap<String, Entry>,
}

/// A scenario input: value, validity (inclusive) and unit.
fn scenario_input(key: &str) -> Option<(f64, (f64, f64), &'static str)> {
    if key == "rail_inclination" {
        // Vertical rails to 1:10; inclinations in use are 1:20 to 1:40.
        return Some((TrackSetup::default().rail_inclination, (0.0, 0.1), "rad"));
    }
    let (profile, field) = key.strip_prefix("wheel.")?.split_once('.')?;
    let state: TreadState = jm3::builtin_state(profile)?;
    match field {
        "tread_slope" => Some((state.tread_slope, (MIN_CONE_SLOPE, MAX_CONE_SLOPE), "1")),
        "band_radius" => Some((state.band_radius, (MIN_BAND_RADIUS, f64::INFINITY), "m")),
        "flange_thickness" => Some((state.flange_thickness, (0.022, 0.034), "m")),
        _ => None,
    }
}

/// The ranges of `ranges_text` (named `origin` in errors) for the vehicle `parameters`, in the
/// file's order of sections: the vehicle parameters by key, then the scenario inputs.
pub fn input_ranges(
    parameters: &ParameterSet,
    ranges_text: &str,
    origin: &str,
) -> Result<Vec<InputRange>> {
    let file: RangesFile = toml::from_str(ranges_text)
        .map_err(|e| LocoError::toml(FileKind::Study, origin, ranges_text, &e))?;
    let bad = |key: &str, line: usize, reason: String| LocoError::InvalidParameterInFile {
        path: origin.to_string(),
        line,
        name: key.to_string(),
        reason,
    };
    for (name, class) in &file.classes {
        let line = line_of(ranges_text, Some("classes"), name);
        check_kind(&class.kind).map_err(|r| bad(name, line, r))?;
        check_factors(class.factors).map_err(|r| bad(name, line, r))?;
    }
    let mut out = Vec::new();
    let mut resolve = |key: String,
                       line: usize,
                       entry: &Entry,
                       nominal: f64,
                       validity: (f64, f64),
                       unit: &str|
     -> Result<()> {
        let (low, high, kind, why, source) = match entry {
            Entry::Class(name) => {
                let class = file
                    .classes
                    .get(name)
                    .ok_or_else(|| bad(&key, line, format!("unknown range class `{name}`")))?;
                let (a, b) = scaled(nominal, class.factors);
                (a, b, &class.kind, &class.why, &class.source)
            }
            Entry::Explicit(e) => {
                let (a, b) = match (e.low, e.high, e.factors) {
                    (Some(low), Some(high), None) => (low, high),
                    (None, None, Some(f)) => {
                        check_factors(f).map_err(|r| bad(&key, line, r))?;
                        scaled(nominal, f)
                    }
                    _ => {
                        let reason = "give either `low` and `high` or `factors`".to_string();
                        return Err(bad(&key, line, reason));
                    }
                };
                check_kind(&e.kind).map_err(|r| bad(&key, line, r))?;
                (a, b, &e.kind, &e.why, &e.source)
            }
        };
        check_range(low, high, nominal, validity, unit).map_err(|r| bad(&key, line, r))?;
        out.push(InputRange {
            key,
            nominal,
            low,
            high,
            unit: unit.to_string(),
            kind: kind.clone(),
            why: why.clone(),
            source: source.clone(),
        });
        Ok(())
    };
    for (section, entries) in &file.parameters {
        let header = format!("parameters.{section}");
        for (name, entry) in entries {
            let key = format!("{section}.{name}");
            let line = line_of(ranges_text, Some(&header), name);
            let Some(s) = spec(&key) else {
                return Err(bad(&key, line, unknown_key_reason(&key)));
            };
            if s.kind == Kind::Count {
                let reason = "is a count (a design choice): it takes no range".to_string();
                return Err(bad(&key, line, reason));
            }
            let nominal = parameters.get(&key)?;
            resolve(key, line, entry, nominal, (s.min, s.max), &s.unit)?;
        }
    }
    for (name, entry) in &file.scenario {
        let quoted = format!("\"{name}\"");
        let line = match line_of(ranges_text, Some("scenario"), name) {
            0 => line_of(ranges_text, Some("scenario"), &quoted),
            n => n,
        };
        let key = if name.starts_with("wheel.") {
            name.clone()
        } else {
            format!("scenario.{name}")
        };
        let Some((nominal, validity, unit)) = scenario_input(name) else {
            let reason = "not a scenario input: expected `rail_inclination` or \
                          `wheel.<jm3-new|jm3-thin-flange|jm3-worn>.<tread_slope|band_radius|\
                          flange_thickness>`"
                .to_string();
            return Err(bad(&key, line, reason));
        };
        resolve(key, line, entry, nominal, validity, unit)?;
    }
    Ok(out)
}

/// `nominal` times the factors, low first (a negative value reverses them).
fn scaled(nominal: f64, [a, b]: [f64; 2]) -> (f64, f64) {
    let (x, y) = (nominal * a, nominal * b);
    (x.min(y), x.max(y))
}

fn check_kind(kind: &str) -> std::result::Result<(), String> {
    if RANGE_KINDS.contains(&kind) {
        Ok(())
    } else {
        Err(format!(
            "kind `{kind}` is not one of {}",
            RANGE_KINDS.join(", ")
        ))
    }
}

fn check_factors([a, b]: [f64; 2]) -> std::result::Result<(), String> {
    if a.is_finite() && b.is_finite() && 0.0 < a && a < b {
        Ok(())
    } else {
        Err(format!(
            "factors must be finite with 0 < low < high, got [{a}, {b}]"
        ))
    }
}

fn check_range(
    low: f64,
    high: f64,
    nominal: f64,
    (min, max): (f64, f64),
    unit: &str,
) -> std::result::Result<(), String> {
    if !(low.is_finite() && high.is_finite()) {
        return Err(format!("range [{low}, {high}] {unit} is not finite"));
    }
    if low >= high {
        return Err(format!(
            "range [{low}, {high}] {unit} is empty or reversed (need low < high)"
        ));
    }
    if low < min || high > max {
        return Err(format!(
            "range [{low}, {high}] {unit} leaves the parameter's validity [{min}, {max}] {unit}"
        ));
    }
    if !(low..=high).contains(&nominal) {
        return Err(format!(
            "range [{low}, {high}] {unit} does not contain the vehicle's value {nominal} {unit}"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests;
