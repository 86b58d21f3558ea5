//! The metrics module applied to a run: ride at the leading Sperling point, stability of the
//! leading bogie frame above its leading wheelset (where EN 14363 measures).

use crate::error::{LocoError, Result};
use crate::metrics::{RunMetrics, RunMetricsParams, RunRecords};
use crate::vehicle::output::run::{RunOutput, BOGIE_LATERAL, CARBODY_LATERAL, CARBODY_VERTICAL};

/// Every metric of a run at running speed `speed` (m/s) with bogie mass `bogie_mass` (kg).
pub fn run_metrics(output: &RunOutput, speed: f64, bogie_mass: f64) -> Result<RunMetrics> {
    let channel = |name: &str| {
        output
            .channel(name)
            .ok_or_else(|| LocoError::input("run output", format!("channel `{name}` missing")))
    };
    RunMetrics::compute(
        &RunRecords {
            fs: output.sampling_rate,
            speed,
            carbody_lateral: channel(CARBODY_LATERAL)?,
            carbody_vertical: Some(channel(CARBODY_VERTICAL)?),
            bogie_lateral: channel(BOGIE_LATERAL)?,
            bogie_mass,
        },
        &RunMetricsParams::default(),
    )
}

/// Metrics of a run too short to evaluate (under one 5 s Sperling segment): every value NaN,
/// the instability flags undefined (`None`, NaN in [`RunMetrics::values`]), not "stable".
pub fn undefined_metrics() -> RunMetrics {
    RunMetrics::undefined()
}

/// [`run_metrics`], or [`undefined_metrics`] when the run is shorter than the metrics need.
pub fn run_metrics_or_undefined(
    output: &RunOutput,
    speed: f64,
    bogie_mass: f64,
) -> Result<RunMetrics> {
    let needed = crate::metrics::SperlingParams::default().segment_duration;
    if (output.time.len() as f64) < needed * output.sampling_rate {
        return Ok(undefined_metrics());
    }
    run_metrics(output, speed, bogie_mass)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::output::run::{
        RunOutput, BOGIE_LATERAL, CARBODY_LATERAL, CARBODY_VERTICAL,
    };

    #[test]
    fn a_run_too_short_has_every_metric_undefined_flags_included() {
        // 4 s at 500 Hz: under one 5 s Sperling segment.
        let n = 2000;
        let output = RunOutput {
            sampling_rate: 500.0,
            time: (0..n).map(|i| i as f64 / 500.0).collect(),
            names: vec![
                CARBODY_LATERAL.into(),
                CARBODY_VERTICAL.into(),
                BOGIE_LATERAL.into(),
            ],
            channels: vec![vec![0.1; n]; 3],
        };
        let m = run_metrics_or_undefined(&output, 55.0, 3441.0).unwrap();
        let values = m.values();
        assert_eq!(values.len(), RunMetrics::names().len());
        for (name, v) in RunMetrics::names().iter().zip(&values) {
            assert!(v.is_nan(), "{name} = {v}: an undefined metric must be NaN");
        }
        assert_eq!(m.ayb_gbt_unstable, None);
    }
}
