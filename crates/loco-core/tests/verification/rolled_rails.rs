//! Rolled rails: a constant cross level on otherwise perfect track, and how far a
//! running wheelset rolls relative to the rails beyond the contact table's rigid pose.
//!
//! Hand calculation. Rails whose heights differ by c are rolled by θ = atan(c / 2b) about the
//! rail-top line (2b = 1.493 m between nominal contact points). A wheelset rolling with them
//! has its centre at y = −h0 sin θ (h0 the centred rolling radius) and the normals lean by θ, so
//! the weight W has a downhill component W sin θ. In steady running it is carried by lateral
//! creep (the vehicle crabs by a few µrad) and by the profiles' gravitational stiffness K_g; the
//! shift of the wheelsets downhill from −h0 sin θ therefore lies between 0 and W sin θ / K_g,
//! with K_g = (W/2)·d(tan γ_L − tan γ_R)/dy taken from the contact table, independently of the
//! vehicle model. The carbody, pushed downhill by M_c g sin θ in the rails' plane, sags on its
//! flexicoil springs by about M_c g sin θ / K_y (K_y their lateral stiffness, all springs).

use crate::record::Record;
use loco_core::contact::table::ROLL_LAYER;
use loco_core::dampers::Damper;
use loco_core::track::{parse_csv, MeasuredParams, TrackIrregularity};
use loco_core::vehicle::model::elements::BodyStates;
use loco_core::vehicle::model::layout::*;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::output::run::{integrate, Flow};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::rail_contact::rail_plane::RailPlane;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::{build_track, start_distance, Scenario, TrackSpec};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use loco_core::vehicle::system::simulation::VehicleSystem;
use loco_core::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use loco_core::LocoError;
use std::sync::Arc;

const CROSS_LEVEL: f64 = 0.002;
const SPEED: f64 = 200.0 / 3.6;
const HALF: f64 = 0.7465;

fn constant_cross_level(length: f64) -> TrackIrregularity {
    let step = 0.5;
    let n = (length / step) as usize + 1;
    let zero = vec![0.0; n];
    let values = [
        zero.clone(),
        zero.clone(),
        vec![CROSS_LEVEL; n],
        zero.clone(),
    ];
    let slopes = [zero.clone(), zero.clone(), zero.clone(), zero];
    TrackIrregularity::from_channels(step, &values, &slopes, 30.0, None).unwrap()
}

fn system(scenario: &Scenario, damper: Option<&Damper>) -> VehicleSystem {
    let structure = Arc::new(VehicleStructure::new(ParameterSet::default_vehicle()).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, scenario).unwrap());
    let track = Arc::new(build_track(scenario, &structure).unwrap());
    let start = start_distance(&structure);
    VehicleSystem::new(structure, wr, track, SPEED, start, damper, 1e-3).unwrap()
}

/// Runs `distance` m and calls `observe` with the system at every `every`-th step.
fn run(
    system: &mut VehicleSystem,
    distance: f64,
    every: usize,
    mut observe: impl FnMut(f64, &VehicleSystem, &[f64]),
) {
    let mut y = static_equilibrium(system, &StaticsSettings::default())
        .unwrap()
        .state;
    let steps = (distance / SPEED / 1e-3) as usize;
    integrate(
        system,
        &mut y,
        1e-3,
        steps,
        None,
        |n, _, _, _| {
            Ok(if n % every == 0 || n == steps {
                Flow::Observe
            } else {
                Flow::Step
            })
        },
        |t, system, y, _| observe(t, system, y),
    )
    .unwrap();
}

struct Steady {
    state: Vec<f64>,
    wheel_lateral: [[f64; 2]; N_WHEELSETS],
    points: [[u8; 2]; N_WHEELSETS],
}

fn steady(name: &str, track: Option<TrackIrregularity>, distance: f64) -> (Steady, VehicleSystem) {
    let mut scenario = Scenario::study(name, SPEED, distance, 0).unwrap();
    scenario.track = match track {
        Some(t) => TrackSpec::Given(Arc::new(t)),
        None => TrackSpec::Perfect,
    };
    let mut sys = system(&scenario, None);
    let mut last = None;
    run(&mut sys, distance, usize::MAX, |_, system, y| {
        last = Some(Steady {
            state: y.to_vec(),
            wheel_lateral: std::array::from_fn(|w| {
                std::array::from_fn(|s| system.wheel_forces[w][s].lateral)
            }),
            points: std::array::from_fn(|w| {
                std::array::from_fn(|s| system.wheel_forces[w][s].points_in_contact)
            }),
        })
    });
    (last.unwrap(), sys)
}

