//! The vehicle model built from its parameters: the 90 coordinates and 25 bodies, the small-motion
//! kinematics, mass properties and the mass matrix, the suspension elements and where they sit,
//! the bogie mass, and [`structure::VehicleStructure`], the assembled vehicle with its gravity,
//! gyroscopic and spring forces (with the lane kernels of its bushings and dampers).

pub mod bodies;
pub mod bogie_mass;
pub(crate) mod bushing_lanes;
pub(crate) mod damper_lanes;
pub mod elements;
pub mod kinematics;
pub mod layout;
pub mod mass;
pub(crate) mod pair_lanes;
pub mod structure;
pub mod suspension;
