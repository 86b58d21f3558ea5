use super::*;
use crate::vehicle::params::parameter_schema::schema;

fn default_ranges() -> Vec<InputRange> {
    input_ranges(
        &ParameterSet::default_vehicle(),
        DEFAULT_UNCERTAINTY_TOML,
        "<default_uncertainty.toml>",
    )
    .unwrap()
}

#[test]
fn every_real_parameter_but_the_constructive_zero_has_a_range_with_its_reasons() {
    let ranges = default_ranges();
    let keys: Vec<&str> = ranges.iter().map(|r| r.key.as_str()).collect();
    for s in schema() {
        let ranged = keys.contains(&s.key.as_str());
        // An optional key the default vehicle leaves out is computed from other inputs (whose
        // ranges carry its uncertainty): it has no value of its own to range.
        let expected = s.kind == Kind::Real
            && !s.optional
            && s.key != "primary.axle_box_spring_shear_stiffness";
        assert_eq!(ranged, expected, "{}", s.key);
    }
    assert!(keys.contains(&"scenario.rail_inclination"));
    assert!(keys.contains(&"wheel.jm3-thin-flange.tread_slope"));
    for r in &ranges {
        assert!(
            r.low < r.high && (r.low..=r.high).contains(&r.nominal),
            "{r:?}"
        );
        assert!(!r.why.is_empty() && !r.source.is_empty(), "{}", r.key);
        assert!(RANGE_KINDS.contains(&r.kind.as_str()), "{}", r.key);
    }
    // A class scales the vehicle's value: the carbody mass ±3 %, a negative offset reversed.
    let mass = ranges.iter().find(|r| r.key == "carbody.mass").unwrap();
    assert_eq!((mass.low, mass.high), (42000.0 * 0.97, 42000.0 * 1.03));
    let rod = ranges
        .iter()
        .find(|r| r.key == "traction_rod.carbody_end_longitudinal_offset")
        .unwrap();
    assert_eq!((rod.low, rod.high), (-0.5 * 1.15, -0.5 * 0.85));
}

fn error_of(text: &str) -> String {
    input_ranges(&ParameterSet::default_vehicle(), text, "r.toml")
        .unwrap_err()
        .to_string()
}

#[test]
fn bad_ranges_are_refused_naming_key_and_line() {
    let e = error_of("[parameters.carbody]\nmasss = { low = 1.0, high = 2.0, kind = \"estimate\", why = \"w\", source = \"s\" }\n");
    assert!(
        e.contains("carbody.masss") && e.contains("r.toml:2:"),
        "{e}"
    );
    let e = error_of("[parameters.carbody]\nmass = { low = 5e4, high = 4e4, kind = \"estimate\", why = \"w\", source = \"s\" }\n");
    assert!(e.contains("carbody.mass") && e.contains("reversed"), "{e}");
    let e = error_of("[parameters.carbody]\nmass = { low = 1e4, high = 5e4, kind = \"estimate\", why = \"w\", source = \"s\" }\n");
    assert!(e.contains("carbody.mass") && e.contains("validity"), "{e}");
    let e = error_of("[parameters.carbody]\nmass = { low = 5e4, high = 6e4, kind = \"estimate\", why = \"w\", source = \"s\" }\n");
    assert!(
        e.contains("does not contain the vehicle's value 42000"),
        "{e}"
    );
    let e = error_of("[parameters.carbody]\nmass = \"no_class\"\n");
    assert!(e.contains("unknown range class `no_class`"), "{e}");
    let e = error_of("[parameters.secondary]\nyaw_dampers_per_side = { low = 1.0, high = 2.0, kind = \"estimate\", why = \"w\", source = \"s\" }\n");
    assert!(e.contains("count"), "{e}");
    let e = error_of("[parameters.carbody]\nmass = { low = 4e4, high = 4.4e4, kind = \"guess\", why = \"w\", source = \"s\" }\n");
    assert!(e.contains("kind `guess`"), "{e}");
    let e = error_of("[classes]\nc = { factors = [1.2, 0.8], kind = \"estimate\", why = \"w\", source = \"s\" }\n");
    assert!(
        e.contains("0 < low < high") && e.contains("r.toml:2:"),
        "{e}"
    );
    let e = error_of("[scenario]\n\"wheel.jm3-worn.band_radius\" = { low = 0.05, high = 0.2, kind = \"estimate\", why = \"w\", source = \"s\" }\n");
    assert!(
        e.contains("wheel.jm3-worn.band_radius") && e.contains("validity"),
        "{e}"
    );
    let e = error_of("[scenario]\ncant = { low = 0.0, high = 0.1, kind = \"estimate\", why = \"w\", source = \"s\" }\n");
    assert!(
        e.contains("scenario.cant") && e.contains("not a scenario input"),
        "{e}"
    );
}
