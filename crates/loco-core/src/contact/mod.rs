//! Wheel-rail contact: profiles, contact geometry, equivalent conicity, Hertz and creep forces.

pub mod hertz;
