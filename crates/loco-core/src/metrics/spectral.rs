//! Spectral estimation shared by the metrics: Welch PSD, dominant frequency, and the
//! energy-correct power spectrum of one record segment.
//!
//! Estimator (documented because every metric built on it depends on it):
//! - window: periodic Hann `w_j = (1 − cos(2π j / N)) / 2`;
//! - each segment has its mean removed before windowing;
//! - scaling: one-sided, energy (power) corrected: `P_k = 2 |X_k|² / (N Σ w_j²)` for
//!   0 < k < N/2 (no factor 2 at DC and Nyquist), so `Σ_k P_k` is the mean square of the
//!   segment; the PSD is `P_k / Δf` with `Δf = fs / N`, in (unit)²/Hz;
//! - Welch: segments of `segment_len` samples with `overlap` (default 50 %), periodograms
//!   averaged; samples after the last full segment are not used.

use crate::error::{check_all_finite, check_positive, LocoError, Result};
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;

/// A window and its normalisation 1/(N Σw²).
type Window = (Rc<[f64]>, f64);

thread_local! {
    /// One planner per thread: plans (twiddles) are cached, so a batch does not re-plan.
    static PLANNER: RefCell<FftPlanner<f64>> = RefCell::new(FftPlanner::new());
    /// Hann windows by length, with 1/(N Σw²), for the same reason.
    static WINDOWS: RefCell<HashMap<usize, Window>> = RefCell::new(HashMap::new());
}

/// The periodic Hann window of length `n` and its normalisation 1/(N Σw²), cached per thread.
fn hann(n: usize) -> Window {
    WINDOWS.with(|w| {
        w.borrow_mut()
            .entry(n)
            .or_insert_with(|| {
                let window: Rc<[f64]> = (0..n)
                    .map(|j| 0.5 * (1.0 - (2.0 * std::f64::consts::PI * j as f64 / n as f64).cos()))
                    .collect();
                let sum_sq: f64 = window.iter().map(|w| w * w).sum();
                (window, 1.0 / (n as f64 * sum_sq))
            })
            .clone()
    })
}

/// The forward FFT of length `n`, from this thread's plan cache.
pub(crate) fn forward_fft(n: usize) -> Arc<dyn Fft<f64>> {
    PLANNER.with(|p| p.borrow_mut().plan_fft_forward(n))
}

/// Checks a record: `fs` positive and finite, at least `min_len` samples, no NaN or infinity.
pub fn check_record(name: &str, x: &[f64], fs: f64, min_len: usize) -> Result<()> {
    check_positive("fs", fs)?;
    if x.len() < min_len {
        return Err(LocoError::input(
            name,
            format!(
                "record too short: {} samples ({:.3} s at {fs} Hz), needs at least {min_len}",
                x.len(),
                x.len() as f64 / fs
            ),
        ));
    }
    check_all_finite(name, x)
}

/// Welch PSD parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WelchParams {
    /// Samples per segment; default: the largest power of two not above half the record
    /// (at least three segments with 50 % overlap), capped at the record length.
    pub segment_len: Option<usize>,
    /// Fraction of a segment shared with the next one, in [0, 1).
    pub overlap: f64,
}

impl Default for WelchParams {
    fn default() -> Self {
        Self {
            segment_len: None,
            overlap: 0.5,
        }
    }
}

/// A one-sided power spectral density.
#[derive(Debug, Clone, PartialEq)]
pub struct Psd {
    /// Frequencies of the bins, Hz (or 1/m for a record in space), from 0 to fs/2.
    pub frequency: Vec<f64>,
    /// Density, (unit of the record)²/Hz.
    pub density: Vec<f64>,
}

/// The frequency where a PSD peaks and its value there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dominant {
    /// Frequency, Hz, refined between bins by fitting a parabola to ln PSD at the peak bin
    /// and its neighbours (exact for a Gaussian-shaped peak, close for a Hann main lobe).
    pub frequency: f64,
    /// PSD at the peak bin, (unit)²/Hz.
    pub peak_density: f64,
}

/// Shortest record the spectral functions accept, samples.
pub const MIN_SAMPLES: usize = 16;

