//! Curves: the track-following frames of a designed alignment (`track::design`,
//! `vehicle::curving::track_frame`) against independent results: balanced cant, cant deficiency, steady
//! state, mirror symmetry, bad input.

use crate::record::Record;
use loco_core::track::design::REFERENCE_CURVE_RADIUS;
use loco_core::track::{CurveDirection, DesignSection};
use loco_core::vehicle::model::layout::*;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::scenarios::scenario::{Scenario, TrackSpec};
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;
use rayon::prelude::*;
use std::sync::Arc;

use crate::curve_support::{run_on_curve, CurveRun};

pub(crate) const G: f64 = 9.81;
/// Half the distance between the nominal contact points, m (parameter file, SPEC §1).
pub(crate) const B: f64 = 0.7465;
pub(crate) const RADIUS: f64 = REFERENCE_CURVE_RADIUS;

/// Runs the S_norm locomotive on perfect track over `distance` m of `sections` at `speed`.
pub(crate) fn run_curve(sections: Vec<DesignSection>, speed: f64, distance: f64) -> CurveRun {
    let mut scenario = Scenario::study("S_norm", speed, distance, 0).unwrap();
    scenario.track = TrackSpec::Perfect;
    let structure = Arc::new(VehicleStructure::new(ParameterSet::default_vehicle()).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, &scenario).unwrap());
    run_on_curve(structure, wr, &scenario, &sections, speed, distance)
}

pub(crate) fn last(run: &CurveRun, name: &str) -> f64 {
    *run.output.channel(name).unwrap().last().unwrap()
}

/// Lateral acceleration in the track plane in a steady curve: the frame's, V²κ cos θ − g sin θ
/// (θ the cant's roll toward the inside), plus the body's own relative to the frame.
fn track_plane_lateral(speed: f64, cant: f64, relative: f64) -> f64 {
    let theta = (cant / (2.0 * B)).atan();
    speed * speed / RADIUS * theta.cos() - G * theta.sin() + relative
}

pub(crate) fn balanced_speed(cant: f64) -> f64 {
    (G * cant / (2.0 * B) * RADIUS).sqrt()
}

