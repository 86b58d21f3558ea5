//! The sections of the bodies: carbody, bogie frames, wheelsets, traction motors, hollow shafts,
//! traction rods and rotary arms (with their axle boxes). Inertias are principal moments about
//! the body's centre of gravity unless a field says otherwise; heights are above rail top.

use crate::error::Result;
use crate::vehicle::params::parameters::ParameterSet;

parameter_section! {
    /// The carbody and its ride-comfort measuring points (`[carbody]`).
    CarbodySection = "carbody" {
        /// Mass (sprung, with equipment), kg.
        mass: positive,
        /// Roll inertia, kg·m².
        roll_inertia: positive,
        /// Pitch inertia, kg·m².
        pitch_inertia: positive,
        /// Yaw inertia, kg·m².
        yaw_inertia: positive,
        /// Centre of gravity above rail top, m.
        cog_height: positive,
        /// Height above rail top of the ride-comfort floor points, m.
        floor_height: signed,
        /// Lateral position (y, left positive) of the ride-comfort floor points, m.
        sperling_point_lateral_offset: signed,
        /// Distance along x of the front and rear floor points from the carbody centre, m.
        sperling_point_longitudinal_offset: signed,
    }
}

parameter_section! {
    /// A bogie frame, without wheelsets, motors and axle boxes (`[bogie_frame]`).
    BogieFrameSection = "bogie_frame" {
        /// Mass, kg.
        mass: positive,
        /// Roll inertia, kg·m².
        roll_inertia: positive,
        /// Pitch inertia, kg·m².
        pitch_inertia: positive,
        /// Yaw inertia, kg·m².
        yaw_inertia: positive,
        /// Centre of gravity above rail top, m.
        cog_height: positive,
    }
}

parameter_section! {
    /// A wheelset: axle, wheels and what turns with them (`[wheelset]`).
    WheelsetSection = "wheelset" {
        /// Mass, kg.
        mass: positive,
        /// Roll inertia about its centre, kg·m².
        roll_inertia: positive,
        /// Spin inertia about the axle, kg·m².
        spin_inertia: positive,
        /// Yaw inertia about its centre, kg·m².
        yaw_inertia: positive,
    }
}

parameter_section! {
    /// A frame-suspended traction motor with its gear case, and its mounts on the frame
    /// (`[traction_motor]`).
    TractionMotorSection = "traction_motor" {
        /// Mass, kg.
        mass: positive,
        /// Roll inertia, kg·m².
        roll_inertia: positive,
        /// Pitch inertia (about its own lateral axis), kg·m².
        pitch_inertia: positive,
        /// Yaw inertia, kg·m².
        yaw_inertia: positive,
        /// Rotor inertia about its axis, kg·m².
        rotor_spin_inertia: positive,
        /// Motor to wheel speed ratio of the single gear stage, 1.
        gear_ratio: positive,
        /// Centre of gravity from its axle toward the bogie centre, m.
        cog_longitudinal_offset: positive,
        /// Centre of gravity above rail top, m.
        cog_height: positive,
        /// Rubber mounts per motor (the per-motor stiffness and damping are split equally).
        suspension_points_per_motor: count_positive,
        /// Mounts at ± this along x from the motor's centre of gravity, m.
        suspension_point_longitudinal_offset: non_negative,
        /// Mounts at ± this along y from the motor's centre of gravity, m.
        suspension_point_lateral_semi_spacing: non_negative,
        /// Height of the mounts above the motor's centre of gravity (negative below), m.
        suspension_point_vertical_offset: signed,
        /// Longitudinal stiffness, per motor (all mounts), N/m.
        suspension_stiffness_x: non_negative,
        /// Lateral stiffness, per motor, N/m.
        suspension_stiffness_y: non_negative,
        /// Vertical stiffness, per motor, N/m.
        suspension_stiffness_z: non_negative,
        /// Longitudinal damping, per motor, N·s/m.
        suspension_damping_x: non_negative,
        /// Lateral damping, per motor, N·s/m.
        suspension_damping_y: non_negative,
        /// Vertical damping, per motor, N·s/m.
        suspension_damping_z: non_negative,
    }
}

