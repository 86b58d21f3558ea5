//! Curve sections as front ends state them: named fields with their units (a `[[scenario.curve]]`
//! table of the batch study file, a Python dict, a row of a CSV file), turned into
//! [`DesignSection`]s with errors naming the section and the field.
//!
//! Fields: `kind` (`straight`, `transition` or `curve`), `length_m`; for a curve `radius_m`,
//! `cant_mm` (default 0) and `direction` (`left` or `right`); for a transition optionally
//! `cant_run_off_m` (default: its length). The CSV file has these names as its header (any
//! order, empty cells for fields a section does not use).

use super::design::{CurveDirection, DesignSection};
use crate::error::{FileKind, LocoError, Result};
use crate::util::csv_table::CsvTable;
use crate::util::toml_fields::read_table;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// One section in named fields (units in the names).
#[derive(Debug, Clone, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SectionSetting {
    pub kind: String,
    pub length_m: f64,
    pub radius_m: Option<f64>,
    pub cant_mm: Option<f64>,
    pub direction: Option<String>,
    pub cant_run_off_m: Option<f64>,
}

fn field(i: usize, name: &str) -> String {
    format!("curve section {} ({name})", i + 1)
}

/// The fields of a section, in the order the docs give them.
pub const SECTION_FIELDS: [&str; 6] = [
    "kind",
    "length_m",
    "radius_m",
    "cant_mm",
    "direction",
    "cant_run_off_m",
];

impl SectionSetting {
    /// Section `i` (0-based) from a TOML value (a `[[scenario.curve]]` table, a Python dict):
    /// an error names the section and the field that is wrong, unknown or of the wrong type,
    /// or the section when a required field is missing.
    pub fn from_toml(i: usize, value: toml::Value) -> Result<Self> {
        let whole = format!("curve section {}", i + 1);
        let toml::Value::Table(table) = value else {
            return Err(LocoError::param(
                whole,
                format!(
                    "expected a table of {}, got a {}",
                    SECTION_FIELDS.join(", "),
                    value.type_str()
                ),
            ));
        };
        let base = toml::Table::try_from(Self::default()).unwrap_or_default();
        read_table(&table, &base, &whole, |k| field(i, k))
    }

    /// The section, checked for the fields its kind needs and allows; `i` is its 0-based index.
    pub fn resolve(&self, i: usize) -> Result<DesignSection> {
        let refuse = |name: &str, given: bool| {
            if given {
                Err(LocoError::param(
                    field(i, name),
                    format!("not used by a {} section", self.kind),
                ))
            } else {
                Ok(())
            }
        };
        match self.kind.as_str() {
            "straight" => {
                refuse("radius_m", self.radius_m.is_some())?;
                refuse("cant_mm", self.cant_mm.is_some())?;
                refuse("direction", self.direction.is_some())?;
                refuse("cant_run_off_m", self.cant_run_off_m.is_some())?;
                Ok(DesignSection::Straight {
                    length: self.length_m,
                })
            }
            "transition" => {
                refuse("radius_m", self.radius_m.is_some())?;
                refuse("cant_mm", self.cant_mm.is_some())?;
                refuse("direction", self.direction.is_some())?;
                Ok(DesignSection::Transition {
                    length: self.length_m,
                    cant_run_off: self.cant_run_off_m,
                })
            }
            "curve" => {
                refuse("cant_run_off_m", self.cant_run_off_m.is_some())?;
                let radius = self.radius_m.ok_or_else(|| {
                    LocoError::param(field(i, "radius_m"), "missing: a curve needs its radius")
                })?;
                let direction = self.direction.as_deref().ok_or_else(|| {
                    LocoError::param(field(i, "direction"), "missing: left or right")
                })?;
                Ok(DesignSection::Curve {
                    length: self.length_m,
                    radius,
                    cant: self.cant_mm.unwrap_or(0.0) * 1e-3,
                    direction: CurveDirection::from_name(direction, &field(i, "direction"))?,
                })
            }
            other => Err(LocoError::param(
                field(i, "kind"),
                format!("expected straight, transition or curve, got '{other}'"),
            )),
        }
    }
}

/// All sections of a list.
pub fn resolve_sections(settings: &[SectionSetting]) -> Result<Vec<DesignSection>> {
    settings
        .iter()
        .enumerate()
        .map(|(i, s)| s.resolve(i))
        .collect()
}

/// Sections from CSV text (header row of field names); `path` names the file in errors.
pub fn parse_sections_csv(text: &str, path: &str) -> Result<Vec<SectionSetting>> {
    let table = CsvTable::parse(text, path, FileKind::Track)?;
    let known = SECTION_FIELDS;
    let header = table.header_line;
    if let Some(bad) = table.names.iter().find(|n| !known.contains(n)) {
        return Err(table.error(
            header,
            format!("unknown column '{bad}'; expected {}", known.join(", ")),
        ));
    }
    for required in ["kind", "length_m"] {
        if !table.names.contains(&required) {
            return Err(table.error(header, format!("missing column '{required}'")));
        }
    }
    let mut out = Vec::new();
    for (number, cells) in &table.rows {
        let number = *number;
        let mut s = SectionSetting::default();
        for (name, &cell) in table.names.iter().zip(cells) {
            if cell.is_empty() {
                continue;
            }
            let number_of = |cell: &str| {
                cell.parse::<f64>()
                    .map_err(|_| table.error(number, format!("{name}: not a number: '{cell}'")))
            };
            match *name {
                "kind" => s.kind = cell.to_string(),
                "direction" => s.direction = Some(cell.to_string()),
                "length_m" => s.length_m = number_of(cell)?,
                "radius_m" => s.radius_m = Some(number_of(cell)?),
                "cant_mm" => s.cant_mm = Some(number_of(cell)?),
                _ => s.cant_run_off_m = Some(number_of(cell)?),
            }
        }
        if s.kind.is_empty() {
            return Err(table.error(number, "kind: empty"));
        }
        out.push(s);
    }
    if out.is_empty() {
        return Err(table.error(0, "no sections"));
    }
    Ok(out)
}

