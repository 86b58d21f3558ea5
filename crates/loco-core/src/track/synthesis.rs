//! Synthesis of track irregularities from a target spectrum with seeded random phases.
//!
//! Method (the spectral representation of a stationary Gaussian process, Shinozuka & Deodatis,
//! Appl. Mech. Rev. 44(4), 1991): on a periodic grid of N points with step h the irregularity
//! is `x(s) = Σ_k a_k cos(2π f_k s + φ_k)`, `f_k = k / (N h)`, with independent uniform phases
//! φ_k and amplitudes `a_k = √(2 σ_k²)`, where `σ_k²` is the target variance in the cell
//! `[f_k − Δf/2, f_k + Δf/2]` clipped to the band (the cell integral rather than `S(f_k)Δf`
//! keeps the total variance equal to the band integral even where the spectrum is steep).
//! The sum and its derivative `d/ds` come out of one inverse FFT (x in the real part, dx/ds
//! in the imaginary part). The four channels are independent (TB/T 3352-2014 gives no
//! cross-spectra).
//!
//! Reproducibility: phases come from ChaCha20 (`rand_chacha`) seeded with
//! `seed_from_u64(seed)` on stream `stream`, drawn channel by channel (vertical, alignment,
//! cross level, gauge) for k = 1 … N/2 − 1, as `φ = 2π · (next_u64() >> 11) · 2⁻⁵³`: the
//! same (seed, stream, parameters) give the same track bit for bit, and a batch can give run
//! i the stream i.

use super::irregularity::TrackIrregularity;
use super::spectrum::{Channel, TrackSpectrum};
use crate::error::{check_non_negative, check_positive, LocoError, Result};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha20Rng;
use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;

/// Parameters of a synthesised track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SynthesisParams {
    /// Target spectrum.
    pub spectrum: TrackSpectrum,
    /// Length of track to produce, m.
    pub length: f64,
    /// Seed of the random phases.
    pub seed: u64,
    /// ChaCha stream (0 for a single run; the run index in a batch).
    pub stream: u64,
    /// Shortest wavelength synthesised, m (TB/T 3352-2014 is fitted down to 2 m).
    pub wavelength_min: f64,
    /// Longest wavelength synthesised, m (TB/T 3352-2014 is fitted up to 200 m).
    pub wavelength_max: f64,
    /// Grid step, m (20 points per shortest wavelength keeps the cubic interpolation error
    /// below 1e-4 of the amplitude).
    pub step: f64,
    /// Length of the cosine run-in, m.
    pub run_in: f64,
}

impl Default for SynthesisParams {
    fn default() -> Self {
        Self {
            spectrum: TrackSpectrum::CnHsr,
            length: 1000.0,
            seed: 0,
            stream: 0,
            wavelength_min: 2.0,
            wavelength_max: 200.0,
            step: 0.1,
            run_in: 30.0,
        }
    }
}

impl SynthesisParams {
    /// Checks every field, naming the offending one.
    pub fn validate(&self) -> Result<()> {
        check_positive("length", self.length)?;
        check_positive("wavelength_min", self.wavelength_min)?;
        check_positive("wavelength_max", self.wavelength_max)?;
        check_positive("step", self.step)?;
        check_non_negative("run_in", self.run_in)?;
        if self.wavelength_max <= self.wavelength_min {
            return Err(LocoError::param(
                "wavelength_max",
                format!(
                    "must exceed wavelength_min = {} m, got {} m",
                    self.wavelength_min, self.wavelength_max
                ),
            ));
        }
        if self.step > 0.25 * self.wavelength_min {
            return Err(LocoError::param(
                "step",
                format!(
                    "must be at most a quarter of wavelength_min ({} m), got {} m",
                    self.wavelength_min, self.step
                ),
            ));
        }
        let nodes = (self.length / self.step).max(2.0 * self.wavelength_max / self.step);
        if nodes > 5.0e7 {
            return Err(LocoError::param(
                "length",
                format!(
                    "{} m at step {} m needs {nodes:.0} grid points (max 5e7)",
                    self.length, self.step
                ),
            ));
        }
        Ok(())
    }
}

/// Synthesises the four irregularities of `params.length` m of track.
pub fn synthesize(params: &SynthesisParams) -> Result<TrackIrregularity> {
    params.validate()?;
    let nodes = (params.length / params.step).ceil() as usize + 1;
    // A period at least as long as the track and the longest wavelength, so that the band's
    // lowest frequency has a bin; power of two for the FFT.
    let min_period_points = (params.wavelength_max / params.step).ceil() as usize * 2;
    let n = nodes.max(min_period_points).next_power_of_two();
    let period = n as f64 * params.step;
    let df = 1.0 / period;
    let (f_lo, f_hi) = (1.0 / params.wavelength_max, 1.0 / params.wavelength_min);

    let mut rng = ChaCha20Rng::seed_from_u64(params.seed);
    rng.set_stream(params.stream);
    let ifft = FftPlanner::<f64>::new().plan_fft_inverse(n);

    let mut values: [Vec<f64>; 4] = Default::default();
    let mut slopes: [Vec<f64>; 4] = Default::default();
    let mut buffer = vec![Complex64::new(0.0, 0.0); n];
    for channel in Channel::ALL {
        buffer.fill(Complex64::new(0.0, 0.0));
        for k in 1..n / 2 {
            let phase = 2.0 * std::f64::consts::PI * unit_interval(rng.next_u64());
            let f = k as f64 * df;
            let (a, b) = ((f - 0.5 * df).max(f_lo), (f + 0.5 * df).min(f_hi));
            if b <= a {
                continue;
            }
            let variance = params.spectrum.variance_with(channel, a, b, 8);
            let x = Complex64::from_polar(0.5 * (2.0 * variance).sqrt(), phase);
            let d = Complex64::new(0.0, 2.0 * std::f64::consts::PI * f) * x;
            let i = Complex64::new(0.0, 1.0);
            buffer[k] = x + i * d;
            buffer[n - k] = x.conj() + i * d.conj();
        }
        ifft.process(&mut buffer);
        values[channel.index()] = buffer[..nodes].iter().map(|z| z.re).collect();
        slopes[channel.index()] = buffer[..nodes].iter().map(|z| z.im).collect();
    }
    TrackIrregularity::from_channels(
        params.step,
        &values,
        &slopes,
        params.run_in,
        Some(params.spectrum),
    )
}

