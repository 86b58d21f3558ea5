use super::*;
use crate::track::{CurveDirection, DesignSection};
use crate::vehicle::model::layout::YAW;
use crate::vehicle::params::parameters::ParameterSet;

#[test]
fn bogies_in_a_steady_curve_sit_on_the_versine_and_yaw_with_the_tangent() {
    // Hand calculation: in a steady curve of radius R a point x ahead on the centre line is
    // x²/(2R) to the inside of the tangent at the origin and its tangent is yawed by x/R; the
    // suspension sees the bogie frame there (no cant: no roll, no vertical offset).
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let radius = 800.0;
    let design = TrackDesign::new(
        &[DesignSection::Curve {
            length: 500.0,
            radius,
            cant: 0.0,
            direction: CurveDirection::Right,
        }],
        0.7465,
        100.0,
    )
    .unwrap();
    let curve = CurvedTrack::new(Arc::new(design), &structure);
    let mut work = FrameWork::default();
    curve.prepare(&structure, 250.0, 50.0, &BodyStates::default(), &mut work);
    for b in 0..N_BOGIES {
        let x = structure.layout.bogie_x[b];
        let p = &work.states.position[body_frame(b)];
        assert!((p[1] + x * x / (2.0 * radius)).abs() < 1e-12, "{p:?}");
        assert!((p[YAW] + x / radius).abs() < 1e-12, "{p:?}");
        assert!(p[2].abs() < 1e-15 && p[3].abs() < 1e-15);
        // Steady curve: the offsets do not change.
        let v = &work.states.velocity[body_frame(b)];
        assert!(v.iter().all(|c| c.abs() < 1e-12), "{v:?}");
    }
    assert!((curve.wheelset_frame_yaw_rate(50.0, &work, 0) + 50.0 / radius).abs() < 1e-15);
}

#[test]
fn attached_bodies_offsets_are_their_motion_maps_of_the_offsets() {
    // The offsets of the attached bodies are formed as their parent's rigid motion; their motion
    // maps applied to the coordinates of that rigid motion (free bodies' offsets, rotary arms at
    // their wheelset's pitch) must give the same, in a transition with cant (all terms nonzero).
    use crate::vehicle::model::layout::{rotary_arm, wheelset, N_DOF, PITCH};
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let design = TrackDesign::new(
        &[
            DesignSection::Straight { length: 20.0 },
            DesignSection::Transition {
                length: 80.0,
                cant_run_off: None,
            },
            DesignSection::Curve {
                length: 500.0,
                radius: 600.0,
                cant: 0.15,
                direction: CurveDirection::Left,
            },
        ],
        0.7465,
        100.0,
    )
    .unwrap();
    let curve = CurvedTrack::new(Arc::new(design), &structure);
    let mut work = FrameWork::default();
    curve.prepare(&structure, 60.0, 40.0, &BodyStates::default(), &mut work);
    let slot = work.slot();
    let (mut q, mut qd) = (vec![0.0; N_DOF], vec![0.0; N_DOF]);
    for (first, body) in free_bodies() {
        q[first..first + 6].copy_from_slice(&slot.offset_states.position[body]);
        qd[first..first + 6].copy_from_slice(&slot.offset_states.velocity[body]);
    }
    for w in 0..N_WHEELSETS {
        for side in 0..2 {
            q[rotary_arm(w, side)] = q[wheelset(w) + PITCH];
            qd[rotary_arm(w, side)] = qd[wheelset(w) + PITCH];
        }
    }
    let mut mapped = BodyStates::default();
    structure.body_states(&q, &qd, &mut mapped);
    let scale = slot.offset_states.position[body_wheelset(0)][1].abs();
    assert!(scale > 1e-3, "the offsets are not exercised: {scale}");
    for body in 0..N_BODIES {
        for k in 0..6 {
            for (a, b) in [
                (
                    mapped.position[body][k],
                    slot.offset_states.position[body][k],
                ),
                (
                    mapped.velocity[body][k],
                    slot.offset_states.velocity[body][k],
                ),
            ] {
                assert!(
                    (a - b).abs() <= 1e-15 * (1.0 + a.abs()),
                    "body {body} {k}: {a} {b}"
                );
            }
        }
    }
}

