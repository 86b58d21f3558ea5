use super::*;

const KINDS: [&str; 4] = ["carbody", "frames", "wheelsets", "motors"];

/// A mode with the given body shares, each body's energy all in one motion (index into MOTIONS).
fn energy(shares: [f64; 4], motion: usize) -> ModeEnergy {
    let mut m = [0.0; 6];
    m[motion] = 1.0;
    ModeEnergy {
        bodies: shares.to_vec(),
        motions: vec![m; 4],
    }
}

#[test]
fn carbody_rule_takes_the_coupled_sway_not_the_pure_sway() {
    let coupled = energy([0.55, 0.10, 0.12, 0.23], 1);
    let pure_sway = energy([0.99, 0.0, 0.005, 0.005], 1);
    let modes = [
        RatedMode {
            frequency: 0.59,
            damping_ratio: 0.10,
            energy: &pure_sway,
        },
        RatedMode {
            frequency: 1.2,
            damping_ratio: 0.15,
            energy: &coupled,
        },
    ];
    assert_eq!(CARBODY_MODE.pick(&modes, &KINDS), Some(1));
    assert_eq!(BOGIE_MODE.pick(&modes, &KINDS), None);
}

#[test]
fn rules_take_the_least_damped_admitted_mode_within_the_band() {
    let bogie = energy([0.02, 0.16, 0.05, 0.77], 1);
    let motor = energy([0.0, 0.03, 0.03, 0.94], 1);
    let vertical = energy([0.02, 0.16, 0.05, 0.77], 2);
    let mode = |frequency, damping_ratio, energy| RatedMode {
        frequency,
        damping_ratio,
        energy,
    };
    let modes = [
        mode(4.5, 0.05, &bogie),
        mode(4.6, 0.02, &bogie),
        mode(7.0, -0.1, &motor),
        mode(9.0, -0.2, &vertical),
        mode(11.0, -0.3, &bogie),
    ];
    assert_eq!(BOGIE_MODE.pick(&modes, &KINDS), Some(1));
    assert_eq!(CARBODY_MODE.pick(&modes, &KINDS), None);
    // Band edges are inclusive.
    assert!(BOGIE_MODE.admits(BOGIE_MODE.band.1, &bogie, &KINDS));
    assert!(!BOGIE_MODE.admits(BOGIE_MODE.band.1 * (1.0 + 1e-12), &bogie, &KINDS));
}

#[test]
fn rules_are_found_by_name_and_an_unknown_name_is_an_error() {
    assert_eq!(mode_rule("carbody").unwrap(), &CARBODY_MODE);
    assert_eq!(mode_rule("bogie").unwrap(), &BOGIE_MODE);
    let e = mode_rule("frame").unwrap_err().to_string();
    assert!(e.contains("frame") && e.contains("carbody, bogie"), "{e}");
    assert_eq!(
        body_kinds(&["carbody".into(), "wheelset2".into()]),
        ["carbody", "wheelsets"]
    );
}
