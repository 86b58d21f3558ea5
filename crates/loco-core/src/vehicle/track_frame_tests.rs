use super::*;
use crate::track::{CurveDirection, DesignSection};
use crate::vehicle::layout::YAW;
use crate::vehicle::parameters::ParameterSet;

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
    use crate::vehicle::layout::{rotary_arm, wheelset, N_DOF, PITCH};
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
