//! Sperling ride index per GB/T 5599-2019 and its rating bands for a locomotive.
//!
//! Per spectral line of amplitude A (m/s², peak) at frequency f (Hz):
//! `W = 3.57 · (A³ · F(f) / f)^(1/10)`, lines combined as `W = (Σ W_i¹⁰)^(1/10)`, with the
//! frequency weighting F of GB/T 5599-2019:
//! - lateral: `0.8 f²` (0.5–5.4 Hz), `650 / f²` (5.4–26 Hz), 1 above 26 Hz;
//! - vertical: `0.325 f²` (0.5–5.9 Hz), `400 / f²` (5.9–20 Hz), 1 above 20 Hz.
//!
//! The index is evaluated on 5 s segments (GB/T 5599-2019 shortened the analysis length from
//! 18–20 s to 5 s, as in UIC 513). Because A enters cubed, the value depends on how a
//! spectrum is cut into lines (Zhang, Zhou, Sun et al., "Analysis of consistency of ride
//! quality evaluation algorithm for railway vehicles", J. Tongji Univ. 51(9), 2023): with
//! one line per FFT bin a sine between two bins leaks into several lines and its index drops by
//! up to ~6 %. We therefore define the lines as *spectral peaks*:
//!
//! 1. segment: mean removed, periodic Hann window, energy-correct one-sided power `P_k`
//!    (`Σ P_k` = mean square, see [`super::spectral`]);
//! 2. the bins are split into lobes at the local minima of `P_k`; a lobe is one line with
//!    power `E = Σ P_k` (so `A = √(2E)`, the leakage of a sine is summed back into it) at the
//!    power-weighted mean frequency of the lobe;
//! 3. lines whose frequency lies in [f_min, f_max] (default 0.5–40 Hz, the range of the
//!    weighting tables) are combined.
//!
//! For a pure sine this gives the formula's value on or off a bin (checked in the tests); for
//! broadband responses a line is a resolved spectral peak.
//!
//! Segments: a record of T s gets ⌈T/5⌉ segments of 5 s spread evenly from its start to its
//! end (overlapping when T is not a multiple of 5 s), so that no sample is discarded.

use super::spectral::{check_record, spectral_lines, SegmentSpectrum};
use crate::error::{check_positive, LocoError, Result};

/// Direction of a carbody acceleration, selecting the Sperling weighting.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// Lateral (y).
    Lateral,
    /// Vertical (z).
    Vertical,
}

impl Direction {
    /// Parses `lateral` or `vertical`.
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "lateral" => Ok(Direction::Lateral),
            "vertical" => Ok(Direction::Vertical),
            _ => Err(LocoError::param(
                "direction",
                format!("must be `lateral` or `vertical`, got `{name}`"),
            )),
        }
    }
}

/// GB/T 5599-2019 frequency weighting F(f) (dimensionless) at f Hz.
pub fn sperling_weighting(direction: Direction, f: f64) -> f64 {
    let (k_low, f_knee, k_high, f_flat) = match direction {
        Direction::Lateral => (0.8, 5.4, 650.0, 26.0),
        Direction::Vertical => (0.325, 5.9, 400.0, 20.0),
    };
    if f < f_knee {
        k_low * f * f
    } else if f < f_flat {
        k_high / (f * f)
    } else {
        1.0
    }
}

/// Sperling index of one line of amplitude `a` (m/s², peak) at `f` Hz.
pub fn sperling_line(direction: Direction, a: f64, f: f64) -> f64 {
    3.57 * (a.powi(3) * sperling_weighting(direction, f) / f).powf(0.1)
}

/// Parameters of the Sperling evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SperlingParams {
    /// Segment length, s.
    pub segment_duration: f64,
    /// Lowest line frequency included, Hz.
    pub f_min: f64,
    /// Highest line frequency included, Hz.
    pub f_max: f64,
}

impl Default for SperlingParams {
    fn default() -> Self {
        Self {
            segment_duration: 5.0,
            f_min: 0.5,
            f_max: 40.0,
        }
    }
}

/// Sperling indices of a record.
#[derive(Debug, Clone, PartialEq)]
pub struct Sperling {
    /// Index of each 5 s segment, in time order.
    pub segments: Vec<f64>,
    /// Mean of the segment indices.
    pub mean: f64,
    /// Largest segment index.
    pub max: f64,
}

