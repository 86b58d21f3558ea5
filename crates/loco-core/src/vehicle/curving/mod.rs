//! The curved-track frame: the vehicle's motion measured from a frame that follows the track
//! design, its inertial forces and the offsets of the bodies in it.

pub mod track_frame;
