//! Butterworth filters as cascades of biquads, applied forward and backward (zero phase).
//! Band-pass design: see [`Filter::bandpass`].
//!
//! Design: analogue Butterworth prototype of even order n, sections with
//! `Q_k = 1 / (2 cos(π (2k+1) / (2n)))`, mapped by the bilinear transform with the corner
//! pre-warped (`K = tan(π fc / fs)`), so the digital magnitude is exactly
//! `|H(f)|² = 1 / (1 + (tan(π f / fs) / K)^{2n})` (low-pass; the reciprocal ratio for a
//! high-pass). Zero-phase filtering passes the record forward then backward, so the gain of
//! [`Filter::filtfilt`] is `|H(f)|²` and peaks are not delayed. The record is extended at each end
//! by its odd reflection over three periods of the lowest corner (or the whole record, if
//! shorter), and every section starts in the steady state of the first sample, so the ends
//! carry no start-up transient.

use crate::error::{LocoError, Result};
use rustfft::num_complex::Complex64;

/// One second-order section, transposed direct form II.
#[derive(Debug, Clone, Copy)]
struct Biquad {
    b: [f64; 3],
    /// a1, a2 (a0 = 1).
    a: [f64; 2],
}

impl Biquad {
    /// Gain at zero frequency.
    fn dc_gain(&self) -> f64 {
        (self.b[0] + self.b[1] + self.b[2]) / (1.0 + self.a[0] + self.a[1])
    }

    /// State (z1, z2) of the steady state for a constant input `u`.
    fn steady_state(&self, u: f64) -> [f64; 2] {
        let y = self.dc_gain() * u;
        [y - self.b[0] * u, self.b[2] * u - self.a[1] * y]
    }
}

/// Runs `x` in place through the cascade `sections`, every section starting in the steady
/// state of input `x[0]`. One pass over the samples with all sections inside: the recursions
/// of different sections are independent chains the processor can overlap.
fn run_cascade(sections: &[Biquad], x: &mut [f64]) {
    let Some(&first) = x.first() else { return };
    let mut state = [[0.0f64; 2]; 16];
    let mut u = first;
    for (s, z) in sections.iter().zip(state.iter_mut()) {
        *z = s.steady_state(u);
        u *= s.dc_gain();
    }
    let state = &mut state[..sections.len()];
    for v in x.iter_mut() {
        let mut u = *v;
        for (s, z) in sections.iter().zip(state.iter_mut()) {
            let y = s.b[0] * u + z[0];
            z[0] = s.b[1] * u - s.a[0] * y + z[1];
            z[1] = s.b[2] * u - s.a[1] * y;
            u = y;
        }
        *v = u;
    }
}

/// A Butterworth low-pass, high-pass or band-pass (high-pass then low-pass) filter.
#[derive(Debug, Clone)]
pub struct Filter {
    sections: Vec<Biquad>,
    /// Samples of odd reflection added at each end.
    pad: usize,
}

impl Filter {
    /// Low-pass of even `order` with corner `fc` (Hz) for sampling rate `fs` (Hz).
    pub fn lowpass(fc: f64, fs: f64, order: usize) -> Result<Self> {
        let k = prewarp("fc", fc, fs)?;
        Ok(Self {
            sections: sections(k, order, false)?,
            pad: (3.0 * fs / fc).ceil() as usize,
        })
    }

    /// High-pass of even `order` with corner `fc` (Hz) for sampling rate `fs` (Hz).
    pub fn highpass(fc: f64, fs: f64, order: usize) -> Result<Self> {
        let k = prewarp("fc", fc, fs)?;
        Ok(Self {
            sections: sections(k, order, true)?,
            pad: (3.0 * fs / fc).ceil() as usize,
        })
    }

