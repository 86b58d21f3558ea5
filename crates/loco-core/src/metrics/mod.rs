//! Ride and stability metrics: PSD, Sperling index, bogie frame stability, comfort.
//!
//! Pure functions on `&[f64]` records sampled at `fs` Hz; bad input (too short, NaN,
//! non-positive `fs`) is a [`crate::LocoError`] naming the argument.
//!
//! - [`spectral`]: Welch PSD, dominant frequency and peak, the shared spectral estimator.
//! - [`sperling`]: Sperling index per GB/T 5599-2019, rating bands for a locomotive.
//! - [`filters`]: zero-phase Butterworth low/high/band-pass.
//! - [`stability`]: bogie frame lateral acceleration (GB/T peaks, EN 14363 sliding rms).
//! - [`comfort`]: EN 12299 / ISO 2631-1 weighted rms (Wd, Wb) and N_MV.
//! - [`metric_table`]: the one table of the run metrics (name, unit, description) the struct,
//!   the Python names and the docs are generated from.
//! - [`summary`]: every metric of one run as a row of named values for the batch engine.

pub mod comfort;
pub mod filters;
pub mod limit_cycle;
pub mod metric_table;
pub mod spectral;
pub mod sperling;
pub mod stability;
pub mod summary;

pub use comfort::{comfort_nmv, weighted_rms, ComfortWeighting, WeightedRms};
pub use filters::Filter;
pub use metric_table::{metric, MetricInfo, METRIC_TABLE};
pub use spectral::{dominant_frequency, welch_psd, Dominant, Psd, WelchParams};
pub use sperling::{sperling, Direction, RideRating, Sperling, SperlingParams};
pub use stability::{bogie_stability, BogieStability, StabilityParams};
pub use summary::{RunMetrics, RunMetricsParams, RunRecords};
