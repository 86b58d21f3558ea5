//! The exponential integration (ETDRK4 at 2 ms) against the reference (RK4 at 1 ms) across the
//! SPEC §6 parameter box, at the nominal vehicle, the two opposite corners of the six
//! parameters and the four damper corners, the three scenarios (S_norm, the speed sweep's:
//! 0.13 % at most), on the study's 500 m runs: W_y, A_yb
//! and the A_yc PSD peak stay within the 0.5 % gate (0.42 % at most, at the corner C_sy
//! 10 kN·s/m, K_ncsy 50 kN/mm, where RK4 itself moves A_yb by 5.5 % between 0.25 and 1 ms, its
//! lateral damper's series spring rigid at 1 ms and compliant at 0.25 ms).
//!
//! On 310 m (a 5.6 s record, one Welch segment's worth, as `parameter_box.rs` runs for CI time)
//! the A_yc PSD peak is a noisier statistic: 0.57 % at the corner C_sy 10 kN·s/m, K_ncsy
//! 10 kN/mm, C_sx 200 kN·s/m, K_ncsx 10 kN/mm, S_high, where RK4 itself moves it by 0.2 % between
//! 0.25 and 1 ms; on 500 m that corner is within 0.09 %.

use crate::record::Record;

use crate::box_support::{damper_corners, vehicle, SOFT_CORNER, STIFF_CORNER};
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::Scenario;
use loco_core::vehicle::scenarios::scenario_settings::{DEFAULT_DISTANCE, DEFAULT_SPEED};
use loco_core::vehicle::time::integrator::Integrator;
use loco_core::vehicle::time::integrator::{EXPONENTIAL_STEP, REFERENCE_STEP};
use rayon::prelude::*;

/// C_sy = 20 kN·s/m with K_ncsy = 40 kN/mm: k/c = 2000 1/s.
const DAMPER_POLE_2000: [(&str, f64); 2] = [("C_sy", 20e3), ("K_ncsy", 40e6)];

/// The accuracy gate on W_y, A_yb and the A_yc PSD peak, relative.
const TOLERANCE: [f64; 3] = [5e-3; 3];

fn metrics(overrides: &[(&str, f64)], name: &str, integrator: Integrator, step: f64) -> [f64; 3] {
    let mut s = Scenario::study(name, DEFAULT_SPEED, DEFAULT_DISTANCE, 1).unwrap();
    s.run.step = step;
    s.run.integrator = integrator;
    let m = simulate(vehicle(overrides), &s).unwrap().metrics;
    [m.wy_max, m.ayb_peak_lp, m.ayc_psd_peak]
}

