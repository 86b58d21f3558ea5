//! The names and values of the channels recorded per wheel and per wheelset: the wheel-rail
//! forces and what a curving assessment (EN 14363) reads from them. Each name is formed
//! here only; the run records them ([`crate::vehicle::output::run`]), Python reads the table
//! (`loco.wheel_channels()`), the batch binary checks a study's channels against
//! [`crate::vehicle::output::run::channel_names`].
//!
//! Forces are in the track frame, which on a curve is rolled by the cant (`track_frame`), so
//! Y and ΣY are the track-plane lateral forces EN 14363 assesses. They act on the wheel
//! (+ left); the force on the track is the opposite.

use crate::vehicle::model::layout::N_WHEELSETS;
use crate::vehicle::rail_contact::wheel_rail::WheelForces;

/// Contact angle above which a loaded point counts as flange contact, rad (45°). The S1002 /
/// 60 kg tread runs below 0.1 rad and the flange flank at 70° (1.22 rad, EN 13715), with the
/// flange root's contact angle rising steeply between them, so any threshold well inside the
/// root separates the two; 45° is where the point's normal force pushes the wheel as much
/// sideways as up, the regime whose Y/Q Nadal's flange-climbing formula bounds.
pub const FLANGE_CONTACT_ANGLE: f64 = std::f64::consts::FRAC_PI_4;

/// The two wheels of a wheelset, in channel order.
pub const WHEEL_SIDES: [&str; 2] = ["left", "right"];

/// A quantity recorded at every wheel (channel `wheel<w>_<side>_<suffix>`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WheelQuantity {
    /// Vertical wheel-rail force Q, N (`Q`).
    VerticalForce,
    /// Lateral wheel-rail force Y in the track plane, N, + left (`Y`).
    LateralForce,
    /// Derailment quotient Y/Q, – (`YQ`; 0 for an unloaded wheel).
    DerailmentQuotient,
    /// Wheel unloading ΔQ/Q0 = (Q0 − Q)/Q0, –, with Q0 the mean static wheel load (the vehicle's
    /// weight over its eight wheels) (`dQQ`).
    Unloading,
    /// Wear number T·γ, N (`Tgamma`, see [`WheelForces::wear_number`]).
    WearNumber,
    /// Largest contact angle of the loaded points, rad (`contact_angle`).
    ContactAngle,
    /// Flange contact, – (`flange`): 1 when a loaded point's contact angle exceeds
    /// [`FLANGE_CONTACT_ANGLE`], else 0.
    FlangeContact,
}

/// The wheel force channels recorded since the first version (their positions are kept).
pub const WHEEL_FORCE_QUANTITIES: [WheelQuantity; 3] = [
    WheelQuantity::VerticalForce,
    WheelQuantity::LateralForce,
    WheelQuantity::DerailmentQuotient,
];

/// The curving channels per wheel, recorded after the damper channels.
pub const CURVING_WHEEL_QUANTITIES: [WheelQuantity; 4] = [
    WheelQuantity::Unloading,
    WheelQuantity::WearNumber,
    WheelQuantity::ContactAngle,
    WheelQuantity::FlangeContact,
];

impl WheelQuantity {
    /// The last part of the channel name.
    pub fn suffix(self) -> &'static str {
        match self {
            WheelQuantity::VerticalForce => "Q",
            WheelQuantity::LateralForce => "Y",
            WheelQuantity::DerailmentQuotient => "YQ",
            WheelQuantity::Unloading => "dQQ",
            WheelQuantity::WearNumber => "Tgamma",
            WheelQuantity::ContactAngle => "contact_angle",
            WheelQuantity::FlangeContact => "flange",
        }
    }

    /// Its SI unit (`–` for a ratio or a flag).
    pub fn unit(self) -> &'static str {
        match self {
            WheelQuantity::VerticalForce | WheelQuantity::LateralForce => "N",
            WheelQuantity::WearNumber => "N",
            WheelQuantity::ContactAngle => "rad",
            WheelQuantity::DerailmentQuotient
            | WheelQuantity::Unloading
            | WheelQuantity::FlangeContact => "–",
        }
    }

    /// Its value at a wheel with forces `f`; `static_load` is Q0, N.
    pub fn value(self, f: &WheelForces, static_load: f64) -> f64 {
        match self {
            WheelQuantity::VerticalForce => f.vertical,
            WheelQuantity::LateralForce => f.lateral,
            WheelQuantity::DerailmentQuotient => {
                if f.vertical > 0.0 {
                    f.lateral / f.vertical
                } else {
                    0.0
                }
            }
            WheelQuantity::Unloading => (static_load - f.vertical) / static_load,
            WheelQuantity::WearNumber => f.wear_number,
            WheelQuantity::ContactAngle => f.contact_angle,
            WheelQuantity::FlangeContact => f64::from(u8::from(
                f.points_in_contact > 0 && f.contact_angle > FLANGE_CONTACT_ANGLE,
            )),
        }
    }
}

