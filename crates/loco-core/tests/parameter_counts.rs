//! Damper counts multiply the dampers: n identical Maxwell dampers in parallel on one line are one
//! Maxwell damper with n times the damping and n times the series stiffness (same relaxation time
//! c/k, n times the force), so the linearised vehicles must agree.

use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::linearised;
use loco_core::vehicle::scenarios::scenario::Scenario;

fn state_matrix(overrides: &[(&str, f64)]) -> (Vec<f64>, usize) {
    let mut p = ParameterSet::default_vehicle();
    for (key, value) in overrides {
        p.set(key, *value).unwrap();
    }
    let scenario = Scenario::study("S_norm", 200.0 / 3.6, 100.0, 1).unwrap();
    linearised(p, &scenario).unwrap()
}

fn max_abs_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn two_dampers_per_place_act_as_one_of_twice_the_damping_and_series_stiffness() {
    let base = ParameterSet::default_vehicle();
    let (reference, n) = state_matrix(&[]);
    let scale = reference.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    for (count, damping, stiffness) in [
        (
            "secondary.yaw_dampers_per_side",
            "secondary.yaw_damper_damping",
            "secondary.yaw_damper_series_stiffness",
        ),
        (
            "secondary.vertical_dampers_per_side",
            "secondary.vertical_damper_damping",
            "secondary.vertical_damper_series_stiffness",
        ),
        (
            "primary.vertical_dampers_per_axle_box",
            "primary.vertical_damper_damping",
            "primary.vertical_damper_series_stiffness",
        ),
    ] {
        let c = base.get(damping).unwrap();
        let k = base.get(stiffness).unwrap();
        let (two, n2) = state_matrix(&[(count, 2.0)]);
        let (doubled, n3) = state_matrix(&[(damping, 2.0 * c), (stiffness, 2.0 * k)]);
        assert_eq!((n2, n3), (n, n), "{count}");
        let same = max_abs_difference(&two, &doubled);
        let changed = max_abs_difference(&two, &reference);
        assert!(same <= 1e-9 * scale, "{count}: {same:e} of {scale:e}");
        assert!(
            changed > 1e-6 * scale,
            "{count} changes nothing: {changed:e}"
        );
    }
}
