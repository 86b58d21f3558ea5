//! The vehicle file against the schema: every key read or refused by name, units checked or
//! converted, ranges and counts enforced, out-of-range research values only when listed.

use super::*;

/// The default file with `old` replaced by `new` (which must occur).
fn edited(old: &str, new: &str) -> String {
    assert!(DEFAULT_VEHICLE_TOML.contains(old), "{old}");
    DEFAULT_VEHICLE_TOML.replacen(old, new, 1)
}

fn parse(text: &str) -> Result<ParameterSet> {
    ParameterSet::from_toml_str(text, "v.toml")
}

const YAW_C: &str = "yaw_damper_damping = { value = 8.0e5, unit = \"N·s/m\"";
const YAW_N: &str = "yaw_dampers_per_side = { value = 1.0,";

#[test]
fn embedded_file_parses_with_sources() {
    let set = ParameterSet::from_toml_str(DEFAULT_VEHICLE_TOML, "embedded").unwrap();
    assert!(set.len() > 100);
    for (key, p) in set.iter() {
        assert!(!p.source.trim().is_empty(), "{key} has no source");
        assert!(!p.unit.trim().is_empty(), "{key} has no unit");
    }
    assert_eq!(set.get("carbody.mass").unwrap(), 42e3);
    assert_eq!(set.allowed_out_of_range().count(), 0);
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
    // A retired key says why it is not a parameter.
    let e = set.set("track.gauge", 1.5).unwrap_err().to_string();
    assert!(e.contains("track.gauge") && e.contains("scenario"), "{e}");
    // Out of range by alias names both.
    let e = set.set("C_sx", 1e30).unwrap_err();
    assert!(
        matches!(e, LocoError::OutOfRange { ref name, .. } if name.contains("C_sx") && name.contains("secondary.yaw_damper_damping")),
        "{e}"
    );
    // Counts: whole and small.
    for bad in [2.5, 0.4, 1e12] {
        let e = set.set("secondary.yaw_dampers_per_side", bad).unwrap_err();
        assert!(e.to_string().contains("yaw_dampers_per_side"), "{e}");
    }
    let e = parse("[a]\nb = 3").unwrap_err();
    assert!(
        matches!(e, LocoError::InvalidParameterInFile { ref name, line: 2, .. } if name == "a.b"),
        "{e}"
    );
    // A file that is not TOML is the file's fault, not a parameter's.
    let e = parse("[a\nb = 3").unwrap_err();
    assert!(matches!(e, LocoError::Parse { line: 1, .. }), "{e}");
}

#[test]
fn unknown_misspelt_retired_and_missing_keys_are_refused_by_name_and_line() {
    let text = edited("[carbody]\nmass =", "[carbody]\nmas =");
    let e = parse(&text).unwrap_err();
    let LocoError::InvalidParameterInFile {
        line, name, reason, ..
    } = &e
    else {
        panic!("{e}")
    };
    assert!(
        name == "carbody.mas" && reason.contains("`carbody.mass`"),
        "{e}"
    );
    assert_eq!(
        text.lines()
            .nth(line - 1)
            .unwrap()
            .trim_start()
            .split(' ')
            .next(),
        Some("mas")
    );
    // The key the model does not read any more.
    let text = edited(
        "[track]\n",
        "[track]\ngauge = { value = 1.435, unit = \"m\", source = \"x\" }\n",
    );
    let e = parse(&text).unwrap_err().to_string();
    assert!(e.contains("track.gauge") && e.contains("scenario"), "{e}");
    // An unknown field of a parameter, a wrong type.
    let e = parse(&edited(
        YAW_C,
        "yaw_damper_damping = { note = 1, value = 8.0e5, unit = \"N·s/m\"",
    ))
    .unwrap_err();
    assert!(
        e.to_string().contains("secondary.yaw_damper_damping"),
        "{e}"
    );
    let e = parse(&edited(
        YAW_C,
        "yaw_damper_damping = { value = true, unit = \"N·s/m\"",
    ))
    .unwrap_err();
    assert!(
        e.to_string().contains("secondary.yaw_damper_damping"),
        "{e}"
    );
    // A missing key.
    let start = DEFAULT_VEHICLE_TOML.find(YAW_N).unwrap();
    let end = start + DEFAULT_VEHICLE_TOML[start..].find('\n').unwrap();
    let text = format!(
        "{}{}",
        &DEFAULT_VEHICLE_TOML[..start],
        &DEFAULT_VEHICLE_TOML[end + 1..]
    );
    let e = parse(&text).unwrap_err().to_string();
    assert!(
        e.contains("missing") && e.contains("secondary.yaw_dampers_per_side"),
        "{e}"
    );
}