/// Sections from a CSV file.
pub fn load_sections_csv(path: &Path) -> Result<Vec<SectionSetting>> {
    let text = crate::util::text_file::read_text(path, FileKind::Track)?;
    parse_sections_csv(&text, &path.display().to_string())
}

/// The `curve` setting: sections in place, or a CSV file of them. Read by
/// [`CurveSetting::from_toml`] (also as serde's `Deserialize`), so that a bad section in a study
/// file is named with its field, not with an untagged enum's "did not match any variant".
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum CurveSetting {
    File(String),
    Sections(Vec<SectionSetting>),
}

impl<'de> Deserialize<'de> for CurveSetting {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let value = toml::Value::deserialize(d)?;
        Self::from_toml(value).map_err(serde::de::Error::custom)
    }
}

impl CurveSetting {
    /// The setting from its TOML value: a string is the path of a CSV file, an array the
    /// sections ([`SectionSetting::from_toml`]); anything else is an error naming `curve`.
    pub fn from_toml(value: toml::Value) -> Result<Self> {
        match value {
            toml::Value::String(path) => Ok(Self::File(path)),
            toml::Value::Array(sections) => sections
                .into_iter()
                .enumerate()
                .map(|(i, s)| SectionSetting::from_toml(i, s))
                .collect::<Result<Vec<_>>>()
                .map(Self::Sections),
            other => Err(LocoError::param(
                "curve",
                format!(
                    "expected the path of a CSV file or a list of sections, got a {}",
                    other.type_str()
                ),
            )),
        }
    }

    /// The sections, a file relative to `dir`.
    pub fn sections(&self, dir: &Path) -> Result<Vec<DesignSection>> {
        let sections = self.sections_given(dir)?;
        if sections.is_empty() {
            return Err(LocoError::param(
                "curve",
                "no sections: give at least one section, or leave `curve` out for straight track",
            ));
        }
        Ok(sections)
    }

    fn sections_given(&self, dir: &Path) -> Result<Vec<DesignSection>> {
        match self {
            Self::File(file) => {
                // As the track: a name that is no file is the setting's fault, named by it.
                let path = dir.join(file);
                if !path.is_file() {
                    return Err(LocoError::param(
                        "curve",
                        format!("'{file}' is not a curve file (CSV of sections), nor a list of sections"),
                    ));
                }
                resolve_sections(&load_sections_csv(&path)?)
            }
            Self::Sections(list) => resolve_sections(list),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_rows_become_sections() {
        let text = "kind,length_m,radius_m,cant_mm,direction,cant_run_off_m\n\
                    straight,50,,,,\n\
                    transition,80,,,,60\n\
                    curve,300,600,120,right,\n";
        let sections = resolve_sections(&parse_sections_csv(text, "c.csv").unwrap()).unwrap();
        assert_eq!(
            sections,
            vec![
                DesignSection::Straight { length: 50.0 },
                DesignSection::Transition {
                    length: 80.0,
                    cant_run_off: Some(60.0)
                },
                DesignSection::Curve {
                    length: 300.0,
                    radius: 600.0,
                    cant: 0.12,
                    direction: CurveDirection::Right
                },
            ]
        );
    }

    #[test]
    fn bad_rows_and_fields_are_named() {
        let e = parse_sections_csv("kind,length_m,speed\n", "c.csv").unwrap_err();
        assert!(
            e.to_string().contains("c.csv:1: unknown column 'speed'"),
            "{e}"
        );
        let e = parse_sections_csv("kind,length_m\nstraight,x\n", "c.csv").unwrap_err();
        assert!(e.to_string().contains("c.csv:2: length_m"), "{e}");
        let curve = SectionSetting {
            kind: "curve".into(),
            length_m: 10.0,
            radius_m: Some(600.0),
            ..SectionSetting::default()
        };
        let e = curve.resolve(2).unwrap_err().to_string();
        assert!(e.contains("curve section 3 (direction)"), "{e}");
        let straight = SectionSetting {
            kind: "straight".into(),
            length_m: 10.0,
            cant_mm: Some(50.0),
            ..SectionSetting::default()
        };
        let e = straight.resolve(0).unwrap_err().to_string();
        assert!(e.contains("curve section 1 (cant_mm)"), "{e}");
    }
}

#[cfg(test)]
mod study_file_tests {
    use crate::vehicle::scenarios::scenario_settings::ScenarioSettings;
    use std::path::Path;

    #[test]
    fn a_study_file_states_curves_as_tables_or_a_csv_path() {
        let text = r#"
            name = "S_norm"
            speed_kmh = 120.0
            distance = 100.0
            track = "perfect"
            [[curve]]
            kind = "transition"
            length_m = 50.0
            [[curve]]
            kind = "curve"
            length_m = 200.0
            radius_m = 800.0
            cant_mm = 110.0
            direction = "left"
        "#;
        let settings: ScenarioSettings = toml::from_str(text).unwrap();
        let scenario = settings
            .resolve(Default::default(), Path::new("."))
            .unwrap();
        assert_eq!(scenario.curve.len(), 2);
        let missing: ScenarioSettings = toml::from_str(
            "name = \"S_norm\"\nspeed = 10.0\ndistance = 10.0\ncurve = \"no-such.csv\"",
        )
        .unwrap();
        let e = missing
            .resolve(Default::default(), Path::new("."))
            .unwrap_err()
            .to_string();
        assert!(e.contains("no-such.csv"), "{e}");
    }
}
