//! Output spectra of the linearised vehicle on a random track (the classic linear stochastic
//! method): PSDs, rms values and the Sperling index without a time-domain run.
//!
//! - Input spectra: the four irregularity channels of a [`TrackSpectrum`], independent (TB/T
//!   3352-2014 and the German spectra give no cross-spectra; the synthesis draws independent
//!   phases), each limited to the synthesis band of wavelengths `[λ_min, λ_max]` (m) so that the
//!   result is comparable with a run on a synthesised track. A spatial one-sided PSD `S(φ)`
//!   (m²/(1/m), φ = f/V) is seen by the running vehicle as the temporal one-sided PSD
//!   `S(f/V)/V` (m²/Hz).
//! - Output PSD (one-sided, unit²/Hz): `S_z(f) = Σ_c |H_zc(f)|² S_c(f)`, each `H_zc` already
//!   combining the four wheelsets' delayed inputs coherently.
//! - rms: `√∫S_z df` by the trapezoidal rule over the given frequencies (only what the grid
//!   covers is counted).
//! - Sperling index W_y of the carbody floor lateral acceleration ([`CARBODY_LATERAL`]), with the
//!   project's definition ([`crate::metrics::sperling`]) applied to the *expected* spectrum of one
//!   5 s segment: the energy-correct power of bin k (f_k = k/T, T = 5 s) of a Hann-windowed
//!   segment has the expectation `P_k = S_z(f_k)·Δf` (Δf = 1/T) for a spectrum smooth over a
//!   bin; these `P_k` are cut into lines at their local minima exactly as a recorded segment's
//!   (a line's energy E is the sum of its bins' P_k, amplitude `A = √(2E)`, frequency the
//!   power-weighted mean), and combined with the GB/T 5599-2019 weighting. The expected spectrum
//!   is smooth, so its lines are its resolved peaks; a recorded segment's random spectrum splits
//!   the same energy into more, smaller lines, and because A enters cubed its index is lower
//!   (see docs/model/frequency_response.md, the linear stochastic method, for the measured ratio).

use crate::error::{check_positive, LocoError, Result};
use crate::metrics::sperling::segment_index;
use crate::metrics::{Direction, SperlingParams};
use crate::track::{Channel, SynthesisParams, TrackSpectrum};
use crate::vehicle::analysis::frequency_response::{
    check_frequencies, FrequencyResponse, ResponseSolver,
};
use crate::vehicle::analysis::linear_critical_speed::LinearSearch;
use crate::vehicle::analysis::linearise::least_damped;
use crate::vehicle::analysis::track_input::TrackInputModel;
use crate::vehicle::output::run::CARBODY_LATERAL;
use std::sync::atomic::AtomicBool;

/// Settings of the linear stochastic response.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PsdSettings {
    /// Track spectrum of the four channels.
    pub spectrum: TrackSpectrum,
    /// Shortest and longest wavelength of the input band, m (default: the synthesis band,
    /// 2–200 m).
    pub wavelength_min: f64,
    pub wavelength_max: f64,
    /// Factor on the irregularity amplitudes (1: the spectrum as published).
    pub amplitude_scale: f64,
    /// Sperling evaluation (segment length, line frequency range).
    pub sperling: SperlingParams,
}

impl Default for PsdSettings {
    fn default() -> Self {
        let synthesis = SynthesisParams::default();
        Self {
            spectrum: synthesis.spectrum,
            wavelength_min: synthesis.wavelength_min,
            wavelength_max: synthesis.wavelength_max,
            amplitude_scale: 1.0,
            sperling: SperlingParams::default(),
        }
    }
}

impl PsdSettings {
    /// Checks every field, naming the offending one; the wavelengths by the name front ends
    /// give them, `band` = (shortest, longest) m.
    pub fn validate(&self) -> Result<()> {
        check_positive("band[0] (shortest wavelength, m)", self.wavelength_min)?;
        check_positive("band[1] (longest wavelength, m)", self.wavelength_max)?;
        if self.wavelength_max <= self.wavelength_min {
            return Err(LocoError::param(
                "band",
                format!(
                    "({}, {}) m: give (shortest, longest) wavelength, the shortest first and \
                     below the longest",
                    self.wavelength_min, self.wavelength_max
                ),
            ));
        }
        check_positive("amplitude_scale", self.amplitude_scale)?;
        check_positive("segment_duration", self.sperling.segment_duration)?;
        check_positive("f_max", self.sperling.f_max)?;
        Ok(())
    }