/// Gravitational stiffness of a wheelset carrying `load` (N), from the table around y = 0, N/m.
fn gravitational_stiffness(system: &VehicleSystem, load: f64) -> f64 {
    let table = system.wheel_rail.table();
    let tan_difference = |y: f64| {
        let pose = table.lookup(y);
        let angle = |side: usize| pose.wheels[side].touching().unwrap().contact_angle.tan();
        angle(0) - angle(1)
    };
    let h = 5e-4;
    0.5 * load * (tan_difference(h) - tan_difference(-h)) / (2.0 * h)
}

#[test]
fn constant_cross_level_rolls_the_wheelsets_with_the_rails() {
    let theta = (CROSS_LEVEL / (2.0 * HALF)).atan();
    let mut record = Record::new("rolled_rails", file!()).value("cross_level", CROSS_LEVEL, "m", 2);
    for name in ["S_low", "S_norm", "S_high"] {
        let (level, _) = steady(name, None, 60.0);
        let (rolled, sys) = steady(name, Some(constant_cross_level(700.0)), 600.0);
        let h0 = sys.wheel_rail.centred_radius();
        let y_roll = -h0 * theta.sin();
        let weight = sys.structure.total_mass() * sys.structure.gravity;
        let shift_bound = weight / 4.0 * theta.sin() / gravitational_stiffness(&sys, weight / 4.0);
        let q = &rolled.state;
        let (mut worst_shift, mut worst_sum, mut worst_change) = (0.0_f64, 0.0_f64, 0.0_f64);
        for w in 0..N_WHEELSETS {
            let yw = q[wheelset(w) + Y];
            let shift = yw - y_roll;
            let sum_y: f64 = rolled.wheel_lateral[w].iter().sum();
            println!(
                "{name} wheelset {}: y {:.4} mm = −h0 sin θ {:.4} mm + {:.4} mm (gravitational-\
                 stiffness bound −{:.4} mm), roll − θ {:.2e} rad, ΣY {sum_y:.0} N",
                w + 1,
                yw * 1e3,
                y_roll * 1e3,
                shift * 1e3,
                shift_bound * 1e3,
                q[wheelset(w) + ROLL] - theta,
            );
            assert!(
                shift.abs() < 1e-4,
                "{name}: wheelset {} off by {shift} m",
                w + 1
            );
            assert!(
                shift > -shift_bound - 3e-5,
                "{name}: downhill shift {shift} m beyond W sin θ / K_g = {shift_bound} m"
            );
            assert!((q[wheelset(w) + ROLL] - theta).abs() < 2e-5);
            assert!(sum_y.abs() < 1e3, "{name}: ΣY {sum_y} N");
            (worst_shift, worst_sum) = (worst_shift.max(shift.abs()), worst_sum.max(sum_y.abs()));
            for s in 0..2 {
                let change = rolled.wheel_lateral[w][s] - level.wheel_lateral[w][s];
                worst_change = worst_change.max(change.abs());
                assert!(change.abs() < 1e3, "{name}: Y changed by {change} N");
                assert_eq!(rolled.points[w][s], 1, "{name}: a second (flange) contact");
            }
        }
        // The carbody's lateral sag on its flexicoil springs, in the rails' plane.
        let mut states = BodyStates::default();
        sys.structure
            .body_states(&q[..N_DOF], &q[N_DOF..2 * N_DOF], &mut states);
        let springs: Vec<_> = sys
            .structure
            .suspension
            .bushings
            .iter()
            .filter(|b| b.name.starts_with("flexicoil"))
            .collect();
        let sag = springs
            .iter()
            .map(|b| {
                let (d, _) = b.at.relative_motion(&states);
                d[1] * theta.cos() + d[2] * theta.sin()
            })
            .sum::<f64>()
            / springs.len() as f64;
        let k_y: f64 = springs.iter().map(|b| b.stiffness[1]).sum();
        let carbody_mass = sys.structure.bodies[BODY_CARBODY].mass;
        let expected = -carbody_mass * sys.structure.gravity * theta.sin() / k_y;
        println!(
            "{name}: carbody sag on the flexicoils {:.4} mm, hand {:.4} mm",
            sag * 1e3,
            expected * 1e3
        );
        // The traction rods and the other carbody-frame links take a little of the load; the
        // springs' preload, tilted by the carbody's own roll on them, adds a few per cent.
        assert!(
            sag < 0.85 * expected && sag > 1.1 * expected,
            "{name}: sag {sag} m, expected {expected} m"
        );
        let n = name.to_lowercase();
        record = record
            .value(&format!("{n}_rolled_pose"), y_roll, "m", 3)
            .within(&format!("{n}_shift"), worst_shift, "m", 2, "<", 1e-4)
            .value(&format!("{n}_shift_bound"), shift_bound, "m", 2)
            .within(&format!("{n}_sum_y"), worst_sum, "N", 2, "<", 1e3)
            .within(
                &format!("{n}_wheel_y_change"),
                worst_change,
                "N",
                2,
                "<",
                1e3,
            )
            .value(&format!("{n}_carbody_sag"), sag, "m", 2)
            .value(&format!("{n}_carbody_sag_hand"), expected, "m", 2);
    }
    record.check();
}

