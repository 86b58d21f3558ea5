//! The computations on a scenario, at the top of the vehicle: simulate (a time run with its
//! metrics), the linearised model, and the nonlinear critical speed by a speed ramp.

pub mod critical_speed;
pub mod simulate;
