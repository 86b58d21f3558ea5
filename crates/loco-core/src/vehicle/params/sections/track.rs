//! The sections of the track and contact, the layout and the assessment.

use crate::error::Result;
use crate::vehicle::params::parameters::ParameterSet;

parameter_section! {
    /// The wheel and rail steel, the wheels' nominal geometry and gravity (`[track]`).
    TrackSection = "track" {
        /// Nominal wheel rolling radius (tape circle), m.
        wheel_rolling_radius: positive,
        /// Half the lateral distance between the nominal contact points of a wheelset, m.
        contact_point_half_distance: positive,
        /// Wheel-rail Coulomb friction coefficient, 1.
        wheel_rail_friction: positive,
        /// Young's modulus of wheel and rail steel, Pa.
        young_modulus: positive,
        /// Poisson's ratio of wheel and rail steel, 1 (the contact checks it is in [0, 0.5)).
        poisson_ratio: signed,
        /// Gravitational acceleration, m/s².
        gravity: positive,
    }
}

impl TrackSection {
    /// Shear modulus of wheel and rail steel, Pa: derived, G = E / (2 (1 + ν)).
    pub fn shear_modulus(&self) -> f64 {
        self.young_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }
}

parameter_section! {
    /// Where the bogies and wheelsets sit (`[layout]`).
    LayoutSection = "layout" {
        /// Half the distance between the bogie centres, m.
        bogie_half_distance: positive,
        /// Half the bogie wheelbase, m.
        half_wheelbase: positive,
    }
}

parameter_section! {
    /// The wheel-rail normal contact (`[contact]`).
    ContactSection = "contact" {
        /// Damping of each wheel-rail normal contact, N·s/m.
        normal_contact_damping: non_negative,
    }
}

parameter_section! {
    /// What the assessment of a run reads beyond the model (`[assessment]`).
    AssessmentSection = "assessment" {
        /// The bogie mass m⁺ of the EN 14363 bogie-frame stability limit `(12 − m⁺/5)/2` m/s²,
        /// kg; `None` when the file leaves it out, and then it is the mass of the bodies each
        /// bogie carries (`vehicle::model::bogie_mass`).
        bogie_mass: optional,
    }
}
