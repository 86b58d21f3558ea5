//! One damper force evaluation (force and state derivatives) per damper type; target < 50 ns.
//! The FSD's valve is advanced once per accepted step: `damper_advance_fsd` (rms-frequency
//! trigger) and `damper_advance_fsd_hydraulic` (the hydraulic valve, target < 50 ns added).

use criterion::{criterion_group, criterion_main, Criterion};
use loco_core::dampers::{Damper, HydraulicDamper, HydraulicParams, MAX_STATES};
use std::hint::black_box;

fn evaluate(c: &mut Criterion) {
    let hydraulic = HydraulicDamper::new(HydraulicParams::default()).expect("default is valid");
    let dampers = [
        ("maxwell_yd2", Damper::yd2()),
        ("fsd", Damper::fsd()),
        ("fsd_hydraulic", Damper::fsd_hydraulic()),
        ("hydraulic", Damper::Hydraulic(hydraulic)),
    ];
    for (name, damper) in dampers {
        let n = damper.n_states();
        let states = [1.0e-4, 0.02];
        let discrete = damper.initial_discrete();
        c.bench_function(&format!("damper_evaluate_{name}"), |b| {
            let mut dstates = [0.0; MAX_STATES];
            b.iter(|| {
                black_box(&damper).evaluate(
                    black_box(2.0e-3),
                    black_box(0.01),
                    black_box(&states[..n]),
                    black_box(&discrete),
                    &mut dstates[..n],
                )
            })
        });
    }
    for (name, damper) in [
        ("fsd", Damper::fsd()),
        ("fsd_hydraulic", Damper::fsd_hydraulic()),
    ] {
        c.bench_function(&format!("damper_advance_{name}"), |b| {
            let mut discrete = damper.initial_discrete();
            let mut t = 0.0_f64;
            b.iter(|| {
                t += 1e-4;
                // A 1.2 Hz stroke, so the hydraulic valve moves and switches.
                let x = 2.0e-3 * (7.54 * t).sin();
                damper.advance(
                    &mut discrete,
                    t,
                    black_box(1e-4),
                    black_box(x),
                    black_box(0.01),
                    &[0.0, 0.0],
                );
            })
        });
    }
}

criterion_group!(benches, evaluate);
criterion_main!(benches);
