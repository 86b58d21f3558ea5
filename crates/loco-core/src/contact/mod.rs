//! Wheel-rail contact: profiles, contact geometry, equivalent conicity, Hertz and creep forces.
//!
//! - [`profile`]: the profile type and its frame; [`profile_builder`]: lines and tangent arcs;
//!   [`profile_io`]: text and SIMPACK loaders.
//! - [`geometry`]: the rigid contact search of a wheelset on a track; [`table`]: contact tables
//!   for the time loop; [`builtin`]: the registry of built-in profiles.

pub mod builtin;
pub mod profile;
pub mod profile_builder;
mod spline;

pub use builtin::{builtin_names, builtin_profile};
pub use profile::{Profile, ProfileKind, MIN_PROFILE_POINTS};
pub use profile_builder::{ProfileBuilder, Segment};
pub use spline::SplineValue;