/// How far each wheelset rolls relative to the rails beyond the table's rigid pose at each
/// wheel's lookup position (the table's relative-roll layers must cover it), and where it runs, on the study's synthetic track (SPEC §6: 200 km/h, 500 m) with YD2 and, for flange
/// contact, with YD1 on S_high (hunting) and S_low.
#[test]
fn relative_roll_stays_at_the_table_pose() {
    let cases = [
        ("S_low", "yd2", Damper::yd2()),
        ("S_norm", "yd2", Damper::yd2()),
        ("S_high", "yd2", Damper::yd2()),
        ("S_high", "yd1", Damper::yd1()),
        ("S_low", "yd1", Damper::yd1()),
    ];
    let mut record = Record::new("rolled_rails_relative_roll", file!());
    for (name, damper_name, damper) in cases {
        let scenario = Scenario::study(name, SPEED, 500.0, 0).unwrap();
        let mut sys = system(&scenario, Some(&damper));
        let h0 = sys.wheel_rail.centred_radius();
        let (mut worst_roll, mut worst_y, mut two_points) = (0.0_f64, 0.0_f64, 0);
        run(&mut sys, 500.0, 5, |t, system, y| {
            for w in 0..N_WHEELSETS {
                let rails = system.track.at(system.wheelset_distance(w, t));
                let plane = RailPlane::new(&rails, HALF, SPEED);
                let i = wheelset(w);
                let pose = plane.pose(y[i + Y], y[i + Z], y[i + ROLL], h0);
                let table = system.wheel_rail.table();
                for side in 0..2 {
                    let rigid = table.lookup(plane.table_position(pose.lateral, side)).roll;
                    worst_roll = worst_roll.max((pose.roll - rigid).abs());
                }
                worst_y = worst_y.max(pose.lateral.abs());
                two_points += system.wheel_forces[w]
                    .iter()
                    .filter(|f| f.points_in_contact > 1)
                    .count();
            }
        });
        println!(
            "{name} {damper:?}: |roll − table roll| ≤ {worst_roll:.2e} rad, |y'| ≤ {:.2} mm, \
             {two_points} wheel samples in two-point contact",
            worst_y * 1e3
        );
        assert!(
            worst_roll < ROLL_LAYER,
            "{name}: relative roll {worst_roll} rad beyond the table's layers"
        );
        let label = format!("{}_{damper_name}", name.to_lowercase());
        record = record
            .within(
                &format!("{label}_roll"),
                worst_roll,
                "rad",
                2,
                "<",
                ROLL_LAYER,
            )
            .count(&format!("{label}_two_point_samples"), two_points);
    }
    record.check();
}

#[test]
fn measured_track_beyond_the_contact_is_refused_with_its_line() {
    let good = "distance,vertical,alignment,cross_level,gauge\n";
    let rows = |bad_line: usize, column: usize, value: f64| {
        let mut text = good.to_string();
        for i in 0..1400 {
            let mut v = [0.0; 4];
            if i + 2 == bad_line {
                v[column] = value;
            }
            text += &format!("{},{},{},{},{}\n", i as f64 * 0.5, v[0], v[1], v[2], v[3]);
        }
        text
    };
    let run = |text: &str| {
        let track = parse_csv(text, "measured.csv", &MeasuredParams::default()).unwrap();
        let mut scenario = Scenario::study("S_low", SPEED, 100.0, 0).unwrap();
        scenario.track = TrackSpec::Given(Arc::new(track));
        simulate(ParameterSet::default_vehicle(), &scenario)
    };
    // 40 mm of gauge widening: 20 mm per wheel plus the thin flange's clearance is off the table.
    match run(&rows(700, 3, 40.0)) {
        Err(LocoError::Parse {
            path, line, reason, ..
        }) => {
            assert_eq!((path.as_str(), line), ("measured.csv", 700));
            assert!(reason.contains("gauge deviation 40.00 mm"), "{reason}");
        }
        other => panic!("expected a parse error, got {other:?}"),
    }
    match run(&rows(900, 2, 45.0)) {
        Err(LocoError::Parse { line, reason, .. }) => {
            assert_eq!(line, 900);
            assert!(reason.contains("cross level 45.00 mm"), "{reason}");
        }
        other => panic!("expected a parse error, got {other:?}"),
    }
    // Within the limits the same file runs.
    assert!(run(&rows(700, 3, 5.0)).is_ok());
    let refused_line = |text: &str| match run(text) {
        Err(LocoError::Parse { line, .. }) => line,
        other => panic!("expected a parse error, got {other:?}"),
    };
    Record::new("measured_track_refused", file!())
        .count("gauge_widening_line", refused_line(&rows(700, 3, 40.0)))
        .count("cross_level_line", refused_line(&rows(900, 2, 45.0)))
        .check();
}
