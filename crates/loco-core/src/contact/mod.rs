//! Wheel-rail contact: profiles, contact geometry, equivalent conicity, Hertz and creep forces.

pub mod conicity;
pub mod conicity_harmonic;
pub mod delta_r;
#[cfg(test)]
mod en15302_data;
mod quadrature;
