//! The static-equilibrium search's own failure and the cost statistics of a run: a search cut
//! short is a typed `Equilibrium` error (not a divergence), and the counts of a run agree with
//! its RK4 schedule.

use loco_core::batch::SampleStatus;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::rail_contact::wheel_rail::ContactMode;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::{build_track, start_distance, Scenario, TrackSpec};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use loco_core::vehicle::system::simulation::VehicleSystem;
use loco_core::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use loco_core::LocoError;
use std::sync::Arc;

fn perfect(speed: f64, distance: f64) -> Scenario {
    let mut s = Scenario::study("S_norm", speed, distance, 0).unwrap();
    s.track = TrackSpec::Perfect;
    s
}

fn system(scenario: &Scenario) -> VehicleSystem {
    let structure = Arc::new(VehicleStructure::new(ParameterSet::default_vehicle()).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, scenario).unwrap());
    let track = Arc::new(build_track(scenario, &structure).unwrap());
    let start = start_distance(&structure);
    VehicleSystem::new(structure, wr, track, scenario.speed, start, None, 1e-3).unwrap()
}

#[test]
fn a_search_cut_short_is_an_equilibrium_error_with_its_iterations_and_residual() {
    let scenario = perfect(50.0, 10.0);
    let mut sys = system(&scenario);
    let full = static_equilibrium(&mut sys, &StaticsSettings::default()).unwrap();
    assert!(full.iterations >= 2, "{} iterations", full.iterations);
    let short = StaticsSettings {
        max_iterations: full.iterations - 1,
        ..StaticsSettings::default()
    };
    let mut sys = system(&scenario);
    let err = static_equilibrium(&mut sys, &short).unwrap_err();
    match &err {
        LocoError::Equilibrium {
            iterations,
            residual,
            ..
        } => {
            assert_eq!(*iterations, full.iterations - 1);
            assert!(*residual > full.residual, "{residual} vs {}", full.residual);
        }
        other => panic!("expected an equilibrium error, got {other:?}"),
    }
    assert_eq!(SampleStatus::from_error(&err), SampleStatus::Equilibrium);
    // The system is left running, not held.
    assert_eq!(sys.contact_mode, ContactMode::Rolling);
    let bad = StaticsSettings {
        tolerance: f64::NAN,
        ..StaticsSettings::default()
    };
    let err = static_equilibrium(&mut sys, &bad).unwrap_err();
    assert!(err.to_string().contains("statics.tolerance"), "{err}");
}

#[test]
fn run_statistics_follow_the_rk4_schedule() {
    let scenario = perfect(50.0, 5.0);
    let r = simulate(ParameterSet::default_vehicle(), &scenario).unwrap();
    let s = r.statistics;
    let dt = scenario.run.step;
    let expected_steps = ((scenario.distance / scenario.speed) / dt).round() as u64;
    assert_eq!(s.steps, expected_steps);
    assert!(s.newton_iterations >= 1);
    // Four stages a step and one at the final sample; the static search evaluates its initial
    // residual, then per Newton iteration 90 Jacobian columns and 1 to 15 line-search trials.
    let time_loop = 4 * s.steps + 1;
    let statics = s.rhs_evaluations - time_loop;
    assert!(
        statics > s.newton_iterations * 91 && statics <= 1 + s.newton_iterations * (90 + 15),
        "{s:?}"
    );
    assert!(s.wall_time > 0.0 && s.wall_time.is_finite());
    // Statistics are extra: a rerun gives the same channels bit for bit and the same counts.
    let again = simulate(ParameterSet::default_vehicle(), &scenario).unwrap();
    assert_eq!(again.output.channels, r.output.channels);
    assert_eq!(
        (again.statistics.rhs_evaluations, again.statistics.steps),
        (s.rhs_evaluations, s.steps)
    );
}

#[test]
fn an_output_rate_between_whole_steps_shortens_the_step_never_lengthens_it() {
    // 400 Hz at the default 2 ms: 1.25 steps per sample. Rounding took one 2.5 ms step, longer
    // than the step the stability check passed; two 1.25 ms steps are what was asked.
    let mut scenario = perfect(50.0, 5.0);
    scenario.run.output_rate = 400.0;
    let requested = scenario.run.step;
    let r = simulate(ParameterSet::default_vehicle(), &scenario).unwrap();
    let duration = scenario.distance / scenario.speed;
    let taken = duration / r.statistics.steps as f64;
    assert!(
        taken <= requested * (1.0 + 1e-9),
        "{taken} s steps for {requested} s"
    );
    assert_eq!(r.statistics.steps, (duration * 800.0).round() as u64);
    assert_eq!(r.output.sampling_rate, 400.0);
    // Whole ratios keep their count: 500 Hz takes one 2 ms step, two 1 ms steps, three of 2/3 ms.
    use loco_core::vehicle::output::run::steps_per_sample;
    for (rate, step, n) in [
        (500.0, 2e-3, 1),
        (500.0, 1e-3, 2),
        (500.0, 2e-3 / 3.0, 3),
        (500.0, 0.25e-3, 8),
        (400.0, 2e-3, 2),
        (300.0, 2e-3, 2),
        (450.0, 2e-3, 2),
        (1000.0, 2e-3, 1),
    ] {
        assert_eq!(steps_per_sample(rate, step), n, "{rate} Hz at {step} s");
    }
}