    /// Temporal one-sided PSD of `channel` at `f` Hz for speed `v` m/s, m²/Hz (0 outside the
    /// band).
    pub fn input_psd(&self, channel: Channel, f: f64, v: f64) -> f64 {
        let phi = f / v;
        if phi < 1.0 / self.wavelength_max || phi > 1.0 / self.wavelength_min {
            return 0.0;
        }
        self.amplitude_scale.powi(2) * self.spectrum.psd(channel, phi) / v
    }
}

/// Output spectra of the linear model.
#[derive(Debug, Clone, PartialEq)]
pub struct ResponsePsd {
    /// Frequencies, Hz.
    pub frequencies: Vec<f64>,
    /// Output channel names.
    pub outputs: Vec<String>,
    /// `psd[o][f]`, one-sided, unit²/Hz.
    pub psd: Vec<Vec<f64>>,
    /// rms of each output over the frequency grid, unit.
    pub rms: Vec<f64>,
    /// Sperling index W_y of [`CARBODY_LATERAL`] (–).
    pub sperling_lateral: f64,
    /// Damping ratio of the least damped mode in 0.3–20 Hz (–; NaN: no mode there). The
    /// spectra describe the running vehicle only when it is positive (linearly stable).
    pub least_damping_ratio: f64,
}

/// Output PSD of one output of a frequency response (all its inputs summed as independent).
fn output_psd(h: &FrequencyResponse, o: usize, settings: &PsdSettings) -> Vec<f64> {
    (0..h.frequencies.len())
        .map(|fi| {
            let f = h.frequencies[fi];
            h.inputs
                .iter()
                .enumerate()
                .map(|(i, &c)| h.at(o, i, fi).norm_sqr() * settings.input_psd(c, f, h.speed))
                .sum()
        })
        .collect()
}

/// PSDs, rms values and W_y of `outputs` (channel names) at `frequencies` (Hz).
pub fn response_psd(
    model: &TrackInputModel,
    outputs: &[String],
    frequencies: &[f64],
    settings: &PsdSettings,
) -> Result<ResponsePsd> {
    response_psd_cancellable(model, outputs, frequencies, settings, None)
}

/// As [`response_psd`]; `cancel`, when set from another thread, stops it with `Interrupted`
/// before the next frequency of either response it solves.
pub fn response_psd_cancellable(
    model: &TrackInputModel,
    outputs: &[String],
    frequencies: &[f64],
    settings: &PsdSettings,
    cancel: Option<&AtomicBool>,
) -> Result<ResponsePsd> {
    settings.validate()?;
    check_frequencies(frequencies)?;
    let mut solver = ResponseSolver::new(model, outputs)?;
    let h = solver.response_cancellable(&Channel::ALL, frequencies, cancel)?;
    let psd: Vec<Vec<f64>> = (0..outputs.len())
        .map(|o| output_psd(&h, o, settings))
        .collect();
    let rms = psd
        .iter()
        .map(|s| {
            let area: f64 = frequencies
                .windows(2)
                .zip(s.windows(2))
                .map(|(f, p)| 0.5 * (p[0] + p[1]) * (f[1] - f[0]))
                .sum();
            area.abs().sqrt()
        })
        .collect();
    Ok(ResponsePsd {
        frequencies: frequencies.to_vec(),
        outputs: outputs.to_vec(),
        psd,
        rms,
        sperling_lateral: expected_sperling(model, settings, cancel)?,
        least_damping_ratio: least_damped(&model.a, model.n, LinearSearch::default().band)?
            .map_or(f64::NAN, |m| m.damping_ratio),
    })
}

/// W_y from the expected power spectrum of one Sperling segment (see the module doc).
fn expected_sperling(
    model: &TrackInputModel,
    settings: &PsdSettings,
    cancel: Option<&AtomicBool>,
) -> Result<f64> {
    let p = &settings.sperling;
    let df = 1.0 / p.segment_duration;
    // Bins to twice the highest line frequency, so that a line near f_max is cut where a
    // recorded segment's would be (its lobe ends at a minimum above f_max).
    let bins = (2.0 * p.f_max / df).ceil() as usize + 1;
    let frequencies: Vec<f64> = (1..bins).map(|k| k as f64 * df).collect();
    let mut solver = ResponseSolver::new(model, &[CARBODY_LATERAL.to_string()])?;
    let h = solver.response_cancellable(&Channel::ALL, &frequencies, cancel)?;
    let mut power = vec![0.0];
    power.extend(output_psd(&h, 0, settings).iter().map(|s| s * df));
    Ok(segment_index(&power, df, Direction::Lateral, p))
}
