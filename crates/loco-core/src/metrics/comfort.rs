//! Passenger comfort: EN 12299 / ISO 2631-1 frequency-weighted rms and the mean comfort
//! index N_MV of EN 12299:2009.
//!
//! Weightings (analogue transfer functions, s = j 2π f):
//! band limiting `s²/(s² + ω1 s/Q1 + ω1²) · ω2²/(s² + ω2 s/Q1 + ω2²)` with Q1 = 1/√2,
//! acceleration–velocity transition `(1 + s/ω3) / (1 + s/(Q4 ω4) + s²/ω4²)`, upward step
//! `K (1 + s/(Q5 ω5) + s²/ω5²) / (1 + s/(Q6 ω6) + s²/ω6²)`:
//! - Wd (horizontal): f1 = 0.4, f2 = 100, f3 = f4 = 2 Hz, Q4 = 0.63, no step (K = 1);
//! - Wb (vertical, EN 12299): f1 = 0.4, f2 = 100, f3 = f4 = 16 Hz, Q4 = 0.63, f5 = 2.5 Hz,
//!   Q5 = 0.8, f6 = 4 Hz, Q6 = 0.8, K = 0.4.
//!
//! The weighting is applied in the frequency domain on each 5 s block (EN 12299 evaluates
//! 5 s rms values): `a_w² = Σ_lines |W(f_line)|² E_line` over the spectral lines of the block
//! (energy-correct Hann power spectrum split into lobes, as for the Sperling index, see
//! [`super::spectral`]). This is the exact analogue weighting (no bilinear warping near
//! 100 Hz), and a sine is weighted at its own frequency on or off a bin (weighting bin by bin
//! would average |W|² over the ±1.5 bins of the Hann main lobe, 0.3 % low at the Wd maximum).
//! Blocks are placed as for the Sperling index (⌈T/5⌉ blocks spread over the record).
//! `N_MV = 6 √((a_XP95^Wd)² + (a_YP95^Wd)² + (a_ZP95^Wb)²)`, with a_P95 the 95th percentile
//! of the 5 s rms values (linear interpolation between order statistics).

use super::spectral::{check_record, spectral_lines, SegmentSpectrum};
use super::sperling::segment_starts;
use crate::error::{check_positive, LocoError, Result};
use rustfft::num_complex::Complex64;

/// A comfort frequency weighting.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ComfortWeighting {
    /// Horizontal (x, y) weighting Wd.
    Wd,
    /// Vertical (z) weighting Wb of EN 12299.
    Wb,
}

impl ComfortWeighting {
    /// |W(f)| at frequency `f` (Hz), dimensionless.
    pub fn gain(self, f: f64) -> f64 {
        let s = Complex64::new(0.0, 2.0 * std::f64::consts::PI * f);
        let w = |hz: f64| 2.0 * std::f64::consts::PI * hz;
        let q1 = std::f64::consts::FRAC_1_SQRT_2;
        let (w1, w2) = (w(0.4), w(100.0));
        let band =
            s * s / (s * s + s * w1 / q1 + w1 * w1) * (w2 * w2) / (s * s + s * w2 / q1 + w2 * w2);
        let transition = |f3: f64, f4: f64, q4: f64| {
            (1.0 + s / w(f3)) / (1.0 + s / (q4 * w(f4)) + s * s / (w(f4) * w(f4)))
        };
        let h = match self {
            ComfortWeighting::Wd => band * transition(2.0, 2.0, 0.63),
            ComfortWeighting::Wb => {
                let (w5, w6) = (w(2.5), w(4.0));
                let step = 0.4 * (1.0 + s / (0.8 * w5) + s * s / (w5 * w5))
                    / (1.0 + s / (0.8 * w6) + s * s / (w6 * w6));
                band * transition(16.0, 16.0, 0.63) * step
            }
        };
        h.norm()
    }
}

/// Weighted rms of a record, per 5 s block and summarised.
#[derive(Debug, Clone, PartialEq)]
pub struct WeightedRms {
    /// Weighted rms of each 5 s block, m/s².
    pub blocks: Vec<f64>,
    /// Rms over all blocks (root of the mean of the block mean squares), m/s².
    pub rms: f64,
    /// 95th percentile of the block values, m/s².
    pub p95: f64,
}

/// Block length of EN 12299, s.
pub const BLOCK_SECONDS: f64 = 5.0;

/// Frequency-weighted rms of acceleration `acc` (m/s²) sampled at `fs` Hz.
pub fn weighted_rms(acc: &[f64], fs: f64, weighting: ComfortWeighting) -> Result<WeightedRms> {
    check_positive("fs", fs)?;
    // At least 16 samples per block (fs ≥ 3.2 Hz) so that a block has a spectrum.
    let len = ((BLOCK_SECONDS * fs).round() as usize).max(16);
    check_record("acc", acc, fs, len)?;
    let df = fs / len as f64;
    let mut spectrum = SegmentSpectrum::new(len);
    let blocks: Vec<f64> = segment_starts(acc.len(), len)
        .into_iter()
        .map(|s| {
            let mut weighted = 0.0;
            spectral_lines(spectrum.power(&acc[s..s + len]), df, |energy, f| {
                weighted += energy * weighting.gain(f).powi(2);
            });
            weighted.sqrt()
        })
        .collect();
    let rms = (blocks.iter().map(|b| b * b).sum::<f64>() / blocks.len() as f64).sqrt();
    Ok(WeightedRms {
        p95: percentile(&blocks, 0.95),
        rms,
        blocks,
    })
}

