//! The named presets every front end shares (the study file's `[scenario]`, Python's
//! `loco.Scenario`, `loco.dampers`): the study's scenarios (SPEC §2) and yaw dampers (SPEC §4),
//! each name spelt once here.
//!
//! The study's scenarios are JM3 treads in three wear states on CN60 rail inclined 1:40: `S_low`
//! thin flange (equivalent conicity 0.04), `S_norm` new wheel (0.10), `S_high` worn wheel (0.70).

use crate::dampers::{Damper, FsdTrigger};
use crate::error::{LocoError, Result};

/// The study's scenarios: (name, wheel, rail) with built-in profile names.
pub const SCENARIOS: [(&str, &str, &str); 3] = [
    ("S_low", "jm3-thin-flange", "cn60"),
    ("S_norm", "jm3-new", "cn60"),
    ("S_high", "jm3-worn", "cn60"),
];

/// The rail of every study scenario, the default rail of a scenario given by its wheel.
pub const STUDY_RAIL: &str = "cn60";

/// The yaw damper presets by name, in the order the studies compare them: the conventional
/// YD1 (Maxwell, 200 kN·s/m in series with 22.5 kN/mm), YD2 (800 kN·s/m) and the spec's
/// frequency-selective damper FSD.
pub const DAMPER_PRESETS: [&str; 3] = ["YD1", "YD2", "FSD"];

/// The yaw dampers the studies compare, in their order, by label: the [`DAMPER_PRESETS`] and
/// `FSD-H`, the FSD with the hydraulic frequency valve. Each is (label, preset, FSD trigger).
pub const COMPARED_DAMPERS: [(&str, &str, Option<&str>); 4] = [
    ("YD1", "YD1", None),
    ("YD2", "YD2", None),
    ("FSD", "FSD", None),
    ("FSD-H", "FSD", Some(FsdTrigger::HYDRAULIC)),
];

/// The dampers of [`COMPARED_DAMPERS`] by label, in order.
pub fn compared_dampers() -> Vec<(&'static str, Damper)> {
    COMPARED_DAMPERS
        .iter()
        .map(|&(label, preset, trigger)| {
            // Every entry is a preset with a trigger it takes (tested), so this cannot fail.
            let damper = damper_preset(preset, trigger)
                .unwrap_or_else(|e| panic!("compared damper {label}: {e}"));
            (label, damper)
        })
        .collect()
}

/// The yaw damper setting that keeps the parameter file's Maxwell yaw damper (the default).
pub const FILE_DAMPER: &str = "file";

/// The wheel and rail of a study scenario: (wheel, rail) built-in profile names.
pub fn scenario_profiles(name: &str) -> Result<(&'static str, &'static str)> {
    SCENARIOS
        .iter()
        .find(|(n, _, _)| *n == name)
        .map(|(_, wheel, rail)| (*wheel, *rail))
        .ok_or_else(|| {
            LocoError::param(
                "scenario",
                format!("unknown scenario '{name}'; expected S_low, S_norm or S_high"),
            )
        })
}

/// A yaw damper preset of [`DAMPER_PRESETS`]; `trigger` (a name of [`FsdTrigger::NAMES`],
/// default `rms-frequency`) chooses the FSD's frequency trigger and is refused for the others.
pub fn damper_preset(name: &str, trigger: Option<&str>) -> Result<Damper> {
    let damper = match name {
        "YD1" => Damper::yd1(),
        "YD2" => Damper::yd2(),
        "FSD" => Damper::fsd(),
        other => {
            return Err(LocoError::param(
                "yaw_damper",
                format!(
                    "expected {FILE_DAMPER}, {}, got '{other}'",
                    DAMPER_PRESETS.join(", ")
                ),
            ))
        }
    };
    match (trigger, name) {
        (None, _) => Ok(damper),
        (Some(t), "FSD") => match FsdTrigger::check_name(t) {
            Ok(FsdTrigger::HYDRAULIC) => Ok(Damper::fsd_hydraulic()),
            Ok(_) => Ok(damper),
            Err(_) => Err(LocoError::param(
                "fsd_trigger",
                format!(
                    "expected one of {}, got '{t}'",
                    FsdTrigger::NAMES.join(", ")
                ),
            )),
        },
        (Some(_), _) => Err(LocoError::param(
            "fsd_trigger",
            "only with the preset yaw_damper = \"FSD\"",
        )),
    }
}

/// The yaw damper of a setting: [`FILE_DAMPER`] (`None`: the parameter file's Maxwell yaw
/// damper) or a preset of [`DAMPER_PRESETS`], with the FSD's `trigger`.
pub fn yaw_damper_preset(name: &str, trigger: Option<&str>) -> Result<Option<Damper>> {
    if name == FILE_DAMPER {
        return match trigger {
            None => Ok(None),
            Some(_) => Err(LocoError::param(
                "fsd_trigger",
                "only with the preset yaw_damper = \"FSD\"",
            )),
        };
    }
    damper_preset(name, trigger).map(Some)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field_of(e: LocoError) -> String {
        match e {
            LocoError::InvalidParameter { name, .. } => name,
            other => panic!("expected an invalid parameter, got {other}"),
        }
    }

    #[test]
    fn damper_presets_are_the_dampers_constructors() {
        assert_eq!(yaw_damper_preset("file", None).unwrap(), None);
        assert_eq!(damper_preset("YD1", None).unwrap(), Damper::yd1());
        assert_eq!(damper_preset("YD2", None).unwrap(), Damper::yd2());
        assert_eq!(damper_preset("FSD", None).unwrap(), Damper::fsd());
        assert_eq!(
            damper_preset("FSD", Some("rms-frequency")).unwrap(),
            Damper::fsd()
        );
        assert_eq!(
            damper_preset("FSD", Some("hydraulic")).unwrap(),
            Damper::fsd_hydraulic()
        );
        for name in DAMPER_PRESETS {
            assert!(damper_preset(name, None).is_ok(), "{name}");
        }
        assert_eq!(
            field_of(damper_preset("fsd", None).unwrap_err()),
            "yaw_damper"
        );
        assert_eq!(
            field_of(damper_preset("FSD", Some("zero-crossing")).unwrap_err()),
            "fsd_trigger"
        );
        assert_eq!(
            field_of(damper_preset("YD1", Some("hydraulic")).unwrap_err()),
            "fsd_trigger"
        );
        assert_eq!(
            field_of(yaw_damper_preset("file", Some("hydraulic")).unwrap_err()),
            "fsd_trigger"
        );
    }

    #[test]
    fn the_compared_dampers_are_the_presets_and_the_hydraulic_fsd() {
        let compared = compared_dampers();
        let labels: Vec<&str> = compared.iter().map(|(l, _)| *l).collect();
        assert_eq!(labels, ["YD1", "YD2", "FSD", "FSD-H"]);
        for (i, name) in DAMPER_PRESETS.iter().enumerate() {
            assert_eq!(compared[i], (*name, damper_preset(name, None).unwrap()));
        }
        assert_eq!(compared[3].1, Damper::fsd_hydraulic());
    }

    #[test]
    fn scenarios_name_built_in_profiles() {
        for (name, wheel, rail) in SCENARIOS {
            assert_eq!(scenario_profiles(name).unwrap(), (wheel, rail));
            assert!(crate::contact::builtin::builtin_profile(wheel).is_ok());
            assert_eq!(rail, STUDY_RAIL);
        }
        assert_eq!(
            field_of(scenario_profiles("S_mid").unwrap_err()),
            "scenario"
        );
    }
}
