use super::*;
use crate::track::{CurveDirection, DesignSection};
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
