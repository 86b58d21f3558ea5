//! A run and what it records: [`run::run`] integrates a system and samples its channels
//! ([`channel_set`]: body, accelerometer and wheel channels), the long-step range, and the metrics
//! of a run's output.

pub mod accelerometer;
pub mod channel;
pub mod channel_set;
pub mod long_step_range;
pub mod run;
pub mod run_metrics;
pub mod wheel_channels;
