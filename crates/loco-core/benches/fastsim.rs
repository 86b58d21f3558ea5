//! FASTSIM cost per call (target: < 2 µs on a 10 × 10 grid), FaStrip's on the same grids (target:
//! at most 1.5 × FASTSIM's) and the Hertz evaluations the vehicle model makes per contact and
//! right-hand side.

use criterion::{criterion_group, criterion_main, Criterion};
use loco_core::contact::fastrip::{Fastrip, FastripParams};
use loco_core::contact::fastsim::{Fastsim, FastsimParams, TractionBound};
use loco_core::contact::fastsim_table::{FastsimTable, FastsimTableParams};
use loco_core::contact::hertz::{ContactRadii, ElasticMaterial, HertzCoefficients};
use loco_core::contact::hertz_table::HertzShapeTable;
use loco_core::contact::kalker::Creepages;
use std::hint::black_box;

fn bench_fastsim(c: &mut Criterion) {
    // The CONTACT reference case: partial slip with spin, the costly regime.
    let creep = Creepages {
        longitudinal: 1e-4,
        lateral: -6.25e-4,
        spin: 0.625,
    };
    for (n, bound) in [
        (10, TractionBound::Parabolic),
        (10, TractionBound::Elliptic),
        (20, TractionBound::Parabolic),
    ] {
        let solver = Fastsim::new(FastsimParams {
            nx: n,
            ny: n,
            bound,
            ..FastsimParams::default()
        })
        .expect("valid parameters");
        c.bench_function(&format!("fastsim {n}x{n} {bound:?}"), |bench| {
            bench.iter(|| {
                solver.creep_forces(
                    black_box(8e-3),
                    black_box(4e-3),
                    black_box(82e3),
                    black_box(0.3),
                    black_box(&creep),
                )
            })
        });
    }
}

fn bench_fastrip(c: &mut Criterion) {
    // The same case as FASTSIM's.
    let creep = Creepages {
        longitudinal: 1e-4,
        lateral: -6.25e-4,
        spin: 0.625,
    };
    for n in [10, 20] {
        let solver = Fastrip::new(FastripParams {
            nx: n,
            ny: n,
            ..FastripParams::default()
        })
        .expect("valid parameters");
        c.bench_function(&format!("fastrip {n}x{n}"), |bench| {
            bench.iter(|| {
                solver.creep_forces(
                    black_box(8e-3),
                    black_box(4e-3),
                    black_box(82e3),
                    black_box(0.3),
                    black_box(&creep),
                )
            })
        });
    }
}

fn bench_fastsim_table(c: &mut Criterion) {
    let creep = Creepages {
        longitudinal: 1e-4,
        lateral: -6.25e-4,
        spin: 0.625,
    };
    let table = FastsimTable::new(FastsimParams::default(), FastsimTableParams::default())
        .expect("valid parameters");
    c.bench_function("fastsim table lookup (10x10 solver)", |bench| {
        bench.iter(|| {
            table.creep_forces(
                black_box(8e-3),
                black_box(4e-3),
                black_box(82e3),
                black_box(0.3),
                black_box(&creep),
            )
        })
    });
}

fn bench_hertz(c: &mut Criterion) {
    let radii = ContactRadii {
        wheel_rolling: 0.625,
        wheel_transverse: -0.5,
        rail_transverse: 0.3,
    };
    let material = ElasticMaterial::default();
    c.bench_function("hertz coefficients (per geometry)", |bench| {
        bench.iter(|| HertzCoefficients::new(black_box(&radii), black_box(&material)))
    });
    let table = HertzShapeTable::new();
    c.bench_function("hertz coefficients (tabulated shape)", |bench| {
        bench.iter(|| table.coefficients(black_box(0.8), black_box(2.4), black_box(1.15e11)))
    });
    let coef = HertzCoefficients::new(&radii, &material).expect("elliptic contact");
    c.bench_function("hertz load from approach + ellipse", |bench| {
        bench.iter(|| coef.contact(coef.load_from_approach(black_box(1e-4))))
    });
}

criterion_group!(
    benches,
    bench_fastsim,
    bench_fastrip,
    bench_fastsim_table,
    bench_hertz
);
criterion_main!(benches);
