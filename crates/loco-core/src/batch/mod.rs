//! Batches: many simulations of the locomotive with different parameters, in parallel.
//!
//! - [`columns`]: what each column of the parameter matrix sets, and the checks run before a
//!   batch starts (errors name the row and column).
//! - [`status`]: how a sample ended ([`SampleStatus`]), with stable numeric codes.
//! - [`engine`]: [`run_batch`] on an explicit rayon pool, with a [`BatchMonitor`] for progress
//!   and cancellation; bit-identical results for any thread count.
//! - [`study_file`], [`study_csv`], [`study_run`]: a batch from files (a TOML study file and a
//!   CSV of samples in, a CSV of metrics and time-history CSVs out), as `loco-batch` and
//!   `loco batch` run it.

pub mod columns;
pub mod engine;
pub mod status;
pub mod study_csv;
pub mod study_file;
pub mod study_run;

pub use columns::SPEED_COLUMN;
pub use engine::{run_batch, BatchMonitor, BatchOutput, BatchSpec};
pub use status::SampleStatus;
pub use study_run::{run_study, StudySummary};