/// Sperling ride index of acceleration `acc` (m/s²) sampled at `fs` Hz.
pub fn sperling(
    acc: &[f64],
    fs: f64,
    direction: Direction,
    params: &SperlingParams,
) -> Result<Sperling> {
    check_positive("fs", fs)?;
    check_positive("segment_duration", params.segment_duration)?;
    check_positive("f_min", params.f_min)?;
    check_positive("f_max", params.f_max)?;
    let len = (params.segment_duration * fs).round() as usize;
    if len < 16 {
        return Err(LocoError::param(
            "segment_duration",
            format!(
                "{} s at {fs} Hz gives {len} samples per segment, needs at least 16",
                params.segment_duration
            ),
        ));
    }
    check_record("acc", acc, fs, len)?;
    let starts = segment_starts(acc.len(), len);
    let mut spectrum = SegmentSpectrum::new(len);
    let df = fs / len as f64;
    let segments: Vec<f64> = starts
        .iter()
        .map(|&s| {
            let power = spectrum.power(&acc[s..s + len]);
            segment_index(power, df, direction, params)
        })
        .collect();
    let mean = segments.iter().sum::<f64>() / segments.len() as f64;
    let max = segments.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    Ok(Sperling {
        segments,
        mean,
        max,
    })
}

/// Starts of ⌈n / len⌉ segments of `len` samples spread evenly over `n` samples.
pub(crate) fn segment_starts(n: usize, len: usize) -> Vec<usize> {
    let count = n.div_ceil(len);
    if count <= 1 {
        return vec![0];
    }
    let span = (n - len) as f64;
    (0..count)
        .map(|i| (i as f64 * span / (count - 1) as f64).round() as usize)
        .collect()
}

/// Combined index of one segment from its power per bin.
pub(crate) fn segment_index(
    power: &[f64],
    df: f64,
    direction: Direction,
    params: &SperlingParams,
) -> f64 {
    let mut sum_w10 = 0.0;
    spectral_lines(power, df, |energy, f| {
        if f >= params.f_min && f <= params.f_max {
            let a = (2.0 * energy).sqrt();
            // W¹⁰ = 3.57¹⁰ · A³ F / f, summed without the 1/10 power per line.
            sum_w10 += 3.57f64.powi(10) * a.powi(3) * sperling_weighting(direction, f) / f;
        }
    });
    sum_w10.powf(0.1)
}

/// Ride quality grade of a locomotive by its Sperling index (GB/T 5599-2019 bands for
/// locomotives: excellent < 2.75, good < 3.10, acceptable < 3.45).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RideRating {
    /// W < 2.75.
    Excellent,
    /// 2.75 ≤ W < 3.10.
    Good,
    /// 3.10 ≤ W < 3.45.
    Acceptable,
    /// W ≥ 3.45 (or NaN).
    Unacceptable,
}

impl RideRating {
    /// Grade of a locomotive with Sperling index `w`.
    pub fn locomotive(w: f64) -> Self {
        if w < 2.75 {
            RideRating::Excellent
        } else if w < 3.10 {
            RideRating::Good
        } else if w < 3.45 {
            RideRating::Acceptable
        } else {
            RideRating::Unacceptable
        }
    }