#[test]
fn balanced_cant_gives_no_lateral_acceleration_and_no_net_guiding_force() {
    let cant = 0.1;
    let speed = balanced_speed(cant);
    // 200 m of steady curve after the transition ends under the last wheelset, then a window of
    // 1.6 m (57 ms) sampled every 0.1 m: every body at rest at every instant, not on average.
    // The traction rods' 49 Hz modes (rod yaw and pitch on their rubber nodes) had
    // 0.13 % damping while the nodes had none, so the transition's excitation rang for seconds
    // (e-fold in 2.4 s, 68 m): frame roll 3.1e-3 rad/s² and rod yaw 0.23 rad/s² here, the
    // same at table steps of 0.1, 0.05 and 0.025 mm (not the table's kinks) and with RK4 at
    // 0.25 ms. With the nodes' hysteresis (`traction_rod.bushing_damping_time`, ζ ≈ 5 %) it
    // has died out (frames ≤ 1.3e-5). The largest left is the rotary arms' own 81-85 Hz ring
    // (6.4e-4 rad/s²): their nodes have no damping, their modes 0.2-0.3 %.
    let window: Vec<CurveRun> = (0..16)
        .into_par_iter()
        .map(|k| {
            run_curve(
                DesignSection::reference_curve(cant, CurveDirection::Left),
                speed,
                300.0 + 0.1 * k as f64,
            )
        })
        .collect();
    let r = &window[0];
    // Every body at rest in the track frame, the light links (traction rods, 80 kg, rotary
    // arms, 180 kg) too: accelerations below 1e-3 m/s² (rad/s²), except along the track: with
    // no traction the curving resistance slows the whole vehicle against the frame moving at V
    // (every body by the same ẍ, and the wheelsets' spin by ẍ/r0: checked below).
    let mut along: Vec<usize> = vec![CARBODY + X, frame(0) + X, frame(1) + X];
    for w in 0..N_WHEELSETS {
        along.extend([wheelset(w) + X, wheelset(w) + PITCH, motor(w) + X]);
    }
    let names = dof_names();
    let (largest, at) = (0..N_DOF)
        .filter(|i| !along.contains(i))
        .flat_map(|i| window.iter().map(move |r| (r.dy[N_DOF + i].abs(), i)))
        .fold((0.0, 0), |a, b| if b.0 > a.0 { b } else { a });
    println!(
        "largest acceleration in the window {largest:.2e} ({})",
        names[at]
    );
    assert!(
        largest < 1e-3,
        "acceleration {largest:.2e} at {}",
        names[at]
    );
    // The same, per group of bodies: the frames' and the traction rods' largest.
    let group = |prefix: &str| {
        (0..N_DOF)
            .filter(|i| !along.contains(i) && names[*i].starts_with(prefix))
            .flat_map(|i| window.iter().map(move |r| r.dy[N_DOF + i].abs()))
            .fold(0.0_f64, f64::max)
    };
    let (frames, rods) = (group("frame"), group("traction_rod"));
    let acc = &r.dy[N_DOF..2 * N_DOF];
    let drift = acc[CARBODY + X];
    for b in 0..N_BOGIES {
        assert!((acc[frame(b) + X] - drift).abs() < 0.05 * drift.abs());
    }
    let r0 = VehicleStructure::new(ParameterSet::default_vehicle())
        .unwrap()
        .layout
        .wheel_radius;
    for w in 0..N_WHEELSETS {
        for i in [wheelset(w) + X, motor(w) + X] {
            assert!((acc[i] - drift).abs() < 0.05 * drift.abs(), "{}", names[i]);
        }
        let spin = acc[wheelset(w) + PITCH];
        assert!(
            (spin - drift / r0).abs() < 0.05 * (drift / r0).abs(),
            "spin {spin}"
        );
    }
    let mass = VehicleStructure::new(ParameterSet::default_vehicle())
        .unwrap()
        .total_mass();
    println!(
        "curving resistance (no traction): {:.0} N, {:.2} N/kN",
        -mass * drift,
        -drift / G * 1e3
    );
    let relative = last(r, "carbody_floor_ay_front");
    let lateral = track_plane_lateral(speed, cant, relative);
    println!(
        "balanced: V = {:.2} m/s, lateral in track plane {lateral:.2e} m/s²",
        speed
    );
    assert!(lateral.abs() < 0.01, "{lateral}");
    let mut largest_sensed = 0.0_f64;
    // What accelerometers read on the floor and the frames: no lateral specific force either.
    for name in [
        "carbody_floor_accelerometer_y_front",
        "carbody_floor_accelerometer_y_rear",
        "frame1_accelerometer_y_centre",
        "frame2_accelerometer_y_wheelset4",
    ] {
        let sensed = last(r, name);
        println!("balanced: {name} {sensed:.2e} m/s²");
        assert!(sensed.abs() < 0.01, "{name} {sensed}");
        largest_sensed = largest_sensed.max(sensed.abs());
    }
    // The resultant of gravity and the centripetal force is normal to the track plane, so the
    // guiding forces of the wheelsets cancel in sum (ΣY over the vehicle ≈ 0 against the
    // ±5 kN each wheelset carries). The wheel loads are printed, not checked here: the outer
    // wheels carry 4.1 % more in sum, which is physics, not a model error. The vehicle runs
    // outward (leading wheelsets at -7.8 mm, at the flange root, the sprung masses following)
    // and the spinning parts need a gyroscopic roll moment: with the contacts at their nominal
    // ±l that roll-moment balance accounts for 7.4 kN of the 15.3 kN; the rest is the S_norm
    // contacts moving across the rail heads (two-point contact on the leading outer wheels):
    // with the rails' whole wrench in place of the loads at ±l the balance closes within
    // 1.4 % (`curving_quasi_static.rs`).
    // `curving_quasi_static.rs` checks that balance on knife-edge rails, where the contacts
    // stay put, and the 1 % where the vehicle runs near the centre line (R = 15 km).
    let (mut left, mut right, mut total_y, mut largest_y) = (0.0, 0.0, 0.0, 0.0f64);
    for w in 1..=4 {
        let (ql, qr) = (
            last(r, &format!("wheel{w}_left_Q")),
            last(r, &format!("wheel{w}_right_Q")),
        );
        let y = last(r, &format!("wheel{w}_right_Y")) + last(r, &format!("wheel{w}_left_Y"));
        println!("wheelset {w}: Q {ql:.0} / {qr:.0} N, sum Y {y:.0} N");
        left += ql;
        right += qr;
        total_y += y;
        largest_y = largest_y.max(y.abs());
    }
    let unbalance = (left - right).abs() / (0.5 * (left + right));
    println!(
        "wheel loads left / right: {left:.0} / {right:.0} N ({:.2} %)",
        100.0 * unbalance
    );
    assert!(largest_y > 1e3, "{largest_y}");
    assert!(total_y.abs() < 0.01 * largest_y, "ΣY {total_y} N");
    Record::new("curve_balanced_cant", file!())
        .value("speed", speed, "m/s", 4)
        .within("track_plane_lateral", lateral, "m/s²", 2, "<", 0.01)
        .within(
            "accelerometers_lateral",
            largest_sensed,
            "m/s²",
            2,
            "<",
            0.01,
        )
        .count("instants", window.len())
        .within("largest_acceleration", largest, "SI", 2, "<", 1e-3)
        .label("largest_acceleration_at", &names[at])
        .value("largest_acceleration_frames", frames, "SI", 2)
        .value("largest_acceleration_traction_rods", rods, "SI", 2)
        .value("sum_y", total_y, "N", 2)
        .value("largest_wheelset_y", largest_y, "N", 2)
        .value("wheel_load_unbalance", unbalance, "", 2)
        .check();
}

