//! Wheel-rail contact of the vehicle: [`wheel_rail::WheelRail`] (normal and creep forces of every
//! wheel), the creep model by name, the rails' plane at a wheelset, which irregularities the
//! contact can follow, and the contact recorder.

#[cfg(feature = "record-contacts")]
pub mod contact_recording;
pub mod creep_model;
pub mod rail_plane;
pub(crate) mod rail_planes;
pub mod track_limits;
pub mod wheel_rail;
