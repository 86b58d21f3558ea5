//! The metrics module applied to a run: ride at the leading Sperling point, stability of the
//! leading bogie frame above its leading wheelset (where EN 14363 measures).

use super::run::RunOutput;
use crate::error::{LocoError, Result};
use crate::metrics::{RunMetrics, RunMetricsParams, RunRecords};

/// Channel of the carbody floor lateral acceleration used for W_y and A_yc.
pub const CARBODY_LATERAL: &str = "carbody_floor_ay_front";
/// Channel of the carbody floor vertical acceleration used for W_z.
pub const CARBODY_VERTICAL: &str = "carbody_floor_az_front";
/// Channel of the bogie frame lateral acceleration used for A_yb.
pub const BOGIE_LATERAL: &str = "frame1_ay_wheelset1";

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
