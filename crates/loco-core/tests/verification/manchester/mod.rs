//! The Manchester contact benchmark in the shared data (CONTACT's example `mbench_a22`:
//! S1002 on UIC60, 21 wheelset poses, 10 kN vertical load per wheel): its input, CONTACT's
//! reference output per wheel, and our geometry for its set-up. Shared by the tests that compare
//! against it; `load` is `None` (the caller skips, saying so) when the data are absent.

// Each test crate that includes this module reads only some of the fields.
#![allow(dead_code)]

use super::support;
use loco_core::contact::*;
use std::path::Path;

/// One wheel's contact in CONTACT's output, converted to the profile frame of `loco` (mm, rad, N).
#[derive(Debug, Clone, Copy)]
pub struct RefContact {
    /// Contact position on the wheel and on the rail profile, mm.
    pub wheel_y: f64,
    pub rail_y: f64,
    /// Contact angle in loco's sign convention, rad.
    pub angle: f64,
    /// Rolling radius, mm.
    pub radius: f64,
    /// CONTACT's elastic approach of the bodies, mm.
    pub approach: f64,
    /// CONTACT's normal force FN, N, and peak pressure PMAX, MPa.
    pub normal_force: f64,
    pub peak_pressure: f64,
}

/// One wheelset pose of the benchmark (CONTACT's axes: y to the right, z down).
#[derive(Debug, Clone, Copy)]
pub struct Pose {
    /// Lateral displacement Y_WS, mm.
    pub y_mm: f64,
    /// Roll ROLL_WS and yaw YAW_WS, rad.
    pub roll: f64,
    pub yaw: f64,
    /// Prescribed vertical force FZ on the wheel, N.
    pub vertical_load: f64,
    /// Forward speed VS, mm/s, and pitch rate VPITCH, rad/s.
    pub speed: f64,
    pub pitch_rate: f64,
}

/// The benchmark: poses, CONTACT's reference per wheel (one patch per wheel in every case) and
/// our contact geometry for its set-up.
pub struct Benchmark {
    pub poses: Vec<Pose>,
    /// CONTACT's right wheel, which flanges for Y_WS > 0: our left wheel (`LEFT`).
    pub flanging: Vec<(usize, RefContact)>,
    /// CONTACT's left wheel: our right wheel (`RIGHT`).
    pub other: Vec<(usize, RefContact)>,
    pub geometry: ContactGeometry,
}

fn numbers(line: &str) -> Vec<f64> {
    line.split_whitespace()
        .map_while(|f| f.parse().ok())
        .collect()
}

/// The poses of the `.inp`: the line `S, Y, FZ, ROLL, YAW, PITCH` and the velocity line after it.
fn read_poses(text: &str) -> Vec<Pose> {
    let lines: Vec<&str> = text.lines().collect();
    lines
        .iter()
        .enumerate()
        .filter(|(_, l)| l.contains("S, Y, FZ, ROLL, YAW, PITCH"))
        .map(|(i, l)| {
            let (p, v) = (numbers(l), numbers(lines[i + 1]));
            Pose {
                y_mm: p[1],
                vertical_load: p[2],
                roll: p[3],
                yaw: p[4],
                speed: v[0],
                pitch_rate: v[5],
            }
        })
        .collect()
}

/// Per case: (number of patches, first patch) from a `.ref_out`. `mirror` is −1 for the left
/// wheel, whose profile coordinates CONTACT reports mirrored (its y axis points to the right).
fn read_reference(text: &str, mirror: f64, nominal_radius_mm: f64) -> Vec<(usize, RefContact)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut patches = 0;
    let (mut tr, mut wheel, mut forces) = (None, None, None);
    for (i, l) in lines.iter().enumerate() {
        let next = || numbers(lines[i + 1]);
        let l = l.trim_start();
        if l.contains("CONTACT PATCH") && l.contains("WHEEL-RAIL") {
            patches = l.split_whitespace().rev().nth(2).unwrap().parse().unwrap();
        } else if l.starts_with("XCP(TR)") && tr.is_none() {
            tr = Some(next());
        } else if l.starts_with("XCP(W)") {
            wheel = Some(next());
        } else if l.starts_with("FN ") {
            forces = Some(next());
        } else if l.starts_with("FN/G") {
            let (approach, peak_pressure) = (next()[3], next()[4]);
            let normal_force = forces.take().map_or(f64::NAN, |f: Vec<f64>| f[0]);
            if let (Some(t), Some(w)) = (tr.take(), wheel.take()) {
                let (t, w): (Vec<f64>, Vec<f64>) = (t, w);
                out.push((
                    patches,
                    RefContact {
                        wheel_y: mirror * w[1],
                        rail_y: mirror * t[4],
                        // DELTCP is about CONTACT's x axis, y to the right: the left wheel's
                        // angle has loco's sign, the right wheel's the opposite one.
                        angle: -mirror * t[3],
                        // ZCP(W) is the wheel profile's z (down) at the contact: r = r0 + z.
                        radius: nominal_radius_mm + w[2],
                        approach,
                        normal_force,
                        peak_pressure,
                    },
                ));
            }
        }
    }
    out
}

/// The benchmark, or `None` (with the skip message of `support`) when a file is missing.
pub fn load() -> Option<Benchmark> {
    let files = [
        "profiles/MBench_S1002_v3.prw",
        "profiles/MBench_UIC60_v3.prr",
        "profiles/mbench_a22_left.inp",
        "profiles/mbench_a22_left.ref_out",
        "profiles/mbench_a22_right.ref_out",
    ];
    let paths = files
        .iter()
        .map(|f| support::shared_file(f))
        .collect::<Option<Vec<_>>>()?;
    let wheel = load_profile(&paths[0], Some(ProfileKind::Wheel), false).unwrap();
    let rail = load_profile(&paths[1], Some(ProfileKind::Rail), false).unwrap();
    let read = |p: &Path| std::fs::read_to_string(p).unwrap();
    let poses = read_poses(&read(&paths[2]));
    let other = read_reference(&read(&paths[3]), -1.0, 460.0);
    let flanging = read_reference(&read(&paths[4]), 1.0, 460.0);
    assert_eq!(poses.len(), 21);
    assert_eq!((other.len(), flanging.len()), (21, 21));
    // The benchmark's set-up (input file): gauge 1435 mm at 14 mm, rails already canted,
    // back-to-back 1360 mm with the flange back 70 mm from the taping line, r0 = 460 mm.
    let track = TrackSetup {
        gauge: 1.435,
        gauge_height: 0.014,
        rail_inclination: 0.0,
    };
    let wheelset = WheelsetSetup {
        back_to_back: 1.360,
        flange_back_offset: 0.070,
        nominal_radius: [0.46, 0.46],
    };
    let geometry =
        ContactGeometry::symmetric(&wheel, &rail, &track, &wheelset, &Default::default()).unwrap();
    Some(Benchmark {
        poses,
        flanging,
        other,
        geometry,
    })
}
