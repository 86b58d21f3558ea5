//! The frequency response of one case (the limit's case: 100 frequencies, 4 inputs, 10 outputs
//! under 200 ms): the whole call (vehicle, contact table, static equilibrium, linearisation with
//! the track as input, Hessenberg reduction, solves), and its parts.

use criterion::{criterion_group, criterion_main, Criterion};
use loco_core::track::Channel;
use loco_core::vehicle::analysis::frequency_response::{frequency_response, ResponseSolver};
use loco_core::vehicle::analysis::track_input::{scenario_track_model, track_input_model};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::scenarios::perfect_track::PerfectTrackVehicle;
use loco_core::vehicle::scenarios::scenario::Scenario;
use std::hint::black_box;

/// Ten recorded channels: accelerations, wheelset motion and damper forces.
const OUTPUTS: [&str; 10] = [
    "carbody_floor_ay_front",
    "carbody_floor_ay_rear",
    "carbody_floor_az_front",
    "frame1_ay_centre",
    "frame1_ay_wheelset1",
    "frame2_ay_wheelset3",
    "wheelset1_y",
    "wheelset4_y",
    "wheel1_left_Q",
    "wheel1_left_Y",
];

fn bench_frequency_response(c: &mut Criterion) {
    let scenario = Scenario::study("S_low", 200.0 / 3.6, 500.0, 0).unwrap();
    let outputs: Vec<String> = OUTPUTS.iter().map(|s| s.to_string()).collect();
    let frequencies: Vec<f64> = (1..=100).map(|i| 0.2 * i as f64).collect();
    let mut group = c.benchmark_group("frequency_response");
    group.sample_size(10);
    group.bench_function("one_case_100f_4in_10out", |b| {
        b.iter(|| {
            frequency_response(
                ParameterSet::default_vehicle(),
                black_box(&scenario),
                &Channel::ALL,
                &outputs,
                &frequencies,
            )
            .unwrap()
        })
    });
    let vehicle = PerfectTrackVehicle::new(ParameterSet::default_vehicle(), &scenario).unwrap();
    group.bench_function("linearise_with_track_input", |b| {
        b.iter(|| track_input_model(&mut vehicle.system(scenario.speed).unwrap()).unwrap())
    });
    let model = scenario_track_model(ParameterSet::default_vehicle(), &scenario).unwrap();
    group.bench_function("reduce_and_solve_100f_4in_10out", |b| {
        b.iter(|| {
            ResponseSolver::new(black_box(&model), &outputs)
                .unwrap()
                .response(&Channel::ALL, &frequencies)
                .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, bench_frequency_response);
criterion_main!(benches);
