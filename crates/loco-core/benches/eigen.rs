//! One eigen analysis of the built vehicle (static equilibrium, linearisation about it, the
//! state matrix's eigenvalues) on S_low and S_high at 200 km/h, its parts, and a linear
//! critical speed (a bisection of such analyses). Limit: one analysis at most 100 ms on one core.

use criterion::{criterion_group, criterion_main, Criterion};
use loco_core::vehicle::analysis::linear_critical_speed::{linear_critical_speed, LinearSearch};
use loco_core::vehicle::analysis::linearise::{eigenvalues, linearise};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::scenarios::perfect_track::PerfectTrackVehicle;
use loco_core::vehicle::scenarios::scenario::Scenario;
use std::hint::black_box;

fn bench_eigen(c: &mut Criterion) {
    let mut group = c.benchmark_group("eigen");
    group.sample_size(10);
    for name in ["S_low", "S_high"] {
        let scenario = Scenario::study(name, 200.0 / 3.6, 500.0, 0).unwrap();
        let vehicle = PerfectTrackVehicle::new(ParameterSet::default_vehicle(), &scenario).unwrap();
        group.bench_function(format!("{name}_statics_linearise_eigenvalues"), |b| {
            b.iter(|| {
                let mut system = vehicle.system(scenario.speed).unwrap();
                let (a, _) = linearise(&mut system).unwrap();
                eigenvalues(black_box(&a), system.len_states()).unwrap()
            })
        });
        group.bench_function(format!("{name}_statics_linearise"), |b| {
            b.iter(|| linearise(&mut vehicle.system(scenario.speed).unwrap()).unwrap())
        });
        let mut system = vehicle.system(scenario.speed).unwrap();
        let n = system.len_states();
        let (a, _) = linearise(&mut system).unwrap();
        group.bench_function(format!("{name}_eigenvalues"), |b| {
            b.iter(|| eigenvalues(black_box(&a), n).unwrap())
        });
    }
    let scenario = Scenario::study("S_high", 200.0 / 3.6, 500.0, 0).unwrap();
    let vehicle =
        std::sync::Arc::new(
            loco_core::vehicle::model::structure::VehicleStructure::new(
                ParameterSet::default_vehicle(),
            )
            .unwrap(),
        );
    group.bench_function("S_high_linear_critical_speed", |b| {
        b.iter(|| {
            linear_critical_speed(
                vehicle.clone(),
                black_box(&scenario),
                &LinearSearch::default(),
            )
            .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, bench_eigen);
criterion_main!(benches);