/// Maps 64 random bits to [0, 1) with 53-bit resolution (documented so that other
/// implementations can reproduce the phases).
fn unit_interval(bits: u64) -> f64 {
    (bits >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::spectral::{welch_psd, WelchParams};

    fn params(length: f64, seed: u64) -> SynthesisParams {
        SynthesisParams {
            length,
            seed,
            run_in: 0.0,
            ..Default::default()
        }
    }

    #[test]
    fn same_seed_same_track_bit_for_bit_and_streams_differ() {
        let a = synthesize(&params(300.0, 7)).unwrap();
        let b = synthesize(&params(300.0, 7)).unwrap();
        assert_eq!(a, b);
        let c = synthesize(&SynthesisParams {
            stream: 1,
            ..params(300.0, 7)
        })
        .unwrap();
        assert_ne!(a.channel(Channel::Vertical), c.channel(Channel::Vertical));
        let d = synthesize(&params(300.0, 8)).unwrap();
        assert_ne!(a.channel(Channel::Vertical), d.channel(Channel::Vertical));
    }

    #[test]
    fn variance_over_a_full_period_is_the_band_integral() {
        // 819.2 m = 8192 points of 0.1 m: exactly one period, so the mean square is Σ a_k²/2.
        for spectrum in [TrackSpectrum::CnHsr, TrackSpectrum::GermanLow] {
            let p = SynthesisParams {
                spectrum,
                length: 819.1,
                ..params(0.0, 3)
            };
            let track = synthesize(&p).unwrap();
            for c in Channel::ALL {
                let x = track.channel(c);
                let ms = x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64;
                let target = spectrum.variance(c, 1.0 / 200.0, 1.0 / 2.0);
                assert!((ms / target - 1.0).abs() < 1e-3, "{c:?}: {ms} vs {target}");
            }
        }
    }

    #[test]
    fn welch_psd_of_a_long_track_matches_the_target() {
        // 40 km, Welch with 4096-point (409.6 m) Hann segments, 50 % overlap: K = 194 averages.
        // One bin scatters by about 1/√K; an octave band of m bins by 1/√(K m) if bins were
        // independent. Taking only K/2 effective averages (overlap, window correlation), the
        // three-sigma tolerance is 3/√(K m / 2): 15 % for the 4-bin lowest octave, 4 % at the top
        // (with 16384-point segments, K = 47, for the longest wavelengths).
        for spectrum in [
            TrackSpectrum::CnHsr,
            TrackSpectrum::GermanLow,
            TrackSpectrum::GermanHigh,
        ] {
            let track = synthesize(&SynthesisParams {
                spectrum,
                length: 40_000.0,
                ..params(0.0, 11)
            })
            .unwrap();
            // 409.6 m segments resolve the middle and the short wavelengths (to 2.1 m, clear
            // of the Hann main lobe at the 2 m cut-off); 1638.4 m segments the long ones, from
            // 154 m (clear of the 200 m cut-off) up.
            let middle = [
                (0.01, 0.02),
                (0.02, 0.04),
                (0.04, 0.08),
                (0.08, 0.16),
                (0.16, 0.32),
                (0.32, 0.48),
            ];
            check_welch_against_target(&track, spectrum, 4096, &middle);
            check_welch_against_target(&track, spectrum, 16384, &[(0.0065, 0.013)]);
        }
    }

    fn check_welch_against_target(
        track: &TrackIrregularity,
        spectrum: TrackSpectrum,
        segment: usize,
        bands: &[(f64, f64)],
    ) {
        let welch = WelchParams {
            segment_len: Some(segment),
            ..Default::default()
        };
        let averages = (track.len() - segment) / (segment / 2) + 1;
        for c in Channel::ALL {
            let psd = welch_psd(&track.channel(c), 1.0 / track.step(), &welch).unwrap();
            for &(a, b) in bands {
                let bins: Vec<usize> = (0..psd.frequency.len())
                    .filter(|&i| psd.frequency[i] >= a && psd.frequency[i] < b)
                    .collect();
                let measured: f64 = bins.iter().map(|&i| psd.density[i]).sum::<f64>();
                let target: f64 = bins
                    .iter()
                    .map(|&i| spectrum.psd(c, psd.frequency[i]))
                    .sum::<f64>();
                let tolerance = 3.0 / ((averages * bins.len()) as f64 / 2.0).sqrt();
                assert!(bins.len() >= 4);
                assert!(
                    (measured / target - 1.0).abs() < tolerance,
                    "{spectrum:?} {c:?} {a:.3}-{b:.3} 1/m: {measured:e} vs {target:e} \
                     (tol {tolerance:.3})"
                );
            }
        }
    }
}
