//! The settings a scenario refuses, each naming its field: conflicting ways of giving one thing,
//! a bad synthesis band, a gauge outside its range, a name that is no profile or track file.

use super::tests::{field_of, settings};
use super::*;

#[test]
fn conflicts_are_refused_naming_the_field() {
    let dir = Path::new(".");
    let err = |s: ScenarioSettings, g: GivenObjects| field_of(s.resolve(g, dir).unwrap_err());
    let both_speeds = ScenarioSettings {
        speed_kmh: Some(100.0),
        ..settings("S_low")
    };
    assert_eq!(err(both_speeds, GivenObjects::default()), "speed");
    let name_and_wheel = ScenarioSettings {
        wheel: Some("jm3-new".into()),
        ..settings("S_low")
    };
    assert_eq!(err(name_and_wheel, GivenObjects::default()), "name");
    for (field, s) in [
        (
            "spectrum",
            ScenarioSettings {
                spectrum: Some("cn-hsr".into()),
                ..settings("S_low")
            },
        ),
        (
            "seed",
            ScenarioSettings {
                seed: Some(1),
                ..settings("S_low")
            },
        ),
        (
            "band",
            ScenarioSettings {
                band: Some([2.0, 100.0]),
                ..settings("S_low")
            },
        ),
    ] {
        let perfect = ScenarioSettings {
            track: Some("perfect".into()),
            ..s.clone()
        };
        assert_eq!(err(perfect, GivenObjects::default()), field);
        let given = GivenObjects {
            track: Some(Arc::new(
                TrackIrregularity::from_channels(
                    0.5,
                    &[vec![0.0; 4], vec![0.0; 4], vec![0.0; 4], vec![0.0; 4]],
                    &[vec![0.0; 4], vec![0.0; 4], vec![0.0; 4], vec![0.0; 4]],
                    0.0,
                    None,
                )
                .unwrap(),
            )),
            ..GivenObjects::default()
        };
        assert_eq!(err(s, given), field);
    }
    let damper_twice = GivenObjects {
        yaw_damper: Some(Damper::fsd()),
        ..GivenObjects::default()
    };
    let preset = ScenarioSettings {
        yaw_damper: Some("YD1".into()),
        ..settings("S_low")
    };
    assert_eq!(err(preset, damper_twice), "yaw_damper");
    let nothing = ScenarioSettings {
        name: None,
        ..settings("S_low")
    };
    assert_eq!(err(nothing, GivenObjects::default()), "name");
}

#[test]
fn a_bad_band_is_refused_as_band_at_once() {
    for band in [
        [f64::NAN, 200.0],
        [0.0, 200.0],
        [2.0, 1.0],
        [1e-30, 200.0],
        [2.0, 1e30],
    ] {
        let s = ScenarioSettings {
            band: Some(band),
            ..settings("S_norm")
        };
        let err = s
            .resolve(GivenObjects::default(), Path::new("."))
            .unwrap_err();
        assert_eq!(field_of(err), "band", "{band:?}");
    }
}

#[test]
fn gauge_and_gauge_height_outside_their_ranges_are_refused_by_name() {
    // The defaults (1.435 m, 16 mm) and EN 13848-1's 14 mm lie inside the ranges.
    for (gauge, height) in [
        (1.435, 0.016),
        (1.435, 0.014),
        (1.426, 0.016),
        (1.470, 0.016),
    ] {
        let s = ScenarioSettings {
            gauge: Some(gauge),
            gauge_height: Some(height),
            ..settings("S_norm")
        };
        assert!(s.resolve(GivenObjects::default(), Path::new(".")).is_ok());
    }
    for (field, gauge, height) in [
        ("gauge", 1.0, 0.016),
        ("gauge", 1.676, 0.016),
        ("gauge_height", 1.435, 0.0),
        ("gauge_height", 1.435, 0.05),
    ] {
        let s = ScenarioSettings {
            gauge: Some(gauge),
            gauge_height: Some(height),
            ..settings("S_norm")
        };
        let err = s
            .resolve(GivenObjects::default(), Path::new("."))
            .unwrap_err();
        assert_eq!(field_of(err), field, "{gauge} {height}");
    }
}

#[test]
fn a_profile_or_track_name_that_is_no_file_is_refused_by_name() {
    for (s, field) in [
        (
            ScenarioSettings {
                name: None,
                wheel: Some("no-such-wheel".into()),
                ..settings("S_norm")
            },
            "wheel",
        ),
        (
            ScenarioSettings {
                name: None,
                wheel: Some("jm3-new".into()),
                rail: Some("no-such-rail".into()),
                ..settings("S_norm")
            },
            "rail",
        ),
        (
            ScenarioSettings {
                track: Some("no-such-track.csv".into()),
                ..settings("S_norm")
            },
            "track",
        ),
    ] {
        let err = s
            .resolve(GivenObjects::default(), Path::new("."))
            .unwrap_err();
        assert_eq!(field_of(err), field);
    }
}
