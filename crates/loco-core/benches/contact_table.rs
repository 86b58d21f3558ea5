//! Contact table: building one for a wheel/rail pair (target < 100 ms) and `lookup(y)` (target
//! < 100 ns). Uses the Manchester benchmark S1002/UIC60 profiles when the shared reference data
//! are found (`$LOCO_SHARED_DATA` or a `shared/data` next to an ancestor directory), otherwise a
//! synthetic flanged wheel and rail built from lines and arcs.

use criterion::{criterion_group, criterion_main, Criterion};
use loco_core::contact::*;
use std::hint::black_box;
use std::path::PathBuf;

fn shared_data() -> Option<PathBuf> {
    if let Ok(dir) = std::env::var("LOCO_SHARED_DATA") {
        return Some(PathBuf::from(dir));
    }
    let mut dir = Some(PathBuf::from(env!("CARGO_MANIFEST_DIR")));
    while let Some(d) = dir {
        if d.join("shared/data").is_dir() {
            return Some(d.join("shared/data"));
        }
        dir = d.parent().map(PathBuf::from);
    }
    None
}

/// (wheel, rail, track, wheelset, grid) of the benchmarked pair.
fn pair() -> (
    Profile,
    Profile,
    TrackSetup,
    WheelsetSetup,
    ContactTableParams,
) {
    let wheelset = WheelsetSetup {
        back_to_back: 1.36,
        flange_back_offset: 0.07,
        nominal_radius: [0.46, 0.46],
    };
    if let Some(data) = shared_data() {
        let w = load_profile(&data.join("profiles/MBench_S1002_v3.prw"), None, false);
        let r = load_profile(&data.join("profiles/MBench_UIC60_v3.prr"), None, false);
        if let (Ok(w), Ok(r)) = (w, r) {
            let track = TrackSetup {
                gauge: 1.435,
                gauge_height: 0.014,
                rail_inclination: 0.0,
            };
            eprintln!("profiles: S1002 / UIC60 (Manchester benchmark), grid ±15 mm by 0.1 mm");
            return (w, r, track, wheelset, ContactTableParams::default());
        }
    }
    eprintln!("profiles: synthetic flanged wheel / rail head, grid ±7.5 mm by 0.1 mm");
    let face = 70_f64.to_radians();
    let wheel = ProfileBuilder::new(-0.048, -0.0347, face)
        .line(0.025)
        .arc(0.015, -(face - 0.05_f64.atan()))
        .line(0.09)
        .build("flanged", ProfileKind::Wheel, 2e-4)
        .expect("synthetic wheel");
    let rail = ProfileBuilder::new(-0.0375, -0.045, 1.5)
        .line(0.030)
        .arc(0.013, -1.42)
        .arc(0.3, -0.16)
        .arc(0.013, -1.42)
        .line(0.015)
        .build("head", ProfileKind::Rail, 2e-4)
        .expect("synthetic rail");
    let grid = ContactTableParams {
        y_min: -0.0075,
        y_max: 0.0075,
        step: 1e-4,
    };
    (wheel, rail, TrackSetup::default(), wheelset, grid)
}

fn bench(c: &mut Criterion) {
    let (wheel, rail, track, wheelset, grid) = pair();
    let g = ContactGeometry::symmetric(&wheel, &rail, &track, &wheelset, &Default::default())
        .expect("geometry");
    c.bench_function("contact_table_build", |b| {
        b.iter(|| ContactTable::build(black_box(&g), black_box(&grid)).expect("table"))
    });
    let table = ContactTable::build(&g, &grid).expect("table");
    // Pseudo-random displacements over the grid so that the branch predictor cannot learn them.
    let ys: Vec<f64> = (0..1024)
        .map(|i| grid.y_min + (grid.y_max - grid.y_min) * ((i * 7919) % 1024) as f64 / 1024.0)
        .collect();
    let mut k = 0;
    c.bench_function("contact_table_lookup", |b| {
        b.iter(|| {
            k = (k + 1) & 1023;
            black_box(table.lookup(black_box(ys[k])))
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = bench
}
criterion_main!(benches);
