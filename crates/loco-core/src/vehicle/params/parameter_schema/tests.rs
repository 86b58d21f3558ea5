//! The schema against the model: every key is read, and changes exactly the parts its `affects`
//! says; the default vehicle and the SPEC §6 study box lie inside the ranges.

use super::*;
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::output::channel_set::ChannelSet;
use crate::vehicle::params::parameters::{ParameterSet, STUDY_PARAMETERS};
use crate::vehicle::scenarios::scenario::ContactParameters;

/// What the model built from a parameter set: structure (bodies, suspension, gravity), the
/// contact's parameters and the measuring points of the metrics, each as a text fingerprint.
fn built(p: &ParameterSet) -> [String; 3] {
    let s = VehicleStructure::new(p.clone()).unwrap();
    let structure = format!(
        "{:?}{:?}{:?}{:?}",
        s.layout, s.bodies, s.suspension, s.gravity
    );
    let contact = format!("{:?}", ContactParameters::from_parameters(p).unwrap());
    // The metrics: where their channels are measured, and the bogie mass of the EN 14363 limit.
    let metrics = format!(
        "{:?}{}",
        ChannelSet::new(&s).unwrap(),
        crate::vehicle::model::bogie_mass::en14363_bogie_mass(&s).unwrap()
    );
    [structure, contact, metrics]
}

/// A different value of `spec`'s parameter inside its range.
fn perturbed(spec: &ParameterSpec, value: f64) -> f64 {
    let candidates = match spec.kind {
        Kind::Count => vec![value + 1.0, value - 1.0],
        Kind::Real if value == 0.0 => vec![spec.min + 0.1 * (spec.max - spec.min)],
        Kind::Real => vec![value * 1.05, value * 0.95, value * 1.001, value * 0.999],
    };
    candidates
        .into_iter()
        .find(|v| (spec.min..=spec.max).contains(v) && *v != value)
        .unwrap_or_else(|| panic!("{}: no perturbation inside the range", spec.key))
}

#[test]
fn every_key_is_read_and_changes_exactly_what_it_affects() {
    let base = ParameterSet::default_vehicle();
    let reference = built(&base);
    for spec in schema() {
        let mut p = base.clone();
        // An optional key the file leaves out is perturbed from the middle of its range.
        let given = match spec.optional {
            true => p.get_optional(&spec.key),
            false => Some(p.get(&spec.key).unwrap()),
        };
        let value = perturbed(spec, given.unwrap_or(0.5 * (spec.min + spec.max)));
        p.set(&spec.key, value).unwrap();
        let now = built(&p);
        let changed = |i: usize| now[i] != reference[i];
        assert!(
            changed(0) || changed(1) || changed(2),
            "{} is not read by the model",
            spec.key
        );
        assert_eq!(
            changed(0),
            spec.affects(Affects::Structure),
            "{}: structure",
            spec.key
        );
        // The batch engine shares the contact across samples unless `affects` says contact.
        assert_eq!(
            changed(1),
            spec.affects(Affects::Contact),
            "{}: contact",
            spec.key
        );
        if spec.affects(Affects::Metrics) {
            assert!(changed(2), "{}: metrics", spec.key);
        } else if !spec.affects(Affects::Structure) {
            assert!(!changed(2), "{}: metrics", spec.key);
        }
    }
}

#[test]
fn the_default_vehicle_has_exactly_the_schema_keys_inside_their_ranges() {
    let base = ParameterSet::default_vehicle();
    let keys: Vec<&str> = base.keys().collect();
    // Every key but the optional ones, which the default vehicle leaves to the model.
    let schema_keys: Vec<&str> = schema()
        .iter()
        .filter(|s| !s.optional)
        .map(|s| s.key.as_str())
        .collect();
    assert_eq!(keys, schema_keys);
    for spec in schema().iter().filter(|s| !s.optional) {
        let v = base.get(&spec.key).unwrap();
        assert!(spec.min <= v && v <= spec.max, "{} = {v}", spec.key);
        assert_eq!(base.parameter(&spec.key).unwrap().unit, spec.unit);
        assert!(spec.check(v, false).is_ok());
    }
    for (key, _) in RETIRED {
        assert!(spec(key).is_none(), "{key} is retired and in the schema");
    }
}

#[test]
fn the_study_box_of_spec_section_6_is_inside_the_ranges() {
    // SPEC §6.2, converted to SI: kN/mm × 1e6, kN·s/m × 1e3.
    let box_si = [
        ("K_px", 10e6, 50e6),
        ("K_py", 2e6, 10e6),
        ("C_sx", 200e3, 1200e3),
        ("C_sy", 10e3, 60e3),
        ("K_ncsx", 10e6, 50e6),
        ("K_ncsy", 10e6, 50e6),
    ];
    for (alias, low, high) in box_si {
        let key = STUDY_PARAMETERS
            .iter()
            .find(|(a, _)| *a == alias)
            .unwrap()
            .1;
        let s = spec(key).unwrap();
        assert!(
            s.min <= low && high <= s.max,
            "{alias}: [{}, {}]",
            s.min,
            s.max
        );
    }
}

#[test]
fn checks_refuse_non_finite_fractional_and_huge_values_with_the_range() {
    let count = spec("secondary.yaw_dampers_per_side").unwrap();
    assert!(count.check(2.0, false).is_ok());
    for bad in [2.5, 0.4, f64::NAN, f64::INFINITY] {
        let e = count.check(bad, true).unwrap_err();
        assert!(
            e.to_string().contains("secondary.yaw_dampers_per_side"),
            "{e}"
        );
    }
    // A count is never an allocation size, even when allowed out of range.
    let e = count.check(1e12, true).unwrap_err();
    assert!(
        matches!(e, LocoError::OutOfRange { max, .. } if max == MAX_COUNT),
        "{e}"
    );
    assert!(count.check(0.0, true).is_ok());
    let real = spec("secondary.yaw_damper_damping").unwrap();
    let e = real.check(1e30, false).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("secondary.yaw_damper_damping")
            && text.contains("1e30")
            && text.contains("N·s/m"),
        "{text}"
    );
    assert!(
        matches!(e, LocoError::OutOfRange { min, max, .. } if min == real.min && max == real.max)
    );
    assert!(real.check(1e30, true).is_ok());
    assert!(real.check(f64::NAN, true).is_err());
}

#[test]
fn unknown_keys_get_a_suggestion_and_retired_keys_their_reason() {
    assert!(unknown_key_reason("carbody.mas").contains("`carbody.mass`"));
    assert!(unknown_key_reason("track.gauge").contains("scenario"));
    assert!(unknown_key_reason("track.shear_modulus").contains("derived"));
    assert!(unknown_key_reason("nothing.like_it_at_all").contains("unknown"));
    assert_eq!(edit_distance("kitten", "sitting"), 3);
}
