//! The linear stochastic method against a long time-domain run: the Welch
//! PSD of the carbody floor and bogie frame lateral accelerations on a synthetic track scaled
//! down to small amplitude lies within its statistical band around the linear model's PSD.
//!
//! The band. A Welch estimate from K Hann segments with 50 % overlap is distributed as
//! `S·χ²_ν/ν` with `ν = 2K / (1 + 2ρ²)`, ρ = 0.167 the correlation of adjacent half-overlapping
//! Hann segments (Percival & Walden, *Spectral Analysis for Physical Applications*, 1993,
//! §6.17). The two-sided 99 % band of the estimate around the true S is
//! `[S·χ²_{ν,0.005}/ν, S·χ²_{ν,0.995}/ν]`, the quantiles by the Wilson–Hilferty approximation
//! `χ²_{ν,p} ≈ ν (1 − 2/(9ν) + z_p √(2/(9ν)))³` (relative error < 1 % for ν > 20). Bins are
//! nearly independent (Hann, bins 0.1 Hz apart), so about 1 % of them fall outside by chance;
//! the test allows 5 %. Two things make the band conservative: the synthesis has deterministic
//! amplitudes per spectral line (random phases only), whose periodogram varies less than χ²₂,
//! and the Welch estimate is the PSD smoothed by the Hann kernel (±0.2 Hz main lobe), a small
//! bias at the sharpest peak compared with the band's ±35 %.

use crate::record::Record;
use loco_core::metrics::{sperling, welch_psd, Direction, SperlingParams, WelchParams};
use loco_core::track::{synthesize, SynthesisParams, TrackSpectrum};
use loco_core::vehicle::analysis::response_psd::{response_psd, PsdSettings};
use loco_core::vehicle::analysis::track_input::scenario_track_model;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::{Scenario, TrackSpec};
use std::sync::Arc;

/// Factor on the TB/T 3352-2014 amplitudes: 0.1 keeps every wheelset within ±1 mm (S_norm).
const SCALE: f64 = 0.1;
const SPEED: f64 = 200.0 / 3.6;

/// The standard normal 0.995 quantile (Abramowitz & Stegun, table 26.5).
const Z_995: f64 = 2.575_829;

fn chi2_quantile(nu: f64, z: f64) -> f64 {
    let c = 2.0 / (9.0 * nu);
    nu * (1.0 - c + z * c.sqrt()).powi(3)
}

#[test]
fn welch_psd_lies_in_its_chi_square_band_around_the_linear_psd() {
    let duration = 120.0;
    let lead_in = 300.0;
    let mut scenario = Scenario::study("S_norm", SPEED, duration * SPEED, 3).unwrap();
    scenario.lead_in = lead_in;
    let length = scenario.lead_in + scenario.distance + 20.0;
    let params = SynthesisParams {
        spectrum: TrackSpectrum::CnHsr,
        seed: 3,
        length,
        ..SynthesisParams::default()
    };
    let track = synthesize(&params).unwrap().scaled(SCALE).unwrap();
    scenario.track = TrackSpec::Given(Arc::new(track));
    let result = simulate(ParameterSet::default_vehicle(), &scenario).unwrap();
    let out = &result.output;
    let fs = out.sampling_rate;

    let segment = (10.0 * fs) as usize;
    let welch = WelchParams {
        segment_len: Some(segment),
        overlap: 0.5,
    };
    let n = out.time.len();
    let k = ((n - segment) / (segment / 2) + 1) as f64;
    let nu = 2.0 * k / (1.0 + 2.0 * 0.167f64.powi(2));
    let (low, high) = (
        chi2_quantile(nu, -Z_995) / nu,
        chi2_quantile(nu, Z_995) / nu,
    );
    let mut record = Record::new("response_psd_band", file!())
        .value("band_low", low, "", 3)
        .value("band_high", high, "", 3);
    println!("K = {k} segments, nu = {nu:.1}, 99 % band [{low:.3}, {high:.3}] x S");

    let model = scenario_track_model(ParameterSet::default_vehicle(), &scenario).unwrap();
    let settings = PsdSettings {
        amplitude_scale: SCALE,
        wavelength_min: params.wavelength_min,
        wavelength_max: params.wavelength_max,
        ..PsdSettings::default()
    };
    for name in ["carbody_floor_ay_front", "frame1_ay_wheelset1"] {
        let estimate = welch_psd(out.channel(name).unwrap(), fs, &welch).unwrap();
        // Bins from 0.5 Hz to 20 Hz (the band the metrics use), where the input band
        // (2–200 m at 55.6 m/s: 0.28–27.8 Hz) is fully inside.
        let bins: Vec<usize> = (0..estimate.frequency.len())
            .filter(|&i| (0.5..=20.0).contains(&estimate.frequency[i]))
            .collect();
        let freqs: Vec<f64> = bins.iter().map(|&i| estimate.frequency[i]).collect();
        let linear = response_psd(&model, &[name.to_string()], &freqs, &settings).unwrap();
        let mut outside = 0;
        let mut ratio_log_sum = 0.0;
        for (j, &i) in bins.iter().enumerate() {
            let ratio = estimate.density[i] / linear.psd[0][j];
            ratio_log_sum += ratio.ln();
            if !(low..=high).contains(&ratio) {
                outside += 1;
            }
        }
        let fraction = outside as f64 / bins.len() as f64;
        let welch_rms = (bins.iter().map(|&i| estimate.density[i]).sum::<f64>() * 0.1).sqrt();
        println!(
            "{name}: {outside}/{} bins outside ({:.1} %), geometric mean ratio {:.3}, \
             rms 0.5-20 Hz: Welch {welch_rms:.4e}, linear {:.4e} m/s²",
            bins.len(),
            100.0 * fraction,
            (ratio_log_sum / bins.len() as f64).exp(),
            linear.rms[0]
        );
        assert!(
            fraction <= 0.05,
            "{name}: {:.1} % of bins outside",
            100.0 * fraction
        );
        let geometric_mean = (ratio_log_sum / bins.len() as f64).exp();
        record = record
            .count(&format!("{name}_bins"), bins.len())
            .count(&format!("{name}_outside"), outside)
            .within(
                &format!("{name}_outside_fraction"),
                fraction,
                "",
                2,
                "≤",
                0.05,
            )
            .value(
                &format!("{name}_geometric_mean_ratio"),
                geometric_mean,
                "",
                3,
            );
        if name == "carbody_floor_ay_front" {
            let recorded = sperling(
                out.channel(name).unwrap(),
                fs,
                Direction::Lateral,
                &SperlingParams::default(),
            )
            .unwrap();
            println!(
                "W_y: time domain mean {:.3}, linear (expected spectrum) {:.3}",
                recorded.mean, linear.sperling_lateral
            );
        }
    }
    record.check();
}