parameter_section! {
    /// A hollow shaft (quill) with its big gear, its gearbox bearings and its six-link coupling
    /// to the wheelset (`[hollow_shaft]`).
    HollowShaftSection = "hollow_shaft" {
        /// Mass, kg.
        mass: positive,
        /// Roll inertia, kg·m².
        roll_inertia: positive,
        /// Yaw inertia, kg·m².
        yaw_inertia: positive,
        /// Inertia about the axle, kg·m².
        spin_inertia: positive,
        /// Rolling bearings carrying the quill.
        bearings_per_shaft: count_positive,
        /// Bearings at ± this along the axle from the quill centre, m.
        bearing_semi_spacing: non_negative,
        /// Radial stiffness of one bearing, N/m.
        bearing_radial_stiffness: positive,
        /// Axial stiffness, per bearing, N/m.
        bearing_axial_stiffness: positive,
        /// Bearing damping as a time times the stiffness, c = β·k (axial and tilt), s.
        bearing_damping_time: non_negative,
        /// Coupling stiffness along the axle, N/m.
        coupling_lateral_stiffness: positive,
        /// Coupling radial stiffness (x and z), N/m.
        coupling_radial_stiffness: positive,
        /// Coupling cardanic (roll and yaw) stiffness, N·m/rad.
        coupling_angular_stiffness: positive,
        /// Coupling radial damping, N·s/m.
        coupling_damping_radial: non_negative,
        /// Coupling lateral damping, N·s/m.
        coupling_damping_lateral: non_negative,
    }
}

parameter_section! {
    /// A traction rod, carbody to frame, with its two rubber nodes (`[traction_rod]`).
    TractionRodSection = "traction_rod" {
        /// Mass, kg.
        mass: positive,
        /// Pitch inertia about its carbody-end pivot, kg·m².
        pitch_inertia: positive,
        /// Yaw inertia about its carbody-end pivot, kg·m².
        yaw_inertia: positive,
        /// Carbody pivot along x from the bogie centre (positive toward the vehicle end), m.
        carbody_end_longitudinal_offset: signed,
        /// Frame end along x from the bogie centre (positive toward the vehicle end), m.
        frame_end_longitudinal_offset: signed,
        /// Carbody pivot above rail top, m.
        carbody_end_height: positive,
        /// Frame end above rail top, m.
        frame_end_height: positive,
        /// Carbody node, axial (x) stiffness, N/m.
        carbody_bushing_stiffness_x: positive,
        /// Carbody node, lateral stiffness, N/m.
        carbody_bushing_stiffness_y: positive,
        /// Carbody node, vertical stiffness, N/m.
        carbody_bushing_stiffness_z: positive,
        /// Frame node, axial stiffness, N/m.
        frame_bushing_stiffness_x: positive,
        /// Frame node, lateral stiffness, N/m.
        frame_bushing_stiffness_y: positive,
        /// Frame node, vertical stiffness, N/m.
        frame_bushing_stiffness_z: positive,
        /// Node damping as a time times their series stiffness, c = τ·k, s.
        bushing_damping_time: non_negative,
    }
}

parameter_section! {
    /// An axle-box housing with its rotary arm and the arm's rubber node on the frame: the
    /// primary longitudinal and lateral positioning (`[rotary_arm]`).
    RotaryArmSection = "rotary_arm" {
        /// Mass, kg.
        mass: positive,
        /// Inertia about the axle, kg·m².
        pitch_inertia: positive,
        /// Axle centre to the arm's rubber node, m.
        arm_length: positive,
        /// Node longitudinal stiffness, per axle box (the study's K_px), N/m.
        node_stiffness_longitudinal: positive,
        /// Node lateral stiffness, per axle box (the study's K_py), N/m.
        node_stiffness_lateral: positive,
        /// Node vertical (radial) stiffness, per axle box, N/m.
        node_stiffness_vertical: positive,
        /// Node torsional stiffness about y, N·m/rad.
        node_stiffness_torsional: non_negative,
    }
}
