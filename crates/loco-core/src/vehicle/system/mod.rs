//! The assembled equations of motion: [`simulation::VehicleSystem`] (structure, contact, track,
//! dampers), its damper elements, the caches of its states, the state check, the static
//! equilibrium every run starts from, and what a run cost.

pub mod damper_elements;
pub mod run_statistics;
pub mod simulation;
pub(crate) mod state_check;
pub(crate) mod states_cache;
pub mod statics;
