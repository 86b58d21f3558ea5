//! The one table of the run metrics: constant, field, type, unit and description of each, in
//! column order. [`metric_table!`](crate::metric_table) hands the table to a macro, which
//! generates from it what each consumer needs: the [`super::RunMetrics`] struct, its names and
//! values ([`super::summary`]), the [`metric`] name constants, the Python `Metric` constants
//! (`loco-py/src/names.rs`) and `docs/metrics.md` (`scripts/docs/metric_docs.py` reads
//! [`METRIC_TABLE`]). A metric is added or renamed here only.

/// Calls `$callback! { $( CONST field: type, "unit", "description"; )* }` with every run metric,
/// in column order. `type` is `f64` or `Option<bool>` (a flag: 0/1, `None` undefined).
#[macro_export]
macro_rules! metric_table {
    ($callback:ident) => {
        $callback! {
            WY_MEAN wy_mean: f64, "–", "Sperling W_y, mean of the 5 s segments";
            WY_MAX wy_max: f64, "–", "Sperling W_y, largest segment";
            WZ_MEAN wz_mean: f64, "–", "Sperling W_z, mean of the 5 s segments (NaN without a vertical record)";
            WZ_MAX wz_max: f64, "–", "Sperling W_z, largest segment";
            AYC_RMS ayc_rms: f64, "m/s²", "Rms of A_yc";
            AYC_PEAK ayc_peak: f64, "m/s²", "Largest |A_yc|";
            AYC_DOMINANT_HZ ayc_dominant_hz: f64, "Hz", "Dominant frequency of A_yc";
            AYC_PSD_PEAK ayc_psd_peak: f64, "(m/s²)²/Hz", "Welch PSD of A_yc at its dominant frequency";
            AYC_WD_P95 ayc_wd_p95: f64, "m/s²", "EN 12299 Wd-weighted rms of A_yc, 95th percentile of 5 s blocks";
            AZC_WB_P95 azc_wb_p95: f64, "m/s²", "EN 12299 Wb-weighted rms of the vertical record, 95th percentile";
            NMV nmv: f64, "–", "N_MV from the lateral and vertical records (no longitudinal)";
            AYB_RMS ayb_rms: f64, "m/s²", "Rms of A_yb";
            AYB_PEAK_LP ayb_peak_lp: f64, "m/s²", "Peak of the 10 Hz low-passed A_yb";
            AYB_GBT_CYCLES ayb_gbt_cycles: f64, "–", "Longest run of cycles ≥ 8 m/s² (GB/T)";
            AYB_GBT_UNSTABLE ayb_gbt_unstable: Option<bool>, "–", "GB/T instability flag (0/1, NaN undefined)";
            AYB_F0_HZ ayb_f0_hz: f64, "Hz", "Instability (dominant) frequency of A_yb";
            AYB_PSD_PEAK ayb_psd_peak: f64, "(m/s²)²/Hz", "Welch PSD of A_yb at f0";
            AYB_EN_RMS ayb_en_rms: f64, "m/s²", "Largest EN 14363 sliding rms of A_yb";
            AYB_EN_LIMIT ayb_en_limit: f64, "m/s²", "EN 14363 limit of the sliding rms";
            AYB_EN_UNSTABLE ayb_en_unstable: Option<bool>, "–", "EN 14363 instability flag (0/1, NaN undefined)";
            AYB_LIMIT_CYCLE ayb_limit_cycle: Option<bool>, "–", "Sustained limit cycle (hunting) of A_yb: narrow-band, not decaying, of steady amplitude (0/1, NaN undefined; rule in metrics::limit_cycle)";
            AYB_CYCLE_HZ ayb_cycle_hz: f64, "Hz", "Frequency of A_yb's dominant oscillation in the record's last half";
            AYB_CYCLE_AMPLITUDE ayb_cycle_amplitude: f64, "m/s²", "Mean cycle peak of A_yb band-passed to that frequency ± 2 Hz in the last half (a cycle of ± this)";
            AYC_LIMIT_CYCLE ayc_limit_cycle: Option<bool>, "–", "Sustained limit cycle of A_yc, the carbody floor's lateral acceleration (the same rule, its dominant frequency sought in the carbody band; 0/1, NaN undefined)";
            AYC_CYCLE_HZ ayc_cycle_hz: f64, "Hz", "Frequency of A_yc's dominant oscillation in the record's last half (carbody band)";
            AYC_CYCLE_AMPLITUDE ayc_cycle_amplitude: f64, "m/s²", "Mean cycle peak of A_yc band-passed to that frequency ± 2 Hz in the last half (a cycle of ± this)";
        }
    };
}

/// A metric's value type: a number, or a flag that may be undefined.
pub trait MetricValue: Copy {
    /// The value of an undefined metric (a run too short to evaluate).
    const UNDEFINED: Self;
    /// Whether the value is a flag.
    const FLAG: bool;
    /// As a number: the value itself, a flag as 0/1, NaN when undefined.
    fn number(self) -> f64;
}

impl MetricValue for f64 {
    const UNDEFINED: Self = f64::NAN;
    const FLAG: bool = false;
    fn number(self) -> f64 {
        self
    }
}

impl MetricValue for Option<bool> {
    const UNDEFINED: Self = None;
    const FLAG: bool = true;
    fn number(self) -> f64 {
        match self {
            Some(true) => 1.0,
            Some(false) => 0.0,
            None => f64::NAN,
        }
    }
}

/// One row of the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MetricInfo {
    /// Column name.
    pub name: &'static str,
    /// SI unit (`–` dimensionless or a flag).
    pub unit: &'static str,
    /// What it is.
    pub description: &'static str,
    /// Whether it is a flag (0/1, NaN undefined).
    pub flag: bool,
}

macro_rules! info_table {
    ($( $constant:ident $field:ident : $ty:ty, $unit:literal, $doc:literal; )*) => {
        /// Every run metric, in column order.
        pub const METRIC_TABLE: &[MetricInfo] = &[$(MetricInfo {
            name: stringify!($field),
            unit: $unit,
            description: $doc,
            flag: <$ty as MetricValue>::FLAG,
        }),*];

        /// The metric names as constants, for code that selects a metric.
        pub mod metric {
            $(
                #[doc = $doc]
                pub const $constant: &str = stringify!($field);
            )*
        }
    };
}
crate::metric_table!(info_table);
