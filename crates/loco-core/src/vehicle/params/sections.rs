//! The parameter file as typed sections: one struct per section of the file (and of the
//! schema), one field per key, read once from a [`ParameterSet`] and checked, so the model
//! builders read fields and not strings.
//!
//! A field is named as its key's name within the section: `secondary.yaw_damper_damping` is
//! `VehicleSections::secondary.yaw_damper_damping`. Each section is declared once by
//! [`parameter_section!`], which gives the struct, its keys (`KEYS`) and its reader, with the check
//! the model needs of the field: `positive` (finite and > 0), `non_negative` (finite and ≥ 0),
//! `signed` (any value the schema accepts), `count` (a whole number ≥ 0), `count_positive` (a
//! whole number ≥ 1) or `optional` (absent: the model computes it). A failed check is a
//! [`crate::LocoError::InvalidParameter`] naming the key. That every schema key is read by exactly
//! one field is tested.
//!
//! Overrides (a batch row, a study sample, `ParameterSet::set`) change the `ParameterSet`; the
//! sections are read again from it whenever a vehicle is built.

use crate::error::Result;
use crate::vehicle::params::parameters::ParameterSet;

/// The Rust type of a field checked as `$check`.
macro_rules! field_type {
    (positive) => { f64 };
    (non_negative) => { f64 };
    (signed) => { f64 };
    (count) => { usize };
    (count_positive) => { usize };
    (optional) => { Option<f64> };
}

/// The value of `$key` in `$p`, checked as `$check`.
macro_rules! read_field {
    ($p:expr, $key:expr, positive) => {
        crate::error::check_positive($key, $p.get($key)?)?
    };
    ($p:expr, $key:expr, non_negative) => {
        crate::error::check_non_negative($key, $p.get($key)?)?
    };
    ($p:expr, $key:expr, signed) => {
        $p.get($key)?
    };
    // The parameter set has checked that a count is a whole number, so the cast is exact.
    ($p:expr, $key:expr, count) => {
        crate::error::check_non_negative($key, $p.get($key)?)? as usize
    };
    ($p:expr, $key:expr, count_positive) => {
        crate::error::check_positive($key, $p.get($key)?)? as usize
    };
    ($p:expr, $key:expr, optional) => {
        $p.get_optional($key)
    };
}

/// The value of a field checked as `$check`, as a number.
macro_rules! field_value {
    ($v:expr, optional) => {
        $v
    };
    ($v:expr, count) => {
        Some($v as f64)
    };
    ($v:expr, count_positive) => {
        Some($v as f64)
    };
    ($v:expr, $check:ident) => {
        Some($v)
    };
}

/// Declares one section: its struct (every field documented with its unit), its name in the
/// file, its keys in field order and its reader.
macro_rules! parameter_section {
    (
        $(#[$meta:meta])*
        $name:ident = $section:literal {
            $( $(#[$field_meta:meta])* $field:ident : $check:ident ),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct $name {
            $( $(#[$field_meta])* pub $field: field_type!($check), )*
        }

        impl $name {
            /// The section's name in the vehicle file.
            pub const SECTION: &'static str = $section;
            /// The keys this section reads, one per field, in field order.
            pub const KEYS: &'static [&'static str] =
                &[$(concat!($section, ".", stringify!($field))),*];
            /// The check of each key, as named in the declaration, in field order.
            pub const CHECKS: &'static [&'static str] = &[$(stringify!($check)),*];

            /// Reads and checks the section; a failed check names the key.
            pub fn read(p: &ParameterSet) -> Result<Self> {
                Ok(Self {
                    $( $field: read_field!(p, concat!($section, ".", stringify!($field)), $check), )*
                })
            }

            /// Each key with its field's value as a number (`None`: an optional field left
            /// out), in field order.
            pub fn values(&self) -> Vec<(&'static str, Option<f64>)> {
                vec![$( (
                    concat!($section, ".", stringify!($field)),
                    field_value!(self.$field, $check),
                ), )*]
            }
        }
    };
}

// The sections, declared after the macros so that the macros are in scope there.
mod bodies;
mod suspension;
mod track;

pub use bodies::{
    BogieFrameSection, CarbodySection, HollowShaftSection, RotaryArmSection, TractionMotorSection,
    TractionRodSection, WheelsetSection,
};
pub use suspension::{PrimarySection, SecondarySection};
pub use track::{AssessmentSection, ContactSection, LayoutSection, TrackSection};

/// Every section of a vehicle's parameters, read and checked once.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VehicleSections {
    pub track: TrackSection,
    pub layout: LayoutSection,
    pub carbody: CarbodySection,
    pub bogie_frame: BogieFrameSection,
    pub wheelset: WheelsetSection,
    pub traction_motor: TractionMotorSection,
    pub hollow_shaft: HollowShaftSection,
    pub traction_rod: TractionRodSection,
    pub rotary_arm: RotaryArmSection,
    pub primary: PrimarySection,
    pub secondary: SecondarySection,
    pub contact: ContactSection,
    pub assessment: AssessmentSection,
}

/// Each section's keys and their checks, section by section in the order of
/// [`VehicleSections`].
pub const SECTION_KEYS: [(&[&str], &[&str]); 13] = [
    (TrackSection::KEYS, TrackSection::CHECKS),
    (LayoutSection::KEYS, LayoutSection::CHECKS),
    (CarbodySection::KEYS, CarbodySection::CHECKS),
    (BogieFrameSection::KEYS, BogieFrameSection::CHECKS),
    (WheelsetSection::KEYS, WheelsetSection::CHECKS),
    (TractionMotorSection::KEYS, TractionMotorSection::CHECKS),
    (HollowShaftSection::KEYS, HollowShaftSection::CHECKS),
    (TractionRodSection::KEYS, TractionRodSection::CHECKS),
    (RotaryArmSection::KEYS, RotaryArmSection::CHECKS),
    (PrimarySection::KEYS, PrimarySection::CHECKS),
    (SecondarySection::KEYS, SecondarySection::CHECKS),
    (ContactSection::KEYS, ContactSection::CHECKS),
    (AssessmentSection::KEYS, AssessmentSection::CHECKS),
];

impl VehicleSections {
    /// Reads every section from `p`, in the order of the struct's fields; the first failed
    /// check is the error.
    pub fn read(p: &ParameterSet) -> Result<Self> {
        Ok(Self {
            track: TrackSection::read(p)?,
            layout: LayoutSection::read(p)?,
            carbody: CarbodySection::read(p)?,
            bogie_frame: BogieFrameSection::read(p)?,
            wheelset: WheelsetSection::read(p)?,
            traction_motor: TractionMotorSection::read(p)?,
            hollow_shaft: HollowShaftSection::read(p)?,
            traction_rod: TractionRodSection::read(p)?,
            rotary_arm: RotaryArmSection::read(p)?,
            primary: PrimarySection::read(p)?,
            secondary: SecondarySection::read(p)?,
            contact: ContactSection::read(p)?,
            assessment: AssessmentSection::read(p)?,
        })
    }

    /// Every key with its field's value, section by section (`None`: an optional field left
    /// out).
    pub fn values(&self) -> Vec<(&'static str, Option<f64>)> {
        [
            self.track.values(),
            self.layout.values(),
            self.carbody.values(),
            self.bogie_frame.values(),
            self.wheelset.values(),
            self.traction_motor.values(),
            self.hollow_shaft.values(),
            self.traction_rod.values(),
            self.rotary_arm.values(),
            self.primary.values(),
            self.secondary.values(),
            self.contact.values(),
            self.assessment.values(),
        ]
        .concat()
    }
}

#[cfg(test)]
mod tests;
