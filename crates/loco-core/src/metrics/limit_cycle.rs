//! A sustained limit cycle of the bogie frame's lateral acceleration: hunting named by its
//! frequency and amplitude, whether or not its level exceeds a standard's limit. The run metrics
//! apply the same rule to the carbody floor's lateral acceleration, its dominant frequency
//! sought in the carbody band ([`super::summary`]).
//!
//! The rule, on the record `x` of the frame's lateral acceleration:
//!
//! 1. f0 is the dominant frequency (Welch PSD, the stability search band) of the record's last
//!    half: the part where a growing oscillation has settled.
//! 2. `y` is `x` band-passed to f0 ± 2 Hz (the EN 14363 filter of [`super::stability`]).
//! 3. **Narrow band**: over the last half, `y` holds more than half of the power of `x`'s
//!    fluctuation (`share` > 0.5): the oscillation dominates the record.
//! 4. **Sustained**: the rms of `y` over the last quarter is at least 0.8 of the third
//!    quarter's. A free oscillation of damping ratio ζ loses exp(−2π ζ f0 T/4) per quarter of a
//!    record of T s, so 0.8 accepts only ζ ≲ ln 1.25 / (2π f0 T/4): 0.4 % at 4 Hz over 9 s, the
//!    record's resolution of "does not decay".
//! 5. **Steady amplitude**: the peaks of `y`'s cycles (upward zero crossing to the next) in the
//!    last half vary by a coefficient of variation of at most 0.25. A limit cycle has one
//!    amplitude (0 for a sinusoid, a little with the track's excitation on top); the response of
//!    a lightly damped mode to a random track is narrow-band Gaussian, whose cycle peaks are
//!    Rayleigh-distributed with a coefficient of variation of √((4 − π)/π) = 0.52.
//! 6. The last quarter's rms of `y` is at least 0.01 m/s² (below an accelerometer's resolution
//!    there is nothing to name).
//!
//! The amplitude reported is the mean cycle peak of `y` in the last half (a cycle of ±A).

use super::filters::Filter;
use super::spectral::{check_record, welch_psd, WelchParams, MIN_SAMPLES};
use super::stability::{rms, StabilityParams};
use crate::error::Result;

/// Least share of the fluctuation's power in the f0 band (rule 3).
pub const NARROW_BAND_SHARE: f64 = 0.5;
/// Least ratio of the last quarter's rms to the third's (rule 4).
pub const SUSTAINED_RATIO: f64 = 0.8;
/// Largest coefficient of variation of the cycle peaks (rule 5).
pub const STEADY_PEAK_VARIATION: f64 = 0.25;
/// Least rms of the oscillation in the last quarter, m/s² (rule 6).
pub const LEAST_RMS: f64 = 0.01;

/// The dominant oscillation of a record and whether it is a sustained limit cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitCycle {
    /// Whether every rule holds.
    pub detected: bool,
    /// f0, Hz.
    pub frequency: f64,
    /// Mean cycle peak of the band-passed record in the last half, m/s² (a cycle of ±this).
    pub amplitude: f64,
    /// Share of the last half's fluctuation power in the f0 band.
    pub share: f64,
    /// Rms of the last quarter over the third's.
    pub sustained_ratio: f64,
    /// Coefficient of variation of the cycle peaks in the last half.
    pub peak_variation: f64,
}

/// The limit-cycle rule (module doc) on record `x` (m/s²) sampled at `fs` Hz.
pub fn limit_cycle(x: &[f64], fs: f64, params: &StabilityParams) -> Result<LimitCycle> {
    check_record("x", x, fs, 4 * MIN_SAMPLES)?;
    let n = x.len();
    let (half, quarter) = (n / 2, n / 4);
    let last_half = &x[n - half..];
    let psd = welch_psd(last_half, fs, &WelchParams::default())?;
    let dominant = psd.dominant_in(params.f0_min, params.f0_max, "f0_max")?;
    let f0 = dominant.frequency;
    if !f0.is_finite() {
        // No power in the band: nothing oscillates.
        return Ok(LimitCycle {
            detected: false,
            frequency: f64::NAN,
            amplitude: 0.0,
            share: 0.0,
            sustained_ratio: f64::NAN,
            peak_variation: f64::NAN,
        });
    }
    let f_lo = (f0 - params.band_half_width).max(params.band_floor);
    let band = Filter::bandpass(f_lo, f0 + params.band_half_width, fs, params.filter_order)?;
    let y = band.filtfilt(x);
    let mean = last_half.iter().sum::<f64>() / half as f64;
    let fluctuation: f64 = last_half.iter().map(|v| (v - mean).powi(2)).sum();
    let in_band: f64 = y[n - half..].iter().map(|v| v * v).sum();
    let share = if fluctuation > 0.0 {
        in_band / fluctuation
    } else {
        0.0
    };
    let last = rms(&y[n - quarter..]);
    let third = rms(&y[n - 2 * quarter..n - quarter]);
    let sustained_ratio = if third > 0.0 { last / third } else { f64::NAN };
    let peaks = cycle_peaks(&y[n - half..]);
    let (amplitude, peak_variation) = mean_and_variation(&peaks);
    let detected = share > NARROW_BAND_SHARE
        && sustained_ratio >= SUSTAINED_RATIO
        && peak_variation <= STEADY_PEAK_VARIATION
        && last >= LEAST_RMS;
    Ok(LimitCycle {
        detected,
        frequency: f0,
        amplitude,
        share,
        sustained_ratio,
        peak_variation,
    })
}

/// The largest |x| of each whole cycle (upward zero crossing to the next).
fn cycle_peaks(x: &[f64]) -> Vec<f64> {
    let mut peaks = Vec::new();
    let mut peak: Option<f64> = None;
    for j in 1..x.len() {
        if x[j - 1] < 0.0 && x[j] >= 0.0 {
            if let Some(p) = peak {
                peaks.push(p);
            }
            peak = Some(0.0);
        }
        if let Some(p) = peak.as_mut() {
            *p = p.max(x[j].abs());
        }
    }
    peaks
}

/// Mean and coefficient of variation (NaN for fewer than three cycles).
fn mean_and_variation(peaks: &[f64]) -> (f64, f64) {
    if peaks.len() < 3 {
        return (peaks.iter().copied().fold(0.0, f64::max), f64::NAN);
    }
    let k = peaks.len() as f64;
    let mean = peaks.iter().sum::<f64>() / k;
    let var = peaks.iter().map(|p| (p - mean).powi(2)).sum::<f64>() / (k - 1.0);
    let cv = if mean > 0.0 {
        var.sqrt() / mean
    } else {
        f64::NAN
    };
    (mean, cv)
}

#[cfg(test)]
mod tests;
