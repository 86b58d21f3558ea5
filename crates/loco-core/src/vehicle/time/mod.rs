//! Time integration below the vehicle system: the ODE trait and the fixed-step RK4, the exponential
//! RK4 (ETDRK4) with the stiff linear part it solves exactly, its row groups, and the decaying
//! (first-order) states of the dampers.

pub mod decaying_states;
pub mod exponential_rk4;
pub mod integrator;
pub(crate) mod row_groups;
pub mod stiff_linear_part;