    /// Lower-case name: `excellent`, `good`, `acceptable`, `unacceptable`.
    pub fn name(self) -> &'static str {
        match self {
            RideRating::Excellent => "excellent",
            RideRating::Good => "good",
            RideRating::Acceptable => "acceptable",
            RideRating::Unacceptable => "unacceptable",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn sine(a: f64, f: f64, fs: f64, seconds: f64) -> Vec<f64> {
        let n = (seconds * fs).round() as usize;
        (0..n)
            .map(|j| a * (2.0 * PI * f * j as f64 / fs + 1.1).sin())
            .collect()
    }

    #[test]
    fn single_sines_give_the_hand_worked_formula_value() {
        // Hand values, W = 3.57 (A³ F(f) / f)^0.1:
        // lateral, A = 0.3, f = 1.2 Hz (on a 0.2 Hz bin): F = 0.8·1.44 = 1.152,
        //   A³F/f = 0.027·1.152/1.2 = 0.02592, ^0.1 = 0.69401, W = 2.4776;
        // lateral, A = 0.3, f = 1.3 Hz (half a bin off): F = 1.352, A³F/f = 0.02808,
        //   ^0.1 = 0.69958, W = 2.4975;
        // vertical, A = 0.5, f = 7.77 Hz (off-bin): F = 400/60.373 = 6.6255,
        //   A³F/f = 0.125·6.6255/7.77 = 0.10659, ^0.1 = 0.79941, W = 2.8539.
        let cases = [
            (Direction::Lateral, 0.3, 1.2, 2.4776),
            (Direction::Lateral, 0.3, 1.3, 2.4975),
            (Direction::Vertical, 0.5, 7.77, 2.8539),
        ];
        for (direction, a, f, expected) in cases {
            for fs in [200.0, 500.0] {
                let acc = sine(a, f, fs, 9.0);
                let w = sperling(&acc, fs, direction, &SperlingParams::default()).unwrap();
                assert_eq!(w.segments.len(), 2);
                for s in &w.segments {
                    assert!(
                        (s - expected).abs() < 2e-3,
                        "{direction:?} {f} Hz: {s} vs {expected}"
                    );
                }
                assert!((sperling_line(direction, a, f) - expected).abs() < 2e-4);
            }
        }
    }

    #[test]
    fn two_separated_sines_combine_as_tenth_power_sum() {
        let fs = 500.0;
        let (a, b) = (sine(0.3, 1.3, fs, 10.0), sine(0.2, 9.1, fs, 10.0));
        let acc: Vec<f64> = a.iter().zip(&b).map(|(x, y)| x + y).collect();
        let w1 = sperling_line(Direction::Lateral, 0.3, 1.3);
        let w2 = sperling_line(Direction::Lateral, 0.2, 9.1);
        let expected = (w1.powi(10) + w2.powi(10)).powf(0.1);
        let w = sperling(&acc, fs, Direction::Lateral, &SperlingParams::default()).unwrap();
        for s in &w.segments {
            assert!((s - expected).abs() < 3e-3, "{s} vs {expected}");
        }
    }

    #[test]
    fn weighting_is_continuous_enough_at_its_knees() {
        for (d, knee, flat) in [
            (Direction::Lateral, 5.4, 26.0),
            (Direction::Vertical, 5.9, 20.0),
        ] {
            let (lo, hi) = (
                sperling_weighting(d, knee - 1e-9),
                sperling_weighting(d, knee),
            );
            assert!((lo / hi - 1.0).abs() < 0.05);
            let (lo, hi) = (
                sperling_weighting(d, flat - 1e-9),
                sperling_weighting(d, flat),
            );
            assert!((lo / hi - 1.0).abs() < 0.05);
        }
    }

    #[test]
    fn ratings_and_errors() {
        assert_eq!(RideRating::locomotive(2.5), RideRating::Excellent);
        assert_eq!(RideRating::locomotive(2.9), RideRating::Good);
        assert_eq!(RideRating::locomotive(3.2), RideRating::Acceptable);
        assert_eq!(RideRating::locomotive(3.6), RideRating::Unacceptable);
        assert_eq!(RideRating::locomotive(f64::NAN), RideRating::Unacceptable);
        let short = sine(0.1, 1.0, 100.0, 4.0);
        let err = sperling(
            &short,
            100.0,
            Direction::Lateral,
            &SperlingParams::default(),
        );
        assert!(err.unwrap_err().to_string().contains("too short"));
        assert!(Direction::from_name("up").is_err());
        let tiny = SperlingParams {
            segment_duration: 1e-9,
            ..Default::default()
        };
        let acc = sine(0.1, 1.0, 100.0, 9.0);
        let err = sperling(&acc, 100.0, Direction::Lateral, &tiny).unwrap_err();
        assert!(err.to_string().contains("segment_duration"));
        assert_eq!(segment_starts(4500, 2500), vec![0, 2000]);
        assert_eq!(segment_starts(2500, 2500), vec![0]);
        assert_eq!(segment_starts(7500, 2500), vec![0, 2500, 5000]);
    }
}
