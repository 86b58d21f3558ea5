//! The bogie mass m⁺ of the EN 14363 bogie-frame stability limit `(12 − m⁺/5)/2` m/s² (m⁺ in t).
//!
//! EN 14363 (and UIC 518 before it) takes m⁺ as the mass of the bogie: frame, wheelsets and the
//! equipment the bogie carries, not the frame alone (the standards' text was not reached; this
//! is how the vehicle-dynamics literature quotes the simplified method's limit, see
//! `docs/assessment.md`). From the model's bodies that is, per bogie:
//!
//! - the bogie frame,
//! - its two wheelsets and their four axle boxes (rotary arms),
//! - its two traction motors (frame-hung: the bogie carries them on their mounts),
//! - its two hollow shafts with their big gears (carried by the motors' bearings on the
//!   wheelsets).
//!
//! Not counted: the carbody and the traction rods, which link the carbody to the bogie with
//! their pivot on the carbody. The vehicle file may state m⁺ instead (`assessment.bogie_mass`,
//! optional), e.g. from a weighed bogie.

use crate::error::{LocoError, Result};
use crate::vehicle::model::layout::*;
use crate::vehicle::model::structure::VehicleStructure;

/// The optional vehicle parameter that states m⁺ (kg) instead of computing it.
pub const BOGIE_MASS_KEY: &str = "assessment.bogie_mass";

/// Bodies of bogie `b` counted in its m⁺, in body-number order.
pub fn bogie_bodies(b: usize) -> Vec<usize> {
    let wheelsets: Vec<usize> = (0..N_WHEELSETS).filter(|&w| bogie_of(w) == b).collect();
    let mut bodies = vec![body_frame(b)];
    bodies.extend(wheelsets.iter().map(|&w| body_wheelset(w)));
    bodies.extend(wheelsets.iter().map(|&w| body_motor(w)));
    bodies.extend(wheelsets.iter().map(|&w| body_hollow_shaft(w)));
    for &w in &wheelsets {
        bodies.extend((0..2).map(|side| body_rotary_arm(w, side)));
    }
    bodies
}

/// The mass of each bogie's bodies ([`bogie_bodies`]), kg.
pub fn computed_bogie_masses(structure: &VehicleStructure) -> [f64; N_BOGIES] {
    std::array::from_fn(|b| {
        bogie_bodies(b)
            .into_iter()
            .map(|i| structure.bodies[i].mass)
            .sum()
    })
}

/// m⁺ of the EN 14363 limit, kg: the vehicle file's `assessment.bogie_mass` when given, else the
/// heavier bogie's computed mass (the lower, stricter limit). A stated mass that leaves the
/// limit no positive value (not in 0 < m⁺ < 60 t, possible with `allow_out_of_range`) is
/// refused naming the key.
pub fn en14363_bogie_mass(structure: &VehicleStructure) -> Result<f64> {
    match structure.sections.assessment.bogie_mass {
        Some(m) if !(m > 0.0 && m < 60_000.0) => Err(LocoError::param(
            BOGIE_MASS_KEY,
            format!("{m} kg leaves the EN 14363 limit (12 − m⁺/5)/2 no positive value (needs 0 < m⁺ < 60 t)"),
        )),
        Some(m) => Ok(m),
        None => Ok(computed_bogie_masses(structure)
            .into_iter()
            .fold(0.0, f64::max)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::params::parameters::ParameterSet;

    #[test]
    fn every_body_but_the_carbody_and_traction_rods_belongs_to_one_bogie() {
        let mut seen: Vec<usize> = (0..N_BOGIES).flat_map(bogie_bodies).collect();
        seen.sort_unstable();
        let others = [BODY_CARBODY, body_traction_rod(0), body_traction_rod(1)];
        let expected: Vec<usize> = (0..N_BODIES).filter(|i| !others.contains(i)).collect();
        assert_eq!(seen, expected);
    }

    #[test]
    fn the_default_bogie_is_frame_wheelsets_axle_boxes_motors_and_hollow_shafts() {
        let p = ParameterSet::default_vehicle();
        let g = |k: &str| p.get(k).unwrap();
        // Summed from the file's parameters, independently of the bodies.
        let by_hand = g("bogie_frame.mass")
            + 2.0 * g("wheelset.mass")
            + 4.0 * g("rotary_arm.mass")
            + 2.0 * g("traction_motor.mass")
            + 2.0 * g("hollow_shaft.mass");
        let s = VehicleStructure::new(p).unwrap();
        assert_eq!(computed_bogie_masses(&s), [by_hand; 2]);
        assert_eq!(en14363_bogie_mass(&s).unwrap(), by_hand);
        // 3441 + 2·2434 + 4·180 + 2·3200 + 2·600 kg.
        assert!((by_hand - 16_629.0).abs() < 1e-9, "{by_hand}");
    }

    #[test]
    fn the_vehicle_file_can_state_it() {
        let mut p = ParameterSet::default_vehicle();
        assert_eq!(p.get_optional(BOGIE_MASS_KEY), None);
        p.set(BOGIE_MASS_KEY, 12_000.0).unwrap();
        let s = VehicleStructure::new(p.clone()).unwrap();
        assert_eq!(en14363_bogie_mass(&s).unwrap(), 12_000.0);
        let e = p.set(BOGIE_MASS_KEY, 100.0).unwrap_err();
        assert!(e.to_string().contains(BOGIE_MASS_KEY), "{e}");
        p.allow_out_of_range(BOGIE_MASS_KEY).unwrap();
        p.set(BOGIE_MASS_KEY, 70_000.0).unwrap();
        let s = VehicleStructure::new(p).unwrap();
        let e = en14363_bogie_mass(&s).unwrap_err();
        assert!(e.to_string().contains(BOGIE_MASS_KEY), "{e}");
        let text = format!(
            "{}\n[assessment]\nbogie_mass = {{ value = 14.5, unit = \"t\", source = \"weighed\" }}\n",
            crate::vehicle::params::parameters::DEFAULT_VEHICLE_TOML
        );
        let from_file = ParameterSet::from_toml_str(&text, "v.toml").unwrap();
        assert_eq!(from_file.get_optional(BOGIE_MASS_KEY), Some(14_500.0));
    }
}