    /// Butterworth band-pass between `f_lo` and `f_hi` (Hz) from a low-pass prototype of even
    /// `order` (a band-pass of twice that order): the low-pass to band-pass transformation
    /// `s → (s² + Ω0²) / (B s)` with pre-warped corners `Ωl = tan(π f_lo/fs)`,
    /// `Ωh = tan(π f_hi/fs)`, `Ω0² = Ωl Ωh`, `B = Ωh − Ωl`, then the bilinear transform, so
    /// `|H|² = 1 / (1 + ((Ω² − Ω0²) / (Ω B))^{2·order})` with Ω = tan(π f/fs): unit gain at the
    /// centre, −3 dB at both corners (a cascade of a high-pass and a low-pass would lose gain at
    /// the centre of a narrow band such as f0 ± 2 Hz).
    pub fn bandpass(f_lo: f64, f_hi: f64, fs: f64, order: usize) -> Result<Self> {
        if f_hi.is_nan() || f_hi <= f_lo {
            return Err(LocoError::param(
                "f_hi",
                format!("band-pass upper corner {f_hi} Hz must exceed the lower {f_lo} Hz"),
            ));
        }
        let (wl, wh) = (prewarp("f_lo", f_lo, fs)?, prewarp("f_hi", f_hi, fs)?);
        if order == 0 || !order.is_multiple_of(2) || order > 16 {
            return Err(LocoError::param(
                "order",
                format!("must be even, 2 to 16, got {order}"),
            ));
        }
        let (w0_sq, bw) = (wl * wh, wh - wl);
        // Band-pass poles in the upper half plane: each prototype pole p gives the roots of
        // s² − p B s + Ω0² = 0; conjugate prototype poles give the conjugate roots.
        let mut poles = Vec::with_capacity(order);
        for k in 0..order {
            let angle = std::f64::consts::PI * (2 * k + order + 1) as f64 / (2 * order) as f64;
            let p = Complex64::from_polar(1.0, angle);
            let disc = (p * p * bw * bw - 4.0 * w0_sq).sqrt();
            for root in [(p * bw + disc) * 0.5, (p * bw - disc) * 0.5] {
                if root.im > 0.0 {
                    poles.push(root);
                }
            }
        }
        // Analogue sections s / (s² − 2 Re(q) s + |q|²), overall gain set to 1 at Ω0.
        let centre = Complex64::new(0.0, w0_sq.sqrt());
        let mut gain = Complex64::new(1.0, 0.0);
        for q in &poles {
            gain *= centre / (centre * centre - 2.0 * q.re * centre + q.norm_sqr());
        }
        let mut sections: Vec<Biquad> = poles
            .iter()
            .map(|q| bilinear([0.0, 1.0, 0.0], [q.norm_sqr(), -2.0 * q.re]))
            .collect();
        let scale = 1.0 / gain.norm();
        sections[0].b.iter_mut().for_each(|b| *b *= scale);
        Ok(Self {
            sections,
            pad: (3.0 * fs / f_lo).ceil() as usize,
        })
    }

    /// Zero-phase filtering of `x` (gain `|H(f)|²`, no delay); returns a record of equal length.
    pub fn filtfilt(&self, x: &[f64]) -> Vec<f64> {
        let n = x.len();
        if n < 2 {
            return x.to_vec();
        }
        let pad = self.pad.min(n - 1);
        let mut ext = Vec::with_capacity(n + 2 * pad);
        ext.extend((1..=pad).rev().map(|i| 2.0 * x[0] - x[i]));
        ext.extend_from_slice(x);
        ext.extend((1..=pad).map(|i| 2.0 * x[n - 1] - x[n - 1 - i]));
        run_cascade(&self.sections, &mut ext);
        ext.reverse();
        run_cascade(&self.sections, &mut ext);
        ext.reverse();
        ext.drain(..pad);
        ext.truncate(n);
        ext
    }
}

/// Bilinear transform (s = (1 − z⁻¹)/(1 + z⁻¹), frequencies pre-warped) of the analogue
/// section `(b0 + b1 s + b2 s²) / (a0 + a1 s + s²)` given as `[b0, b1, b2]`, `[a0, a1]`.
fn bilinear(b: [f64; 3], a: [f64; 2]) -> Biquad {
    let d0 = 1.0 + a[1] + a[0];
    Biquad {
        b: [
            (b[2] + b[1] + b[0]) / d0,
            2.0 * (b[0] - b[2]) / d0,
            (b[2] - b[1] + b[0]) / d0,
        ],
        a: [2.0 * (a[0] - 1.0) / d0, (1.0 - a[1] + a[0]) / d0],
    }
}

/// `tan(π fc / fs)` after checking 0 < fc < fs/2.
fn prewarp(name: &str, fc: f64, fs: f64) -> Result<f64> {
    crate::error::check_positive("fs", fs)?;
    if !(fc > 0.0 && fc < 0.5 * fs) {
        return Err(LocoError::param(
            name,
            format!("corner must be in (0, fs/2 = {}) Hz, got {fc}", 0.5 * fs),
        ));
    }
    Ok((std::f64::consts::PI * fc / fs).tan())
}

