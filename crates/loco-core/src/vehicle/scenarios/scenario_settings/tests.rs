//! Tests of [`super::ScenarioSettings`]: defaults, settings applied, conflicts refused.

use super::*;
use crate::track::TrackSpectrum;
use crate::vehicle::params::presets::scenario_profiles;
use crate::vehicle::scenarios::scenario::TrackSpec;

pub(super) fn settings(name: &str) -> ScenarioSettings {
    ScenarioSettings {
        name: Some(name.into()),
        speed: Some(50.0),
        distance: Some(100.0),
        ..ScenarioSettings::default()
    }
}

pub(super) fn field_of(e: LocoError) -> String {
    match e {
        LocoError::InvalidParameter { name, .. } => name,
        other => panic!("expected an invalid parameter, got {other}"),
    }
}

#[test]
fn defaults_are_the_core_defaults() {
    let s = settings("S_norm")
        .resolve(GivenObjects::default(), Path::new("."))
        .unwrap();
    let study = Scenario::study("S_norm", 50.0, 100.0, 0).unwrap();
    assert_eq!(s.wheel.name(), study.wheel.name());
    assert_eq!(s.rail.name(), study.rail.name());
    assert_eq!(s.track_setup, TrackSetup::default());
    assert_eq!(s.track_setup, study.track_setup);
    assert_eq!(s.run.step, RunSettings::default().step);
    assert_eq!(s.run.output_rate, RunSettings::default().output_rate);
    assert_eq!(s.fastsim, FastsimParams::default());
    assert_eq!(s.lead_in, study.lead_in);
    assert_eq!(s.initial_lateral_offset, study.initial_lateral_offset);
    assert!(s.creep == CreepModel::Fastsim && s.yaw_damper.is_none());
    assert_eq!(s.creep, study.creep);
    match (&s.track, &study.track) {
        (TrackSpec::Synthetic(a), TrackSpec::Synthetic(b)) => {
            assert_eq!(a, b);
            assert_eq!(*a, SynthesisParams::default());
        }
        other => panic!("expected synthetic tracks, got {other:?}"),
    }
}

#[test]
fn a_scheme_named_without_a_step_runs_at_its_own_step() {
    // Before, `integrator = "etdrk4"` alone ran at RK4's 1 ms: correct but without the gain.
    let given = |integrator: &str, step: Option<f64>| {
        ScenarioSettings {
            integrator: Some(integrator.into()),
            step,
            ..settings("S_norm")
        }
        .resolve(GivenObjects::default(), Path::new("."))
        .unwrap()
        .run
    };
    let etd = given("etdrk4", None);
    assert_eq!(etd.integrator, Integrator::ExponentialRk4);
    assert_eq!(etd.step, crate::vehicle::time::integrator::EXPONENTIAL_STEP);
    assert_eq!(
        given("rk4", None).step,
        crate::vehicle::time::integrator::REFERENCE_STEP
    );
    assert_eq!(given("etdrk4", Some(1e-3)).step, 1e-3);
}

#[test]
fn settings_are_applied() {
    let s = ScenarioSettings {
        speed: None,
        speed_kmh: Some(180.0),
        wheel: Some("jm3-worn".into()),
        name: None,
        seed: Some(7),
        band: Some([3.0, 100.0]),
        spectrum: Some("german-low".into()),
        step: Some(5e-4),
        output_rate: Some(200.0),
        fastsim_grid: Some([8, 12]),
        creep: Some("table".into()),
        initial_lateral_offset: Some(0.002),
        lead_in: Some(20.0),
        gauge: Some(1.44),
        gauge_height: Some(0.014),
        rail_inclination: Some(0.05),
        yaw_damper: Some("YD2".into()),
        ..settings("S_norm")
    }
    .resolve(GivenObjects::default(), Path::new("."))
    .unwrap();
    assert!((s.speed - 50.0).abs() < 1e-12);
    assert_eq!(s.wheel.name(), "jm3-worn");
    assert_eq!(s.rail.name(), "cn60");
    assert_eq!((s.fastsim.nx, s.fastsim.ny), (8, 12));
    assert_eq!(s.run.step, 5e-4);
    assert_eq!(s.run.output_rate, 200.0);
    assert_eq!(s.creep, CreepModel::from_name("table").unwrap());
    assert_eq!(s.initial_lateral_offset, 0.002);
    assert_eq!(s.lead_in, 20.0);
    assert_eq!(
        s.track_setup,
        TrackSetup {
            gauge: 1.44,
            gauge_height: 0.014,
            rail_inclination: 0.05
        }
    );
    assert_eq!(s.yaw_damper, Some(Damper::yd2()));
    match s.track {
        TrackSpec::Synthetic(p) => {
            assert_eq!(p.seed, 7);
            assert_eq!((p.wavelength_min, p.wavelength_max), (3.0, 100.0));
            assert_eq!(p.spectrum, TrackSpectrum::GermanLow);
        }
        other => panic!("expected a synthetic track, got {other:?}"),
    }
}

