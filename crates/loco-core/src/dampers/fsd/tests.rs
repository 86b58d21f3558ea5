use super::*;

#[test]
fn validation_names_the_field() {
    let bad = FsdParams {
        low_damping_nspm: 900e3,
        ..FsdParams::default()
    };
    let err = FsdDamper::new(bad).unwrap_err().to_string();
    assert!(
        err.contains("low_damping_nspm") && err.contains("c1 must be < c2"),
        "{err}"
    );
    let bad = FsdParams {
        cutoff_frequency_hz: 0.0,
        ..FsdParams::default()
    };
    assert!(FsdDamper::new(bad)
        .unwrap_err()
        .to_string()
        .contains("cutoff_frequency_hz"));
    let bad = FsdParams {
        equivalent_mass_kg: -1.0,
        ..FsdParams::default()
    };
    assert!(FsdDamper::new(bad)
        .unwrap_err()
        .to_string()
        .contains("equivalent_mass_kg"));
    assert!(FsdDamper::new(FsdParams::default()).is_ok());
}

#[test]
fn valve_states_follow_scale_factor_and_decision() {
    assert_eq!(FsdDamper::valve_state(0.0, false), ValveState::Open);
    assert_eq!(FsdDamper::valve_state(1.0, true), ValveState::Closed);
    assert_eq!(FsdDamper::valve_state(0.4, true), ValveState::Closing);
    assert_eq!(FsdDamper::valve_state(0.4, false), ValveState::Opening);
}

#[test]
fn reversal_half_way_starts_from_the_current_position() {
    let params = FsdTriggerParams::default();
    let mut trigger = TriggerMemory::new(true);
    let mut scale = 0.0;
    let dt = 1e-3;
    // Closing toward a "high" decision for half the delay: s = 0.5, no jump.
    for _ in 0..25 {
        advance_scale_factor(&mut trigger, &mut scale, &params, 2.0, 0.05, dt, 0.0, 0.0);
    }
    assert!((scale - 0.5).abs() < 1e-12, "{scale}");
    assert_eq!(FsdDamper::valve_state(scale, true), ValveState::Closing);
    // The trigger turns to "low": the valve goes back from 0.5 at the same rate.
    trigger.high_frequency = false;
    let mut previous = scale;
    for step in 0..30 {
        advance_scale_factor(&mut trigger, &mut scale, &params, 2.0, 0.05, dt, 0.0, 0.0);
        assert!(
            (previous - scale - dt / 0.05).abs() < 1e-12 || scale == 0.0,
            "{step}"
        );
        previous = scale;
    }
    assert_eq!(scale, 0.0);
    assert_eq!(FsdDamper::valve_state(scale, false), ValveState::Open);
}
