//! Bogie frame lateral acceleration statistics used to judge running stability.
//!
//! - Peak of the 10 Hz low-passed acceleration, and the GB/T 5599-2019 criterion: the bogie is
//!   flagged unstable when the low-passed peaks reach 8 m/s² in 6 or more consecutive cycles
//!   (a cycle runs from one upward zero crossing to the next; its peak is its largest |a|).
//! - EN 14363:2016 simplified criterion: band-pass f0 ± 2 Hz around the instability frequency
//!   f0 (taken as the dominant frequency of the record), sliding rms over 100 m of track in
//!   steps of 10 m, limit `(12 − m⁺/5) / 2` m/s² with the bogie mass m⁺ in tonnes.
//!
//! Filters are zero-phase Butterworth (see [`super::filters`]).

use super::filters::Filter;
use super::spectral::{check_record, WelchParams, MIN_SAMPLES};
use crate::error::{check_positive, LocoError, Result};

/// Parameters of the bogie stability statistics (defaults: the standards' values).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StabilityParams {
    /// Low-pass corner for the peak statistics, Hz (GB/T 5599-2019: 10 Hz).
    pub lowpass_hz: f64,
    /// Order of each Butterworth filter (even).
    pub filter_order: usize,
    /// GB/T peak limit, m/s².
    pub gbt_limit: f64,
    /// Consecutive cycles at or above the limit that flag instability.
    pub gbt_cycles: usize,
    /// Search band for the instability frequency f0, Hz.
    pub f0_min: f64,
    /// Search band for the instability frequency f0, Hz.
    pub f0_max: f64,
    /// Half width of the EN 14363 band-pass, Hz.
    pub band_half_width: f64,
    /// Lowest lower corner of the band-pass, Hz (when f0 − half width falls below it).
    pub band_floor: f64,
    /// Sliding rms window, m of track.
    pub window_m: f64,
    /// Sliding rms step, m of track.
    pub step_m: f64,
}

impl Default for StabilityParams {
    fn default() -> Self {
        Self {
            lowpass_hz: 10.0,
            filter_order: 4,
            gbt_limit: 8.0,
            gbt_cycles: 6,
            f0_min: 1.0,
            f0_max: 15.0,
            band_half_width: 2.0,
            band_floor: 0.5,
            window_m: 100.0,
            step_m: 10.0,
        }
    }
}

/// Bogie frame lateral acceleration statistics of one record.
#[derive(Debug, Clone, PartialEq)]
pub struct BogieStability {
    /// Largest |a| of the low-passed acceleration, m/s².
    pub peak_lowpassed: f64,
    /// Rms of the low-passed acceleration, m/s².
    pub rms_lowpassed: f64,
    /// Longest run of consecutive cycles with a low-passed peak ≥ the GB/T limit.
    pub max_consecutive_cycles: usize,
    /// GB/T flag: `max_consecutive_cycles ≥ gbt_cycles`.
    pub gbt_unstable: bool,
    /// Instability frequency f0 (dominant frequency of the record in the search band), Hz.
    pub f0: f64,
    /// Welch PSD of the record at f0, (m/s²)²/Hz.
    pub f0_psd_peak: f64,
    /// Largest sliding rms of the band-passed acceleration, m/s².
    pub sliding_rms_max: f64,
    /// EN 14363 limit `(12 − m⁺/5) / 2`, m/s².
    pub limit: f64,
    /// EN 14363 flag: `sliding_rms_max > limit`.
    pub en_unstable: bool,
    /// Window used for the sliding rms, m (shorter than asked when the record is shorter).
    pub window_m: f64,
}

/// EN 14363 simplified limit `(12 − m/5)/2` m/s² for a bogie of `bogie_mass` kg.
pub fn en14363_limit(bogie_mass: f64) -> Result<f64> {
    check_positive("bogie_mass", bogie_mass)?;
    let limit = 0.5 * (12.0 - bogie_mass / 1000.0 / 5.0);
    if limit <= 0.0 {
        return Err(LocoError::param(
            "bogie_mass",
            format!("{bogie_mass} kg leaves no positive EN 14363 limit (needs < 60 t)"),
        ));
    }
    Ok(limit)
}

/// Stability statistics of bogie frame lateral acceleration `acc` (m/s²) sampled at `fs`
/// Hz, running at `speed` m/s, for a bogie of `bogie_mass` kg.
pub fn bogie_stability(
    acc: &[f64],
    fs: f64,
    speed: f64,
    bogie_mass: f64,
    params: &StabilityParams,
) -> Result<BogieStability> {
    check_record("acc", acc, fs, MIN_SAMPLES)?;
    check_positive("speed", speed)?;
    check_positive("window_m", params.window_m)?;
    check_positive("step_m", params.step_m)?;
    let limit = en14363_limit(bogie_mass)?;

    let low = Filter::lowpass(params.lowpass_hz, fs, params.filter_order)?.filtfilt(acc);
    let peak_lowpassed = low.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let rms_lowpassed = rms(&low);
    let max_consecutive_cycles = longest_run_of_cycles(&low, params.gbt_limit);

    let psd = super::spectral::welch_psd(acc, fs, &WelchParams::default())?;
    let dominant = psd.dominant_in(params.f0_min, params.f0_max, "f0_max")?;
    let f0 = dominant.frequency;
    let f_lo = (f0 - params.band_half_width).max(params.band_floor);
    let band = Filter::bandpass(f_lo, f0 + params.band_half_width, fs, params.filter_order)?;
    let passed = band.filtfilt(acc);

    let samples_per_m = fs / speed;
    let window = ((params.window_m * samples_per_m).round() as usize).clamp(1, acc.len());
    let step = ((params.step_m * samples_per_m).round() as usize).max(1);
    let sliding_rms_max = sliding_rms_max(&passed, window, step);

    Ok(BogieStability {
        peak_lowpassed,
        rms_lowpassed,
        max_consecutive_cycles,
        gbt_unstable: max_consecutive_cycles >= params.gbt_cycles,
        f0,
        f0_psd_peak: dominant.peak_density,
        sliding_rms_max,
        limit,
        en_unstable: sliding_rms_max > limit,
        window_m: window as f64 / samples_per_m,
    })
}

