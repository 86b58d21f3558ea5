//! The sections of the primary (frame to axle box) and secondary (carbody to frame) suspension.

use crate::error::Result;
use crate::vehicle::params::parameters::ParameterSet;

parameter_section! {
    /// The primary coil springs and vertical dampers at each axle box (`[primary]`); the
    /// positioning stiffness is the rotary arm's node ([`super::RotaryArmSection`]).
    PrimarySection = "primary" {
        /// Coil-spring vertical stiffness, per axle box, N/m.
        axle_box_spring_vertical_stiffness: positive,
        /// Coil-spring shear stiffness in x and y, per axle box, added to the arm node, N/m.
        axle_box_spring_shear_stiffness: non_negative,
        /// Axle boxes and primary springs at ± this along y, m.
        spring_lateral_semi_spacing: positive,
        /// Spring mid-height above rail top, m.
        axle_box_spring_height: positive,
        /// Vertical damper damping, per damper, N·s/m.
        vertical_damper_damping: positive,
        /// Vertical damper series (joint) stiffness, N/m.
        vertical_damper_series_stiffness: positive,
        /// Vertical dampers at ± this along y, m.
        vertical_damper_lateral_semi_spacing: positive,
        /// Identical vertical dampers in parallel at each axle box.
        vertical_dampers_per_axle_box: count,
    }
}

parameter_section! {
    /// The secondary suspension of each bogie (`[secondary]`): flexicoil springs, lateral,
    /// yaw and vertical dampers, the lateral bump stop.
    SecondarySection = "secondary" {
        /// Flexicoil springs per side of a bogie.
        flexicoil_springs_per_side: count_positive,
        /// Spring vertical stiffness, per spring, N/m.
        flexicoil_vertical_stiffness: positive,
        /// Spring lateral (shear) stiffness, per spring, N/m.
        flexicoil_lateral_stiffness: positive,
        /// Spring longitudinal (shear) stiffness, per spring, N/m.
        flexicoil_longitudinal_stiffness: positive,
        /// Spring bending stiffness (roll and pitch), per spring, N·m/rad.
        flexicoil_bending_stiffness: non_negative,
        /// Springs at ± this along y, m.
        flexicoil_lateral_semi_spacing: positive,
        /// Distance along x between the first and last spring of a side, m.
        flexicoil_longitudinal_spacing: non_negative,
        /// Spring seat on the frame above rail top, m.
        flexicoil_bottom_height: positive,
        /// Spring seat under the carbody above rail top, m.
        flexicoil_top_height: positive,
        /// Lateral damper damping, per damper (the study's C_sy), N·s/m.
        lateral_damper_damping: positive,
        /// Lateral damper series stiffness (the study's K_ncsy), N/m.
        lateral_damper_series_stiffness: positive,
        /// Lateral dampers per bogie, 0.25 m apart along x.
        lateral_dampers_per_bogie: count,
        /// Lateral damper height above rail top, m.
        lateral_damper_height: positive,
        /// Yaw damper damping, per damper (the study's C_sx), N·s/m.
        yaw_damper_damping: positive,
        /// Yaw damper series stiffness (the study's K_ncsx), N/m.
        yaw_damper_series_stiffness: positive,
        /// Identical yaw dampers in parallel on each side of a bogie.
        yaw_dampers_per_side: count,
        /// Yaw dampers at ± this along y, m.
        yaw_damper_lateral_semi_spacing: positive,
        /// Installed length of a yaw damper between its pins, m.
        yaw_damper_length: positive,
        /// Yaw damper height above rail top, m.
        yaw_damper_height: positive,
        /// Vertical damper damping, per damper, N·s/m.
        vertical_damper_damping: positive,
        /// Vertical damper series stiffness, N/m.
        vertical_damper_series_stiffness: positive,
        /// Vertical dampers at ± this along y, m.
        vertical_damper_lateral_semi_spacing: positive,
        /// Identical vertical dampers in parallel on each side of a bogie.
        vertical_dampers_per_side: count,
        /// Free lateral clearance carbody-bogie before the bump stop, m.
        bump_stop_clearance: positive,
        /// Bump stop initial stiffness after the clearance, N/m.
        bump_stop_stiffness: positive,
        /// Stop compression beyond which it stiffens, m.
        bump_stop_hardening_deflection: positive,
        /// Bump stop stiffness beyond the hardening deflection, N/m.
        bump_stop_hardening_stiffness: positive,
        /// Bump stop height above rail top, m.
        bump_stop_height: positive,
    }
}
