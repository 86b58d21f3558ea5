//! Cost bounds of a run: the settings whose cost grows without limit (a crawling speed, a tiny
//! step, a huge creep grid, a record too long to hold) are refused before any work, with the
//! reason in the error, instead of a run that takes hours, exhausts memory or ignores Ctrl-C.
//!
//! The figures in the reasons were measured on the default vehicle, S_norm, 300 m at 200 km/h
//! (5 398 steps of 1 ms) on one core of the shared development machine: 0.24 ms per step with the
//! default 10 × 10 creep grid, 3.6 ms with 50 × 50. FASTSIM against a 400 × 400 grid (four
//! creepage states, a = 6 mm, b = 4 mm): the largest force error is 0.56 % of μN at 10 × 10,
//! 0.10 % at 20 × 20, 0.02 % at 50 × 50.

use crate::metrics::RunMetricsParams;

/// Lowest running speed, m/s (3.6 km/h). The run lasts `distance / speed`, so its cost per metre
/// grows as 1/speed: at 1 m/s and the 1 ms step a metre is 1000 steps (~0.25 s of computing),
/// at 1e-3 m/s a million steps. The creepages are slip velocities divided by the running speed,
/// singular at standstill; nothing in the study runs below 20 m/s.
pub const MIN_SPEED: f64 = 1.0;

/// Most integration steps of one run (lead-in and record): 1e7 steps are about 40 minutes of one
/// core; the study's 500 m at 200 km/h is 9 000 steps, 100 km at 200 km/h 1.8 million.
pub const MAX_STEPS: f64 = 1e7;

/// Most recorded samples per channel of one run (memory: every channel keeps every sample, 8 MB
/// per channel at this bound, 0.6 GB for the default vehicle's 74 channels); 2 000 s at the
/// default 500 Hz.
pub const MAX_SAMPLES: f64 = 1e6;

/// Most elements (nx · ny) of the creep model's grid. FASTSIM's cost grows with it and dominates
/// a run's step: 50 × 50, the bound, already costs 15 times the default 10 × 10 per step, while
/// the forces change by under 0.1 % of μN beyond 20 × 20 (module documentation).
pub const MAX_CREEP_GRID_ELEMENTS: usize = 2_500;

/// Fewest elements of the creep model's grid along each direction (nx and ny): the coarsest
/// square grid that keeps the study's metrics (W_y and the peak of the low-passed A_yb) within
/// [`CREEP_GRID_TOLERANCE`] of their values at 20 × 20 on the three study scenarios (500 m at
/// 200 km/h, track seed 1, the default vehicle; `tests/creep_grid.rs` checks it). Measured
/// (largest deviation over the six metrics): 10 × 10, the default, 2.3 %; 8 × 8 3.4 %; 6 × 6
/// 4.8 % (S_low A_yb 0.446 against 0.426 m/s²); 5 × 5 5.6 %; 4 × 4 7.3 %; 1 × 1 50 % (S_norm
/// A_yb 0.842 against 0.560 m/s², S_high 2.28 against 1.59 m/s²).
pub const MIN_CREEP_GRID_SIDE: usize = 6;

/// Largest relative deviation of a study metric from its converged (20 × 20) value that a creep
/// grid may cause: 5 %, about twice the default grid's own (2.3 %), rounded.
pub const CREEP_GRID_TOLERANCE: f64 = 0.05;