#[test]
fn the_exponential_integration_keeps_the_reference_metrics_over_the_box() {
    let mut vehicles: Vec<(String, Vec<(&str, f64)>)> = vec![
        ("nominal".into(), vec![]),
        ("soft corner".into(), SOFT_CORNER.to_vec()),
        ("stiff corner".into(), STIFF_CORNER.to_vec()),
    ];
    // A lateral damper pole k/c = 2000 1/s, inside (1250, 2500]: the reference (1 ms) keeps the
    // series spring, and 2 ms takes the damper's state as a decaying state solved exactly.
    vehicles.push((
        "lateral damper pole 2000 1/s".into(),
        DAMPER_POLE_2000.to_vec(),
    ));
    for corner in damper_corners() {
        let [(_, c_sy), (_, k_sy), (_, c_sx), (_, k_sx)] = corner;
        vehicles.push((
            format!("dampers C_sy {c_sy:.0e} K_ncsy {k_sy:.0e} C_sx {c_sx:.0e} K_ncsx {k_sx:.0e}"),
            corner.to_vec(),
        ));
    }
    let cases: Vec<(usize, &str)> = (0..vehicles.len())
        .flat_map(|i| [(i, "S_low"), (i, "S_norm"), (i, "S_high")])
        .collect();
    let changes: Vec<(String, [f64; 3], [f64; 3])> = cases
        .par_iter()
        .map(|&(i, name)| {
            let o = &vehicles[i].1;
            let reference = metrics(o, name, Integrator::Rk4, REFERENCE_STEP);
            let default = metrics(o, name, Integrator::ExponentialRk4, EXPONENTIAL_STEP);
            (format!("{} {name}", vehicles[i].0), reference, default)
        })
        .collect();
    let mut failures = Vec::new();
    for (label, reference, default) in &changes {
        let change: Vec<f64> = reference
            .iter()
            .zip(default)
            .map(|(r, d)| (d - r) / r.abs())
            .collect();
        println!(
            "{label}: W_y {:+.4} %, A_yb {:+.4} %, A_yc PSD peak {:+.4} %",
            100.0 * change[0],
            100.0 * change[1],
            100.0 * change[2]
        );
        if change
            .iter()
            .zip(TOLERANCE)
            .any(|(c, t)| c.is_nan() || c.abs() >= t)
        {
            failures.push(format!(
                "{label}: reference {reference:?}, default {default:?}"
            ));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
    let mut worst = [0.0_f64; 3];
    for (_, reference, default) in &changes {
        for k in 0..3 {
            worst[k] = worst[k].max(((default[k] - reference[k]) / reference[k]).abs());
        }
    }
    Record::new("exponential_step_box", file!())
        .count("runs", changes.len())
        .within("wy", worst[0], "", 2, "<", TOLERANCE[0])
        .within("ayb", worst[1], "", 2, "<", TOLERANCE[1])
        .within("ayc_psd_peak", worst[2], "", 2, "<", TOLERANCE[2])
        .check();
}

/// A vehicle whose lateral damper pole (2000 1/s) RK4 carries at 1 ms but not at 2 ms runs at
/// the exponential scheme's 2 ms with the reference's law: half the steps of the reference
/// (before, such a vehicle ran at 1 ms throughout, a quarter of the SPEC §6 box).
#[test]
fn a_damper_pole_beyond_the_explicit_limit_keeps_the_long_step() {
    let steps = |integrator: Integrator, step: f64| {
        let mut s = Scenario::study("S_low", DEFAULT_SPEED, 60.0, 1).unwrap();
        s.run.step = step;
        s.run.integrator = integrator;
        simulate(vehicle(&DAMPER_POLE_2000), &s)
            .unwrap()
            .statistics
            .steps
    };
    let reference = steps(Integrator::Rk4, REFERENCE_STEP);
    let exponential = steps(Integrator::ExponentialRk4, EXPONENTIAL_STEP);
    assert_eq!(
        2 * exponential,
        reference,
        "steps {exponential} against {reference}"
    );
}

/// Slow runs: where the long step does not resolve the creep forces' decay (λh > 0.5) the
/// default takes the reference step and keeps the reference's metrics; before that rule
/// (stop 26–27) S_low at 80 km/h ran at 2 ms with A_yb off by up to 9.3 % and the A_yc PSD peak
/// by up to 40 % (300 m, four vehicles of the box). At 200 km/h (λh 0.42 on S_low) it keeps 2 ms.
#[test]
fn slow_runs_take_the_reference_step_and_keep_its_metrics() {
    let run = |speed: f64, integrator: Integrator, step: f64| {
        let mut s = Scenario::study("S_low", speed, 300.0, 1).unwrap();
        s.run.step = step;
        s.run.integrator = integrator;
        let r = simulate(vehicle(&[]), &s).unwrap();
        let m = r.metrics;
        (
            r.statistics.steps,
            [m.wy_max, m.ayb_peak_lp, m.ayc_psd_peak],
        )
    };
    for (speed, long) in [(80.0 / 3.6, false), (DEFAULT_SPEED, true)] {
        let (ref_steps, reference) = run(speed, Integrator::Rk4, REFERENCE_STEP);
        let (steps, default) = run(speed, Integrator::ExponentialRk4, EXPONENTIAL_STEP);
        assert_eq!(
            steps * if long { 2 } else { 1 },
            ref_steps,
            "{speed} m/s: {steps} steps"
        );
        for ((r, d), t) in reference.iter().zip(default).zip(TOLERANCE) {
            assert!(
                (d - r).abs() < t * r.abs(),
                "{speed} m/s: {reference:?} {default:?}"
            );
        }
    }
}