/// Welch PSD of record `x` sampled at `fs` Hz (see the module doc for the estimator).
pub fn welch_psd(x: &[f64], fs: f64, params: &WelchParams) -> Result<Psd> {
    check_record("x", x, fs, MIN_SAMPLES)?;
    if !(0.0..1.0).contains(&params.overlap) {
        return Err(LocoError::param(
            "overlap",
            format!("must be in [0, 1), got {}", params.overlap),
        ));
    }
    let n = match params.segment_len {
        Some(n) if n < 8 || n > x.len() => {
            return Err(LocoError::param(
                "segment_len",
                format!("must be in [8, {}] (the record length), got {n}", x.len()),
            ))
        }
        Some(n) => n,
        None => default_segment_len(x.len()),
    };
    let hop = (((1.0 - params.overlap) * n as f64).round() as usize).max(1);
    let mut power = vec![0.0; n / 2 + 1];
    let mut scratch = SegmentSpectrum::new(n);
    let mut count = 0usize;
    let mut start = 0;
    while start + n <= x.len() {
        let p = scratch.power(&x[start..start + n]);
        power.iter_mut().zip(p).for_each(|(acc, v)| *acc += v);
        count += 1;
        start += hop;
    }
    let df = fs / n as f64;
    let scale = 1.0 / (count as f64 * df);
    Ok(Psd {
        frequency: (0..power.len()).map(|k| k as f64 * df).collect(),
        density: power.iter().map(|p| p * scale).collect(),
    })
}

/// Default Welch segment: largest power of two ≤ len/2, at least 8, at most len.
fn default_segment_len(len: usize) -> usize {
    let half = (len / 2).max(8);
    let pow = if half.is_power_of_two() {
        half
    } else {
        half.next_power_of_two() / 2
    };
    pow.clamp(8, len)
}

impl Psd {
    /// [`Self::dominant`], or an error naming `field` (the setting that gave `f_max`) when no
    /// bin lies in the range.
    pub fn dominant_in(&self, f_min: f64, f_max: f64, field: &str) -> Result<Dominant> {
        self.dominant(f_min, f_max).ok_or_else(|| {
            let resolution = self.frequency.get(1).copied().unwrap_or(0.0);
            let nyquist = self.frequency.last().copied().unwrap_or(0.0);
            LocoError::param(
                field,
                format!(
                    "no PSD bin between {f_min} and {f_max} Hz (resolution {resolution} Hz, \
                     Nyquist {nyquist} Hz)"
                ),
            )
        })
    }

    /// The peak of the PSD between `f_min` and `f_max` (Hz, inclusive), DC excluded; `None`
    /// when no bin lies in the range.
    pub fn dominant(&self, f_min: f64, f_max: f64) -> Option<Dominant> {
        let candidates = (1..self.frequency.len())
            .filter(|&k| self.frequency[k] >= f_min && self.frequency[k] <= f_max);
        let k = candidates.max_by(|&a, &b| self.density[a].total_cmp(&self.density[b]))?;
        if self.density[k] <= 0.0 {
            // A signal without power in the band (e.g. a vehicle at rest) has no dominant
            // frequency; the last bin the search happened to keep would be a made-up answer.
            return Some(Dominant {
                frequency: f64::NAN,
                peak_density: 0.0,
            });
        }
        let df = self.frequency.get(1).copied().unwrap_or(0.0);
        let mut frequency = self.frequency[k];
        if k >= 1 && k + 1 < self.density.len() {
            let (l, c, r) = (self.density[k - 1], self.density[k], self.density[k + 1]);
            if l > 0.0 && c > 0.0 && r > 0.0 {
                let (l, c, r) = (l.ln(), c.ln(), r.ln());
                let denom = l - 2.0 * c + r;
                if denom < 0.0 {
                    frequency += (0.5 * (l - r) / denom).clamp(-0.5, 0.5) * df;
                }
            }
        }
        Some(Dominant {
            frequency,
            peak_density: self.density[k],
        })
    }
}

/// Dominant frequency of `x` (Hz) between `f_min` and `f_max` and its Welch PSD peak.
pub fn dominant_frequency(
    x: &[f64],
    fs: f64,
    f_min: f64,
    f_max: f64,
    params: &WelchParams,
) -> Result<Dominant> {
    welch_psd(x, fs, params)?.dominant_in(f_min, f_max, "f_max")
}

/// Splits a one-sided power spectrum (`power[k]` at `k·df`, k ≥ 1; DC ignored) into lines:
/// lobes between local minima, each reported once as `line(energy, frequency)` with its summed
/// power (unit²) and power-weighted mean frequency (Hz). The leakage of a sine, which decreases
/// monotonically away from its peak for a Hann window, stays in its lobe, so a sine is one line
/// of energy A²/2 at its own frequency, on or off a bin.
pub(crate) fn spectral_lines(power: &[f64], df: f64, mut line: impl FnMut(f64, f64)) {
    let (mut energy, mut moment) = (0.0, 0.0);
    let mut emit = |energy: f64, moment: f64| {
        if energy > 0.0 {
            line(energy, moment / energy);
        }
    };
    for k in 1..power.len() {
        let is_minimum =
            k > 1 && k + 1 < power.len() && power[k] <= power[k - 1] && power[k] < power[k + 1];
        if is_minimum {
            emit(energy, moment);
            energy = 0.0;
            moment = 0.0;
        }
        energy += power[k];
        moment += power[k] * k as f64 * df;
    }
    emit(energy, moment);
}

