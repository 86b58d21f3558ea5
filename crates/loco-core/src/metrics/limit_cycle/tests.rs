//! The limit-cycle rule on records whose answer is known: a steady sinusoid (with broad-band
//! noise on top), a decaying one, narrow-band random noise (a lightly damped mode driven by
//! white noise) and silence.

use super::*;
use std::f64::consts::PI;

const FS: f64 = 500.0;

/// A deterministic uniform pseudo-random sequence in [−1, 1) (xorshift64*).
fn noise(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s ^= s >> 12;
            s ^= s << 25;
            s ^= s >> 27;
            let u = (s.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64;
            2.0 * u - 1.0
        })
        .collect()
}

fn run(x: &[f64]) -> LimitCycle {
    limit_cycle(x, FS, &StabilityParams::default()).unwrap()
}

#[test]
fn a_steady_sinusoid_with_noise_is_a_limit_cycle_at_its_frequency_and_amplitude() {
    let n = (9.0 * FS) as usize;
    let e = noise(n, 7);
    let x: Vec<f64> = (0..n)
        .map(|i| 7.5 * (2.0 * PI * 3.9 * i as f64 / FS).sin() + 1.0 * e[i])
        .collect();
    let c = run(&x);
    println!("{c:?}");
    assert!(c.detected);
    assert!((c.frequency - 3.9).abs() < 0.1, "{}", c.frequency);
    assert!((c.amplitude - 7.5).abs() < 0.3, "{}", c.amplitude);
}

#[test]
fn a_growing_oscillation_that_saturates_is_one_and_a_decaying_one_is_not() {
    let n = (9.0 * FS) as usize;
    let t = |i: usize| i as f64 / FS;
    let growing: Vec<f64> = (0..n)
        .map(|i| 5.0 * (1.0 - (-t(i) / 1.0).exp()) * (2.0 * PI * 4.2 * t(i)).sin())
        .collect();
    assert!(run(&growing).detected);
    // Damping ratio 1 %: it decays by 0.6 per quarter of 9 s at 4.2 Hz.
    let zeta = 0.01;
    let w = 2.0 * PI * 4.2;
    let decaying: Vec<f64> = (0..n)
        .map(|i| 5.0 * (-zeta * w * t(i)).exp() * (w * t(i)).sin())
        .collect();
    let c = run(&decaying);
    println!("{c:?}");
    assert!(!c.detected);
    assert!(c.sustained_ratio < SUSTAINED_RATIO);
}

#[test]
fn narrow_band_random_noise_is_not_a_limit_cycle() {
    // A 4 Hz mode of 3 % damping driven by white noise (explicit second-order recursion at
    // 500 Hz): sustained and narrow-band, but its cycle peaks vary as a Rayleigh variable's.
    let n = (60.0 * FS) as usize;
    let e = noise(n, 11);
    let (w, zeta, dt) = (2.0 * PI * 4.0, 0.03, 1.0 / FS);
    let (mut u, mut v) = (0.0, 0.0);
    let x: Vec<f64> = e
        .iter()
        .map(|f| {
            let a = 50.0 * f - 2.0 * zeta * w * v - w * w * u;
            v += a * dt;
            u += v * dt;
            // The mode's elastic force per mass: its response, without the white forcing.
            w * w * u
        })
        .collect();
    let c = run(&x);
    println!("{c:?}");
    assert!(c.share > NARROW_BAND_SHARE, "{c:?}");
    assert!(c.peak_variation > STEADY_PEAK_VARIATION, "{c:?}");
    assert!(!c.detected);
}

#[test]
fn silence_is_nothing() {
    let c = run(&vec![0.0; 4000]);
    assert!(!c.detected);
    assert_eq!(c.amplitude, 0.0);
}
