//! Every metric of one simulated run as a row of named values, for the batch engine.

use super::comfort::{weighted_rms, ComfortWeighting};
use super::limit_cycle::limit_cycle;
use super::metric_table::MetricValue;
use super::spectral::{check_record, dominant_frequency, WelchParams, MIN_SAMPLES};
use super::sperling::{sperling, Direction, SperlingParams};
use super::stability::{bogie_stability, rms, StabilityParams};
use crate::error::{check_positive, Result};

/// The records of one run that the metrics need.
#[derive(Debug, Clone, Copy)]
pub struct RunRecords<'a> {
    /// Sampling rate of every record, Hz.
    pub fs: f64,
    /// Running speed, m/s.
    pub speed: f64,
    /// Carbody floor lateral acceleration A_yc, m/s².
    pub carbody_lateral: &'a [f64],
    /// Carbody floor vertical acceleration, m/s² (optional).
    pub carbody_vertical: Option<&'a [f64]>,
    /// Bogie frame lateral acceleration A_yb, m/s².
    pub bogie_lateral: &'a [f64],
    /// Bogie mass for the EN 14363 limit, kg.
    pub bogie_mass: f64,
}

/// Parameters of every metric of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunMetricsParams {
    /// Sperling evaluation.
    pub sperling: SperlingParams,
    /// Bogie stability statistics.
    pub stability: StabilityParams,
    /// Welch PSD for the carbody dominant frequency.
    pub welch: WelchParams,
    /// Search band for the carbody dominant frequency, Hz.
    pub carbody_band: (f64, f64),
}

impl Default for RunMetricsParams {
    fn default() -> Self {
        Self {
            sperling: SperlingParams::default(),
            stability: StabilityParams::default(),
            welch: WelchParams::default(),
            carbody_band: (0.2, 20.0),
        }
    }
}

macro_rules! run_metrics_struct {
    ($( $constant:ident $field:ident : $ty:ty, $unit:literal, $doc:literal; )*) => {
        /// All metrics of one run, the fields of [`super::metric_table`] (units there:
        /// m/s² for accelerations, Hz, (m/s²)²/Hz for PSD values); flags are 0 or 1 in
        /// [`Self::values`]; NaN where a record was not given, and every value NaN, the flags too
        /// (`None`), when the metrics are undefined (a run too short to evaluate): an undefined
        /// flag must not read as "stable".
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct RunMetrics {
            $(
                #[doc = concat!($doc, ", ", $unit, ".")]
                pub $field: $ty,
            )*
        }

        /// Names of [`RunMetrics::values`], in order.
        const NAMES: &[&str] = &[$(stringify!($field)),*];

        impl RunMetrics {
            /// Every metric undefined: NaN, the flags `None`.
            pub fn undefined() -> Self {
                Self {
                    $($field: <$ty as MetricValue>::UNDEFINED,)*
                }
            }

            /// The metrics as numbers (flags as 0/1, NaN when undefined), in the order of
            /// [`Self::names`].
            pub fn values(&self) -> Vec<f64> {
                vec![$(MetricValue::number(self.$field)),*]
            }
        }
    };
}
crate::metric_table!(run_metrics_struct);

