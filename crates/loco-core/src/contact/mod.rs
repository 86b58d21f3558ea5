//! Wheel-rail contact: profiles, contact geometry, equivalent conicity, Hertz and creep forces.
//!
//! - [`profile`]: the profile type and its frame; [`profile_builder`]: lines and tangent arcs;
//!   [`profile_io`]: text and SIMPACK loaders.
//! - [`geometry`]: the rigid contact search of a wheelset on a track; [`table`]: contact tables
//!   for the time loop; [`builtin`]: the registry of built-in profiles.
//! - [`delta_r`]: a sampled rolling radius difference Δr(y); [`conicity`]: equivalent conicity by
//!   the nonlinear kinematic method of EN 15302; [`conicity_harmonic`]: by harmonic
//!   linearisation.
//! - [`linear_parameters`]: the linear contact parameters λ, ε, σ and the gravitational
//!   stiffness (Wickens).
//! - [`hertz`], [`kalker`], [`creepage`], [`fastsim`] and their tables, [`fastrip`]: normal and
//!   creep forces.

pub mod builtin;
pub mod conicity;
pub mod conicity_harmonic;
pub mod creepage;
pub mod delta_r;
pub mod elliptic;
#[cfg(test)]
mod en15302_data;
pub mod fastrip;
mod fastrip_lanes;
pub mod fastsim;
mod fastsim_lanes;
pub mod fastsim_table;
pub mod geometry;
pub mod hertz;
pub mod hertz_table;
pub mod kalker;
pub mod linear_parameters;
pub mod profile;
pub mod profile_builder;
pub mod profile_io;
pub mod profile_simpack;
mod quadrature;
pub mod setup;
mod side;
mod spline;
pub mod table;

pub use builtin::{builtin_names, builtin_profile};
pub use geometry::{
    ContactGeometry, ContactPoint, ContactWorkspace, WheelContact, WheelsetContact,
};
pub use profile::{Profile, ProfileKind, MIN_PROFILE_POINTS};
pub use profile_builder::{ProfileBuilder, Segment};
pub use profile_io::load_profile;
pub use setup::{ContactSearchParams, TrackSetup, WheelsetSetup, LEFT, RIGHT};
pub use spline::SplineValue;
pub use table::{rolling_radius_difference, ContactTable, ContactTableParams};