/// `add_frame_forces` as it was before the lanes: every term formed per body from the design
/// at the body (looked up afresh) and the slot's offsets (the formulas `compute_frames` keeps),
/// one body after another.
fn frame_forces_reference(
    curve: &CurvedTrack,
    s_r: f64,
    speed: f64,
    work: &FrameWork,
    relative: &BodyStates,
    wrenches: &mut [[f64; 6]; N_BODIES],
) {
    use crate::vehicle::model::kinematics::{cross, sub};
    let slot = work.slot();
    let (v2, g) = (speed * speed, curve.gravity);
    for (i, body) in curve.bodies.iter().enumerate() {
        let o = &slot.offset_states.position[i];
        let rot = [o[3], o[4], o[5]];
        let p = &curve.design.at(s_r + body.position[0]);
        let (s, c) = p.roll.sin_cos();
        let a = v2 * p.curvature;
        let mg = body.mass * g;
        let gravity = [-mg * rot[1], -mg * s + mg * rot[0], mg - mg * c];
        let centripetal = [-body.mass * a * c, body.mass * a * s];
        let yaw_acceleration = body.yaw_inertia * v2 * p.curvature_rate;
        let w = &mut wrenches[i];
        let f = sub([w[0], w[1], w[2]], cross(rot, [w[0], w[1], w[2]]));
        let m = sub([w[3], w[4], w[5]], cross(rot, [w[3], w[4], w[5]]));
        w[0] = f[0] + gravity[0];
        w[1] = f[1] + gravity[1] + centripetal[0];
        w[2] = f[2] + gravity[2] + centripetal[1];
        w[3] = m[0];
        w[4] = m[1];
        w[5] = m[2] - yaw_acceleration;
        if body.spin != 0.0 {
            let h = body.spin * speed;
            let common = &work.states.velocity[i];
            let own = &relative.velocity[i];
            let yaw = own[YAW] + speed * p.curvature * c;
            let roll = own[3] + speed * p.roll_rate;
            w[3] += h * (yaw - common[YAW]);
            w[5] -= h * (roll - common[3]);
        }
    }
}

#[test]
fn frame_forces_are_the_per_body_formulas_bit_for_bit() {
    // In a transition with cant every term is nonzero; the states and wrenches are arbitrary.
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let design = TrackDesign::new(
        &[
            DesignSection::Straight { length: 20.0 },
            DesignSection::Transition {
                length: 80.0,
                cant_run_off: Some(60.0),
            },
            DesignSection::Curve {
                length: 500.0,
                radius: 900.0,
                cant: 0.12,
                direction: CurveDirection::Right,
            },
        ],
        0.7465,
        100.0,
    )
    .unwrap();
    let curve = CurvedTrack::new(Arc::new(design), &structure);
    let mut x = 0.61_f64;
    let mut next = || {
        x = (x * 613.0 + 0.217).fract();
        (x - 0.5) * 10f64.powi((x * 10.0) as i32 - 4)
    };
    let mut relative = BodyStates::default();
    for body in 0..N_BODIES {
        for k in 0..6 {
            relative.position[body][k] = 1e-3 * next();
            relative.velocity[body][k] = 1e-2 * next();
        }
    }
    assert!(!curve.spinning.is_empty());
    for (s_r, speed) in [(45.0, 50.0), (61.5, 38.0), (150.0, 69.0), (5.0, 20.0)] {
        let mut work = FrameWork::default();
        curve.prepare(&structure, s_r, speed, &relative, &mut work);
        let mut wrenches = [[0.0; 6]; N_BODIES];
        for w in wrenches.iter_mut() {
            w.iter_mut().for_each(|c| *c = 1e3 * next());
        }
        let mut expected = wrenches;
        frame_forces_reference(&curve, s_r, speed, &work, &relative, &mut expected);
        curve.add_frame_forces(&work, &relative, &mut wrenches);
        for body in 0..N_BODIES {
            assert_eq!(
                wrenches[body].map(f64::to_bits),
                expected[body].map(f64::to_bits),
                "s {s_r} body {body}"
            );
        }
    }
}

#[test]
fn the_states_are_summed_as_one_addition_each() {
    // Signed zeros, infinities and NaN included: each sum is its own IEEE addition.
    let specials = [
        0.0,
        -0.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        1e-310,
        -3.5,
    ];
    let (mut own, mut offset) = (BodyStates::default(), BodyStates::default());
    let mut x = 0.29_f64;
    for body in 0..N_BODIES {
        for k in 0..6 {
            x = (x * 719.0 + 0.311).fract();
            let n = (body * 6 + k) % 11;
            let pick = |m: usize, v: f64| specials.get(m).copied().unwrap_or(v);
            own.position[body][k] = pick(n, x - 0.5);
            offset.position[body][k] = pick((n + 3) % 11, 1e-3 * x);
            own.velocity[body][k] = pick((n + 5) % 11, 7.0 * x);
            offset.velocity[body][k] = pick((n + 1) % 11, -x);
        }
    }
    let mut sum = BodyStates::default();
    add_states(&mut sum, &own, &offset);
    for body in 0..N_BODIES {
        for k in 0..6 {
            let p = own.position[body][k] + offset.position[body][k];
            let v = own.velocity[body][k] + offset.velocity[body][k];
            assert_eq!(sum.position[body][k].to_bits(), p.to_bits(), "{body} {k}");
            assert_eq!(sum.velocity[body][k].to_bits(), v.to_bits(), "{body} {k}");
        }
    }
}