/// Bilinear-transformed Butterworth sections for pre-warped corner `k`.
fn sections(k: f64, order: usize, high: bool) -> Result<Vec<Biquad>> {
    if order == 0 || !order.is_multiple_of(2) || order > 16 {
        return Err(LocoError::param(
            "order",
            format!("must be even, 2 to 16, got {order}"),
        ));
    }
    Ok((0..order / 2)
        .map(|i| {
            let theta = std::f64::consts::PI * (2 * i + 1) as f64 / (2 * order) as f64;
            let q = 1.0 / (2.0 * theta.cos());
            let norm = 1.0 / (1.0 + k / q + k * k);
            let a = [2.0 * (k * k - 1.0) * norm, (1.0 - k / q + k * k) * norm];
            let b = if high {
                [norm, -2.0 * norm, norm]
            } else {
                let b0 = k * k * norm;
                [b0, 2.0 * b0, b0]
            };
            Biquad { b, a }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Amplitude of the f-Hz component of `y` over its middle half, by least squares.
    fn amplitude(y: &[f64], f: f64, fs: f64) -> f64 {
        let (a, b) = (y.len() / 4, 3 * y.len() / 4);
        let (mut s, mut c, mut ss, mut cc, mut sc) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for (j, v) in y.iter().enumerate().take(b).skip(a) {
            let (sj, cj) = (2.0 * PI * f * j as f64 / fs).sin_cos();
            s += v * sj;
            c += v * cj;
            ss += sj * sj;
            cc += cj * cj;
            sc += sj * cj;
        }
        let det = ss * cc - sc * sc;
        let (p, q) = ((s * cc - c * sc) / det, (c * ss - s * sc) / det);
        (p * p + q * q).sqrt()
    }

    fn gain(filter: &Filter, f: f64, fs: f64) -> f64 {
        let x: Vec<f64> = (0..(60.0 * fs) as usize)
            .map(|j| (2.0 * PI * f * j as f64 / fs + 0.4).sin())
            .collect();
        amplitude(&filter.filtfilt(&x), f, fs)
    }

    #[test]
    fn lowpass_gain_matches_the_butterworth_magnitude_squared() {
        let fs = 500.0;
        let filter = Filter::lowpass(10.0, fs, 4).unwrap();
        let k = (PI * 10.0 / fs).tan();
        for f in [1.0, 5.0, 10.0, 14.0, 20.0] {
            let ratio = (PI * f / fs).tan() / k;
            let expected = 1.0 / (1.0 + ratio.powi(8));
            let g = gain(&filter, f, fs);
            assert!((g - expected).abs() < 1e-4, "{f} Hz: {g} vs {expected}");
        }
        // At the corner the zero-phase gain is exactly 1/2 (−3 dB twice).
        assert!((gain(&filter, 10.0, fs) - 0.5).abs() < 1e-4);
    }

    #[test]
    fn bandpass_gain_matches_the_butterworth_band_pass_magnitude_squared() {
        let fs = 500.0;
        let filter = Filter::bandpass(4.0, 8.0, fs, 4).unwrap();
        let (kl, kh) = ((PI * 4.0 / fs).tan(), (PI * 8.0 / fs).tan());
        for f in [2.0, 4.0, 5.0, 6.0, 8.0, 12.0] {
            let t = (PI * f / fs).tan();
            let x = (t * t - kl * kh) / (t * (kh - kl));
            // Zero phase: the amplitude gain is the single-pass |H|².
            let expected = 1.0 / (1.0 + x.powi(8));
            let g = gain(&filter, f, fs);
            assert!((g - expected).abs() < 1e-4, "{f} Hz: {g} vs {expected}");
        }
    }

    #[test]
    fn constant_and_ends_pass_a_lowpass_unchanged() {
        let filter = Filter::lowpass(10.0, 500.0, 4).unwrap();
        let y = filter.filtfilt(&[2.5; 300]);
        assert!(y.iter().all(|v| (v - 2.5).abs() < 1e-9));
        assert!(Filter::lowpass(300.0, 500.0, 4).is_err());
        assert!(Filter::lowpass(10.0, 500.0, 3).is_err());
        assert!(Filter::bandpass(8.0, 4.0, 500.0, 4).is_err());
    }
}
