//! Stability of the locomotive on worn wheels (S_high) with the soft yaw damper YD1: the time
//! simulation against the model's own linearisation, and the nonlinear critical speed of a
//! speed ramp-down against the linear one (subcritical hunting).

use crate::record::Record;
use loco_core::dampers::Damper;
use loco_core::vehicle::analysis::linear_critical_speed::{linear_critical_speed, LinearSearch};
use loco_core::vehicle::analysis::linearise::{least_damped, LinearisationSettings};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::critical_speed::{
    nonlinear_critical_speed, RampOutcome, RampSettings,
};
use loco_core::vehicle::runs::simulate::{linearised, simulate};
use loco_core::vehicle::scenarios::scenario::{Scenario, TrackSpec};

/// S_high with YD1 on perfect track at `speed` (m/s) for `seconds` (s), every wheelset
/// displaced laterally by `disturbance` (m) at the start.
fn worn_yd1(speed: f64, seconds: f64, disturbance: f64) -> Scenario {
    let mut s = Scenario::study("S_high", speed, speed * seconds, 0).unwrap();
    s.track = TrackSpec::Perfect;
    s.yaw_damper = Some(Damper::yd1());
    s.initial_lateral_offset = disturbance;
    s
}

fn linear_critical() -> f64 {
    let v = linear_critical_speed(
        ParameterSet::default_vehicle(),
        &worn_yd1(50.0, 1.0, 0.0),
        &LinearSearch::default(),
    )
    .unwrap();
    assert!(v.is_finite() && v > 25.0, "linear critical speed {v} m/s");
    v
}

/// Half the peak-to-peak lateral displacement of the leading wheelset in each of the last
/// `windows` windows of `window` seconds of a run at `speed` (m/s), m.
fn tail_amplitudes(scenario: &Scenario, window: f64, windows: usize) -> Vec<f64> {
    let r = simulate(ParameterSet::default_vehicle(), scenario).unwrap();
    let y = r.output.channel("wheelset1_y").unwrap();
    let n = (window * r.output.sampling_rate) as usize;
    (0..windows)
        .rev()
        .map(|k| {
            let w = &y[y.len() - (k + 1) * n..y.len() - k * n];
            let (lo, hi) = w
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
                    (l.min(*v), h.max(*v))
                });
            0.5 * (hi - lo)
        })
        .collect()
}

#[test]
fn disturbance_decays_below_and_persists_above_the_critical_speed() {
    // Relative to the linear critical speed of the model's own linearisation. A small
    // disturbance (0.5 mm) keeps the motion in the linear range below it: on worn wheels a large
    // one can find the limit cycle there too (see the ramp test). Above it the motion grows,
    // overshoots and settles onto the limit cycle within about 12 s.
    let critical = linear_critical();
    let disturbance = 5e-4;
    let below = tail_amplitudes(&worn_yd1(0.8 * critical, 16.0, disturbance), 2.0, 2);
    assert!(
        below[1] < 0.2 * disturbance && below[1] < 0.8 * below[0],
        "at 0.8 × {critical:.1} m/s the disturbance should decay: {below:?}"
    );
    let above = tail_amplitudes(&worn_yd1(1.3 * critical, 16.0, disturbance), 2.0, 2);
    let ratio = above[1] / above[0];
    assert!(
        above[1] > 2.0 * disturbance && (ratio - 1.0).abs() < 0.05,
        "at 1.3 × {critical:.1} m/s a limit cycle should settle: {above:?}"
    );
    Record::new("stability_decay_and_limit_cycle", file!())
        .value("linear_critical_speed", critical, "m/s", 3)
        .within("decay_below", below[1] / disturbance, "", 2, "<", 0.2)
        .within("cycle_change_above", (ratio - 1.0).abs(), "", 2, "<", 0.05)
        .value("cycle_amplitude_above", above[1], "m", 2)
        .check();
}

