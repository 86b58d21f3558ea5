//! Benchmarks of the metrics of one run (target: all metrics of a 9 s record at 500 Hz in
//! under 1 ms) and of the track lookup the vehicle model calls every step.

use criterion::{criterion_group, criterion_main, Criterion};
use loco_core::metrics::{
    bogie_stability, sperling, weighted_rms, ComfortWeighting, Direction, RunMetrics,
    RunMetricsParams, RunRecords, SperlingParams, StabilityParams,
};
use loco_core::track::{synthesize, SynthesisParams};
use std::f64::consts::PI;
use std::hint::black_box;

/// A record of `n` samples at `fs` Hz: a few sines plus deterministic noise, m/s².
fn record(n: usize, fs: f64, freqs: &[(f64, f64)], seed: u64) -> Vec<f64> {
    let mut state = seed;
    (0..n)
        .map(|j| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let noise = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.1;
            let t = j as f64 / fs;
            noise
                + freqs
                    .iter()
                    .map(|(a, f)| a * (2.0 * PI * f * t).sin())
                    .sum::<f64>()
        })
        .collect()
}

fn bench_run_metrics(c: &mut Criterion) {
    let fs = 500.0;
    let n = 4500; // 9 s
    let ayc = record(n, fs, &[(0.2, 1.2), (0.05, 7.0)], 1);
    let azc = record(n, fs, &[(0.1, 1.5), (0.05, 9.0)], 2);
    let ayb = record(n, fs, &[(2.0, 6.0), (0.5, 15.0)], 3);
    let records = RunRecords {
        fs,
        speed: 200.0 / 3.6,
        carbody_lateral: &ayc,
        carbody_vertical: Some(&azc),
        bogie_lateral: &ayb,
        bogie_mass: 12_000.0,
    };
    let params = RunMetricsParams::default();
    c.bench_function("run_metrics_9s_500Hz", |b| {
        b.iter(|| RunMetrics::compute(black_box(&records), &params).unwrap())
    });
    // The parts, to see where the time goes.
    c.bench_function("sperling_9s", |b| {
        b.iter(|| {
            sperling(
                black_box(&ayc),
                fs,
                Direction::Lateral,
                &SperlingParams::default(),
            )
        })
    });
    c.bench_function("weighted_rms_9s", |b| {
        b.iter(|| weighted_rms(black_box(&ayc), fs, ComfortWeighting::Wd))
    });
    c.bench_function("bogie_stability_9s", |b| {
        b.iter(|| {
            bogie_stability(
                black_box(&ayb),
                fs,
                55.6,
                12_000.0,
                &StabilityParams::default(),
            )
        })
    });
}

fn bench_track_lookup(c: &mut Criterion) {
    let track = synthesize(&SynthesisParams {
        length: 1000.0,
        seed: 1,
        ..Default::default()
    })
    .unwrap();
    let mut s = 0.0;
    c.bench_function("track_at", |b| {
        b.iter(|| {
            s = (s + 0.137) % 1000.0;
            track.at(black_box(s))
        })
    });
    c.bench_function("track_synthesize_1km", |b| {
        b.iter(|| {
            synthesize(&SynthesisParams {
                length: 1000.0,
                seed: 2,
                ..Default::default()
            })
            .unwrap()
        })
    });
}

criterion_group!(benches, bench_run_metrics, bench_track_lookup);
criterion_main!(benches);
