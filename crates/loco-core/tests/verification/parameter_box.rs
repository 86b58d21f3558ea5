//! The default integration settings across the SPEC §6 parameter box: every corner runs, and
//! halving the step changes the study's metrics by less than 1 %.

use crate::record::Record;

use crate::box_support::{damper_corners, vehicle, SOFT_CORNER, STIFF_CORNER};
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::model::suspension::DamperRole;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::{build_track, start_distance, Scenario};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use loco_core::vehicle::system::simulation::VehicleSystem;
use rayon::prelude::*;
use std::sync::Arc;

/// 200 km/h, m/s.
const SPEED: f64 = 200.0 / 3.6;
/// 310 m at 200 km/h is 5.6 s: one 5 s Sperling segment after the first samples.
const DISTANCE: f64 = 310.0;

fn scenario(name: &str, step: f64) -> Scenario {
    let mut s = Scenario::study(name, SPEED, DISTANCE, 1).unwrap();
    s.run.step = step;
    s
}

/// Whether the vehicle integrates its secondary lateral dampers with a rigid series spring at
/// step `dt` (s).
fn lateral_damper_rigid(parameters: ParameterSet, dt: f64) -> bool {
    let s = scenario("S_low", dt);
    let structure = Arc::new(VehicleStructure::new(parameters).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, &s).unwrap());
    let track = Arc::new(build_track(&s, &structure).unwrap());
    let start = start_distance(&structure);
    let system = VehicleSystem::new(structure, wr, track, SPEED, start, None, dt).unwrap();
    let forms: Vec<bool> = system
        .dampers
        .iter()
        .filter(|d| d.placement.role == DamperRole::SecondaryLateral)
        .map(|d| d.law.has_rigid_series())
        .collect();
    assert!(!forms.is_empty() && forms.iter().all(|f| *f == forms[0]));
    forms[0]
}

#[test]
fn every_damper_corner_of_the_study_box_runs_at_the_default_step() {
    let corners = damper_corners();
    // The stiff-spring corner needs the rigid form at 1 ms (k/c = 5e3 1/s) and not at 0.5 ms.
    let stiff = vehicle(&corners[1]);
    assert!(lateral_damper_rigid(stiff.clone(), 1e-3));
    assert!(!lateral_damper_rigid(stiff, 5e-4));
    let cases: Vec<(usize, &str)> = (0..corners.len())
        .flat_map(|i| [(i, "S_low"), (i, "S_high")])
        .collect();
    let failures: Vec<String> = cases
        .par_iter()
        .filter_map(|&(i, name)| {
            let result = simulate(vehicle(&corners[i]), &scenario(name, 1e-3));
            match result {
                Ok(r) if r.metrics.wy_max.is_finite() && r.metrics.ayb_peak_lp.is_finite() => None,
                Ok(_) => Some(format!("{:?} {name}: metrics undefined", corners[i])),
                Err(e) => Some(format!("{:?} {name}: {e}", corners[i])),
            }
        })
        .collect();
    assert!(failures.is_empty(), "{failures:#?}");
    Record::new("parameter_box_damper_corners", file!())
        .count("runs", cases.len())
        .within("failed", failures.len() as f64, "", 1, "=", 0.0)
        .check();
}

#[test]
fn halving_the_step_changes_wy_and_ayb_by_less_than_one_percent() {
    // The nominal vehicle and two opposite corners of the six-parameter box.
    let vehicles: [(&str, &[(&str, f64)]); 3] = [
        ("nominal", &[]),
        ("soft corner", &SOFT_CORNER),
        ("stiff corner", &STIFF_CORNER),
    ];
    let cases: Vec<(usize, &str)> = (0..vehicles.len())
        .flat_map(|i| [(i, "S_low"), (i, "S_high")])
        .collect();
    let changes: Vec<(String, f64, f64, f64)> = cases
        .par_iter()
        .map(|&(i, name)| {
            let metric = |step: f64| {
                let m = simulate(vehicle(vehicles[i].1), &scenario(name, step))
                    .unwrap()
                    .metrics;
                if name == "S_low" {
                    m.wy_max
                } else {
                    m.ayb_peak_lp
                }
            };
            let (full, half) = (metric(1e-3), metric(5e-4));
            let label = format!("{} {name}", vehicles[i].0);
            (label, full, half, (full - half).abs() / half.abs())
        })
        .collect();
    for (label, full, half, change) in &changes {
        println!(
            "{label}: 1 ms {full:.5}, 0.5 ms {half:.5}, change {:.4} %",
            100.0 * change
        );
    }
    for (label, full, half, change) in &changes {
        assert!(
            *change < 0.01,
            "{label}: {full} at 1 ms, {half} at 0.5 ms ({:.3} %)",
            100.0 * change
        );
    }
    let worst = |scenario: &str| {
        changes
            .iter()
            .filter(|c| c.0.ends_with(scenario))
            .fold(0.0_f64, |m, c| m.max(c.3))
    };
    Record::new("parameter_box_half_step", file!())
        .count("vehicles", vehicles.len())
        .within("wy_change_s_low", worst("S_low"), "", 2, "<", 0.01)
        .within("ayb_change_s_high", worst("S_high"), "", 2, "<", 0.01)
        .check();
}
