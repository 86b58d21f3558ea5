//! Wheel-rail contact: profiles, contact geometry, equivalent conicity, Hertz and creep forces.

pub mod creepage;
pub mod elliptic;
pub mod fastsim;
pub mod fastsim_table;
pub mod hertz;
pub mod hertz_table;
pub mod kalker;