#[test]
fn cant_deficiency_gives_its_lateral_acceleration_and_load_transfer() {
    // 50 mm cant at the speed that balances 150 mm: 100 mm deficiency.
    let (cant, deficiency) = (0.05, 0.1);
    let speed = balanced_speed(cant + deficiency);
    let r = run_curve(
        DesignSection::reference_curve(cant, CurveDirection::Left),
        speed,
        300.0,
    );
    let relative = last(&r, "carbody_floor_ay_front");
    let lateral = track_plane_lateral(speed, cant, relative);
    let expected = G * deficiency / (2.0 * B);
    println!(
        "deficiency 100 mm: V = {speed:.2} m/s, lateral {lateral:.4} m/s², g·d/2b = {expected:.4}"
    );
    assert!((lateral - expected).abs() < 0.02 * expected, "{lateral}");
    // The carbody leans outward on its suspension (positive roll, right side down, in a left
    // curve); the roll coefficient is its roll over the cant deficiency's angle d/2b.
    let roll = r.y[CARBODY + ROLL];
    let coefficient = roll / (deficiency / (2.0 * B));
    println!("carbody roll {roll:.5} rad, roll coefficient {coefficient:.3}");
    assert!(roll > 0.0);
    // An accelerometer on the floor reads g·d/2b in the track plane (its reading turned back
    // by the carbody's roll) and g·d/2b·(1 + roll coefficient) in the carbody's rolled axes.
    let (sensed_y, sensed_z) = (
        last(&r, "carbody_floor_accelerometer_y_front"),
        last(&r, "carbody_floor_accelerometer_z_front"),
    );
    let in_track_plane = sensed_y - roll * sensed_z;
    let in_carbody = expected * (1.0 + coefficient);
    println!(
        "floor accelerometer: {sensed_y:.4} m/s² (g·d/2b·(1 + s) = {in_carbody:.4}), \
         in the track plane {in_track_plane:.4} (g·d/2b = {expected:.4}), vertical {sensed_z:.3}"
    );
    assert!((in_track_plane - expected).abs() < 0.02 * expected);
    assert!((sensed_y - in_carbody).abs() < 0.02 * in_carbody);
    assert!((sensed_z - G).abs() < 0.01 * G, "{sensed_z}");
    // A frame rolls on its primary springs only: its accelerometer by the frame's own roll.
    let frame_roll = r.y[frame(0) + ROLL];
    let frame_sensed = last(&r, "frame1_accelerometer_y_centre");
    let frame_expected = expected * (1.0 + frame_roll / (deficiency / (2.0 * B)));
    println!("frame 1 accelerometer: {frame_sensed:.4} m/s² (expected {frame_expected:.4})");
    assert!((frame_sensed - frame_expected).abs() < 0.02 * frame_expected);
    Record::new("curve_cant_deficiency", file!())
        .value("speed", speed, "m/s", 4)
        .value("expected_lateral", expected, "m/s²", 3)
        .within(
            "track_plane_lateral",
            lateral,
            "m/s²",
            4,
            "within 2 % of",
            expected,
        )
        .value("carbody_roll", roll, "rad", 2)
        .value("roll_coefficient", coefficient, "", 3)
        .within(
            "floor_accelerometer",
            sensed_y,
            "m/s²",
            4,
            "within 2 % of",
            in_carbody,
        )
        .within(
            "frame_accelerometer",
            frame_sensed,
            "m/s²",
            4,
            "within 2 % of",
            frame_expected,
        )
        .check();
    // The outer (right) wheels carry more.
    for w in 1..=4 {
        assert!(
            last(&r, &format!("wheel{w}_right_Q")) > last(&r, &format!("wheel{w}_left_Q")),
            "wheelset {w}"
        );
    }
}

#[test]
fn a_radius_the_contact_cannot_follow_is_refused_by_section() {
    let mut scenario = Scenario::study("S_norm", 20.0, 50.0, 0).unwrap();
    scenario.track = TrackSpec::Perfect;
    scenario.curve = vec![
        DesignSection::Straight { length: 10.0 },
        DesignSection::Curve {
            length: 100.0,
            radius: 20.0,
            cant: 0.0,
            direction: CurveDirection::Left,
        },
    ];
    let e =
        loco_core::vehicle::runs::simulate::simulate(ParameterSet::default_vehicle(), &scenario)
            .unwrap_err()
            .to_string();
    assert!(e.contains("curve section 2 (radius_m)"), "{e}");
    println!("{e}");
}