#[test]
fn units_are_converted_or_refused() {
    // 800 kN·s/m stated as such is 8e5 N·s/m.
    let set = parse(&edited(
        YAW_C,
        "yaw_damper_damping = { value = 800, unit = \"kN·s/m\"",
    ))
    .unwrap();
    assert_eq!(set.get("secondary.yaw_damper_damping").unwrap(), 8e5);
    let p = set.parameter("secondary.yaw_damper_damping").unwrap();
    assert_eq!(p.unit, "N·s/m");
    assert!(p.source.contains("800 kN·s/m"), "{}", p.source);
    // The same number in N·s/m labelled kN·s/m is 1000 times too much: out of range, not silent.
    let e = parse(&edited(
        YAW_C,
        "yaw_damper_damping = { value = 8.0e5, unit = \"kN·s/m\"",
    ))
    .unwrap_err();
    assert!(
        matches!(e, LocoError::OutOfRange { value, .. } if value == 8e8),
        "{e}"
    );
    // A unit of another quantity and a made-up one.
    for unit in ["kN/mm", "furlong", ""] {
        let e = parse(&edited(
            YAW_C,
            &format!("yaw_damper_damping = {{ value = 8.0e5, unit = \"{unit}\""),
        ))
        .unwrap_err();
        let text = e.to_string();
        assert!(
            text.contains("secondary.yaw_damper_damping") && text.contains("N·s/m"),
            "{text}"
        );
    }
}

#[test]
fn out_of_range_values_need_the_explicit_allowance() {
    let heavy = edited(
        "mass = { value = 42000.0, unit = \"kg\"",
        "mass = { value = 420000.0, unit = \"kg\"",
    );
    let e = parse(&heavy).unwrap_err();
    let text = e.to_string();
    assert!(matches!(e, LocoError::OutOfRange { .. }), "{text}");
    assert!(
        text.contains("carbody.mass") && text.contains("420000") && text.contains("120000"),
        "{text}"
    );
    let allowed = format!("allow_out_of_range = [\"carbody.mass\"]\n{heavy}");
    let mut set = parse(&allowed).unwrap();
    assert_eq!(set.get("carbody.mass").unwrap(), 420e3);
    // The allowance covers overrides of that key, and only that key.
    set.set("carbody.mass", 5e3).unwrap();
    assert!(set.set("bogie_frame.mass", 5e2).is_err());
    // Counts stay whole and small even when allowed.
    let mut set = ParameterSet::default_vehicle();
    set.allow_out_of_range("secondary.lateral_dampers_per_bogie")
        .unwrap();
    set.set("secondary.lateral_dampers_per_bogie", 0.0).unwrap();
    assert!(set.set("secondary.lateral_dampers_per_bogie", 1e9).is_err());
    assert!(set.set("secondary.lateral_dampers_per_bogie", 0.4).is_err());
    // The list names keys of the schema only.
    let e = parse(&format!(
        "allow_out_of_range = [\"carbody.mas\"]\n{DEFAULT_VEHICLE_TOML}"
    ))
    .unwrap_err();
    assert!(e.to_string().contains("carbody.mas"), "{e}");
    let e = parse(&format!(
        "allow_out_of_range = \"carbody.mass\"\n{DEFAULT_VEHICLE_TOML}"
    ))
    .unwrap_err();
    assert!(e.to_string().contains("allow_out_of_range"), "{e}");
}

#[test]
fn a_value_of_the_wrong_type_is_a_parameter_error_naming_the_key_and_its_line() {
    let line_of_yaw = DEFAULT_VEHICLE_TOML[..DEFAULT_VEHICLE_TOML.find(YAW_C).unwrap()]
        .matches('\n')
        .count()
        + 1;
    let cases = [
        (
            "value = \"8.0e5\", unit = \"N·s/m\"",
            "`value` must be a number, got string \"8.0e5\"",
        ),
        (
            "value = true, unit = \"N·s/m\"",
            "`value` must be a number, got boolean true",
        ),
        (
            "value = [8.0e5], unit = \"N·s/m\"",
            "`value` must be a number, got array",
        ),
        (
            "value = 8.0e5, unit = 3",
            "`unit` must be a string, got integer 3",
        ),
    ];
    for (fields, expected) in cases {
        let text = edited(YAW_C, &format!("yaw_damper_damping = {{ {fields}"));
        let e = parse(&text).unwrap_err();
        let LocoError::InvalidParameterInFile {
            path,
            line,
            name,
            reason,
        } = &e
        else {
            panic!("{fields}: {e}")
        };
        assert_eq!(
            (path.as_str(), *line, name.as_str()),
            ("v.toml", line_of_yaw, "secondary.yaw_damper_damping"),
            "{e}"
        );
        assert!(reason.contains(expected), "{e}");
        let shown = e.to_string();
        assert!(
            shown.starts_with(&format!(
                "v.toml:{line_of_yaw}: invalid parameter `secondary.yaw_damper_damping`"
            )),
            "{shown}"
        );
    }
    // Not an inline table at all, and a non-finite value: the same class, the same place.
    let text = edited(
        YAW_C,
        "yaw_damper_damping = \"soft\"\nx = { value = 1.0, unit = \"N·s/m\"",
    );
    let e = parse(&text).unwrap_err();
    assert!(
        matches!(&e, LocoError::InvalidParameterInFile { name, line, reason, .. }
            if name == "secondary.yaw_damper_damping" && *line == line_of_yaw
                && reason.contains("got string \"soft\"")),
        "{e}"
    );
    let e = parse(&edited(
        YAW_C,
        "yaw_damper_damping = { value = nan, unit = \"N·s/m\"",
    ))
    .unwrap_err();
    assert!(
        matches!(&e, LocoError::InvalidParameterInFile { name, line, .. }
            if name == "secondary.yaw_damper_damping" && *line == line_of_yaw),
        "{e}"
    );
}
