use super::*;
use crate::vehicle::params::parameter_schema::{schema, spec, Kind};
use crate::LocoError;
use std::collections::BTreeMap;

/// Every key of the sections with its check, and how many fields read it.
fn mapped() -> BTreeMap<&'static str, (Vec<&'static str>, usize)> {
    let mut out: BTreeMap<&str, (Vec<&str>, usize)> = BTreeMap::new();
    for (keys, checks) in SECTION_KEYS {
        assert_eq!(keys.len(), checks.len());
        for (key, check) in keys.iter().zip(checks.iter()) {
            let entry = out.entry(key).or_default();
            entry.0.push(check);
            entry.1 += 1;
        }
    }
    out
}

#[test]
fn every_schema_key_is_read_by_exactly_one_field() {
    let mapped = mapped();
    for s in schema() {
        match mapped.get(s.key.as_str()) {
            None => panic!("schema key `{}` is read by no section field", s.key),
            Some((_, n)) => assert_eq!(*n, 1, "schema key `{}` is read by {n} fields", s.key),
        }
    }
    for key in mapped.keys() {
        assert!(
            spec(key).is_some(),
            "section field `{key}` is not a schema key"
        );
    }
    assert_eq!(mapped.len(), schema().len());
}

#[test]
fn each_field_is_checked_as_its_schema_kind() {
    for (key, (checks, _)) in mapped() {
        let s = spec(key).unwrap();
        let check = checks[0];
        let is_count = check.starts_with("count");
        assert_eq!(is_count, s.kind == Kind::Count, "`{key}` read as {check}");
        assert_eq!(check == "optional", s.optional, "`{key}` read as {check}");
    }
}

#[test]
fn the_sections_hold_the_values_of_the_parameter_set() {
    let mut p = ParameterSet::default_vehicle();
    p.set("K_py", 6.0e6).unwrap();
    let sections = VehicleSections::read(&p).unwrap();
    assert_eq!(sections.rotary_arm.node_stiffness_lateral, 6.0e6);
    assert_eq!(sections.secondary.flexicoil_springs_per_side, 2);
    assert_eq!(sections.assessment.bogie_mass, None);
    let values = sections.values();
    assert_eq!(values.len(), schema().len());
    for (key, value) in values {
        assert_eq!(value, p.get_optional(key), "`{key}`");
    }
    p.set("assessment.bogie_mass", 15_000.0).unwrap();
    let sections = VehicleSections::read(&p).unwrap();
    assert_eq!(sections.assessment.bogie_mass, Some(15_000.0));
}

#[test]
fn a_value_the_model_cannot_take_is_refused_naming_its_key() {
    for (key, value) in [
        ("secondary.yaw_damper_damping", 0.0),
        ("primary.axle_box_spring_shear_stiffness", -1.0),
        ("traction_motor.suspension_points_per_motor", 0.0),
    ] {
        let mut p = ParameterSet::default_vehicle();
        p.allow_out_of_range(key).unwrap();
        p.set(key, value).unwrap();
        let e = VehicleSections::read(&p).unwrap_err();
        match &e {
            LocoError::InvalidParameter { name, .. } => assert_eq!(name, key, "{e}"),
            other => panic!("{key}: {other}"),
        }
    }
    // A signed field takes a negative value.
    let mut p = ParameterSet::default_vehicle();
    p.set("traction_motor.suspension_point_vertical_offset", -0.2)
        .unwrap();
    let s = VehicleSections::read(&p).unwrap();
    assert_eq!(s.traction_motor.suspension_point_vertical_offset, -0.2);
}

#[test]
fn the_shear_modulus_follows_young_modulus_and_poisson_ratio() {
    let mut set = ParameterSet::default_vehicle();
    // Steel, 210 GPa and 0.28: G = 210e9 / 2.56.
    let g = |set: &ParameterSet| TrackSection::read(set).unwrap().shear_modulus();
    assert_eq!(g(&set), 2.1e11 / 2.56);
    set.set("track.young_modulus", 2.0e11).unwrap();
    set.set("track.poisson_ratio", 0.3).unwrap();
    assert!((g(&set) - 2.0e11 / 2.6).abs() < 1.0);
}