/// Root mean square of `x`.
pub fn rms(x: &[f64]) -> f64 {
    if x.is_empty() {
        return 0.0;
    }
    (x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64).sqrt()
}

/// Longest run of consecutive cycles (upward zero crossing to the next) whose largest |x|
/// reaches `limit`. The part before the first and after the last crossing is not a cycle.
pub fn longest_run_of_cycles(x: &[f64], limit: f64) -> usize {
    let (mut best, mut run) = (0usize, 0usize);
    let mut cycle_peak: Option<f64> = None;
    for j in 1..x.len() {
        if x[j - 1] < 0.0 && x[j] >= 0.0 {
            if let Some(peak) = cycle_peak {
                run = if peak >= limit { run + 1 } else { 0 };
                best = best.max(run);
            }
            cycle_peak = Some(0.0);
        }
        if let Some(peak) = cycle_peak.as_mut() {
            *peak = peak.max(x[j].abs());
        }
    }
    best
}

/// Largest rms over windows of `window` samples starting every `step` samples (the last
/// window ends at the record's end).
fn sliding_rms_max(x: &[f64], window: usize, step: usize) -> f64 {
    let mut prefix = Vec::with_capacity(x.len() + 1);
    prefix.push(0.0);
    let mut acc = 0.0;
    for v in x {
        acc += v * v;
        prefix.push(acc);
    }
    let ms = |start: usize| (prefix[start + window] - prefix[start]) / window as f64;
    let last = x.len() - window;
    let best = (0..=last).step_by(step).map(ms).fold(ms(last), f64::max);
    best.max(0.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn limit_formula() {
        // m⁺ = 5 t: (12 − 1)/2 = 5.5 m/s².
        assert!((en14363_limit(5000.0).unwrap() - 5.5).abs() < 1e-12);
        assert!(en14363_limit(60_000.0).is_err());
        assert!(en14363_limit(-1.0).is_err());
    }

    #[test]
    fn hunting_sine_is_flagged_by_both_criteria() {
        // 9 m/s² at 6 Hz for 9 s at 55.6 m/s: the band-pass (unit gain at its centre) keeps the
        // sine, rms 9/√2 = 6.36 m/s² > 5.5.
        let fs = 500.0;
        let acc: Vec<f64> = (0..4500)
            .map(|j| 9.0 * (2.0 * PI * 6.0 * j as f64 / fs).sin())
            .collect();
        let s = bogie_stability(&acc, fs, 55.6, 5000.0, &StabilityParams::default()).unwrap();
        assert!((s.f0 - 6.0).abs() < 0.03, "{}", s.f0);
        // Zero-phase 4th-order Butterworth at 10 Hz: gain 1/(1 + (tan(π6/fs)/tan(π10/fs))⁸).
        let ratio = (PI * 6.0 / fs).tan() / (PI * 10.0 / fs).tan();
        let expected = 9.0 / (1.0 + ratio.powi(8));
        assert!(
            (s.peak_lowpassed - expected).abs() < 0.01,
            "{} vs {expected}",
            s.peak_lowpassed
        );
        assert!(s.max_consecutive_cycles >= 50 && s.gbt_unstable, "{s:?}");
        // The 100 m window (1.8 s) holds 10.8 cycles, not a whole number: the windowed rms of
        // a sine then varies by up to 1/(4π·10.8) ≈ 0.7 % around A/√2 and the maximum is taken.
        let expected = 9.0 / 2f64.sqrt();
        assert!(
            (s.sliding_rms_max / expected - 1.0).abs() < 0.01,
            "{}",
            s.sliding_rms_max
        );
        assert!(s.en_unstable);
        assert!((s.window_m - 100.0).abs() < 0.2);
    }

    #[test]
    fn small_vibration_is_stable() {
        let fs = 500.0;
        let acc: Vec<f64> = (0..4500)
            .map(|j| 2.0 * (2.0 * PI * 3.0 * j as f64 / fs).sin())
            .collect();
        let s = bogie_stability(&acc, fs, 55.6, 5000.0, &StabilityParams::default()).unwrap();
        assert_eq!(s.max_consecutive_cycles, 0);
        assert!(!s.gbt_unstable && !s.en_unstable);
    }

    #[test]
    fn consecutive_cycles_are_counted() {
        // Four cycles of amplitude 10, then one of 1, then two of 10 (the last, unclosed, is no cycle).
        let mut x = vec![-1.0];
        for amp in [10.0, 10.0, 10.0, 10.0, 1.0, 10.0, 10.0, 0.5] {
            x.extend((0..20).map(|j| amp * (2.0 * PI * j as f64 / 20.0 + 0.01).sin()));
        }
        assert_eq!(longest_run_of_cycles(&x, 8.0), 4);
    }
}