/// A quantity recorded per wheelset (channel `wheelset<w>_<suffix>`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WheelsetQuantity {
    /// Lateral displacement relative to the track frame, m (`y`).
    Lateral,
    /// Yaw relative to the track frame at the wheelset, rad, + nose left (`yaw`): on a curve, the
    /// angle of attack (the wheelset's yaw against the track tangent at its own position, not
    /// at the bogie's or the vehicle's). Its sign follows the axes, not the curve: an
    /// under-radial wheelset (nose toward the outer rail, as a flanging leading wheelset runs)
    /// reads negative in a left curve and positive in a right one (tests: `curving.rs`,
    /// `curving_quasi_static.rs` against Boocock's linear curving solution).
    Yaw,
    /// Track-plane lateral force of the rails on the wheelset ΣY = Y_left + Y_right, N, + left
    /// (`sumY`; the track shifting force is its opposite).
    GuidingForce,
}

/// The wheelset motion channels recorded since the first version.
pub const WHEELSET_MOTION_QUANTITIES: [WheelsetQuantity; 2] =
    [WheelsetQuantity::Lateral, WheelsetQuantity::Yaw];

impl WheelsetQuantity {
    /// The last part of the channel name.
    pub fn suffix(self) -> &'static str {
        match self {
            WheelsetQuantity::Lateral => "y",
            WheelsetQuantity::Yaw => "yaw",
            WheelsetQuantity::GuidingForce => "sumY",
        }
    }
}

/// Name of the channel of `quantity` at wheelset `w` (0-based), side 0 left, 1 right.
pub fn wheel_channel(w: usize, side: usize, quantity: WheelQuantity) -> String {
    format!("wheel{}_{}_{}", w + 1, WHEEL_SIDES[side], quantity.suffix())
}

/// Name of the channel of `quantity` of wheelset `w` (0-based).
pub fn wheelset_channel(w: usize, quantity: WheelsetQuantity) -> String {
    format!("wheelset{}_{}", w + 1, quantity.suffix())
}

/// Every per-wheel quantity's channel names, wheelset by wheelset, left before right.
pub fn wheel_channel_table() -> Vec<(&'static str, Vec<String>)> {
    WHEEL_FORCE_QUANTITIES
        .iter()
        .chain(CURVING_WHEEL_QUANTITIES.iter())
        .map(|&q| {
            let names = (0..N_WHEELSETS)
                .flat_map(|w| (0..2).map(move |side| wheel_channel(w, side, q)))
                .collect();
            (q.suffix(), names)
        })
        .collect()
}

/// Every per-wheelset quantity's channel names, wheelset by wheelset.
pub fn wheelset_channel_table() -> Vec<(&'static str, Vec<String>)> {
    [
        WheelsetQuantity::Lateral,
        WheelsetQuantity::Yaw,
        WheelsetQuantity::GuidingForce,
    ]
    .iter()
    .map(|&q| {
        let names = (0..N_WHEELSETS).map(|w| wheelset_channel(w, q)).collect();
        (q.suffix(), names)
    })
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::model::structure::VehicleStructure;
    use crate::vehicle::output::run::channel_names;
    use crate::vehicle::params::parameters::ParameterSet;
    use std::collections::HashSet;

    #[test]
    fn every_table_name_is_recorded_once() {
        let s = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
        let names = channel_names(&s).unwrap();
        let unique: HashSet<&String> = names.iter().collect();
        assert_eq!(unique.len(), names.len(), "duplicate channel names");
        let tables = wheel_channel_table()
            .into_iter()
            .chain(wheelset_channel_table());
        let mut listed = 0;
        for (quantity, channels) in tables {
            for c in &channels {
                assert!(unique.contains(c), "{quantity}: {c} not recorded");
            }
            listed += channels.len();
        }
        // 7 quantities × 8 wheels, 3 × 4 wheelsets.
        assert_eq!(listed, 7 * 8 + 3 * 4);
        // The older channels keep their places: the wheel forces right after the wheelsets.
        let first_wheel = names.iter().position(|n| n == "wheel1_left_Q").unwrap();
        assert_eq!(names[first_wheel - 1], "wheelset4_yaw");
        // The curving channels end where the accelerometer channels, appended after them, begin.
        let first_accelerometer = names
            .iter()
            .position(|n| n == "carbody_floor_accelerometer_y_front")
            .unwrap();
        assert_eq!(names[first_accelerometer - 1], "wheelset4_sumY");
        assert_eq!(names.last().unwrap(), "frame2_accelerometer_y_wheelset4");
    }

    #[test]
    fn values_follow_their_definitions() {
        let f = WheelForces {
            vertical: 80e3,
            lateral: -20e3,
            longitudinal: 0.0,
            points_in_contact: 2,
            wear_number: 150.0,
            contact_angle: 1.2,
        };
        let q0 = 100e3;
        assert_eq!(WheelQuantity::DerailmentQuotient.value(&f, q0), -0.25);
        assert_eq!(WheelQuantity::Unloading.value(&f, q0), 0.2);
        assert_eq!(WheelQuantity::FlangeContact.value(&f, q0), 1.0);
        let tread = WheelForces {
            contact_angle: 0.05,
            ..f
        };
        assert_eq!(WheelQuantity::FlangeContact.value(&tread, q0), 0.0);
        let lifted = WheelForces::default();
        assert_eq!(WheelQuantity::DerailmentQuotient.value(&lifted, q0), 0.0);
        assert_eq!(WheelQuantity::Unloading.value(&lifted, q0), 1.0);
    }
}