#[test]
fn kept_frame_terms_are_the_ones_computed_afresh() {
    // A run through a transition into a steady curve (stations keep their terms there), a
    // speed change, another track of the same design in the same workspace: each slot must
    // hold the bits a fresh workspace computes.
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let design = Arc::new(
        TrackDesign::new(
            &DesignSection::study_curve(CurveDirection::Right),
            0.7465,
            100.0,
        )
        .unwrap(),
    );
    let curve = CurvedTrack::new(design.clone(), &structure);
    let other = CurvedTrack::new(design, &structure);
    let mut work = FrameWork::default();
    let relative = BodyStates::default();
    let mut asks: Vec<(&CurvedTrack, f64, f64)> =
        (0..400).map(|k| (&curve, 0.37 * k as f64, 55.0)).collect();
    asks.extend([
        (&curve, 148.0, 54.0),
        (&curve, 148.37, 54.0),
        (&other, 148.74, 54.0),
    ]);
    asks.extend([
        (&curve, 149.11, 54.0),
        (&curve, 149.48, 54.0),
        (&other, 149.85, 54.0),
    ]);
    let bits = slot_bits;
    for (n, &(track, s_r, speed)) in asks.iter().enumerate() {
        track.prepare(&structure, s_r, speed, &relative, &mut work);
        let mut fresh = FrameWork::default();
        track.prepare(&structure, s_r, speed, &relative, &mut fresh);
        assert!(bits(work.slot()) == bits(fresh.slot()), "ask {n}: s {s_r}");
    }
}

/// The bits of everything a slot holds for the evaluations.
fn slot_bits(slot: &FrameSlot) -> Vec<u64> {
    let mut out: Vec<u64> = Vec::new();
    for q in &slot.lanes {
        out.extend(q.rot.as_flattened().iter().map(|v| v.to_bits()));
        out.extend(q.gravity.as_flattened().iter().map(|v| v.to_bits()));
        out.extend(q.centripetal.as_flattened().iter().map(|v| v.to_bits()));
        out.extend(q.yaw_acceleration.iter().map(|v| v.to_bits()));
    }
    for l in &slot.loads {
        out.extend([l.yaw_rate, l.roll_rate, l.spin].map(f64::to_bits));
    }
    out.extend(slot.cant_gravity.map(f64::to_bits));
    for states in [&slot.offset_states.position, &slot.offset_states.velocity] {
        out.extend(states.as_flattened().iter().map(|v| v.to_bits()));
    }
    for (p, (s, c)) in slot.station_points.iter().zip(&slot.station_roll) {
        let values = [
            p.curvature,
            p.curvature_rate,
            p.roll,
            p.roll_rate,
            p.heading,
        ];
        out.extend(values.map(f64::to_bits));
        out.extend([p.heading_integral, *s, *c].map(f64::to_bits));
    }
    out
}

#[test]
fn frames_compiled_for_avx_are_the_plain_ones() {
    // The dispatching `prepare` (AVX where the processor has it) against the plain
    // computation in the same slots, through a transition with cant into a curve.
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let design = TrackDesign::new(
        &DesignSection::entry_curve(700.0, 0.13, CurveDirection::Left),
        0.7465,
        100.0,
    )
    .unwrap();
    let curve = CurvedTrack::new(Arc::new(design), &structure);
    let relative = BodyStates::default();
    let (mut work, mut plain) = (FrameWork::default(), FrameWork::default());
    for k in 0..600 {
        let (s_r, speed) = (-15.0 + 0.29 * k as f64, 40.0 + 0.01 * (k / 100) as f64);
        curve.prepare(&structure, s_r, speed, &relative, &mut work);
        // `prepare`'s choice of slot, with the plain computation.
        let key = Some((
            &curve as *const CurvedTrack as usize,
            s_r.to_bits(),
            speed.to_bits(),
        ));
        if let Some(k) = plain.slots.iter().position(|slot| slot.key == key) {
            plain.active = k;
        } else {
            plain.active = 1 - plain.active;
            curve.compute_frames_plain(s_r, speed, &mut plain);
            plain.slots[plain.active].key = key;
        }
        assert_eq!(work.active, plain.active);
        assert!(slot_bits(work.slot()) == slot_bits(plain.slot()), "s {s_r}");
    }
}