/// `q`-quantile (0–1) of `values` by linear interpolation between order statistics.
pub fn percentile(values: &[f64], q: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let pos = q.clamp(0.0, 1.0) * (v.len() - 1) as f64;
    let i = pos.floor() as usize;
    let frac = pos - i as f64;
    if i + 1 < v.len() {
        v[i] + frac * (v[i + 1] - v[i])
    } else {
        v[i]
    }
}

/// N_MV from the 95th percentiles (m/s²) of the weighted 5 s rms values.
pub fn nmv_from_p95(ax_wd: f64, ay_wd: f64, az_wb: f64) -> f64 {
    6.0 * (ax_wd * ax_wd + ay_wd * ay_wd + az_wb * az_wb).sqrt()
}

/// N_MV of floor accelerations (m/s²) sampled at `fs` Hz; absent directions count as zero,
/// at least one must be given.
pub fn comfort_nmv(
    ax: Option<&[f64]>,
    ay: Option<&[f64]>,
    az: Option<&[f64]>,
    fs: f64,
) -> Result<f64> {
    if ax.is_none() && ay.is_none() && az.is_none() {
        return Err(LocoError::input(
            "ay",
            "N_MV needs at least one acceleration",
        ));
    }
    let p95 = |x: Option<&[f64]>, w| -> Result<f64> {
        x.map_or(Ok(0.0), |x| weighted_rms(x, fs, w).map(|r| r.p95))
    };
    Ok(nmv_from_p95(
        p95(ax, ComfortWeighting::Wd)?,
        p95(ay, ComfortWeighting::Wd)?,
        p95(az, ComfortWeighting::Wb)?,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn wd_gain_against_hand_evaluated_transfer_function() {
        // At 2 Hz (ω3 = ω4 = ω): transition = (1 + j)/(1 + j/0.63 − 1) = (1 + j)·0.63/j,
        // |·| = 0.63·√2 = 0.89095; band limiting at 2 Hz: high-pass |s²/(s²+√2ω1 s+ω1²)| with
        // ω1/ω = 0.2: 1/|(1 − 0.04) − j·√2·0.2| = 1/√(0.9216 + 0.08) = 0.99920; low-pass with
        // ω/ω2 = 0.02: 1/√((1−0.0004)² + 0.0008) ≈ 1.00000. Product: 0.89024.
        assert!((ComfortWeighting::Wd.gain(2.0) - 0.89024).abs() < 2e-4);
        // ISO 2631-1:1997 Table 3 tabulates Wd (×1000): 0.5 Hz 853, 1 Hz 1011, 4 Hz 512,
        // 16 Hz 125.
        for (f, table) in [(0.5, 0.853), (1.0, 1.011), (4.0, 0.512), (16.0, 0.125)] {
            assert!(
                (ComfortWeighting::Wd.gain(f) - table).abs() < 1e-3,
                "{f} Hz"
            );
        }
    }

    #[test]
    fn wb_gain_against_hand_evaluated_transfer_function() {
        // At 1 Hz: step 0.4·|0.84 + 0.5j| / |0.9375 + 0.3125j| = 0.4·0.97755/0.98821 = 0.39568;
        // transition |1 + 0.0625j| / |0.99609 + 0.09921j| = 1.00092; high-pass
        // 1/|0.84 − 0.56569j| = 0.98744; low-pass 1.0000. Product 0.39107.
        assert!((ComfortWeighting::Wb.gain(1.0) - 0.39107).abs() < 2e-4);
    }

    #[test]
    fn weighted_rms_of_a_sine_is_gain_times_rms() {
        let fs = 500.0;
        for (w, f) in [
            (ComfortWeighting::Wd, 1.0),
            (ComfortWeighting::Wd, 1.3),
            (ComfortWeighting::Wb, 5.77),
        ] {
            let acc: Vec<f64> = (0..4500)
                .map(|j| 0.4 * (2.0 * PI * f * j as f64 / fs).sin())
                .collect();
            let r = weighted_rms(&acc, fs, w).unwrap();
            let expected = w.gain(f) * 0.4 / 2f64.sqrt();
            for b in &r.blocks {
                assert!(
                    (b / expected - 1.0).abs() < 1e-3,
                    "{w:?}: {b} vs {expected}"
                );
            }
            let nmv = comfort_nmv(None, Some(&acc), None, fs).unwrap();
            if w == ComfortWeighting::Wd {
                assert!((nmv / (6.0 * expected) - 1.0).abs() < 1e-3);
            }
        }
    }

    #[test]
    fn percentile_interpolates() {
        assert_eq!(percentile(&[1.0, 2.0, 3.0, 4.0, 5.0], 0.5), 3.0);
        assert!((percentile(&[0.0, 10.0], 0.95) - 9.5).abs() < 1e-12);
        assert!(comfort_nmv(None, None, None, 100.0).is_err());
    }
}
