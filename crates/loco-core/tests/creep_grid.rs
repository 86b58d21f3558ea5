//! The creep model's smallest grid (`run_limits::MIN_CREEP_GRID_SIDE`) keeps the study's metrics
//! within `CREEP_GRID_TOLERANCE` of their converged values: the study's 500 m runs at 200 km/h
//! (track seed 1) on the three study scenarios, each metric at the smallest grid against 20 × 20.

use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::run_limits::{CREEP_GRID_TOLERANCE, MIN_CREEP_GRID_SIDE};
use loco_core::vehicle::scenarios::scenario::Scenario;

/// (W_y, peak of the low-passed A_yb) of `name` on an n × n creep grid.
fn metrics(name: &str, n: usize) -> (f64, f64) {
    let mut scenario = Scenario::study(name, 200.0 / 3.6, 500.0, 1).unwrap();
    (scenario.fastsim.nx, scenario.fastsim.ny) = (n, n);
    let m = simulate(ParameterSet::default_vehicle(), &scenario)
        .unwrap()
        .metrics;
    (m.wy_max, m.ayb_peak_lp)
}

#[test]
fn the_smallest_creep_grid_keeps_the_study_metrics_within_the_tolerance() {
    for name in ["S_low", "S_norm", "S_high"] {
        let (wy, ayb) = metrics(name, MIN_CREEP_GRID_SIDE);
        let (wy_ref, ayb_ref) = metrics(name, 20);
        for (what, value, reference) in [("W_y", wy, wy_ref), ("A_yb", ayb, ayb_ref)] {
            let deviation = (value / reference - 1.0).abs();
            assert!(
                deviation <= CREEP_GRID_TOLERANCE,
                "{name} {what}: {value} at {MIN_CREEP_GRID_SIDE} x {MIN_CREEP_GRID_SIDE} against \
                 {reference} at 20 x 20 ({:.1} %)",
                deviation * 100.0
            );
        }
    }
}
