//! Equivalent conicity from a sampled Δr(y): one amplitude and the full EN 15302 curve (66
//! amplitudes, 1.0 … 7.5 mm) by the nonlinear kinematic method and by harmonic linearisation.
//!
//! The Δr function is the built-in worn JM3-type wheel on CN60 rail (the study's S_high pair, the
//! most nonlinear of the three), sampled every 0.1 mm over ±12 mm as the contact report does;
//! the contact geometry itself is outside the timing.

use criterion::{criterion_group, criterion_main, Criterion};
use loco_core::contact::conicity::{conicity_curve, equivalent_conicity};
use loco_core::contact::conicity_harmonic::conicity_curve_harmonic;
use loco_core::contact::delta_r::DeltaR;
use loco_core::contact::{
    builtin_profile, rolling_radius_difference, ContactGeometry, ContactSearchParams, TrackSetup,
    WheelsetSetup,
};
use std::hint::black_box;

fn worn_jm3_on_cn60() -> DeltaR {
    let wheel = builtin_profile("jm3-worn").expect("built-in wheel");
    let rail = builtin_profile("cn60").expect("built-in rail");
    let geometry = ContactGeometry::symmetric(
        &wheel,
        &rail,
        &TrackSetup::default(),
        &WheelsetSetup::default(),
        &ContactSearchParams::default(),
    )
    .expect("contact geometry");
    let ys: Vec<f64> = (0..=240).map(|i| -0.012 + 1e-4 * i as f64).collect();
    let dr = rolling_radius_difference(&geometry, &ys).expect("Δr");
    DeltaR::new(ys, dr).expect("Δr samples")
}

fn bench(c: &mut Criterion) {
    let f = worn_jm3_on_cn60();
    let amplitudes: Vec<f64> = (10..=75).map(|i| i as f64 * 1e-4).collect();
    c.bench_function("conicity nonlinear, 3 mm", |b| {
        b.iter(|| equivalent_conicity(black_box(&f), black_box(0.003)))
    });
    c.bench_function("conicity nonlinear, 66 amplitudes", |b| {
        b.iter(|| conicity_curve(black_box(&f), black_box(&amplitudes)))
    });
    c.bench_function("conicity harmonic, 66 amplitudes", |b| {
        b.iter(|| conicity_curve_harmonic(black_box(&f), black_box(&amplitudes)))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