impl RunMetrics {
    /// Computes every metric of a run.
    pub fn compute(records: &RunRecords<'_>, params: &RunMetricsParams) -> Result<Self> {
        let fs = check_positive("fs", records.fs)?;
        check_record("carbody_lateral", records.carbody_lateral, fs, MIN_SAMPLES)?;
        check_record("bogie_lateral", records.bogie_lateral, fs, MIN_SAMPLES)?;
        let ayc = records.carbody_lateral;
        let wy = sperling(ayc, fs, Direction::Lateral, &params.sperling)?;
        let (wz_mean, wz_max, azc_wb_p95) = match records.carbody_vertical {
            Some(az) => {
                let wz = sperling(az, fs, Direction::Vertical, &params.sperling)?;
                let wb = weighted_rms(az, fs, ComfortWeighting::Wb)?;
                (wz.mean, wz.max, wb.p95)
            }
            None => (f64::NAN, f64::NAN, f64::NAN),
        };
        let (lo, hi) = params.carbody_band;
        let dominant = dominant_frequency(ayc, fs, lo, hi, &params.welch)?;
        let ayc_wd_p95 = weighted_rms(ayc, fs, ComfortWeighting::Wd)?.p95;
        let nmv = 6.0 * (ayc_wd_p95.powi(2) + azc_wb_p95.max(0.0).powi(2)).sqrt();
        // The carbody's limit cycle by the frame's rule, its frequency sought in the carbody band.
        let carbody_search = StabilityParams {
            f0_min: lo,
            f0_max: hi,
            ..params.stability
        };
        let carbody_cycle = limit_cycle(ayc, fs, &carbody_search)?;
        let ayb = records.bogie_lateral;
        let cycle = limit_cycle(ayb, fs, &params.stability)?;
        let stability = bogie_stability(
            ayb,
            fs,
            records.speed,
            records.bogie_mass,
            &params.stability,
        )?;
        Ok(Self {
            wy_mean: wy.mean,
            wy_max: wy.max,
            wz_mean,
            wz_max,
            ayc_rms: rms(ayc),
            ayc_peak: ayc.iter().fold(0.0f64, |m, v| m.max(v.abs())),
            ayc_dominant_hz: dominant.frequency,
            ayc_psd_peak: dominant.peak_density,
            ayc_wd_p95,
            azc_wb_p95,
            nmv,
            ayb_rms: rms(ayb),
            ayb_peak_lp: stability.peak_lowpassed,
            ayb_gbt_cycles: stability.max_consecutive_cycles as f64,
            ayb_gbt_unstable: Some(stability.gbt_unstable),
            ayb_f0_hz: stability.f0,
            ayb_psd_peak: stability.f0_psd_peak,
            ayb_en_rms: stability.sliding_rms_max,
            ayb_en_limit: stability.limit,
            ayb_en_unstable: Some(stability.en_unstable),
            ayb_limit_cycle: Some(cycle.detected),
            ayb_cycle_hz: cycle.frequency,
            ayb_cycle_amplitude: cycle.amplitude,
            ayc_limit_cycle: Some(carbody_cycle.detected),
            ayc_cycle_hz: carbody_cycle.frequency,
            ayc_cycle_amplitude: carbody_cycle.amplitude,
        })
    }

    /// Column names, in the order of [`Self::values`].
    pub fn names() -> &'static [&'static str] {
        NAMES
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::sperling::sperling_line;
    use std::f64::consts::PI;

    #[test]
    fn row_of_a_synthetic_run() {
        let fs = 500.0;
        let ayc: Vec<f64> = (0..4500)
            .map(|j| 0.3 * (2.0 * PI * 1.3 * j as f64 / fs).sin())
            .collect();
        let ayb: Vec<f64> = (0..4500)
            .map(|j| 2.0 * (2.0 * PI * 6.0 * j as f64 / fs).sin())
            .collect();
        let records = RunRecords {
            fs,
            speed: 200.0 / 3.6,
            carbody_lateral: &ayc,
            carbody_vertical: None,
            bogie_lateral: &ayb,
            bogie_mass: 12_000.0,
        };
        let m = RunMetrics::compute(&records, &RunMetricsParams::default()).unwrap();
        let values = m.values();
        assert_eq!(values.len(), RunMetrics::names().len());
        assert!((m.wy_max - sperling_line(Direction::Lateral, 0.3, 1.3)).abs() < 2e-3);
        assert!(m.wz_mean.is_nan());
        assert!((m.ayc_dominant_hz - 1.3).abs() < 0.03);
        assert!((m.ayb_f0_hz - 6.0).abs() < 0.03);
        assert!((m.ayb_en_limit - 0.5 * (12.0 - 2.4)).abs() < 1e-12);
        assert_eq!(values[14], 0.0);
        // Two steady sinusoids: limit cycles of the frame and the carbody at their frequencies
        // and amplitudes.
        assert_eq!(m.ayb_limit_cycle, Some(true));
        assert!((m.ayb_cycle_hz - 6.0).abs() < 0.1 && (m.ayb_cycle_amplitude - 2.0).abs() < 0.05);
        assert_eq!(m.ayc_limit_cycle, Some(true));
        // Under six cycles of 1.3 Hz in the last half: the band-passed peaks read 4 % high.
        assert!((m.ayc_cycle_hz - 1.3).abs() < 0.1 && (m.ayc_cycle_amplitude - 0.3).abs() < 0.015);
        let bad = RunRecords { fs: 0.0, ..records };
        assert!(RunMetrics::compute(&bad, &RunMetricsParams::default()).is_err());
    }
}
