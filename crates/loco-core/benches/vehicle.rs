//! One 500 m run of the full 90-DOF model at 200 km/h (9 s simulated), with FASTSIM (the study's
//! creep model) and RK4 at 1 ms (the reference settings; the series the performance history
//! follows), the same with the default exponential scheme at 2 ms (`integrator = "etdrk4"`), with
//! FaStrip, with the FASTSIM table and with the table at 2 ms, the same FASTSIM run on a curved track
//! (the design of `loco-dev`'s `run_fingerprint … curve`: 10 m straight, 60 m clothoid, R = 1200 m
//! left with 100 mm cant; against `run_500m_200kmh` it gives what the curve terms cost), the same
//! on a curve of the curving study (R = 3000 m, 60 mm cant) with both schemes, and one evaluation
//! of its right-hand side.

use criterion::measurement::WallTime;
use criterion::{criterion_group, criterion_main, BenchmarkGroup, Criterion};
use loco_core::track::{CurveDirection, DesignSection, TrackIrregularity};
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::output::run::{Recorded, RunSettings};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::rail_contact::creep_model::CreepModel;
use loco_core::vehicle::rail_contact::wheel_rail::WheelRail;
use loco_core::vehicle::runs::simulate::simulate_prepared;
use loco_core::vehicle::scenarios::scenario::{build_track, start_distance, Scenario};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use loco_core::vehicle::system::simulation::VehicleSystem;
use loco_core::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use loco_core::vehicle::time::integrator::{Integrator, OdeSystem};
use loco_core::vehicle::time::integrator::{EXPONENTIAL_STEP, REFERENCE_STEP};
use std::hint::black_box;
use std::sync::Arc;

/// One timed `simulate_prepared` of `scenario` on prepared contact and track.
fn bench_run(
    group: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    structure: &Arc<VehicleStructure>,
    (contact, track): (&Arc<WheelRail>, &Arc<TrackIrregularity>),
    scenario: &Scenario,
) {
    group.bench_function(name, |b| {
        b.iter(|| {
            simulate_prepared(
                structure.clone(),
                contact.clone(),
                track.clone(),
                black_box(scenario),
                Recorded::Every,
                None,
            )
            .unwrap()
        })
    });
}

fn bench_vehicle(c: &mut Criterion) {
    let mut scenario = Scenario::study("S_high", 200.0 / 3.6, 500.0, 1).unwrap();
    scenario.run.integrator = Integrator::Rk4;
    scenario.run.step = REFERENCE_STEP;
    let structure = Arc::new(VehicleStructure::new(ParameterSet::default_vehicle()).unwrap());
    let wheel_rail = Arc::new(build_wheel_rail(&structure.parameters, &scenario).unwrap());
    let track = Arc::new(build_track(&scenario, &structure).unwrap());
    // The same run with the exponential scheme at its 2 ms step: the default.
    let exponential = RunSettings {
        integrator: Integrator::ExponentialRk4,
        step: EXPONENTIAL_STEP,
        ..scenario.run
    };
    let with = |base: &Scenario, run: RunSettings| Scenario {
        run,
        ..base.clone()
    };

    let mut group = c.benchmark_group("vehicle");
    group.sample_size(10);
    let straight = (&wheel_rail, &track);
    bench_run(
        &mut group,
        "run_500m_200kmh",
        &structure,
        straight,
        &scenario,
    );
    let default = with(&scenario, exponential);
    bench_run(
        &mut group,
        "run_500m_200kmh_etdrk4",
        &structure,
        straight,
        &default,
    );
    let fastrip = Scenario {
        creep: CreepModel::Fastrip,
        ..scenario.clone()
    };
    let fastrip_contact = Arc::new(build_wheel_rail(&structure.parameters, &fastrip).unwrap());
    let case = (&fastrip_contact, &track);
    bench_run(
        &mut group,
        "run_500m_200kmh_fastrip",
        &structure,
        case,
        &fastrip,
    );
    let table = Scenario {
        creep: CreepModel::from_name("table").unwrap(),
        ..scenario.clone()
    };
    // The table is built once per batch, outside the timed run.
    let table_contact = Arc::new(build_wheel_rail(&structure.parameters, &table).unwrap());
    let case = (&table_contact, &track);
    bench_run(
        &mut group,
        "run_500m_200kmh_table",
        &structure,
        case,
        &table,
    );
    // The table with the exponential scheme at its 2 ms step: both speed options together.
    let table_exponential = with(&table, exponential);
    let name = "run_500m_200kmh_table_etdrk4";
    bench_run(&mut group, name, &structure, case, &table_exponential);
    // The scenario on a curve, with its contact and track (built outside the timed runs).
    let on_curve = |curve: Vec<DesignSection>| {
        let curved = Scenario {
            curve,
            ..scenario.clone()
        };
        let contact = Arc::new(build_wheel_rail(&structure.parameters, &curved).unwrap());
        let track = Arc::new(build_track(&curved, &structure).unwrap());
        (curved, contact, track)
    };
    let (curved, curved_contact, curved_track) =
        on_curve(DesignSection::reference_curve(0.1, CurveDirection::Left));
    let case = (&curved_contact, &curved_track);
    bench_run(
        &mut group,
        "run_500m_200kmh_curve",
        &structure,
        case,
        &curved,
    );
    // A curve like the curving study's (R = 3000 m, 60 mm cant: about 97 mm of deficiency at
    // 200 km/h, one contact patch per wheel as on straight track), with both schemes.
    let (study_curve, study_contact, study_track) =
        on_curve(DesignSection::study_curve(CurveDirection::Left));
    let case = (&study_contact, &study_track);
    let name = "run_500m_200kmh_study_curve";
    bench_run(&mut group, name, &structure, case, &study_curve);
    let study_curve_exponential = with(&study_curve, exponential);
    let name = "run_500m_200kmh_study_curve_etdrk4";
    bench_run(&mut group, name, &structure, case, &study_curve_exponential);
    group.finish();

    let mut system = VehicleSystem::new(
        structure.clone(),
        wheel_rail,
        track,
        scenario.speed,
        start_distance(&structure),
        None,
        scenario.run.step,
    )
    .unwrap();
    let y = static_equilibrium(&mut system, &StaticsSettings::default())
        .unwrap()
        .state;
    let mut dy = vec![0.0; y.len()];
    c.bench_function("vehicle_right_hand_side", |b| {
        b.iter(|| system.derivatives(0.1, black_box(&y), &mut dy))
    });
}

criterion_group!(benches, bench_vehicle);
criterion_main!(benches);