/// Lowest output rate, Hz: the metrics read frequencies up to the carbody dominant-frequency band
/// (20 Hz), the EN 14363 band-pass (f0 ≤ 15 Hz, ± 2 Hz) and the 10 Hz low-pass of A_yb, so the
/// record's Nyquist frequency must lie above the highest of them.
pub fn min_output_rate() -> f64 {
    let p = RunMetricsParams::default();
    let highest = p
        .carbody_band
        .1
        .max(p.stability.f0_max + p.stability.band_half_width)
        .max(p.stability.lowpass_hz);
    2.0 * highest
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::LocoError;
    use crate::vehicle::scenarios::scenario::Scenario;

    fn study() -> Scenario {
        Scenario::study("S_norm", 200.0 / 3.6, 500.0, 0).unwrap()
    }

    fn refused_field(s: &Scenario) -> String {
        match s.validate().unwrap_err() {
            LocoError::InvalidParameter { name, reason } => {
                assert!(!reason.is_empty());
                name
            }
            other => panic!("expected an invalid parameter, got {other}"),
        }
    }

    #[test]
    fn the_study_run_is_within_every_bound() {
        assert!(study().validate().is_ok());
        // The study's extremes: the sweep's lowest speed, 100 km at 200 km/h.
        let slow = Scenario {
            speed: 80.0 / 3.6,
            ..study()
        };
        assert!(slow.validate().is_ok());
        let long = Scenario {
            distance: 100_000.0,
            ..study()
        };
        assert!(long.validate().is_ok());
    }

    #[test]
    fn a_crawling_speed_is_refused_with_its_cost() {
        let mut s = Scenario {
            speed: 1e-3,
            ..study()
        };
        s.run.step = 1e-3;
        assert_eq!(refused_field(&s), "speed");
        let msg = s.validate().unwrap_err().to_string();
        // 1 / (1e-3 m/s · 1e-3 s) = 1e6 steps per metre, spelled out in the reason.
        assert!(msg.contains("1000000 integration steps per metre"), "{msg}");
        let at_bound = Scenario {
            speed: MIN_SPEED,
            distance: 100.0,
            ..study()
        };
        assert!(at_bound.validate().is_ok());
    }

    #[test]
    fn a_slow_output_rate_blames_output_rate() {
        // 40 Hz: twice the 20 Hz top of the carbody band, the highest metric frequency.
        assert_eq!(min_output_rate(), 40.0);
        for rate in [1e-3, 1.0, 40.0] {
            let mut s = study();
            s.run.output_rate = rate;
            assert_eq!(refused_field(&s), "output_rate", "{rate}");
        }
        let mut s = study();
        s.run.output_rate = 50.0;
        assert!(s.validate().is_ok());
    }

    #[test]
    fn a_huge_creep_grid_is_refused() {
        for grid in [
            (10_000, 10_000),
            (0, 10),
            (51, 50),
            (usize::MAX, 6),
            (1, 1),
            (5, 10),
        ] {
            let mut s = study();
            (s.fastsim.nx, s.fastsim.ny) = grid;
            assert_eq!(refused_field(&s), "fastsim_grid", "{grid:?}");
        }
        let mut s = study();
        (s.fastsim.nx, s.fastsim.ny) = (50, 50);
        assert!(s.validate().is_ok());
        (s.fastsim.nx, s.fastsim.ny) = (MIN_CREEP_GRID_SIDE, MIN_CREEP_GRID_SIDE);
        assert!(s.validate().is_ok());
    }

    #[test]
    fn a_record_shorter_than_one_sample_is_refused() {
        let tiny = Scenario {
            distance: 1e-30,
            ..study()
        };
        assert_eq!(refused_field(&tiny), "distance");
        // 0.2 m at 200 km/h: 3.6 ms of record, one sample interval (2 ms at 500 Hz) and more.
        let one_sample = Scenario {
            distance: 0.2,
            ..study()
        };
        assert!(one_sample.validate().is_ok());
    }

    #[test]
    fn too_many_steps_name_the_step_or_the_distance() {
        let mut tiny_step = study();
        tiny_step.run.step = 1e-9;
        tiny_step.run.output_rate = 500.0;
        assert_eq!(refused_field(&tiny_step), "step");
        // 100 km at 3.6 km/h: 1e8 steps of 1 ms.
        let slow_and_long = Scenario {
            speed: MIN_SPEED,
            distance: 100_000.0,
            ..study()
        };
        assert_eq!(refused_field(&slow_and_long), "distance");
    }
}
