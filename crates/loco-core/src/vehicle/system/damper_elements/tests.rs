//! The vehicle's damper laws at its step: a step too long for a law names the damper (the
//! reduced laws themselves are tested with the damper module).

use super::*;

use crate::vehicle::model::elements::Attachment;

fn yaw_placement(name: &str) -> DamperPlacement {
    DamperPlacement {
        name: name.into(),
        role: DamperRole::Yaw,
        at: Attachment {
            body_a: 0,
            point_a: [0.0; 3],
            body_b: 1,
            point_b: [0.0; 3],
        },
        direction: [0.0, 1.0, 0.0],
        damping: 800e3,
        series_stiffness: 22.5e6,
        count: 1.0,
    }
}

#[test]
fn a_step_too_long_for_a_law_names_the_step_and_the_damper() {
    // Stiff only above the knee: no rigid form, a typed error naming the step and the damper.
    let blow_off = crate::dampers::stiff_above_the_knee();
    let err = law_for_step(&yaw_placement("yaw_damper_x"), Some(&blow_off), 1e-3).unwrap_err();
    let text = err.to_string();
    assert!(
        matches!(err, LocoError::InvalidParameter { ref name, .. } if name == "step"),
        "{text}"
    );
    assert!(text.contains("yaw_damper_x"), "{text}");
    // A law that fits the step is used as it is.
    let law = law_for_step(&yaw_placement("yaw_damper_x"), Some(&Damper::yd2()), 1e-3).unwrap();
    assert_eq!(law, Damper::yd2());
}