#[test]
fn presets() {
    let base = ScenarioSettings {
        name: Some("S_low".into()),
        speed: Some(50.0),
        distance: Some(10.0),
        track: Some("perfect".into()),
        yaw_damper: Some("FSD".into()),
        fsd_trigger: Some("hydraulic".into()),
        ..ScenarioSettings::default()
    };
    let dir = Path::new(".");
    let hydraulic = base.resolve(GivenObjects::default(), dir).unwrap();
    assert_eq!(hydraulic.yaw_damper, Some(Damper::fsd_hydraulic()));
    let bad = ScenarioSettings {
        fsd_trigger: Some("zero-crossing".into()),
        ..base.clone()
    };
    assert_eq!(
        field_of(bad.resolve(GivenObjects::default(), dir).unwrap_err()),
        "fsd_trigger"
    );
    let not_fsd = ScenarioSettings {
        yaw_damper: Some("YD1".into()),
        ..base
    };
    assert_eq!(
        field_of(not_fsd.resolve(GivenObjects::default(), dir).unwrap_err()),
        "fsd_trigger"
    );
}

#[test]
fn toml_keys_are_checked() {
    let s: ScenarioSettings = toml::from_str(
        "name = 'S_high'\nspeed_kmh = 200.0\ndistance = 10.0\nfastsim_grid = [6, 6]\n",
    )
    .unwrap();
    assert_eq!(s.fastsim_grid, Some([6, 6]));
    assert!(toml::from_str::<ScenarioSettings>("name = 'S_high'\ndistanse = 10.0\n").is_err());
}

#[test]
fn creep_model_by_name_and_the_removed_key() {
    let resolve = |text: &str| {
        toml::from_str::<ScenarioSettings>(text)
            .unwrap()
            .resolve(GivenObjects::default(), Path::new("."))
    };
    let base = "name = 'S_norm'\nspeed = 50.0\ndistance = 10.0\ntrack = 'perfect'\n";
    let s = resolve(&format!("{base}creep = 'fastrip'\n")).unwrap();
    assert_eq!(s.creep, CreepModel::Fastrip);
    let err = resolve(&format!("{base}creep = 'kalker'\n")).unwrap_err();
    assert_eq!(field_of(err), "creep");
    let err = resolve(&format!("{base}creep_table = true\n")).unwrap_err();
    assert!(err.to_string().contains("creep = \"table\""), "{err}");
    assert_eq!(field_of(err), "creep_table");
}

#[test]
fn the_defaults_are_what_an_empty_setting_resolves_to() {
    let dir = Path::new(".");
    // Every default given explicitly (the rail with the wheel: a scenario name brings its own;
    // the FSD's trigger is refused with the file's damper).
    let explicit = ScenarioSettings {
        wheel: Some(scenario_profiles("S_high").unwrap().0.into()),
        fsd_trigger: None,
        ..ScenarioSettings::defaults()
    }
    .resolve(GivenObjects::default(), dir)
    .unwrap();
    let implicit = ScenarioSettings {
        name: Some("S_high".into()),
        ..ScenarioSettings::default()
    }
    .resolve(GivenObjects::default(), dir)
    .unwrap();
    let study = Scenario::study("S_high", DEFAULT_SPEED, DEFAULT_DISTANCE, 0).unwrap();
    for s in [&explicit, &implicit] {
        assert_eq!(s.wheel.name(), study.wheel.name());
        assert_eq!(s.rail.name(), study.rail.name());
        assert_eq!((s.speed, s.distance), (study.speed, study.distance));
        assert_eq!(s.track_setup, study.track_setup);
        assert_eq!(s.fastsim, study.fastsim);
        assert_eq!(s.run.step, study.run.step);
        assert_eq!(s.run.output_rate, study.run.output_rate);
        assert_eq!((s.lead_in, s.creep), (study.lead_in, study.creep));
        assert_eq!(s.yaw_damper, None);
        match (&s.track, &study.track) {
            (TrackSpec::Synthetic(a), TrackSpec::Synthetic(b)) => assert_eq!(a, b),
            other => panic!("expected synthetic tracks, got {other:?}"),
        }
    }
    // The study's values (SPEC §6: 200 km/h over 500 m).
    assert!((DEFAULT_SPEED * 3.6 - 200.0).abs() < 1e-12 && DEFAULT_DISTANCE == 500.0);
}

#[test]
fn a_preset_damper_by_name_and_its_trigger() {
    let dir = Path::new(".");
    let base = ScenarioSettings {
        track: Some(PERFECT.into()),
        ..settings("S_low")
    };
    let fsd = ScenarioSettings {
        yaw_damper: Some("FSD".into()),
        ..base.clone()
    };
    assert_eq!(
        fsd.resolve(GivenObjects::default(), dir)
            .unwrap()
            .yaw_damper,
        Some(Damper::fsd())
    );
    let trigger_alone = ScenarioSettings {
        fsd_trigger: Some("hydraulic".into()),
        ..base
    };
    assert_eq!(
        field_of(
            trigger_alone
                .resolve(GivenObjects::default(), dir)
                .unwrap_err()
        ),
        "fsd_trigger"
    );
}