#[test]
fn hunting_survives_below_the_linear_critical_speed_down_to_the_ramp_result() {
    // Start well above the linear critical speed, where the disturbance settles onto the large
    // hunting cycle, and ramp down at two rates: the slower ramp follows the dying cycle more
    // closely (a smaller detection delay), so it may only be higher, and not by much.
    let linear = linear_critical();
    let ramp = |deceleration: f64| {
        let settings = RampSettings {
            deceleration,
            end_speed: 0.4 * linear,
            ..RampSettings::default()
        };
        nonlinear_critical_speed(
            ParameterSet::default_vehicle(),
            &worn_yd1(1.3 * linear, 1.0, 0.0),
            &settings,
            None,
        )
        .unwrap()
    };
    let (slow, fast) = rayon::join(|| ramp(0.5), || ramp(1.0));
    for r in [&slow, &fast] {
        assert_eq!(r.outcome, RampOutcome::DiedOut, "{r:?}");
    }
    let (nonlinear, quick) = (slow.critical_speed, fast.critical_speed);
    println!("linear {linear:.2} m/s, nonlinear {nonlinear:.2} m/s (at 1 m/s²: {quick:.2} m/s)");
    assert!(
        nonlinear >= quick - 0.5 && nonlinear - quick < 0.1 * nonlinear,
        "0.5 m/s²: {nonlinear} m/s, 1 m/s²: {quick} m/s"
    );
    // Subcritical Hopf: the limit cycle outlives the linear instability (a margin for the
    // bisection tolerance and the ramp's windows).
    assert!(
        nonlinear <= linear + 1.0 && nonlinear > 0.4 * linear,
        "nonlinear {nonlinear} m/s against linear {linear} m/s"
    );
    if nonlinear < linear - 2.0 {
        // Where the cycle died the equilibrium is linearly stable: two attractors coexisted.
        let s = worn_yd1(nonlinear + 1.0, 1.0, 0.0);
        let (a, n) = linearised(ParameterSet::default_vehicle(), &s).unwrap();
        let mode = least_damped(&a, n, LinearSearch::default().band)
            .unwrap()
            .unwrap();
        assert!(mode.damping_ratio > 0.0, "{mode:?} at {nonlinear} m/s");
    }
    Record::new("stability_ramp_down", file!())
        .value("linear_critical_speed", linear, "m/s", 3)
        .within(
            "nonlinear_critical_speed",
            nonlinear,
            "m/s",
            3,
            "≤",
            linear + 1.0,
        )
        .value("nonlinear_at_1_m_s2", quick, "m/s", 3)
        .check();
}

/// Linear critical speeds of the three study scenarios with YD1 and YD2 (the table of docs/model/frequency_response.md)
/// with the candidate two groups of linearisation steps and with the default one step of 1e-7
/// (`vehicle::analysis::linearise`): how much the linear stability results depend on the steps (run with
/// `--ignored --nocapture`).
#[test]
#[ignore = "prints a table for the documentation (about a minute on 2 cores)"]
fn linear_critical_speeds_against_the_linearisation_step() {
    for name in ["S_low", "S_norm", "S_high"] {
        for (label, damper) in [("YD1", Damper::yd1()), ("YD2", Damper::yd2())] {
            let mut s = Scenario::study(name, 50.0, 50.0, 0).unwrap();
            s.track = TrackSpec::Perfect;
            s.yaw_damper = Some(damper);
            let speeds: Vec<f64> = [
                LinearisationSettings::two_groups(),
                LinearisationSettings::default(),
            ]
            .iter()
            .map(|&linearisation| {
                let search = LinearSearch {
                    high: 150.0,
                    tolerance: 0.1,
                    linearisation,
                    ..LinearSearch::default()
                };
                linear_critical_speed(ParameterSet::default_vehicle(), &s, &search).unwrap()
            })
            .collect();
            println!(
                "{name} {label}: two groups: {:.2} m/s, default (1e-7): {:.2} m/s ({:+.2} %)",
                speeds[0],
                speeds[1],
                100.0 * (speeds[0] / speeds[1] - 1.0)
            );
        }
    }
}
