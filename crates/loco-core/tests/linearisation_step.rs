//! The central-difference steps of the linearisation (`vehicle::analysis::linearise`) lie on plateaus of
//! the right-hand side: each group of a wheelset's columns of `A` (and the rails' columns of `B`)
//! is compared with the same columns at other steps, about the candidate two groups of steps
//! (`LinearisationSettings::two_groups`). S_norm + YD1 at 200 km/h shows both effects
//! the split steps answer: the Hertz secant along vertical displacement and roll, and FASTSIM's
//! stick/slip structure at tiny creepages along the velocities.

use loco_core::dampers::Damper;
use loco_core::vehicle::analysis::linearise::LinearisationSettings;
use loco_core::vehicle::analysis::track_input::{
    scenario_track_model_with, TrackInputModel, RAIL_INPUTS,
};
use loco_core::vehicle::model::layout::{wheelset, N_DOF, PITCH, ROLL, X, YAW, Z};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::scenarios::scenario::Scenario;

/// The model of S_norm + YD1 at 200 km/h linearised with `settings`.
fn model(settings: LinearisationSettings) -> TrackInputModel {
    let mut s = Scenario::study("S_norm", 200.0 / 3.6, 100.0, 0).unwrap();
    s.yaw_damper = Some(Damper::yd1());
    scenario_track_model_with(ParameterSet::default_vehicle(), &s, &settings).unwrap()
}

/// Columns of coordinate `k` of every wheelset, `offset` 0 (displacements) or `N_DOF`
/// (velocities).
fn wheelset_columns(offset: usize, k: usize) -> Vec<usize> {
    (0..4).map(|w| offset + wheelset(w) + k).collect()
}

/// Relative difference (Frobenius) of the columns `cols` of two n×p row-major matrices.
fn difference(a: &[f64], b: &[f64], n: usize, p: usize, cols: &[usize]) -> f64 {
    let (mut d, mut r) = (0.0, 0.0);
    for &j in cols {
        for i in 0..n {
            d += (a[i * p + j] - b[i * p + j]).powi(2);
            r += b[i * p + j].powi(2);
        }
    }
    (d / r).sqrt()
}

#[test]
fn each_step_lies_on_a_plateau_of_its_coordinates() {
    let candidate = LinearisationSettings::two_groups();
    let base = model(candidate);
    let tiny = model(LinearisationSettings {
        step: 1e-8,
        ..candidate
    });
    let coarse_displacement = model(LinearisationSettings {
        step: 5e-5,
        ..candidate
    });
    let coarse_velocity = model(LinearisationSettings {
        contact_step: 2e-4,
        ..candidate
    });
    let fine_velocity = model(LinearisationSettings {
        contact_step: 1e-7,
        ..candidate
    });
    let n = base.n;
    let a = |m: &TrackInputModel, cols: &[usize]| difference(&m.a, &base.a, n, n, cols);
    // Vertical position and roll: the tangent of the Hertz law (1e-8 agrees), and a step of
    // 5e-5 (60 % of the 81 µm approach; a roll of 5e-5 moves each wheel by 37 µm) is a secant
    // off by more than 0.2 % (measured 1.3 % and 0.32 %).
    for k in [Z, ROLL] {
        let cols = wheelset_columns(0, k);
        assert!(a(&tiny, &cols) < 1e-3, "{k}: {}", a(&tiny, &cols));
        let secant = a(&coarse_displacement, &cols);
        assert!(secant > 2e-3, "{k}: the secant differs by only {secant}");
    }
    // The rails' heights move the Hertz approach as the wheelset's vertical position does.
    let p = base.n_inputs;
    let heights: Vec<usize> = (0..4)
        .flat_map(|w| [w * RAIL_INPUTS + 1, w * RAIL_INPUTS + 3])
        .collect();
    let b = |m: &TrackInputModel| difference(&m.b, &base.b, n, p, &heights);
    assert!(b(&tiny) < 1e-3, "rail heights: {}", b(&tiny));
    assert!(
        b(&coarse_displacement) > 5e-3,
        "{}",
        b(&coarse_displacement)
    );
    // Longitudinal, spin (the wheelset's PITCH coordinate) and yaw rates: 5e-5 and 2e-4 m/s agree (the creep law as a motion of
    // creepage 1e-4 samples it), while 1e-7 m/s reads the stick/slip structure, over 1 % away.
    for k in [X, PITCH, YAW] {
        let cols = wheelset_columns(N_DOF, k);
        assert!(
            a(&coarse_velocity, &cols) < 5e-3,
            "{k}: {}",
            a(&coarse_velocity, &cols)
        );
        let fine = a(&fine_velocity, &cols);
        assert!(
            fine > 1e-2,
            "{k}: the small velocity step differs by only {fine}"
        );
    }
}