/// Reusable buffers for the energy-correct one-sided power spectrum of fixed-length segments.
pub(crate) struct SegmentSpectrum {
    window: Rc<[f64]>,
    /// 1 / (N Σ w²).
    norm: f64,
    fft: Arc<dyn Fft<f64>>,
    buffer: Vec<Complex64>,
    scratch: Vec<Complex64>,
    power: Vec<f64>,
}

impl SegmentSpectrum {
    /// Buffers for segments of `n` samples.
    pub(crate) fn new(n: usize) -> Self {
        let (window, norm) = hann(n);
        let fft = forward_fft(n);
        let scratch = vec![Complex64::new(0.0, 0.0); fft.get_inplace_scratch_len()];
        Self {
            norm,
            window,
            fft,
            buffer: vec![Complex64::new(0.0, 0.0); n],
            scratch,
            power: vec![0.0; n / 2 + 1],
        }
    }

    /// Power per bin `P_k` (unit², k = 0 … N/2) of `segment` (length N): mean removed, Hann
    /// window, `Σ P_k` = mean square of the segment.
    pub(crate) fn power(&mut self, segment: &[f64]) -> &[f64] {
        let n = self.window.len();
        let mean = segment.iter().sum::<f64>() / n as f64;
        for ((b, &x), &w) in self.buffer.iter_mut().zip(segment).zip(self.window.iter()) {
            *b = Complex64::new((x - mean) * w, 0.0);
        }
        self.fft
            .process_with_scratch(&mut self.buffer, &mut self.scratch);
        for (k, p) in self.power.iter_mut().enumerate() {
            let edge = k == 0 || (n.is_multiple_of(2) && k == n / 2);
            let factor = if edge { 1.0 } else { 2.0 };
            *p = factor * self.buffer[k].norm_sqr() * self.norm;
        }
        &self.power
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn sine(a: f64, f: f64, fs: f64, n: usize) -> Vec<f64> {
        (0..n)
            .map(|j| a * (2.0 * PI * f * j as f64 / fs + 0.3).sin())
            .collect()
    }

    #[test]
    fn a_silent_signal_has_no_dominant_frequency() {
        let d =
            dominant_frequency(&[0.0; 4096], 500.0, 0.2, 20.0, &WelchParams::default()).unwrap();
        assert!(d.frequency.is_nan());
        assert_eq!(d.peak_density, 0.0);
    }

    #[test]
    fn psd_integrates_to_the_mean_square_of_a_sine() {
        // A² / 2 = 0.5 for A = 1, on or off a bin.
        for f in [4.0, 4.1, 7.33] {
            let psd =
                welch_psd(&sine(1.0, f, 200.0, 8000), 200.0, &WelchParams::default()).unwrap();
            let df = psd.frequency[1];
            let ms: f64 = psd.density.iter().sum::<f64>() * df;
            assert!((ms - 0.5).abs() < 2e-3, "f = {f}: {ms}");
        }
    }

    #[test]
    fn white_noise_psd_level() {
        // Uniform noise in [-1, 1): variance 1/3, flat PSD (1/3)/(fs/2).
        let mut state = 12345u64;
        let x: Vec<f64> = (0..65536)
            .map(|_| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
            })
            .collect();
        let psd = welch_psd(
            &x,
            100.0,
            &WelchParams {
                segment_len: Some(256),
                overlap: 0.5,
            },
        )
        .unwrap();
        let mean: f64 = psd.density[5..120].iter().sum::<f64>() / 115.0;
        assert!((mean / (1.0 / 3.0 / 50.0) - 1.0).abs() < 0.03, "{mean}");
    }

    #[test]
    fn dominant_frequency_between_bins() {
        let fs = 500.0;
        let x = sine(0.7, 6.37, fs, 4500);
        let d = dominant_frequency(&x, fs, 0.5, 20.0, &WelchParams::default()).unwrap();
        // Resolution 500/2048 = 0.244 Hz; the log-parabola lands within a tenth of a bin.
        assert!((d.frequency - 6.37).abs() < 0.025, "{}", d.frequency);
        assert!(d.peak_density > 0.0);
    }

    #[test]
    fn bad_records_are_named_errors() {
        let err = welch_psd(&[1.0; 10], 100.0, &WelchParams::default()).unwrap_err();
        assert!(err.to_string().contains("too short"));
        let mut x = vec![0.0; 100];
        x[40] = f64::NAN;
        assert!(welch_psd(&x, 100.0, &WelchParams::default())
            .unwrap_err()
            .to_string()
            .contains("element 40"));
        assert!(welch_psd(&[0.0; 100], 0.0, &WelchParams::default())
            .unwrap_err()
            .to_string()
            .contains("fs"));
        assert!(welch_psd(&[0.0; 100], -5.0, &WelchParams::default()).is_err());
    }
}
