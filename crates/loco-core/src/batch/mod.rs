//! Batches: many simulations of the locomotive with different parameters, in parallel.
//!
//! - [`columns`]: what each column of the parameter matrix sets, and the checks run before a
//!   batch starts (errors name the row and column).
//! - [`status`]: how a sample ended ([`SampleStatus`]), with stable numeric codes.
//! - [`engine`]: [`run_batch`] on an explicit rayon pool, with a [`BatchMonitor`] for progress
//!   and cancellation; bit-identical results for any thread count.

pub mod columns;
pub mod engine;
pub mod status;

pub use columns::SPEED_COLUMN;
pub use engine::{run_batch, BatchMonitor, BatchOutput, BatchSpec};
pub use status::SampleStatus;
